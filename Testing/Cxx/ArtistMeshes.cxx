#include "ArtistMeshes.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <utility>

namespace foldingmeshes
{
namespace artist
{
namespace
{
using Vec3 = Eigen::Vector3d;
using Tri = foldingmeshes::Triangle;

/// A mesh under construction, counted in parts.
struct Assembly
{
  std::vector<Vec3> points;
  std::vector<Tri> triangles;
  int parts = 0;

  int Add(const Vec3& p)
  {
    points.push_back(p);
    return static_cast<int>(points.size()) - 1;
  }
  void Triangle(int a, int b, int c, bool flip)
  {
    triangles.push_back(flip ? Tri{ a, c, b } : Tri{ a, b, c });
  }

  /// An axis-aligned box (12 triangles, outward unless flipped).
  void Box(const Vec3& centre, const Vec3& half, bool flip = false)
  {
    int v[8];
    for (int i = 0; i < 8; ++i)
      v[i] = Add(centre +
        Vec3((i & 1) ? half.x() : -half.x(),
          (i & 2) ? half.y() : -half.y(),
          (i & 4) ? half.z() : -half.z()));
    const int quads[6][4] = {
      { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 }
    };
    for (const auto& q : quads)
    {
      Triangle(v[q[0]], v[q[1]], v[q[2]], flip);
      Triangle(v[q[0]], v[q[2]], v[q[3]], flip);
    }
    ++parts;
  }

  /// A cylinder along `axis` (0 x, 1 y, 2 z), `segments` around, with or without caps.
  void Cylinder(const Vec3& centre,
    double radius,
    double halfLength,
    int axis,
    int segments,
    bool caps,
    bool flip = false)
  {
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    std::vector<int> ring[2];
    for (int end = 0; end < 2; ++end)
      for (int k = 0; k < segments; ++k)
      {
        const double a = 2.0 * M_PI * (k + 0.5) / segments;
        Vec3 p = centre;
        p[axis] += end ? halfLength : -halfLength;
        p[u] += radius * std::cos(a);
        p[w] += radius * std::sin(a);
        ring[end].push_back(Add(p));
      }
    for (int k = 0; k < segments; ++k)
    {
      const int k1 = (k + 1) % segments;
      Triangle(ring[0][k], ring[0][k1], ring[1][k1], flip);
      Triangle(ring[0][k], ring[1][k1], ring[1][k], flip);
    }
    if (caps)
      for (int end = 0; end < 2; ++end)
      {
        Vec3 c = centre;
        c[axis] += end ? halfLength : -halfLength;
        const int m = Add(c);
        for (int k = 0; k < segments; ++k)
        {
          const int k1 = (k + 1) % segments;
          if (end)
            Triangle(m, ring[1][k], ring[1][k1], flip);
          else
            Triangle(m, ring[0][k1], ring[0][k], flip);
        }
      }
    ++parts;
  }

  /// A UV sphere with `segments` longitudes and segments / 2 latitude bands.
  void Sphere(const Vec3& centre, double radius, int segments, bool flip = false)
  {
    const int bands = segments / 2;
    const int top = Add(centre + Vec3(0, 0, radius));
    std::vector<std::vector<int>> rows;
    for (int j = 1; j < bands; ++j)
    {
      const double t = M_PI * j / bands;
      std::vector<int> row;
      for (int k = 0; k < segments; ++k)
      {
        const double a = 2.0 * M_PI * (k + 0.5) / segments;
        row.push_back(Add(centre +
          radius * Vec3(std::sin(t) * std::cos(a), std::sin(t) * std::sin(a), std::cos(t))));
      }
      rows.push_back(row);
    }
    const int bottom = Add(centre - Vec3(0, 0, radius));
    for (int k = 0; k < segments; ++k)
    {
      const int k1 = (k + 1) % segments;
      Triangle(top, rows.front()[k], rows.front()[k1], flip);
      Triangle(bottom, rows.back()[k1], rows.back()[k], flip);
      for (size_t j = 0; j + 1 < rows.size(); ++j)
      {
        Triangle(rows[j][k], rows[j + 1][k], rows[j + 1][k1], flip);
        Triangle(rows[j][k], rows[j + 1][k1], rows[j][k1], flip);
      }
    }
    ++parts;
  }

