#include "vtkAxisGlyph.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>

namespace foldingmeshes
{
void SetAxisLineGlyph(const RotationAxis& axis,
  const std::vector<Vec3>& points,
  double diagonal,
  vtkPolyData* glyph)
{
  double lo = 0.0, hi = 0.0;
  for (size_t i = 0; i < points.size(); ++i)
  {
    const double t = (points[i] - axis.origin).dot(axis.direction);
    lo = i == 0 ? t : std::min(lo, t);
    hi = i == 0 ? t : std::max(hi, t);
  }
  const double margin = 0.1 * (hi - lo) + 1e-3 * diagonal;
  vtkNew<vtkPoints> ends;
  ends->SetDataTypeToDouble();
  for (double t : { lo - margin, hi + margin })
  {
    const Vec3 p = axis.origin + t * axis.direction;
    ends->InsertNextPoint(p.x(), p.y(), p.z());
  }
  vtkNew<vtkCellArray> line;
  const vtkIdType ids[2] = { 0, 1 };
  line->InsertNextCell(2, ids);
  glyph->SetPoints(ends);
  glyph->SetLines(line);
}
}
