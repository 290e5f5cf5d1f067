// Seam stitching and final weld: union-find pairing, budgeted cluster placement, smoothing.
#include "FoldingTreeUnfolderInternal.h"
#include "PointKdTree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <numeric>
#include <unordered_map>

namespace foldingmeshes
{
namespace unfolder_detail
{
namespace
{
/// The smallest stitch / weld tolerance, as a share of the tree's diagonal (rounding).
constexpr double RoundingOfDiagonal = 1e-12;
/// Two open vertices of one copy closer than this share of the root epsilon are welded too
/// (WeldBoundaries).
constexpr double SameCopyWeldOfEpsilon = 0.01;
}

void Unfolder::Stitch(const FoldingNode& node,
  Piece& piece,
  const std::vector<int>& childOf,
  SeamReport& seam,
  double toleranceShare)
{
  const int level = node.depth;
  const double tol = std::max(toleranceShare * this->Options.stitchToleranceScale * node.epsilon,
    RoundingOfDiagonal * std::max(this->Tree.diagonal, 1e-300));
  std::vector<char> isTear(piece.points.size());
  for (int v = 0; v < piece.NumberOfPoints(); ++v)
    isTear[v] = IsTear(piece.tear[v], level);
  this->StitchVertices(piece, isTear, childOf, tol, node.epsilon, this->Options.fillSeamGaps, seam);
  {
    std::vector<char> tear(piece.points.size());
    for (int v = 0; v < piece.NumberOfPoints(); ++v)
      tear[v] = IsTear(piece.tear[v], level);
    this->CountGaps(piece, tear, seam);
    Consume(piece, 2 * level);
  }
  this->Result.stitchedVertices += seam.stitchedVertices;
  this->Result.unmatchedTearVertices += seam.unmatchedTearVertices;
  this->Result.gapEdges += seam.gapEdges;
  this->Result.gapLength += seam.gapLength;
}

/**
 * The final seam pass (UnfoldOptions::weldBoundaries): every vertex on an open edge is a
 * candidate, copies play the part of children (a copy's own vertices are merged only when
 * nearly coincident, see below), tolerance weldToleranceScale * root epsilon; moves are
 * bounded by the error budgets.
 */
void Unfolder::WeldBoundaries(Piece& piece, SeamReport& seam)
{
  const std::vector<char> open = BorderPoints(piece.triangles, piece.points.size());
  const double tol = std::max(this->Options.weldToleranceScale * this->Tree.rootEpsilon,
    RoundingOfDiagonal * std::max(this->Tree.diagonal, 1e-300));
  // No gap filling here: loops of open edges between copies may be the input's own
  // borders (new faces there would leave the input surface).
  // Two open vertices of one copy within a hundredth of the root epsilon are merged as well:
  // a fold whose plane passes that close to a row of vertices keeps them beside their
  // neighbours' projections (a sliver strip), and a seam that reaches the strip can close
  // onto only one of its sides. (An input crack that narrow closes too. Such pairs do not
  // chain (ClusterStitches): a run of open edges of one copy, each that short - the rim of a
  // finely tessellated open part - once collapsed to one point and took the part's faces with
  // it, 0.12 of the diagonal away on an artist-like chair; issue 21.)
  const std::vector<int> copyOf = piece.pointCopy;
  this->StitchVertices(piece,
    open,
    copyOf,
    tol,
    this->Tree.rootEpsilon,
    false,
    seam,
    std::min(tol, SameCopyWeldOfEpsilon * this->Tree.rootEpsilon));
}

/// Whether face t of `piece` (`face`: its input face and the sorted input ids of its
/// vertices before the stitch), on the same vertices as the faces `same`, is one of the
/// input's own duplicate faces: another input face on the same input vertices as one of them,
/// every edge a copy of an input non-manifold edge (the duplicates make them so).
bool Unfolder::InputDuplicate(const Piece& piece,
  const Triangle& t,
  const std::pair<int, std::array<int, 3>>& face,
  const std::vector<std::pair<int, std::array<int, 3>>>& same) const
{
  bool sameVertices = false;
  for (const auto& s : same)
  {
    if (s.first == face.first)
      return false;
    sameVertices = sameVertices || s.second == face.second;
  }
  if (!sameVertices)
    return false;
  for (int k = 0; k < 3; ++k)
    if (this->InputNonManifoldFaces(piece, t[k], t[(k + 1) % 3]) < 3)
      return false;
  return true;
}

/**
 * Stitching of the candidate vertices (see UnfoldFoldingTree), in stages: proposals
 * (ProposeStitches), clusters (ClusterStitches), their placement within the error budgets
 * (PlaceClusters), the merge (MergeClusters), the zipper, gap filling and the paper's
 * constrained Laplacian smoothing (ConstrainedLaplacianSmoothing). Two vertices of one child
 * merge only within `sameChildDistance`. Fills seam's stitch statistics (not the gaps).
 */
void Unfolder::StitchVertices(Piece& piece,
  const std::vector<char>& candidate,
  const std::vector<int>& childOf,
  double tol,
  double epsilon,
  bool fill,
  SeamReport& seam,
  double sameChildDistance)
{
  std::vector<int> tears;
  for (int v = 0; v < piece.NumberOfPoints(); ++v)
    if (candidate[v])
      tears.push_back(v);
  seam.tearVertices = static_cast<int>(tears.size());
  const std::vector<StitchProposal> proposals =
    ProposeStitches(piece.points, tears, childOf, tol, sameChildDistance);
  StitchClusters clusters = ClusterStitches(proposals, childOf, piece.NumberOfPoints());
  PlaceClusters(piece, clusters, seam);
  // Smoothing budget: how far a merged vertex may move (its cluster's spread); 0: fixed.
  SeamPiece out = this->MergeClusters(
    piece, candidate, childOf, clusters, this->Options.exactStitchFraction * epsilon, seam);

  // Zipper: tear vertices left without a partner vertex are inserted into the nearest open
  // seam edge of another child (splitting its triangle), so seams whose two sides were
  // tessellated differently close too.
  if (this->Options.zipper)
  {
    const int zipped =
      Zip(out.piece, out.faceChild, out.children, out.matched, out.candidate, tol, out.rough);
    seam.zippedVertices = zipped;
    seam.stitchedVertices += zipped;
    seam.unmatchedTearVertices -= zipped;
  }
  if (fill)
    FillSeamGaps(out.piece, out.faceChild, out.children, out.candidate, tol, seam);
  seam.smoothedVertices = ConstrainedLaplacianSmoothing(
    out.piece, out.rough, this->Options.smoothingIterations, this->Options.smoothingWeight);
  piece = std::move(out.piece);
}

std::vector<StitchProposal> ProposeStitches(const std::vector<Vec3>& points,
  const std::vector<int>& tears,
  const std::vector<int>& childOf,
  double tol,
  double sameChildDistance)
{
  const PointKdTree grid(points, tears);
  std::vector<StitchProposal> proposals;
  for (int v : tears)
  {
    // Each tear vertex's nearest tear vertex of another child (lowest distance, then id).
    const int best =
      grid.NearestWithinWhere(points[v], tol, [&](int w) { return childOf[w] != childOf[v]; });
    if (best >= 0)
      proposals.push_back(
        { (points[best] - points[v]).norm(), std::min(v, best), std::max(v, best), false });
    // Two vertices of one child are merged with each other only when nearly coincident.
    if (sameChildDistance > 0.0)
      grid.ForEachWithin(points[v],
        sameChildDistance,
        [&](int w)
        {
          const double d = (points[w] - points[v]).norm();
          if (childOf[w] == childOf[v] && w > v && d <= sameChildDistance)
            proposals.push_back({ d, v, w, true });
        });
  }
  std::sort(proposals.begin(),
    proposals.end(),
    [](const StitchProposal& x, const StitchProposal& y)
    {
      if (x.distance != y.distance)
        return x.distance < y.distance;
      if (x.a != y.a)
        return x.a < y.a;
      return x.b < y.b;
    });
  return proposals;
}

StitchClusters ClusterStitches(const std::vector<StitchProposal>& proposals,
  const std::vector<int>& childOf,
  int n)
{
  StitchClusters clusters;
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto& childrenOfRoot = clusters.children;
  auto childrenOf = [&](int root) -> std::vector<int>&
  {
    auto it = childrenOfRoot.find(root);
    if (it == childrenOfRoot.end())
      it = childrenOfRoot.emplace(root, std::vector<int>{ childOf[root] }).first;
    return it->second;
  };
  // Clusters that hold a same-child pair take no further same-child pair: a run of short open
  // edges of one copy would otherwise chain into one point, collapsing a finely tessellated
  // open part (a rim of 1200 segments) and every face on it.
  std::vector<char> hasSameChildPair(n, 0);
  for (const StitchProposal& pr : proposals)
  {
    const int ra = FindRoot(parent, pr.a), rb = FindRoot(parent, pr.b);
    if (ra == rb)
      continue;
    if (pr.sameChild && (hasSameChildPair[ra] || hasSameChildPair[rb]))
      continue;
    std::vector<int>& ca = childrenOf(ra);
    std::vector<int>& cb = childrenOf(rb);
    bool disjoint = true;
    for (int c : cb)
      disjoint = disjoint && !std::binary_search(ca.begin(), ca.end(), c);
    if (!disjoint && !pr.sameChild)
      continue;
    const int root = std::min(ra, rb), other = std::max(ra, rb);
    std::vector<int> merged;
    std::merge(ca.begin(), ca.end(), cb.begin(), cb.end(), std::back_inserter(merged));
    merged.erase(std::unique(merged.begin(), merged.end()), merged.end());
    parent[other] = root;
    hasSameChildPair[root] = hasSameChildPair[ra] || hasSameChildPair[rb] || pr.sameChild;
    childrenOfRoot[root] = std::move(merged);
    childrenOfRoot.erase(other);
  }
  clusters.rep.resize(n);
  clusters.count.assign(n, 0);
  for (int v = 0; v < n; ++v)
  {
    clusters.rep[v] = FindRoot(parent, v);
    ++clusters.count[clusters.rep[v]];
  }
  return clusters;
}

void PlaceClusters(Piece& piece, StitchClusters& clusters, SeamReport& seam)
{
  const int n = piece.NumberOfPoints();
  std::vector<int>& rep = clusters.rep;
  std::vector<int>& count = clusters.count;
  std::vector<Vec3> sum(n, Vec3::Zero());
  for (int v = 0; v < n; ++v)
    sum[rep[v]] += piece.points[v];
  // Where a cluster goes: its mean, else the position of one of its members (lowest id
  // first), whichever moves no member farther than its error budget; none: not merged.
  std::vector<std::vector<int>> members(n);
  for (int v = 0; v < n; ++v)
    if (count[rep[v]] >= 2)
      members[rep[v]].push_back(v);
  std::vector<Vec3> target(n);
  for (int r = 0; r < n; ++r)
  {
    if (members[r].empty())
      continue;
    std::vector<Vec3> candidates{ sum[r] / count[r] };
    for (int v : members[r])
      candidates.push_back(piece.points[v]);
    bool placed = false;
    for (const Vec3& c : candidates)
    {
      bool fits = true;
      for (int v : members[r])
        fits = fits && (piece.points[v] - c).norm() <= piece.budget[v] * (1.0 + 1e-12);
      if (fits)
      {
        target[r] = c;
        placed = true;
        break;
      }
    }
    if (!placed)
    {
      ++seam.budgetRejectedClusters;
      for (int v : members[r])
      {
        rep[v] = v;
        count[v] = 1;
      }
      clusters.children.erase(r);
      members[r].clear();
    }
  }
  std::vector<double>& spread = clusters.spread;
  spread.assign(n, 0.0);
  for (int r = 0; r < n; ++r)
    for (int v : members[r])
    {
      const double moved = (piece.points[v] - target[r]).norm();
      spread[r] = std::max(spread[r], moved);
      piece.budget[v] = std::max(0.0, piece.budget[v] - moved);
      ++seam.stitchedVertices;
    }
  for (int r = 0; r < n; ++r)
    if (!members[r].empty())
    {
      double least = std::numeric_limits<double>::infinity();
      for (int v : members[r])
        least = std::min(least, piece.budget[v]);
      piece.points[r] = target[r];
      piece.budget[r] = least;
      seam.maximumStitchDistance = std::max(seam.maximumStitchDistance, spread[r]);
    }
  for (int v = 0; v < n; ++v)
    if (rep[v] != v)
    {
      TearList& into = piece.tear[rep[v]];
      into.insert(into.end(), piece.tear[v].begin(), piece.tear[v].end());
      Normalize(into);
      piece.onPlane[rep[v]] |= piece.onPlane[v];
      piece.border[rep[v]] = std::max(piece.border[rep[v]], piece.border[v]);
    }
  seam.unmatchedTearVertices = seam.tearVertices - seam.stitchedVertices;
}

SeamPiece Unfolder::MergeClusters(const Piece& piece,
  const std::vector<char>& candidate,
  const std::vector<int>& childOf,
  const StitchClusters& clusters,
  double roughAbove,
  SeamReport& seam) const
{
  const int n = piece.NumberOfPoints();
  const std::vector<int>& rep = clusters.rep;
  const std::vector<int>& count = clusters.count;
  SeamPiece merged;
  Piece& out = merged.piece;
  std::vector<int> newId(n, -1);
  for (int v = 0; v < n; ++v)
    if (rep[v] == v)
    {
      newId[v] = out.NumberOfPoints();
      out.AppendPoint(piece, v);
      merged.candidate.push_back(candidate[v]);
      auto it = clusters.children.find(v);
      merged.children.push_back(
        it != clusters.children.end() ? it->second : std::vector<int>{ childOf[v] });
      merged.matched.push_back(count[v] >= 2);
    }
  merged.rough.assign(out.points.size(), 0.0);
  for (int v = 0; v < n; ++v)
    if (rep[v] == v && count[v] >= 2 && clusters.spread[v] > roughAbove)
      merged.rough[newId[v]] = clusters.spread[v];
  // Remap faces; drop collapsed and duplicate ones (but the input's own duplicates:
  // InputDuplicate, against the faces on the same vertices kept before: their input face and
  // the sorted input ids of their vertices). The faces on each set of vertices are judged in
  // face order, group by group (one sort instead of a map of lists).
  const int nf = piece.NumberOfFaces();
  std::vector<Triangle> remapped(nf), sortedOf(nf);
  std::vector<int> byVertices;
  byVertices.reserve(nf);
  for (int f = 0; f < nf; ++f)
  {
    const Triangle& t = piece.triangles[f];
    const Triangle u{ newId[rep[t[0]]], newId[rep[t[1]]], newId[rep[t[2]]] };
    remapped[f] = u;
    if (u[0] == u[1] || u[1] == u[2] || u[0] == u[2])
      continue;
    sortedOf[f] = u;
    std::sort(sortedOf[f].begin(), sortedOf[f].end());
    byVertices.push_back(f);
  }
  std::stable_sort(
    byVertices.begin(), byVertices.end(), [&](int a, int b) { return sortedOf[a] < sortedOf[b]; });
  std::vector<char> keep(nf, 0);
  std::vector<std::pair<int, std::array<int, 3>>> same;
  for (size_t i = 0; i < byVertices.size();)
  {
    size_t j = i;
    while (j < byVertices.size() && sortedOf[byVertices[j]] == sortedOf[byVertices[i]])
      ++j;
    same.clear();
    for (size_t k = i; k < j; ++k) // increasing face order (stable sort)
    {
      const int f = byVertices[k];
      const Triangle& t = piece.triangles[f];
      std::array<int, 3> ids{ piece.pointOrig[t[0]], piece.pointOrig[t[1]], piece.pointOrig[t[2]] };
      std::sort(ids.begin(), ids.end());
      if (!same.empty() &&
        !this->InputDuplicate(out, remapped[f], { piece.faceOrig[f], ids }, same))
        continue;
      same.push_back({ piece.faceOrig[f], ids });
      keep[f] = 1;
    }
    i = j;
  }
  for (int f = 0; f < nf; ++f)
  {
    if (!keep[f])
    {
      ++seam.droppedFaces;
      continue;
    }
    const Triangle& t = piece.triangles[f];
    const Triangle& u = remapped[f];
    out.triangles.push_back(u);
    out.faceOrig.push_back(piece.faceOrig[f]);
    out.faceCopy.push_back(piece.faceCopy[f]);
    out.faceFilled.push_back(piece.faceFilled[f]);
    merged.faceChild.push_back(childOf[t[0]]);
  }
  DropUnusedPoints(merged);
  return merged;
}

void DropUnusedPoints(SeamPiece& merged)
{
  Piece& out = merged.piece;
  std::vector<char> used(out.points.size(), 0);
  for (const Triangle& t : out.triangles)
    for (int v : t)
      used[v] = 1;
  SeamPiece compact;
  std::vector<int> id(out.points.size(), -1);
  for (int v = 0; v < out.NumberOfPoints(); ++v)
    if (used[v])
    {
      id[v] = compact.piece.NumberOfPoints();
      compact.piece.AppendPoint(out, v);
      compact.candidate.push_back(merged.candidate[v]);
      compact.rough.push_back(merged.rough[v]);
      compact.matched.push_back(merged.matched[v]);
      compact.children.push_back(merged.children[v]);
    }
  for (const Triangle& t : out.triangles)
    compact.piece.triangles.push_back({ id[t[0]], id[t[1]], id[t[2]] });
  compact.piece.faceOrig = std::move(out.faceOrig);
  compact.piece.faceCopy = std::move(out.faceCopy);
  compact.piece.faceFilled = std::move(out.faceFilled);
  compact.faceChild = std::move(merged.faceChild);
  merged = std::move(compact);
}

int ConstrainedLaplacianSmoothing(Piece& out,
  std::vector<double> rough,
  int iterations,
  double lambda)
{
  int smoothed = 0;
  for (double r : rough)
    smoothed += r > 0.0;
  if (smoothed == 0 || iterations <= 0)
    return smoothed;
  std::vector<std::vector<int>> ring(out.points.size());
  for (const Triangle& t : out.triangles)
    for (int k = 0; k < 3; ++k)
    {
      const int a = t[k], b = t[(k + 1) % 3];
      if (rough[a] > 0.0)
        ring[a].push_back(b);
      if (rough[b] > 0.0)
        ring[b].push_back(a);
    }
  for (auto& r : ring)
  {
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end()), r.end());
  }
  const std::vector<Vec3> start = out.points;
  for (size_t v = 0; v < rough.size(); ++v)
    rough[v] = std::min(rough[v], out.budget[v]);
  for (int iteration = 0; iteration < iterations; ++iteration)
  {
    std::vector<Vec3> next = out.points;
    for (int v = 0; v < out.NumberOfPoints(); ++v)
      if (rough[v] > 0.0 && !ring[v].empty())
      {
        Vec3 mean = Vec3::Zero();
        for (int w : ring[v])
          mean += out.points[w];
        mean /= static_cast<double>(ring[v].size());
        next[v] = (1.0 - lambda) * out.points[v] + lambda * mean;
        const Vec3 moved = next[v] - start[v];
        if (moved.norm() > rough[v])
          next[v] = start[v] + moved * (rough[v] / moved.norm());
      }
    out.points.swap(next);
  }
  for (int v = 0; v < out.NumberOfPoints(); ++v)
    out.budget[v] = std::max(0.0, out.budget[v] - (out.points[v] - start[v]).norm());
  return smoothed;
}
} // namespace unfolder_detail
} // namespace foldingmeshes
