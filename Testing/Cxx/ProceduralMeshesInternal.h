// Internal helpers of the ProceduralMeshes*.cxx sources: types, random numbers, declarations.
#ifndef foldingmeshes_testing_ProceduralMeshesInternal_h
#define foldingmeshes_testing_ProceduralMeshesInternal_h

#include "ProceduralMeshes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

namespace foldingmeshes
{
namespace testing
{
namespace procedural
{
using Vec3 = Eigen::Vector3d;
using Vec2 = Eigen::Vector2d;
using Id = vtkIdType;
using Tri = std::array<Id, 3>;
constexpr double kPi = 3.14159265358979323846;

struct TriMesh
{
  std::vector<Vec3> p;
  std::vector<Tri> t;
  std::vector<char> sym; // per triangle
  Id Add(const Vec3& x)
  {
    p.push_back(x);
    return Id(p.size()) - 1;
  }
  void Face(Id a, Id b, Id c, char s)
  {
    t.push_back({ a, b, c });
    sym.push_back(s);
  }
  void Append(const TriMesh& o)
  {
    const Id off = Id(p.size());
    p.insert(p.end(), o.p.begin(), o.p.end());
    for (const Tri& f : o.t)
    {
      t.push_back({ f[0] + off, f[1] + off, f[2] + off });
    }
    sym.insert(sym.end(), o.sym.begin(), o.sym.end());
  }
  double Area(size_t f) const
  {
    return 0.5 * (p[t[f][1]] - p[t[f][0]]).cross(p[t[f][2]] - p[t[f][0]]).norm();
  }
};

// ---- deterministic random numbers (std distributions are implementation-defined) ----
inline std::mt19937 Rng(unsigned seed, unsigned salt)
{
  std::seed_seq s{ seed, salt };
  return std::mt19937(s);
}
inline double Uniform(std::mt19937& g)
{
  return (double(g()) + 0.5) / 4294967296.0;
}
inline double Uniform(std::mt19937& g, double a, double b)
{
  return a + (b - a) * Uniform(g);
}
inline double Gauss(std::mt19937& g)
{
  const double u = Uniform(g);
  const double v = Uniform(g);
  return std::sqrt(-2 * std::log(u)) * std::cos(2 * kPi * v);
}
inline Vec3 RandomUnit(std::mt19937& g)
{
  const double z = Uniform(g, -1, 1);
  const double a = 2 * kPi * Uniform(g);
  const double s = std::sqrt(1 - z * z);
  return { s * std::cos(a), s * std::sin(a), z };
}
inline Vec3 MirrorX(const Vec3& v)
{
  return { -v.x(), v.y(), v.z() };
}

// ---- analytic closed surfaces: unit directions d -> points ----
inline double Gaussian(double x)
{
  return std::exp(-x * x);
}
inline double SmoothStep(double x)
{
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

// Zipper strip between an inner loop and an outer loop (same rotational sense, parameters in
// [0, 1) increasing from 0). Triangles use the inner edges backwards and the outer edges forwards:
// counter-clockwise when both loops are counter-clockwise around the inner one. A one-vertex
// inner loop gives a fan.
template <class Emit>
void Zip(const std::vector<Id>& in,
  const std::vector<double>& tin,
  const std::vector<Id>& out,
  const std::vector<double>& tout,
  Emit emit)
{
  const size_t ni = in.size(), no = out.size(), iend = ni == 1 ? 0 : ni;
  size_t i = 0, k = 0;
  while (i < iend || k < no)
  {
    const double nexti = i + 1 < ni ? tin[i + 1] : 1.0;
    const double nexto = k + 1 < no ? tout[k + 1] : 1.0;
    if (i >= iend || (k < no && nexto <= nexti))
    {
      emit(in[i % ni], out[k % no], out[(k + 1) % no]);
      ++k;
    }
    else
    {
      emit(in[i % ni], out[k % no], in[(i + 1) % ni]);
      ++i;
    }
  }
}

// ---- octahedral-grid tessellation (ProceduralMeshesTessellation.cxx) ----
std::vector<double> UniformParams(size_t n);
std::vector<double> ArcParams(const TriMesh& m, const std::vector<Id>& loop);
TriMesh OctaSphere(int n, const std::function<Vec3(const Vec3&)>& shape, bool mirror, char sym);
TriMesh OctaSphereTwoResolutions(int n, int m, const std::function<Vec3(const Vec3&)>& shape);
std::vector<Vec2> RingTable(int q);
int OctaResolution(double faces);

// ---- tubes (horns, necks) in a local frame: centreline from 0, leaving along +z ----
struct TubeSpec
{
  std::function<Vec3(double)> center; // local centreline, t in [0, 1], c(0) = 0, c'(0) along +z
  std::function<Vec2(double)> radii;  // section semi-axes along the section's X and Y axes
  // Optional general section: the offset (along X, Y) of the ring point of unit direction dir
  // (a RingTable entry) at t; replaces (radii.x dir.x, radii.y dir.y). radii(1) still sets the
  // length of the end cap.
  std::function<Vec2(double, const Vec2&)> section;
  int quarter = 2;                 // 4 * quarter vertices per ring
  double spacing = 0.1;            // target edge length
  bool symmetricDiagonals = false; // triangulate mirror-symmetrically about local x = 0
};

// ---- cutting a disc-shaped hole and welding a tube into it ----
struct Hole
{
  std::vector<char> removed; // per face
  std::vector<Id> loop;      // boundary, in the direction of the kept faces' edges
  Vec3 normal, center;       // mean normal of the removed faces, centroid of the loop
};

// ---- tubes, holes and welds (ProceduralMeshesAttachments.cxx) ----
TriMesh BuildTube(const TubeSpec& s,
  const Vec3& o,
  const Eigen::Matrix3d& E,
  char sym,
  std::vector<Id>& ring0);
Hole CutHoleRobust(const TriMesh& m,
  const Vec3& P,
  double rho,
  double h,
  const std::vector<char>& allowed);
double MeshArea(const TriMesh& m, int onlySym = -1);
double EdgeLength(const TriMesh& m);
double LoopLift(const TriMesh& m, const Hole& hole);
Eigen::Matrix3d ClearestFrame(const TriMesh& body,
  const Eigen::Matrix3d& E,
  const TubeSpec& s,
  const Vec3& o,
  double L,
  double skip,
  const std::function<double(const Eigen::Matrix3d&)>& cost = {},
  double minGap = 0);
TriMesh WeldToFraction(const TriMesh& body,
  const Hole& hole,
  const std::function<TubeSpec(double)>& spec,
  const Vec3& o,
  const Eigen::Matrix3d& E,
  char tubeSym,
  int which,
  double target,
  double L0);

// ---- VTK conversion and access (ProceduralMeshesConversion.cxx) ----
ProceduralMesh Finish(const TriMesh& m, std::vector<KnownPlane> planes);
std::vector<Vec3> GetPoints(vtkPolyData* pd);
void SetPoints(vtkPolyData* pd, const std::vector<Vec3>& p);

template <class Fn> // fn(cellId, a, b, c) for every triangle of every polygon (fan)
void ForEachTriangle(vtkPolyData* pd, Fn fn)
{
  for (vtkIdType c = 0; c < pd->GetNumberOfCells(); ++c)
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    const int type = pd->GetCellType(c);
    if (type != VTK_TRIANGLE && type != VTK_POLYGON && type != VTK_QUAD)
    {
      continue;
    }
    pd->GetCellPoints(c, n, ids);
    for (vtkIdType k = 1; k + 1 < n; ++k)
    {
      fn(c, ids[0], ids[k], ids[k + 1]);
    }
  }
}

const KnownPlane kPlaneX{ Vec3::Zero(), Vec3::UnitX() };
const KnownPlane kPlaneY{ Vec3::Zero(), Vec3::UnitY() };
const KnownPlane kPlaneZ{ Vec3::Zero(), Vec3::UnitZ() };
} // namespace procedural
} // namespace testing
} // namespace foldingmeshes

#endif
