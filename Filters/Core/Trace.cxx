#include "Trace.h"

#include <cstdarg>
#include <cstdio>
#include <vector>

namespace foldingmeshes
{
std::string FormatTrace(const char* format, ...)
{
  va_list args;
  va_start(args, format);
  va_list copy;
  va_copy(copy, args);
  const int n = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  std::string line;
  if (n > 0)
  {
    std::vector<char> buffer(static_cast<size_t>(n) + 1);
    std::vsnprintf(buffer.data(), buffer.size(), format, args);
    line.assign(buffer.data(), static_cast<size_t>(n));
  }
  va_end(args);
  return line;
}
}
