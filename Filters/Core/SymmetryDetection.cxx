#include "SymmetryDetection.h"
#include "Trace.h"

#include "CandidatePlanes.h"
#include "ClusteredMesh.h"
#include "MeshPreparation.h"
#include "MirrorDistance.h"
#include "ParallelTasks.h"
#include "RegionGrowing.h"
#include "RobustCost.h"
#include "SymmetryRefiner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>

namespace foldingmeshes
{
namespace
{
using namespace symmetry_detail;

/// Iterations of the polish phase (sigma = epsilon) at most. It refines a converged plane; a
/// polish still moving after this many steps is drifting along the region's border (the
/// eagle's first local fold: 56.6% compression with 50 iterations allowed, 63.1% with 10),
/// at no cost in accuracy (TestSymmetryAccuracy: same planes, but for the 30% sub-part at
/// epsilon 1%: 0.6 -> 0.9 degrees).
constexpr int PolishIterations = 10;

/// Probes are finished only if their region is at least this fraction of the best probe's;
/// a probe whose support after its first two iterations is smaller is not continued
/// (the same results on all 29 shared meshes, about 10% less time).
constexpr double PromisingFraction = 0.5;
/// Probes finished and ranked for the result ...
constexpr size_t RankedFinalists = 3;
/// ... and, with SymmetryOptions::scoreEveryFinalist, this many more finished and returned
/// after them, unranked (a chair's seat is as symmetric diagonally as left to right: the
/// plane the whole parts need can rank fourth).
constexpr size_t ExtraFinalists = 3;

/// A probe whose tight region misses less than this fraction of the area ends the probing.
constexpr double GlobalSymmetryMargin = 0.02;

bool SamePlane(const Plane& a, const Plane& b, double epsilon)
{
  return PlaneAngleDegrees(a, b) < 2.0 && PlaneOffsetAt(a, b, b.origin) < epsilon;
}

/// A region whose distances stay well below epsilon (the "symmetry found" residual rule):
/// an accidental region spreads its distances over [0, epsilon).
/// Tight = the documented SymmetryFound rule holds for the run's region.
bool Tight(const Run& r, const SymmetryOptions& options, double totalArea)
{
  return r.regionArea > 0.0 && r.regionArea >= options.minimumSymmetricAreaFraction * totalArea &&
    r.rms <= FoundResidualRatio * options.epsilon;
}

/// Better final result: a tight region beats a loose one; then the larger region; within
/// 2% of the mesh area, the lower residual.
bool Better(const Run& a, const Run& b, double totalArea, const SymmetryOptions& options)
{
  const bool ta = Tight(a, options, totalArea), tb = Tight(b, options, totalArea);
  if (ta != tb)
    return ta;
  if (std::abs(a.regionArea - b.regionArea) > 0.02 * totalArea)
    return a.regionArea > b.regionArea;
  return a.rms < b.rms;
}
}

namespace
{
/// Full-range distances and labels of the winning run into the result.
void Finish(const PreparedMesh& mesh,
  const SymmetryOptions& options,
  const Refiner& refiner,
  Run& best,
  SymmetryResult& result)
{
  const int nf = mesh.NumberOfFaces();
  // Distances up to 3 sigma for the output (the run's own reach epsilon: the same region).
  if (options.distancesUpTo3Sigma)
    refiner.Score(best, 9.0 * options.epsilon);
  result.plane = CanonicalPlane(best.plane, best.plane.origin);
  result.distance = best.distance;
  result.weight = best.weight;
  result.costHistory = best.cost;
  result.coarseIterations = best.coarseIterations;
  result.fineIterations = best.fineIterations;
  result.faceLabel.assign(nf, 0);
  for (int f = 0; f < nf; ++f)
    result.faceLabel[f] = best.region[f] ? 2 : (best.support[f] ? 1 : 0);
  result.symmetricArea = best.regionArea;
  result.symmetricAreaFraction = best.regionArea / mesh.totalArea;
  result.rmsResidual = best.rms;
  result.found = result.symmetricAreaFraction >= options.minimumSymmetricAreaFraction &&
    best.rms <= FoundResidualRatio * options.epsilon;
}

/// The detection proper: iterations over the vertices of `mesh`, distances measured to the
/// surface of `targetFaces` (the mesh itself, or the full mesh of a sampled copy).
SymmetryResult DetectOn(const PreparedMesh& mesh,
  const FaceTree& targetFaces,
  const SymmetryOptions& options);

/// Large meshes: the candidate search on a sampled copy (ClusterVertices: some of the mesh's
/// own vertices) whose distances are measured to the full mesh; its finalists are then
/// refined (refineSampledFinalists) and scored on the full mesh: a tight first one settles
/// it, else the best of them wins.
SymmetryResult DetectOnSampledCopy(const PreparedMesh& mesh,
  const FaceTree& meshFaces,
  const SymmetryOptions& options)
{
  SymmetryResult result;
  auto report = [&](double p) { return !options.progress || options.progress(p); };
  const auto t0 = Clock::now();
  PreparedMesh small;
  std::string error;
  const int sampledFaces = std::min(
    MaximumSampledFaces, static_cast<int>(std::ceil(SampledFaceFraction * mesh.NumberOfFaces())));
  const ClusteredMesh clustered = ClusterVertices(mesh, sampledFaces);
  if (!PrepareMesh(clustered.mesh, clustered.normals, small, error) || small.NumberOfFaces() < 4)
    return DetectOn(mesh, meshFaces, options);
  if (!mesh.proximityLinks.empty())
    LinkNearbyParts(small, options.epsilon);
  SymmetryOptions coarseOptions = options;
  coarseOptions.progress = [&](double p) { return report(0.6 * p); };
  coarseOptions.distancesUpTo3Sigma = false; // the copy's distances are not returned
  const SymmetryResult coarse = DetectOn(small, meshFaces, coarseOptions);
  result.candidateSeconds = Seconds(t0);
  if (coarse.aborted)
  {
    result.aborted = true;
    return result;
  }
  const auto t1 = Clock::now();
  Refiner refiner(mesh, meshFaces, options);
  std::vector<Run> runs;
  bool settled = false;
  for (size_t k = 0; k < coarse.finalists.size(); ++k)
  {
    Run run;
    refiner.Seed(run, coarse.finalists[k], nullptr);
    if (options.refineSampledFinalists)
    {
      refiner.Fine(run, options.maximumIterations);
      refiner.Polish(run, std::min(options.maximumIterations, PolishIterations));
    }
    refiner.Score(run, options.epsilon);
    const bool tight = Tight(run, options, mesh.totalArea);
    runs.push_back(std::move(run));
    if (!report(0.6 + 0.4 * static_cast<double>(k + 1) / coarse.finalists.size()))
    {
      result.aborted = true;
      return result;
    }
    // The finalists come best first: a tight result for the best one settles it (the
    // others could only win with a larger tight region, which the sampled copy ranked lower).
    settled = settled || (k == 0 && tight);
    if (settled && !options.scoreEveryFinalist)
      break;
  }
  result.fineSeconds = Seconds(t1);
  result.startsTried = coarse.startsTried;
  if (runs.empty())
    return DetectOn(mesh, meshFaces, options);
  int bestRun = 0;
  for (size_t k = 1; k < runs.size() && k < coarse.rankedFinalists && !settled; ++k)
    if (Better(runs[k], runs[bestRun], mesh.totalArea, options))
      bestRun = static_cast<int>(k);
  for (size_t k = 0; k < runs.size(); ++k)
    result.finalists.push_back(runs[k].plane);
  result.rankedFinalists = settled ? 1 : std::min(runs.size(), coarse.rankedFinalists);
  std::swap(result.finalists[0], result.finalists[bestRun]);
  Finish(mesh, options, refiner, runs[bestRun], result);
  return result;
}
}

SymmetryResult DetectSymmetry(const PreparedMesh& mesh,
  const SymmetryOptions& options,
  const FaceTree* meshFaces)
{
  std::unique_ptr<FaceTree> own;
  if (!meshFaces || &meshFaces->Surface() != &mesh)
    meshFaces = (own = std::make_unique<FaceTree>(mesh)).get();
  if (options.closestFaceFastPath && !options.fastPathQuery)
  {
    // The fast path's query over the mesh: every fine distance is measured to it.
    const std::unique_ptr<ClosestFaceQuery> plain =
      options.closestFaceFastPath(TriangleMesh{ mesh.points, mesh.triangles });
    SymmetryOptions withQuery = options;
    withQuery.fastPathQuery = plain.get();
    if (plain)
      return DetectSymmetry(mesh, withQuery, meshFaces);
  }
  if (options.robust && mesh.NumberOfFaces() > options.sampledSearchAboveFaces)
    return DetectOnSampledCopy(mesh, *meshFaces, options);
  return DetectOn(mesh, *meshFaces, options);
}

namespace
{
/// One detection (DetectOn): the runs tried, in the order they were judged.
class PlaneSearch
{
public:
  PlaneSearch(const PreparedMesh& mesh, const FaceTree& targetFaces, const SymmetryOptions& options)
    : Mesh(mesh)
    , Target(targetFaces.Surface())
    , Options(options)
    , Refine(mesh, targetFaces, options)
  {
  }

