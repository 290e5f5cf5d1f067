// Checks that the procedural test meshes are what ProceduralMeshes.h promises: triangles only, no
// duplicate points, closed, edge- and vertex-manifold, consistently and outwardly oriented, face
// counts near the request, exact mirror planes (also after a rigid motion and a scaling), the
// surface-only symmetry of the differently tessellated blob, area fractions, components,
// determinism, and that the ground truth is unambiguous for the detector at its default
// tolerance (2% of the diagonal): no other plane gives a comparable symmetric region.
// Prints one line per mesh; returns nonzero with a message per failed check.
//
// The symmetric regions are measured with FoldingMeshesCore (PrepareMesh, MirrorDistance,
// LargestConnectedRegion) when that library is linked to this test, else with an equivalent
// implementation of the same rule in this file.
#include "ProceduralMeshes.h"

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkStaticPointLocator.h>

#include <Eigen/Eigenvalues>

// The core's headers are visible only when FoldingMeshesCore is linked to this test.
#if defined(__has_include)
#if __has_include("MeshPreparation.h") &&                                                          \
  __has_include("MirrorDistance.h") && __has_include("RegionGrowing.h")
#include "MeshPreparation.h"
#include "MirrorDistance.h"
#include "RegionGrowing.h"
#define FOLDINGMESHES_TEST_HAS_CORE 1
#endif
#endif
#ifndef FOLDINGMESHES_TEST_HAS_CORE
#define FOLDINGMESHES_TEST_HAS_CORE 0
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <numeric>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

using namespace foldingmeshes::testing;
using Vec3 = Eigen::Vector3d;
using Tri = std::array<vtkIdType, 3>;

namespace
{
int failures = 0;
bool quiet = false;       // while checking that the checks catch broken meshes
std::string firstFailure; // ... the first message then

#define EXPECT(cond, msg)                                                                          \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
    {                                                                                              \
      std::ostringstream os_;                                                                      \
      os_ << msg;                                                                                  \
      if (!quiet)                                                                                  \
        std::printf("FAIL: %s\n", os_.str().c_str());                                              \
      else if (firstFailure.empty())                                                               \
        firstFailure = os_.str();                                                                  \
      ++failures;                                                                                  \
    }                                                                                              \
  } while (0)

