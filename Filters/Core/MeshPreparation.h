// Turns an indexed triangle soup into a PreparedMesh (welding, orientation, normals, adjacency).
#ifndef foldingmeshes_MeshPreparation_h
#define foldingmeshes_MeshPreparation_h

#include "TriangleMesh.h"

#include <string>

namespace foldingmeshes
{
/**
 * Prepare `input` for symmetry detection:
 * - points with identical coordinates are welded (the input is never changed);
 * - faces with a repeated vertex or (near) zero area are flagged degenerate;
 * - faces are oriented consistently across manifold edges by a breadth-first walk of
 *   each part; a closed part is turned outward (positive signed volume), an open part
 *   keeps the orientation most of its input faces had;
 * - unit face normals, area-weighted vertex normals, areas, centroids, edge adjacency.
 * If `inputNormals` is non-empty (one per input point) it is used for the vertex normals
 * instead of the computed ones. Returns false with `error` set for empty input,
 * non-finite coordinates, indices out of range or zero total area.
 */
bool PrepareMesh(const TriangleMesh& input,
  const std::vector<Vec3>& inputNormals,
  PreparedMesh& mesh,
  std::string& error);

/**
 * PrepareMesh's bounds (over the points that triangles use), diagonal, face areas, degenerate
 * faces (a repeated vertex, or an area not above 1e-12 diagonal^2) and total area, from
 * mesh.points and mesh.triangles (at least one triangle). Shared with PrepareFaceSubset,
 * which must give the same values bit for bit.
 */
void ComputeBoundsAndAreas(PreparedMesh& mesh);

/// For every point, the smallest index of a point with exactly the same coordinates (itself
/// when it has no earlier duplicate): the representatives of a weld of coincident points.
std::vector<int> CoincidentPointRepresentatives(const std::vector<Vec3>& points);

/**
 * Records, for every vertex with a vertex of another part closer than `gap`, the pair
 * (vertex, its nearest such vertex) in mesh.proximityLinks: linear in the mesh size even
 * for triangle soups. Region growing treats them as connections, so symmetric regions
 * may span touching parts.
 */
void LinkNearbyParts(PreparedMesh& mesh, double gap);

/// Per point (pointCount of them): 1 when it is an end of an edge used by exactly one of
/// `triangles` (a border or crack of that set of faces), else 0.
std::vector<char> BorderPoints(const std::vector<Triangle>& triangles, size_t pointCount);
}

#endif
