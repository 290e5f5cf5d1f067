// Builder::Fold: projection/sliding onto the plane, error-budget charging, tear flags.
#include "FoldingTreeBuilderInternal.h"
#include "Trace.h"

#include "CandidatePlanes.h"
#include "MeshPreparation.h"
#include "MirrorDistance.h"
#include "ParallelTasks.h"
#include "PointKdTree.h"
#include "RegionGrowing.h"
#include "SurfaceDistance.h"

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <memory>
#include <numeric>

namespace foldingmeshes
{
namespace treebuilder
{
namespace
{
/**
 * The point of the intersection of the planes closest to x (planes[0] is the new fold plane,
 * the others ancestors' planes x already lies on). Planes nearly dependent on the others
 * (e.g. three planes through almost the same line) are treated as redundant (relative
 * singular-value threshold 1e-3); if the result is inconsistent - it misses a plane by more
 * than `tolerance`, or moves x much farther than the distances to the planes - x is only
 * projected onto planes[0] and false is returned (the caller then drops the ancestors'
 * flags the point no longer satisfies).
 */
bool ProjectOntoPlanes(Vec3& x, const std::vector<Plane>& planes, double tolerance)
{
  if (planes.size() == 1)
  {
    x = planes[0].Project(x);
    return true;
  }
  Eigen::MatrixXd A(planes.size(), 3);
  Eigen::VectorXd r(planes.size());
  double largest = 0.0;
  for (size_t k = 0; k < planes.size(); ++k)
  {
    A.row(k) = planes[k].normal.transpose();
    r[k] = -planes[k].SignedDistance(x);
    largest = std::max(largest, std::abs(r[k]));
  }
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(A);
  cod.setThreshold(1e-3);
  const Eigen::Vector3d delta = cod.solve(r);
  const Vec3 y = x + delta;
  bool consistent = delta.allFinite() && delta.norm() <= 4.0 * largest + tolerance;
  for (const Plane& p : planes)
    consistent = consistent && std::abs(p.SignedDistance(y)) <= tolerance;
  x = consistent ? y : planes[0].Project(x);
  return consistent;
}
}

bool KeepsPositiveSide(const std::vector<Vec3>& points,
  const std::vector<Triangle>& triangles,
  const Plane& plane,
  KeepSide keepSide)
{
  int positive = 0, negative = 0;
  for (const Triangle& t : triangles)
  {
    const double s = plane.SignedDistance((points[t[0]] + points[t[1]] + points[t[2]]) / 3.0);
    positive += s > 0;
    negative += s < 0;
  }
  return keepSide == KeepSide::MoreFaces ? positive >= negative : positive <= negative;
}

void Builder::TransferDiscardedTears(WorkMesh& w,
  const std::vector<char>& used,
  const Plane& plane,
  int depth,
  double eps) const
{
  const uint64_t bit = uint64_t(1) << depth;
  std::vector<int> lost;
  for (int v = 0; v < w.NumberOfPoints(); ++v)
    if (!used[v] && (w.tear[v] != 0 || !w.mirrorFlags[v].empty()))
      lost.push_back(v);
  if (lost.empty())
    return;
  // Boundary vertices of the region (all its faces, before the fold).
  const std::vector<char> boundary = BorderPoints(w.triangles, w.points.size());
  std::vector<int> keptIds;
  for (int v = 0; v < w.NumberOfPoints(); ++v)
    if (used[v] && boundary[v])
      keptIds.push_back(v);
  const PointKdTree kept(w.points, keptIds), removed(w.points, lost);
  auto transfer = [&](int t, int v)
  {
    auto& into = w.mirrorFlags[v];
    for (int level = 0; level < depth; ++level)
      if (w.tear[t] & (uint64_t(1) << level))
        into.push_back({ 2 * level, bit });
    for (const auto& e : w.mirrorFlags[t])
      if (e.first % 2 == 0) // plane flags are recomputed by FlagMirroredFoldLines
        into.push_back({ e.first, e.second | bit });
  };
  std::vector<std::pair<int, int>> pairs; // (kept, removed)
  for (int t : lost)
  {
    const int v = kept.NearestWithin(plane.Reflect(w.points[t]), eps);
    if (v >= 0)
      pairs.push_back({ v, t });
  }
  for (int v = 0; v < w.NumberOfPoints(); ++v)
    if (used[v] && boundary[v])
    {
      const int t = removed.NearestWithin(plane.Reflect(w.points[v]), eps);
      if (t >= 0)
        pairs.push_back({ v, t });
    }
  for (const auto& pr : pairs)
    transfer(pr.second, pr.first);
  for (const auto& pr : pairs)
  {
    auto& into = w.mirrorFlags[pr.first];
    std::sort(into.begin(), into.end());
    into.erase(std::unique(into.begin(), into.end()), into.end());
  }
}

void Builder::FlagMirroredFoldLines(WorkMesh& w,
  const std::vector<char>& keep,
  const Plane& plane,
  int depth,
  uint64_t pathFolds) const
{
  std::vector<int> ancestors; // increasing depth
  for (int d = 0; d < depth; ++d)
    if (pathFolds & (uint64_t(1) << d))
      ancestors.push_back(d);
  if (ancestors.empty())
    return;
  // Plane flags of earlier folds hold for where the vertex was then; projected onto this
  // fold's plane (or slid) it may have left the spot: a corner of a face that touched a fold
  // line's copy no longer does (a folded square's corner moved half a side). The unfolder
  // moves a flagged copy onto the plane within the error budget; a flag whose copy is now
  // farther than that fold's epsilon from its plane is stale.
  for (int v = 0; v < w.NumberOfPoints(); ++v)
  {
    auto& flags = w.mirrorFlags[v];
    flags.erase(std::remove_if(flags.begin(),
                  flags.end(),
                  [&](const std::pair<int, uint64_t>& e)
                  {
                    if (e.first % 2 == 0)
                      return false; // tear flags: kept
                    const int a = e.first / 2;
                    Vec3 y = w.points[v];
                    for (int d = depth - 1; d > a; --d)
                      if (e.second & (uint64_t(1) << d))
                        y = this->PlaneAtDepth[d].Reflect(y);
                    return std::abs(this->PlaneAtDepth[a].SignedDistance(y)) >
                      this->EpsilonAtDepth[a];
                  }),
      flags.end());
  }
  std::vector<Triangle> kept;
  for (int f = 0; f < w.NumberOfFaces(); ++f)
    if (keep[f])
      kept.push_back(w.triangles[f]);
  const std::vector<char> boundary = BorderPoints(kept, w.points.size());
  const uint64_t bit = uint64_t(1) << depth;
  for (int v = 0; v < w.NumberOfPoints(); ++v)
  {
    if (!boundary[v])
      continue;
    const Vec3 x = plane.Reflect(w.points[v]);
    for (size_t i = 0; i < ancestors.size(); ++i)
    {
      const int a = ancestors[i];
      const Plane& pa = this->PlaneAtDepth[a];
      const double tolerance = std::max(
        this->Options.planeSnapFraction * this->EpsilonAtDepth[a], 1e-12 * this->Tree.diagonal);
      // Folds between a and this fold, deepest first.
      std::vector<int> between(ancestors.begin() + i + 1, ancestors.end());
      std::reverse(between.begin(), between.end());
      const size_t combinations = size_t(1) << between.size();
      for (size_t m = 0; m < combinations; ++m)
      {
        Vec3 y = x;
        uint64_t mask = bit;
        for (size_t k = 0; k < between.size(); ++k)
          if (m & (size_t(1) << k))
          {
            y = this->PlaneAtDepth[between[k]].Reflect(y);
            mask |= uint64_t(1) << between[k];
          }
        if (std::abs(pa.SignedDistance(y)) <= tolerance)
          w.mirrorFlags[v].push_back({ 2 * a + 1, mask });
      }
    }
    std::sort(w.mirrorFlags[v].begin(), w.mirrorFlags[v].end());
    w.mirrorFlags[v].erase(
      std::unique(w.mirrorFlags[v].begin(), w.mirrorFlags[v].end()), w.mirrorFlags[v].end());
  }
}

namespace
{
/// Per discarded-side vertex of a kept face, the point where one of its edges to a kept-side
/// vertex crosses the plane, nearest to its orthogonal projection (on the input surface):
/// slide[v], with slides[v] = 1 where there is one.
void SlideTargets(const WorkMesh& w,
  const std::vector<char>& keep,
  const std::vector<int>& side,
  const Plane& plane,
  std::vector<Vec3>& slide,
  std::vector<char>& slides)
{
  const int nf = w.NumberOfFaces();

  std::vector<double> slideMove(w.points.size(), std::numeric_limits<double>::infinity());
  for (int f = 0; f < nf; ++f)
    if (keep[f])
      for (int k = 0; k < 3; ++k)
        for (int j = 1; j <= 2; ++j)
        {
          const int v = w.triangles[f][k], a = w.triangles[f][(k + j) % 3];
          if (side[v] >= 0 || side[a] <= 0)
            continue;
          const double sv = plane.SignedDistance(w.points[v]);
          const double sa = plane.SignedDistance(w.points[a]);
          const Vec3 q = w.points[v] + (sv / (sv - sa)) * (w.points[a] - w.points[v]);
          const double move = (q - plane.Project(w.points[v])).norm();
          if (move < slideMove[v])
          {
            slideMove[v] = move;
            slide[v] = plane.Project(q); // exactly on the plane
            slides[v] = 1;
          }
        }
}

/// The largest distance of a point projected (or snapped) onto the fold plane(s), or of the
/// centroid of a kept face one moved, to the region as it was; each point's budget becomes
/// what is left of its limit after its mirror charge and that displacement.
double SpendProjectionBudget(WorkMesh& w,
  const std::vector<char>& used,
  const std::vector<char>& keep,
  const std::vector<int>& side,
  const SurfaceDistanceQuery& toRegion,
  const std::vector<double>& charge,
  const std::vector<double>& limit)
{
  const int nf = w.NumberOfFaces();
  double projectionError = 0.0;

  std::vector<Vec3> moved;
  std::vector<int> movedPoint, movedFace;
  for (int v = 0; v < w.NumberOfPoints(); ++v)
    if (used[v] && side[v] <= 0)
    {
      moved.push_back(w.points[v]);
      movedPoint.push_back(v);
    }
  // Faces changed by a move: their centroids too (a slid vertex is on the surface, its
  // faces need not be).
  for (int f = 0; f < nf; ++f)
  {
    const Triangle& t = w.triangles[f];
    if (keep[f] && (side[t[0]] < 0 || side[t[1]] < 0 || side[t[2]] < 0))
    {
      moved.push_back((w.points[t[0]] + w.points[t[1]] + w.points[t[2]]) / 3.0);
      movedFace.push_back(f);
    }
  }
  const std::vector<double> d = toRegion.Distances(moved);
  std::vector<double> displacement(w.points.size(), 0.0);
  for (size_t k = 0; k < movedPoint.size(); ++k)
    displacement[movedPoint[k]] = std::max(displacement[movedPoint[k]], d[k]);
  for (size_t k = 0; k < movedFace.size(); ++k)
    for (int v : w.triangles[movedFace[k]])
      displacement[v] = std::max(displacement[v], d[movedPoint.size() + k]);
  for (int v = 0; v < w.NumberOfPoints(); ++v)
  {
    projectionError = std::max(projectionError, displacement[v]);
    w.budget[v] = std::max(0.0, limit[v] - charge[v] - displacement[v]);
  }
  return projectionError;
}

}

/**
 * What the copies made by a fold add at each kept point (see Fold): a kept point's mirror copy
 * must lie near the input (error: its distance to the input); a discarded point must be
 * reproduced by the mirror copy of the kept half (error: the distance of its mirror image to
 * the region), charged to the kept point nearest to that image. Fills charge and limit (the
 * least budget of the points a charge lands on); returns the largest error.
 */
double Builder::ChargeMirrorError(const WorkMesh& w,
  const std::vector<char>& used,
  const Plane& plane,
  double eps,
  const SurfaceDistanceQuery& toRegion,
  std::vector<double>& charge,
  std::vector<double>& limit) const
{
  double mirrorError = 0.0;

  const int np = w.NumberOfPoints();
  std::vector<Vec3> mirrored(np);
  for (int v = 0; v < np; ++v)
    mirrored[v] = plane.Reflect(w.points[v]);
  const std::vector<double> toS = toRegion.Distances(mirrored);
  const std::vector<double> toM = this->ToInput.Distances(mirrored);
  std::vector<int> keptIds;
  double least = std::numeric_limits<double>::infinity();
  for (int v = 0; v < np; ++v)
  {
    if (used[v])
      keptIds.push_back(v);
    least = std::min(least, w.budget[v]);
  }
  const PointKdTree all(w.points), kept(w.points, keptIds);
  // Each point's charged kept point and the point nearest its mirror image, every point alone
  // (read-only trees); then the charges, in point order.
  std::vector<int> chargedPoint(np, -1), nearestPoint(np, -1);
  ForRanges(np,
    256,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType v = first; v < last; ++v)
      {
        chargedPoint[v] = used[v] ? static_cast<int>(v) : kept.NearestWithin(mirrored[v], eps);
        if (chargedPoint[v] >= 0)
          nearestPoint[v] = all.NearestWithin(mirrored[v], eps);
      }
    });
  for (int v = 0; v < np; ++v)
  {
    const double e = used[v] ? toM[v] : toS[v];
    mirrorError = std::max(mirrorError, e);
    const int k = chargedPoint[v];
    if (k < 0)
      continue; // no kept point there: its copy reproduces nothing of v
    const int p = nearestPoint[v];
    charge[k] = std::max(charge[k], e);
    limit[k] = std::min({ limit[k], w.budget[v], p >= 0 ? w.budget[p] : least });
  }
  for (int v = 0; v < w.NumberOfPoints(); ++v)
    limit[v] = std::min(limit[v], w.budget[v]);
  return mirrorError;
}

