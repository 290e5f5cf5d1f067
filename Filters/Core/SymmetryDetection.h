// Symmetric region detection: the IRLS of the paper's section 3, with several starts.
#ifndef foldingmeshes_SymmetryDetection_h
#define foldingmeshes_SymmetryDetection_h

#include "Plane.h"

#include <functional>
#include <vector>

namespace foldingmeshes
{
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
  /// Called with progress in [0,1]; return false to abort.
  std::function<bool(double)> progress;
};

struct SymmetryResult
{
  Plane plane;
  bool found = false; ///< the documented "symmetry found" rule holds
  bool aborted = false;
  std::vector<double> distance; ///< fine d_i per vertex (infinite: no compatible face near)
  std::vector<double> weight;   ///< final IRLS weight per vertex
  std::vector<char> faceLabel;  ///< 2 symmetric region, 1 support only, 0 outside
  double symmetricArea = 0.0;
  double symmetricAreaFraction = 0.0;
  double rmsResidual = 0.0; ///< area-weighted RMS of d over the symmetric region
  int coarseIterations = 0;
  int fineIterations = 0;
  std::vector<double> costHistory; ///< sum of rho per iteration, coarse then fine
  int startsTried = 0;
  std::vector<Plane> finalists; ///< planes of the runs iterated to convergence, best first
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
SymmetryResult DetectSymmetry(const PreparedMesh& mesh, const SymmetryOptions& options);
// Setting the environment variable FOLDINGMESHES_DEBUG prints every run (start, iterations,
// region, RMS/epsilon, plane) and region statistics to stderr.

/// DetectSymmetry without the simplified-copy candidate search of very large meshes.
SymmetryResult DetectSymmetryOnFullMesh(const PreparedMesh& mesh, const SymmetryOptions& options);

/// Meshes with more faces than this are searched for candidate planes on a simplified
/// copy (SimplifiedMeshFaces faces); the finalists are then refined on the full mesh.
constexpr int SimplifyAboveFaces = 50000;
/// The "symmetry found" residual rule: area-weighted RMS of d over S <= this * epsilon.
constexpr double FoundResidualRatio = 0.35;
constexpr int SimplifiedMeshFaces = 30000;
}

#endif
