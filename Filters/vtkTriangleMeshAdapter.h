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
 * follow). Null, with the reason in `error`, if a polygon or strip refers to a point id
 * outside 0..number of points-1.
 */
vtkSmartPointer<vtkPolyData> TriangulateSurface(vtkPolyData* input,
  vtkIdType& droppedVerts,
  vtkIdType& droppedLines,
  std::string& error);

/// Copies the points and triangles of an all-triangle vtkPolyData. False, with the reason in
/// `error`, if a cell is not a triangle or refers to a point that does not exist.
bool ToTriangleMesh(vtkPolyData* triangles,
  TriangleMesh& mesh,
  std::vector<Vec3>& normals,
  std::string& error);

/// The supported bounding-box diagonals (of the points triangles use): beyond them squared
/// lengths, areas and second moments under- or overflow double precision.
constexpr double MinimumSupportedDiagonal = 1e-60;
constexpr double MaximumSupportedDiagonal = 1e60;

/**
 * False, with the reason in `error`, if a point of `mesh` has a NaN or infinite coordinate or
 * the bounding-box diagonal of the points its triangles use is positive but outside
 * [MinimumSupportedDiagonal, MaximumSupportedDiagonal] (computed without overflow; a zero
 * diagonal is left to the callers' zero-area checks).
 */
bool CheckExtent(const TriangleMesh& mesh, std::string& error);

/**
 * The input step shared by the filters: rejects a mesh without points or without polygons
 * (`purpose` completes "The input has no polygons: ..."), triangulates it
 * (TriangulateSurface), copies it (ToTriangleMesh) and checks its extent (CheckExtent).
 * Returns the triangulated surface, or null with the whole message in `error`.
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
