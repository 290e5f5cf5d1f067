// Seam repair after pairing: the zipper and the ear-clipping fill of small seam gap loops.
#include "FoldingTreeUnfolderInternal.h"
#include "IntegerTripleHash.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>
#include <unordered_set>

namespace foldingmeshes
{
namespace unfolder_detail
{
namespace
{
/// The zipper's grid cells are at least the longest open edge over this.
constexpr double ZipCellsPerLongestEdge = 8.0;
/// A tear vertex is zipped into an edge only between its end shares (as a share of the
/// edge's length): nearer an end point, the end point is its partner.
constexpr double ZipEdgeEndShare = 0.02;
}

/**
 * Inserts unmatched tear vertices into open boundary edges of other children whose two end
 * points are tear vertices, within `tol` (the vertex moves half way to the edge). Returns
 * the number of vertices inserted.
 */
namespace
{
/// The faces of one edge in the order they were added, the first two held inline (an edge
/// of a mesh has one or two faces, rarely more): no allocation for most edges.
class EdgeFaceList
{
public:
  size_t size() const { return this->Inline + this->More.size(); }
  int operator[](size_t i) const { return i < this->Inline ? this->First[i] : this->More[i - 2]; }
  void push_back(int f)
  {
    if (this->Inline < 2)
      this->First[this->Inline++] = f;
    else
      this->More.push_back(f);
  }
  /// Removes the first occurrence of f (which must be there), keeping the others' order.
  void erase(int f)
  {
    size_t i = 0;
    while ((*this)[i] != f)
      ++i;
    for (; i + 1 < this->size(); ++i)
      this->Set(i, (*this)[i + 1]);
    if (!this->More.empty())
      this->More.pop_back();
    else
      --this->Inline;
  }

private:
  void Set(size_t i, int f)
  {
    if (i < 2)
      this->First[i] = f;
    else
      this->More[i - 2] = f;
  }
  int First[2] = { -1, -1 };
  size_t Inline = 0;
  std::vector<int> More;
};
}

int Unfolder::Zip(Piece& out,
  std::vector<int>& faceChild,
  std::vector<std::vector<int>>& children,
  std::vector<char>& matched,
  const std::vector<char>& isTear,
  double tol,
  std::vector<double>& rough)
{
  using Edge = std::pair<int, int>;
  auto key = [](int a, int b) { return Edge{ std::min(a, b), std::max(a, b) }; };
  // Hashed (the open edges are sorted below: the same order as an ordered map's); an edge
  // whose faces are all gone keeps an empty list, which every use below treats as no edge.
  FlatEdgeMap<EdgeFaceList> edgeFaces;
  auto addFace = [&](int f)
  {
    const Triangle& t = out.triangles[f];
    for (int k = 0; k < 3; ++k)
      edgeFaces[key(t[k], t[(k + 1) % 3])].push_back(f);
  };
  auto removeFace = [&](int f)
  {
    const Triangle& t = out.triangles[f];
    for (int k = 0; k < 3; ++k)
      edgeFaces[key(t[k], t[(k + 1) % 3])].erase(f);
  };
  // Only the faces with two candidate corners or more: an edge between two candidates (the
  // only edges looked up below) belongs to those alone, and so do the faces a split makes (u
  // and a candidate of the split edge) - the same lists as over every face, for a fraction
  // of the hashing on a large piece.
  std::vector<int> seamFaces;
  for (int f = 0; f < out.NumberOfFaces(); ++f)
  {
    const Triangle& t = out.triangles[f];
    if ((isTear[t[0]] != 0) + (isTear[t[1]] != 0) + (isTear[t[2]] != 0) >= 2)
      seamFaces.push_back(f);
  }
  edgeFaces.reserve(3 * seamFaces.size()); // a seam band has 2-3 edges a face
  for (int f : seamFaces)
    addFace(f);
  int zipped = 0;
  for (int pass = 0; pass < 3; ++pass)
  {
    bool changed = false;
    // The open edges between two candidates at the start of the pass (edges split during
    // the pass are skipped, the new ones wait for the next pass), bucketed on a grid of
    // cell `tol` by the box of the edge grown by tol.
    std::vector<Edge> open;
    edgeFaces.ForEach(
      [&](const Edge& e, const EdgeFaceList& faces)
      {
        if (faces.size() == 1 && isTear[e.first] && isTear[e.second])
          open.push_back(e);
      });
    std::sort(open.begin(), open.end());
    // Cells of at least tol, and no smaller than an eighth of the longest open edge: an
    // edge much longer than tol would otherwise cover (length / tol)^3 cells.
    double longest = 0.0;
    for (const Edge& e : open)
      longest = std::max(longest, (out.points[e.first] - out.points[e.second]).norm());
    const double cell = std::max({ tol, longest / ZipCellsPerLongestEdge, 1e-300 });
    auto cellOf = [cell](double x) { return static_cast<long long>(std::floor(x / cell)); };
    std::unordered_map<std::array<long long, 3>, std::vector<int>, IntegerTripleHash> buckets;
    for (int i = 0; i < static_cast<int>(open.size()); ++i)
    {
      const Vec3 lo = out.points[open[i].first].cwiseMin(out.points[open[i].second]);
      const Vec3 hi = out.points[open[i].first].cwiseMax(out.points[open[i].second]);
      for (long long x = cellOf(lo.x() - tol); x <= cellOf(hi.x() + tol); ++x)
        for (long long y = cellOf(lo.y() - tol); y <= cellOf(hi.y() + tol); ++y)
          for (long long z = cellOf(lo.z() - tol); z <= cellOf(hi.z() + tol); ++z)
            buckets[{ x, y, z }].push_back(i);
    }
    for (int u = 0; u < out.NumberOfPoints(); ++u)
    {
      if (!isTear[u] || matched[u])
        continue;
      const Vec3 x = out.points[u];
      int bestFace = -1;
      Edge bestEdge;
      double bestDistance = tol;
      Vec3 bestPoint = x;
      auto bucket = buckets.find({ cellOf(x.x()), cellOf(x.y()), cellOf(x.z()) });
      if (bucket == buckets.end())
        continue;
      for (int i : bucket->second) // increasing i: the map order of the edges
      {
        const EdgeFaceList* e = edgeFaces.find(open[i]);
        if (!e || e->size() != 1)
          continue;
        const int a = open[i].first, b = open[i].second, f = (*e)[0];
        const Triangle& tf = out.triangles[f];
        if (a == u || b == u || tf[0] == u || tf[1] == u || tf[2] == u || !isTear[a] ||
          !isTear[b] || std::binary_search(children[u].begin(), children[u].end(), faceChild[f]))
          continue;
        const Vec3 ab = out.points[b] - out.points[a];
        const double len2 = ab.squaredNorm();
        if (!(len2 > 0.0))
          continue;
        const double t = (x - out.points[a]).dot(ab) / len2;
        if (t <= ZipEdgeEndShare || t >= 1.0 - ZipEdgeEndShare)
          continue;
        const Vec3 q = out.points[a] + t * ab;
        const double d = (x - q).norm();
        if (d <= bestDistance)
        {
          bestDistance = d;
          bestFace = f;
          bestEdge = open[i];
          bestPoint = q;
        }
      }
      if (bestFace < 0)
        continue;
      // Split bestFace (p, q, c) with edge p -> q into (p, u, c) and (u, q, c).
      const Triangle t = out.triangles[bestFace];
      int k = 0;
      while (key(t[k], t[(k + 1) % 3]) != bestEdge)
        ++k;
      const int p = t[k], q = t[(k + 1) % 3], c = t[(k + 2) % 3];
      removeFace(bestFace);
      out.triangles[bestFace] = { p, u, c };
      addFace(bestFace);
      out.triangles.push_back({ u, q, c });
      out.faceOrig.push_back(out.faceOrig[bestFace]);
      out.faceCopy.push_back(out.faceCopy[bestFace]);
      out.faceFilled.push_back(out.faceFilled[bestFace]);
      faceChild.push_back(faceChild[bestFace]);
      addFace(out.NumberOfFaces() - 1);
      // Half way to the edge, or as far as u's error budget allows.
      const double move = std::min(0.5 * bestDistance, out.budget[u]);
      if (bestDistance > 0.0)
        out.points[u] = x + (move / bestDistance) * (bestPoint - x);
      out.budget[u] = std::max(0.0, out.budget[u] - move);
      matched[u] = 1;
      rough[u] = move;
      children[u].push_back(faceChild[bestFace]);
      std::sort(children[u].begin(), children[u].end());
      ++zipped;
      changed = true;
    }
    if (!changed)
      break;
  }
  return zipped;
}

namespace
{
constexpr int MaximumGapLoop = 256;

/// Unfolder::FillSeamGaps' state: the piece's edges and faces as the fills grow.
class SeamGapFiller
{
public:
  SeamGapFiller(Piece& out,
    std::vector<int>& faceChild,
    const std::vector<std::vector<int>>& children,
    const std::vector<char>& isTear,
    double tol,
    SeamReport& seam,
    std::function<bool(int, int)> inputBorderEdge)
    : Out(out)
    , FaceChild(faceChild)
    , Children(children)
    , IsTear(isTear)
    , Tol(tol)
    , Seam(seam)
    , InputBorderEdge(std::move(inputBorderEdge))
  {
    const size_t edges = 3 * static_cast<size_t>(out.NumberOfFaces());
    this->HalfEdges.reserve(edges);
    this->Uses.reserve(edges);
    this->FaceSets.reserve(static_cast<size_t>(out.NumberOfFaces()));
    for (int f = 0; f < out.NumberOfFaces(); ++f)
    {
      const Triangle& t = out.triangles[f];
      this->FaceSets.insert(Sorted(t));
      for (int k = 0; k < 3; ++k)
      {
        const int a = t[k], b = t[(k + 1) % 3];
        this->HalfEdges[{ a, b }] = f;
        ++this->Uses[{ std::min(a, b), std::max(a, b) }];
      }
    }
  }