double Seconds(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Soup
{
  std::vector<Vec3> p;
  std::vector<Tri> t;
};

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

struct TopoInfo
{
  int components = 0;
  double minAreaRatio = 0; // smallest face area / mean face area
};

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

// Max distance (relative to the diagonal) from each reflected vertex of the masked faces to the
// nearest vertex; counts the masked faces whose reflection is not a face; fraction of vertices
// whose reflection is within tol of a vertex.
struct Reflection
{
  double maxDist = 0;
  size_t unmatchedFaces = 0;
  double matchedFraction = 0;
};
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

// ---- what the detector sees: the region of a plane at epsilon = 2% of the diagonal ----
// RegionFraction(plane) = area fraction of the largest edge-connected set of faces whose three
// vertices, reflected through the plane together with their normals, lie closer than epsilon to
// a face whose normal (interpolated from the vertex normals at the closest point) is within 45
// degrees of the reflected normal: the detector's fine metric and region rule. With
// FoldingMeshesCore linked (its headers visible) the core computes it; otherwise an equivalent
// implementation here does (same rule; a uniform grid replaces the core's face tree).
class RegionMeasure
{
public:
  explicit RegionMeasure(vtkPolyData* pd)
  {
#if FOLDINGMESHES_TEST_HAS_CORE
    foldingmeshes::TriangleMesh soup;
    for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
    {
      Vec3 p;
      pd->GetPoint(i, p.data());
      soup.points.push_back(p);
    }
    for (vtkIdType c = 0; c < pd->GetNumberOfCells(); ++c)
    {
      vtkIdType n = 0;
      const vtkIdType* ids = nullptr;
      pd->GetCellPoints(c, n, ids);
      soup.triangles.push_back({ int(ids[0]), int(ids[1]), int(ids[2]) });
    }
    std::string error;
    foldingmeshes::PrepareMesh(soup, {}, this->Mesh, error);
    this->Distance.reset(new foldingmeshes::MirrorDistance(this->Mesh, 45.0));
    this->P = this->Mesh.points;
    for (const auto& t : this->Mesh.triangles)
    {
      this->T.push_back({ t[0], t[1], t[2] });
    }
#else
    Soup s;
    Extract("RegionMeasure", pd, s);
    this->P = s.p;
    this->T = s.t;
#endif
    const size_t nf = this->T.size();
    this->Area.resize(nf);
    this->FaceN.resize(nf);
    this->VertexN.assign(this->P.size(), Vec3::Zero());
    for (size_t f = 0; f < nf; ++f)
    {
      const Tri& t = this->T[f];
      const Vec3 w = (this->P[t[1]] - this->P[t[0]]).cross(this->P[t[2]] - this->P[t[0]]);
      this->Area[f] = 0.5 * w.norm();
      this->FaceN[f] = w.normalized();
      for (vtkIdType v : t)
      {
        this->VertexN[size_t(v)] += w;
      }
    }
    for (Vec3& n : this->VertexN)
    {
      n.normalize();
    }
    this->TotalArea = std::accumulate(this->Area.begin(), this->Area.end(), 0.0);
    this->Epsilon = 0.02 * BoundsDiagonal(pd);
#if !FOLDINGMESHES_TEST_HAS_CORE
    std::unordered_map<uint64_t, size_t> half; // directed edge -> face
    for (size_t f = 0; f < nf; ++f)
    {
      for (int e = 0; e < 3; ++e)
      {
        half[(uint64_t(this->T[f][e]) << 32) | uint64_t(this->T[f][(e + 1) % 3])] = f;
      }
    }
    this->Neighbors.resize(nf);
    for (size_t f = 0; f < nf; ++f)
    {
      for (int e = 0; e < 3; ++e)
      {
        auto it = half.find((uint64_t(this->T[f][(e + 1) % 3]) << 32) | uint64_t(this->T[f][e]));
        if (it != half.end())
        {
          this->Neighbors[f].push_back(it->second);
        }
      }
    }
    Vec3 lo = this->P[0], hi = this->P[0];
    for (const Vec3& p : this->P)
    {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    this->Lo = lo;
    for (int k = 0; k < 3; ++k)
    {
      this->Dims[k] = std::max(1, int(std::ceil((hi[k] - lo[k]) / this->Epsilon)));
    }
    this->Cells.resize(size_t(this->Dims[0]) * this->Dims[1] * this->Dims[2]);
    for (size_t f = 0; f < nf; ++f)
    {
      const Tri& t = this->T[f];
      const Vec3 a = this->P[t[0]].cwiseMin(this->P[t[1]]).cwiseMin(this->P[t[2]]);
      const Vec3 b = this->P[t[0]].cwiseMax(this->P[t[1]]).cwiseMax(this->P[t[2]]);
      const std::array<int, 3> i0 = this->Cell(a), i1 = this->Cell(b);
      for (int i = i0[0]; i <= i1[0]; ++i)
        for (int j = i0[1]; j <= i1[1]; ++j)
          for (int k = i0[2]; k <= i1[2]; ++k)
            this->Cells[this->Index(i, j, k)].push_back(f);
    }
#endif
  }

  double Eps() const
  {
    return this->Epsilon;
  }

  double Fraction(const KnownPlane& plane) const
  {
    const Vec3 n = plane.normal.normalized();
#if FOLDINGMESHES_TEST_HAS_CORE
    std::vector<double> d;
    this->Distance->Compute(foldingmeshes::Plane{ plane.origin, n },
      foldingmeshes::DistanceMetric::Fine,
      3 * this->Epsilon,
      d);
    const std::vector<char> region = foldingmeshes::LargestConnectedRegion(
      this->Mesh, foldingmeshes::FacesWithVerticesWithin(this->Mesh, d, this->Epsilon, true));
    return foldingmeshes::RegionArea(this->Mesh, region) / this->Mesh.totalArea;
#else
    std::vector<char> near(this->P.size(), 0);
    const double cosLimit = std::cos(45.0 * 3.14159265358979323846 / 180);
    std::vector<int> stamp(this->T.size(), -1);
    for (size_t v = 0; v < this->P.size(); ++v)
    {
      const Vec3 r = this->P[v] - 2 * n.dot(this->P[v] - plane.origin) * n;
      const Vec3 rn = this->VertexN[v] - 2 * n.dot(this->VertexN[v]) * n;
      const std::array<int, 3> i0 = this->Cell(r - Vec3::Constant(this->Epsilon));
      const std::array<int, 3> i1 = this->Cell(r + Vec3::Constant(this->Epsilon));
      for (int i = i0[0]; i <= i1[0] && !near[v]; ++i)
        for (int j = i0[1]; j <= i1[1] && !near[v]; ++j)
          for (int k = i0[2]; k <= i1[2] && !near[v]; ++k)
            for (size_t f : this->Cells[this->Index(i, j, k)])
            {
              if (stamp[f] == int(v))
              {
                continue;
              }
              stamp[f] = int(v);
              const Tri& t = this->T[f];
              const Vec3 q = ClosestOnTriangle(r, this->P[t[0]], this->P[t[1]], this->P[t[2]]);
              if ((q - r).norm() < this->Epsilon &&
                this->InterpolatedNormal(f, q).dot(rn) >= cosLimit)
              {
                near[v] = 1;
                break;
              }
            }
    }
    // largest edge-connected region of the faces with three near vertices
    std::vector<int> label(this->T.size(), -1);
    double best = 0;
    for (size_t f0 = 0; f0 < this->T.size(); ++f0)
    {
      if (label[f0] >= 0 || !this->AllNear(f0, near))
      {
        continue;
      }
      double area = 0;
      std::vector<size_t> stack{ f0 };
      label[f0] = int(f0);
      while (!stack.empty())
      {
        const size_t f = stack.back();
        stack.pop_back();
        area += this->Area[f];
        for (size_t g : this->Neighbors[f])
        {
          if (label[g] < 0 && this->AllNear(g, near))
          {
            label[g] = int(f0);
            stack.push_back(g);
          }
        }
      }
      best = std::max(best, area);
    }
    return best / this->TotalArea;
#endif
  }

  // area-weighted centroid of the faces with mask[f] (all faces if mask is empty)
  Vec3 Centroid(const std::vector<char>& mask = {}) const
  {
    Vec3 c = Vec3::Zero();
    double w = 0;
    for (size_t f = 0; f < this->T.size(); ++f)
    {
      if (mask.empty() || mask[f])
      {
        c += this->Area[f] *
          (this->P[this->T[f][0]] + this->P[this->T[f][1]] + this->P[this->T[f][2]]) / 3;
        w += this->Area[f];
      }
    }
    return c / w;
  }

  // normals of the principal planes of the area-weighted covariance of the surface
  std::array<Vec3, 3> PrincipalNormals() const
  {
    const Vec3 mu = this->Centroid();
    Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
    for (size_t f = 0; f < this->T.size(); ++f)
    {
      const Vec3 a = this->P[this->T[f][0]] - mu, b = this->P[this->T[f][1]] - mu,
                 c = this->P[this->T[f][2]] - mu, m = (a + b + c) / 3;
      // exact second moment of the triangle: A / 12 (9 m m^T + a a^T + b b^T + c c^T)
      C += this->Area[f] / 12 *
        (9 * m * m.transpose() + a * a.transpose() + b * b.transpose() + c * c.transpose());
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
    return { es.eigenvectors().col(0), es.eigenvectors().col(1), es.eigenvectors().col(2) };
  }

private:
#if !FOLDINGMESHES_TEST_HAS_CORE
  std::array<int, 3> Cell(const Vec3& x) const
  {
    std::array<int, 3> c;
    for (int k = 0; k < 3; ++k)
    {
      c[size_t(k)] =
        std::clamp(int(std::floor((x[k] - this->Lo[k]) / this->Epsilon)), 0, this->Dims[k] - 1);
    }
    return c;
  }
  size_t Index(int i, int j, int k) const
  {
    return (size_t(i) * this->Dims[1] + j) * this->Dims[2] + k;
  }
  bool AllNear(size_t f, const std::vector<char>& near) const
  {
    return near[this->T[f][0]] && near[this->T[f][1]] && near[this->T[f][2]];
  }
  // barycentric interpolation of the vertex normals at the point q of face f (unit)
  Vec3 InterpolatedNormal(size_t f, const Vec3& q) const
  {
    const Vec3 &a = this->P[this->T[f][0]], &b = this->P[this->T[f][1]],
               &c = this->P[this->T[f][2]];
    const Vec3 w = (b - a).cross(c - a);
    const double ww = w.squaredNorm();
    const double la = (c - b).cross(q - b).dot(w) / ww, lb = (a - c).cross(q - c).dot(w) / ww;
    const Vec3 n = la * this->VertexN[this->T[f][0]] + lb * this->VertexN[this->T[f][1]] +
      (1 - la - lb) * this->VertexN[this->T[f][2]];
    return n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero();
  }
  std::vector<std::vector<size_t>> Neighbors;
  std::vector<std::vector<size_t>> Cells;
  Vec3 Lo = Vec3::Zero();
  int Dims[3] = { 1, 1, 1 };
#else
  foldingmeshes::PreparedMesh Mesh;
  std::unique_ptr<foldingmeshes::MirrorDistance> Distance;
#endif
  std::vector<Vec3> P, FaceN, VertexN;
  std::vector<Tri> T;
  std::vector<double> Area;
  double TotalArea = 0, Epsilon = 0;
};

// Deterministic random unit vectors (own Box-Muller: std distributions are implementation-defined).
Vec3 RandomNormal(std::mt19937& g)
{
  auto u = [&] { return (double(g()) + 0.5) / 4294967296.0; };
  Vec3 n;
  for (int k = 0; k < 3; ++k)
  {
    n[k] = std::sqrt(-2 * std::log(u())) * std::cos(2 * 3.14159265358979323846 * u());
  }
  return n.normalized();
}

struct Competition
{
  double truth = -1;    // RegionFraction of the true plane (-1: none)
  double principal = 0; // best principal plane other than the true one
  double random = 0;    // best random plane (through the centroids given)
  double refined = 0;   // best after refining the best random planes (if asked)
  int skipped = 0;      // random planes within `exclude` degrees of the true plane
  double Best() const { return std::max({ principal, random, refined }); }
};

// RegionFraction of the true plane (if any), of the principal planes through the area centroid
// and of `count` random planes through each of `centers`, skipping planes within `exclude`
// degrees of the true plane (they are the true plane's own basin: the region shrinks
// continuously as the plane turns away from it); with `refine`, the 5 best random planes are
// improved by a random local search (tilts and shifts, halved when stuck), never entering the
// excluded cone either.
Competition Compete(const ProceduralMesh& m,
  const RegionMeasure& rm,
  const std::vector<Vec3>& centers,
  int count,
  double exclude,
  unsigned seed,
  bool refine)
{
  Competition c;
  const bool hasTruth = !m.planes.empty();
  if (hasTruth)
  {
    c.truth = rm.Fraction(m.planes[0]);
  }
  auto isOther = [&](const Vec3& n)
  { return !hasTruth || PlaneAngleDegrees(n, m.planes[0].normal) > exclude; };
  const Vec3 centroid = rm.Centroid();
  for (const Vec3& n : rm.PrincipalNormals())
  {
    if (isOther(n))
    {
      c.principal = std::max(c.principal, rm.Fraction({ centroid, n }));
    }
  }
  std::mt19937 g(seed);
  std::vector<std::pair<double, KnownPlane>> tried;
  for (const Vec3& o : centers)
  {
    for (int k = 0; k < count; ++k)
    {
      const Vec3 n = RandomNormal(g);
      if (!isOther(n))
      {
        ++c.skipped;
        continue;
      }
      const KnownPlane p{ o, n };
      tried.push_back({ rm.Fraction(p), p });
      c.random = std::max(c.random, tried.back().first);
    }
  }
  if (refine)
  {
    std::sort(
      tried.begin(), tried.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    for (size_t k = 0; k < std::min<size_t>(5, tried.size()); ++k)
    {
      KnownPlane p = tried[k].second;
      double r = tried[k].first, tilt = 0.08, shift = rm.Eps();
      for (int it = 0; it < 48; ++it)
      {
        KnownPlane q = p;
        q.normal = (p.normal + tilt * RandomNormal(g)).normalized();
        q.origin = p.origin + shift * (2 * (double(g()) / 4294967296.0) - 1) * q.normal;
        const double rq = isOther(q.normal) ? rm.Fraction(q) : 0.0;
        if (rq > r)
        {
          r = rq;
          p = q;
        }
        else if (it % 12 == 11)
        {
          tilt *= 0.5;
          shift *= 0.5;
        }
      }
      c.refined = std::max(c.refined, r);
    }
  }
  return c;
}

struct Gen
{
  std::string name;
  std::function<ProceduralMesh(int)> make;
  bool exactVertices;  // every listed plane maps the (masked) vertex set onto itself
  bool exactTriangles; // ... and the masked triangles onto triangles
  int components;
};

// Full check of one mesh; returns its reflection error (max over planes).
double CheckMesh(const Gen& g,
  const ProceduralMesh& m,
  const std::string& name,
  int approxFaces,
  double seconds = -1)
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
} // namespace

int main()
{
  const auto start = std::chrono::steady_clock::now();
  auto section = [&](const char* title) { std::printf("[%.1f s] %s\n", Seconds(start), title); };
  const std::vector<Gen> gens = {
    { "BilateralBlob", [](int f) { return MakeBilateralBlob(f); }, true, true, 1 },
    { "BilateralBlobDifferentTessellation",
      [](int f) { return MakeBilateralBlobDifferentTessellation(f); },
      false,
      false,
      1 },
    { "ThreePlaneShape", [](int f) { return MakeThreePlaneShape(f); }, true, true, 1 },
    { "BlobWithAsymmetricPart(0.25)",
      [](int f) { return MakeBlobWithAsymmetricPart(f, 0.25); },
      true,
      true,
      1 },
    { "AsymmetricBodyWithSymmetricPart(0.2)",
      [](int f) { return MakeAsymmetricBodyWithSymmetricPart(f, 0.2); },
      true,
      true,
      1 },
    { "AsymmetricBlob", [](int f) { return MakeAsymmetricBlob(f); }, false, false, 1 },
    { "Sphere", [](int f) { return MakeSphere(f); }, true, true, 1 },
    { "Cylinder", [](int f) { return MakeCylinder(f); }, true, false, 1 },
    { "MultiPartSymmetric", [](int f) { return MakeMultiPartSymmetric(f); }, true, true, 3 },
  };

  section("the checks catch broken meshes");
  {
    const Gen& g = gens[0];
    const ProceduralMesh m = MakeBilateralBlob(500);
    ExpectCaught(g, m, "one flipped triangle", [](Soup& s) { std::swap(s.t[7][0], s.t[7][1]); });
    ExpectCaught(g,
      m,
      "all triangles flipped (inward)",
      [](Soup& s)
      {
        for (Tri& t : s.t)
          std::swap(t[0], t[1]);
      });
    ExpectCaught(g, m, "one triangle removed (hole)", [](Soup& s) { s.t.pop_back(); });
    ExpectCaught(g, m, "one triangle doubled", [](Soup& s) { s.t.push_back(s.t[3]); });
    ExpectCaught(g,
      m,
      "a duplicated point",
      [](Soup& s)
      {
        s.p.push_back(s.p[s.t[5][0]]);
        s.t[5][0] = vtkIdType(s.p.size() - 1);
      });
    ExpectCaught(g, m, "an unused point", [](Soup& s) { s.p.push_back(Vec3(9, 9, 9)); });
    ExpectCaught(g, m, "a vertex moved by 1e-7", [](Soup& s) { s.p[s.t[0][0]].y() += 1e-7; });
    ExpectCaught(g,
      m,
      "two spheres sharing a vertex (pinch)",
      [](Soup& s)
      {
        Soup o = s;
        const vtkIdType off = vtkIdType(s.p.size());
        vtkIdType pin = 0; // the vertex of largest x: the mirrored copy touches only there
        for (size_t i = 0; i < s.p.size(); ++i)
          pin = s.p[i].x() > s.p[size_t(pin)].x() ? vtkIdType(i) : pin;
        const Vec3 shift = s.p[pin] - Vec3(-s.p[pin].x(), s.p[pin].y(), s.p[pin].z());
        for (Vec3& p : o.p)
          s.p.push_back(Vec3(-p.x(), p.y(), p.z()) + shift);
        for (Tri t : o.t)
        {
          for (vtkIdType& v : t)
            v = v == pin ? pin : v + off;
          s.t.push_back({ t[1], t[0], t[2] });
        }
        s.p[size_t(pin + off)] = s.p.back(); // no unused point: the last one fills the pin's slot
        s.p.pop_back();
        for (Tri& t : s.t)
          for (vtkIdType& v : t)
            v = v == vtkIdType(s.p.size()) ? pin + off : v;
      });
  }

  section("generators at 500, 2000, 200000 faces");
  for (const Gen& g : gens)
  {
    for (int F : { 500, 2000, 200000 })
    {
      const auto t0 = std::chrono::steady_clock::now();
      const ProceduralMesh m = g.make(F);
      CheckMesh(g, m, g.name + "@" + std::to_string(F), F, Seconds(t0));
    }
  }

  section("exact planes after RandomRigidMotion + ScaleUniformly(2.5)");
  for (const Gen& g : gens)
  {
    ProceduralMesh m = g.make(2000);
    ApplyRigidMotion(m, RandomRigidMotion(3));
    ScaleUniformly(m, 2.5);
    CheckMesh(g, m, g.name + " moved", 0);
    for (size_t k = 0; k < m.planes.size(); ++k)
    {
      const PlaneMatch pm = BestPlaneMatch(m, m.planes[k].origin, m.planes[k].normal);
      EXPECT(pm.angleDegrees < 1e-9 && pm.offsetError < 1e-12,
        g.name << " moved: BestPlaneMatch of plane " << k << " gives " << pm.angleDegrees
               << " deg, " << pm.offsetError);
    }
  }

  section("different tessellation: symmetric surface, not vertex set");
  {
    const ProceduralMesh m = MakeBilateralBlobDifferentTessellation(20000);
    Soup s;
    Extract("DifferentTessellation", m.mesh, s);
    const Reflection r = ReflectVertices(m.mesh, s, m.planes[0], nullptr);
    std::vector<Vec3> q;
    for (const Vec3& p : s.p)
    {
      q.push_back(Reflect(p, m.planes[0]));
    }
    const std::vector<double> d = SurfaceDistances(s, q);
    const double diag = BoundsDiagonal(m.mesh);
    const double maxd = *std::max_element(d.begin(), d.end()) / diag;
    std::printf("  %zu faces: %.1f%% of reflected vertices on a vertex, max surface distance "
                "%.2e diag\n",
      s.t.size(),
      100 * r.matchedFraction,
      maxd);
    EXPECT(r.matchedFraction < 0.2, "DifferentTessellation: the vertex set is symmetric");
    EXPECT(maxd < 1e-3, "DifferentTessellation: reflected vertex " << maxd << " diag off surface");
  }

  section("no other symmetry (RMS reflected-vertex distance, principal planes)");
  for (const auto& named : { std::make_pair(std::string("BilateralBlob"), MakeBilateralBlob(2000)),
         std::make_pair(std::string("AsymmetricBlob"), MakeAsymmetricBlob(2000)),
         std::make_pair(std::string("AsymmetricBlob seed 2"), MakeAsymmetricBlob(2000, 2)) })
  {
    Soup s;
    Extract(named.first, named.second.mesh, s);
    for (const auto& res : PrincipalPlaneResiduals(named.second.mesh, s))
    {
      const bool isTrue = !named.second.planes.empty() &&
        PlaneAngleDegrees(res.first, named.second.planes[0].normal) < 5;
      std::printf("  %-22s normal (%6.3f %6.3f %6.3f): RMS %.4f%s\n",
        named.first.c_str(),
        res.first.x(),
        res.first.y(),
        res.first.z(),
        res.second,
        isTrue ? " (true plane)" : "");
      EXPECT(isTrue ? res.second < 2e-3 : res.second > 1e-2,
        named.first << ": principal plane residual " << res.second);
    }
  }

  section("unambiguous ground truth at epsilon = 2% of the diagonal (RegionFraction)");
  std::printf("  measured with %s\n",
    FOLDINGMESHES_TEST_HAS_CORE
      ? "FoldingMeshesCore (PrepareMesh, MirrorDistance fine, LargestConnectedRegion)"
      : "this test's implementation of the detector's fine metric (FoldingMeshesCore not linked)");
  {
    auto report = [](const std::string& name, const Competition& c)
    {
      char truth[16] = "    -";
      if (c.truth >= 0)
      {
        std::snprintf(truth, sizeof(truth), "%6.3f", c.truth);
      }
      std::printf("  %-36s true %s  other principal %.3f  random %.3f",
        name.c_str(),
        truth,
        c.principal,
        c.random);
      if (c.refined > 0)
      {
        std::printf("  refined %.3f", c.refined);
      }
      std::printf("  (%d near the true plane skipped)\n", c.skipped);
    };
    // Bilateral creatures: the true plane keeps everything, the two other principal planes and
    // 200 random planes through the centroid at least 20 degrees away keep less than half.
    const std::vector<std::pair<std::string, ProceduralMesh>> bilateral = {
      { "BilateralBlob", MakeBilateralBlob(4000) },
      { "BilateralBlob seed 3", MakeBilateralBlob(4000, 3) },
      { "DifferentTessellation", MakeBilateralBlobDifferentTessellation(4000) },
      { "DifferentTessellation seed 7", MakeBilateralBlobDifferentTessellation(4000, 7) },
    };
    for (const auto& named : bilateral)
    {
      const RegionMeasure rm(named.second.mesh);
      const Competition c = Compete(named.second, rm, { rm.Centroid() }, 200, 20, 11, false);
      report(named.first, c);
      EXPECT(c.truth > 0.97, named.first << ": true plane keeps only " << c.truth);
      EXPECT(c.principal < 0.5, named.first << ": another principal plane keeps " << c.principal);
      EXPECT(c.random < 0.5, named.first << ": a random plane keeps " << c.random);
    }
    // Asymmetric blobs: no plane keeps 40% (principal planes, 500 random planes through the
    // centroid and a local refinement of the 5 best).
    for (unsigned seed : { 1u, 13u })
    {
      const ProceduralMesh m = MakeAsymmetricBlob(4000, seed);
      const RegionMeasure rm(m.mesh);
      const Competition c = Compete(m, rm, { rm.Centroid() }, 500, 0, seed, true);
      const std::string name = "AsymmetricBlob seed " + std::to_string(seed);
      report(name, c);
      EXPECT(c.Best() < 0.4, name << ": a plane keeps " << c.Best());
    }
    // Creature with a horn: the true plane keeps the body (all but the attachment, give or take
    // 5%), and every other plane keeps less: principal planes, 200 random planes through the
    // centroid and 200 through the body's centroid, at least 10 degrees from the true plane.
    for (double a : { 0.3, 0.5 })
    {
      const ProceduralMesh m = MakeBlobWithAsymmetricPart(4000, a);
      const RegionMeasure rm(m.mesh);
      const Competition c =
        Compete(m, rm, { rm.Centroid(), rm.Centroid(m.symmetricFace) }, 200, 10, 12, false);
      const std::string name = "BlobWithAsymmetricPart(" + std::to_string(a).substr(0, 3) + ")";
      report(name, c);
      EXPECT(c.truth > 1 - a - 0.05, name << ": true plane keeps only " << c.truth);
      EXPECT(c.Best() < c.truth, name << ": another plane keeps " << c.Best() << " >= " << c.truth);
    }
    // Lumpy body with a symmetric head: the true plane keeps most of the head, every other plane
    // (principal, 200 random through the centroid, 200 through the head's centroid, at least 10
    // degrees away) keeps less.
    for (double f : { 0.2, 0.3 })
    {
      const ProceduralMesh m = MakeAsymmetricBodyWithSymmetricPart(4000, f);
      const RegionMeasure rm(m.mesh);
      const Competition c =
        Compete(m, rm, { rm.Centroid(), rm.Centroid(m.symmetricFace) }, 200, 10, 13, false);
      const std::string name =
        "AsymmetricBodyWithSymmetricPart(" + std::to_string(f).substr(0, 3) + ")";
      report(name, c);
      EXPECT(c.truth > 0.8 * f, name << ": true plane keeps only " << c.truth);
      EXPECT(c.Best() < c.truth, name << ": another plane keeps " << c.Best() << " >= " << c.truth);
    }
  }

  section("area fractions");
  for (int F : { 2000, 200000 })
  {
    for (double f : { 0.1, 0.25, 0.4, 0.6 })
    {
      const ProceduralMesh a = MakeBlobWithAsymmetricPart(F, f);
      std::vector<char> notSym(a.symmetricFace.size());
      for (size_t i = 0; i < notSym.size(); ++i)
      {
        notSym[i] = !a.symmetricFace[i];
      }
      const double fa = MaskAreaFraction(a.mesh, notSym);
      const ProceduralMesh b = MakeAsymmetricBodyWithSymmetricPart(F, f);
      const double fb = MaskAreaFraction(b.mesh, b.symmetricFace);
      std::printf("  F=%6d request %.2f: asymmetric attachment %.3f (%lld faces), symmetric part "
                  "%.3f (%lld faces)\n",
        F,
        f,
        fa,
        (long long)a.mesh->GetNumberOfCells(),
        fb,
        (long long)b.mesh->GetNumberOfCells());
      EXPECT(std::abs(fa - f) <= 0.1, "BlobWithAsymmetricPart(" << F << ", " << f << "): " << fa);
      EXPECT(std::abs(fb - f) <= 0.1,
        "AsymmetricBodyWithSymmetricPart(" << F << ", " << f << "): " << fb);
      Gen ga = gens[3], gb = gens[4];
      CheckMesh(ga, a, "  attachment " + std::to_string(f), F);
      CheckMesh(gb, b, "  symmetric part " + std::to_string(f), F);
    }
  }

  section("determinism");
  {
    const std::vector<std::function<ProceduralMesh(unsigned)>> seeded = {
      [](unsigned s) { return MakeBilateralBlob(3000, s); },
      [](unsigned s) { return MakeBilateralBlobDifferentTessellation(3000, s); },
      [](unsigned s) { return MakeBlobWithAsymmetricPart(3000, 0.3, s); },
      [](unsigned s) { return MakeAsymmetricBodyWithSymmetricPart(3000, 0.3, s); },
      [](unsigned s) { return MakeAsymmetricBlob(3000, s); },
    };
    for (size_t k = 0; k < seeded.size(); ++k)
    {
      EXPECT(SamePoints(seeded[k](5).mesh, seeded[k](5).mesh),
        "generator " << k << " not deterministic");
      EXPECT(
        !SamePoints(seeded[k](5).mesh, seeded[k](6).mesh), "generator " << k << " ignores seed");
    }
    for (const Gen& g : gens)
    {
      EXPECT(SamePoints(g.make(1000).mesh, g.make(1000).mesh), g.name << " not deterministic");
    }
    EXPECT(
      RandomRigidMotion(9).matrix() == RandomRigidMotion(9).matrix(), "motion not deterministic");
    ProceduralMesh a = MakeSphere(2000), b = MakeSphere(2000);
    AddGaussianNoise(a, 0.01, 4);
    AddGaussianNoise(b, 0.01, 4);
    EXPECT(SamePoints(a.mesh, b.mesh), "noise not deterministic");
  }

  section("transformations and measures");
  {
    const Eigen::Isometry3d T = RandomRigidMotion(11);
    EXPECT(std::abs(T.linear().determinant() - 1) < 1e-12 &&
        (T.linear().transpose() * T.linear() - Eigen::Matrix3d::Identity()).norm() < 1e-12 &&
        T.translation().cwiseAbs().maxCoeff() <= 5,
      "RandomRigidMotion is not a rotation + translation in [-5,5]^3");
    ProceduralMesh clean = MakeSphere(20000), noisy = MakeSphere(20000);
    AddGaussianNoise(noisy, 0.01, 1);
    double ss = 0;
    for (vtkIdType i = 0; i < clean.mesh->GetNumberOfPoints(); ++i)
    {
      Vec3 p, q;
      clean.mesh->GetPoint(i, p.data());
      noisy.mesh->GetPoint(i, q.data());
      ss += (q - p).squaredNorm();
    }
    const double rms = std::sqrt(ss / double(clean.mesh->GetNumberOfPoints()));
    const double want = 0.01 * BoundsDiagonal(clean.mesh);
    std::printf("  noise RMS %.5f for sigma %.5f\n", rms, want);
    EXPECT(std::abs(rms / want - 1) < 0.05, "AddGaussianNoise: RMS " << rms << " vs " << want);

    EXPECT(std::abs(PlaneAngleDegrees(Vec3(1, 0, 0), Vec3(-2, 0, 0))) < 1e-12, "angle sign");
    EXPECT(std::abs(PlaneAngleDegrees(Vec3(1, 0, 0), Vec3(0, 0, 3)) - 90) < 1e-12, "angle 90");
    EXPECT(std::abs(PlaneAngleDegrees(Vec3(1, 0, 0), Vec3(1, 1, 0)) - 45) < 1e-12, "angle 45");
    const KnownPlane truth{ Vec3(0, 0, 0), Vec3(1, 0, 0) };
    EXPECT(std::abs(PlaneOffsetError(truth, Vec3(0.3, 7, 1), Vec3(-1, 0, 0), Vec3(0, 1, 2), 3) -
             0.1) < 1e-12,
      "PlaneOffsetError");
    // sphere: any plane through the centre; cylinder: any plane containing the axis
    const ProceduralMesh sp = MakeSphere(2000), cy = MakeCylinder(2000);
    const Vec3 n = Vec3(0.3, -0.5, 0.8).normalized();
    const PlaneMatch ms = BestPlaneMatch(sp, Vec3::Zero(), n);
    EXPECT(ms.index == -1 && ms.angleDegrees < 1e-9 && ms.offsetError < 1e-12, "sphere family");
    const PlaneMatch mc = BestPlaneMatch(cy, Vec3(0, 0, 0.4), Vec3(0.6, 0.8, 0));
    EXPECT(mc.index == -1 && mc.angleDegrees < 1e-9 && mc.offsetError < 1e-12, "cylinder family");
    const PlaneMatch mz = BestPlaneMatch(cy, Vec3(0, 0, 0.1), Vec3(0, 0.02, 1));
    EXPECT(mz.index == 4 && std::abs(mz.angleDegrees - 1.1457628) < 1e-6, "cylinder mid plane");
    const PlaneMatch mt = BestPlaneMatch(cy, Vec3(0, 0, 0), Vec3(0.6, 0.8, 0.1));
    EXPECT(mt.index == -1 &&
        std::abs(
          mt.angleDegrees - std::asin(0.1 / std::sqrt(1.01)) * 180 / 3.14159265358979323846) < 1e-9,
      "cylinder tilted plane " << mt.angleDegrees);
    // IoU
    const ProceduralMesh bb = MakeBilateralBlob(2000);
    const size_t nf = bb.symmetricFace.size();
    std::vector<char> left(nf, 0), right(nf, 0), all(nf, 1);
    for (size_t f = 0; f < nf; ++f)
    {
      (f < nf / 2 ? right : left)[f] = 1;
    }
    EXPECT(std::abs(RegionIoU(bb.mesh, all, bb.symmetricFace) - 1) < 1e-12, "IoU identical");
    EXPECT(RegionIoU(bb.mesh, left, right) == 0, "IoU disjoint");
    EXPECT(std::abs(RegionIoU(bb.mesh, left, all) - 0.5) < 1e-9, "IoU half (mirror halves)");
    EXPECT(RegionIoU(bb.mesh, std::vector<char>(nf, 0), std::vector<char>(nf, 0)) == 1, "IoU 0/0");
  }

  section("1M-face bilateral blob");
  {
    const auto t0 = std::chrono::steady_clock::now();
    const ProceduralMesh m = MakeBilateralBlob(1000000);
    const double dt = Seconds(t0);
    std::printf("  MakeBilateralBlob(1000000): %lld faces in %.3f s\n",
      (long long)m.mesh->GetNumberOfCells(),
      dt);
    CheckMesh(gens[0], m, "BilateralBlob@1000000", 1000000);
  }

  section("done");
  if (failures)
  {
    std::printf("TestProceduralMeshes: %d check(s) FAILED\n", failures);
    return 1;
  }
  std::printf("TestProceduralMeshes: all checks passed\n");
  return 0;
}
