#include "FoldingTreeUnfolder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <unordered_map>

namespace foldingmeshes
{
namespace
{
/// Pending flags of a vertex copy (MirroredFlag): (2 * level + flag, reflections still
/// required), flag 0 tear, 1 plane. An entry with no reflection left applies to the copy.
using TearList = std::vector<std::pair<int, uint64_t>>;

void Normalize(TearList& t)
{
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
}

bool IsTear(const TearList& t, int level)
{
  for (const auto& e : t)
    if (e.first == 2 * level && e.second == 0)
      return true;
  return false;
}

bool IsOnPlane(const TearList& t, int level)
{
  for (const auto& e : t)
    if (e.first == 2 * level + 1 && e.second == 0)
      return true;
  return false;
}

/// A partial result of the postorder traversal.
struct Piece
{
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
  std::vector<int> pointOrig;
  std::vector<int> pointCopy;
  std::vector<TearList> tear;
  std::vector<uint64_t> onPlane;
  std::vector<double> budget; ///< how far the point may still move (infinite: unknown)
  std::vector<int> faceOrig;
  std::vector<int> faceCopy;
  std::vector<char> faceFilled;

  int NumberOfPoints() const { return static_cast<int>(points.size()); }
  int NumberOfFaces() const { return static_cast<int>(triangles.size()); }

