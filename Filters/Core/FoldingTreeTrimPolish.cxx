// Builder: choosing S among detection's planes, trimming S to its mirror-consistent part and
// polishing the fold plane on S.
#include "FoldingTreeBuilderInternal.h"

#include "CandidatePlanes.h"
#include "MeshPreparation.h"
#include "MirrorDistance.h"
#include "MirroredFaceBound.h"
#include "RegionGrowing.h"
#include "ShrinkingMirrorBudget.h"
#include "ShrinkingSubsetDistances.h"
#include "SubsetPreparation.h"
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
/// On a mesh of several parts, whole parts join S when its connected region covers less than
/// this share of the node's area (see ChooseSymmetricRegion).
constexpr double WholePartsBelowShare = 0.75;
}

bool Builder::PrepareSubset(const WorkMesh& /*w*/,
  const PreparedMesh& pm,
  const std::vector<char>& S,
  const FaceEdgeUses& edgeUses,
  PreparedMesh& spm)
{
  // w's points and (oriented) triangles are pm's: pm welded nothing (see Build).
  // The region's vertex normals (not the sub-mesh's), as detection used them.
  return PrepareFaceSubset(pm, S, spm, edgeUses);
}

Plane Builder::Polish(const WorkMesh& w,
  const PreparedMesh& pm,
  const std::vector<char>& S,
  const Plane& plane,
  double eps,
  const FaceEdgeUses& edgeUses,
  PreparedSubsetQueries* prepared) const
{
  auto subset = std::make_unique<PreparedMesh>();
  if (!PrepareSubset(w, pm, S, edgeUses, *subset))
    return plane;
  const PreparedMesh& spm = *subset;
  auto queries = std::make_unique<MirrorDistance>(spm, this->Options.symmetry.compatibilityAngle);
  MirrorDistance& distances = *queries;
  std::vector<double> d;
  std::vector<Vec3> closest, closestNormals;
  Plane current = plane, best = plane;
  double bestCost = std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration < 12; ++iteration)
  {
    distances.Compute(current, DistanceMetric::Fine, eps, d, &closest, &closestNormals);
    double cost = 0.0;
    std::vector<double> weights(d.size(), 0.0);
    for (size_t v = 0; v < d.size(); ++v)
    {
      const double dv = std::isfinite(d[v]) ? d[v] : eps;
      cost += spm.vertexAreas[v] * dv * dv;
      if (std::isfinite(d[v]))
        weights[v] = spm.vertexAreas[v];
    }
    if (!(cost < bestCost))
      break;
    bestCost = cost;
    best = current;
    Plane next;
    if (!RefinePlaneFromCorrespondences(
          spm.points, closest, closestNormals, weights, current, next))
      break;
    const bool small = PlaneAngleDegrees(next, current) < 1e-7 &&
      PlaneOffsetAt(current, next, next.origin) < 1e-12 * this->Tree.diagonal;
    current = next;
    if (small)
      break;
  }
  if (prepared)
    *prepared = PreparedSubsetQueries{ std::move(subset), std::move(queries) };
  return CanonicalPlane(best, plane.origin);
}

std::vector<char> Builder::TrimAndPolish(const WorkMesh& w,
  const PreparedMesh& pm,
  const FaceTree& region,
  std::vector<char> S,
  double eps,
  bool wholeParts,
  double winAbove,
  Plane& plane,
  int& provenSide) const
{
  provenSide = 0;
  if (std::find(S.begin(), S.end(), 1) == S.end())
    return S;
  // Trimming keeps the faces whose mirrored vertices are within eps of S - or within the
  // error budget left there, if less (errorBudget).
  // The region's edge uses, for every subset prepared below.
  const FaceEdgeUses edgeUses = ComputeFaceEdgeUses(pm);
  if (this->Options.trimToMirrorConsistent)
    S = this->Trim(w, pm, region, S, plane, eps, wholeParts, winAbove, provenSide, edgeUses);
  // Polishing and trimming again only shrink S further: one already no larger than winAbove
  // is done with.
  if (RegionArea(pm, S) <= winAbove)
    return std::vector<char>(S.size(), 0);
  if (this->Options.polishPlane)
  {
    // S prepared and its face tree, made by Polish, start the second trim.
    PreparedSubsetQueries prepared;
    plane = this->Polish(w, pm, S, plane, eps, edgeUses, &prepared);
    provenSide = 0; // the proof was for the plane before polishing
    if (this->Options.trimToMirrorConsistent)
      S = this->Trim(w,
        pm,
        region,
        S,
        plane,
        eps,
        wholeParts,
        winAbove,
        provenSide,
        edgeUses,
        std::move(prepared));
  }
  return S;
}

