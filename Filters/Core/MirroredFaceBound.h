// Whether the mirror image of a face stays within a distance of a surface at every point,
// not only at its corners.
#ifndef foldingmeshes_MirroredFaceBound_h
#define foldingmeshes_MirroredFaceBound_h

#include "FaceTree.h"
#include "Plane.h"

#include <functional>
#include <vector>

namespace foldingmeshes
{
/**
 * For every triangle `faces[k]` (indices into `points`): true when every point x of its
 * mirror image through `plane` is provably closer than limit[k] to the surface of `mesh`
 * (plain Euclidean distance to its triangles; `queries` returns a closest-triangle query over
 * them - a FaceTreeQuery, which leaves degenerate triangles out, or a VTK cell locator, which
 * measures them as their edges - and is called once, serially, only if a face needs more
 * than the quick proof; any query gives a sound proof, the answers can differ only where
 * triangles tie for the closest). The
 * proof: dist(x, mesh) <= dist(x, T) for any triangle T of the mesh, and dist(., T) is convex,
 * so on a (sub)triangle P it is at most max over P's corners of dist(corner, T); T ranges
 * over the triangles closest to P's centroid and corners. Where that bound is not below the limit,
 * P is split into four at its edge midpoints, down to `depth` levels. False when a corner, centroid
 * or midpoint is itself not closer than the limit, or no proof was found within `depth` levels
 * (conservative). First the cheap proof, with no query: cornerDistance[v] (an upper bound of
 * the distance of v's mirror image, e.g. a compatible-face distance) is 1-Lipschitz-extended,
 * max over the corners + (longest edge) / sqrt(3), which settles most faces. In parallel
 * (vtkSMPTools), each face on its own: deterministic. A face's answer depends only on its
 * corners (in order), their cornerDistance, its limit and the surface `queries` answer for,
 * not on the other faces tested with it.
 */
std::vector<char> MirroredFacesWithin(const PreparedMesh& mesh,
  const std::function<const ClosestFaceQuery&()>& queries,
  const Plane& plane,
  const std::vector<Triangle>& faces,
  const std::vector<Vec3>& points,
  const std::vector<double>& cornerDistance,
  const std::vector<double>& limit,
  int depth);
}

#endif
