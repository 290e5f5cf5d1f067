// Shared pieces of the foldingmeshes command-line program (one file per command family).
#ifndef foldingmeshes_CommandLine_h
#define foldingmeshes_CommandLine_h

#include <vtkObject.h>

#include <cstdio>
#include <string>
#include <vector>

namespace foldingmeshes
{
namespace cli
{
/// The --help text of all commands.
extern const char* const Usage;

/// The value of --up: -1 for "auto", 0, 1, 2 for "x", "y", "z"; throws std::runtime_error on
/// anything else.
int ParseUpAxis(const std::string& value);

/// Collects the text of VTK ErrorEvents (without the file/line prefix).
struct ErrorCollector
{
  std::string messages;
  static void OnError(vtkObject*, unsigned long, void* self, void* data)
  {
    auto* collector = static_cast<ErrorCollector*>(self);
    if (data)
    {
      std::string text = static_cast<const char*>(data);
      const auto pos = text.find("): ");
      collector->messages += (pos != std::string::npos ? text.substr(pos + 3) : text);
    }
  }
};

/// Prints "label: NN%" on stderr for ProgressEvents.
struct ProgressPrinter
{
  const char* label = "detecting symmetry";
  int lastPercent = -1;
  static void OnProgress(vtkObject*, unsigned long, void* self, void* data)
  {
    auto* printer = static_cast<ProgressPrinter*>(self);
    const int percent = static_cast<int>(100.0 * *static_cast<double*>(data));
    if (percent != printer->lastPercent)
    {
      printer->lastPercent = percent;
      std::fprintf(stderr, "\r%s: %3d%%", printer->label, percent);
      std::fflush(stderr);
    }
  }
};

/// The number `text` in [lo, hi] (and > 0 when `positive`), for the option `what`; throws
/// std::runtime_error with a clear message on anything else (trailing text, NaN, infinity).
double ParseNumber(const std::string& what,
  const std::string& text,
  double lo,
  double hi,
  bool positive = false);
/// An integer in [lo, hi], as ParseNumber.
int ParseInteger(const std::string& what, const std::string& text, int lo, int hi);

/// Comma-separated finite numbers; false on anything else.
bool ParseNumbers(const std::string& text, std::vector<double>& values);
/// A JSON string literal.
std::string JsonString(const std::string& s);

/// The commands: arguments after the command name; return the exit code.
int Detect(int argc, char* argv[]);
int Fold(int argc, char* argv[]);
int Unfold(int argc, char* argv[]);
int Roundtrip(int argc, char* argv[]);
int Compress(int argc, char* argv[]);
int Decompress(int argc, char* argv[]);
}
}

#endif
