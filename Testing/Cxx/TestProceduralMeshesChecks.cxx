// Mesh checks of TestProceduralMeshes: topology, reflections, surface distances, CheckMesh.
#include "TestProceduralMeshesChecks.h"

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkStaticPointLocator.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <set>
#include <unordered_map>

namespace tpm
{
int failures = 0;
bool quiet = false;
std::string firstFailure;

// Triangles-only check + extraction.
bool Extract(const std::string& name, vtkPolyData* pd, Soup& s)
{
  bool ok = pd->GetNumberOfVerts() == 0 && pd->GetNumberOfLines() == 0 &&
    pd->GetNumberOfStrips() == 0 && pd->GetNumberOfPolys() == pd->GetNumberOfCells() &&
    pd->GetNumberOfCells() > 0;
  s.p.resize(size_t(pd->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    pd->GetPoint(i, s.p[size_t(i)].data());
  }
  s.t.clear();
  for (vtkIdType c = 0; ok && c < pd->GetNumberOfCells(); ++c)
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    pd->GetCellPoints(c, n, ids);
    ok = n == 3 && pd->GetCellType(c) == VTK_TRIANGLE;
    for (vtkIdType k = 0; ok && k < 3; ++k)
    {
      ok = ids[k] >= 0 && ids[k] < pd->GetNumberOfPoints() && ids[k] != ids[(k + 1) % 3];
    }
    s.t.push_back({ ids[0], ids[1], ids[2] });
  }
  EXPECT(ok, name << ": not made of valid triangles only");
  return ok;
}

// Closed, edge-manifold, consistently oriented (each directed edge once, its reverse once),
// vertex-manifold (one fan per vertex), no unused or duplicate points, no degenerate faces,
// positive signed volume per connected component.
TopoInfo CheckTopology(const std::string& name, vtkPolyData* pd, const Soup& s)
{
  TopoInfo info;
  const size_t np = s.p.size(), nt = s.t.size();
  std::vector<int> used(np, 0);
  for (const Tri& t : s.t)
  {
    for (vtkIdType v : t)
    {
      ++used[size_t(v)];
    }
  }
  EXPECT(std::count(used.begin(), used.end(), 0) == 0, name << ": unused points");
  double bb[6];
  pd->GetBounds(bb);
  const double diag = Vec3(bb[1] - bb[0], bb[3] - bb[2], bb[5] - bb[4]).norm();
  vtkNew<vtkStaticPointLocator> loc;
  loc->SetDataSet(pd);
  loc->BuildLocator();
  vtkNew<vtkIdList> ids;
  size_t dups = 0;
  for (size_t i = 0; i < np; ++i)
  {
    loc->FindClosestNPoints(2, s.p[i].data(), ids);
    const vtkIdType other = ids->GetId(0) == vtkIdType(i) ? ids->GetId(1) : ids->GetId(0);
    dups += (s.p[size_t(other)] - s.p[i]).norm() <= 1e-9 * diag;
  }
  EXPECT(dups == 0, name << ": " << dups << " duplicate points");
  std::unordered_map<uint64_t, int> half;
  half.reserve(3 * nt);
  auto key = [](vtkIdType a, vtkIdType b) { return (uint64_t(a) << 32) | uint64_t(b); };
  double minA = 1e300, sumA = 0;
  for (const Tri& t : s.t)
  {
    for (int e = 0; e < 3; ++e)
    {
      ++half[key(t[e], t[(e + 1) % 3])];
    }
    const double a = (s.p[t[1]] - s.p[t[0]]).cross(s.p[t[2]] - s.p[t[0]]).norm() / 2;
    minA = std::min(minA, a);
    sumA += a;
  }
  size_t multi = 0, boundary = 0;
  for (const auto& kv : half)
  {
    multi += kv.second != 1;
    auto tw = half.find((kv.first << 32) | (kv.first >> 32));
    boundary += tw == half.end();
    multi += tw != half.end() && tw->second != 1;
  }
  EXPECT(multi == 0, name << ": " << multi << " edges not used once in each direction");
  EXPECT(boundary == 0, name << ": " << boundary << " boundary edges (not closed)");
  info.minAreaRatio = minA / (sumA / double(nt));
  EXPECT(minA > 0, name << ": degenerate (zero-area) faces");
  // vertex-manifold: the link of every vertex is one cycle
  std::vector<size_t> start(np + 1, 0);
  for (const Tri& t : s.t)
  {
    for (vtkIdType v : t)
    {
      ++start[size_t(v) + 1];
    }
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::pair<vtkIdType, vtkIdType>> link(3 * nt);
  std::vector<size_t> fill(start.begin(), start.end() - 1);
  for (const Tri& t : s.t)
  {
    for (int e = 0; e < 3; ++e)
    {
      link[fill[size_t(t[e])]++] = { t[(e + 1) % 3], t[(e + 2) % 3] };
    }
  }
  size_t badFans = 0;
  for (size_t v = 0; v < np; ++v)
  {
    auto b = link.begin() + long(start[v]), e = link.begin() + long(start[v + 1]);
    std::sort(b, e);
    if (b == e)
    {
      continue;
    }
    size_t steps = 0;
    vtkIdType cur = b->first;
    do
    {
      auto it = std::lower_bound(b, e, std::make_pair(cur, vtkIdType(-1)));
      if (it == e || it->first != cur)
      {
        break;
      }
      cur = it->second;
      ++steps;
    } while (cur != b->first && steps <= size_t(e - b));
    badFans += !(cur == b->first && steps == size_t(e - b));
  }
  EXPECT(badFans == 0, name << ": " << badFans << " non-manifold vertices");
  // components and signed volumes
  std::vector<vtkIdType> parent(np);
  std::iota(parent.begin(), parent.end(), 0);
  std::function<vtkIdType(vtkIdType)> find = [&](vtkIdType x)
  {
    while (parent[size_t(x)] != x)
    {
      x = parent[size_t(x)] = parent[size_t(parent[size_t(x)])];
    }
    return x;
  };
  for (const Tri& t : s.t)
  {
    parent[size_t(find(t[1]))] = find(t[0]);
    parent[size_t(find(t[2]))] = find(t[0]);
  }
  std::unordered_map<vtkIdType, double> volume;
  for (const Tri& t : s.t)
  {
    volume[find(t[0])] += s.p[t[0]].dot(s.p[t[1]].cross(s.p[t[2]])) / 6;
  }
  info.components = int(volume.size());
  for (const auto& kv : volume)
  {
    EXPECT(kv.second > 0, name << ": a component has non-positive volume " << kv.second);
  }
  return info;
}

Vec3 Reflect(const Vec3& x, const KnownPlane& p)
{
  const Vec3 n = p.normal.normalized();
  return x - 2 * n.dot(x - p.origin) * n;
}

Reflection ReflectVertices(vtkPolyData* pd,
  const Soup& s,
  const KnownPlane& pl,
  const std::vector<char>* mask)
{
  Reflection r;
  const double diag = BoundsDiagonal(pd);
  vtkNew<vtkStaticPointLocator> loc;
  loc->SetDataSet(pd);
  loc->BuildLocator();
  std::vector<char> want(s.p.size(), mask == nullptr);
  for (size_t f = 0; mask && f < s.t.size(); ++f)
  {
    for (vtkIdType v : s.t[f])
    {
      want[size_t(v)] |= (*mask)[f];
    }
  }
  std::vector<vtkIdType> image(s.p.size(), -1);
  size_t n = 0, matched = 0;
  for (size_t i = 0; i < s.p.size(); ++i)
  {
    if (want[i])
    {
      const Vec3 q = Reflect(s.p[i], pl);
      image[i] = loc->FindClosestPoint(q.data());
      const double d = (s.p[size_t(image[i])] - q).norm() / diag;
      r.maxDist = std::max(r.maxDist, d);
      matched += d <= 1e-9;
      ++n;
    }
  }
  r.matchedFraction = n ? double(matched) / double(n) : 0;
  std::set<Tri> faces;
  for (Tri t : s.t)
  {
    std::sort(t.begin(), t.end());
    faces.insert(t);
  }
  for (size_t f = 0; f < s.t.size(); ++f)
  {
    if (!mask || (*mask)[f])
    {
      Tri t = { image[size_t(s.t[f][0])], image[size_t(s.t[f][1])], image[size_t(s.t[f][2])] };
      std::sort(t.begin(), t.end());
      r.unmatchedFaces += !faces.count(t);
    }
  }
  return r;
}

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection 5.1.5).
Vec3 ClosestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0)
    return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3)
    return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0)
    return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6)
    return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0)
    return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double den = 1 / (va + vb + vc);
  return a + ab * (vb * den) + ac * (vc * den);
}

