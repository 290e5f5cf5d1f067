// Final repair of the unfolded mesh (UnfoldOptions::closeHoles): faces that make an edge
// non-manifold are dropped, the orientation is made consistent per connected component, and
// the boundary loops that are not the input's own border are filled within the error bound.
#include "FoldingTreeUnfolderInternal.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
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
using Edge = std::pair<int, int>;
Edge Key(int a, int b)
{
  return { std::min(a, b), std::max(a, b) };
}

Vec3 Normal(const Piece& p, const Triangle& t)
{
  return (p.points[t[1]] - p.points[t[0]]).cross(p.points[t[2]] - p.points[t[0]]);
}

double Area(const Piece& p, const Triangle& t)
{
  return 0.5 * Normal(p, t).norm();
}

/// Undirected edge -> faces using it.
std::map<Edge, std::vector<int>> EdgeFaces(const Piece& p)
{
  std::map<Edge, std::vector<int>> edges;
  for (int f = 0; f < p.NumberOfFaces(); ++f)
  {
    const Triangle& t = p.triangles[f];
    for (int k = 0; k < 3; ++k)
      edges[Key(t[k], t[(k + 1) % 3])].push_back(f);
  }
  return edges;
}

/// +1 when face t traverses a -> b, -1 when b -> a, 0 when it does not use the edge.
int Direction(const Triangle& t, int a, int b)
{
  for (int k = 0; k < 3; ++k)
  {
    if (t[k] == a && t[(k + 1) % 3] == b)
      return 1;
    if (t[k] == b && t[(k + 1) % 3] == a)
      return -1;
  }
  return 0;
}

/// Keeps the faces whose flag is 0 (and their attributes), in order.
void KeepFaces(Piece& p, const std::vector<char>& drop)
{
  Piece out;
  for (int f = 0; f < p.NumberOfFaces(); ++f)
    if (!drop[f])
    {
      out.triangles.push_back(p.triangles[f]);
      out.faceOrig.push_back(p.faceOrig[f]);
      out.faceCopy.push_back(p.faceCopy[f]);
      out.faceFilled.push_back(p.faceFilled[f]);
    }
  p.triangles = std::move(out.triangles);
  p.faceOrig = std::move(out.faceOrig);
  p.faceCopy = std::move(out.faceCopy);
  p.faceFilled = std::move(out.faceFilled);
}

