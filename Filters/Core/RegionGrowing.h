// Connected face regions (edge adjacency, plus links between nearby parts).
#ifndef foldingmeshes_RegionGrowing_h
#define foldingmeshes_RegionGrowing_h

#include "TriangleMesh.h"

#include <vector>

namespace foldingmeshes
{
/// Faces whose three vertices have d <= threshold (inclusive) or d < threshold (strict).
std::vector<char> FacesWithVerticesWithin(const PreparedMesh& mesh,
  const std::vector<double>& d,
  double threshold,
  bool strict);

/**
 * Labels the connected regions of the faces selected by `mask` (faces sharing an edge
 * are connected; so are faces at the two ends of a proximity link). labels[f] is the
 * region of f, or -1 outside the mask; regions are numbered by their lowest face id.
 * Returns the number of regions.
 */
int LabelConnectedRegions(const PreparedMesh& mesh,
  const std::vector<char>& mask,
  std::vector<int>& labels);

/// The connected region of `mask` with the largest area (ties: lowest face id).
std::vector<char> LargestConnectedRegion(const PreparedMesh& mesh, const std::vector<char>& mask);

/**
 * Every whole part of the mesh in `mask` (a connected component, the same edges and proximity
 * links, none of whose non-degenerate faces is outside `mask`), plus the largest connected
 * region of `mask` that is not made of whole parts only. Meshes assembled from separate parts (a
 * chair's legs, a plane's wings) have symmetry between parts: a leg maps onto the other leg, not
 * onto its own neighbours, so no single connected region holds it. A whole part within epsilon of
 * its mirror image is no accidental match; a piece of a part is left out as in the paper. On a mesh
 * of one part: exactly LargestConnectedRegion.
 */
std::vector<char> LargestRegionAndWholeParts(const PreparedMesh& mesh,
  const std::vector<char>& mask);

/// Whether the faces of `mesh` (edges and proximity links) form more than one part.
bool HasSeveralParts(const PreparedMesh& mesh);

/// Total area of the faces selected by mask.
double RegionArea(const PreparedMesh& mesh, const std::vector<char>& mask);

/// Area-weighted centroid of the faces selected by mask (zero when they have no area).
Vec3 RegionCentroid(const PreparedMesh& mesh, const std::vector<char>& mask);
}

#endif
