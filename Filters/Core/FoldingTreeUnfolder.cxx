#include "FoldingTreeUnfolder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <unordered_map>

namespace foldingmeshes
{
namespace
{
/// Pending tear entries of a vertex: (segmentation level, reflections still required).
using TearList = std::vector<std::pair<int, uint64_t>>;

void Normalize(TearList& t)
{
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
}

bool IsTear(const TearList& t, int level)
{
  for (const auto& e : t)
    if (e.first == level && e.second == 0)
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
  std::vector<int> faceOrig;
  std::vector<int> faceCopy;

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
    for (const Triangle& t : o.triangles)
      triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
    faceOrig.insert(faceOrig.end(), o.faceOrig.begin(), o.faceOrig.end());
    faceCopy.insert(faceCopy.end(), o.faceCopy.begin(), o.faceCopy.end());
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
          piece.tear[v].push_back({ level, 0 });
    for (const MirroredTear& t : m.mirroredTears)
      piece.tear[t.point].push_back({ t.level, t.mirrorMask });
    for (TearList& t : piece.tear)
      Normalize(t);
    piece.onPlane = m.planeMask;
    piece.faceOrig = m.originalFaceIds;
    piece.faceCopy.assign(m.triangles.size(), id);
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
    std::vector<int> mirror(n);
    for (int v = 0; v < n; ++v)
    {
      const double s = p.SignedDistance(piece.points[v]);
      if ((piece.onPlane[v] & bit) || std::abs(s) <= tolerance)
      {
        // Both copies: the reflection at this fold does not matter.
        piece.points[v] -= s * p.normal;
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
      piece.onPlane.push_back(piece.onPlane[v]);
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
    }
  }

  void CountTears(const FoldingNode& node, Piece& piece, SeamReport& seam)
  {
    std::vector<char> isTear(piece.points.size());
    for (int v = 0; v < piece.NumberOfPoints(); ++v)
      seam.tearVertices += isTear[v] = IsTear(piece.tear[v], node.depth);
    seam.unmatchedTearVertices = seam.tearVertices;
    this->CountGaps(piece, isTear, seam);
    Consume(piece, node.depth);
    this->Result.unmatchedTearVertices += seam.unmatchedTearVertices;
    this->Result.gapEdges += seam.gapEdges;
    this->Result.gapLength += seam.gapLength;
  }

  /// Drops the tear entries of a processed level.
  static void Consume(Piece& piece, int level)
  {
    for (TearList& t : piece.tear)
      t.erase(std::remove_if(t.begin(), t.end(), [&](const std::pair<int, uint64_t>& e)
                { return e.first == level; }),
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

  void Stitch(const FoldingNode& node, Piece& piece, const std::vector<int>& childOf,
    SeamReport& seam)
  {
    const int level = node.depth;
    const double tol = std::max(this->Options.stitchToleranceScale * node.epsilon,
      1e-12 * std::max(this->Tree.diagonal, 1e-300));
    std::vector<int> tears;
    for (int v = 0; v < piece.NumberOfPoints(); ++v)
      if (IsTear(piece.tear[v], level))
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
    std::vector<double> spread(n, 0.0);
    for (int v = 0; v < n; ++v)
    {
      const int r = rep[v];
      if (count[r] < 2)
        continue;
      const Vec3 mean = sum[r] / count[r];
      spread[r] = std::max(spread[r], (piece.points[v] - mean).norm());
      ++seam.stitchedVertices;
    }
    for (int v = 0; v < n; ++v)
      if (count[v] >= 2 && rep[v] == v)
      {
        piece.points[v] = sum[v] / count[v];
        seam.maximumStitchDistance = std::max(seam.maximumStitchDistance, spread[v]);
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
    for (int v = 0; v < n; ++v)
      if (rep[v] == v)
      {
        newId[v] = out.NumberOfPoints();
        out.points.push_back(piece.points[v]);
        out.pointOrig.push_back(piece.pointOrig[v]);
        out.pointCopy.push_back(piece.pointCopy[v]);
        out.tear.push_back(piece.tear[v]);
        out.onPlane.push_back(piece.onPlane[v]);
      }
    std::vector<char> rough(out.points.size(), 0);
    for (int v = 0; v < n; ++v)
      if (rep[v] == v && count[v] >= 2 &&
        spread[v] > this->Options.exactStitchFraction * node.epsilon)
        rough[newId[v]] = 1;
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
    }
    // Drop points no face uses any more (keeps the output compact).
    {
      std::vector<char> used(out.points.size(), 0);
      for (const Triangle& t : out.triangles)
        for (int v : t)
          used[v] = 1;
      Piece compact;
      std::vector<int> id(out.points.size(), -1);
      std::vector<char> compactRough;
      for (int v = 0; v < out.NumberOfPoints(); ++v)
        if (used[v])
        {
          id[v] = compact.NumberOfPoints();
          compact.points.push_back(out.points[v]);
          compact.pointOrig.push_back(out.pointOrig[v]);
          compact.pointCopy.push_back(out.pointCopy[v]);
          compact.tear.push_back(out.tear[v]);
          compact.onPlane.push_back(out.onPlane[v]);
          compactRough.push_back(rough[v]);
        }
      for (const Triangle& t : out.triangles)
        compact.triangles.push_back({ id[t[0]], id[t[1]], id[t[2]] });
      compact.faceOrig = std::move(out.faceOrig);
      compact.faceCopy = std::move(out.faceCopy);
      out = std::move(compact);
      rough = std::move(compactRough);
    }

    // Constrained Laplacian smoothing of the rough seam vertices (others fixed).
    int smoothed = 0;
    for (char r : rough)
      smoothed += r;
    if (smoothed > 0 && this->Options.smoothingIterations > 0)
    {
      std::vector<std::vector<int>> ring(out.points.size());
      for (const Triangle& t : out.triangles)
        for (int k = 0; k < 3; ++k)
        {
          const int a = t[k], b = t[(k + 1) % 3];
          if (rough[a])
            ring[a].push_back(b);
          if (rough[b])
            ring[b].push_back(a);
        }
      for (auto& r : ring)
      {
        std::sort(r.begin(), r.end());
        r.erase(std::unique(r.begin(), r.end()), r.end());
      }
      const double lambda = this->Options.smoothingWeight;
      for (int iteration = 0; iteration < this->Options.smoothingIterations; ++iteration)
      {
        std::vector<Vec3> next = out.points;
        for (int v = 0; v < out.NumberOfPoints(); ++v)
          if (rough[v] && !ring[v].empty())
          {
            Vec3 mean = Vec3::Zero();
            for (int w : ring[v])
              mean += out.points[w];
            mean /= static_cast<double>(ring[v].size());
            next[v] = (1.0 - lambda) * out.points[v] + lambda * mean;
          }
        out.points.swap(next);
      }
    }
    seam.smoothedVertices = smoothed;
    {
      std::vector<char> isTear(out.points.size());
      for (int v = 0; v < out.NumberOfPoints(); ++v)
        isTear[v] = IsTear(out.tear[v], level);
      this->CountGaps(out, isTear, seam);
      Consume(out, level);
    }
    piece = std::move(out);
    this->Result.stitchedVertices += seam.stitchedVertices;
    this->Result.unmatchedTearVertices += seam.unmatchedTearVertices;
    this->Result.gapEdges += seam.gapEdges;
    this->Result.gapLength += seam.gapLength;
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
  result.aborted = unfolder.Aborted;
  result.points = std::move(piece.points);
  result.triangles = std::move(piece.triangles);
  result.pointOriginalIds = std::move(piece.pointOrig);
  result.pointCopy = std::move(piece.pointCopy);
  result.faceOriginalIds = std::move(piece.faceOrig);
  result.faceCopy = std::move(piece.faceCopy);
  result.pointMirrored.resize(result.points.size());
  for (size_t v = 0; v < result.points.size(); ++v)
    result.pointMirrored[v] = result.copies[result.pointCopy[v]].mirrored;
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
