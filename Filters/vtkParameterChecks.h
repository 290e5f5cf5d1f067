// The checks the three filters make on their parameters before they run (internal header).
#ifndef vtkParameterChecks_h
#define vtkParameterChecks_h

#include <initializer_list>
#include <string>

namespace foldingmeshes
{
/// A parameter's name (as in the filter's Set/Get methods) and its value.
struct NamedValue
{
  const char* name;
  double value;
};

/**
 * NaN passes vtkSetClampMacro, so each filter checks its floating-point parameters when it
 * runs: false, with the message in `error`, when one of `positive` is not a positive finite
 * number or one of `finite` is NaN or infinite.
 */
bool CheckParameters(std::initializer_list<NamedValue> positive,
  std::initializer_list<NamedValue> finite,
  std::string& error);

/**
 * The tolerance length epsilon: `tolerance` itself when `absolute`, else `tolerance` x the
 * bounding-box `diagonal`. False, with the message in `error`, when the diagonal is not finite,
 * when a relative tolerance meets a zero extent, or when epsilon is not positive and finite.
 */
bool ToleranceLengthOf(bool absolute,
  double tolerance,
  double diagonal,
  double& epsilon,
  std::string& error);
}

#endif
