// Internal to SymmetryDetection.cxx: one robust IRLS run of the paper's section 3 (Run) and
// the Refiner that seeds, iterates, polishes and scores such runs on a prepared mesh.
#ifndef foldingmeshes_SymmetryRefiner_h
#define foldingmeshes_SymmetryRefiner_h

#include "MeshPreparation.h"
#include "MirrorDistance.h"
#include "RegionGrowing.h"
#include "RobustCost.h"
#include "SymmetryDetection.h"
#include "Trace.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

namespace foldingmeshes
{
namespace symmetry_detail
{
using Clock = std::chrono::steady_clock;

inline double Seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}

/// State of one IRLS run.
struct Run
{
  Plane plane;
  std::vector<char> support;
  std::vector<double> weight;
  std::vector<double> distance;
  std::vector<double> cost;
  int coarseIterations = 0;
  int fineIterations = 0;
  double sigmaScale = 3.0; ///< fine sigma in units of epsilon (the paper: 3; polish: 1)
  std::vector<int> hints;  ///< closest faces of the last distance pass (search hints only)
  // Scores, after the final region is extracted.
  std::vector<char> region;
  double regionArea = 0.0;
  double rms = 0.0;
};

/// A probe and what its judgement needs of its state after the first two iterations.
struct Probe
{
  Run run;
  Plane earlyPlane;
  double earlySupportArea = 0.0;
};

class Refiner
{
public:
  /// Iterations over the vertices of `mesh`, their distances measured to the surface of
  /// `targetFaces` (the same mesh, or the full mesh of a sampled copy).
  Refiner(const PreparedMesh& mesh, const FaceTree& targetFaces, const SymmetryOptions& options)
    : Mesh(mesh)
    , Options(options)
    , Distances(mesh, targetFaces, options.compatibilityAngle)
  {
    this->Distances.SetFastPath(options.fastPathQuery);
  }

  /// Coarse then (optionally) fine phase from a start. `start` null: the paper's start.
  void Coarse(Run& run, const Plane* start) const
  {
    const int nf = Mesh.NumberOfFaces();
    run.support.assign(nf, 1);
    for (int f = 0; f < nf; ++f)
      run.support[f] = !Mesh.faceDegenerate[f];
    run.weight = Mesh.vertexAreas;
    // A user's plane (beyond the paper): the first coarse iteration takes sigma at its floor,
    // 3 epsilon, instead of the median rule, so the support is what is symmetric near it.
    bool seeded = start != nullptr;
    if (seeded)
      run.plane = *start;
    else
      run.plane = ChooseByCost(run.weight, run.support, DistanceMetric::Coarse, nullptr);
    Iterate(run, DistanceMetric::Coarse, seeded, Options.maximumIterations);
  }

  void Fine(Run& run, int iterations) const
  {
    Iterate(run, DistanceMetric::Fine, false, iterations);
  }

  /// Robust only: fine iterations with sigma = epsilon instead of 3 epsilon, so that the
  /// vertices that are symmetric within epsilon dominate the plane step rather than the
  /// near-symmetric surroundings the 3-epsilon support lets in.
  void Polish(Run& run, int iterations) const
  {
    run.sigmaScale = 1.0;
    Iterate(run, DistanceMetric::Fine, false, iterations);
    run.sigmaScale = 3.0;
  }

  /// A run starting at `plane` with all faces in the support (or `from`'s state).
  void Seed(Run& run, const Plane& plane, const Run* from) const
  {
    if (from)
    {
      run = *from;
      return;
    }
    run.plane = plane;
    run.support.assign(Mesh.NumberOfFaces(), 0);
    for (int f = 0; f < Mesh.NumberOfFaces(); ++f)
      run.support[f] = !Mesh.faceDegenerate[f];
    run.weight = Mesh.vertexAreas;
  }