  void Append(const Piece& o)
  {
    const int offset = NumberOfPoints();
    points.insert(points.end(), o.points.begin(), o.points.end());
    pointOrig.insert(pointOrig.end(), o.pointOrig.begin(), o.pointOrig.end());
    pointCopy.insert(pointCopy.end(), o.pointCopy.begin(), o.pointCopy.end());
    tear.insert(tear.end(), o.tear.begin(), o.tear.end());
    onPlane.insert(onPlane.end(), o.onPlane.begin(), o.onPlane.end());
    budget.insert(budget.end(), o.budget.begin(), o.budget.end());
    for (const Triangle& t : o.triangles)
      triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
    faceOrig.insert(faceOrig.end(), o.faceOrig.begin(), o.faceOrig.end());
    faceCopy.insert(faceCopy.end(), o.faceCopy.begin(), o.faceCopy.end());
    faceFilled.insert(faceFilled.end(), o.faceFilled.begin(), o.faceFilled.end());
  }
};

int FindRoot(std::vector<int>& parent, int a)
{
  while (parent[a] != a)
  {
    parent[a] = parent[parent[a]];
    a = parent[a];
  }
  return a;
}

struct CellKey
{
  long long x, y, z;
  bool operator==(const CellKey& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct CellHash
{
  size_t operator()(const CellKey& k) const
  {
    return static_cast<size_t>(k.x * 73856093LL ^ k.y * 19349663LL ^ k.z * 83492791LL);
  }
};

class Unfolder
{
public:
  Unfolder(const FoldingTree& tree, const UnfoldOptions& options, UnfoldedMesh& result)
    : Tree(tree)
    , Options(options)
    , Result(result)
  {
  }

  bool Aborted = false;

  Piece Unfold(int index)
  {
    const FoldingNode& node = this->Tree.nodes[index];
    Piece piece;
    if (this->Aborted)
      return piece;
    switch (node.kind)
    {
      case FoldingNodeKind::Leaf:
        piece = this->FromLeaf(index);
        break;
      case FoldingNodeKind::Folding:
        piece = this->Unfold(node.children[0]);
        this->Reflect(node, piece);
        break;
      case FoldingNodeKind::Segmentation:
      {
        std::vector<int> childOfPoint;
        for (size_t c = 0; c < node.children.size(); ++c)
        {
          const Piece child = this->Unfold(node.children[c]);
          piece.Append(child);
          childOfPoint.insert(childOfPoint.end(), child.points.size(), static_cast<int>(c));
        }
        SeamReport seam;
        seam.node = index;
        seam.depth = node.depth;
        if (this->Options.stitch)
          this->Stitch(node, piece, childOfPoint, seam);
        else
          this->CountTears(node, piece, seam);
        this->Result.seams.push_back(seam);
        break;
      }
    }
    ++this->Done;
    if (this->Options.progress &&
      !this->Options.progress(static_cast<double>(this->Done) / this->Tree.NumberOfNodes()))
      this->Aborted = true;
    return piece;
  }

private:
  Piece FromLeaf(int index)
  {
    const FoldingLeafMesh& m = this->Tree.nodes[index].mesh;
    UnfoldCopy copy;
    copy.leaf = index;
    const int id = static_cast<int>(this->Result.copies.size());
    this->Result.copies.push_back(copy);
    Piece piece;
    piece.points = m.points;
    piece.triangles = m.triangles;
    piece.pointOrig = m.originalPointIds;
    piece.pointCopy.assign(m.points.size(), id);
    piece.tear.assign(m.points.size(), {});
    for (int v = 0; v < m.NumberOfPoints(); ++v)
      for (int level = 0; level < MaximumFoldingTreeLevels; ++level)
        if (m.tearMask[v] & (uint64_t(1) << level))
          piece.tear[v].push_back({ 2 * level, 0 });
    for (const MirroredFlag& t : m.mirroredFlags)
      piece.tear[t.point].push_back(
        { 2 * t.level + (t.flag == LevelFlag::Plane ? 1 : 0), t.mirrorMask });
    for (TearList& t : piece.tear)
      Normalize(t);
    piece.onPlane = m.planeMask;
    if (m.errorBudget.empty() || !this->Options.respectErrorBudget)
      piece.budget.assign(m.points.size(), std::numeric_limits<double>::infinity());
    else
      piece.budget = m.errorBudget;
    piece.faceOrig = m.originalFaceIds;
    piece.faceCopy.assign(m.triangles.size(), id);
    piece.faceFilled.assign(m.triangles.size(), 0);
    return piece;
  }

  void Reflect(const FoldingNode& node, Piece& piece)
  {
    const Plane& p = node.plane;
    const uint64_t bit = uint64_t(1) << node.depth;
    const double tolerance = this->Options.planeTolerance * this->Tree.diagonal;
    // Mirrored copies.
    std::map<int, int> mirrorCopy;
    const Eigen::Matrix3d R = Eigen::Matrix3d::Identity() - 2.0 * p.normal * p.normal.transpose();
    const Vec3 shift = 2.0 * p.normal.dot(p.origin) * p.normal;
    for (int c : piece.faceCopy)
      mirrorCopy[c] = -1;
    for (int c : piece.pointCopy)
      mirrorCopy[c] = -1;
    for (auto& entry : mirrorCopy)
    {
      UnfoldCopy copy = this->Result.copies[entry.first];
      copy.mirrorMask |= bit;
      copy.mirrored = !copy.mirrored;
      copy.linear = R * copy.linear;
      copy.translation = R * copy.translation + shift;
      entry.second = static_cast<int>(this->Result.copies.size());
      this->Result.copies.push_back(copy);
    }
    const int n = piece.NumberOfPoints();
    // Open boundary edges lying within the fold-line slab: the copies of fold-line vertices
    // made by approximate symmetries below this node are off the plane by less than the
    // node's epsilon (the error budget of its subtree).
    std::vector<char> inSlab(n, 0);
    if (this->Options.foldLineToleranceScale > 0.0)
    {
      const double slab = this->Options.foldLineToleranceScale * node.epsilon;
      std::map<std::pair<int, int>, int> edges;
      for (const Triangle& t : piece.triangles)
        for (int k = 0; k < 3; ++k)
          ++edges[{ std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]) }];
      for (const auto& e : edges)
      {
        const int a = e.first.first, b = e.first.second;
        if (e.second == 1 && std::abs(p.SignedDistance(piece.points[a])) <= slab &&
          std::abs(p.SignedDistance(piece.points[b])) <= slab)
          inSlab[a] = inSlab[b] = 1;
      }
    }
    std::vector<int> mirror(n);
    for (int v = 0; v < n; ++v)
    {
      const double s = p.SignedDistance(piece.points[v]);
      if ((piece.onPlane[v] & bit) || IsOnPlane(piece.tear[v], node.depth) ||
        std::abs(s) <= tolerance || (inSlab[v] && std::abs(s) <= piece.budget[v]))
      {
        // Both copies: the reflection at this fold does not matter. Onto the plane, or as
        // far towards it as the error budget allows (flagged copies of fold-line vertices
        // made by approximate folds below may lie off it).
        const double move =
          std::abs(s) <= tolerance ? std::abs(s) : std::min(std::abs(s), piece.budget[v]);
        if (move > 0.0)
          piece.points[v] -= (s > 0 ? move : -move) * p.normal;
        piece.budget[v] = std::max(0.0, piece.budget[v] - move);
        piece.onPlane[v] |= bit;
        for (auto& e : piece.tear[v])
          e.second &= ~bit;
        Normalize(piece.tear[v]);
        mirror[v] = v;
        ++this->Result.planeMergedVertices;
        continue;
      }
      TearList kept, reflected;
      for (const auto& e : piece.tear[v])
        if (e.second & bit)
          reflected.push_back({ e.first, e.second & ~bit });
        else
          kept.push_back(e);
      piece.tear[v] = std::move(kept);
      mirror[v] = piece.NumberOfPoints();
      piece.points.push_back(p.Reflect(piece.points[v]));
      piece.pointOrig.push_back(piece.pointOrig[v]);
      piece.pointCopy.push_back(mirrorCopy[piece.pointCopy[v]]);
      piece.tear.push_back(std::move(reflected));
      piece.onPlane.push_back(0); // the copy's own fold-line flags come from `reflected`
      piece.budget.push_back(piece.budget[v]);
    }
    const int nf = piece.NumberOfFaces();
    for (int f = 0; f < nf; ++f)
    {
      const Triangle t = piece.triangles[f];
      if (mirror[t[0]] == t[0] && mirror[t[1]] == t[1] && mirror[t[2]] == t[2])
      {
        ++this->Result.droppedMirrorFaces;
        continue;
      }
      piece.triangles.push_back({ mirror[t[0]], mirror[t[2]], mirror[t[1]] });
      piece.faceOrig.push_back(piece.faceOrig[f]);
      piece.faceCopy.push_back(mirrorCopy[piece.faceCopy[f]]);
      piece.faceFilled.push_back(piece.faceFilled[f]);
    }
    Consume(piece, 2 * node.depth + 1);
  }

