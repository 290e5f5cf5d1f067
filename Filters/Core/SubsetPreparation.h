// A prepared mesh of some faces of a prepared mesh, without PrepareMesh's weld and sorts.
#ifndef foldingmeshes_SubsetPreparation_h
#define foldingmeshes_SubsetPreparation_h

#include "TriangleMesh.h"

#include <vector>

namespace foldingmeshes
{
/**
 * The faces of `mesh` selected by `faceMask` as a prepared mesh: exactly what PrepareMesh
 * returns for the soup of those faces (in face order) and the points they use (in
 * increasing order), with mesh.vertexNormals of those points as input normals - the same
 * points, triangles, orientation, degenerate faces (the area floor from the subset's own
 * diagonal), normals (the sign of each from the subset's own faces), adjacency and parts.
 *
 * Welded points are distinct, so the weld is the identity; the edges come from
 * mesh.vertexFaces instead of a sort of all edge uses. When the subset's orientation walk
 * would turn a face against another one (a manifold edge of the subset traversed twice in
 * one direction, e.g. a non-manifold edge of `mesh` that is manifold in the subset) or a
 * selected face repeats a vertex, it calls PrepareMesh itself. Returns false where
 * PrepareMesh would (no face selected, zero area).
 */
bool PrepareFaceSubset(const PreparedMesh& mesh,
  const std::vector<char>& faceMask,
  PreparedMesh& subset);
}

#endif