  void Run()
  {
    // The open half-edges in increasing order (as an ordered map holds them): the loops are
    // traced, and filled, in that order.
    std::vector<std::pair<int, int>> openHalfEdges;
    this->HalfEdges.ForEach(
      [&](const std::pair<int, int>& h, int)
      {
        if (this->IsOpen(h.first, h.second))
          openHalfEdges.push_back(h);
      });
    std::sort(openHalfEdges.begin(), openHalfEdges.end());
    std::vector<std::pair<int, int>> holes;
    for (const auto& h : openHalfEdges)
      holes.push_back({ h.second, h.first });
    for (const auto& first : holes)
    {
      if (this->VisitedHoles.count(first))
        continue;
      std::vector<int> loop;
      if (!this->TraceLoop(first, loop) || !this->IsNarrowSeamLoop(loop))
        continue;
      std::vector<Triangle> added;
      std::vector<int> addedFace;
      if (this->Triangulate(loop, added, addedFace))
        this->Append(loop, added, addedFace);
    }
  }

private:
  static std::array<int, 3> Sorted(const Triangle& t)
  {
    std::array<int, 3> key{ t[0], t[1], t[2] };
    std::sort(key.begin(), key.end());
    return key;
  }
  bool IsOpen(int a, int b) const
  {
    const int* uses = this->Uses.find({ std::min(a, b), std::max(a, b) });
    return uses && *uses == 1;
  }

