// RegionMeasure (the detector's region of a plane) and the plane competition (Compete).
#ifndef TestProceduralMeshesRegion_h
#define TestProceduralMeshesRegion_h

#include "TestProceduralMeshesChecks.h"

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
#include <cmath>
#include <cstddef>
#include <memory>
#include <random>
#include <vector>

namespace tpm
{
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
  explicit RegionMeasure(vtkPolyData* pd);

  double Eps() const { return this->Epsilon; }

  double Fraction(const KnownPlane& plane) const;

  // area-weighted centroid of the faces with mask[f] (all faces if mask is empty)
  Vec3 Centroid(const std::vector<char>& mask = {}) const;

  // normals of the principal planes of the area-weighted covariance of the surface
  std::array<Vec3, 3> PrincipalNormals() const;

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
Vec3 RandomNormal(std::mt19937& g);

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
  bool refine);
} // namespace tpm

#endif
