// The line glyph of a rotation axis (internal header): vtkSymmetryPlaneDetector's output 2 and
// a rotation node's "Axis" block in the folding tree.
#ifndef vtkAxisGlyph_h
#define vtkAxisGlyph_h

#include "RotationAxis.h"

#include <vector>

class vtkPolyData;

namespace foldingmeshes
{
/// A line along `axis` over the extent of `points` along it, with a margin of 10% of that
/// extent plus 1e-3 * diagonal at both ends (one cell, two double-precision points).
void SetAxisLineGlyph(const RotationAxis& axis,
  const std::vector<Vec3>& points,
  double diagonal,
  vtkPolyData* glyph);
}

#endif