std::vector<char> Builder::ChooseSymmetricRegion(const WorkMesh& w,
  const PreparedMesh& pm,
  const FaceTree& region,
  const SymmetryResult& result,
  double eps,
  uint64_t pathFolds,
  Plane& plane,
  int& provenSide) const
{
  const int nf = w.NumberOfFaces();
  std::vector<char> best(nf, 0);
  for (int f = 0; f < nf; ++f)
    best[f] = result.faceLabel[f] == 2;
  plane = result.plane;
  // The detector's region is one connected region. On a mesh of several parts where it covers
  // less than three quarters of the node, parts that map onto other parts join it (and the regions
  // of the other candidate planes and the trimmed regions keep their whole parts too). Where the
  // connected region already covers most of the node the paper's region is kept: measured on
  // the artist-like corpus, whole parts there lead the greedy folds to worse trees (the rack
  // 87.6% -> 79.1%, the slatted bench 93.4% -> 66.2%).
  const bool wholeParts =
    HasSeveralParts(pm) && RegionArea(pm, best) < WholePartsBelowShare * pm.totalArea;
  std::unique_ptr<MirrorDistance> distances;
  std::vector<double> d;
  if (wholeParts)
  {
    distances =
      std::make_unique<MirrorDistance>(pm, region, this->Options.symmetry.compatibilityAngle);
    distances->Compute(plane, DistanceMetric::Fine, eps, d);
    std::vector<char> mask = FacesWithVerticesWithin(pm, d, eps, true);
    for (int f = 0; f < nf; ++f)
      mask[f] = mask[f] || best[f];
    const std::vector<char> parts = LargestRegionAndWholeParts(pm, mask);
    for (int f = 0; f < nf; ++f)
      best[f] = best[f] || parts[f];
  }
  const double untrimmedArea = RegionArea(pm, best);
  best = this->TrimAndPolish(w,
    pm,
    region,
    std::move(best),
    eps,
    wholeParts,
    -std::numeric_limits<double>::infinity(),
    plane,
    provenSide);
  double bestArea = RegionArea(pm, best);
  // A trace line per plane tried: S before trimming, and after (`after`), or not trimmed
  // (its S no larger than the best), or trimmed only until it could not beat the best.
  enum class Trimmed
  {
    Fully,
    Not,
    UntilBeaten
  };
  auto trace = [&](const Plane& p, double before, double after, Trimmed how)
  {
    if (!this->Options.trace)
      return;
    this->Options.trace(FormatTrace("[region] n=(%.3f %.3f %.3f): S %.3f of the area, %s%.3f%s",
      p.normal.x(),
      p.normal.y(),
      p.normal.z(),
      before / pm.totalArea,
      how == Trimmed::Fully   ? "trimmed "
        : how == Trimmed::Not ? "not trimmed, no larger than the best "
                              : "trimmed until no larger than the best ",
      (how == Trimmed::Fully ? after : bestArea) / pm.totalArea,
      wholeParts ? " (with whole parts)" : ""));
  };
  trace(plane, untrimmedArea, bestArea, Trimmed::Fully);
  if (!this->Options.trimToMirrorConsistent)
  {
    for (int f = 0; f < nf; ++f)
      best[f] = best[f] && !this->IsPinned(w, f);
    return best;
  }
  // The finalists scored only for the whole parts (SymmetryOptions::scoreEveryFinalist) are
  // tried only with them: without, the search's own ranking stands.
  const size_t candidates = wholeParts
    ? std::min(result.finalists.size(), RegionCandidatePlanes + MultiPartCandidatePlanes)
    : std::min(result.rankedFinalists, RegionCandidatePlanes);
  for (size_t k = 1; k < candidates; ++k)
  {
    Plane candidate = result.finalists[k];
    if (PlaneAngleDegrees(candidate, result.plane) < 2.0 &&
      PlaneOffsetAt(result.plane, candidate, candidate.origin) < eps)
      continue;
    if (!distances)
      distances =
        std::make_unique<MirrorDistance>(pm, region, this->Options.symmetry.compatibilityAngle);
    distances->Compute(candidate, DistanceMetric::Fine, eps, d);
    const std::vector<char> within = FacesWithVerticesWithin(pm, d, eps, true);
    std::vector<char> S =
      wholeParts ? LargestRegionAndWholeParts(pm, within) : LargestConnectedRegion(pm, within);
    // Trimming only removes faces: a region no larger than the best S cannot win.
    const double candidateArea = RegionArea(pm, S);
    if (!(candidateArea > bestArea))
    {
      trace(candidate, candidateArea, 0.0, Trimmed::Not);
      continue;
    }
    if (this->IsAncestorPlane(candidate, pathFolds, RegionCentroid(pm, S), eps))
      continue;
    int side = 0;
    // Trimming and polishing stop once S cannot beat the best (empty S then).
    S =
      this->TrimAndPolish(w, pm, region, std::move(S), eps, wholeParts, bestArea, candidate, side);
    const double area = RegionArea(pm, S);
    const bool stopped = std::find(S.begin(), S.end(), 1) == S.end();
    trace(candidate, candidateArea, area, stopped ? Trimmed::UntilBeaten : Trimmed::Fully);
    if (area > bestArea)
    {
      best = std::move(S);
      bestArea = area;
      plane = candidate;
      provenSide = side;
    }
  }
  return best;
}

