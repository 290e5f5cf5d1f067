// Candidate mirror planes: the paper's closed-form principal planes and pair voting.
#ifndef foldingmeshes_CandidatePlanes_h
#define foldingmeshes_CandidatePlanes_h

#include "Plane.h"

#include <array>
#include <vector>

namespace foldingmeshes
{
/**
 * The closed-form step of the paper: weighted centroid m and weighted covariance C of
 * the vertices; the three planes through m normal to C's eigenvectors (ascending
 * eigenvalue). Returns false when the weights sum to zero.
 */
bool PrincipalPlanes(const PreparedMesh& mesh,
  const std::vector<double>& weights,
  std::array<Plane, 3>& planes);

/**
 * One Gauss-Newton step of a point-to-plane fit of the mirror plane: finds the small
 * change of `current` (tilt of the normal, shift of the offset) that best moves each
 * reflected point onto the tangent plane of its partner q_i (unit surface normal m_i at
 * q_i), by weighted linear least squares. Unlike the principal axes of the weighted
 * points, the fixed point does not move when mirror-image vertices carry unequal weights
 * (differently tessellated halves), and tangential sliding costs nothing, so it converges
 * in a few steps. The tilt is limited to 10 degrees per step. Returns false without
 * information.
 */
bool RefinePlaneFromCorrespondences(const std::vector<Vec3>& points,
  const std::vector<Vec3>& partners,
  const std::vector<Vec3>& partnerNormals,
  const std::vector<double>& weights,
  const Plane& current,
  Plane& plane);

/**
 * The three planes through the area centroid of the *surface* normal to the principal
 * axes of its exact second moments (triangle integrals, independent of the tessellation:
 * for a mirror-symmetric surface one of them is the mirror plane).
 */
bool SurfacePrincipalPlanes(const PreparedMesh& mesh, std::array<Plane, 3>& planes);
/// The same for the faces f with faceMask[f] nonzero only (e.g. one part of the mesh).
bool SurfacePrincipalPlanes(const PreparedMesh& mesh,
  const std::vector<char>& faceMask,
  std::array<Plane, 3>& planes);

/**
 * Whether two eigenvalues of the surface's second moments (about its area centroid, exact
 * triangle integrals) agree within `relativeGap` times the larger of the two: a necessary condition for
 * a rotational symmetry of order 3 or more of the whole surface about any axis (such a turn
 * maps the moment tensor onto itself, so it is axially symmetric about that axis), cheap to
 * test. False without area.
 */
bool AxiallySymmetricSecondMoments(const TriangleMesh& mesh, double relativeGap);

/**
 * Planes voted for by random vertex pairs (p, q) whose normals are mirror images of each
 * other across their bisector plane (within 25 degrees): the bisector planes are clustered
 * (normals within 4 degrees, offsets within epsilon, votes weighted by vertex area) and
 * the `count` strongest distinct clusters returned, strongest first. Deterministic for a seed.
 */
std::vector<Plane> VotedPlanes(const PreparedMesh& mesh, int count, double epsilon, unsigned seed);
}

#endif