/**
 * Moves the kept points on or behind the fold plane onto it (the paper's fold rule: faces
 * straddling the plane keep their far vertices, projected): orthogonally by default, onto the
 * intersection with the ancestors' planes the point lies on when that is within eps of the
 * orthogonal projection, or slid along an edge (SlideTargets) when slideOntoPlane asks for it
 * or when beyondBudget(v) says the projection would leave the budget. Flags the points on the
 * plane; returns how many were projected from behind it.
 */
template <typename BeyondBudget>
int Builder::ProjectOntoFoldPlane(WorkMesh& w,
  const std::vector<char>& used,
  const std::vector<int>& side,
  const Plane& plane,
  int depth,
  double eps,
  uint64_t pathFolds,
  const std::vector<Vec3>& slide,
  const std::vector<char>& slides,
  BeyondBudget beyondBudget)
{
  const uint64_t bit = uint64_t(1) << depth;
  int projected = 0;
  for (int v = 0; v < w.NumberOfPoints(); ++v)
  {
    if (!used[v] || side[v] > 0)
      continue;
    bool onAncestorPlane = false;
    for (int d = 0; d < depth; ++d)
      onAncestorPlane = onAncestorPlane ||
        ((w.onPlane[v] & (uint64_t(1) << d)) && (pathFolds & (uint64_t(1) << d)));
    // Projecting is the default; sliding when asked for, or when the projected point
    // would be farther from the region than the error budget left there.
    bool slideIt = slides[v] && !onAncestorPlane && side[v] < 0;
    if (slideIt && !this->Options.slideOntoPlane)
      slideIt = beyondBudget(v);
    if (slideIt)
    {
      w.points[v] = slide[v];
      w.onPlane[v] |= bit;
      w.projected[v] = 1;
      ++projected;
      continue;
    }
    std::vector<Plane> constraints{ plane };
    for (int d = 0; d < depth; ++d)
      if ((w.onPlane[v] & (uint64_t(1) << d)) && (pathFolds & (uint64_t(1) << d)))
        constraints.push_back(this->PlaneAtDepth[d]);
    const double tolerance = 1e-9 * this->Tree.diagonal;
    // The intersection of the planes keeps the ancestors' fold lines closed, but only where
    // it is close to the orthogonal projection: a vertex that merely touches an ancestor's
    // plane at a corner of its faces (the plane does not run along them) would be dragged
    // along the new plane, up to the whole face away (a face of a folded square collapsed
    // onto a point and was lost). Farther than epsilon, it is projected orthogonally and
    // leaves the ancestors' planes.
    const Vec3 orthogonal = plane.Project(w.points[v]);
    Vec3 target = w.points[v];
    bool onAll = ProjectOntoPlanes(target, constraints, tolerance);
    if (onAll && constraints.size() > 1 && (target - orthogonal).norm() > eps)
    {
      target = orthogonal;
      onAll = false;
    }
    w.points[v] = target;
    if (!onAll)
      for (int d = 0; d < depth; ++d)
        if ((w.onPlane[v] & (uint64_t(1) << d)) &&
          std::abs(this->PlaneAtDepth[d].SignedDistance(w.points[v])) > tolerance)
          w.onPlane[v] &= ~(uint64_t(1) << d);
    w.onPlane[v] |= bit;
    if (side[v] < 0)
    {
      w.projected[v] = 1;
      ++projected;
    }
  }
  return projected;
}

