/**
 * @file    MeshComparison.h
 * @brief   measures between two surface meshes (command line, benchmarks)
 */
#ifndef foldingmeshes_MeshComparison_h
#define foldingmeshes_MeshComparison_h

class vtkPolyData;

namespace foldingmeshes
{
/// Edges used by exactly one polygon, vertices at identical positions counted as one.
long long CountOpenEdges(vtkPolyData* mesh);

/**
 * Symmetric Hausdorff distance (the largest distance from a point of either mesh to the
 * other surface, vtkStaticCellLocator, in parallel) and the mean of those point-to-surface
 * distances over the points of both meshes. Lengths, not fractions of a diagonal.
 */
void SymmetricSurfaceDistance(vtkPolyData* a, vtkPolyData* b, double& hausdorff, double& mean);
}

#endif
