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
 * Welded points are distinct, so the weld is the identity; the edges come from a table of
 * edge uses (the overload below) or from
 * mesh.vertexFaces instead of a sort of all edge uses. When the subset's orientation walk
 * would turn a face against another one (a manifold edge of the subset traversed twice in
 * one direction, e.g. a non-manifold edge of `mesh` that is manifold in the subset) or a
 * selected face repeats a vertex, it calls PrepareMesh itself. Returns false where
 * PrepareMesh would (no face selected, zero area).
 */
bool PrepareFaceSubset(const PreparedMesh& mesh,
  const std::vector<char>& faceMask,
  PreparedMesh& subset);

/**
 * For each face f of a prepared mesh and each of its edges k (from corner k to corner k + 1),
 * the other faces that use that edge, with their direction: what PrepareFaceSubset otherwise
 * finds by scanning the faces around the edge's first point on every call. For a caller that
 * prepares several subsets of one mesh (Builder::Trim's loop).
 */
struct FaceEdgeUses
{
  std::vector<int> offsets; ///< 3 * faces + 1: the uses of edge k of face f start at 3 f + k
  std::vector<int> faces;   ///< the other face, in the order of the mesh's vertexFaces
  std::vector<signed char> directions; ///< +1: it runs the edge the same way, -1: opposite
};

/// The table of `mesh`'s edge uses (one scan of every face's edges; a PrepareFaceSubset call
/// without it scans the selected faces' edges).
FaceEdgeUses ComputeFaceEdgeUses(const PreparedMesh& mesh);

/// PrepareFaceSubset with `uses` = ComputeFaceEdgeUses(mesh): the same result, bit for bit
/// (a table of another size is ignored).
bool PrepareFaceSubset(const PreparedMesh& mesh,
  const std::vector<char>& faceMask,
  PreparedMesh& subset,
  const FaceEdgeUses& uses);
}

#endif