  /// Fine distances at the run's plane and the final symmetric region. Only distances
  /// below `searchLimit` (at least epsilon) are resolved; larger ones are infinite.
  void Score(Run& run, double searchLimit) const
  {
    const double eps = Options.epsilon;
    Distances.Compute(run.plane,
      DistanceMetric::Fine,
      std::max(searchLimit, eps),
      run.distance,
      nullptr,
      nullptr,
      nullptr,
      &run.hints);
    run.region =
      LargestConnectedRegion(Mesh, FacesWithVerticesWithin(Mesh, run.distance, eps, true));
    run.regionArea = RegionArea(Mesh, run.region);
    double sum = 0.0, area = 0.0;
    std::vector<char> inRegion(Mesh.NumberOfPoints(), 0);
    for (int f = 0; f < Mesh.NumberOfFaces(); ++f)
      if (run.region[f])
        for (int v : Mesh.triangles[f])
          inRegion[v] = 1;
    for (int v = 0; v < Mesh.NumberOfPoints(); ++v)
      if (inRegion[v])
      {
        sum += Mesh.vertexAreas[v] * run.distance[v] * run.distance[v];
        area += Mesh.vertexAreas[v];
      }
    run.rms = area > 0.0 ? std::sqrt(sum / area) : std::numeric_limits<double>::infinity();
    if (this->Options.trace)
    {
      std::vector<double> values;
      for (int v = 0; v < Mesh.NumberOfPoints(); ++v)
        if (inRegion[v])
          values.push_back(run.distance[v] / eps);
      std::sort(values.begin(), values.end());
      if (!values.empty())
        this->Options.trace(FormatTrace("  region stats: median %.3f p75 %.3f p90 %.3f",
          values[values.size() / 2],
          values[values.size() * 3 / 4],
          values[values.size() * 9 / 10]));
    }
  }

private:
  double Sigma(DistanceMetric metric,
    const std::vector<double>& d,
    const std::vector<char>& vertexInSupport,
    double fineScale = 3.0) const
  {
    const double floor = 3.0 * Options.epsilon;
    if (metric == DistanceMetric::Fine)
      return fineScale * Options.epsilon;
    // Median of the finite distances of the support's vertices (a vertex without a
    // compatible face in the coarse metric has no distance to take a median of).
    std::vector<double> values;
    values.reserve(d.size());
    for (size_t i = 0; i < d.size(); ++i)
      if (vertexInSupport[i] && std::isfinite(d[i]))
        values.push_back(d[i]);
    if (values.empty())
      return floor;
    auto mid = values.begin() + values.size() / 2;
    std::nth_element(values.begin(), mid, values.end());
    return std::max(1.4826 * *mid, floor);
  }

  std::vector<char> SupportVertices(const std::vector<char>& support) const
  {
    std::vector<char> used(Mesh.NumberOfPoints(), 0);
    for (int f = 0; f < Mesh.NumberOfFaces(); ++f)
      if (support[f])
        for (int v : Mesh.triangles[f])
          used[v] = 1;
    return used;
  }

  double MaxDistance(DistanceMetric metric) const
  {
    // Beyond 3 sigma (fine) rho >= 0.9: treat as infinite, it saves most of the search.
    return metric == DistanceMetric::Fine ? 9.0 * Options.epsilon
                                          : std::numeric_limits<double>::infinity();
  }

  /// Search limit of an iteration's own distances: only support vertices (d <= 2 sigma)
  /// enter its cost, weights and plane step, so a fine iteration resolves distances up to
  /// 2 sigma (a hair more, so that d == 2 sigma is never lost to rounding) - 6 epsilon
  /// instead of 9, and 2 instead of 9 in the polish phase: the same support, weights and
  /// planes for a fraction of the search.
  double IterationMaxDistance(DistanceMetric metric, double fineScale) const
  {
    if (metric != DistanceMetric::Fine)
      return MaxDistance(metric);
    return std::min(MaxDistance(metric), 2.0 * fineScale * Options.epsilon * (1.0 + 1e-9));
  }

  double Cost(const std::vector<double>& d,
    const std::vector<char>& vertexInSupport,
    double sigma) const
  {
    double sum = 0.0;
    for (size_t i = 0; i < d.size(); ++i)
      if (vertexInSupport[i])
        sum += GemanMcClureCost(d[i], sigma);
    return sum;
  }

  /// Closed-form step choosing the eigen-plane of lowest sum of rho (the paper's rule).
  /// All three are scored with the same sigma: the current iteration's, or (first step)
  /// the one the candidate's own distances give.
  Plane ChooseByCost(const std::vector<double>& weight,
    const std::vector<char>& support,
    DistanceMetric metric,
    std::vector<double>* chosenDistances,
    double sigma = -1.0) const
  {
    std::array<Plane, 3> planes;
    if (!PrincipalPlanes(Mesh, weight, planes))
      return Plane();
    const std::vector<char> vin = SupportVertices(support);
    double bestCost = std::numeric_limits<double>::infinity();
    int best = 0;
    std::vector<double> d, bestD;
    for (int k = 0; k < 3; ++k)
    {
      Distances.Compute(planes[k], metric, MaxDistance(metric), d);
      const double c = Cost(d, vin, sigma > 0.0 ? sigma : Sigma(metric, d, vin));
      if (c < bestCost)
      {
        bestCost = c;
        best = k;
        bestD = d;
      }
    }
    if (chosenDistances)
      *chosenDistances = bestD;
    return planes[best];
  }

