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

#include <vector>

namespace foldingmeshes
{
vtkSmartPointer<vtkPolyData> TriangulateSurface(vtkPolyData* input,
  vtkIdType& droppedVerts,
  vtkIdType& droppedLines)
{
  droppedVerts = input->GetNumberOfVerts();
  droppedLines = input->GetNumberOfLines();
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
  vtkSmartPointer<vtkPolyData> surface = TriangulateSurface(input, droppedVerts, droppedLines);
  std::string why;
  if (!ToTriangleMesh(surface, mesh, normals, why))
  {
    error = "Invalid input mesh: " + why + ".";
    return nullptr;
  }
  return surface;
}
}