  /// Arrived at b by the hole edge a -> b (face half-edge b -> a): the next hole edge found
  /// by turning around b through its faces, so each gap at a pinch vertex is its own loop.
  int NextHole(int a, int b)
  {
    const int* it = this->HalfEdges.find({ b, a });
    for (int guard = 0; it && guard < 64; ++guard)
    {
      const Triangle& t = this->Out.triangles[*it];
      int k = 0;
      while (t[(k + 1) % 3] != b)
        ++k;
      const int y = t[k]; // half-edge y -> b in this face
      if (this->IsOpen(y, b))
        return y;
      it = this->HalfEdges.find({ b, y });
    }
    return -1;
  }

  /// The boundary loop from hole edge `first`, along hole half-edges (the reverses of open
  /// face half-edges); true when it closes, is simple and has 3..MaximumGapLoop vertices.
  bool TraceLoop(const std::pair<int, int>& first, std::vector<int>& loop)
  {
    std::pair<int, int> edge = first;
    bool closed = false;
    while (static_cast<int>(loop.size()) <= MaximumGapLoop)
    {
      if (this->VisitedHoles.count(edge))
      {
        closed = edge == first && !loop.empty();
        break;
      }
      this->VisitedHoles.insert(edge);
      loop.push_back(edge.first);
      const int nx = this->NextHole(edge.first, edge.second);
      if (nx < 0)
        break;
      edge = { edge.second, nx };
    }
    std::vector<int> sortedLoop = loop;
    std::sort(sortedLoop.begin(), sortedLoop.end());
    const bool simple =
      std::adjacent_find(sortedLoop.begin(), sortedLoop.end()) == sortedLoop.end();
    const int n = static_cast<int>(loop.size());
    return closed && simple && n >= 3 && n <= MaximumGapLoop;
  }

