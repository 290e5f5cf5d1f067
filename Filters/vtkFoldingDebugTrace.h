// The core's diagnostics (Core/Trace.h) as VTK debug output (internal header).
#ifndef vtkFoldingDebugTrace_h
#define vtkFoldingDebugTrace_h

#include "Core/Trace.h"

class vtkObject;

namespace foldingmeshes
{
/**
 * A sink that hands each line of the core's diagnostics to VTK's debug output as a debug
 * message of `self` (what vtkDebugMacro would print, also in release builds; VTK's output
 * window: stderr in a console program, Output Messages in ParaView) when self's Debug flag is
 * on (`DebugOn()`); an empty sink, so no diagnostics are made at all, when it is off. Lines
 * from worker threads are serialized.
 */
TraceSink DebugTrace(vtkObject* self);
}

#endif
