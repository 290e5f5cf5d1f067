// The hole filling of the final repair (UnfoldOptions::closeHoles): the classification of
// the boundary loops (the input's own border or a gap; the loops themselves are traced in
// FoldingTreeUnfolderBoundaryLoops.cxx), minimal-area triangulation, the error bound check.
#include "FoldingTreeUnfolderRepairInternal.h"
#include "LoopFillDeviation.h"
#include "Trace.h"

#include <Eigen/Dense>

#include <algorithm>
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
/// A small loop (FillWithinTolerance) is no wider than this many tolerances ...
constexpr double SmallLoopDiameter = 4.0;
/// ... or this many of its mean edge lengths (a missing face or two on a coarse mesh).
constexpr double SmallLoopMeanEdges = 2.5;
}

using namespace repair;

/**
 * Minimal-area triangulation of a loop (dynamic programming over its vertex sequence; new
 * diagonals never repeat an existing edge), ear clipping for long loops. Triangles follow
 * the loop's direction, i.e. they are oriented like the faces around the hole. Returns
 * false when no triangulation exists.
 */
bool Unfolder::TriangulateLoop(const Piece& piece,
  const std::vector<int>& loop,
  const EdgeSet& existing,
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
  auto area = [&](int i, int j, int k) { return Area(piece, { loop[i], loop[j], loop[k] }); };
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
  EdgeSet added; // the new diagonals
  const bool clipped = ClipShortestEars(
    piece.points,
    poly,
    [&](int a, int c) { return !existing.count(Key(a, c)) && !added.count(Key(a, c)); },
    [&](int a, int b, int c)
    {
      triangles.push_back({ a, b, c });
      added.insert(Key(a, c));
    });
  if (!clipped)
    return false;
  triangles.push_back({ poly[0], poly[1], poly[2] });
  return true;
}

/// Both end points are copies of input border points and, when the tree lists the input's
/// border edges (FoldingTree::inputBorderEdges), their input ids form one.
bool Unfolder::IsInputBorderEdge(const Piece& piece, int a, int b) const
{
  if (piece.border[a] != 1 || piece.border[b] != 1)
    return false;
  const auto& edges = this->Tree.inputBorderEdges;
  if (edges.empty())
    return true;
  const int x = piece.pointOrig[a], y = piece.pointOrig[b];
  return std::binary_search(
    edges.begin(), edges.end(), std::make_pair(std::min(x, y), std::max(x, y)));
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
  piece.projected.push_back(0);
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
  piece.projected.pop_back();
}

/**
 * Whether the fill of `loop` stays within the error bound: either every new face is close
 * to the loop itself (a narrow crack: every point of it within the tolerance of the loop's
 * edges, which are parts of the surface; proved, ProvedLoopDeviation), or the loop is small and
 * flat: its vertices within half the tolerance of their best-fit plane, no two farther apart
 * than four times the tolerance or 2.5 mean loop edges (a missing face or two, on a coarse
 * mesh, re-tessellated like its neighbours; flat, so not across a crease).
 */
bool FillWithinTolerance(const std::vector<Vec3>& points,
  const std::vector<int>& loop,
  const std::vector<Triangle>& fill,
  double tolerance)
{
  const int n = static_cast<int>(loop.size());
  // Every point of the fill, not only sample points (a long sliver reaches far between them).
  const bool narrow = ProvedLoopDeviation(points, fill, loop, tolerance) <= tolerance;
  if (narrow)
    return true;
  Vec3 mean = Vec3::Zero();
  for (int v : loop)
    mean += points[v];
  mean /= n;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  double diameter = 0.0;
  for (int i = 0; i < n; ++i)
  {
    const Vec3 d = points[loop[i]] - mean;
    cov += d * d.transpose();
    for (int j = i + 1; j < n; ++j)
      diameter = std::max(diameter, (points[loop[i]] - points[loop[j]]).norm());
  }
  double perimeter = 0.0;
  for (int i = 0; i < n; ++i)
    perimeter += (points[loop[i]] - points[loop[(i + 1) % n]]).norm();
  if (diameter > std::max(SmallLoopDiameter * tolerance, SmallLoopMeanEdges * perimeter / n))
    return false;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Vec3 normal = eig.eigenvectors().col(0);
  for (int v : loop)
    if (std::abs((points[v] - mean).dot(normal)) > 0.5 * tolerance)
      return false;
  return true;
}

bool Unfolder::FillWithinTolerance(const Piece& piece,
  const std::vector<int>& loop,
  const std::vector<Triangle>& fill) const
{
  return unfolder_detail::FillWithinTolerance(
    piece.points, loop, fill, this->Options.holeToleranceScale * this->Tree.rootEpsilon);
}