  /// A seam loop (two children, at least half tear vertices) whose every vertex has a vertex
  /// of another child on the loop within 2 * max(tol, mean loop edge).
  bool IsNarrowSeamLoop(const std::vector<int>& loop) const
  {
    const std::vector<std::vector<int>>& children = this->Children;
    const int n = static_cast<int>(loop.size());
    std::vector<int> kids;
    int tears = 0;
    double perimeter = 0.0;
    for (int i = 0; i < n; ++i)
    {
      kids.insert(kids.end(), children[loop[i]].begin(), children[loop[i]].end());
      tears += this->IsTear[loop[i]];
      perimeter += (this->Out.points[loop[i]] - this->Out.points[loop[(i + 1) % n]]).norm();
    }
    std::sort(kids.begin(), kids.end());
    kids.erase(std::unique(kids.begin(), kids.end()), kids.end());
    if (kids.size() < 2 || 2 * tears < n)
      return false;
    // A loop along the input's own border is the surface's edge, not a crack between the
    // children (on a piece of a few faces it can look narrow: a fan's two leaves, 2026-12-05);
    // a gap that opens into the border is the final repair's (CloseBorderGaps).
    for (int i = 0; i < n; ++i)
      if (this->InputBorderEdge(loop[i], loop[(i + 1) % n]))
        return false;
    const double reach = 2.0 * std::max(this->Tol, perimeter / n);
    bool narrow = true;
    for (int i = 0; i < n && narrow; ++i)
    {
      bool near = children[loop[i]].size() > 1; // a stitched vertex: on both sides
      for (int j = 0; j < n && !near; ++j)
      {
        if (i == j)
          continue;
        bool other = false;
        for (int c : children[loop[j]])
          other =
            other || !std::binary_search(children[loop[i]].begin(), children[loop[i]].end(), c);
        near = other && (this->Out.points[loop[i]] - this->Out.points[loop[j]]).norm() <= reach;
      }
      narrow = near;
    }
    return narrow;
  }