  void CountTears(const FoldingNode& node, Piece& piece, SeamReport& seam)
  {
    std::vector<char> isTear(piece.points.size());
    for (int v = 0; v < piece.NumberOfPoints(); ++v)
      seam.tearVertices += isTear[v] = IsTear(piece.tear[v], node.depth);
    seam.unmatchedTearVertices = seam.tearVertices;
    this->CountGaps(piece, isTear, seam);
    Consume(piece, 2 * node.depth);
    this->Result.unmatchedTearVertices += seam.unmatchedTearVertices;
    this->Result.gapEdges += seam.gapEdges;
    this->Result.gapLength += seam.gapLength;
  }

  /// Drops the entries of a processed level and flag (code = 2 * level + flag).
  static void Consume(Piece& piece, int code)
  {
    for (TearList& t : piece.tear)
      t.erase(
        std::remove_if(
          t.begin(), t.end(), [&](const std::pair<int, uint64_t>& e) { return e.first == code; }),
        t.end());
  }

  /// Boundary edges whose two vertices are tear vertices.
  static void CountGaps(const Piece& piece, const std::vector<char>& isTear, SeamReport& seam)
  {
    std::map<std::pair<int, int>, int> edges;
    for (const Triangle& t : piece.triangles)
      for (int k = 0; k < 3; ++k)
      {
        const int a = t[k], b = t[(k + 1) % 3];
        if (isTear[a] && isTear[b])
          ++edges[{ std::min(a, b), std::max(a, b) }];
      }
    for (const auto& e : edges)
      if (e.second == 1)
      {
        ++seam.gapEdges;
        seam.gapLength += (piece.points[e.first.first] - piece.points[e.first.second]).norm();
      }
  }

