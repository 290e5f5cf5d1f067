// The geometry of a rotation node's sector (FoldingTreeRotationSector.h): the cut, its seams
// made to meet, faces cut along the half-planes, and the errors of the turned copies. The rule
// that uses them is in FoldingTreeRotation.cxx.
#include "FoldingTreeRotationSector.h"

#include "PointKdTree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace foldingmeshes
{
namespace treebuilder
{
namespace sector
{
namespace
{
/// Seam vertices this many times offAxis (1e-9 of the diagonal) from the axis are moved onto
/// it; farther ones are seam vertices like any other (the stitcher joins the copies' poles).
constexpr double OnAxisOfOffAxis = 1000.0;
/// k sectors may hold at most this many times the region's faces (faces cut along the
/// half-planes add pieces).
constexpr double MaximumFaceGrowth = 3.0;
/// k sectors' area may differ from the region's by this share of one sector.
constexpr double SectorAreaTolerance = 0.25;
/// Bins per sector of the histogram that finds phi0.
constexpr int AngleBins = 2048;

/// a in (-pi, pi].
double Wrapped(double a)
{
  const double r = Modulo(a + EIGEN_PI, TwoPi);
  return r - EIGEN_PI;
}

/// The angle modulo the sector width that most vertices (off the axis) share: the mean of
/// the angles in the fullest bin (the lowest bin on ties).
double SectorStart(const AxisFrame& frame, const WorkMesh& w, double width, double offAxis)
{
  std::vector<int> count(AngleBins, 0);
  std::vector<double> sum(AngleBins, 0.0);
  for (const Vec3& p : w.points)
  {
    if (frame.Radius(p) <= offAxis)
      continue;
    const double a = Modulo(frame.Angle(p), width);
    const int bin = std::min(AngleBins - 1, static_cast<int>(a / width * AngleBins));
    ++count[bin];
    sum[bin] += a;
  }
  const int best = static_cast<int>(std::max_element(count.begin(), count.end()) - count.begin());
  return count[best] > 0 ? sum[best] / count[best] : 0.0;
}

/// Edges of the region its faces use once within the sector but other faces use too.
std::vector<char> SeamVertices(const EdgeTable& edges, const std::vector<char>& keep, int np)
{
  std::vector<char> seam(np, 0);
  for (const auto& e : edges)
  {
    int kept = 0;
    for (int f : e.second)
      kept += keep[f];
    if (kept == 1 && e.second.size() >= 2)
      seam[e.first.first] = seam[e.first.second] = 1;
  }
  return seam;
}

/**
 * w with every face that crosses the half-plane at angle `angle` about the axis cut along it:
 * a new point where an edge crosses (shared by the faces of that edge), the face cut into two
 * or three triangles of the same orientation and input face. A new point takes the input id,
 * flags and budget of the edge's nearer end (its tear and plane flags: those both ends have;
 * the smaller budget). Crossings within `tiny` of an end use the end.
 */
WorkMesh SplitAtHalfPlane(const AxisFrame& frame, const WorkMesh& w, double angle, double tiny)
{
  const Vec3 normal = -std::sin(angle) * frame.U + std::cos(angle) * frame.V;
  const Vec3 along = std::cos(angle) * frame.U + std::sin(angle) * frame.V;
  const Vec3& o = frame.Axis.origin;
  std::vector<double> s(w.points.size());
  for (int v = 0; v < w.NumberOfPoints(); ++v)
  {
    s[v] = normal.dot(w.points[v] - o);
    if (std::abs(s[v]) <= tiny)
      s[v] = 0.0;
  }
  WorkMesh out = w;
  out.triangles.clear();
  out.faceOrig.clear();
  std::map<std::pair<int, int>, int> crossing;
  auto cut = [&](int a, int b) -> int
  {
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    auto it = crossing.find(key);
    if (it != crossing.end())
      return it->second;
    const double t = s[a] / (s[a] - s[b]);
    const int nearer = t < 0.5 ? a : b;
    out.AppendPoint(w, nearer);
    const int id = out.NumberOfPoints() - 1;
    out.points[id] = w.points[a] + t * (w.points[b] - w.points[a]);
    out.tear[id] = w.tear[a] & w.tear[b];
    out.onPlane[id] = w.onPlane[a] & w.onPlane[b];
    out.projected[id] = 0;
    out.mirrorFlags[id].clear();
    out.budget[id] = std::min(w.budget[a], w.budget[b]);
    crossing.emplace(key, id);
    return id;
  };
  for (int f = 0; f < w.NumberOfFaces(); ++f)
  {
    const Triangle& t = w.triangles[f];
    auto keep = [&](const Triangle& piece)
    {
      out.triangles.push_back(piece);
      out.faceOrig.push_back(w.faceOrig[f]);
    };
    // The rotation of t whose first vertex is alone on its side (or on the plane).
    int lone = -1;
    for (int i = 0; i < 3 && lone < 0; ++i)
    {
      const double a = s[t[i]], b = s[t[(i + 1) % 3]], c = s[t[(i + 2) % 3]];
      if ((a > 0 && b < 0 && c < 0) || (a < 0 && b > 0 && c > 0) ||
        (a == 0 && ((b > 0 && c < 0) || (b < 0 && c > 0))))
        lone = i;
    }
    if (lone < 0)
    {
      keep(t);
      continue;
    }
    const int a = t[lone], b = t[(lone + 1) % 3], c = t[(lone + 2) % 3];
    // Only where the edges cross the half-plane, not the opposite one (decided per edge, so
    // the two faces of an edge agree).
    auto onHalfPlane = [&](int p, int q)
    {
      const double u = s[p] / (s[p] - s[q]);
      return along.dot(w.points[p] + u * (w.points[q] - w.points[p]) - o) > 0.0;
    };
    if (s[a] == 0.0 ? !onHalfPlane(b, c) : (!onHalfPlane(a, b) || !onHalfPlane(c, a)))
    {
      keep(t);
      continue;
    }
    if (s[a] == 0.0) // through vertex a: two triangles
    {
      const int bc = cut(b, c);
      keep({ a, b, bc });
      keep({ a, bc, c });
      continue;
    }
    const int ab = cut(a, b), ca = cut(c, a);
    keep({ a, ab, ca });
    keep({ ab, b, c });
    keep({ ab, c, ca });
  }
  return out;
}

}

/**
 * w with the faces the axis pierces cut at the point where it does, the pieces of the same
 * orientation and input face: a face whose inside the axis passes through (farther than `tiny`
 * from each edge) into three triangles about that point, the two faces of an edge it passes
 * through (an even polygon's diagonal) into two each, sharing the point. Not where a corner
 * of the face lies within OnAxisOfOffAxis * tiny of the axis (1e-6 of the diagonal from the
 * builder): that corner is the face's own pole, which CutSector moves onto the axis; nor a
 * face the axis would enter through two of its edges (one along the axis, or a needle
 * thinner than tiny): its edges keep their faces whole rather than split one face twice and
 * its neighbours once (a crack). The new point takes the input id of the nearest corner, the tear
 * and plane flags every corner has, the smallest budget. SplitAtHalfPlane then cuts the pieces
 * through that point, so the sector keeps its share of the face and nothing more (without it, a
 * face across the axis is cut along one half-plane only and kept or dropped whole by its centroid:
 * the copies overlap or leave a hole).
 */
WorkMesh SplitAtAxis(const AxisFrame& frame, const WorkMesh& w, double tiny)
{
  const double poleRadius = OnAxisOfOffAxis * tiny; // CutSector's poles
  const Vec3& o = frame.Axis.origin;
  // The points across the axis (the axis at 0).
  std::vector<Eigen::Vector2d> q(w.points.size());
  for (int v = 0; v < w.NumberOfPoints(); ++v)
  {
    const Vec3 r = w.points[v] - o;
    q[v] = Eigen::Vector2d(r.dot(frame.U), r.dot(frame.V));
  }
  auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b)
  { return a.x() * b.y() - a.y() * b.x(); };
  WorkMesh out = w;
  out.triangles.clear();
  out.faceOrig.clear();
  // A new point on the axis, from the corners `corners` of a face.
  auto addPole = [&](const Vec3& at, std::initializer_list<int> corners) -> int
  {
    int nearest = *corners.begin();
    uint64_t tear = ~uint64_t(0), onPlane = ~uint64_t(0);
    double budget = std::numeric_limits<double>::infinity();
    for (int v : corners)
    {
      if ((w.points[v] - at).squaredNorm() < (w.points[nearest] - at).squaredNorm())
        nearest = v;
      tear &= w.tear[v];
      onPlane &= w.onPlane[v];
      budget = std::min(budget, w.budget[v]);
    }
    out.AppendPoint(w, nearest);
    const int id = out.NumberOfPoints() - 1;
    out.points[id] = frame.OntoAxis(at);
    out.tear[id] = tear;
    out.onPlane[id] = onPlane;
    out.projected[id] = 0;
    out.mirrorFlags[id].clear();
    out.budget[id] = budget;
    return id;
  };
  // The faces the axis passes through inside (their pierce point) and the edges it passes
  // through (where along the edge, from its lower id).
  std::vector<Vec3> facePierce(w.NumberOfFaces());
  std::vector<char> pierced(w.NumberOfFaces(), 0);
  std::map<std::pair<int, int>, double> edgeAt;
  auto edgeKey = [](int a, int b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
  for (int f = 0; f < w.NumberOfFaces(); ++f)
  {
    const Triangle& t = w.triangles[f];
    if (q[t[0]].norm() <= poleRadius || q[t[1]].norm() <= poleRadius ||
      q[t[2]].norm() <= poleRadius)
      continue;
    const double whole = cross(q[t[1]] - q[t[0]], q[t[2]] - q[t[0]]);
    if (whole == 0.0)
      continue; // its plane holds the axis direction: no point of the axis inside it
    int inside = 0, onEdge = -1;
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::Vector2d &a = q[t[k]], &b = q[t[(k + 1) % 3]];
      // Twice the area of (a, b, 0), signed like the face: its distance from the edge times
      // the edge's length.
      const double part = cross(a, b) * (whole > 0.0 ? 1.0 : -1.0);
      if (part > tiny * (b - a).norm())
        ++inside;
      else if (part >= -tiny * (b - a).norm())
        onEdge = onEdge < 0 ? k : 3; // 3: more than one edge
    }
    if (inside == 3)
    {
      const Vec3 &a = w.points[t[0]], &b = w.points[t[1]], &c = w.points[t[2]];
      const Vec3 n = (b - a).cross(c - a);
      const Vec3& d = frame.Axis.direction;
      facePierce[f] = o + (n.dot(a - o) / n.dot(d)) * d;
      pierced[f] = 1;
    }
    else if (inside == 2 && onEdge >= 0 && onEdge < 3)
    {
      const int a = t[onEdge], b = t[(onEdge + 1) % 3];
      const Eigen::Vector2d ab = q[b] - q[a];
      const double u = std::min(1.0, std::max(0.0, -q[a].dot(ab) / ab.squaredNorm()));
      edgeAt.emplace(edgeKey(a, b), a < b ? u : 1.0 - u);
    }
  }
  // A face with two such edges keeps all its edges whole (and so do their other faces).
  std::vector<std::pair<int, int>> crowded;
  for (const Triangle& t : w.triangles)
  {
    int edges = 0;
    for (int k = 0; k < 3; ++k)
      edges += static_cast<int>(edgeAt.count(edgeKey(t[k], t[(k + 1) % 3])));
    for (int k = 0; k < 3 && edges > 1; ++k)
      crowded.push_back(edgeKey(t[k], t[(k + 1) % 3]));
  }
  for (const auto& e : crowded)
    edgeAt.erase(e);
  // The new points: the faces' in face order, then the edges' in edge order.
  std::vector<int> facePole(w.NumberOfFaces(), -1);
  for (int f = 0; f < w.NumberOfFaces(); ++f)
    if (pierced[f])
    {
      const Triangle& t = w.triangles[f];
      facePole[f] = addPole(facePierce[f], { t[0], t[1], t[2] });
    }
  std::map<std::pair<int, int>, int> edgePole;
  for (const auto& e : edgeAt)
  {
    const int a = e.first.first, b = e.first.second;
    edgePole.emplace(
      e.first, addPole(w.points[a] + e.second * (w.points[b] - w.points[a]), { a, b }));
  }
  for (int f = 0; f < w.NumberOfFaces(); ++f)
  {
    const Triangle& t = w.triangles[f];
    auto keep = [&](const Triangle& piece)
    {
      out.triangles.push_back(piece);
      out.faceOrig.push_back(w.faceOrig[f]);
    };
    if (facePole[f] >= 0)
    {
      for (int k = 0; k < 3; ++k)
        keep({ t[k], t[(k + 1) % 3], facePole[f] });
      continue;
    }
    int split = -1, pole = -1;
    for (int k = 0; k < 3 && split < 0; ++k)
    {
      const auto found = edgePole.find(edgeKey(t[k], t[(k + 1) % 3]));
      if (found != edgePole.end())
      {
        split = k;
        pole = found->second;
      }
    }
    if (split < 0)
    {
      keep(t);
      continue;
    }
    const int a = t[split], b = t[(split + 1) % 3], c = t[(split + 2) % 3];
    keep({ a, pole, c });
    keep({ pole, b, c });
  }
  return out;
}

/// a in [0, m).
double Modulo(double a, double m)
{
  const double r = std::fmod(a, m);
  return r < 0.0 ? r + m : r;
}

const char* const NotCoveredOnce = "k sectors do not cover the area once";
const char* const NoSector = "no face or every face in the sector";
const char* const TooManyPieces = "k sectors would hold more than three times the region's faces";

/// SplitAtHalfPlane at both half-planes of the sector [start, start + width), after
/// SplitAtAxis (a face the axis pierces would otherwise be cut along one half-plane only).
WorkMesh SplitAtHalfPlanes(const AxisFrame& frame,
  const WorkMesh& w,
  double start,
  double width,
  double tiny)
{
  const WorkMesh poles = SplitAtAxis(frame, w, tiny);
  return SplitAtHalfPlane(frame, SplitAtHalfPlane(frame, poles, start, tiny), start + width, tiny);
}

/// Why order k has no sector here (nullptr: it has, in `cut`).
const char* CutSector(const AxisFrame& frame,
  const WorkMesh& w,
  const EdgeTable& edges,
  int k,
  double snap,
  double offAxis,
  SectorCut& cut,
  double start,
  int regionFaces)
{
  const double width = TwoPi / k;
  cut = SectorCut();
  cut.order = k;
  cut.start = std::isnan(start) ? SectorStart(frame, w, width, offAxis) : start;
  const int nf = w.NumberOfFaces(), np = w.NumberOfPoints();
  cut.keep.assign(nf, 0);
  int kept = 0;
  for (int f = 0; f < nf; ++f)
  {
    const Triangle& t = w.triangles[f];
    const Vec3 c = (w.points[t[0]] + w.points[t[1]] + w.points[t[2]]) / 3.0;
    kept += cut.keep[f] = Modulo(frame.Angle(c) - cut.start, TwoPi) < width;
  }
  if (kept == 0 || kept == nf)
    return NoSector;
  // Faces cut along the half-planes multiply: k sectors may hold at most three times as many
  // faces as the region had (the bearing's sector: 4.4 times its input's faces in its k copies,
  // which the unfolder thins back to 1.0 times; twice until 2026-12-06 kept the queen's order
  // 15 out, 549 stored faces against 812).
  if (k * static_cast<double>(kept) > MaximumFaceGrowth * (regionFaces < 0 ? nf : regionFaces))
    return TooManyPieces;
  // k sectors cover the region once: their area within a quarter sector of the region's (a
  // sector wider than 360/k, whose copies overlap, or narrower, fails; the seams' pairing
  // tolerance alone would let a 16-gon pass as 17 sectors).
  double regionArea = 0.0, sectorArea = 0.0;
  for (int f = 0; f < nf; ++f)
  {
    const double a = TriangleArea(w, w.triangles[f]);
    regionArea += a;
    sectorArea += cut.keep[f] ? a : 0.0;
  }
  if (std::abs(k * sectorArea - regionArea) > SectorAreaTolerance * regionArea / k)
    return NotCoveredOnce;
  cut.seam = SeamVertices(edges, cut.keep, np);
  cut.points = w.points;
  cut.move.assign(np, 0.0);
  const AxisTurn forward(frame.Axis, width), back(frame.Axis, -width);
  // Sides: 0 near phi0, 1 near phi0 + width; axis vertices go onto the axis.
  std::vector<int> side0, side1;
  std::vector<double> offset(np, 0.0);
  bool planar = true;
  for (int v = 0; v < np; ++v)
  {
    if (!cut.seam[v])
      continue;
    const double radius = frame.Radius(w.points[v]);
    if (radius <= OnAxisOfOffAxis * offAxis) // on the axis (a pole): every turn keeps it
    {
      cut.points[v] = frame.OntoAxis(w.points[v]);
      cut.move[v] = radius;
      continue;
    }
    const double angle = frame.Angle(w.points[v]);
    const double a0 = Wrapped(angle - cut.start), a1 = Wrapped(angle - cut.start - width);
    const bool first = std::abs(a0) <= std::abs(a1);
    offset[v] = first ? a0 : a1;
    cut.halfPlaneMove =
      std::max(cut.halfPlaneMove, 2.0 * radius * std::abs(std::sin(0.5 * offset[v])));
    planar = cut.halfPlaneMove <= snap;
    (first ? side0 : side1).push_back(v);
  }
  const PointKdTree tree0(w.points, side0), tree1(w.points, side1);
  // Mutual nearest pairs: a (side 0) turned forward meets b (side 1) and b turned back a.
  std::vector<std::pair<int, int>> pairs;
  bool paired = side0.size() == side1.size();
  for (size_t i = 0; paired && i < side0.size(); ++i)
  {
    const int a = side0[i];
    const int b = tree1.NearestWithin(forward.Point(w.points[a]), snap);
    paired = b >= 0 && tree0.NearestWithin(back.Point(w.points[b]), snap) == a;
    pairs.push_back({ a, b });
  }
  if (!paired) // each seam onto its half-plane; the unfolder's zipper joins them
    for (const std::vector<int>* side : { &side0, &side1 })
      for (int v : *side)
      {
        cut.points[v] = AxisTurn(frame.Axis, -offset[v]).Point(w.points[v]);
        cut.move[v] = (cut.points[v] - w.points[v]).norm();
      }
  for (size_t i = 0; paired && i < pairs.size(); ++i)
  {
    const auto& pr = pairs[i];
    Vec3 pa = w.points[pr.first], pb = back.Point(w.points[pr.second]);
    if (planar) // both onto the half-plane at phi0 (turned about the axis, radius kept)
    {
      pa = AxisTurn(frame.Axis, -offset[pr.first]).Point(pa);
      pb = AxisTurn(frame.Axis, -offset[pr.second]).Point(pb);
    }
    const Vec3 t = 0.5 * (pa + pb);
    cut.points[pr.first] = t;
    cut.points[pr.second] = forward.Point(t);
    cut.move[pr.first] = (t - w.points[pr.first]).norm();
    cut.move[pr.second] = (cut.points[pr.second] - w.points[pr.second]).norm();
  }
  // Turning a seam vertex onto its half-plane keeps it on a surface of revolution however
  // far it moves (ChargeTurns measures where it lands); it must not flip a face.
  for (int f = 0; f < nf; ++f)
  {
    const Triangle& t = w.triangles[f];
    if (!cut.keep[f] ||
      std::max({ cut.move[t[0]], cut.move[t[1]], cut.move[t[2]] }) <= offAxis) // rounding
      continue;
    const Vec3 before = (w.points[t[1]] - w.points[t[0]]).cross(w.points[t[2]] - w.points[t[0]]);
    const Vec3 after =
      (cut.points[t[1]] - cut.points[t[0]]).cross(cut.points[t[2]] - cut.points[t[0]]);
    if (before.norm() <= offAxis * offAxis) // degenerate already (e.g. in the input)
      continue;
    if (!(before.dot(after) > 0.0))
      return "moving the seams onto the half-planes would flip or collapse a face";
  }
  return nullptr;
}

/// The error check (FoldingTreeRotation.cxx, step 4); fills the per-point charge (kept points) and
/// returns whether every distance is within `limit` and every charge within its point's budget
/// (`worst`: the largest distance measured).
bool ChargeTurns(const AxisFrame& frame,
  const WorkMesh& w,
  const SurfaceDistanceQuery& toRegion,
  const SectorCut& cut,
  double limit,
  std::vector<double>& charge,
  double& worst,
  int* failedStage)
{
  worst = 0.0;
  auto Failed = [failedStage](int stage)
  {
    if (failedStage)
      *failedStage = stage;
    return false;
  };
  if (failedStage)
    *failedStage = 0;
  const int np = w.NumberOfPoints(), k = cut.order;
  const double width = TwoPi / k;
  std::vector<char> used(np, 0);
  for (int f = 0; f < w.NumberOfFaces(); ++f)
    if (cut.keep[f])
      for (int v : w.triangles[f])
        used[v] = 1;
  std::vector<int> keptPoints;
  for (int v = 0; v < np; ++v)
    if (used[v])
      keptPoints.push_back(v);
  // Kept points, turned j times, against the region.
  charge.assign(np, 0.0);
  for (int j = 0; j < k; ++j) // j = 0: the sector itself, its seams moved
  {
    const AxisTurn turn(frame.Axis, j * width);
    std::vector<Vec3> turned;
    turned.reserve(keptPoints.size());
    for (int v : keptPoints)
      turned.push_back(turn.Point(cut.points[v]));
    const std::vector<double> d = toRegion.Distances(turned);
    for (size_t i = 0; i < keptPoints.size(); ++i)
      charge[keptPoints[i]] = std::max(charge[keptPoints[i]], d[i]);
    worst = std::max(worst, *std::max_element(d.begin(), d.end()));
    if (worst > limit)
      return Failed(1); // a wrong order fails at its first bad turn (cost: the turns so far)
  }
  // Kept faces with a moved seam vertex: their centroids and edge midpoints, where a face
  // stretched onto a half-plane can leave the surface between its corners (fold's
  // SpendProjectionBudget measures its projected faces the same way).
  {
    std::vector<Vec3> samples;
    std::vector<int> sampleFace;
    for (int f = 0; f < w.NumberOfFaces(); ++f)
    {
      const Triangle& t = w.triangles[f];
      if (!cut.keep[f] || !(cut.move[t[0]] > 0.0 || cut.move[t[1]] > 0.0 || cut.move[t[2]] > 0.0))
        continue;
      const Vec3 &a = cut.points[t[0]], &b = cut.points[t[1]], &c = cut.points[t[2]];
      for (const Vec3& x :
        { Vec3((a + b + c) / 3.0), Vec3(0.5 * (a + b)), Vec3(0.5 * (b + c)), Vec3(0.5 * (c + a)) })
      {
        samples.push_back(x);
        sampleFace.push_back(f);
      }
    }
    const std::vector<double> d = toRegion.Distances(samples);
    for (size_t i = 0; i < samples.size(); ++i)
    {
      worst = std::max(worst, d[i]);
      for (int v : w.triangles[sampleFace[i]])
        charge[v] = std::max(charge[v], d[i]);
    }
    if (worst > limit)
      return Failed(2);
  }
  // Removed points, turned back into the sector, against the sector.
  TriangleMesh sector;
  sector.points = cut.points;
  for (int f = 0; f < w.NumberOfFaces(); ++f)
    if (cut.keep[f])
      sector.triangles.push_back(w.triangles[f]);
  const SurfaceDistanceQuery toSector(sector);
  // Each entry of `back` belongs to a group (a removed point, or a removed face's sample); a
  // group's distance is its nearest entry's.
  std::vector<Vec3> back;
  std::vector<int> group;
  auto turnBack = [&](const Vec3& x, const Vec3& by)
  {
    const double angle = Modulo(frame.Angle(by) - cut.start, TwoPi);
    const int j = std::min(k - 1, static_cast<int>(angle / width));
    return AxisTurn(frame.Axis, -j * width).Point(x);
  };
  int groups = 0;
  for (int v = 0; v < np; ++v)
    if (!used[v])
    {
      back.push_back(turnBack(w.points[v], w.points[v]));
      group.push_back(groups++);
    }
  // The removed faces' centroids and edge midpoints too: a removed face whose corners all
  // have turned partners can still span surface that no copy reproduces (a polygon across the
  // axis, triangulated in large faces, whose whole faces fall in other sectors: the copies'
  // corners are all there, the disc between them is not). A sample is turned back by its own
  // angle and by its face's centroid's (the copy its face belongs to: a midpoint can lie in the
  // next wedge where the sector's border zigzags), the nearer counts.
  for (int f = 0; f < w.NumberOfFaces(); ++f)
    if (!cut.keep[f])
    {
      const Triangle& t = w.triangles[f];
      const Vec3 &a = w.points[t[0]], &b = w.points[t[1]], &c = w.points[t[2]];
      const Vec3 centroid = (a + b + c) / 3.0;
      for (const Vec3& x :
        { centroid, Vec3(0.5 * (a + b)), Vec3(0.5 * (b + c)), Vec3(0.5 * (c + a)) })
      {
        const Vec3 own = turnBack(x, x), byFace = turnBack(x, centroid);
        back.push_back(own);
        group.push_back(groups);
        if (byFace != own)
        {
          back.push_back(byFace);
          group.push_back(groups);
        }
        ++groups;
      }
    }
  // A removed point is reproduced by the copy of the sector face closest to it turned back:
  // its distance is charged to that face's corners (as a fold charges a discarded point to
  // the kept point nearest its mirror image; a rotation node has no fold or rotation above
  // it, so every budget there is still the node's epsilon, the removed points' too).
  std::vector<double> distance;
  std::vector<int> closest;
  toSector.Closest(back, distance, closest);
  std::vector<size_t> nearest(groups, back.size());
  for (size_t i = 0; i < back.size(); ++i)
  {
    size_t& n = nearest[group[i]];
    if (n == back.size() || distance[i] < distance[n])
      n = i;
  }
  for (size_t i : nearest)
  {
    worst = std::max(worst, distance[i]);
    if (!(distance[i] <= limit) || closest[i] < 0)
      return Failed(3);
    for (int v : sector.triangles[closest[i]])
      charge[v] = std::max(charge[v], distance[i]);
  }
  for (int v : keptPoints)
    if (charge[v] > limit || charge[v] > w.budget[v])
      return Failed(4);
  return true;
}
}
}
}