/**
 * The paper's fold (section 4.2) of region `w` at `plane`: keep the faces on the kept side and
 * those straddling the plane, charge the mirror copies' error (ChargeMirrorError), move the
 * kept points on or behind the plane onto it (SlideTargets, ProjectOntoFoldPlane), spend the
 * budgets (SpendProjectionBudget), record the node and build the kept half one level down.
 * (Over 100 lines because it is that sequence with the face classification and the node
 * record inline; each step is named.)
 */
void Builder::Fold(int index,
  WorkMesh w,
  Plane plane,
  int depth,
  double eps,
  int folds,
  uint64_t pathFolds,
  int provenSide)
{
  const FoldingTreeOptions& O = this->Options;
  const int nf = w.NumberOfFaces();
  // The side the trim's face proof covered (a near tie that the final S tips the other way
  // would keep unproved faces); without a proof, the side keepSide chooses.
  if (provenSide != 0 ? provenSide < 0
                      : !KeepsPositiveSide(w.points, w.triangles, plane, O.keepSide))
    plane.normal = -plane.normal;

  const double snap = std::max(O.planeSnapFraction * eps, 1e-12 * this->Tree.diagonal);
  std::vector<int> side(w.points.size());
  for (int v = 0; v < w.NumberOfPoints(); ++v)
  {
    const double s = plane.SignedDistance(w.points[v]);
    side[v] = s > snap ? 1 : (s < -snap ? -1 : 0);
  }
  std::vector<char> keep(nf, 0);
  std::vector<int> discarded;
  for (int f = 0; f < nf; ++f)
  {
    const Triangle& t = w.triangles[f];
    const int hi = std::max({ side[t[0]], side[t[1]], side[t[2]] });
    const int lo = std::min({ side[t[0]], side[t[1]], side[t[2]] });
    keep[f] = hi == 1 || (hi == 0 && lo == 0);
    if (!keep[f])
      discarded.push_back(w.faceOrig[f]);
  }
  // A fold that removes no face (every face of S straddles the plane, e.g. S is a single
  // triangle) stores as many faces as before and doubles them on unfolding; repeated, it
  // never ends when no stop criterion is on. Such a region stays a leaf (whatever the
  // options: a hard bound like the depth bound).
  if (discarded.empty())
  {
    this->MakeLeaf(index, w, LeafReason::NoSymmetry);
    return;
  }
  std::vector<char> used(w.points.size(), 0);
  for (int f = 0; f < nf; ++f)
    if (keep[f])
      for (int v : w.triangles[f])
        used[v] = 1;
  // The error this fold adds to unfold(): the largest distance of a mirrored vertex of the
  // region to the region (both halves: either may be the one reproduced), before projection.
  TriangleMesh region;
  region.points = w.points;
  region.triangles = w.triangles;
  const SurfaceDistanceQuery toRegion(region);
  // Per kept point: what the copies made by this fold add there. A kept point's mirror
  // copy must lie near the input (error: its distance to the input); a discarded point must
  // be reproduced by the mirror copy of the kept half (error: the distance of its mirror
  // image to the region), charged to the kept point nearest to that image. Either lands
  // where the budget of the partner point applies too.
  std::vector<double> charge(w.points.size(), 0.0),
    limit(w.points.size(), std::numeric_limits<double>::infinity());
  double mirrorError = 0.0;
  if (O.errorBudget)
    mirrorError = this->ChargeMirrorError(w, used, plane, eps, toRegion, charge, limit);
  this->TransferDiscardedTears(w, used, plane, depth, eps);
  const uint64_t bit = uint64_t(1) << depth;
  // Sliding (see FoldingTreeOptions::slideOntoPlane): per discarded-side vertex, the point
  // where one of its edges to a kept-side vertex of a kept face crosses the plane, nearest
  // to its orthogonal projection. That point lies on the input surface.
  std::vector<Vec3> slide(w.points.size());
  std::vector<char> slides(w.points.size(), 0);
  if (O.slideOntoPlane || O.errorBudget)
    SlideTargets(w, keep, side, plane, slide, slides);
  const int projected = this->ProjectOntoFoldPlane(w,
    used,
    side,
    plane,
    depth,
    eps,
    pathFolds,
    slide,
    slides,
    [&](int v) { return charge[v] + toRegion.Distance(plane.Project(w.points[v])) > limit[v]; });

  // ... plus the largest distance of a point projected (or snapped) onto the plane(s) to
  // the region as it was.
  double projectionError = 0.0;
  if (O.errorBudget)
    projectionError = SpendProjectionBudget(w, used, keep, side, toRegion, charge, limit);
  double childBudget = eps;
  for (int v = 0; v < w.NumberOfPoints(); ++v)
    if (used[v])
      childBudget = std::min(childBudget, w.budget[v]);
  if (this->Options.trace)
    this->Options.trace(
      FormatTrace("[fold] node %d depth %d eps %.3g: mirror error %.3g, projection "
                  "error %.3g, least child budget %.3g",
        index,
        depth,
        eps,
        mirrorError,
        projectionError,
        childBudget));

  this->FlagMirroredFoldLines(w, keep, plane, depth, pathFolds);

  FoldingNode& node = this->Tree.nodes[index];
  node.kind = FoldingNodeKind::Folding;
  node.plane = plane;
  node.discardedFaces = static_cast<int>(discarded.size());
  node.projectedPoints = projected;
  std::sort(discarded.begin(), discarded.end());
  node.discardedOriginalFaces = std::move(discarded);
  this->DoneFaces += node.discardedFaces;
  this->Report(this->Fraction(this->DoneFaces));

  this->PlaneAtDepth[depth] = plane;
  this->EpsilonAtDepth[depth] = eps;
  WorkMesh half = Extract(w, keep);
  this->Build(std::move(half), index, depth + 1, 0.5 * eps, folds + 1, pathFolds | bit);
}
}
}
