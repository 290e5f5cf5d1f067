// Attachments: tubes (horns, necks), disc-shaped holes, welding a tube to an area fraction.
#include "ProceduralMeshesInternal.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace foldingmeshes
{
namespace testing
{
namespace procedural
{
// Builds the tube (open at t = 0, closed by a half-ellipsoid cap and a tip vertex) in world
// coordinates o + E * local. The section frame (X, Y) is parallel-transported along the
// centreline from X = local x at t = 0 (so a centreline in the plane x = 0 keeps X = (1, 0, 0)
// exactly, and a section offset odd in x along X and even along Y gives a tube exactly
// symmetric about local x = 0). Returns the mesh; ring0 receives the ids of the first ring,
// whose edges the tube uses as ring0[k+1] -> ring0[k].
TriMesh BuildTube(const TubeSpec& s,
  const Vec3& o,
  const Eigen::Matrix3d& E,
  char sym,
  std::vector<Id>& ring0)
{
  double len = 0;
  for (int k = 0; k < 64; ++k)
  {
    len += (s.center((k + 1) / 64.0) - s.center(k / 64.0)).norm();
  }
  const int rings = std::max(2, int(std::ceil(len / s.spacing)));
  struct Section
  {
    Vec3 c, X, Y;
    double t, scale;
  };
  std::vector<Section> sec;
  Vec3 X = Vec3::UnitX(), T = Vec3::UnitZ();
  auto transport = [&](double t)
  {
    const double dt = 1e-5, t0 = std::max(0.0, t - dt), t1 = std::min(1.0, t + dt);
    T = (s.center(t1) - s.center(t0)).normalized();
    X = (X - X.dot(T) * T).normalized();
  };
  for (int j = 0; j <= rings; ++j)
  {
    const double t = double(j) / rings;
    transport(t);
    sec.push_back({ s.center(t), X, T.cross(X), t, 1.0 });
  }
  const Vec3 c1 = s.center(1.0), T1 = T, X1 = X;
  const double capLen = s.radii(1.0).minCoeff();
  const int capRings = std::max(1, int(std::lround(0.5 * kPi * capLen / s.spacing)) - 1);
  for (int i = 1; i <= capRings; ++i)
  {
    const double th = 0.5 * kPi * i / (capRings + 1);
    sec.push_back({ c1 + capLen * std::sin(th) * T1, X1, T1.cross(X1), 1.0, std::cos(th) });
  }
  const std::vector<Vec2> table = RingTable(s.quarter);
  const size_t M = table.size();
  TriMesh m;
  std::vector<std::vector<Id>> ring(sec.size());
  for (size_t j = 0; j < sec.size(); ++j)
  {
    const Section& S = sec[j];
    const Vec2 r = s.radii(S.t);
    for (size_t k = 0; k < M; ++k)
    {
      const Vec2 off =
        s.section ? s.section(S.t, table[k]) : Vec2(r.x() * table[k].x(), r.y() * table[k].y());
      const Vec3 local = S.c + (S.scale * off.x()) * S.X + (S.scale * off.y()) * S.Y;
      ring[j].push_back(m.Add(o + E * local));
    }
  }
  const Id tip = m.Add(o + E * (c1 + capLen * T1));
  for (size_t j = 0; j + 1 < sec.size(); ++j)
  {
    const auto& R = ring[j];
    const auto& Q = ring[j + 1];
    for (size_t k = 0; k < M; ++k)
    {
      const size_t k1 = (k + 1) % M;
      if (!s.symmetricDiagonals || table[k].x() + table[k1].x() > 0)
      {
        m.Face(R[k1], R[k], Q[k], sym);
        m.Face(R[k1], Q[k], Q[k1], sym);
      }
      else
      {
        m.Face(R[k1], R[k], Q[k1], sym);
        m.Face(R[k], Q[k], Q[k1], sym);
      }
    }
  }
  for (size_t k = 0; k < M; ++k)
  {
    m.Face(ring.back()[(k + 1) % M], ring.back()[k], tip, sym);
  }
  ring0 = ring[0];
  return m;
}

namespace
{
uint64_t EdgeKey(Id a, Id b)
{
  return (uint64_t(a) << 32) | uint64_t(b);
}

// Removes the faces around P (connected to the face nearest P, centroid within rho, allowed),
// fills notches, and checks that the boundary is one simple loop.
bool CutHole(const TriMesh& m,
  const Vec3& P,
  double rho,
  double h,
  const std::vector<char>& allowed,
  Hole& hole)
{
  const size_t nf = m.t.size();
  std::vector<Vec3> cen(nf);
  std::unordered_map<uint64_t, size_t> half; // directed edge -> face, for faces near P
  std::vector<size_t> cand;
  for (size_t f = 0; f < nf; ++f)
  {
    cen[f] = (m.p[m.t[f][0]] + m.p[m.t[f][1]] + m.p[m.t[f][2]]) / 3;
    if ((cen[f] - P).norm() < rho + 3 * h)
    {
      cand.push_back(f);
      for (int e = 0; e < 3; ++e)
      {
        half[EdgeKey(m.t[f][e], m.t[f][(e + 1) % 3])] = f;
      }
    }
  }
  auto twin = [&](size_t f, int e) -> long
  {
    auto it = half.find(EdgeKey(m.t[f][(e + 1) % 3], m.t[f][e]));
    return it == half.end() ? -1 : long(it->second);
  };
  long seed = -1;
  for (size_t f : cand)
  {
    if (allowed[f] && (seed < 0 || (cen[f] - P).norm() < (cen[seed] - P).norm()))
    {
      seed = long(f);
    }
  }
  if (seed < 0)
  {
    return false;
  }
  std::vector<char>& rem = hole.removed;
  rem.assign(nf, 0);
  rem[seed] = 1;
  std::vector<size_t> stack{ size_t(seed) };
  while (!stack.empty())
  {
    const size_t f = stack.back();
    stack.pop_back();
    for (int e = 0; e < 3; ++e)
    {
      const long g = twin(f, e);
      if (g >= 0 && !rem[g] && allowed[g] && (cen[g] - P).norm() < rho)
      {
        rem[g] = 1;
        stack.push_back(size_t(g));
      }
    }
  }
  // fill notches: kept faces with 2+ edges on the hole, or (smoother loops) with an edge on the
  // hole and the third vertex on it too
  for (bool changed = true; changed;)
  {
    changed = false;
    std::unordered_map<Id, char> onHole;
    for (size_t f : cand)
    {
      for (int e = 0; rem[f] && e < 3; ++e)
      {
        onHole[m.t[f][e]] = 1;
      }
    }
    for (size_t f : cand)
    {
      int n = 0, v = 0;
      for (int e = 0; e < 3; ++e)
      {
        const long g = twin(f, e);
        n += g >= 0 && rem[g];
        v += onHole.count(m.t[f][e]) > 0;
      }
      if (!rem[f] && allowed[f] && (n >= 2 || (n == 1 && v == 3)))
      {
        rem[f] = changed = true;
      }
    }
  }
  std::unordered_map<Id, Id> next;
  for (size_t f : cand)
  {
    for (int e = 0; e < 3; ++e)
    {
      const long g = twin(f, e);
      if (!rem[f] && g >= 0 && rem[g] && !next.emplace(m.t[f][e], m.t[f][(e + 1) % 3]).second)
      {
        return false; // pinch
      }
    }
  }
  if (next.size() < 3)
  {
    return false;
  }
  hole.loop.clear();
  Id v = next.begin()->first;
  do
  {
    hole.loop.push_back(v);
    auto it = next.find(v);
    if (it == next.end() || hole.loop.size() > next.size())
    {
      return false;
    }
    v = it->second;
  } while (v != hole.loop.front());
  if (hole.loop.size() != next.size())
  {
    return false; // several loops
  }
  hole.normal.setZero();
  hole.center.setZero();
  for (size_t f = 0; f < nf; ++f)
  {
    if (rem[f])
    {
      hole.normal += (m.p[m.t[f][1]] - m.p[m.t[f][0]]).cross(m.p[m.t[f][2]] - m.p[m.t[f][0]]);
    }
  }
  hole.normal.normalize();
  for (Id u : hole.loop)
  {
    hole.center += m.p[u];
  }
  hole.center /= double(hole.loop.size());
  {
    // the normal of the loop's least-squares plane (oriented as the removed faces): the loop
    // then winds around it as evenly as it can
    Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
    for (Id u : hole.loop)
    {
      C += (m.p[u] - hole.center) * (m.p[u] - hole.center).transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
    const Vec3 fit = es.eigenvectors().col(0);
    hole.normal = fit.dot(hole.normal) < 0 ? Vec3(-fit) : fit;
  }
  return true;
}
} // namespace

// Tries radii around rho until the hole is a clean disc.
Hole CutHoleRobust(const TriMesh& m,
  const Vec3& P,
  double rho,
  double h,
  const std::vector<char>& allowed)
{
  Hole hole;
  for (int k = 0; k < 24; ++k)
  {
    const double f = 1 + 0.04 * ((k + 1) / 2) * (k % 2 ? -1 : 1);
    if (CutHole(m, P, rho * f, h, allowed, hole))
    {
      return hole;
    }
  }
  throw std::runtime_error("ProceduralMeshes: could not cut a disc-shaped hole");
}

namespace
{
double LoopSense(const TriMesh& m, const std::vector<Id>& loop, const Vec3& c, const Vec3& n)
{
  double s = 0;
  for (size_t k = 0; k < loop.size(); ++k)
  {
    s += (m.p[loop[k]] - c).cross(m.p[loop[(k + 1) % loop.size()]] - c).dot(n);
  }
  return s;
}

// body minus the hole + tube + collar (marked 0) joining the hole loop to the tube's first ring;
// unused vertices removed.
TriMesh Weld(const TriMesh& body, const Hole& hole, TriMesh tube, std::vector<Id> ring0)
{
  TriMesh out;
  out.p = body.p;
  for (size_t f = 0; f < body.t.size(); ++f)
  {
    if (!hole.removed[f])
    {
      out.t.push_back(body.t[f]);
      out.sym.push_back(body.sym[f]);
    }
  }
  const Id off = Id(out.p.size());
  for (Id& v : ring0)
  {
    v += off;
  }
  out.Append(tube);
  const Vec3 n = hole.normal, c = hole.center;
  if ((LoopSense(out, hole.loop, c, n) > 0) != (LoopSense(out, ring0, c, n) > 0))
  {
    std::reverse(ring0.begin() + 1, ring0.end()); // same sense as the loop: flip the tube
    for (size_t f = out.t.size() - tube.t.size(); f < out.t.size(); ++f)
    {
      std::swap(out.t[f][0], out.t[f][1]);
    }
  }
  auto flat = [&](Id v)
  {
    const Vec3 d = out.p[v] - c;
    return Vec3(d - d.dot(n) * n).normalized();
  };
  std::vector<Id> loop = hole.loop;
  size_t start = 0;
  for (size_t k = 1; k < loop.size(); ++k)
  {
    if (flat(loop[k]).dot(flat(ring0[0])) > flat(loop[start]).dot(flat(ring0[0])))
    {
      start = k;
    }
  }
  std::rotate(loop.begin(), loop.begin() + long(start), loop.end());
  // Pair the two loops by the angle around the normal when both wind monotonically around it
  // (no crossing collar triangles on a wiggly hole), else by arc length.
  const Vec3 e0 = flat(ring0[0]), e1 = n.cross(e0);
  auto angles = [&](const std::vector<Id>& l, std::vector<double>& t)
  {
    t.assign(l.size(), 0.0);
    const double sense = LoopSense(out, l, c, n) > 0 ? 1 : -1;
    double prev = 0;
    for (size_t k = 0; k < l.size(); ++k)
    {
      const Vec3 d = flat(l[k]);
      double a = sense * std::atan2(d.dot(e1), d.dot(e0));
      while (a < prev - kPi)
      {
        a += 2 * kPi;
      }
      while (a > prev + kPi)
      {
        a -= 2 * kPi;
      }
      prev = a;
      t[k] = k > 0 ? std::max(t[k - 1], a) : a; // monotone envelope of the winding angle
    }
    const double a0 = t[0];
    for (double& x : t)
    {
      x = (x - a0) / (2 * kPi);
    }
    const Vec3 d0 = flat(l[0]), dn = flat(l.back()); // the loop winds once around c
    const double last = sense * std::atan2(d0.cross(dn).dot(n), d0.dot(dn));
    return t.size() > 2 && t.back() < 1 && std::abs(prev - a0 - (2 * kPi + last)) < 1e-6;
  };
  std::vector<double> tl, tr;
  if (!(angles(loop, tl) && angles(ring0, tr)))
  {
    tl = ArcParams(out, loop);
    tr = ArcParams(out, ring0);
  }
  Zip(loop, tl, ring0, tr, [&](Id a, Id b, Id d) { out.Face(a, b, d, 0); });
  std::vector<Id> map(out.p.size(), -1);
  TriMesh packed;
  for (size_t f = 0; f < out.t.size(); ++f)
  {
    Tri t = out.t[f];
    for (Id& v : t)
    {
      if (map[v] < 0)
      {
        map[v] = packed.Add(out.p[v]);
      }
      v = map[v];
    }
    packed.Face(t[0], t[1], t[2], out.sym[f]);
  }
  return packed;
}
} // namespace

double MeshArea(const TriMesh& m, int onlySym)
{
  double a = 0;
  for (size_t f = 0; f < m.t.size(); ++f)
  {
    a += onlySym < 0 || m.sym[f] == onlySym ? m.Area(f) : 0.0;
  }
  return a;
}

double EdgeLength(const TriMesh& m)
{
  return std::sqrt(4 * MeshArea(m) / (std::sqrt(3.0) * double(m.t.size())));
}

// Height of the hole loop above its centre along the hole normal: tubes start above it, so the
// collar does not dip into a bumpy body.
double LoopLift(const TriMesh& m, const Hole& hole)
{
  double lift = 0;
  for (Id v : hole.loop)
  {
    lift = std::max(lift, (m.p[v] - hole.center).dot(hole.normal));
  }
  return lift;
}

// Of 8 turns about the hole normal of the frame E, the one whose tube spec (length L) keeps
// farthest from the body's vertices beyond arc length `skip` from its start at o; with `cost`,
// the one of least cost among those keeping at least `minGap` away (if any).
Eigen::Matrix3d ClearestFrame(const TriMesh& body,
  const Eigen::Matrix3d& E,
  const TubeSpec& s,
  const Vec3& o,
  double L,
  double skip,
  const std::function<double(const Eigen::Matrix3d&)>& cost,
  double minGap)
{
  const size_t stride = std::max<size_t>(1, body.p.size() / 3000);
  const std::vector<Vec2> dirs = RingTable(4);
  const double u0 = std::min(0.9, skip / L);
  Eigen::Matrix3d best = E, cheapest = E;
  double bestGap = -1e300, bestCost = 1e300;
  for (int k = 0; k < 8; ++k)
  {
    const double b = 2 * kPi * k / 8;
    Eigen::Matrix3d R = E;
    R.col(0) = std::cos(b) * E.col(0) + std::sin(b) * E.col(1);
    R.col(1) = E.col(2).cross(R.col(0));
    double gap = 1e300;
    for (int j = 0; j <= 32; ++j)
    {
      const double u = u0 + (1 - u0) * j / 32;
      const Vec3 c = o + R * s.center(u);
      const Vec2 r = s.radii(u);
      double rs = r.maxCoeff();
      for (const Vec2& d : dirs)
      {
        rs = std::max(rs, s.section ? s.section(u, d).norm() : 0.0);
      }
      for (size_t i = 0; i < body.p.size(); i += stride)
      {
        gap = std::min(gap, (body.p[i] - c).norm() - rs);
      }
    }
    if (gap > bestGap)
    {
      bestGap = gap;
      best = R;
    }
    const double c = cost && gap >= minGap ? cost(R) : 1e300;
    if (c < bestCost)
    {
      bestCost = c;
      cheapest = R;
    }
  }
  return bestCost < 1e300 ? cheapest : best;
}

// Welds tubes of growing length until the area fraction of faces with sym == which reaches target.
TriMesh WeldToFraction(const TriMesh& body,
  const Hole& hole,
  const std::function<TubeSpec(double)>& spec,
  const Vec3& o,
  const Eigen::Matrix3d& E,
  char tubeSym,
  int which,
  double target,
  double L0)
{
  auto make = [&](double L)
  {
    std::vector<Id> ring0;
    TriMesh tube = BuildTube(spec(L), o, E, tubeSym, ring0);
    return Weld(body, hole, tube, ring0);
  };
  auto frac = [&](const TriMesh& m) { return MeshArea(m, which) / MeshArea(m); };
  const double Lmin = spec(1).spacing;
  double La = std::max(Lmin, L0), Lb = 1.3 * La;
  TriMesh a = make(La), b = make(Lb);
  double fa = frac(a) - target, fb = frac(b) - target;
  for (int it = 0; it < 6 && std::abs(fb) > 0.005 && fb != fa; ++it)
  {
    const double Lc = std::clamp(Lb - fb * (Lb - La) / (fb - fa), Lmin, 60.0);
    La = Lb;
    fa = fb;
    a = std::move(b);
    Lb = Lc;
    b = make(Lb);
    fb = frac(b) - target;
  }
  return std::abs(fb) <= std::abs(fa) ? b : a;
}
} // namespace procedural
} // namespace testing
} // namespace foldingmeshes