namespace
{
/// Subdivision levels of MirroredFacesWithin: pieces 1/64 of the face's size, where a long
/// face lies over several coplanar faces of the region (only the pieces over their shared
/// edges need that depth).
constexpr int MirroredFaceLevels = 6;

/// A closest-face query (the user's locator) over the faces of `mesh` in `subset`, answering
/// with the faces' ids in `mesh`.
class SubsetFaceQuery : public ClosestFaceQuery
{
public:
  SubsetFaceQuery(const PreparedMesh& mesh,
    const std::vector<char>& subset,
    const ClosestFaceQueryFactory& factory)
  {
    TriangleMesh part{ mesh.points, {} };
    for (size_t f = 0; f < subset.size(); ++f)
      if (subset[f])
      {
        part.triangles.push_back(mesh.triangles[f]);
        this->Ids.push_back(static_cast<int>(f));
      }
    this->Inner = factory(part);
  }
  ClosestFaceHit Closest(const Vec3& p) const override
  {
    return this->Mapped(this->Inner->Closest(p));
  }
  ClosestFaceHit ClosestWithin(const Vec3& p, double radius) const override
  {
    return this->Mapped(this->Inner->ClosestWithin(p, radius));
  }

private:
  ClosestFaceHit Mapped(ClosestFaceHit hit) const
  {
    if (hit.face >= 0)
      hit.face = this->Ids[hit.face];
    return hit;
  }
  std::vector<int> Ids;
  std::unique_ptr<ClosestFaceQuery> Inner;
};
}