  SymmetryResult Detect();

private:
  bool Report(double p) const { return !this->Options.progress || this->Options.progress(p); }
  void Trace(const char* what, size_t k, const Run& run) const
  {
    if (this->Options.trace)
      this->Options.trace(
        FormatTrace("%s %zu: iterations %d/%d region %.3f rms/eps %.3f n=(%.3f %.3f %.3f)",
          what,
          k,
          run.coarseIterations,
          run.fineIterations,
          run.regionArea / this->Mesh.totalArea,
          run.rms / this->Options.epsilon,
          run.plane.normal.x(),
          run.plane.normal.y(),
          run.plane.normal.z()));
  }
  bool SamePlaneAsAny(const std::vector<Plane>& planes, const Plane& p) const
  {
    for (const Plane& q : planes)
      if (SamePlane(q, p, this->Options.epsilon))
        return true;
    return false;
  }

  /// The paper's path: coarse phase from the principal start (or the user's plane).
  void PaperStart();
  /// Probes the starts distinct[first..] (in parallel), then judges them in order; true when
  /// one settles the search (a tight region covering almost the whole mesh).
  bool ProbeStarts(const std::vector<Plane>& distinct,
    size_t first,
    std::vector<Probe>& started,
    std::vector<size_t>& probes,
    size_t& tried);
  /// The other starts: the user's plane, the principal planes of the surface and the voted
  /// planes, appended to `distinct` unless already there.
  void AddCandidateStarts(std::vector<Plane>& distinct) const;
  /// Finishes the best three distinct probes that could still win, in parallel; their runs
  /// go to `finished`.
  void FinishBestProbes(std::vector<size_t>& probes,
    std::vector<size_t>& finished,
    std::vector<size_t>& extra);
  /// The robust search after the paper start; false when aborted.
  bool RobustSearch(SymmetryResult& result,
    std::vector<size_t>& finished,
    std::vector<size_t>& extra);

