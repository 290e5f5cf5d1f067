// Conversions between vtkPolyData and the core's plain mesh types (internal header).
#ifndef vtkTriangleMeshAdapter_h
#define vtkTriangleMeshAdapter_h

#include "Core/TriangleMesh.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;
class vtkAlgorithm;

namespace foldingmeshes
{
/**
 * Triangulates the polygons and strips of `input` (vertices and lines are dropped; the
 * counts are returned so the caller can warn). The result keeps the input's points and
 * all point and cell arrays (cell arrays of the polygons, each triangle with its polygon's
 * tuple: every array, global ids, unnamed and non-numeric arrays included; active attributes
 * follow).
 */
vtkSmartPointer<vtkPolyData> TriangulateSurface(vtkPolyData* input,
  vtkIdType& droppedVerts,
  vtkIdType& droppedLines);

/// Copies the points and triangles of an all-triangle vtkPolyData. False if a cell is not a
/// triangle.
bool ToTriangleMesh(vtkPolyData* triangles,
  TriangleMesh& mesh,
  std::vector<Vec3>& normals,
  std::string& error);

/**
 * The input step shared by the filters: rejects a mesh without points or without polygons
 * (`purpose` completes "The input has no polygons: ..."), triangulates it
 * (TriangulateSurface) and copies it (ToTriangleMesh). Returns the triangulated surface, or
 * null with the whole message in `error`.
 */
vtkSmartPointer<vtkPolyData> SurfaceInput(vtkPolyData* input,
  const char* purpose,
  TriangleMesh& mesh,
  std::vector<Vec3>& normals,
  vtkIdType& droppedVerts,
  vtkIdType& droppedLines,
  std::string& error);
}

#endif
