// SymmetricHausdorffBounds where the two surfaces are triangulated differently: their edges
// cross each other's triangles, so a piece over such an edge is not bounded well by any single
// triangle of the other surface (the case that took tens of seconds and ~1 GB before the
// two-triangle bound, until the evaluation budget ran out). On
// - two flat grids of different resolutions and diagonals (Hausdorff 0), one of them unwelded
//   (every triangle its own points: neighbours are matched by position);
// - the same with one grid lifted by t (Hausdorff exactly t);
// - a roof (two slopes meeting at a ridge that is an edge of both) in two triangulations
//   (Hausdorff 0), and a flat grid against the roof (Hausdorff exactly the roof's height);
// the bounds must bracket the known distance within the tolerance, be converged, and take few
// evaluations (a count the bounds report, not a time). A tiny budget must end unconverged with
// `upper` still a bound. Deterministic for any SMP backend.
#include "CoreTestUtilities.h"
#include "SurfaceDistance.h"

#include <vtkSMPTools.h>

#include <cmath>
#include <functional>

using namespace foldingmeshes;

namespace
{
/// An n x n grid on [0, 1]^2, z = height(x): squares split along the diagonal (0,0)-(1,1)
/// (`rising`) or the other one; welded, or every triangle with its own three points.
TriangleMesh Grid(int n, bool rising, bool welded, const std::function<double(double)>& height)
{
  TriangleMesh m;
  auto point = [&](int i, int j)
  {
    const double x = double(i) / n, y = double(j) / n;
    return Vec3(x, y, height(x));
  };
  auto id = [&](int i, int j)
  {
    if (!welded)
    {
      m.points.push_back(point(i, j));
      return static_cast<int>(m.points.size()) - 1;
    }
    return j * (n + 1) + i;
  };
  if (welded)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        m.points.push_back(point(i, j));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (rising)
      {
        m.triangles.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
        m.triangles.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
      }
      else
      {
        m.triangles.push_back({ id(i, j), id(i + 1, j), id(i, j + 1) });
        m.triangles.push_back({ id(i + 1, j), id(i + 1, j + 1), id(i, j + 1) });
      }
  return m;
}

double Flat(double)
{
  return 0.0;
}

/// Brackets `expected` within tol, converged, within `maxEvaluations`.
void Check(const char* name,
  const TriangleMesh& a,
  const TriangleMesh& b,
  double expected,
  double tol,
  long long maxEvaluations)
{
  const HausdorffBounds h = SymmetricHausdorffBounds(a, b, tol);
  std::printf("%s: [%.12g, %.12g], %lld evaluations%s\n",
    name,
    h.lower,
    h.upper,
    h.evaluations,
    h.converged ? "" : " (not converged)");
  EXPECT(h.lower <= expected + 1e-12 && h.upper >= expected - 1e-12,
    name << ": [" << h.lower << ", " << h.upper << "] does not hold " << expected);
  EXPECT(h.converged && h.upper - h.lower <= tol && h.upper <= expected + tol + 1e-12,
    name << ": [" << h.lower << ", " << h.upper << "] not within " << tol << " of " << expected
         << (h.converged ? "" : " (not converged)"));
  EXPECT(h.evaluations <= maxEvaluations,
    name << ": " << h.evaluations << " evaluations, expected at most " << maxEvaluations);
}
}

int main()
{
  const double tol = 1e-5 * std::sqrt(2.0); // the unfolder's: 1e-5 of the diagonal
  const TriangleMesh fine = Grid(7, true, true, Flat), coarse = Grid(5, false, false, Flat);
  // Every edge of one grid crosses triangles of the other; the pieces at the other's vertices
  // still need splitting down to the tolerance: a few per level, about 17 levels.
  Check("flat grids", fine, coarse, 0.0, tol, 100000);
  const double t = 0.01;
  Check("lifted grid",
    fine,
    Grid(5, false, false, [t](double) { return t; }),
    t,
    tol,
    100000);
  auto roof = [](double x) { return 0.4 * std::abs(x - 0.5); };
  Check("roofs", Grid(6, true, true, roof), Grid(4, false, false, roof), 0.0, tol, 100000);
  Check("flat grid and roof", Grid(6, true, true, Flat), Grid(4, false, true, roof), 0.2, tol,
    100000);

  // A budget too small to converge: still a proved bound, reported unconverged.
  const HausdorffBounds tight = SymmetricHausdorffBounds(fine, coarse, 1e-9, 2000);
  EXPECT(!tight.converged && tight.upper - tight.lower > 1e-9,
    "tiny budget: [" << tight.lower << ", " << tight.upper << "] reported converged");

  vtkSMPTools::SetBackend("Sequential");
  const HausdorffBounds one = SymmetricHausdorffBounds(fine, coarse, tol);
  vtkSMPTools::SetBackend("STDThread");
  vtkSMPTools::Initialize(2);
  const HausdorffBounds two = SymmetricHausdorffBounds(fine, coarse, tol);
  EXPECT(one.lower == two.lower && one.upper == two.upper && one.evaluations == two.evaluations,
    "bounds depend on the SMP backend");
  return coretest::Finish("TestHausdorffBounds");
}
