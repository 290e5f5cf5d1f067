#include "vtkCellLocatorFaceQuery.h"

#include "vtkAbstractCellLocator.h"
#include "vtkCellType.h"
#include "vtkGenericCell.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSmartPointer.h"
#include "vtkStaticCellLocator.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

namespace foldingmeshes
{
namespace
{
class CellLocatorFaceQuery : public ClosestFaceQuery
{
public:
  CellLocatorFaceQuery(const TriangleMesh& surface, vtkAbstractCellLocator* prototype)
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(surface.points.size()));
    for (size_t i = 0; i < surface.points.size(); ++i)
      points->SetPoint(static_cast<vtkIdType>(i), surface.points[i].data());
    this->Grid->SetPoints(points);
    this->Grid->Allocate(static_cast<vtkIdType>(surface.triangles.size()));
    for (const Triangle& t : surface.triangles)
    {
      const Vec3 &a = surface.points[t[0]], &b = surface.points[t[1]], &c = surface.points[t[2]];
      const double longest =
        std::max({ (b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm() });
      const vtkIdType ids[4] = { t[0], t[1], t[2], t[0] };
      if (longest == 0.0)
        this->Grid->InsertNextCell(VTK_VERTEX, 1, ids);
      else if ((b - a).cross(c - a).squaredNorm() <= 1e-24 * longest * longest)
        this->Grid->InsertNextCell(VTK_POLY_LINE, 4, ids); // collinear: its three edges
      else
        this->Grid->InsertNextCell(VTK_TRIANGLE, 3, ids);
    }
    this->Locator = prototype
      ? vtk::TakeSmartPointer(prototype->NewInstance())
      : vtkSmartPointer<vtkAbstractCellLocator>(vtkSmartPointer<vtkStaticCellLocator>::New());
    this->Locator->SetDataSet(this->Grid);
    this->Locator->BuildLocator();
    this->ThreadSafe = vtkStaticCellLocator::SafeDownCast(this->Locator) != nullptr;
  }

  ClosestFaceHit Closest(const Vec3& p) const override
  {
    return this->ClosestWithin(p, std::numeric_limits<double>::infinity());
  }

  ClosestFaceHit ClosestWithin(const Vec3& p, double radius) const override
  {
    ClosestFaceHit hit;
    if (this->Grid->GetNumberOfCells() == 0 || !(radius > 0.0))
      return hit;
    double x[3] = { p.x(), p.y(), p.z() }, closest[3], dist2 = 0.0;
    vtkIdType cellId = -1;
    int subId = 0, inside = 0;
    vtkGenericCell* cell = this->Cells.Local();
    if (this->ThreadSafe)
      this->Locator->FindClosestPointWithinRadius(
        x, radius, closest, cell, cellId, subId, dist2, inside);
    else
    {
      std::lock_guard<std::mutex> lock(this->Serial);
      this->Locator->FindClosestPointWithinRadius(
        x, radius, closest, cell, cellId, subId, dist2, inside);
    }
    if (cellId >= 0 && std::sqrt(dist2) < radius)
    {
      hit.face = static_cast<int>(cellId);
      hit.distance = std::sqrt(dist2);
      hit.point = Vec3(closest[0], closest[1], closest[2]);
    }
    return hit;
  }

private:
  vtkNew<vtkUnstructuredGrid> Grid;
  vtkSmartPointer<vtkAbstractCellLocator> Locator;
  bool ThreadSafe = false;
  mutable vtkSMPThreadLocalObject<vtkGenericCell> Cells;
  mutable std::mutex Serial;
};
}

ClosestFaceQueryFactory CellLocatorFaceQueryFactory(vtkAbstractCellLocator* prototype)
{
  vtkSmartPointer<vtkAbstractCellLocator> keep = prototype;
  return [keep](const TriangleMesh& surface) -> std::unique_ptr<ClosestFaceQuery>
  { return std::make_unique<CellLocatorFaceQuery>(surface, keep); };
}
}
