// Distance queries through a VTK cell locator (vtkCellLocatorFaceQuery, issue 19) against the
// core's FaceTree, on procedural and real meshes and on a mesh with degenerate triangles
// (collinear corners, coincident corners, a sliver):
// - point-to-surface distances of 3000 random points (inside and around the bounds) agree to
//   1e-9 of the diagonal, with vtkStaticCellLocator and with a user's vtkCellLocator;
// - the sampled comparison (CompareSurfaces) and the proved Hausdorff bounds against a moved
//   copy agree (to rounding; the bounds to their tolerance);
// - vtkFoldingTreeUnfolder uses vtkStaticCellLocator by default (field data DistanceLocator),
//   a user-set locator when given, with the same HausdorffToOriginal and bound.
// Prints the query times of both (a measurement, not a check).
#include "TestExpect.h"
#include "vtkCellLocatorFaceQuery.h"
#include "vtkFoldingTreeBuilder.h"
#include "vtkFoldingTreeUnfolder.h"
#include "vtkOFFReader.h"

#include "Core/SurfaceDistance.h"
#include "ProceduralMeshes.h"

#include <vtkCellArray.h>
#include <vtkCellLocator.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

using namespace foldingmeshes;
namespace pm = foldingmeshes::testing;

namespace
{
int failures = 0;
#define EXPECT(cond, msg) FOLDINGMESHES_EXPECT(failures, cond, msg)

TriangleMesh ToMesh(vtkPolyData* pd)
{
  TriangleMesh m;
  m.points.resize(pd->GetNumberOfPoints());
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
    pd->GetPoint(i, m.points[i].data());
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < pd->GetNumberOfCells(); ++c)
  {
    pd->GetCellPoints(c, ids);
    for (vtkIdType k = 1; k + 1 < ids->GetNumberOfIds(); ++k) // polygons as fans
      m.triangles.push_back({ static_cast<int>(ids->GetId(0)),
        static_cast<int>(ids->GetId(k)),
        static_cast<int>(ids->GetId(k + 1)) });
  }
  return m;
}

double Diagonal(const TriangleMesh& m)
{
  Vec3 lo = m.points[0], hi = m.points[0];
  for (const Vec3& p : m.points)
    lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return (hi - lo).norm();
}