  const PreparedMesh& Mesh;
  const PreparedMesh& Target;
  const SymmetryOptions& Options;
  Refiner Refine;
  std::vector<Run> Runs;
};

void PlaneSearch::PaperStart()
{
  Run run;
  this->Refine.Coarse(run, this->Options.useInitialPlane ? &this->Options.initialPlane : nullptr);
  if (!this->Options.robust)
    this->Refine.Fine(run, this->Options.maximumIterations);
  this->Refine.Score(run, this->Options.epsilon);
  this->Trace("paper start", 0, run);
  this->Runs.push_back(std::move(run));
}

bool PlaneSearch::ProbeStarts(const std::vector<Plane>& distinct,
  size_t first,
  std::vector<Probe>& started,
  std::vector<size_t>& probes,
  size_t& tried)
{
  const SymmetryOptions& options = this->Options;
  started.resize(distinct.size());
  RunTasksInParallel(started.size() - first,
    [&](size_t i)
    {
      const size_t k = first + i;
      Probe& probe = started[k];
      this->Refine.Seed(probe.run, distinct[k], k == 0 ? &this->Runs[0] : nullptr);
      this->Refine.Fine(probe.run, std::min(options.maximumIterations, 2));
      probe.earlyPlane = probe.run.plane;
      probe.earlySupportArea = RegionArea(this->Mesh, probe.run.support);
      this->Refine.Fine(probe.run, std::min(options.maximumIterations, 4));
      this->Refine.Score(probe.run, options.epsilon);
    });
  bool settled = false;
  for (size_t k = first; k < started.size() && !settled; ++k)
  {
    ++tried;
    Probe& probe = started[k];
    bool duplicate = false;
    for (size_t j : probes)
      duplicate = duplicate || SamePlane(this->Runs[j].plane, probe.earlyPlane, options.epsilon);
    // A probe whose support after two iterations is already below half the best region
    // so far is dropped too: it would not be finished (see PromisingFraction).
    if (!duplicate)
    {
      double bestArea = 0.0;
      for (size_t j : probes)
        bestArea = std::max(bestArea, this->Runs[j].regionArea);
      duplicate = probe.earlySupportArea < PromisingFraction * bestArea;
    }
    if (!duplicate)
    {
      this->Trace("probe", k, probe.run);
      // A tight region covering almost the whole mesh cannot be beaten by the region
      // rule (Better: more than 2% of the area larger): no need to probe further.
      settled = Tight(probe.run, options, this->Mesh.totalArea) &&
        probe.run.regionArea >= (1.0 - GlobalSymmetryMargin) * this->Mesh.totalArea;
      probes.push_back(this->Runs.size());
      this->Runs.push_back(std::move(probe.run));
    }
  }
  return settled;
}

void PlaneSearch::AddCandidateStarts(std::vector<Plane>& distinct) const
{
  // All from the full surface (target: a sampled copy has fewer vertex pairs to vote with;
  // small local symmetries were missed, triceratops 60% -> 50%).
  const SymmetryOptions& options = this->Options;
  std::vector<Plane> seeds;
  if (options.useInitialPlane)
    seeds.push_back(options.initialPlane);
  std::array<Plane, 3> principal;
  if (SurfacePrincipalPlanes(this->Target, principal))
    seeds.insert(seeds.end(), principal.begin(), principal.end());
  for (const Plane& p :
    VotedPlanes(this->Target, options.numberOfCandidates, options.epsilon, options.seed))
    seeds.push_back(p);
  for (const Plane& p : seeds)
    if (!this->SamePlaneAsAny(distinct, p))
      distinct.push_back(p);
}

void PlaneSearch::FinishBestProbes(std::vector<size_t>& probes,
  std::vector<size_t>& chosen,
  std::vector<size_t>& extra)
{
  const SymmetryOptions& options = this->Options;
  std::vector<Run>& runs = this->Runs;
  std::stable_sort(probes.begin(),
    probes.end(),
    [&](size_t a, size_t b) { return Better(runs[a], runs[b], this->Mesh.totalArea, options); });
  for (size_t k : probes)
  {
    bool duplicate = false;
    for (size_t c : chosen)
      duplicate = duplicate || SamePlane(runs[c].plane, runs[k].plane, options.epsilon);
    for (size_t c : extra)
      duplicate = duplicate || SamePlane(runs[c].plane, runs[k].plane, options.epsilon);
    const bool promising = runs[k].regionArea >= PromisingFraction * runs[probes[0]].regionArea;
    if (!duplicate && promising && chosen.size() < RankedFinalists)
      chosen.push_back(k);
    else if (!duplicate && promising && options.scoreEveryFinalist && extra.size() < ExtraFinalists)
      extra.push_back(k);
  }
  std::vector<size_t> all = chosen;
  all.insert(all.end(), extra.begin(), extra.end());
  RunTasksInParallel(all.size(),
    [&](size_t i)
    {
      Run& run = runs[all[i]];
      this->Refine.Fine(run, options.maximumIterations);
      this->Refine.Polish(run, std::min(options.maximumIterations, PolishIterations));
      this->Refine.Score(run, options.epsilon);
    });
  for (size_t k : all)
    this->Trace("final", k, runs[k]);
}

// More starts, each refined directly by a few fine iterations (sigma = 3 epsilon): the
// coarse metric tends to drag a good start away. Probes: two fine iterations each; probes
// that land on the plane of an earlier probe are dropped; the rest get four more iterations
// and are scored by their region. The first probe continues the paper start and comes
// alone: a globally symmetric mesh settles there, and needs no other start. The others run
// in parallel, each serially (RunTasksInParallel), and are then judged one after the other
// exactly as if they had run in turn - the same decisions and results for any thread count,
// at the price of finishing probes that are then dropped.
bool PlaneSearch::RobustSearch(SymmetryResult& result,
  std::vector<size_t>& finished,
  std::vector<size_t>& extra)
{
  const auto t2 = Clock::now();
  std::vector<Plane> distinct{ this->Runs[0].plane };
  std::vector<size_t> probes;
  std::vector<Probe> started;
  size_t tried = 0;
  bool settled = false;
  for (size_t first = 0; first < distinct.size() && !settled; first = started.size())
  {
    settled = this->ProbeStarts(distinct, first, started, probes, tried);
    if (!this->Report(0.2 + (first == 0 ? 0.1 : 0.5)))
      return false;
    if (first == 0 && !settled)
    {
      const auto t1 = Clock::now();
      this->AddCandidateStarts(distinct);
      result.candidateSeconds = Seconds(t1);
    }
  }
  if (!this->Report(0.7))
    return false;
  this->FinishBestProbes(probes, finished, extra);
  if (!this->Report(1.0))
    return false;
  result.fineSeconds = Seconds(t2) - result.candidateSeconds;
  result.startsTried = static_cast<int>(tried);
  return true;
}

SymmetryResult PlaneSearch::Detect()
{
  SymmetryResult result;
  std::vector<size_t> finished; // runs iterated to convergence
  std::vector<size_t> extra;    // ... and not ranked (scoreEveryFinalist)
  const auto t0 = Clock::now();
  this->PaperStart();
  result.coarseSeconds = Seconds(t0);
  if (!this->Report(this->Options.robust ? 0.2 : 0.9))
  {
    result.aborted = true;
    return result;
  }
  if (this->Options.robust)
  {
    if (!this->RobustSearch(result, finished, extra))
    {
      result.aborted = true;
      return result;
    }
  }
  else
    result.startsTried = 1;

  // The result is the best converged run (robust: runs[0], the paper's coarse phase alone,
  // only seeded a probe). Finalists: the converged runs, best first.
  std::vector<Run>& runs = this->Runs;
  if (!this->Options.robust)
    finished.assign(1, 0);
  if (finished.empty()) // no probe at all (cannot happen with a paper start): take any run
    for (size_t k = 0; k < runs.size(); ++k)
      finished.push_back(k);
  std::stable_sort(finished.begin(),
    finished.end(),
    [&](size_t a, size_t b)
    { return Better(runs[a], runs[b], this->Mesh.totalArea, this->Options); });
  for (size_t k : finished)
    result.finalists.push_back(runs[k].plane);
  result.rankedFinalists = result.finalists.size();
  for (size_t k : extra)
    result.finalists.push_back(runs[k].plane);
  Finish(this->Mesh, this->Options, this->Refine, runs[finished[0]], result);
  return result;
}

SymmetryResult DetectOn(const PreparedMesh& mesh,
  const FaceTree& targetFaces,
  const SymmetryOptions& options)
{
  PlaneSearch search(mesh, targetFaces, options);
  return search.Detect();
}
}
}
