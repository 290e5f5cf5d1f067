// Meshes and measures of TestUnfoldingAccuracy: a tessellated cube, scaling, triangle sets,
// areas, edge and border counts (no assertions here).
#ifndef foldingmeshes_UnfoldingAccuracyMeshes_h
#define foldingmeshes_UnfoldingAccuracyMeshes_h

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <array>
#include <vector>

namespace foldingmeshes
{
namespace testing
{
/// Summed area of the triangles of pd.
double TotalArea(vtkPolyData* pd);

/// Summed area of the triangles of an unfolded mesh that the unfolder added to close seam gaps
/// and holes (cell array FoldingFilled nonzero; 0 without the array).
double FilledArea(vtkPolyData* pd);

/// The surface of [-h, h]^3, n x n squares of 4 triangles (around a centre point) per face,
/// outward: symmetric about x, y, z = 0 and the diagonal planes, as a triangle set.
vtkSmartPointer<vtkPolyData> Cube(int n, double h);

/// The closed box [0,1]^3 whose top and bottom are n x n grids of squares (2 triangles
/// each) and whose sides are one square (2 triangles) per grid edge, with the top's centre
/// vertex raised by `bump` (n even): mirror planes x = 1/2, y = 1/2 and the diagonals, and
/// z = 1/2 away from the bump. Double coordinates or float (as VTK's sources make them).
vtkSmartPointer<vtkPolyData> BumpBox(int n, double bump, bool doublePoints);

/// A copy of `in` with its points scaled by s about the origin.
vtkSmartPointer<vtkPolyData> Scaled(vtkPolyData* in, double s);

struct EdgeCounts
{
  long long edges = 0, open = 0, nonManifold = 0, misoriented = 0;
};

/// Undirected edge uses (open: 1, non-manifold: > 2) and interior edges whose two faces
/// traverse them in the same direction (inconsistent orientation).
EdgeCounts CountEdges(vtkPolyData* pd);

/// Border of M: open edges, their total length and connected components (loops), vertices
/// at identical positions counted as one.
struct Border
{
  long long loops = 0;
  double length = 0.0;
};

Border InputBorder(vtkPolyData* pd);

/// Points of M used by a polygon, coincident ones counted once.
long long WeldedPointCount(vtkPolyData* pd);

/// Triangles of M's polygons (n - 2 per n-gon).
long long TriangleCount(vtkPolyData* pd);

/// A triangle set from points and triangles.
vtkSmartPointer<vtkPolyData> Triangles(const std::vector<std::array<double, 3>>& points,
  const std::vector<std::array<vtkIdType, 3>>& triangles);
}
}

#endif