  /// The faces [from, end) once more (exact duplicates, as modelling tools leave them).
  void DuplicateFaces(size_t from)
  {
    const size_t end = triangles.size();
    for (size_t f = from; f < end; ++f)
      triangles.push_back(triangles[f]);
  }
};

/// A part and its mirror image about x = 0 (the same builder called at x and -x).
template <typename Part>
void Pair(double x, Part part)
{
  part(x);
  part(-x);
}

Assembly Chair(int segments)
{
  Assembly a;
  a.Box(Vec3(0, 0, 0.45), Vec3(0.25, 0.25, 0.03));
  Pair(0.21, [&](double x) { a.Cylinder(Vec3(x, 0.21, 0.22), 0.025, 0.22, 2, segments, true); });
  Pair(0.21, [&](double x) { a.Cylinder(Vec3(x, -0.21, 0.22), 0.025, 0.22, 2, segments, true); });
  for (int s = -3; s <= 3; ++s)
    a.Box(Vec3(0.065 * s, 0.23, 0.75), Vec3(0.02, 0.015, 0.27));
  a.Box(Vec3(0, 0.23, 1.03), Vec3(0.26, 0.02, 0.03));
  Pair(0.27, [&](double x) { a.Cylinder(Vec3(x, 0, 0.62), 0.02, 0.2, 1, segments, false); });
  // Rungs between the legs, interpenetrating them.
  a.Cylinder(Vec3(0, 0.21, 0.12), 0.015, 0.23, 0, segments, true);
  a.Cylinder(Vec3(0, -0.21, 0.12), 0.015, 0.23, 0, segments, true);
  return a;
}

Assembly SlattedBench(int slats)
{
  Assembly a;
  Pair(0.9, [&](double x) { a.Box(Vec3(x, 0, 0.25), Vec3(0.04, 0.3, 0.25)); });
  for (int s = 0; s < slats; ++s)
  {
    const double y = -0.28 + 0.56 * (s + 0.5) / slats;
    a.Box(Vec3(0, y, 0.5), Vec3(0.95, 0.25 / slats, 0.015));
  }
  const size_t before = a.triangles.size();
  a.Box(Vec3(0, 0, 0.1), Vec3(0.9, 0.02, 0.02)); // a stretcher, its faces twice
  a.DuplicateFaces(before);
  return a;
}

Assembly Rack(int n)
{
  Assembly a;
  Pair(1.05, [&](double x) { a.Box(Vec3(x, 0, 1.0), Vec3(0.03, 0.3, 1.0)); });
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
    {
      const double x = -1.0 + 2.0 * (i + 0.5) / n, z = 0.05 + 1.9 * (j + 0.5) / n;
      a.Box(Vec3(x, 0, z), Vec3(0.8 / n, 0.25, 0.8 / n), (i + j) % 7 == 0);
    }
  return a;
}

Assembly Biplane(int segments)
{
  Assembly a;
  a.Cylinder(Vec3(0, 0, 0), 0.18, 1.2, 1, segments, false); // fuselage, open ends
  a.Sphere(Vec3(0, 1.25, 0), 0.17, segments);               // nose
  for (const double z : { -0.25, 0.35 })
  {
    const size_t before = a.triangles.size();
    a.Box(Vec3(0, 0.3, z), Vec3(1.6, 0.3, 0.02)); // wings through the fuselage
    if (z > 0)
      a.DuplicateFaces(before);
  }
  for (const double x : { 0.5, 1.0, 1.45 })
    Pair(x, [&](double px) { a.Cylinder(Vec3(px, 0.3, 0.05), 0.015, 0.3, 2, 12, false); });
  a.Box(Vec3(0, -1.1, 0.05), Vec3(0.5, 0.12, 0.015)); // tail plane
  a.Box(Vec3(0, -1.1, 0.25), Vec3(0.015, 0.12, 0.2)); // fin, on the plane
  Pair(0.35, [&](double x) { a.Sphere(Vec3(x, 0.5, -0.55), 0.12, segments / 2); });
  Pair(0.35, [&](double x) { a.Cylinder(Vec3(x, 0.5, -0.4), 0.01, 0.15, 2, 8, false); });
  for (int b = 0; b < 2; ++b) // propeller blades, crossing on the axis
    a.Box(Vec3(0, 1.43, 0), b ? Vec3(0.5, 0.01, 0.04) : Vec3(0.04, 0.01, 0.5));
  return a;
}

Assembly Figure(int segments)
{
  Assembly a;
  a.Sphere(Vec3(0, 0, 1.7), 0.12, segments);
  a.Cylinder(Vec3(0, 0, 1.3), 0.17, 0.25, 2, segments, true);
  a.Cylinder(Vec3(0, 0, 1.55), 0.05, 0.06, 2, segments, false); // neck, open
  Pair(0.25, [&](double x) { a.Cylinder(Vec3(x, 0, 1.25), 0.045, 0.28, 2, segments, false); });
  Pair(0.25, [&](double x) { a.Sphere(Vec3(x, 0, 1.52), 0.06, segments / 2, x > 0); });
  Pair(0.1, [&](double x) { a.Cylinder(Vec3(x, 0, 0.52), 0.07, 0.5, 2, segments, true); });
  Pair(0.1, [&](double x) { a.Box(Vec3(x, 0.06, 0.02), Vec3(0.05, 0.12, 0.02)); });
  for (int k = 0; k < 12; ++k) // buttons on the chest, on the plane
    a.Sphere(Vec3(0, -0.17, 1.1 + 0.04 * k), 0.012, 8);
  return a;
}

Assembly Soup(int n)
{
  Assembly a;
  // A floor of two triangles spanning the model, symmetric about x = 0, open.
  const int p0 = a.Add(Vec3(-3, -3, 0)), p1 = a.Add(Vec3(3, -3, 0)), p2 = a.Add(Vec3(3, 3, 0)),
            p3 = a.Add(Vec3(-3, 3, 0)), c = a.Add(Vec3(0, 0, 0));
  for (const auto& t : { Tri{ c, p0, p1 }, Tri{ c, p1, p2 }, Tri{ c, p2, p3 }, Tri{ c, p3, p0 } })
    a.Triangle(t[0], t[1], t[2], false);
  ++a.parts;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < n; ++i)
  {
    const double x = 2.5 * u(random), y = 5.0 * u(random) - 2.5, s = 0.05 + 0.2 * u(random);
    Pair(x, [&](double px) { a.Box(Vec3(px, y, s), Vec3(s, 0.6 * s, s)); });
  }
  return a;
}

/// Pushes the points with x > -0.2 of the extent by a smooth, uneven field (about 60% of the
/// area of a model symmetric about x = 0): no plane folds it within a few percent.
void Deform(Assembly& a)
{
  Vec3 lo = a.points[0], hi = a.points[0];
  for (const Vec3& p : a.points)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double extent = (hi - lo).norm();
  for (Vec3& p : a.points)
  {
    const double x = (p.x() - lo.x()) / extent, z = (p.z() - lo.z()) / extent;
    if (p.x() > -0.2 * (hi.x() - lo.x()) / 2)
      p += 0.08 * extent * Vec3(std::sin(7 * z), 0.5 * std::cos(5 * x + 3 * z), std::sin(4 * x));
  }
}

Eigen::Isometry3d RigidMotion(unsigned seed)
{
  std::mt19937 random(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  Eigen::Quaterniond q(g(random), g(random), g(random), g(random));
  q.normalize();
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = q.toRotationMatrix();
  t.translation() = Vec3(g(random), g(random), g(random)) * 3.0;
  return t;
}
}

std::vector<ArtistMesh> MakeArtistCorpus()
{
  const std::vector<std::pair<std::string, Assembly>> models = { { "chair", Chair(48) },
    { "chair_dense", Chair(1200) },
    { "bench_slats", SlattedBench(300) },
    { "rack", Rack(32) },
    { "biplane", Biplane(160) },
    { "figure", Figure(96) },
    { "soup", Soup(400) } };
  std::vector<ArtistMesh> corpus;
  unsigned seed = 1;
  for (const auto& model : models)
    for (const std::string variant : { "exact", "moved", "deformed" })
    {
      Assembly a = model.second;
      ArtistMesh m;
      m.origin = Vec3(0, 0, 0);
      m.normal = Vec3(1, 0, 0);
      m.deformed = variant == "deformed";
      if (m.deformed)
        Deform(a);
      if (variant == "moved")
      {
        const Eigen::Isometry3d t = RigidMotion(seed++);
        for (Vec3& p : a.points)
          p = t * p;
        m.origin = t * m.origin;
        m.normal = t.linear() * m.normal;
      }
      m.name = model.first + "_" + variant;
      m.mesh.points = std::move(a.points);
      m.mesh.triangles = std::move(a.triangles);
      m.parts = a.parts;
      corpus.push_back(std::move(m));
    }
  return corpus;
}

ArtistMesh MakeCrate(int pairs)
{
  Assembly a;
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(pairs))));
  for (int b = 0; b < pairs; ++b)
  {
    // One draw per statement: the order of a call's arguments is unspecified.
    const double hx = 0.5 * (0.3 + 1.4 * u(random)), hy = 0.5 * (0.3 + 1.4 * u(random)),
                 hz = 0.5 * (0.3 + 1.4 * u(random));
    const Vec3 half(hx, hy, hz);
    const double x = 1.5 + 3.0 * (b % side), y = 3.0 * (b / side);
    Pair(x, [&](double px) { a.Box(Vec3(px, y, 0.0), half); });
  }
  ArtistMesh m;
  const Eigen::Isometry3d t = RigidMotion(17);
  for (Vec3& p : a.points)
    p = t * p;
  m.name = "crate_" + std::to_string(a.triangles.size());
  m.origin = t * Vec3(0, 0, 0);
  m.normal = t.linear() * Vec3(1, 0, 0);
  m.mesh.points = std::move(a.points);
  m.mesh.triangles = std::move(a.triangles);
  m.parts = a.parts;
  return m;
}

vtkSmartPointer<vtkPolyData> ToPolyData(const TriangleMesh& m, bool doublePoints)
{
  vtkNew<vtkPoints> points;
  if (doublePoints)
    points->SetDataTypeToDouble();
  else
    points->SetDataTypeToFloat();
  for (const Vec3& p : m.points)
    points->InsertNextPoint(p.data());
  vtkNew<vtkCellArray> polys;
  for (const Triangle& t : m.triangles)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    polys->InsertNextCell(3, ids);
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}
}
}