  /**
   * Inserts unmatched tear vertices into open boundary edges of other children whose two end
   * points are tear vertices, within `tol` (the vertex moves half way to the edge). Returns
   * the number of vertices inserted.
   */
  static int Zip(Piece& out,
    std::vector<int>& faceChild,
    std::vector<std::vector<int>>& children,
    std::vector<char>& matched,
    const std::vector<char>& isTear,
    double tol,
    std::vector<double>& rough)
  {
    using Edge = std::pair<int, int>;
    auto key = [](int a, int b) { return Edge{ std::min(a, b), std::max(a, b) }; };
    std::map<Edge, std::vector<int>> edgeFaces;
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
      {
        auto it = edgeFaces.find(key(t[k], t[(k + 1) % 3]));
        it->second.erase(std::find(it->second.begin(), it->second.end(), f));
        if (it->second.empty())
          edgeFaces.erase(it);
      }
    };
    for (int f = 0; f < out.NumberOfFaces(); ++f)
      addFace(f);
    int zipped = 0;
    for (int pass = 0; pass < 3; ++pass)
    {
      bool changed = false;
      // The open edges between two candidates at the start of the pass (edges split during
      // the pass are skipped, the new ones wait for the next pass), bucketed on a grid of
      // cell `tol` by the box of the edge grown by tol.
      std::vector<Edge> open;
      for (const auto& e : edgeFaces)
        if (e.second.size() == 1 && isTear[e.first.first] && isTear[e.first.second])
          open.push_back(e.first);
      const double cell = std::max(tol, 1e-300);
      auto cellOf = [cell](double x) { return static_cast<long long>(std::floor(x / cell)); };
      std::unordered_map<CellKey, std::vector<int>, CellHash> buckets;
      for (int i = 0; i < static_cast<int>(open.size()); ++i)
      {
        const Vec3 lo = out.points[open[i].first].cwiseMin(out.points[open[i].second]);
        const Vec3 hi = out.points[open[i].first].cwiseMax(out.points[open[i].second]);
        for (long long x = cellOf(lo.x() - tol); x <= cellOf(hi.x() + tol); ++x)
          for (long long y = cellOf(lo.y() - tol); y <= cellOf(hi.y() + tol); ++y)
            for (long long z = cellOf(lo.z() - tol); z <= cellOf(hi.z() + tol); ++z)
              buckets[CellKey{ x, y, z }].push_back(i);
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
        auto bucket = buckets.find(CellKey{ cellOf(x.x()), cellOf(x.y()), cellOf(x.z()) });
        if (bucket == buckets.end())
          continue;
        for (int i : bucket->second) // increasing i: the map order of the edges
        {
          const auto e = edgeFaces.find(open[i]);
          if (e == edgeFaces.end() || e->second.size() != 1)
            continue;
          const int a = e->first.first, b = e->first.second, f = e->second[0];
          if (a == u || b == u || !isTear[a] || !isTear[b] ||
            std::binary_search(children[u].begin(), children[u].end(), faceChild[f]))
            continue;
          const Vec3 ab = out.points[b] - out.points[a];
          const double len2 = ab.squaredNorm();
          if (!(len2 > 0.0))
            continue;
          const double t = (x - out.points[a]).dot(ab) / len2;
          if (t <= 0.02 || t >= 0.98)
            continue;
          const Vec3 q = out.points[a] + t * ab;
          const double d = (x - q).norm();
          if (d <= bestDistance)
          {
            bestDistance = d;
            bestFace = f;
            bestEdge = e->first;
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

  /**
   * Fills the small boundary loops left along a seam (e.g. the saw-tooth gaps between a
   * mirrored, approximately symmetric region and its neighbour) by ear clipping. A loop is
   * filled when it has 3..maximumGapLoop vertices, touches two children, at least half of its
   * vertices are tear vertices of this level, and every vertex has a vertex of another child
   * on the loop within 2 * max(tol, mean loop edge): loops that include an ancestor's open
   * fold line or the input's own border fail that test and stay open. New triangles take the
   * attributes of the face across their first loop edge.
   */
  static void FillSeamGaps(Piece& out,
    std::vector<int>& faceChild,
    const std::vector<std::vector<int>>& children,
    const std::vector<char>& isTear,
    double tol,
    SeamReport& seam)
  {
    constexpr int maximumGapLoop = 256;
    std::map<std::pair<int, int>, int> halfEdges; // directed edge -> face
    std::map<std::pair<int, int>, int> uses;
    std::set<std::array<int, 3>> faceSets;
    for (int f = 0; f < out.NumberOfFaces(); ++f)
    {
      const Triangle& t = out.triangles[f];
      std::array<int, 3> key{ t[0], t[1], t[2] };
      std::sort(key.begin(), key.end());
      faceSets.insert(key);
      for (int k = 0; k < 3; ++k)
      {
        const int a = t[k], b = t[(k + 1) % 3];
        halfEdges[{ a, b }] = f;
        ++uses[{ std::min(a, b), std::max(a, b) }];
      }
    }
    // Boundary loops, traced along hole half-edges (the reverses of open face half-edges);
    // at a pinch vertex (several openings) the next edge is found by turning around the
    // vertex through its faces, so each gap is traced as its own loop.
    auto isOpen = [&](int a, int b) { return uses[{ std::min(a, b), std::max(a, b) }] == 1; };
    auto nextHole = [&](int a, int b) -> int
    {
      // Arrived at b by the hole edge a -> b: face half-edge b -> a.
      auto it = halfEdges.find({ b, a });
      for (int guard = 0; it != halfEdges.end() && guard < 64; ++guard)
      {
        const Triangle& t = out.triangles[it->second];
        int k = 0;
        while (t[(k + 1) % 3] != b)
          ++k;
        const int y = t[k]; // half-edge y -> b in this face
        if (isOpen(y, b))
          return y;
        it = halfEdges.find({ b, y });
      }
      return -1;
    };
    std::set<std::pair<int, int>> visitedHoles;
    std::vector<std::pair<int, int>> holes;
    for (const auto& h : halfEdges)
      if (isOpen(h.first.first, h.first.second))
        holes.push_back({ h.first.second, h.first.first });
    for (const auto& first : holes)
    {
      if (visitedHoles.count(first))
        continue;
      std::vector<int> loop;
      std::pair<int, int> edge = first;
      bool closed = false;
      while (static_cast<int>(loop.size()) <= maximumGapLoop)
      {
        if (visitedHoles.count(edge))
        {
          closed = edge == first && !loop.empty();
          break;
        }
        visitedHoles.insert(edge);
        loop.push_back(edge.first);
        const int nx = nextHole(edge.first, edge.second);
        if (nx < 0)
          break;
        edge = { edge.second, nx };
      }
      std::vector<int> sortedLoop = loop;
      std::sort(sortedLoop.begin(), sortedLoop.end());
      const bool simple =
        std::adjacent_find(sortedLoop.begin(), sortedLoop.end()) == sortedLoop.end();
      const int n = static_cast<int>(loop.size());
      if (!closed || !simple || n < 3 || n > maximumGapLoop)
        continue;
      // Seam loop?
      std::vector<int> kids;
      int tears = 0;
      double perimeter = 0.0;
      for (int i = 0; i < n; ++i)
      {
        kids.insert(kids.end(), children[loop[i]].begin(), children[loop[i]].end());
        tears += isTear[loop[i]];
        perimeter += (out.points[loop[i]] - out.points[loop[(i + 1) % n]]).norm();
      }
      std::sort(kids.begin(), kids.end());
      kids.erase(std::unique(kids.begin(), kids.end()), kids.end());
      if (kids.size() < 2 || 2 * tears < n)
        continue;
      const double reach = 2.0 * std::max(tol, perimeter / n);
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
          near = other && (out.points[loop[i]] - out.points[loop[j]]).norm() <= reach;
        }
        narrow = near;
      }
      if (!narrow)
        continue;
      // Ear clipping: the ear with the shortest new diagonal, not an existing edge.
      std::vector<int> poly = loop;
      std::vector<Triangle> added;
      std::vector<int> addedFace;
      while (poly.size() > 3)
      {
        const int m = static_cast<int>(poly.size());
        int best = -1;
        double bestLength = std::numeric_limits<double>::infinity();
        for (int i = 0; i < m; ++i)
        {
          const int a = poly[i], c = poly[(i + 2) % m];
          if (uses.count({ std::min(a, c), std::max(a, c) }))
            continue;
          const double length = (out.points[a] - out.points[c]).norm();
          if (length < bestLength)
          {
            bestLength = length;
            best = i;
          }
        }
        if (best < 0)
          break;
        const int a = poly[best], b = poly[(best + 1) % m], c = poly[(best + 2) % m];
        added.push_back({ a, b, c });
        addedFace.push_back(halfEdges.count({ b, a }) ? halfEdges[{ b, a }] : -1);
        ++uses[{ std::min(a, c), std::max(a, c) }];
        poly.erase(poly.begin() + (best + 1) % m);
      }
      std::array<int, 3> last{
        poly[0], poly.size() > 1 ? poly[1] : -1, poly.size() > 2 ? poly[2] : -1
      };
      std::sort(last.begin(), last.end());
      if (poly.size() != 3 || faceSets.count(last))
      {
        // Gave up: the loop stays open (and is reported as a gap).
        for (const Triangle& t : added)
          --uses[{ std::min(t[0], t[2]), std::max(t[0], t[2]) }];
        continue;
      }
      added.push_back({ poly[0], poly[1], poly[2] });
      addedFace.push_back(
        halfEdges.count({ poly[1], poly[0] }) ? halfEdges[{ poly[1], poly[0] }] : -1);
      for (size_t k = 0; k < added.size(); ++k)
      {
        int from = addedFace[k];
        if (from < 0)
          from = halfEdges[{ loop[1], loop[0] }];
        out.triangles.push_back(added[k]);
        out.faceOrig.push_back(out.faceOrig[from]);
        out.faceCopy.push_back(out.faceCopy[from]);
        out.faceFilled.push_back(1);
        faceChild.push_back(faceChild[from]);
        std::array<int, 3> key{ added[k][0], added[k][1], added[k][2] };
        std::sort(key.begin(), key.end());
        faceSets.insert(key);
      }
      seam.filledFaces += static_cast<int>(added.size());
      ++seam.filledLoops;
    }
  }

  void Stitch(const FoldingNode& node,
    Piece& piece,
    const std::vector<int>& childOf,
    SeamReport& seam)
  {
    const int level = node.depth;
    const double tol = std::max(this->Options.stitchToleranceScale * node.epsilon,
      1e-12 * std::max(this->Tree.diagonal, 1e-300));
    std::vector<char> isTear(piece.points.size());
    for (int v = 0; v < piece.NumberOfPoints(); ++v)
      isTear[v] = IsTear(piece.tear[v], level);
    this->StitchVertices(
      piece, isTear, childOf, tol, node.epsilon, this->Options.fillSeamGaps, seam);
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

public:
  /**
   * The final seam pass (UnfoldOptions::weldBoundaries): every vertex on an open edge is a
   * candidate, copies play the part of children (a copy's own vertices are never merged),
   * tolerance weldToleranceScale * root epsilon; moves are bounded by the error budgets.
   */
  void WeldBoundaries(Piece& piece, SeamReport& seam)
  {
    std::map<std::pair<int, int>, int> edges;
    for (const Triangle& t : piece.triangles)
      for (int k = 0; k < 3; ++k)
        ++edges[{ std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]) }];
    std::vector<char> open(piece.points.size(), 0);
    for (const auto& e : edges)
      if (e.second == 1)
        open[e.first.first] = open[e.first.second] = 1;
    const double tol = std::max(this->Options.weldToleranceScale * this->Tree.rootEpsilon,
      1e-12 * std::max(this->Tree.diagonal, 1e-300));
    // No gap filling here: loops of open edges between copies may be the input's own
    // borders (new faces there would leave the input surface).
    const std::vector<int> copyOf = piece.pointCopy;
    this->StitchVertices(piece, open, copyOf, tol, this->Tree.rootEpsilon, false, seam);
  }

private:
  /**
   * Stitching of the candidate vertices `isTear` (see UnfoldFoldingTree): pairing by
   * union-find within `tol` (never two vertices of one child), merged clusters placed where
   * every member's move stays within its error budget, zipper, gap filling, constrained
   * smoothing. Fills seam's stitch statistics (not the gaps).
   */
  void StitchVertices(Piece& piece,
    const std::vector<char>& candidate,
    const std::vector<int>& childOf,
    double tol,
    double epsilon,
    bool fill,
    SeamReport& seam)
  {
    std::vector<int> tears;
    for (int v = 0; v < piece.NumberOfPoints(); ++v)
      if (candidate[v])
        tears.push_back(v);
    seam.tearVertices = static_cast<int>(tears.size());

    auto key = [&](const Vec3& x)
    {
      return CellKey{ static_cast<long long>(std::floor(x.x() / tol)),
        static_cast<long long>(std::floor(x.y() / tol)),
        static_cast<long long>(std::floor(x.z() / tol)) };
    };
    std::unordered_map<CellKey, std::vector<int>, CellHash> cells;
    for (int v : tears)
      cells[key(piece.points[v])].push_back(v);

    // Proposals: each tear vertex's nearest tear vertex of another child.
    struct Proposal
    {
      double distance;
      int a, b;
    };
    std::vector<Proposal> proposals;
    for (int v : tears)
    {
      const CellKey c = key(piece.points[v]);
      int best = -1;
      double bestDistance = tol;
      for (long long dx = -1; dx <= 1; ++dx)
        for (long long dy = -1; dy <= 1; ++dy)
          for (long long dz = -1; dz <= 1; ++dz)
          {
            auto it = cells.find(CellKey{ c.x + dx, c.y + dy, c.z + dz });
            if (it == cells.end())
              continue;
            for (int w : it->second)
            {
              if (childOf[w] == childOf[v])
                continue;
              const double d = (piece.points[w] - piece.points[v]).norm();
              if (d <= tol && (best < 0 || d < bestDistance || (d == bestDistance && w < best)))
              {
                bestDistance = d;
                best = w;
              }
            }
          }
      if (best >= 0)
        proposals.push_back({ bestDistance, std::min(v, best), std::max(v, best) });
    }
    std::sort(proposals.begin(),
      proposals.end(),
      [](const Proposal& x, const Proposal& y)
      {
        if (x.distance != y.distance)
          return x.distance < y.distance;
        if (x.a != y.a)
          return x.a < y.a;
        return x.b < y.b;
      });

    const int n = piece.NumberOfPoints();
    std::vector<int> parent(n);
    std::iota(parent.begin(), parent.end(), 0);
    std::unordered_map<int, std::vector<int>> childrenOfRoot; // sorted child ids per cluster
    auto childrenOf = [&](int root) -> std::vector<int>&
    {
      auto it = childrenOfRoot.find(root);
      if (it == childrenOfRoot.end())
        it = childrenOfRoot.emplace(root, std::vector<int>{ childOf[root] }).first;
      return it->second;
    };
    for (const Proposal& pr : proposals)
    {
      const int ra = FindRoot(parent, pr.a), rb = FindRoot(parent, pr.b);
      if (ra == rb)
        continue;
      std::vector<int>& ca = childrenOf(ra);
      std::vector<int>& cb = childrenOf(rb);
      bool disjoint = true;
      for (int c : cb)
        disjoint = disjoint && !std::binary_search(ca.begin(), ca.end(), c);
      if (!disjoint)
        continue;
      const int root = std::min(ra, rb), other = std::max(ra, rb);
      std::vector<int> merged;
      std::merge(ca.begin(), ca.end(), cb.begin(), cb.end(), std::back_inserter(merged));
      parent[other] = root;
      childrenOfRoot[root] = std::move(merged);
      childrenOfRoot.erase(other);
    }

    // Clusters: mean position; spread decides smoothing.
    std::vector<int> rep(n);
    std::vector<Vec3> sum(n, Vec3::Zero());
    std::vector<int> count(n, 0);
    for (int v = 0; v < n; ++v)
    {
      rep[v] = FindRoot(parent, v);
      sum[rep[v]] += piece.points[v];
      ++count[rep[v]];
    }
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
        childrenOfRoot.erase(r);
        members[r].clear();
      }
    }
    std::vector<double> spread(n, 0.0);
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
      }
    seam.unmatchedTearVertices = seam.tearVertices - seam.stitchedVertices;