  void Iterate(Run& run, DistanceMetric metric, bool firstSigmaAtFloor, int maxIterations) const
  {
    const bool coarse = metric == DistanceMetric::Coarse;
    const double diag = Mesh.diagonal;
    (void)diag;
    const double angleTol = coarse ? 0.5 : 0.02;
    const double offsetTol = (coarse ? 1e-3 : 1e-4) * diag;
    std::vector<double> d;
    std::vector<Vec3> closest, closestNormals;
    bool haveDistances = false;
    std::vector<std::vector<char>> supports; // history, for cycle detection
    int& iterations = coarse ? run.coarseIterations : run.fineIterations;
    for (int it = 0; it < maxIterations; ++it)
    {
      if (!haveDistances)
        Distances.Compute(run.plane,
          metric,
          IterationMaxDistance(metric, run.sigmaScale),
          d,
          Options.robust ? &closest : nullptr,
          Options.robust ? &closestNormals : nullptr,
          nullptr,
          &run.hints);
      haveDistances = false;
      const std::vector<char> vin = SupportVertices(run.support);
      double sigma = Sigma(metric, d, vin, run.sigmaScale);
      if (firstSigmaAtFloor && it == 0)
        sigma = 3.0 * Options.epsilon;
      if (!std::isfinite(sigma))
        break;
      std::vector<char> support =
        LargestConnectedRegion(Mesh, FacesWithVerticesWithin(Mesh, d, 2.0 * sigma, false));
      if (RegionArea(Mesh, support) <= 0.0)
        break;
      const std::vector<char> sv = SupportVertices(support);
      run.support = support;
      run.cost.push_back(Cost(d, sv, sigma));
      ++iterations; // one entry of the cost history per counted iteration
      run.weight.assign(Mesh.NumberOfPoints(), 0.0);
      for (int v = 0; v < Mesh.NumberOfPoints(); ++v)
        if (sv[v])
          run.weight[v] = GemanMcClureWeight(d[v], sigma) * Mesh.vertexAreas[v];

      Plane next;
      if (!Options.robust)
      {
        next = ChooseByCost(run.weight, run.support, metric, &d, sigma);
        haveDistances = true;
      }
      else
      {
        // Robust: the plane that maps every weighted vertex onto the tangent plane of its
        // mirror partner (no jumps between eigen-axes, no bias from unequal vertex areas
        // of mirror images).
        if (!RefinePlaneFromCorrespondences(
              Mesh.points, closest, closestNormals, run.weight, run.plane, next))
          break;
      }
      const double angle = PlaneAngleDegrees(next, run.plane);
      const double offset = PlaneOffsetAt(run.plane, next, next.origin);
      const bool converged = angle < angleTol && offset < offsetTol;
      // A support that comes back after two or more iterations (a cycle: the fine phase's
      // 2-cycles move the plane by hundredths of a degree forever), or one that hardly
      // changes while the plane barely moves (within 3x the tolerances), ends the phase.
      const bool cycled = supports.size() >= 2 &&
        std::find(supports.begin(), supports.end() - 1, support) != supports.end() - 1 &&
        angle < 50.0 * angleTol;
      double changedArea = 0.0;
      if (!supports.empty())
        for (int f = 0; f < Mesh.NumberOfFaces(); ++f)
          if (supports.back()[f] != support[f])
            changedArea += Mesh.faceAreas[f];
      const bool stalled = !supports.empty() && changedArea < 0.002 * Mesh.totalArea &&
        angle < 3.0 * angleTol && offset < 3.0 * offsetTol;
      run.plane = next;
      if (converged || cycled || stalled)
        break;
      supports.push_back(std::move(support));
      if (supports.size() > 4)
        supports.erase(supports.begin());
    }
  }

  const PreparedMesh& Mesh;
  const SymmetryOptions& Options;
  MirrorDistance Distances;
};
} // namespace symmetry_detail
} // namespace foldingmeshes

#endif