/// One pass of FillLoops: the mesh's edges as the fills grow, and what it reports.
struct LoopFill
{
  RepairReport& report;
  const bool apply; ///< false: nothing is added, the loops are only classified
  EdgeSet existing;
  FlatEdgeMap<int> faceOfHalfEdge; ///< directed face half-edge -> face (the last face of two)
  EdgeSet openEdges;               ///< with input non-manifold edges: the open edges (reported)

  /// Every edge lookup of the pass is between two vertices of `loops` (diagonals, chords, the
  /// face across a loop's first edge), or of a fill added since (Append): the faces with two
  /// loop vertices among their corners are the only ones such an edge belongs to, so only
  /// they are hashed - the same answers as with every face, for a fraction of the hashing.
  LoopFill(const Piece& piece,
    const std::vector<std::vector<int>>& loops,
    RepairReport& r,
    bool a,
    bool nonManifoldInput)
    : report(r)
    , apply(a)
  {
    std::vector<char> onLoop(piece.points.size(), 0);
    for (const std::vector<int>& loop : loops)
      for (int v : loop)
        onLoop[v] = 1;
    std::vector<int> faces;
    for (int f = 0; f < piece.NumberOfFaces(); ++f)
    {
      const Triangle& t = piece.triangles[f];
      if (onLoop[t[0]] + onLoop[t[1]] + onLoop[t[2]] >= 2)
        faces.push_back(f);
    }
    this->existing.reserve(3 * faces.size());
    this->faceOfHalfEdge.reserve(3 * faces.size());
    for (int f : faces) // increasing ids: the last face of two, as over every face
    {
      const Triangle& t = piece.triangles[f];
      for (int k = 0; k < 3; ++k)
      {
        this->existing.insert(Key(t[k], t[(k + 1) % 3]));
        this->faceOfHalfEdge[{ t[k], t[(k + 1) % 3] }] = f;
      }
    }
    // Loops closed by non-manifold edges (BoundaryLoops) report only their open edges.
    if (nonManifoldInput)
      for (const auto& e : EdgeFaces(piece))
        if (e.second.size() == 1)
          this->openEdges.insert(e.first);
  }

  /// Appends the fill of a loop whose first edge is a -> b, with the attributes (ids, copy)
  /// of the face across that edge (hole a -> b: face b -> a).
  void Append(Piece& piece, const std::vector<Triangle>& fill, int a, int b)
  {
    const int* from = this->faceOfHalfEdge.find({ b, a });
    const int source = from ? *from : 0;
    for (const Triangle& t : fill)
    {
      piece.triangles.push_back(t);
      piece.faceOrig.push_back(piece.faceOrig[source]);
      piece.faceCopy.push_back(piece.faceCopy[source]);
      piece.faceFilled.push_back(1);
      for (int k = 0; k < 3; ++k)
        this->existing.insert(Key(t[k], t[(k + 1) % 3]));
    }
    this->report.filledFaces += static_cast<int>(fill.size());
    ++this->report.filledLoops;
  }

  /// Counts an unfilled loop as open.
  void CountOpen(const LoopShape& shape);
};

/// A boundary loop's edges: their length, those reported, and whether the loop runs along
/// the input's border or points of unknown border flags.
struct LoopShape
{
  int edges = 0;
  double length = 0.0, reportedLength = 0.0;
  int reported = 0;
  bool border = false, unknown = false;
};

void LoopFill::CountOpen(const LoopShape& shape)
{
  ++this->report.openLoops;
  this->report.openEdges += shape.reported;
  this->report.openLength += shape.reportedLength;
}

LoopShape Unfolder::MeasureLoop(const Piece& piece,
  const std::vector<int>& loop,
  const LoopFill& pass) const
{
  LoopShape shape;
  const int n = static_cast<int>(loop.size());
  shape.edges = n;
  for (int i = 0; i < n; ++i)
  {
    const int a = loop[i], b = loop[(i + 1) % n];
    const double l = (piece.points[a] - piece.points[b]).norm();
    shape.length += l;
    if (this->Tree.inputNonManifoldEdges.empty() ||
      (pass.openEdges.count(Key(a, b)) && (n > 2 || i == 0)))
    {
      ++shape.reported;
      shape.reportedLength += l;
    }
    shape.border = shape.border || this->IsInputBorderEdge(piece, a, b);
    shape.unknown = shape.unknown || piece.border[a] == 2 || piece.border[b] == 2;
  }
  return shape;
}

/**
 * A gap that opens into the input's border: closes each run of non-border edges between two
 * border vertices p, q by the chord q -> p (a new border edge), when the chord is short
 * (within twice the tolerance) and the fill within the tolerance. Returns the runs closed.
 */
