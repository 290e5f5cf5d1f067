// Final repair of the unfolded mesh (UnfoldOptions::closeHoles): faces that make an edge
// non-manifold are dropped, the orientation is made consistent per connected component, then
// the boundary loops are filled (FoldingTreeUnfolderHoles.cxx).
#include "FoldingTreeUnfolderRepairInternal.h"
#include "Trace.h"

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>

namespace foldingmeshes
{
namespace unfolder_detail
{
namespace
{
/// A face whose height over its longest edge is below this share of the root epsilon is a
/// sliver (the last kept at a non-manifold edge).
constexpr double SliverHeightOfEpsilon = 0.01;
}

using namespace repair;
/// The number of faces of the input's non-manifold edge that the edge a-b of `piece` copies
/// (through the points' input ids, FoldingTree::inputNonManifoldEdges), 0 if none.
int Unfolder::InputNonManifoldFaces(const Piece& piece, int a, int b) const
{
  const auto& edges = this->Tree.inputNonManifoldEdges;
  const int x = std::min(piece.pointOrig[a], piece.pointOrig[b]);
  const int y = std::max(piece.pointOrig[a], piece.pointOrig[b]);
  if (edges.empty() || x == y)
    return 0;
  const auto it = std::lower_bound(edges.begin(),
    edges.end(),
    std::make_pair(x, y),
    [](const InputNonManifoldEdge& e, const std::pair<int, int>& k)
    { return std::make_pair(e.a, e.b) < k; });
  return it != edges.end() && it->a == x && it->b == y ? it->faces : 0;
}

/**
 * Drops faces until no edge has more than two, except at the copies of the input's own
 * non-manifold edges (InputNonManifoldFaces), which keep as many faces as the input edge had:
 * at such an edge with more (faces the unfolding laid on top) the extra ones go, gap fills
 * first, then those whose third vertex lies nearest another face's (a duplicate copy), the
 * later face on a tie. At any other edge the two faces kept are those that traverse it in
 * opposite directions and are the least folded against each other (largest normal
 * agreement), preferring faces that are not gap fills nor slivers; the others go (the holes
 * they leave are filled afterwards). Returns the number of faces dropped.
 */
// (Over 100 lines because the ranking of the faces at an edge - input non-manifold edges,
// fills, slivers, duplicates, normal agreement - is one rule written in one place.)
int Unfolder::DropNonManifoldFaces(Piece& piece) const
{
  int dropped = 0;
  const double sliverHeight = SliverHeightOfEpsilon * this->Tree.rootEpsilon;
  for (int round = 0; round < 4; ++round)
  {
    const auto edges = EdgeFaces(piece);
    std::vector<char> drop(piece.triangles.size(), 0);
    bool any = false;
    std::vector<int> faces; // of the edge below, not dropped (one buffer for all edges)
    for (const auto& e : edges)
    {
      faces.clear();
      for (int f : e.second)
        if (!drop[f])
          faces.push_back(f);
      if (faces.size() <= 2)
        continue;
      const int a = e.first.first, b = e.first.second;
      const int inputFaces = this->InputNonManifoldFaces(piece, a, b);
      if (inputFaces > 2)
      {
        if (static_cast<int>(faces.size()) <= inputFaces)
          continue; // the input's own non-manifold edge: kept
        any = true;
        auto opposite = [&](int f) -> const Vec3&
        {
          const Triangle& t = piece.triangles[f];
          int k = 0;
          while (k < 2 && (t[k] == a || t[k] == b))
            ++k;
          return piece.points[t[k]];
        };
        while (static_cast<int>(faces.size()) > inputFaces)
        {
          size_t worst = 0;
          double worstNearest = 0.0;
          for (size_t i = 0; i < faces.size(); ++i)
          {
            double nearest = std::numeric_limits<double>::infinity();
            for (size_t j = 0; j < faces.size(); ++j)
              if (j != i)
                nearest = std::min(nearest, (opposite(faces[i]) - opposite(faces[j])).norm());
            const int f = faces[i], w = faces[worst];
            const bool worse = i == 0 ||
              (piece.faceFilled[f] != piece.faceFilled[w]
                  ? piece.faceFilled[f] > piece.faceFilled[w]
                  : nearest != worstNearest ? nearest < worstNearest
                                            : f > w);
            if (worse)
            {
              worst = i;
              worstNearest = nearest;
            }
          }
          drop[faces[worst]] = 1;
          faces.erase(faces.begin() + static_cast<std::ptrdiff_t>(worst));
        }
        continue;
      }
      any = true;
      // A sliver (height below a hundredth of the root tolerance: the thin strips a fold
      // line leaves between a vertex near the plane and its projection) has a meaningless
      // normal; keeping a real face and dropping a sliver costs nothing the fill cannot
      // restore within the tolerance.
      auto sliver = [&](int f)
      {
        const Triangle& t = piece.triangles[f];
        double longest = 0.0;
        for (int k = 0; k < 3; ++k)
          longest = std::max(longest, (piece.points[t[k]] - piece.points[t[(k + 1) % 3]]).norm());
        return longest <= 0.0 || 2.0 * Area(piece, t) / longest < sliverHeight ? 1 : 0;
      };
      int bestF = -1, bestG = -1;
      double bestScore = -std::numeric_limits<double>::infinity();
      for (size_t i = 0; i < faces.size(); ++i)
        for (size_t j = i + 1; j < faces.size(); ++j)
        {
          const int f = faces[i], g = faces[j];
          const Triangle& tf = piece.triangles[f];
          const Triangle& tg = piece.triangles[g];
          const bool opposite = Direction(tf, a, b) != Direction(tg, a, b);
          const Vec3 nf = Normal(piece, tf), ng = Normal(piece, tg);
          const double d = nf.norm() * ng.norm();
          // Consistent pairs first, then real faces (no gap fills, no slivers), then the
          // flattest pair.
          double score = (opposite ? 20.0 : 0.0) -
            4.0 * (piece.faceFilled[f] + piece.faceFilled[g]) - 2.0 * (sliver(f) + sliver(g)) +
            (d > 0.0 ? (opposite ? 1.0 : -1.0) * nf.dot(ng) / d : -1.0);
          if (score > bestScore)
          {
            bestScore = score;
            bestF = f;
            bestG = g;
          }
        }
      for (int f : faces)
        if (f != bestF && f != bestG)
          drop[f] = 1;
    }
    if (!any)
      break;
    for (char d : drop)
      dropped += d;
    KeepFaces(piece, drop);
  }
  return dropped;
}

/**
 * Makes the orientation consistent per connected component (faces connected through edges
 * of exactly two faces). Faces joined by consistently oriented edges form patches (most
 * faces already agree: leaf triangles follow the input, mirrored copies are reversed); the
 * patches are decided greedily, largest area first, each flipped when most of its
 * misoriented edges to decided patches say so. Where a component cannot be oriented (a
 * stitch made it one-sided), the faces of the smaller patch along the conflicting edges are
 * dropped (the hole is filled afterwards). Returns the number of faces flipped; `dropped`
 * counts the faces removed.
 */
// (Over 100 lines because patches, the greedy decision and the conflict drop share the
// patch tables built at the start.)
int Unfolder::OrientComponents(Piece& piece, int& dropped)
{
  const int nf = piece.NumberOfFaces();
  const auto edges = EdgeFaces(piece);
  std::vector<int> parent(nf);
  for (int f = 0; f < nf; ++f)
    parent[f] = f;
  struct Link
  {
    int f, g;
  };
  std::vector<Link> flipped; // manifold edges whose two faces run the same way
  for (const auto& e : edges)
  {
    if (e.second.size() != 2 || e.second[0] == e.second[1])
      continue;
    const int f = e.second[0], g = e.second[1];
    const int a = e.first.first, b = e.first.second;
    if (Direction(piece.triangles[f], a, b) != Direction(piece.triangles[g], a, b))
    {
      const int rf = FindRoot(parent, f), rg = FindRoot(parent, g);
      if (rf != rg)
        parent[std::max(rf, rg)] = std::min(rf, rg);
    }
    else
      flipped.push_back({ f, g });
  }
  std::vector<int> patch(nf);
  std::vector<double> area(nf, 0.0);
  for (int f = 0; f < nf; ++f)
  {
    patch[f] = FindRoot(parent, f);
    area[patch[f]] += Area(piece, piece.triangles[f]);
  }
  // Patch adjacency through misoriented edges (with multiplicity).
  std::map<int, std::vector<int>> across;
  for (const Link& l : flipped)
  {
    const int p = patch[l.f], q = patch[l.g];
    across[p].push_back(q);
    across[q].push_back(p);
  }
  std::vector<int> flip(nf, -1); // per patch root
  std::vector<int> order;
  for (int f = 0; f < nf; ++f)
    if (patch[f] == f)
      order.push_back(f);
  std::sort(order.begin(),
    order.end(),
    [&](int x, int y) { return area[x] != area[y] ? area[x] > area[y] : x < y; });
  for (int seed : order)
  {
    if (flip[seed] >= 0)
      continue;
    flip[seed] = 0;
    // Grow from the seed: the largest undecided patch next to decided ones first.
    std::set<std::pair<double, int>> frontier; // (-area, patch)
    auto push = [&](int p)
    {
      auto it = across.find(p);
      if (it == across.end())
        return;
      for (int q : it->second)
        if (flip[q] < 0)
          frontier.insert({ -area[q], q });
    };
    push(seed);
    while (!frontier.empty())
    {
      const int p = frontier.begin()->second;
      frontier.erase(frontier.begin());
      if (flip[p] >= 0)
        continue;
      int vote = 0; // > 0: flip
      for (int q : across[p])
        if (flip[q] >= 0)
          vote += flip[q] == 0 ? 1 : -1;
      flip[p] = vote > 0 ? 1 : 0;
      push(p);
    }
  }
  int count = 0;
  for (int f = 0; f < nf; ++f)
    if (flip[patch[f]] == 1)
    {
      std::swap(piece.triangles[f][1], piece.triangles[f][2]);
      ++count;
    }
  // Conflicts left: one-sided components. Drop the faces of the smaller patch there.
  std::vector<char> drop(nf, 0);
  bool any = false;
  for (const Link& l : flipped)
    if (flip[patch[l.f]] == flip[patch[l.g]])
    {
      drop[area[patch[l.f]] < area[patch[l.g]] ? l.f : l.g] = 1;
      any = true;
    }
  if (any)
  {
    for (char d : drop)
      dropped += d;
    KeepFaces(piece, drop);
  }
  return count;
}

/// Diagnostics (UnfoldOptions::trace): where the bad edges are.
static void TraceEdgeClasses(const TraceSink& trace, const Piece& piece, const char* when)
{
  if (!trace)
    return;
  int open[4] = { 0, 0, 0, 0 }, nonManifold[3] = { 0, 0, 0 }, misoriented[3] = { 0, 0, 0 };
  for (const auto& e : EdgeFaces(piece))
  {
    const int a = e.first.first, b = e.first.second;
    bool filled = false, sameCopy = true;
    for (int f : e.second)
    {
      filled = filled || piece.faceFilled[f];
      sameCopy = sameCopy && piece.faceCopy[f] == piece.faceCopy[e.second[0]];
    }
    if (e.second.size() == 1)
    {
      const int f = e.second[0];
      if (piece.border[a] == 1 && piece.border[b] == 1)
        ++open[0];
      else if (piece.onPlane[a] && piece.onPlane[b])
        ++open[1];
      else if (piece.pointCopy[a] == piece.faceCopy[f] && piece.pointCopy[b] == piece.faceCopy[f])
        ++open[2];
      else
        ++open[3];
    }
    const int cls = filled ? 0 : sameCopy ? 1 : 2;
    if (e.second.size() > 2)
      ++nonManifold[cls];
    if (e.second.size() == 2 &&
      Direction(piece.triangles[e.second[0]], a, b) ==
        Direction(piece.triangles[e.second[1]], a, b))
      ++misoriented[cls];
  }
  trace(FormatTrace(
    "repair %s: open border %d foldline %d in-copy %d across-stitch %d | non-manifold filled %d "
    "one-copy %d copies %d | misoriented filled %d one-copy %d copies %d",
    when,
    open[0],
    open[1],
    open[2],
    open[3],
    nonManifold[0],
    nonManifold[1],
    nonManifold[2],
    misoriented[0],
    misoriented[1],
    misoriented[2]));
}

/// The final repair (UnfoldOptions::closeHoles), see RepairReport.
void Unfolder::Repair(Piece& piece, RepairReport& report)
{
  const TraceSink& trace = this->Options.trace;
  TraceEdgeClasses(trace, piece, "before");
  {
    // Degenerate faces (a repeated vertex) first.
    std::vector<char> drop(piece.triangles.size(), 0);
    for (size_t f = 0; f < piece.triangles.size(); ++f)
    {
      const Triangle& t = piece.triangles[f];
      drop[f] = t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
      report.droppedFaces += drop[f];
    }
    KeepFaces(piece, drop);
  }
  report.droppedFaces += this->DropNonManifoldFaces(piece);
  TraceEdgeClasses(trace, piece, "after drop");
  report.flippedFaces = this->OrientComponents(piece, report.droppedFaces);
  TraceEdgeClasses(trace, piece, "after orient");
  for (int pass = 0; pass < 3; ++pass)
  {
    const int filledNow = this->FillLoops(piece, report, true);
    TraceEdgeClasses(trace, piece, "after fill");
    if (filledNow == 0)
      break;
    // Fills of loops that share a pinch vertex may meet at an edge: clean up.
    report.droppedFaces += this->DropNonManifoldFaces(piece);
    report.flippedFaces += this->OrientComponents(piece, report.droppedFaces);
  }
  this->FillLoops(piece, report, false);
  if (trace)
  {
    TraceEdgeClasses(trace, piece, "after");
    trace(FormatTrace(
      "repair: dropped %d flipped %d filled %d loops %d faces; border %d loops %d edges; open "
      "%d loops %d edges %.4g length; unknown %d loops",
      report.droppedFaces,
      report.flippedFaces,
      report.filledLoops,
      report.filledFaces,
      report.borderLoops,
      report.borderEdges,
      report.openLoops,
      report.openEdges,
      report.openLength,
      report.unknownLoops));
  }
}
} // namespace unfolder_detail
} // namespace foldingmeshes
