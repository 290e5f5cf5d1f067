// RegionMeasure (the detector's region of a plane), RandomNormal and the plane competition.
#include "TestProceduralMeshesRegion.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <unordered_map>

namespace tpm
{
RegionMeasure::RegionMeasure(vtkPolyData* pd)
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

double RegionMeasure::Fraction(const KnownPlane& plane) const
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
Vec3 RegionMeasure::Centroid(const std::vector<char>& mask) const
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
std::array<Vec3, 3> RegionMeasure::PrincipalNormals() const
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
} // namespace tpm
