// VTK conversion and access: TriMesh -> vtkPolyData, ProceduralMesh assembly, point access.
#include "ProceduralMeshesInternal.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPoints.h>

#include <algorithm>
#include <vector>

namespace foldingmeshes
{
namespace testing
{
namespace procedural
{
// ---- VTK conversion and access ----
namespace
{
vtkSmartPointer<vtkPolyData> ToPolyData(const TriMesh& m)
{
  auto coords = vtkSmartPointer<vtkDoubleArray>::New();
  coords->SetNumberOfComponents(3);
  coords->SetNumberOfTuples(vtkIdType(m.p.size()));
  double* c = coords->GetPointer(0);
  for (size_t i = 0; i < m.p.size(); ++i)
  {
    std::copy(m.p[i].data(), m.p[i].data() + 3, c + 3 * i);
  }
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(coords);
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto conn = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(vtkIdType(m.t.size() + 1));
  conn->SetNumberOfValues(vtkIdType(3 * m.t.size()));
  for (size_t f = 0; f <= m.t.size(); ++f)
  {
    offsets->SetValue(vtkIdType(f), vtkIdType(3 * f));
  }
  for (size_t f = 0; f < m.t.size(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      conn->SetValue(vtkIdType(3 * f + k), m.t[f][k]);
    }
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets.Get(), conn.Get());
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetPolys(cells);
  return pd;
}
} // namespace

ProceduralMesh Finish(const TriMesh& m, std::vector<KnownPlane> planes)
{
  ProceduralMesh r;
  r.mesh = ToPolyData(m);
  r.planes = std::move(planes);
  r.symmetricFace = m.sym;
  return r;
}

std::vector<Vec3> GetPoints(vtkPolyData* pd)
{
  std::vector<Vec3> p(size_t(pd->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    pd->GetPoint(i, p[size_t(i)].data());
  }
  return p;
}

void SetPoints(vtkPolyData* pd, const std::vector<Vec3>& p)
{
  vtkPoints* pts = pd->GetPoints();
  for (size_t i = 0; i < p.size(); ++i)
  {
    pts->SetPoint(vtkIdType(i), p[i].data());
  }
  pts->Modified();
  pd->Modified();
}
} // namespace procedural
} // namespace testing
} // namespace foldingmeshes