// Brute force (with bounding-sphere rejection) distances from points to the surface.
std::vector<double> SurfaceDistances(const Soup& s, const std::vector<Vec3>& q)
{
  std::vector<Vec3> cen(s.t.size());
  std::vector<double> rad(s.t.size());
  for (size_t f = 0; f < s.t.size(); ++f)
  {
    cen[f] = (s.p[s.t[f][0]] + s.p[s.t[f][1]] + s.p[s.t[f][2]]) / 3;
    rad[f] = 0;
    for (vtkIdType v : s.t[f])
    {
      rad[f] = std::max(rad[f], (s.p[v] - cen[f]).norm());
    }
  }
  std::vector<double> d(q.size());
  for (size_t i = 0; i < q.size(); ++i)
  {
    double best = 1e300;
    for (size_t f = 0; f < s.t.size(); ++f)
    {
      if ((q[i] - cen[f]).norm() - rad[f] < best)
      {
        const Tri& t = s.t[f];
        best =
          std::min(best, (ClosestOnTriangle(q[i], s.p[t[0]], s.p[t[1]], s.p[t[2]]) - q[i]).norm());
      }
    }
    d[i] = best;
  }
  return d;
}

// RMS surface distance of the reflected vertices for the three principal planes through the
// area centroid, relative to the diagonal.
std::array<std::pair<Vec3, double>, 3> PrincipalPlaneResiduals(vtkPolyData* pd, const Soup& s)
{
  const Vec3 c = AreaCentroid(pd);
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for (const Vec3& p : s.p)
  {
    C += (p - c) * (p - c).transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
  std::array<std::pair<Vec3, double>, 3> out;
  for (int k = 0; k < 3; ++k)
  {
    const KnownPlane pl{ c, es.eigenvectors().col(k) };
    std::vector<Vec3> q;
    for (const Vec3& p : s.p)
    {
      q.push_back(Reflect(p, pl));
    }
    double ss = 0;
    for (double d : SurfaceDistances(s, q))
    {
      ss += d * d;
    }
    out[size_t(k)] = { pl.normal, std::sqrt(ss / double(q.size())) / BoundsDiagonal(pd) };
  }
  return out;
}

// Full check of one mesh; returns its reflection error (max over planes).
double CheckMesh(const Gen& g,
  const ProceduralMesh& m,
  const std::string& name,
  int approxFaces,
  double seconds)
{
  Soup s;
  if (!Extract(name, m.mesh, s))
  {
    return 1;
  }
  const TopoInfo info = CheckTopology(name, m.mesh, s);
  EXPECT(info.components == g.components,
    name << ": " << info.components << " components, expected " << g.components);
  if (approxFaces > 0)
  {
    const double ratio = double(s.t.size()) / approxFaces;
    EXPECT(ratio > 0.5 && ratio < 2, name << ": " << s.t.size() << " faces for " << approxFaces);
  }
  EXPECT(m.symmetricFace.size() == s.t.size(), name << ": symmetricFace size");
  for (const KnownPlane& pl : m.planes)
  {
    EXPECT(std::abs(pl.normal.norm() - 1) < 1e-12, name << ": plane normal not unit");
  }
  const bool masked = std::count(m.symmetricFace.begin(), m.symmetricFace.end(), 0) > 0;
  double worst = 0;
  for (size_t k = 0; g.exactVertices && k < m.planes.size(); ++k)
  {
    const Reflection r =
      ReflectVertices(m.mesh, s, m.planes[k], masked ? &m.symmetricFace : nullptr);
    worst = std::max(worst, r.maxDist);
    EXPECT(r.maxDist <= 1e-9,
      name << ": plane " << k << " maps a vertex " << r.maxDist << " diagonals off a vertex");
    EXPECT(!g.exactTriangles || r.unmatchedFaces == 0,
      name << ": plane " << k << ": " << r.unmatchedFaces << " faces do not map onto faces");
  }
  char refl[32] = "-", gen[32] = "";
  if (g.exactVertices && !m.planes.empty())
  {
    std::snprintf(refl, sizeof(refl), "%.1e", worst);
  }
  if (seconds >= 0)
  {
    std::snprintf(gen, sizeof(gen), "  (%.3f s)", seconds);
  }
  if (!quiet)
  {
    std::printf("  %-44s %7zu faces %7zu pts %d comp min/mean area %.3f refl err %s%s\n",
      name.c_str(),
      s.t.size(),
      s.p.size(),
      info.components,
      info.minAreaRatio,
      refl,
      gen);
  }
  return worst;
}

vtkSmartPointer<vtkPolyData> FromSoup(const Soup& s)
{
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (const Vec3& p : s.p)
  {
    pts->InsertNextPoint(p.data());
  }
  vtkNew<vtkCellArray> cells;
  for (const Tri& t : s.t)
  {
    cells->InsertNextCell(3, t.data());
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(pts);
  pd->SetPolys(cells);
  return pd;
}

// Runs the checks on a deliberately broken copy of m; they must report a failure.
void ExpectCaught(const Gen& g,
  const ProceduralMesh& m,
  const std::string& what,
  const std::function<void(Soup&)>& breakIt)
{
  Soup s;
  Extract(what, m.mesh, s);
  breakIt(s);
  ProceduralMesh b = m;
  b.mesh = FromSoup(s);
  b.symmetricFace.resize(s.t.size(), 1);
  const int before = failures;
  quiet = true;
  firstFailure.clear();
  CheckMesh(g, b, what, 0);
  quiet = false;
  const bool caught = failures > before;
  failures = before;
  std::printf("  %-38s %s\n", what.c_str(), caught ? firstFailure.c_str() : "MISSED");
  EXPECT(caught, "the checks missed: " << what);
}

bool SamePoints(vtkPolyData* a, vtkPolyData* b)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints() ||
    a->GetNumberOfCells() != b->GetNumberOfCells())
  {
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    if (p[0] != q[0] || p[1] != q[1] || p[2] != q[2])
    {
      return false;
    }
  }
  for (vtkIdType c = 0; c < a->GetNumberOfCells(); ++c)
  {
    vtkIdType n1, n2;
    const vtkIdType *i1, *i2;
    a->GetCellPoints(c, n1, i1);
    b->GetCellPoints(c, n2, i2);
    if (n1 != n2 || !std::equal(i1, i1 + n1, i2))
    {
      return false;
    }
  }
  return true;
}
} // namespace tpm
