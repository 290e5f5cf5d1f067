// A coarse query mesh for the candidate search of symmetry detection, made of some of a
// mesh's own vertices.
#ifndef foldingmeshes_ClusteredMesh_h
#define foldingmeshes_ClusteredMesh_h

#include "TriangleMesh.h"

#include <vector>

namespace foldingmeshes
{
/// A triangle soup whose points are vertices of a finer mesh, with those vertices' normals.
struct ClusteredMesh
{
  TriangleMesh mesh;
  std::vector<Vec3> normals; ///< per point of `mesh`: the fine mesh's normal at that vertex
  std::vector<int> vertex;   ///< per point of `mesh`: its vertex index in the fine mesh
};

/**
 * About `targetFaces` triangles over the surface of `mesh` by vertex clustering: the
 * vertices are grouped by the cells of a uniform grid, a cell's group split into the parts
 * that edges inside the cell connect between vertices with normals less than 90 degrees
 * apart (so the two sides of a thin part stay apart); each cluster is represented by one of
 * its own vertices (the nearest to the cluster's area-weighted mean; ties: the lowest index);
 * a face of `mesh` whose corners lie in three clusters gives a triangle (duplicates once).
 *
 * Unlike a mesh of averaged cluster points, its points lie exactly on `mesh`: the mirror
 * image of a point of an exactly symmetric surface lies on that surface, so distances
 * measured from its points to the full mesh keep exact symmetry exact. Deterministic.
 * Meshes with at most `targetFaces` faces come back whole.
 */
ClusteredMesh ClusterVertices(const PreparedMesh& mesh, int targetFaces);
}

#endif
