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
 * The cell size is the one that many faces of a connected surface would take; where the copy
 * of a mesh above 5000 faces then still queries more points than `targetFaces` (many small
 * parts: a part smaller than a cell keeps every corner its edges take out of the cell), the
 * cells grow and the copy at the smallest size found by bisection that uses at most
 * `targetFaces` points (and at least 0.4 of them) is taken instead - the artist-like rack 5012
 * of its 8208 vertices -> 3078 (issue 21).
 *
 * Unlike a mesh of averaged cluster points, its points lie exactly on `mesh`: the mirror
 * image of a point of an exactly symmetric surface lies on that surface, so distances
 * measured from its points to the full mesh keep exact symmetry exact. Deterministic.
 * Meshes with at most `targetFaces` faces come back whole.
 */
ClusteredMesh ClusterVertices(const PreparedMesh& mesh, int targetFaces);
}

#endif