double Seconds(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void CompareQueries(const TriangleMesh& mesh, const char* name)
{
  const double diagonal = Diagonal(mesh);
  Vec3 lo = mesh.points[0], hi = mesh.points[0];
  for (const Vec3& p : mesh.points)
    lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  std::vector<Vec3> queries;
  for (int i = 0; i < 3000; ++i)
    queries.push_back(lo + Vec3(u(random), u(random), u(random)).cwiseProduct(hi - lo));
  for (const Vec3& p : mesh.points) // on the surface too
    if (queries.size() < 4000)
      queries.push_back(p);

  auto start = std::chrono::steady_clock::now();
  const SurfaceDistanceQuery tree(mesh);
  const std::vector<double> expected = tree.Distances(queries);
  const double treeSeconds = Seconds(start);
  vtkNew<vtkCellLocator> userLocator;
  for (vtkAbstractCellLocator* prototype : { static_cast<vtkAbstractCellLocator*>(nullptr),
         static_cast<vtkAbstractCellLocator*>(userLocator.Get()) })
  {
    start = std::chrono::steady_clock::now();
    const SurfaceDistanceQuery located(mesh, CellLocatorFaceQueryFactory(prototype));
    const std::vector<double> got = located.Distances(queries);
    const double seconds = Seconds(start);
    double worst = 0.0;
    for (size_t i = 0; i < queries.size(); ++i)
      worst = std::max(worst, std::abs(got[i] - expected[i]));
    const char* which = prototype ? "vtkCellLocator" : "vtkStaticCellLocator";
    std::printf("%s, %zu triangles, %zu queries: FaceTree %.4f s, %s %.4f s, largest "
                "difference %.3g of the diagonal\n",
      name,
      mesh.triangles.size(),
      queries.size(),
      treeSeconds,
      which,
      seconds,
      worst / diagonal);
    EXPECT(worst <= 1e-9 * diagonal,
      name << ": " << which << " distances agree (" << worst / diagonal << " of the diagonal)");
  }

  // Against a moved copy: sampled distances and proved bounds.
  TriangleMesh moved = mesh;
  for (Vec3& p : moved.points)
    p += Vec3(0.003, -0.002, 0.001) * diagonal + 0.002 * diagonal * Vec3(std::sin(7 * p.x()), 0, 0);
  const SurfaceComparison a = CompareSurfaces(mesh, moved);
  const SurfaceComparison b = CompareSurfaces(mesh, moved, CellLocatorFaceQueryFactory(nullptr));
  EXPECT(std::abs(a.hausdorff - b.hausdorff) <= 1e-9 * diagonal &&
      std::abs(a.mean - b.mean) <= 1e-9 * diagonal,
    name << ": CompareSurfaces agrees (" << a.hausdorff << " / " << b.hausdorff << ")");
  const double tolerance = 1e-4 * diagonal;
  const HausdorffBounds x = SymmetricHausdorffBounds(mesh, moved, tolerance);
  const HausdorffBounds y = SymmetricHausdorffBounds(
    mesh, moved, tolerance, DefaultMaximumEvaluations, 0.0, CellLocatorFaceQueryFactory(nullptr));
  EXPECT(std::abs(x.upper - y.upper) <= tolerance && std::abs(x.lower - y.lower) <= tolerance &&
      y.lower <= y.upper,
    name << ": proved bounds agree ([" << x.lower << ", " << x.upper << "] / [" << y.lower << ", "
         << y.upper << "])");
}

TriangleMesh WithDegenerateTriangles(TriangleMesh m)
{
  const int n = static_cast<int>(m.points.size());
  const Vec3 a = m.points[0], b = m.points[1];
  m.points.push_back(a + 2.0 * (b - a));                           // n: on the line through a, b
  m.points.push_back(a + Vec3(0.5, 0.5, 0.5));                     // n + 1
  m.points.push_back(a + Vec3(0.5, 0.5, 0.5));                     // n + 2: the same point
  m.points.push_back(a + Vec3(0.5, 0.5, 0.5) + Vec3(1e-13, 0, 0)); // n + 3: a sliver corner
  m.triangles.push_back({ 0, 1, n });                              // collinear corners
  m.triangles.push_back({ n + 1, n + 2, n + 1 });                  // one point three times
  m.triangles.push_back({ n + 1, n + 3, 0 });                      // a sliver
  return m;
}

void Unfolder(const std::string& dino)
{
  vtkNew<vtkOFFReader> reader;
  reader->SetFileName(dino.c_str());
  vtkNew<vtkFoldingTreeBuilder> builder;
  builder->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkFoldingTreeUnfolder> unfolder;
  unfolder->SetInputConnection(builder->GetOutputPort(0));
  unfolder->SetOriginalConnection(reader->GetOutputPort());
  EXPECT(unfolder->GetLocator() == nullptr, "the unfolder's Locator is null by default");
  unfolder->Update();
  auto field = [&](const char* name)
  {
    vtkDataArray* a = unfolder->GetOutput()->GetFieldData()->GetArray(name);
    return a ? a->GetTuple1(0) : -1.0;
  };
  auto locator = [&]() -> std::string
  {
    auto* a = vtkStringArray::SafeDownCast(
      unfolder->GetOutput()->GetFieldData()->GetAbstractArray("DistanceLocator"));
    return a && a->GetNumberOfValues() ? a->GetValue(0) : std::string();
  };
  EXPECT(
    locator() == "vtkStaticCellLocator", "default: vtkStaticCellLocator (" << locator() << ")");
  const double hausdorff = field("HausdorffToOriginal"), bound = field("HausdorffToOriginalBound");
  vtkNew<vtkCellLocator> user;
  unfolder->SetLocator(user);
  unfolder->Update();
  EXPECT(locator() == "vtkCellLocator", "a user's locator: vtkCellLocator (" << locator() << ")");
  EXPECT(std::abs(field("HausdorffToOriginal") - hausdorff) <= 1e-9 * std::max(1.0, hausdorff) &&
      std::abs(field("HausdorffToOriginalBound") - bound) <= 1e-3 * std::max(1e-9, bound) + 1e-9,
    "the same distances with either locator (" << hausdorff << ", " << bound << ")");
}
}

int main(int argc, char* argv[])
{
  CompareQueries(ToMesh(pm::MakeBilateralBlob(4000).mesh), "bilateral blob");
  CompareQueries(WithDegenerateTriangles(ToMesh(pm::MakeSphere(2000).mesh)), "sphere + degenerate");
  if (argc > 1)
  {
    vtkNew<vtkOFFReader> reader;
    reader->SetFileName(argv[1]);
    reader->Update();
    CompareQueries(ToMesh(reader->GetOutput()), "dino");
    Unfolder(argv[1]);
  }
  std::printf("TestCellLocatorDistances: %s\n", failures ? "FAILED" : "all checks passed");
  return failures ? 1 : 0;
}
