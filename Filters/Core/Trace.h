// Diagnostics of the core: lines handed to a sink the caller connects (the VTK filters connect
// it to vtkDebugMacro when their Debug flag is on), never printed by the library itself.
#ifndef foldingmeshes_Trace_h
#define foldingmeshes_Trace_h

#include <functional>
#include <string>

namespace foldingmeshes
{
/// Receives one diagnostic line (no trailing newline). Empty: no diagnostics (the default).
using TraceSink = std::function<void(const std::string&)>;

/// printf-style formatting into a string.
std::string FormatTrace(const char* format, ...)
#if defined(__GNUC__)
  __attribute__((format(printf, 1, 2)))
#endif
  ;
}

#endif
