// Symmetric region detection: the IRLS of the paper's section 3, with several starts.
#ifndef foldingmeshes_SymmetryDetection_h
#define foldingmeshes_SymmetryDetection_h

#include "ClosestFaceQuery.h"
#include "FaceTree.h"
#include "Plane.h"
#include "Trace.h"

#include <functional>
#include <vector>

namespace foldingmeshes
{
/// Meshes with more faces than this are searched for candidate planes on a sampled copy by
/// default (SymmetryOptions::sampledSearchAboveFaces).
constexpr int SampledSearchAboveFaces = 15000;
/// The sampled copy has about this fraction of the mesh's faces ...
constexpr double SampledFaceFraction = 0.25;
/// ... and at most this many.
constexpr int MaximumSampledFaces = 30000;

struct SymmetryOptions
{
  double epsilon = 0.0; ///< tolerance as a length (required, > 0)
  bool robust = true;   ///< several starts judged by final region; false: the paper
  bool useInitialPlane = false;
  Plane initialPlane;         ///< replaces the first closed-form step when used
  int numberOfCandidates = 8; ///< voted starts (robust only)
  int maximumIterations = 50; ///< per phase
  double compatibilityAngle = 45.0;
  double minimumSymmetricAreaFraction = 0.1;
  unsigned seed = 1;
  /// Robust only: meshes with more faces than this search their candidate planes on a
  /// sampled copy (see DetectSymmetry).
  int sampledSearchAboveFaces = SampledSearchAboveFaces;
  /// With the sampled search, the copy's finalists get the fine and polish iterations on
  /// the full mesh before they are scored there; false: they are only scored (for callers
  /// that refine the plane on its region themselves, like the folding-tree builder).
  bool refineSampledFinalists = true;
  /// Up to three more probes are finished after the ranked finalists and returned after them
  /// in SymmetryResult::finalists (unranked: the result is the same), and with the sampled
  /// search every finalist of the copy is scored on the full mesh, also when the first one
  /// settles the search: the folding-tree builder tries them as other planes for regions of
  /// several parts, where the connected regions that rank them can miss symmetry between parts.
  bool scoreEveryFinalist = false;
  /// SymmetryResult::distance up to 3 sigma (9 epsilon: the detector's SymmetryDistance
  /// output), one more distance pass at the end; false: only those below epsilon are finite
  /// (the folding-tree builder needs no more). The plane and the regions are the same.
  bool distancesUpTo3Sigma = true;
  /// A fast path for the fine distances (issue 19): a plain closest-face query over the
  /// mesh (the VTK layer's vtkStaticCellLocator, vtkCellLocatorFaceQuery.h) asked before the
  /// face tree, whose answer is taken where it is the closest compatible face
  /// (MirrorDistance::SetFastPath). The same planes and regions; slower on every mesh
  /// measured (docs/benchmarks.md), so empty (off) by default.
  ClosestFaceQueryFactory closestFaceFastPath;
  /// Called with progress in [0,1]; return false to abort.
  std::function<bool(double)> progress;
  /// Diagnostics: every run (start, iterations, region, RMS/epsilon, plane) and region
  /// statistics, one line each (Trace.h; empty: none).
  TraceSink trace;
  /// Internal: the query DetectSymmetry made from closestFaceFastPath (callers leave it null).
  const ClosestFaceQuery* fastPathQuery = nullptr;
};

struct SymmetryResult
{
  Plane plane;
  bool found = false; ///< the documented "symmetry found" rule holds
  bool aborted = false;
  /// Fine d_i per vertex (infinite: no compatible face near; see distancesUpTo3Sigma).
  std::vector<double> distance;
  std::vector<double> weight;  ///< final IRLS weight per vertex
  std::vector<char> faceLabel; ///< 2 symmetric region, 1 support only, 0 outside
  double symmetricArea = 0.0;
  double symmetricAreaFraction = 0.0;
  double rmsResidual = 0.0; ///< area-weighted RMS of d over the symmetric region
  int coarseIterations = 0;
  int fineIterations = 0;
  std::vector<double> costHistory; ///< sum of rho per iteration, coarse then fine
  int startsTried = 0;
  std::vector<Plane> finalists; ///< planes of the runs iterated to convergence, best first
  /// How many of the finalists the search itself scored: fewer than finalists.size() when
  /// the first settled it and the others were only scored for scoreEveryFinalist.
  size_t rankedFinalists = 0;
  double coarseSeconds = 0.0, fineSeconds = 0.0, candidateSeconds = 0.0;
};

/**
 * Finds the plane p and the largest connected region S symmetric under p within epsilon.
 * The paper's iteration (coarse metric to convergence, then the fine metric) is run from
 * one start (paper) or several (robust: the principal start, every principal plane, the
 * user's plane and the voted planes); the winner has the largest final region, ties
 * (within 2% of the area) going to the lower residual.
 * SymmetryFound: area(S) >= minimumSymmetricAreaFraction * area(M) and the area-weighted
 * RMS of d over S <= 0.35 epsilon.
 */
SymmetryResult DetectSymmetry(const PreparedMesh& mesh,
  const SymmetryOptions& options,
  const FaceTree* meshFaces = nullptr);
// `meshFaces`: a FaceTree of `mesh` (its Surface() is `mesh`) the caller already has (else
// one is built).
// Meshes with more faces than options.sampledSearchAboveFaces (robust method) are searched
// on a sampled copy: about SampledFaceFraction of the faces (at most MaximumSampledFaces) by
// vertex clustering whose points are vertices of the mesh (ClusterVertices), iterated with
// their distances measured to the full mesh - so an exact symmetry stays exact; the copy's
// finalists are then refined (refineSampledFinalists) and scored on the full mesh: a tight
// first one settles it, else all of them are, and the best wins.
// The probes after the first and the finals run in parallel (vtkSMPTools), so an abort
// requested through `progress` takes effect after a batch of probes or the finals.
// SymmetryOptions::trace receives every run (start, iterations, region, RMS/epsilon, plane)
// and region statistics.

/// The "symmetry found" residual rule: area-weighted RMS of d over S <= this * epsilon.
constexpr double FoundResidualRatio = 0.35;
}

#endif