    // Remap faces; drop collapsed and duplicate ones.
    Piece out;
    std::vector<int> newId(n, -1);
    std::vector<std::vector<int>> outChildren; // children a point belongs to (sorted)
    std::vector<char> outMatched, outCandidate;
    for (int v = 0; v < n; ++v)
      if (rep[v] == v)
      {
        newId[v] = out.NumberOfPoints();
        out.points.push_back(piece.points[v]);
        out.pointOrig.push_back(piece.pointOrig[v]);
        out.pointCopy.push_back(piece.pointCopy[v]);
        out.tear.push_back(piece.tear[v]);
        out.onPlane.push_back(piece.onPlane[v]);
        out.budget.push_back(piece.budget[v]);
        outCandidate.push_back(candidate[v]);
        auto it = childrenOfRoot.find(v);
        outChildren.push_back(
          it != childrenOfRoot.end() ? it->second : std::vector<int>{ childOf[v] });
        outMatched.push_back(count[v] >= 2);
      }
    std::vector<int> faceChild;
    // Smoothing budget: how far a merged vertex may move (its cluster's spread); 0: fixed.
    std::vector<double> rough(out.points.size(), 0.0);
    for (int v = 0; v < n; ++v)
      if (rep[v] == v && count[v] >= 2 && spread[v] > this->Options.exactStitchFraction * epsilon)
        rough[newId[v]] = spread[v];
    std::map<std::array<int, 3>, int> seen;
    for (int f = 0; f < piece.NumberOfFaces(); ++f)
    {
      const Triangle& t = piece.triangles[f];
      const Triangle u{ newId[rep[t[0]]], newId[rep[t[1]]], newId[rep[t[2]]] };
      if (u[0] == u[1] || u[1] == u[2] || u[0] == u[2])
      {
        ++seam.droppedFaces;
        continue;
      }
      std::array<int, 3> sorted{ u[0], u[1], u[2] };
      std::sort(sorted.begin(), sorted.end());
      if (!seen.emplace(sorted, f).second)
      {
        ++seam.droppedFaces;
        continue;
      }
      out.triangles.push_back(u);
      out.faceOrig.push_back(piece.faceOrig[f]);
      out.faceCopy.push_back(piece.faceCopy[f]);
      out.faceFilled.push_back(piece.faceFilled[f]);
      faceChild.push_back(childOf[t[0]]);
    }
    // Drop points no face uses any more (keeps the output compact).
    {
      std::vector<char> used(out.points.size(), 0);
      for (const Triangle& t : out.triangles)
        for (int v : t)
          used[v] = 1;
      Piece compact;
      std::vector<int> id(out.points.size(), -1);
      std::vector<double> compactRough;
      std::vector<char> compactMatched, compactCandidate;
      std::vector<std::vector<int>> compactChildren;
      for (int v = 0; v < out.NumberOfPoints(); ++v)
        if (used[v])
        {
          id[v] = compact.NumberOfPoints();
          compact.points.push_back(out.points[v]);
          compact.pointOrig.push_back(out.pointOrig[v]);
          compact.pointCopy.push_back(out.pointCopy[v]);
          compact.tear.push_back(out.tear[v]);
          compact.onPlane.push_back(out.onPlane[v]);
          compact.budget.push_back(out.budget[v]);
          compactCandidate.push_back(outCandidate[v]);
          compactRough.push_back(rough[v]);
          compactMatched.push_back(outMatched[v]);
          compactChildren.push_back(outChildren[v]);
        }
      for (const Triangle& t : out.triangles)
        compact.triangles.push_back({ id[t[0]], id[t[1]], id[t[2]] });
      compact.faceOrig = std::move(out.faceOrig);
      compact.faceCopy = std::move(out.faceCopy);
      compact.faceFilled = std::move(out.faceFilled);
      out = std::move(compact);
      rough = std::move(compactRough);
      outMatched = std::move(compactMatched);
      outChildren = std::move(compactChildren);
      outCandidate = std::move(compactCandidate);
    }

