#include "vtkParameterChecks.h"

#include <cmath>
#include <sstream>

namespace foldingmeshes
{
bool CheckParameters(std::initializer_list<NamedValue> positive,
  std::initializer_list<NamedValue> finite,
  std::string& error)
{
  for (const NamedValue& p : positive)
    if (!std::isfinite(p.value) || !(p.value > 0.0))
    {
      std::ostringstream message;
      message << p.name << " must be a positive, finite number (it is " << p.value << ")";
      error = message.str();
      return false;
    }
  bool ok = true;
  for (const NamedValue& p : finite)
    ok = ok && std::isfinite(p.value);
  if (ok)
    return true;
  std::ostringstream names, values;
  size_t i = 0;
  for (const NamedValue& p : finite)
  {
    const char* separator = i == 0 ? "" : (i + 1 == finite.size() ? " and " : ", ");
    names << separator << p.name;
    values << separator << p.value;
    ++i;
  }
  error = names.str() +
    (finite.size() > 1 ? " must be finite numbers (they are "
                       : " must be a finite number (it is ") +
    values.str() + ")";
  return false;
}

bool ToleranceLengthOf(bool absolute,
  double tolerance,
  double diagonal,
  double& epsilon,
  std::string& error)
{
  std::ostringstream message;
  if (!std::isfinite(diagonal))
    message << "Invalid input mesh: non-finite point coordinates";
  else if (!absolute && !(diagonal > 0.0))
    message << "Invalid input mesh: zero extent, so the relative tolerance is zero";
  else
  {
    epsilon = absolute ? tolerance : tolerance * diagonal;
    if (std::isfinite(epsilon) && epsilon > 0.0)
      return true;
    message << "The tolerance length (Tolerance x the bounding-box diagonal " << diagonal << ") is "
            << epsilon << ": it must be positive and finite";
  }
  error = message.str();
  return false;
}
}