/// Distance from x to the segment [a, b].
double SegmentDistance(const Vec3& x, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((x - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (x - (a + t * ab)).norm();
}
} // namespace

/**
 * Drops faces until no edge has more than two: at each such edge the two faces kept are
 * those that traverse it in opposite directions and are the least folded against each other
 * (largest normal agreement), preferring faces that are not gap fills; the others go (the
 * holes they leave are filled afterwards). Returns the number of faces dropped.
 */
int Unfolder::DropNonManifoldFaces(Piece& piece)
{
  int dropped = 0;
  for (int round = 0; round < 4; ++round)
  {
    const auto edges = EdgeFaces(piece);
    std::vector<char> drop(piece.triangles.size(), 0);
    bool any = false;
    for (const auto& e : edges)
    {
      std::vector<int> faces;
      for (int f : e.second)
        if (!drop[f])
          faces.push_back(f);
      if (faces.size() <= 2)
        continue;
      any = true;
      const int a = e.first.first, b = e.first.second;
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
          // Consistent pairs first, then real faces, then the flattest pair.
          double score = (opposite ? 10.0 : 0.0) -
            4.0 * (piece.faceFilled[f] + piece.faceFilled[g]) +
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

/**
 * Boundary loops of the mesh, traced along hole half-edges (the reverses of the open face
 * half-edges) and split at pinch vertices into simple loops.
 */
std::vector<std::vector<int>> Unfolder::BoundaryLoops(const Piece& piece)
{
  std::map<Edge, int> uses;
  std::map<int, std::vector<int>> holeNext; // hole half-edge a -> b, by a
  for (const Triangle& t : piece.triangles)
    for (int k = 0; k < 3; ++k)
      ++uses[Key(t[k], t[(k + 1) % 3])];
  for (const Triangle& t : piece.triangles)
    for (int k = 0; k < 3; ++k)
    {
      const int a = t[k], b = t[(k + 1) % 3];
      if (uses[Key(a, b)] == 1)
        holeNext[b].push_back(a);
    }
  std::vector<std::vector<int>> loops;
  std::set<Edge> visited;
  for (const auto& start : holeNext)
    for (int firstNext : start.second)
    {
      if (visited.count({ start.first, firstNext }))
        continue;
      // Walk unused hole half-edges until none leaves the current vertex.
      std::vector<int> walk;
      int a = start.first, b = firstNext;
      bool closed = false;
      while (true)
      {
        visited.insert({ a, b });
        walk.push_back(a);
        auto it = holeNext.find(b);
        if (it == holeNext.end())
          break; // a dead end: inconsistent orientation around b
        int next = -1;
        for (int c : it->second)
          if (!visited.count({ b, c }))
          {
            next = c;
            break;
          }
        if (next < 0)
        {
          closed = b == start.first; // back where the walk began
          break;
        }
        a = b;
        b = next;
      }
      // Split at repeated vertices into simple loops.
      std::vector<int> stack;
      std::map<int, size_t> at;
      for (int v : walk)
      {
        auto it = at.find(v);
        if (it != at.end())
        {
          std::vector<int> loop(stack.begin() + it->second, stack.end());
          for (size_t i = it->second; i < stack.size(); ++i)
            at.erase(stack[i]);
          stack.resize(it->second);
          if (loop.size() >= 3)
            loops.push_back(loop);
        }
        at[v] = stack.size();
        stack.push_back(v);
      }
      if (closed && stack.size() >= 3)
        loops.push_back(stack);
    }
  return loops;
}

/**
 * Minimal-area triangulation of a loop (dynamic programming over its vertex sequence; new
 * diagonals never repeat an existing edge), ear clipping for long loops. Triangles follow
 * the loop's direction, i.e. they are oriented like the faces around the hole. Returns
 * false when no triangulation exists.
 */
bool Unfolder::TriangulateLoop(const Piece& piece,
  const std::vector<int>& loop,
  const std::set<Edge>& existing,
  std::vector<Triangle>& triangles)
{
  const int n = static_cast<int>(loop.size());
  triangles.clear();
  auto allowed = [&](int i, int j)
  {
    if ((j - i + n) % n == 1 || (i - j + n) % n == 1)
      return true; // a loop edge
    return !existing.count(Key(loop[i], loop[j]));
  };
  auto area = [&](int i, int j, int k)
  { return Area(piece, { loop[i], loop[j], loop[k] }); };
  constexpr int maximumDynamic = 160;
  if (n <= maximumDynamic)
  {
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<double> cost(n * n, inf);
    std::vector<int> split(n * n, -1);
    for (int i = 0; i + 1 < n; ++i)
      cost[i * n + i + 1] = 0.0;
    for (int len = 2; len < n; ++len)
      for (int i = 0; i + len < n; ++i)
      {
        const int j = i + len;
        if (!allowed(i, j))
          continue;
        for (int k = i + 1; k < j; ++k)
        {
          const double c = cost[i * n + k] + cost[k * n + j];
          if (c == inf)
            continue;
          const double total = c + area(i, k, j);
          if (total < cost[i * n + j])
          {
            cost[i * n + j] = total;
            split[i * n + j] = k;
          }
        }
      }
    if (cost[n - 1] == inf)
      return false;
    std::vector<std::pair<int, int>> todo{ { 0, n - 1 } };
    while (!todo.empty())
    {
      const auto [i, j] = todo.back();
      todo.pop_back();
      if (j - i < 2)
        continue;
      const int k = split[i * n + j];
      triangles.push_back({ loop[i], loop[k], loop[j] });
      todo.push_back({ i, k });
      todo.push_back({ k, j });
    }
    return true;
  }
  // Ear clipping: the ear with the shortest new diagonal.
  std::vector<int> poly(loop.begin(), loop.end());
  std::set<Edge> used = existing;
  while (poly.size() > 3)
  {
    const int m = static_cast<int>(poly.size());
    int best = -1;
    double bestLength = std::numeric_limits<double>::infinity();
    for (int i = 0; i < m; ++i)
    {
      const int a = poly[i], c = poly[(i + 2) % m];
      if (used.count(Key(a, c)))
        continue;
      const double length = (piece.points[a] - piece.points[c]).norm();
      if (length < bestLength)
      {
        bestLength = length;
        best = i;
      }
    }
    if (best < 0)
      return false;
    const int a = poly[best], b = poly[(best + 1) % m], c = poly[(best + 2) % m];
    triangles.push_back({ a, b, c });
    used.insert(Key(a, c));
    poly.erase(poly.begin() + (best + 1) % m);
  }
  triangles.push_back({ poly[0], poly[1], poly[2] });
  return true;
}

/// Appends a point at x with the data of point `like` (copy, ids); no budget left, no flags.
void Unfolder::AddPoint(Piece& piece, const Vec3& x, int like)
{
  piece.points.push_back(x);
  piece.pointOrig.push_back(piece.pointOrig[like]);
  piece.pointCopy.push_back(piece.pointCopy[like]);
  piece.tear.push_back({});
  piece.onPlane.push_back(0);
  piece.budget.push_back(0.0);
  piece.border.push_back(0);
}

void Unfolder::RemoveLastPoint(Piece& piece)
{
  piece.points.pop_back();
  piece.pointOrig.pop_back();
  piece.pointCopy.pop_back();
  piece.tear.pop_back();
  piece.onPlane.pop_back();
  piece.budget.pop_back();
  piece.border.pop_back();
}

/**
 * Whether the fill of `loop` stays within the error bound: either every new face is close
 * to the loop itself (a narrow crack: its centroid and edge midpoints lie within the
 * tolerance of the loop's edges, which are parts of the surface), or the loop is small and
 * flat: its vertices within half the tolerance of their best-fit plane, no two farther apart
 * than four times the tolerance or 2.5 mean loop edges (a missing face or two, on a coarse
 * mesh, re-tessellated like its neighbours; flat, so not across a crease).
 */
bool Unfolder::FillWithinTolerance(const Piece& piece,
  const std::vector<int>& loop,
  const std::vector<Triangle>& fill) const
{
  const double tolerance = this->Options.holeToleranceScale * this->Tree.rootEpsilon;
  const int n = static_cast<int>(loop.size());
  bool narrow = true;
  for (size_t f = 0; f < fill.size() && narrow; ++f)
  {
    const Triangle& t = fill[f];
    const Vec3 c = (piece.points[t[0]] + piece.points[t[1]] + piece.points[t[2]]) / 3.0;
    const Vec3 probes[4] = { c, 0.5 * (piece.points[t[0]] + piece.points[t[1]]),
      0.5 * (piece.points[t[1]] + piece.points[t[2]]),
      0.5 * (piece.points[t[2]] + piece.points[t[0]]) };
    for (const Vec3& x : probes)
    {
      double d = std::numeric_limits<double>::infinity();
      for (int i = 0; i < n && d > tolerance; ++i)
        d = std::min(
          d, SegmentDistance(x, piece.points[loop[i]], piece.points[loop[(i + 1) % n]]));
      narrow = narrow && d <= tolerance;
    }
  }
  if (narrow)
    return true;
  Vec3 mean = Vec3::Zero();
  for (int v : loop)
    mean += piece.points[v];
  mean /= n;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  double diameter = 0.0;
  for (int i = 0; i < n; ++i)
  {
    const Vec3 d = piece.points[loop[i]] - mean;
    cov += d * d.transpose();
    for (int j = i + 1; j < n; ++j)
      diameter = std::max(diameter, (piece.points[loop[i]] - piece.points[loop[j]]).norm());
  }
  double perimeter = 0.0;
  for (int i = 0; i < n; ++i)
    perimeter += (piece.points[loop[i]] - piece.points[loop[(i + 1) % n]]).norm();
  if (diameter > std::max(4.0 * tolerance, 2.5 * perimeter / n))
    return false;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Vec3 normal = eig.eigenvectors().col(0);
  for (int v : loop)
    if (std::abs((piece.points[v] - mean).dot(normal)) > 0.5 * tolerance)
      return false;
  return true;
}

/**
 * One pass over the boundary loops: the input's border (an edge whose two end points are
 * copies of input border points) and loops with unknown border flags are left alone; the
 * others are triangulated and filled when the fill stays within the tolerance. With
 * `apply` false nothing is added and the loops are only classified into the report.
 * Returns the number of loops filled (or fillable).
 */
int Unfolder::FillLoops(Piece& piece, RepairReport& report, bool apply)
{
  const auto loops = BoundaryLoops(piece);
  std::set<Edge> existing;
  std::map<Edge, int> faceOfHalfEdge; // directed face half-edge -> face
  for (int f = 0; f < piece.NumberOfFaces(); ++f)
  {
    const Triangle& t = piece.triangles[f];
    for (int k = 0; k < 3; ++k)
    {
      existing.insert(Key(t[k], t[(k + 1) % 3]));
      faceOfHalfEdge[{ t[k], t[(k + 1) % 3] }] = f;
    }
  }
  int filled = 0;
  for (const std::vector<int>& loop : loops)
  {
    const int n = static_cast<int>(loop.size());
    double length = 0.0;
    bool border = false, unknown = false;
    for (int i = 0; i < n; ++i)
    {
      const int a = loop[i], b = loop[(i + 1) % n];
      length += (piece.points[a] - piece.points[b]).norm();
      border = border || (piece.border[a] == 1 && piece.border[b] == 1);
      unknown = unknown || piece.border[a] == 2 || piece.border[b] == 2;
    }
    if (border || unknown)
    {
      if (!apply)
      {
        int& count = border ? report.borderLoops : report.unknownLoops;
        ++count;
        (border ? report.borderEdges : report.unknownEdges) += n;
        (border ? report.borderLength : report.unknownLength) += length;
      }
      continue;
    }
    std::vector<Triangle> fill;
    const bool shortEnough = n <= this->Options.maximumHoleEdges;
    bool triangulated = shortEnough && TriangulateLoop(piece, loop, existing, fill);
    // No triangulation of the loop's own vertices (every diagonal would repeat an edge of
    // the mesh, e.g. a pocket between stitched copies): a fan around a new vertex at the
    // loop's centroid, with the point data of the nearest loop vertex.
    bool fan = false;
    if (shortEnough && !triangulated)
    {
      Vec3 c = Vec3::Zero();
      for (int v : loop)
        c += piece.points[v];
      c /= n;
      int nearest = loop[0];
      for (int v : loop)
        if ((piece.points[v] - c).norm() < (piece.points[nearest] - c).norm())
          nearest = v;
      AddPoint(piece, c, nearest);
      const int centre = piece.NumberOfPoints() - 1;
      for (int i = 0; i < n; ++i)
        fill.push_back({ loop[i], loop[(i + 1) % n], centre });
      triangulated = fan = true;
    }
    bool ok = triangulated && this->FillWithinTolerance(piece, loop, fill);
    if (fan && (!ok || !apply))
      RemoveLastPoint(piece);
    if (!ok || !apply)
    {
      if (!apply && std::getenv("FOLDINGMESHES_REPAIR_DEBUG"))
        std::fprintf(stderr, "  open loop: %d edges, length %.4g, %s\n", n, length,
          !shortEnough ? "too long" : fan ? "fan beyond tolerance" : "beyond tolerance");
      if (!apply)
      {
        ++report.openLoops;
        report.openEdges += n;
        report.openLength += length;
      }
      filled += ok;
      continue;
    }
    // Attributes of the face across the loop's first edge (hole a -> b: face b -> a).
    auto from = faceOfHalfEdge.find({ loop[1], loop[0] });
    const int source = from != faceOfHalfEdge.end() ? from->second : 0;
    for (const Triangle& t : fill)
    {
      piece.triangles.push_back(t);
      piece.faceOrig.push_back(piece.faceOrig[source]);
      piece.faceCopy.push_back(piece.faceCopy[source]);
      piece.faceFilled.push_back(1);
      for (int k = 0; k < 3; ++k)
        existing.insert(Key(t[k], t[(k + 1) % 3]));
    }
    report.filledFaces += static_cast<int>(fill.size());
    report.addedPoints += fan;
    ++report.filledLoops;
    ++filled;
  }
  return filled;
}

/// Diagnostics (FOLDINGMESHES_REPAIR_DEBUG set): where the bad edges are.
void PrintEdgeClasses(const Piece& piece, const char* when)
{
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
    {
      ++nonManifold[cls];
      if (std::getenv("FOLDINGMESHES_REPAIR_DEBUG2"))
        for (int f : e.second)
          std::fprintf(stderr, "   nm %d-%d face %d: %d %d %d filled %d\n", a, b, f,
            piece.triangles[f][0], piece.triangles[f][1], piece.triangles[f][2],
            piece.faceFilled[f]);
    }
    if (e.second.size() == 2 &&
      Direction(piece.triangles[e.second[0]], a, b) == Direction(piece.triangles[e.second[1]], a, b))
      ++misoriented[cls];
  }
  std::fprintf(stderr,
    "repair %s: open border %d foldline %d in-copy %d across-stitch %d | non-manifold filled %d "
    "one-copy %d copies %d | misoriented filled %d one-copy %d copies %d\n",
    when, open[0], open[1], open[2], open[3], nonManifold[0], nonManifold[1], nonManifold[2],
    misoriented[0], misoriented[1], misoriented[2]);
}

/// The final repair (UnfoldOptions::closeHoles), see RepairReport.
void Unfolder::Repair(Piece& piece, RepairReport& report)
{
  const bool debug = std::getenv("FOLDINGMESHES_REPAIR_DEBUG") != nullptr;
  if (debug)
    PrintEdgeClasses(piece, "before");
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
  report.flippedFaces = this->OrientComponents(piece, report.droppedFaces);
  for (int pass = 0; pass < 3; ++pass)
  {
    if (this->FillLoops(piece, report, true) == 0)
      break;
    // Fills of loops that share a pinch vertex may meet at an edge: clean up.
    report.droppedFaces += this->DropNonManifoldFaces(piece);
    report.flippedFaces += this->OrientComponents(piece, report.droppedFaces);
  }
  this->FillLoops(piece, report, false);
  if (debug)
  {
    PrintEdgeClasses(piece, "after");
    std::fprintf(stderr,
      "repair: dropped %d flipped %d filled %d loops %d faces; border %d loops %d edges; open "
      "%d loops %d edges %.4g length; unknown %d loops\n",
      report.droppedFaces, report.flippedFaces, report.filledLoops, report.filledFaces,
      report.borderLoops, report.borderEdges, report.openLoops, report.openEdges,
      report.openLength, report.unknownLoops);
  }
}
} // namespace unfolder_detail
} // namespace foldingmeshes