    // Zipper: tear vertices left without a partner vertex are inserted into the nearest open
    // seam edge of another child (splitting its triangle), so seams whose two sides were
    // tessellated differently close too.
    if (this->Options.zipper)
    {
      const int zipped = Zip(out, faceChild, outChildren, outMatched, outCandidate, tol, rough);
      seam.zippedVertices = zipped;
      seam.stitchedVertices += zipped;
      seam.unmatchedTearVertices -= zipped;
    }
    if (fill)
      FillSeamGaps(out, faceChild, outChildren, outCandidate, tol, seam);

    // Constrained Laplacian smoothing of the rough seam vertices: the others are fixed, and
    // each moves at most by its budget (the distance its stitch already moved it), so
    // sharp features along a seam are not eroded.
    int smoothed = 0;
    for (double r : rough)
      smoothed += r > 0.0;
    if (smoothed > 0 && this->Options.smoothingIterations > 0)
    {
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
      const double lambda = this->Options.smoothingWeight;
      const std::vector<Vec3> start = out.points;
      for (size_t v = 0; v < rough.size(); ++v)
        rough[v] = std::min(rough[v], out.budget[v]);
      for (int iteration = 0; iteration < this->Options.smoothingIterations; ++iteration)
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
    }
    seam.smoothedVertices = smoothed;
    piece = std::move(out);
  }