  /// Ear clipping (the ear with the shortest new diagonal, not an existing edge), kept when
  /// it closes the loop with a new face and stays within the tolerance; else the diagonals
  /// it counted are taken back.
  bool Triangulate(const std::vector<int>& loop,
    std::vector<Triangle>& added,
    std::vector<int>& addedFace)
  {
    std::vector<int> poly = loop;
    ClipShortestEars(
      this->Out.points,
      poly,
      [&](int a, int c) {
        return !this->Uses.count({ std::min(a, c), std::max(a, c) });
      },
      [&](int a, int b, int c)
      {
        added.push_back({ a, b, c });
        addedFace.push_back(this->HalfEdges.count({ b, a }) ? this->HalfEdges[{ b, a }] : -1);
        ++this->Uses[{ std::min(a, c), std::max(a, c) }];
      });
    std::array<int, 3> last{
      poly[0], poly.size() > 1 ? poly[1] : -1, poly.size() > 2 ? poly[2] : -1
    };
    std::sort(last.begin(), last.end());
    if (poly.size() != 3 || this->FaceSets.count(last))
    {
      // Gave up: the loop stays open (and is reported as a gap).
      for (const Triangle& t : added)
        --this->Uses[{ std::min(t[0], t[2]), std::max(t[0], t[2]) }];
      return false;
    }
    added.push_back({ poly[0], poly[1], poly[2] });
    addedFace.push_back(
      this->HalfEdges.count({ poly[1], poly[0] }) ? this->HalfEdges[{ poly[1], poly[0] }] : -1);
    if (!unfolder_detail::FillWithinTolerance(this->Out.points, loop, added, this->Tol))
    {
      // Not a narrow crack (nor small and flat): a flat fill may leave the surface by more
      // than the tolerance (a missing patch of a curved surface). Left to the final repair,
      // which tests it the same way against the root epsilon.
      for (size_t k = 0; k + 1 < added.size(); ++k)
        --this->Uses[{ std::min(added[k][0], added[k][2]), std::max(added[k][0], added[k][2]) }];
      return false;
    }
    return true;
  }

  /// Adds the fill; each new face takes the attributes of the face across its first loop
  /// edge (or across the loop's first edge).
  void Append(const std::vector<int>& loop,
    const std::vector<Triangle>& added,
    const std::vector<int>& addedFace)
  {
    Piece& out = this->Out;
    for (size_t k = 0; k < added.size(); ++k)
    {
      int from = addedFace[k];
      if (from < 0)
        from = this->HalfEdges[{ loop[1], loop[0] }];
      out.triangles.push_back(added[k]);
      out.faceOrig.push_back(out.faceOrig[from]);
      out.faceCopy.push_back(out.faceCopy[from]);
      out.faceFilled.push_back(1);
      this->FaceChild.push_back(this->FaceChild[from]);
      this->FaceSets.insert(Sorted(added[k]));
    }
    this->Seam.filledFaces += static_cast<int>(added.size());
    ++this->Seam.filledLoops;
  }

  Piece& Out;
  std::vector<int>& FaceChild;
  const std::vector<std::vector<int>>& Children;
  const std::vector<char>& IsTear;
  const double Tol;
  const std::function<bool(int, int)> InputBorderEdge; ///< Unfolder::IsInputBorderEdge
  SeamReport& Seam;
  FlatEdgeMap<int> HalfEdges; // directed edge -> face (the last face of two)
  FlatEdgeMap<int> Uses;      // undirected edge -> faces
  std::unordered_set<std::array<int, 3>, IntegerTripleHash> FaceSets; // sorted corners
  EdgeSet VisitedHoles;
};
} // namespace

/**
 * Fills the small boundary loops left along a seam (e.g. the saw-tooth gaps between a
 * mirrored, approximately symmetric region and its neighbour) by ear clipping. A loop is
 * filled when it has 3..MaximumGapLoop vertices, touches two children, at least half of its
 * vertices are tear vertices of this level, and every vertex has a vertex of another child
 * on the loop within 2 * max(tol, mean loop edge): loops that include an ancestor's open
 * fold line fail that test and stay open, a loop with an edge of the input's own border is
 * never filled (IsInputBorderEdge); so does a loop whose
 * fill would not stay within `tol` of it (FillWithinTolerance: a narrow crack, or small and
 * flat), which bounds the fill by the seam's tolerance. New triangles take the attributes of
 * the face across their first loop edge.
 */
void Unfolder::FillSeamGaps(Piece& out,
  std::vector<int>& faceChild,
  const std::vector<std::vector<int>>& children,
  const std::vector<char>& isTear,
  double tol,
  SeamReport& seam) const
{
  SeamGapFiller(out,
    faceChild,
    children,
    isTear,
    tol,
    seam,
    [this, &out](int a, int b) { return this->IsInputBorderEdge(out, a, b); })
    .Run();
}
} // namespace unfolder_detail
} // namespace foldingmeshes