std::vector<char> Builder::Trim(const WorkMesh& w,
  const PreparedMesh& pm,
  const FaceTree& region,
  std::vector<char> S,
  const Plane& plane,
  double eps,
  bool wholeParts,
  double winAbove,
  int& provenSide,
  const FaceEdgeUses& edgeUses,
  PreparedSubsetQueries prepared) const
{
  provenSide = 0;
  // One plane while S only shrinks: the iterations after the first update what changed
  // (distances, budget partners) instead of starting over - bit for bit the same results (see
  // the classes).
  ShrinkingSubsetDistances distances(
    pm, plane, this->Options.symmetry.compatibilityAngle, eps, &edgeUses);
  distances.Adopt(std::move(prepared));
  ShrinkingMirrorBudget budget(w.points, w.budget, plane, eps);
  // The mirrored-face proof's closest triangles: those of S itself (the region's face tree
  // without the faces that left S, or the user's locator over S, built when a face first
  // needs it), not of the whole region - a kept face whose mirror image lies on faces outside
  // S would be unfolded on top of them, the surface there twice (issue 21). S shrinks from
  // iteration to iteration, so each iteration proves its faces anew.
  std::vector<char> outsideS(S.size());
  std::unique_ptr<SubsetFaceQuery> locatorQueries;
  for (int iteration = 0; iteration < 8; ++iteration)
  {
    if (!distances.Update(S))
      break;
    for (size_t f = 0; f < S.size(); ++f)
      outsideS[f] = !S[f];
    const FaceTreeQuery treeQueries(region, &outsideS);
    locatorQueries.reset();
    const auto queries = [&]() -> const ClosestFaceQuery&
    {
      if (this->Options.verificationQueries && !locatorQueries)
        locatorQueries.reset(new SubsetFaceQuery(pm, S, this->Options.verificationQueries));
      return locatorQueries ? *locatorQueries : static_cast<const ClosestFaceQuery&>(treeQueries);
    };
    const PreparedMesh& spm = distances.Subset();
    std::vector<double> d = distances.Distances();
    std::vector<double> vertexLimit(d.size(), eps);
    if (this->Options.errorBudget)
    {
      // The vertices of S are spm's points, in increasing order of their ids in w.
      std::vector<int> ids;
      {
        std::vector<char> inS(w.points.size(), 0);
        for (int f = 0; f < w.NumberOfFaces(); ++f)
          if (S[f])
            for (int v : w.triangles[f])
              inS[v] = 1;
        for (int v = 0; v < w.NumberOfPoints(); ++v)
          if (inS[v])
            ids.push_back(v);
      }
      const std::vector<double> limit = budget.Limits(ids);
      for (size_t k = 0; k < d.size() && k < ids.size(); ++k)
      {
        vertexLimit[k] = std::min(eps, limit[k]);
        if (!(d[k] < limit[k]))
          d[k] = std::numeric_limits<double>::infinity();
      }
    }
    std::vector<char> ok = FacesWithVerticesWithin(spm, d, eps, true);
    // The faces of S in w (and pm) ids, in spm's order.
    std::vector<int> faceOf;
    for (int f = 0; f < w.NumberOfFaces(); ++f)
      if (S[f])
        faceOf.push_back(f);
    // What is left of S lies in its faces kept so far: the face proof below only removes
    // more, and the largest region (with whole parts) adds at most degenerate faces, of area
    // 0 in pm. Their area, summed in RegionArea's order, bounds S's from above, also in
    // floating point (adding a non-negative term never lowers a sum).
    if (winAbove > -std::numeric_limits<double>::infinity())
    {
      double keptArea = 0.0;
      for (size_t k = 0; k < faceOf.size(); ++k)
        if (ok[k] || spm.faceDegenerate[k])
          keptArea += pm.faceAreas[faceOf[k]];
      if (keptArea <= winAbove)
        return std::vector<char>(S.size(), 0);
    }
    if (this->Options.errorBudget)
    {
      // ... and the whole mirror image of each face, not only its corners, within the limit
      // of S (a copy passing over a dip of the surface would leave the budget between its
      // corners; one lying on faces outside S would lay surface twice).
      // Only the faces the fold will keep are copied (those with a vertex on the kept side).
      const double keptSign =
        KeepsPositiveSide(spm.points, spm.triangles, plane, this->Options.keepSide) ? 1.0 : -1.0;
      provenSide = keptSign > 0 ? 1 : -1;
      std::vector<Triangle> faces;
      std::vector<double> faceLimit;
      std::vector<int> at;
      for (int k = 0; k < spm.NumberOfFaces(); ++k)
        if (ok[k] && !spm.faceDegenerate[k] &&
          std::max({ keptSign * plane.SignedDistance(spm.points[spm.triangles[k][0]]),
            keptSign * plane.SignedDistance(spm.points[spm.triangles[k][1]]),
            keptSign * plane.SignedDistance(spm.points[spm.triangles[k][2]]) }) > 0.0)
        {
          const Triangle& t = spm.triangles[k];
          faces.push_back(t);
          faceLimit.push_back(
            std::min({ vertexLimit[t[0]], vertexLimit[t[1]], vertexLimit[t[2]] }));
          at.push_back(k);
        }
      const std::vector<char> within = MirroredFacesWithin(
        pm, queries, plane, faces, spm.points, d, faceLimit, MirroredFaceLevels);
      for (size_t j = 0; j < at.size(); ++j)
        ok[at[j]] = within[j];
    }
    std::vector<char> next = S;
    bool changed = false;
    for (size_t k = 0; k < faceOf.size(); ++k)
      // Degenerate faces have no distance of their own: judged with their neighbours.
      if ((!ok[k] && !spm.faceDegenerate[k]) || this->IsPinned(w, faceOf[k]))
      {
        next[faceOf[k]] = 0;
        changed = true;
      }
    if (!changed)
      break;
    S = wholeParts ? LargestRegionAndWholeParts(pm, next) : LargestConnectedRegion(pm, next);
  }
  return S;
}
}
}