int Unfolder::CloseBorderGaps(Piece& piece, const std::vector<int>& loop, LoopFill& pass) const
{
  const int n = static_cast<int>(loop.size());
  const double tolerance = this->Options.holeToleranceScale * this->Tree.rootEpsilon;
  auto isBorderEdge = [&](int i)
  { return this->IsInputBorderEdge(piece, loop[i], loop[(i + 1) % n]); };
  int filled = 0;
  int first = 0;
  while (first < n && !isBorderEdge(first))
    ++first;
  for (int k = 0; k < n;)
  {
    const int i = (first + k) % n;
    if (isBorderEdge(i))
    {
      ++k;
      continue;
    }
    // Run of non-border edges from loop[i] (a border vertex) to the next border vertex.
    std::vector<int> run{ loop[i] };
    int m = 0;
    while (k + m < n && !isBorderEdge((first + k + m) % n))
    {
      run.push_back(loop[(first + k + m + 1) % n]);
      ++m;
    }
    k += m;
    const int p = run.front(), q = run.back();
    std::vector<Triangle> fill;
    if (run.size() < 3 || p == q || piece.border[p] != 1 || piece.border[q] != 1 ||
      pass.existing.count(Key(p, q)) ||
      (piece.points[p] - piece.points[q]).norm() > 2.0 * tolerance ||
      !TriangulateLoop(piece, run, pass.existing, fill) ||
      !this->FillWithinTolerance(piece, run, fill))
      continue;
    pass.Append(piece, fill, run[0], run[1]);
    ++filled;
  }
  return filled;
}

/// A loop along the input's border or points of unknown border flags: left alone, counted
/// (and traced) when classifying.
void Unfolder::CountBorderLoop(const Piece& piece,
  const std::vector<int>& loop,
  const LoopShape& shape,
  LoopFill& pass) const
{
  if (pass.apply)
    return;
  const int n = shape.edges;
  if (this->Options.trace)
  {
    int be = 0, bv = 0;
    for (int i = 0; i < n; ++i)
    {
      be += this->IsInputBorderEdge(piece, loop[i], loop[(i + 1) % n]);
      bv += piece.border[loop[i]] == 1;
    }
    this->Options.trace(
      FormatTrace("  border loop: %d edges (%d border edges, %d border vertices), length %.4g",
        n,
        be,
        bv,
        shape.length));
  }
  RepairReport& report = pass.report;
  int& count = shape.border ? report.borderLoops : report.unknownLoops;
  ++count;
  (shape.border ? report.borderEdges : report.unknownEdges) += shape.reported;
  (shape.border ? report.borderLength : report.unknownLength) += shape.reportedLength;
}

/**
 * An open loop: triangulated (or, when no triangulation of its own vertices exists, a fan
 * around a new point) and filled when the fill stays within the tolerance. Returns 1 when it
 * was filled (or, classifying, could be).
 */
int Unfolder::FillOpenLoop(Piece& piece,
  const std::vector<int>& loop,
  const LoopShape& shape,
  LoopFill& pass) const
{
  const int n = shape.edges;
  std::vector<Triangle> fill;
  const bool shortEnough = n <= this->Options.maximumHoleEdges;
  bool triangulated = shortEnough && TriangulateLoop(piece, loop, pass.existing, fill);
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
  const bool ok = triangulated && this->FillWithinTolerance(piece, loop, fill);
  if (fan && (!ok || !pass.apply))
    RemoveLastPoint(piece);
  if (!ok || !pass.apply)
  {
    if (!pass.apply && this->Options.trace)
      this->Options.trace(FormatTrace("  open loop: %d edges, length %.4g, %s",
        n,
        shape.length,
        !shortEnough ? "too long"
          : fan      ? "fan beyond tolerance"
                     : "beyond tolerance"));
    if (!pass.apply)
      pass.CountOpen(shape);
    return ok ? 1 : 0;
  }
  pass.Append(piece, fill, loop[0], loop[1]);
  pass.report.addedPoints += fan;
  return 1;
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
  size_t reportOnly = 0;
  const bool nonManifoldInput = !this->Tree.inputNonManifoldEdges.empty();
  const auto loops = BoundaryLoops(piece, nonManifoldInput, reportOnly);
  if (loops.empty())
    return 0; // no loop (e.g. a closed piece): no edge sets to build (a hash of every edge)
  LoopFill pass(piece, loops, report, apply, nonManifoldInput);
  int filled = 0;
  for (size_t index = 0; index < loops.size(); ++index)
  {
    const std::vector<int>& loop = loops[index];
    const LoopShape shape = this->MeasureLoop(piece, loop, pass);
    if (shape.border && !shape.unknown && apply && shape.edges <= this->Options.maximumHoleEdges &&
      index < reportOnly)
      filled += this->CloseBorderGaps(piece, loop, pass);
    else if (shape.border || shape.unknown)
      this->CountBorderLoop(piece, loop, shape, pass);
    else if (index >= reportOnly) // open edges BoundaryLoops could not close: reported only
    {
      if (!apply)
        pass.CountOpen(shape);
    }
    else
      filled += this->FillOpenLoop(piece, loop, shape, pass);
  }
  return filled;
}
} // namespace unfolder_detail
} // namespace foldingmeshes
