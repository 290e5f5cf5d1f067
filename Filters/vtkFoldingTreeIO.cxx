// IsIdOrMaskArrayName; the conversions are in vtkFoldingTreeIOWrite/Read.cxx.
#include "vtkFoldingTreeIO.h"

#include <cstring>
#include <string>

namespace foldingmeshes
{
//------------------------------------------------------------------------------
bool IsIdOrMaskArrayName(const char* name)
{
  if (!name)
    return false;
  const std::string s(name);
  auto endsWith = [&](const char* suffix)
  {
    const size_t n = std::strlen(suffix);
    return s.size() >= n && s.compare(s.size() - n, n, suffix) == 0;
  };
  return endsWith("Id") || endsWith("Ids") || endsWith("ID") || endsWith("IDs") ||
    s.find("Mask") != std::string::npos || s.find("mask") != std::string::npos;
}
}