  const FoldingTree& Tree;
  const UnfoldOptions& Options;
  UnfoldedMesh& Result;
  int Done = 0;
};
}

bool UnfoldFoldingTree(const FoldingTree& tree,
  const UnfoldOptions& options,
  UnfoldedMesh& result,
  std::string& error)
{
  result = UnfoldedMesh();
  error = tree.Validate();
  if (!error.empty())
  {
    error = "invalid folding tree: " + error;
    return false;
  }
  Unfolder unfolder(tree, options, result);
  Piece piece = unfolder.Unfold(0);
  if (!unfolder.Aborted && options.stitch && options.weldBoundaries)
  {
    result.weld.node = -1;
    unfolder.WeldBoundaries(piece, result.weld);
  }
  result.aborted = unfolder.Aborted;
  result.points = std::move(piece.points);
  result.triangles = std::move(piece.triangles);
  result.pointOriginalIds = std::move(piece.pointOrig);
  result.pointCopy = std::move(piece.pointCopy);
  result.faceOriginalIds = std::move(piece.faceOrig);
  result.faceCopy = std::move(piece.faceCopy);
  result.faceFilled = std::move(piece.faceFilled);
  result.pointMirrored.resize(result.points.size());
  for (size_t v = 0; v < result.points.size(); ++v)
    result.pointMirrored[v] = result.copies[result.pointCopy[v]].mirrored;
  {
    // Per undirected edge: uses in increasing and in decreasing vertex order.
    std::map<std::pair<int, int>, std::array<int, 2>> edges;
    for (const Triangle& t : result.triangles)
      for (int k = 0; k < 3; ++k)
      {
        const int a = t[k], b = t[(k + 1) % 3];
        auto it =
          edges.emplace(std::make_pair(std::min(a, b), std::max(a, b)), std::array<int, 2>{ 0, 0 })
            .first;
        ++it->second[a < b ? 0 : 1];
      }
    for (const auto& e : edges)
    {
      const int uses = e.second[0] + e.second[1];
      result.openEdges += uses == 1;
      result.nonManifoldEdges += uses > 2;
      result.misorientedEdges += uses == 2 && e.second[0] != 1;
    }
    for (const SeamReport& seam : result.seams)
      result.budgetRejectedClusters += seam.budgetRejectedClusters;
    result.budgetRejectedClusters += result.weld.budgetRejectedClusters;
  }
  result.filledFaces =
    static_cast<int>(std::count(result.faceFilled.begin(), result.faceFilled.end(), char(1)));
  result.faceLeaf.resize(result.triangles.size());
  result.faceMirrored.resize(result.triangles.size());
  for (size_t f = 0; f < result.triangles.size(); ++f)
  {
    result.faceLeaf[f] = result.copies[result.faceCopy[f]].leaf;
    result.faceMirrored[f] = result.copies[result.faceCopy[f]].mirrored;
  }
  return true;
}
}
