#include "vtkTriangleMeshAdapter.h"
#include "vtkFoldingArrays.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>

#include <limits>
#include <sstream>
#include <vector>

namespace foldingmeshes
{
namespace
{
const char* const NoSuchPoint = "a triangle refers to a point that does not exist";

// True if every cell of `cells` refers to points 0..np-1 only.
bool PointIdsInRange(vtkCellArray* cells, vtkIdType np)
{
  if (!cells)
    return true;
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    for (vtkIdType k = 0; k < n; ++k)
      if (ids[k] < 0 || ids[k] >= np)
        return false;
  }
  return true;
}
}

vtkSmartPointer<vtkPolyData> TriangulateSurface(vtkPolyData* input,
  vtkIdType& droppedVerts,
  vtkIdType& droppedLines,
  std::string& error)
{
  droppedVerts = input->GetNumberOfVerts();
  droppedLines = input->GetNumberOfLines();
  // vtkTriangleFilter reads the points of polygons and strips: check their ids first.
  const vtkIdType np = input->GetNumberOfPoints();
  if (!PointIdsInRange(input->GetPolys(), np) || !PointIdsInRange(input->GetStrips(), np))
  {
    error = NoSuchPoint;
    return nullptr;
  }
  // vtkTriangleFilter copies cell data with the default copy flags, which drop cell global
  // ids: it only carries each triangle's input cell id here, the cell arrays are copied by it.
  vtkNew<vtkPolyData> surface;
  surface->ShallowCopy(input);
  const vtkIdType nc = input->GetNumberOfCells();
  vtkNew<vtkIdTypeArray> cellIds;
  cellIds->SetName("FoldingMeshesTriangulatedFrom");
  cellIds->SetNumberOfTuples(nc);
  for (vtkIdType c = 0; c < nc; ++c)
    cellIds->SetValue(c, c);
  surface->GetCellData()->Initialize();
  surface->GetCellData()->AddArray(cellIds);
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(surface);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  vtkSmartPointer<vtkPolyData> result = triangulate->GetOutput();
  vtkIdTypeArray* from =
    vtkIdTypeArray::SafeDownCast(result->GetCellData()->GetArray(cellIds->GetName()));
  const vtkIdType n = result->GetNumberOfCells();
  std::vector<vtkIdType> ids(n, 0);
  for (vtkIdType c = 0; from && c < n && c < from->GetNumberOfTuples(); ++c)
    ids[c] = from->GetValue(c);
  result->GetCellData()->Initialize();
  CopyTuplesById(input->GetCellData(), result->GetCellData(), ids.data(), n);
  // The points are the input's: every point array as it is (global ids too).
  if (result->GetNumberOfPoints() == input->GetNumberOfPoints())
    result->GetPointData()->ShallowCopy(input->GetPointData());
  return result;
}

bool ToTriangleMesh(vtkPolyData* triangles,
  TriangleMesh& mesh,
  std::vector<Vec3>& normals,
  std::string& error)
{
  const vtkIdType np = triangles->GetNumberOfPoints();
  if (np > std::numeric_limits<int>::max())
  {
    error = "the mesh has more points than this program can index";
    return false;
  }
  mesh.points.resize(np);
  for (vtkIdType i = 0; i < np; ++i)
  {
    double p[3];
    triangles->GetPoint(i, p);
    mesh.points[i] = Vec3(p[0], p[1], p[2]);
  }
  mesh.triangles.clear();
  mesh.triangles.reserve(triangles->GetNumberOfPolys());
  auto it = vtk::TakeSmartPointer(triangles->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    if (n != 3)
    {
      error = "a polygon could not be triangulated";
      return false;
    }
    for (int k = 0; k < 3; ++k)
      if (ids[k] < 0 || ids[k] >= np)
      {
        error = NoSuchPoint;
        return false;
      }
    mesh.triangles.push_back(
      { static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]) });
  }
  normals.clear();
  if (vtkDataArray* n = triangles->GetPointData()->GetNormals())
  {
    if (n->GetNumberOfComponents() == 3 && n->GetNumberOfTuples() == np)
    {
      normals.resize(np);
      for (vtkIdType i = 0; i < np; ++i)
      {
        double v[3];
        n->GetTuple(i, v);
        normals[i] = Vec3(v[0], v[1], v[2]);
      }
    }
  }
  return true;
}

bool CheckExtent(const TriangleMesh& mesh, std::string& error)
{
  for (const Vec3& p : mesh.points)
    if (!p.allFinite())
    {
      error = "the mesh has NaN or infinite point coordinates";
      return false;
    }
  if (mesh.triangles.empty())
    return true;
  Vec3 lo = mesh.points[mesh.triangles[0][0]], hi = lo;
  for (const Triangle& t : mesh.triangles)
    for (int v : t)
    {
      lo = lo.cwiseMin(mesh.points[v]);
      hi = hi.cwiseMax(mesh.points[v]);
    }
  // hi - lo may overflow (coordinates near +-1.8e308): halve first.
  const Vec3 half = 0.5 * hi - 0.5 * lo;
  const double largest = half.cwiseAbs().maxCoeff();
  const double diagonal = largest > 0.0 ? 2.0 * largest * (half / largest).norm() : 0.0;
  if (diagonal > 0.0 &&
    !(diagonal >= MinimumSupportedDiagonal && diagonal <= MaximumSupportedDiagonal))
  {
    std::ostringstream os;
    os << "its bounding-box diagonal " << diagonal << " is outside the supported range ["
       << MinimumSupportedDiagonal << ", " << MaximumSupportedDiagonal
       << "] (scale the mesh's coordinates)";
    error = os.str();
    return false;
  }
  return true;
}

vtkSmartPointer<vtkPolyData> SurfaceInput(vtkPolyData* input,
  const char* purpose,
  TriangleMesh& mesh,
  std::vector<Vec3>& normals,
  vtkIdType& droppedVerts,
  vtkIdType& droppedLines,
  std::string& error)
{
  droppedVerts = droppedLines = 0;
  if (input->GetNumberOfPoints() == 0)
  {
    error = "The input mesh is empty (no points).";
    return nullptr;
  }
  if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    error = std::string("The input has no polygons: ") + purpose + ".";
    return nullptr;
  }
  std::string why;
  vtkSmartPointer<vtkPolyData> surface = TriangulateSurface(input, droppedVerts, droppedLines, why);
  if (!surface || !ToTriangleMesh(surface, mesh, normals, why) || !CheckExtent(mesh, why))
  {
    error = "Invalid input mesh: " + why + ".";
    return nullptr;
  }
  return surface;
}
}
