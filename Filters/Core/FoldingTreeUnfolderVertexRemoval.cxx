// Unfolder: removal of single interior vertices by re-triangulating their closed 1-rings
// (VertexRemover, see FoldingTreeUnfolderVertexRemoval.h).
#include "FoldingTreeUnfolderVertexRemoval.h"
#include "PointTriangleDistance.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace foldingmeshes
{
namespace unfolder_detail
{
namespace
{
/// Largest share of the error limit a collapse of a vertex into its ring may use.
constexpr double CollapseShareOfLimit = 0.1;
/// A point is inside a projected star face down to this barycentric weight (rounding).
constexpr double BarycentricSlack = 1e-9;
/// A new face is degenerate when twice its area is at most this share of its longest edge
/// squared.
constexpr double DegenerateAreaOfLongest = 1e-6;
/// Every star face must face the star's mean normal by more than this cosine (else the star
/// does not project one-to-one).
constexpr double FacingCosine = 1e-3;
/// An ear is too flat (or reflex) in the projection when its doubled signed area is at most
/// this share of its longer side squared.
constexpr double FlatEarArea = 1e-9;
/// Weight of the new diagonal's length in an ear's cost (a tie-breaker: the shorter one).
constexpr double EarLengthWeight = 1e-3;
/// Vertices with more star faces stay: the ear clipping measures every ear against every old
/// face at each step (cubic in the ring; a projected hub of a 1200-segment cylinder took 20 s
/// of a 33,708-face unfold). Such a projected point stays as an extra vertex on the fold line,
/// and a copy's hub stays unthinned: more faces than the input, never a larger error.
constexpr size_t MaximumRemovedValence = 64;

/// 2D orientation (twice the signed area) of (a, b, c).
double Orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c)
{
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

/// The smallest interior angle of the triangle (a, b, c), in radians.
double SmallestAngle(const Vec3& a, const Vec3& b, const Vec3& c)
{
  auto angle = [](const Vec3& p, const Vec3& q, const Vec3& r)
  { return std::atan2((q - p).cross(r - p).norm(), (q - p).dot(r - p)); };
  return std::min({ angle(a, b, c), angle(b, c, a), angle(c, a, b) });
}

/// Distance of x to the nearest of `triangles`; `regular` (optional): IsRegularTriangle of
/// each, tested once by the caller for triangles measured many times.
double DistanceToTriangles(const Vec3& x,
  const std::vector<Vec3>& points,
  const std::vector<Triangle>& triangles,
  const std::vector<char>* regular = nullptr)
{
  double best = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < triangles.size(); ++k)
  {
    const Triangle& t = triangles[k];
    const Vec3 &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
    best = std::min(best,
      (regular && (*regular)[k] ? ClosestPointRegularTriangle(x, a, b, c)
                                : ClosestPointTriangle(x, a, b, c))
        .squaredDistance);
  }
  return std::sqrt(best);
}

/// Rings up to this size get the test of NoRingTriangleWithin before their re-triangulation
/// (at most 3 C(12, 3) = 660 triangles, most tests ending at the first ones).
constexpr size_t MaximumBoundedRing = 12;

/**
 * The star face (index into `ring`/`ringFace` order) a new face over the ring of v takes its
 * ids and flags from, among the `candidate` ones: the one whose projection
 * into the star's plane (perpendicular to its mean normal) contains the new face's centroid,
 * the nearest one in 3D among several; none (a crease): the one with the nearest centroid.
 * Ties go to the first in ring order; -1 without candidates.
 */
int OverlappingStarFace(const std::vector<Vec3>& x,
  int v,
  const std::vector<int>& ring,
  const std::vector<char>& candidate,
  const Triangle& created)
{
  const int m = static_cast<int>(ring.size());
  const Vec3 c = (x[created[0]] + x[created[1]] + x[created[2]]) / 3.0;
  Vec3 normal = Vec3::Zero();
  for (int i = 0; i < m; ++i)
    normal += (x[ring[i]] - x[v]).cross(x[ring[(i + 1) % m]] - x[v]);
  int best = -1;
  double bestDistance = std::numeric_limits<double>::infinity();
  if (normal.norm() > 0.0)
  {
    normal.normalize();
    const Vec3 u = normal.unitOrthogonal(), w = normal.cross(u);
    auto flat = [&](const Vec3& p)
    { return Eigen::Vector2d((p - x[v]).dot(u), (p - x[v]).dot(w)); };
    const Eigen::Vector2d q = flat(c), o = flat(x[v]);
    for (int i = 0; i < m; ++i)
    {
      if (!candidate[i])
        continue;
      const Eigen::Vector2d a = flat(x[ring[i]]), b = flat(x[ring[(i + 1) % m]]);
      const double area = Orientation(o, a, b);
      if (area == 0.0)
        continue;
      const double l0 = Orientation(q, a, b) / area, l1 = Orientation(o, q, b) / area,
                   l2 = Orientation(o, a, q) / area;
      const double slack = -BarycentricSlack;
      if (l0 < slack || l1 < slack || l2 < slack)
        continue;
      const double d =
        ClosestPointTriangle(c, x[v], x[ring[i]], x[ring[(i + 1) % m]]).squaredDistance;
      if (d < bestDistance)
      {
        bestDistance = d;
        best = i;
      }
    }
  }
  if (best >= 0)
    return best;
  for (int i = 0; i < m; ++i)
  {
    if (!candidate[i])
      continue;
    const double d = (c - (x[v] + x[ring[i]] + x[ring[(i + 1) % m]]) / 3.0).squaredNorm();
    if (d < bestDistance)
    {
      bestDistance = d;
      best = i;
    }
  }
  return best;
}

/// The closed 1-ring of v: star faces (v, a, b) give ring edges a -> b; ring[i] is followed
/// by ring[i + 1], face[i] is the star face with ring edge ring[i] -> ring[i + 1]. False
/// unless the edges form one cycle through every star face (v interior, manifold there).
bool ClosedRing(const std::vector<Triangle>& triangles,
  const std::vector<int>& star,
  int v,
  std::vector<int>& ring,
  std::vector<int>& face)
{
  // a -> (b, face) per star face, few of them: a flat list (at most MaximumRemovedValence).
  struct Link
  {
    int a, b, face;
  };
  if (star.empty())
    return false;
  std::vector<Link> next;
  next.reserve(star.size());
  auto find = [&next](int a)
  {
    for (const Link& l : next)
      if (l.a == a)
        return &l;
    return static_cast<const Link*>(nullptr);
  };
  int start = std::numeric_limits<int>::max();
  for (int f : star)
  {
    const Triangle& t = triangles[f];
    const int k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
    const int a = t[(k + 1) % 3], b = t[(k + 2) % 3];
    if (a == v || b == v || a == b || find(a))
      return false;
    next.push_back({ a, b, f });
    start = std::min(start, a);
  }
  ring.clear();
  face.clear();
  int a = start;
  for (size_t i = 0; i < star.size(); ++i)
  {
    const Link* l = find(a);
    if (!l)
      return false;
    ring.push_back(a);
    face.push_back(l->face);
    a = l->b;
  }
  if (a != ring.front())
    return false;
  std::vector<int> sorted = ring;
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end() && ring.size() >= 3;
}
} // namespace

bool NoRingTriangleWithin(const Vec3& x,
  const std::vector<Vec3>& points,
  const std::vector<int>& ring,
  double reach)
{
  const size_t m = ring.size();
  for (size_t i = 0; i < m; ++i)
    for (size_t j = i + 1; j < m; ++j)
      for (size_t k = j + 1; k < m; ++k)
      {
        const Vec3 &p = points[ring[i]], &q = points[ring[j]], &r = points[ring[k]];
        for (const std::array<const Vec3*, 3>& t : { std::array<const Vec3*, 3>{ &p, &q, &r },
               std::array<const Vec3*, 3>{ &q, &r, &p },
               std::array<const Vec3*, 3>{ &r, &p, &q } })
          if (std::sqrt(ClosestPointTriangle(x, *t[0], *t[1], *t[2]).squaredDistance) <= reach)
            return false;
      }
  return true;
}

VertexRemover::VertexRemover(Piece& piece, double slack)
  : Mesh(piece)
  , Slack(slack)
  , VertexFaces(FacesOfPoints(piece.triangles, piece.points.size()))
  , FaceAlive(piece.triangles.size(), 1)
  , IsRemoved(piece.points.size(), 0)
{
}

double VertexRemover::Limit(int v, double fallback) const
{
  const Piece& piece = this->Mesh;
  double limit = piece.budget[v];
  for (int f : this->VertexFaces[v])
    if (this->FaceAlive[f])
      for (int a : piece.triangles[f])
        limit = std::min(limit, piece.budget[a]);
  if (!std::isfinite(limit))
    limit = fallback;
  return std::max(limit, this->Slack);
}

bool VertexRemover::Interior(int v) const
{
  std::vector<int> star, ring, ringFace;
  for (int f : this->VertexFaces[v])
    if (this->FaceAlive[f])
      star.push_back(f);
  return star.size() >= 3 && ClosedRing(this->Mesh.triangles, star, v, ring, ringFace);
}

namespace
{
/**
 * One attempt of VertexRemover::Try: the star of v (closed ring), the faces that may replace
 * it and the checks they must pass - ear clipping in the plane of the star, else a collapse
 * of v into its ring, then the sampled deviation from the old star.
 */
class RingRetriangulation
{
public:
  RingRetriangulation(const Piece& piece,
    const std::vector<std::vector<int>>& facesOf,
    const std::vector<char>& alive,
    int v,
    const std::vector<int>& star,
    const std::vector<int>& ring,
    const RingRules& rules)
    : Piece_(piece)
    , FacesOf(facesOf)
    , Alive(alive)
    , X(piece.points)
    , V(v)
    , Star(star)
    , Ring(ring)
    , Rules(rules)
    , M(static_cast<int>(ring.size()))
  {
    for (int f : star)
    {
      const Triangle& t = piece.triangles[f];
      this->Old.push_back(t);
      this->OldRegular.push_back(IsRegularTriangle(X[t[0]], X[t[1]], X[t[2]]));
    }
    this->Sharpest = rules.minimumAngle;
    if (this->Sharpest > 0.0)
      for (const Triangle& t : this->Old)
        this->Sharpest = std::min(this->Sharpest, SmallestAngle(X[t[0]], X[t[1]], X[t[2]]));
  }

  /// Ear clipping in the plane perpendicular to the star's mean normal.
  bool ClipEars(std::vector<Triangle>& created, const char*& why);
  /// Where the star does not project one-to-one or no ear order works: v collapsed into a
  /// ring vertex (see the definition). Keeps `why` when it fails.
  bool CollapseIntoRing(double limit, std::vector<Triangle>& created, const char*& why);
  /// Forgets the diagonals of a failed ear clipping.
  void ClearDiagonals() { this->Diagonals.clear(); }
  /// A face on the ring's three vertices already (a tetrahedron-like spot): a duplicate.
  bool DuplicatesAFace() const;
  /// The deviation between the old star and `created`, sampled (stops once over `limit`).
  double Deviation(const std::vector<Triangle>& created, double limit) const;

private:
  bool HasEdge(int a, int c) const
  {
    if (this->Diagonals.count({ std::min(a, c), std::max(a, c) }))
      return true;
    for (int f : this->FacesOf[a])
      if (this->Alive[f])
      {
        const Triangle& t = this->Piece_.triangles[f];
        if (t[0] == c || t[1] == c || t[2] == c)
          return true;
      }
    return false;
  }
  /// RingRules: a new edge between two fixed points.
  bool FixedEdge(int a, int c) const
  {
    const std::vector<char>* fixed = this->Rules.noNewEdgeBetween;
    return fixed && (*fixed)[a] && (*fixed)[c];
  }
  /// Not degenerate (and not sharper than the rules allow).
  bool Regular(int a, int b, int c) const
  {
    const std::vector<Vec3>& x = this->X;
    const double longest = std::max(
      { (x[a] - x[b]).squaredNorm(), (x[b] - x[c]).squaredNorm(), (x[c] - x[a]).squaredNorm() });
    return (x[b] - x[a]).cross(x[c] - x[a]).norm() > DegenerateAreaOfLongest * longest &&
      (this->Sharpest <= 0.0 || SmallestAngle(x[a], x[b], x[c]) >= this->Sharpest);
  }

  const Piece& Piece_;
  const std::vector<std::vector<int>>& FacesOf;
  const std::vector<char>& Alive;
  const std::vector<Vec3>& X;
  const int V;
  const std::vector<int>& Star;
  const std::vector<int>& Ring;
  const RingRules& Rules;
  const int M;
  /// Distance of p to the nearest face of the old star.
  double DistanceToOld(const Vec3& p) const
  {
    return DistanceToTriangles(p, this->X, this->Old, &this->OldRegular);
  }

  std::vector<Triangle> Old;    ///< the star's faces
  std::vector<char> OldRegular; ///< IsRegularTriangle of each
  double Sharpest = 0.0;        ///< the smallest angle a new face may have (0: any)
  EdgeSet Diagonals;            ///< the new edges (the budget check samples their midpoints)
};

bool RingRetriangulation::ClipEars(std::vector<Triangle>& created, const char*& why)
{
  const std::vector<Vec3>& x = this->X;
  const std::vector<int>& ring = this->Ring;
  const int v = this->V, m = this->M;
  why = "not one-to-one";
  Vec3 normal = Vec3::Zero();
  std::vector<Vec3> faceNormal(m);
  for (int i = 0; i < m; ++i)
  {
    faceNormal[i] = (x[ring[i]] - x[v]).cross(x[ring[(i + 1) % m]] - x[v]);
    normal += faceNormal[i];
  }
  if (normal.norm() <= 0.0)
    return false;
  normal.normalize();
  for (const Vec3& n : faceNormal)
    if (n.dot(normal) <= FacingCosine * n.norm())
      return false;
  // The ring in the plane perpendicular to the mean normal, v at the origin; the polygon below
  // holds positions in the ring (flat[i] is ring[i]'s).
  const Vec3 u = normal.unitOrthogonal(), w = normal.cross(u);
  std::vector<Eigen::Vector2d> flat(m);
  for (int i = 0; i < m; ++i)
    flat[i] = Eigen::Vector2d((x[ring[i]] - x[v]).dot(u), (x[ring[i]] - x[v]).dot(w));
  double turn = 0.0;
  for (int i = 0; i < m; ++i)
  {
    const Eigen::Vector2d& p = flat[i];
    const Eigen::Vector2d& q = flat[(i + 1) % m];
    turn += std::atan2(p.x() * q.y() - p.y() * q.x(), p.dot(q));
  }
  if (std::abs(turn - 2.0 * M_PI) > 1e-6)
    return false;

  why = "no triangulation";
  std::vector<int> poly(m);
  for (int i = 0; i < m; ++i)
    poly[i] = i;
  created.clear();
  auto allowed = [&](int ia, int ic)
  {
    const int i = static_cast<int>(std::find(poly.begin(), poly.end(), ia) - poly.begin());
    const int ib = poly[(i + 1) % poly.size()];
    const Eigen::Vector2d &pa = flat[ia], &pb = flat[ib], &pc = flat[ic];
    const double area = Orientation(pa, pb, pc);
    if (area <= FlatEarArea * std::max((pa - pc).squaredNorm(), (pb - pa).squaredNorm()))
      return false;
    for (int iq : poly)
      if (iq != ia && iq != ib && iq != ic)
      {
        const Eigen::Vector2d& pq = flat[iq];
        if (Orientation(pa, pb, pq) >= 0.0 && Orientation(pb, pc, pq) >= 0.0 &&
          Orientation(pc, pa, pq) >= 0.0)
          return false;
      }
    const int a = ring[ia], b = ring[ib], c = ring[ic];
    return this->Regular(a, b, c) && !this->FixedEdge(a, c) && !this->HasEdge(a, c);
  };
  auto cut = [&](int ia, int ib, int ic)
  {
    const int a = ring[ia], c = ring[ic];
    created.push_back({ a, ring[ib], c });
    this->Diagonals.insert({ std::min(a, c), std::max(a, c) });
  };
  // The ear that departs least from the old star first (sampled at its centroid and the
  // midpoint of its new diagonal), the shorter diagonal on (near) ties: on a crease, the
  // diagonals follow the crease instead of cutting across it.
  const double lengthWeight = EarLengthWeight;
  double spoke = 0.0;
  for (int a : ring)
    spoke += (x[a] - x[v]).norm() / m;
  auto deviation = [&](int ia, int ib, int ic)
  {
    const int a = ring[ia], b = ring[ib], c = ring[ic];
    double value = std::max(this->DistanceToOld((x[a] + x[b] + x[c]) / 3.0),
                     this->DistanceToOld(0.5 * (x[a] + x[c]))) +
      lengthWeight * (x[a] - x[c]).norm();
    if (this->Rules.shapeWeight > 0.0)
      value +=
        this->Rules.shapeWeight * spoke * (1.0 - SmallestAngle(x[a], x[b], x[c]) / (M_PI / 3.0));
    return value;
  };
  if (!ClipCheapestEars(poly, allowed, deviation, cut))
    return false;
  if (Orientation(flat[poly[0]], flat[poly[1]], flat[poly[2]]) <= 0.0 ||
    !this->Regular(ring[poly[0]], ring[poly[1]], ring[poly[2]]))
    return false;
  created.push_back({ ring[poly[0]], ring[poly[1]], ring[poly[2]] });
  return true;
}

// Collapse v into the ring vertex u whose new faces depart least from the old star, by at
// most a tenth of the limit (a collapse follows the old star less closely than ears do; with
// the whole budget it cut the corners of a CAD mesh: bearing 0.0033 -> 0.0061). Each star
// face (v, a, b) becomes (u, a, b), the two faces on edge v-u vanish; accepted when no new
// edge exists already (the link condition), no new face is degenerate and none turns by 90
// degrees or more against the face it replaces.
bool RingRetriangulation::CollapseIntoRing(double limit,
  std::vector<Triangle>& created,
  const char*& why)
{
  const std::vector<Vec3>& x = this->X;
  const std::vector<int>& ring = this->Ring;
  const int v = this->V, m = this->M;
  const char* reason = why;
  double best = std::numeric_limits<double>::infinity();
  std::vector<Triangle> bestFaces;
  int bestU = -1;
  for (int i = 0; i < m; ++i)
  {
    const int u = ring[i];
    const int previous = ring[(i + m - 1) % m], next = ring[(i + 1) % m];
    auto newEdgeFree = [&](int a)
    { return a == previous || a == next || (!this->FixedEdge(u, a) && !this->HasEdge(u, a)); };
    std::vector<Triangle> faces;
    bool ok = true;
    for (int j = 0; j < m && ok; ++j)
    {
      const int a = ring[j], b = ring[(j + 1) % m];
      if (a == u || b == u)
        continue;
      const Vec3 before = (x[a] - x[v]).cross(x[b] - x[v]);
      const Vec3 after = (x[a] - x[u]).cross(x[b] - x[u]);
      ok = this->Regular(u, a, b) && after.dot(before) > 0.0 && newEdgeFree(a) && newEdgeFree(b);
      faces.push_back({ u, a, b });
    }
    if (!ok || faces.empty())
      continue;
    double worst = DistanceToTriangles(x[v], x, faces);
    for (const Triangle& t : faces)
      worst = std::max(worst, this->DistanceToOld((x[t[0]] + x[t[1]] + x[t[2]]) / 3.0));
    if (worst <= CollapseShareOfLimit * limit && worst < best)
    {
      best = worst;
      bestFaces = std::move(faces);
      bestU = u;
    }
  }
  if (bestFaces.empty())
  {
    why = reason;
    return false;
  }
  // The new edges from u, sampled like an ear's diagonals by the budget check.
  for (const Triangle& t : bestFaces)
    for (int k = 1; k < 3; ++k)
      this->Diagonals.insert({ std::min(bestU, t[k]), std::max(bestU, t[k]) });
  created = std::move(bestFaces);
  return true;
}

bool RingRetriangulation::DuplicatesAFace() const
{
  if (this->M != 3)
    return false;
  const std::vector<int>& ring = this->Ring;
  for (int f : this->FacesOf[ring[0]])
    if (this->Alive[f] && std::find(this->Star.begin(), this->Star.end(), f) == this->Star.end())
    {
      Triangle t = this->Piece_.triangles[f], r = { ring[0], ring[1], ring[2] };
      std::sort(t.begin(), t.end());
      std::sort(r.begin(), r.end());
      if (t == r)
        return true;
    }
  return false;
}

// Sampled: v, the star's face centroids and spoke midpoints against the new faces; the new
// faces' centroids and diagonal midpoints against the star (the ring edges belong to both).
double RingRetriangulation::Deviation(const std::vector<Triangle>& created, double limit) const
{
  const std::vector<Vec3>& x = this->X;
  const std::vector<int>& ring = this->Ring;
  const int v = this->V, m = this->M;
  double moved = DistanceToTriangles(x[v], x, created);
  for (int i = 0; i < m && moved <= limit; ++i)
  {
    const Vec3& a = x[ring[i]];
    const Vec3& b = x[ring[(i + 1) % m]];
    moved = std::max(moved, DistanceToTriangles((x[v] + a + b) / 3.0, x, created));
    moved = std::max(moved, DistanceToTriangles(0.5 * (x[v] + a), x, created));
  }
  for (size_t k = 0; k < created.size() && moved <= limit; ++k)
  {
    const Triangle& t = created[k];
    moved = std::max(moved, this->DistanceToOld((x[t[0]] + x[t[1]] + x[t[2]]) / 3.0));
    for (int j = 0; j < 3; ++j)
      if (this->Diagonals.count({ std::min(t[j], t[(j + 1) % 3]), std::max(t[j], t[(j + 1) % 3]) }))
        moved = std::max(moved, this->DistanceToOld(0.5 * (x[t[j]] + x[t[(j + 1) % 3]])));
  }
  return moved;
}
} // namespace

bool VertexRemover::Try(int v,
  double limit,
  const RingRules& rules,
  RingRemoval& removal,
  const char*& why) const
{
  removal.vertex = v;
  removal.limit = limit;
  removal.created.clear();
  removal.moved = 0.0;
  std::vector<int> star;
  for (int f : this->VertexFaces[v])
    if (this->FaceAlive[f])
      star.push_back(f);
  why = "too many faces around it";
  if (star.size() > MaximumRemovedValence)
    return false;
  why = "open ring";
  if (star.size() < 3 || !ClosedRing(this->Mesh.triangles, star, v, removal.ring, removal.ringFace))
    return false;
  // The budget check measures v against the new faces first; where no triangle of ring
  // points comes within the limit, it must fail: the re-triangulation is not worth making
  // (most removals the thinning tries end here).
  why = "budget";
  if (removal.ring.size() <= MaximumBoundedRing &&
    NoRingTriangleWithin(this->Mesh.points[v], this->Mesh.points, removal.ring, limit))
    return false;
  RingRetriangulation candidate(
    this->Mesh, this->VertexFaces, this->FaceAlive, v, star, removal.ring, rules);
  if (!candidate.ClipEars(removal.created, why))
  {
    removal.created.clear();
    candidate.ClearDiagonals();
    if (!candidate.CollapseIntoRing(limit, removal.created, why))
      return false;
  }
  if (candidate.DuplicatesAFace())
    return false;
  why = "budget";
  removal.moved = candidate.Deviation(removal.created, limit);
  return removal.moved <= limit;
}

void VertexRemover::Apply(const RingRemoval& removal)
{
  Piece& piece = this->Mesh;
  // Each new face carries the ids, copy and flags of the old star face containing its centroid
  // (seen along the star's mean normal; else the nearest centroid) among
  // those with the copy and filled flag of the star face whose ring edge starts at its second
  // vertex (the copy steers the later thinning; the choice is made on the old star).
  std::map<int, int> faceAt; // ring vertex -> the star face with the ring edge from it
  for (size_t i = 0; i < removal.ring.size(); ++i)
    faceAt[removal.ring[i]] = removal.ringFace[i];
  std::vector<int> likes;
  std::vector<char> candidate(removal.ring.size());
  for (const Triangle& t : removal.created)
  {
    const int first = faceAt[t[1]];
    for (size_t i = 0; i < removal.ring.size(); ++i)
    {
      const int f = removal.ringFace[i];
      candidate[i] = piece.faceCopy[f] == piece.faceCopy[first] &&
        piece.faceFilled[f] == piece.faceFilled[first];
    }
    const int i = OverlappingStarFace(piece.points, removal.vertex, removal.ring, candidate, t);
    likes.push_back(i >= 0 ? removal.ringFace[i] : first);
  }
  // A new face is a fill (UnfoldedMesh::faceFilled) only where the whole old star was: one
  // that also covers surface of the copy is not added surface, however it overlaps a small
  // fill of the star (the bearing's thinned sector copies would flag 2% of its area as fill).
  bool starFilled = true;
  for (int f : removal.ringFace)
    starFilled = starFilled && piece.faceFilled[f] != 0;
  for (int f : removal.ringFace)
    this->FaceAlive[f] = 0;
  for (size_t k = 0; k < removal.created.size(); ++k)
  {
    const Triangle& t = removal.created[k];
    const int like = likes[k];
    const int f = piece.NumberOfFaces();
    piece.triangles.push_back(t);
    piece.faceOrig.push_back(piece.faceOrig[like]);
    piece.faceCopy.push_back(piece.faceCopy[like]);
    piece.faceFilled.push_back(starFilled ? piece.faceFilled[like] : 0);
    this->FaceAlive.push_back(1);
    for (int a : t)
      this->VertexFaces[a].push_back(f);
  }
  for (int a : removal.ring)
  {
    auto& list = this->VertexFaces[a];
    list.erase(std::remove_if(list.begin(), list.end(), [&](int f) { return !this->FaceAlive[f]; }),
      list.end());
    piece.budget[a] = std::max(0.0, piece.budget[a] - removal.moved);
  }
  this->VertexFaces[removal.vertex].clear();
  this->IsRemoved[removal.vertex] = 1;
  ++this->RemovedCount;
}

int VertexRemover::Compact(std::vector<char>* perPoint)
{
  if (this->RemovedCount == 0)
    return 0;
  Piece& piece = this->Mesh;
  const int n = piece.NumberOfPoints();
  std::vector<int> index(n, -1);
  Piece out;
  std::vector<char> kept;
  for (int v = 0; v < n; ++v)
    if (!this->IsRemoved[v])
    {
      index[v] = out.NumberOfPoints();
      out.AppendPoint(piece, v);
      if (perPoint)
        kept.push_back((*perPoint)[v]);
    }
  if (perPoint)
    *perPoint = std::move(kept);
  for (int f = 0; f < piece.NumberOfFaces(); ++f)
    if (this->FaceAlive[f])
    {
      const Triangle& t = piece.triangles[f];
      out.triangles.push_back({ index[t[0]], index[t[1]], index[t[2]] });
      out.faceOrig.push_back(piece.faceOrig[f]);
      out.faceCopy.push_back(piece.faceCopy[f]);
      out.faceFilled.push_back(piece.faceFilled[f]);
    }
  piece = std::move(out);
  const int count = this->RemovedCount;
  // The piece is a new one: start over on it.
  this->VertexFaces = FacesOfPoints(piece.triangles, piece.points.size());
  this->FaceAlive.assign(piece.triangles.size(), 1);
  this->IsRemoved.assign(piece.points.size(), 0);
  this->RemovedCount = 0;
  return count;
}
} // namespace unfolder_detail
} // namespace foldingmeshes
