/**
 * @class   vtkSymmetryPlaneDetector
 * @brief   finds the dominant planar reflection symmetry of a triangle mesh and
 *          the largest connected region that has it (Folding meshes, SGP 2006, section 3)
 *
 * The filter fits a mirror plane p and a connected symmetric region S to a
 * surface mesh by iteratively reweighted least squares with the Geman-McClure
 * estimator: every vertex is reflected through the current plane, its distance
 * d_i to the closest *compatible* face of the mesh is measured (a face whose
 * interpolated normal at the closest point is within CompatibilityAngle of
 * the reflected vertex normal), the weights w_i = (1/d) d rho/dd times the
 * vertex area give a weighted centroid and covariance whose eigenvectors span
 * three candidate planes; the one with the lowest sum of rho wins. The
 * support region (faces whose vertices all have d <= 2 sigma, largest
 * connected part) restricts the next fit. A coarse phase (distance to the
 * plane of the face with the nearest centroid, sigma = 1.4826 median(d), never
 * below 3 epsilon) is followed by a fine phase (exact compatible distance,
 * sigma = 3 epsilon). The result is the plane and S, the largest connected set
 * of faces whose vertex distances are all below epsilon.
 *
 * Two methods:
 * - ROBUST (default): several starts -- the result of the paper's coarse phase,
 *   the principal planes of the surface, the optional user plane, and planes
 *   voted for by sampled vertex pairs with mirror-compatible normals -- are each
 *   refined by fine iterations whose plane step is a Gauss-Newton fit of the
 *   mirrored vertices to their partners' tangent planes (instead of the
 *   principal axes of the weighted vertices, which drift when mirror images
 *   carry unequal vertex areas). The winner has a tight region (RMS distance
 *   within the SymmetryFound rule) if any does, then the largest final
 *   symmetric region (ties within 2% of the area: the lower RMS residual), not
 *   the lowest sum of rho. This finds local symmetries on asymmetric bodies and
 *   resists large asymmetric attachments. The finalists end with a polish
 *   phase at sigma = epsilon (support d <= 2 epsilon). Meshes above
 *   SampledSearchAboveFaces (15k) faces search candidates on a sampled copy
 *   (some of their own vertices, measured against the full mesh) and refine
 *   the best on the full mesh.
 * - PAPER: exactly one start (the principal axes of the area-weighted mesh, or
 *   the user's initial plane), as in the paper.
 *
 * Inputs with several parts (separate connected components): with
 * ConnectNearbyParts on (default), faces of different parts whose vertices lie
 * within epsilon of each other count as connected, so a symmetric region may
 * span touching or interpenetrating parts (artist meshes often are made that
 * way). Off: strict edge connectivity, as in the paper.
 *
 * Output 0: the triangulated input (all its point and cell arrays kept; one named like an
 * array below is renamed "<name>_input", with a warning) plus
 * - cell array  "SymmetryRegion": 2 symmetric, 1 support only, 0 outside;
 * - point array "SymmetryDistance": fine distance d_i of the reflected vertex;
 * - point array "SymmetryWeight": final IRLS weight (0 outside the support);
 * - field data  "SymmetryPlaneOrigin", "SymmetryPlaneNormal" (3 components),
 *   "SymmetricAreaFraction", "SymmetryFound" (0/1), "SymmetryTolerance"
 *   (epsilon as a length), "SymmetryCostHistory" (sum of rho per iteration,
 *   coarse then fine, of the winning start), "SymmetryIterations" (coarse, fine).
 * Output 1: the plane glyph: a quad on the plane covering the projection of
 * the symmetric region with a 10% margin, with the same plane field data.
 *
 * Rotational symmetry (DetectRotation, off by default): the filter also looks for an axis
 * and the largest order k (2 <= k <= MaximumRotationOrder) such that turning the mesh by
 * 360/k degrees about the axis maps a region of it onto itself within epsilon (the paper's
 * future work, "axial symmetries"). Candidate axes are the surface's principal axes, those
 * of its large separate parts, and the lines where two of the mirror planes tried above
 * meet; for each, every turn j/k of an order must keep the same share of a vertex sample
 * (so a near-identity turn cannot pass alone, and a multiple of the true order fails); the
 * best is refined by Gauss-Newton on the axis. A surface of revolution within epsilon passes
 * every order: RotationContinuous is 1 and RotationOrder is MaximumRotationOrder. With it:
 * - output 0 gains cell array "RotationRegion" (1: its vertices map within epsilon under the
 *   turns by 360/k and by floor(k/2) 360/k degrees) and point array "RotationDistance"
 *   (the larger distance of the two turned copies of the vertex; NaN beyond 3 epsilon);
 * - field data "RotationAxisOrigin", "RotationAxisDirection" (3 components; the direction's
 *   largest component positive, the origin nearest the bounding-box centre),
 *   "RotationOrder" (0: no candidate passed), "RotationFound" (0/1: the region covers at
 *   least MinimumSymmetricAreaFraction of the area with an area-weighted RMS distance of
 *   at most 0.35 epsilon), "RotationContinuous" (0/1), "RotationalAreaFraction";
 * - output 2: the axis glyph, a line along the axis over the extent of the region (of the
 *   mesh if the region is empty) with a 10% margin, carrying the same field data.
 * Off, output 2 is empty and none of these arrays is added. The progress bar covers both
 * searches (the plane's first 40%); an abort during the rotation search keeps the plane's
 * outputs and adds no rotation result (with a warning).
 *
 * "No symmetry" rule: SymmetryFound is 1 when the symmetric region covers at
 * least MinimumSymmetricAreaFraction of the mesh area and the area-weighted
 * RMS distance over it is at most 0.35 epsilon; otherwise the best plane is
 * still reported, with SymmetryFound = 0.
 *
 * Bad input (no points, no polygons, a triangle referring to a point that does
 * not exist, NaN/Inf coordinates, zero total area) and bad parameters (NaN,
 * which the clamping setters let through; a tolerance length that is not
 * positive and finite; with UseInitialPlane a zero or non-finite normal or
 * origin) are reported with vtkErrorMacro and the request fails.
 *
 * Parallel runs (pvbatch or pvserver under MPI): when Controller (by default the global
 * controller) has more than one process and the pipeline asks for one of several pieces
 * (ParaView does; a plain Update() asks for the whole data, so nothing is gathered), the input
 * pieces of all ranks are gathered on rank 0 and the filter runs once there, so the plane and the
 * region do not depend on how the data is distributed. Rank 0 holds the outputs; the outputs of the
 * other ranks are empty (an empty input piece there is not an error); the result getters give the
 * same values on every rank.
 */
#ifndef vtkSymmetryPlaneDetector_h
#define vtkSymmetryPlaneDetector_h

#include "FoldingMeshesFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class vtkAbstractCellLocator;
class vtkMultiProcessController;

#include <memory> // for std::unique_ptr

class FOLDINGMESHESFILTERS_EXPORT vtkSymmetryPlaneDetector : public vtkPolyDataAlgorithm
{
public:
  static vtkSymmetryPlaneDetector* New();
  vtkTypeMacro(vtkSymmetryPlaneDetector, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ToleranceModes
  {
    RELATIVE_TO_DIAGONAL = 0,
    ABSOLUTE = 1
  };
  enum Methods
  {
    ROBUST = 0,
    PAPER = 1
  };

  ///@{
  /**
   * The symmetry tolerance epsilon. With ToleranceMode RELATIVE_TO_DIAGONAL
   * (default) it is a fraction of the bounding-box diagonal (default 0.02,
   * the paper's 2%); with ABSOLUTE it is a length. Clamped to [1e-12, 1e30].
   */
  vtkSetClampMacro(Tolerance, double, 1e-12, 1e30);
  vtkGetMacro(Tolerance, double);
  vtkSetClampMacro(ToleranceMode, int, RELATIVE_TO_DIAGONAL, ABSOLUTE);
  vtkGetMacro(ToleranceMode, int);
  ///@}

  ///@{
  /** ROBUST (default, several starts judged by final region) or PAPER (the paper: one start). */
  vtkSetClampMacro(Method, int, ROBUST, PAPER);
  vtkGetMacro(Method, int);
  ///@}

  ///@{
  /**
   * Optional initial plane replacing the paper's first closed-form step.
   * Off by default; origin (0,0,0), normal (1,0,0). The normal need not be unit.
   */
  vtkSetMacro(UseInitialPlane, bool);
  vtkGetMacro(UseInitialPlane, bool);
  vtkBooleanMacro(UseInitialPlane, bool);
  vtkSetVector3Macro(InitialPlaneOrigin, double);
  vtkGetVector3Macro(InitialPlaneOrigin, double);
  vtkSetVector3Macro(InitialPlaneNormal, double);
  vtkGetVector3Macro(InitialPlaneNormal, double);
  ///@}

  ///@{
  /** Number of voted candidate planes tried by the ROBUST method (default 8, range 0..64). */
  vtkSetClampMacro(NumberOfCandidates, int, 0, 64);
  vtkGetMacro(NumberOfCandidates, int);
  ///@}

  ///@{
  /**
   * With the ROBUST method, meshes with more faces than this search their candidate planes on
   * a sampled copy with a quarter of the faces (at most 30k; its points are vertices of the
   * mesh, its distances measured to the full mesh) and refine the copy's best finalists on the
   * full mesh (default 15000: above it the full search took 2-13 s on artist-like meshes and
   * the sampled one found the same regions on every mesh measured). 0: every mesh; a value
   * above the input's face count: the full search (range 0..1e9).
   */
  vtkSetClampMacro(SampledSearchAboveFaces, int, 0, 1000000000);
  vtkGetMacro(SampledSearchAboveFaces, int);
  ///@}

  ///@{
  /** Iteration cap of each phase (coarse, fine). Default 50, range 1..1000. */
  vtkSetClampMacro(MaximumIterations, int, 1, 1000);
  vtkGetMacro(MaximumIterations, int);
  ///@}

  ///@{
  /** Normal compatibility angle in degrees (default 45, the paper's; range 1..90). */
  vtkSetClampMacro(CompatibilityAngle, double, 1.0, 90.0);
  vtkGetMacro(CompatibilityAngle, double);
  ///@}

  ///@{
  /** Let regions span parts that touch within epsilon (default on). */
  vtkSetMacro(ConnectNearbyParts, bool);
  vtkGetMacro(ConnectNearbyParts, bool);
  vtkBooleanMacro(ConnectNearbyParts, bool);
  ///@}

  ///@{
  /** Minimum symmetric area fraction for SymmetryFound (default 0.1, range 0..1). */
  vtkSetClampMacro(MinimumSymmetricAreaFraction, double, 0.0, 1.0);
  vtkGetMacro(MinimumSymmetricAreaFraction, double);
  ///@}

  ///@{
  /** Seed of the candidate sampling (default 1); results are deterministic for a seed. */
  vtkSetMacro(RandomSeed, int);
  vtkGetMacro(RandomSeed, int);
  ///@}

  ///@{
  /** Also find the best rotational axis and order (default off; see above). */
  vtkSetMacro(DetectRotation, bool);
  vtkGetMacro(DetectRotation, bool);
  vtkBooleanMacro(DetectRotation, bool);
  ///@}

  ///@{
  /** Largest rotation order tried (default 64, range 2..360). */
  vtkSetClampMacro(MaximumRotationOrder, int, 2, 360);
  vtkGetMacro(MaximumRotationOrder, int);
  ///@}

  ///@{
  /** Rotation results, valid after Update() with DetectRotation on (else 0). */
  vtkGetVector3Macro(RotationAxisOrigin, double);
  vtkGetVector3Macro(RotationAxisDirection, double);
  vtkGetMacro(RotationOrder, int);
  vtkGetMacro(RotationFound, bool);
  vtkGetMacro(RotationContinuous, bool);
  vtkGetMacro(RotationalAreaFraction, double);
  ///@}

  ///@{
  /** Results, valid after Update(). */
  vtkGetVector3Macro(PlaneOrigin, double);
  vtkGetVector3Macro(PlaneNormal, double);
  vtkGetMacro(SymmetricAreaFraction, double);
  vtkGetMacro(SymmetryFound, bool);
  /** Reweighting iterations of the winning start: coarse (sigma = 3 epsilon), fine (epsilon). */
  vtkGetMacro(CoarseIterations, int);
  vtkGetMacro(FineIterations, int);
  /** Epsilon as a length, as used by the last run. */
  vtkGetMacro(ToleranceLength, double);
  ///@}

  ///@{
  /**
   * A cell locator as a fast path of the fine mirror distances (issue 19): each reflected
   * vertex first asks it for the closest triangle; when that triangle's interpolated normal
   * is compatible, its distance bounds the core's face-tree search, which then decides among
   * the triangles that close. The planes, regions and distances are bit for bit those
   * without it, but detection is slower on every mesh measured (5-15x, docs/benchmarks.md),
   * so nullptr (the default): the face tree alone. A locator set here is not used itself: a
   * new instance of its class is built over the surface (its settings are not copied);
   * locators other than vtkStaticCellLocator are queried by one thread at a time. C++ and
   * Python only: ParaView keeps the default.
   */
  virtual void SetLocator(vtkAbstractCellLocator*);
  vtkGetObjectMacro(Locator, vtkAbstractCellLocator);
  ///@}

  ///@{
  /**
   * Controller of a parallel run (default: the global controller, if any). With more than
   * one process the filter gathers its input on rank 0 (see above); nullptr makes every
   * process run on its own piece.
   */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

protected:
  vtkSymmetryPlaneDetector();
  ~vtkSymmetryPlaneDetector() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /** RequestData of a serial run, or of rank 0 on the gathered input. */
  int RequestWholeData(vtkInformation*, vtkInformationVector**, vtkInformationVector*);

  double Tolerance = 0.02;
  int ToleranceMode = RELATIVE_TO_DIAGONAL;
  int Method = ROBUST;
  bool UseInitialPlane = false;
  double InitialPlaneOrigin[3] = { 0.0, 0.0, 0.0 };
  double InitialPlaneNormal[3] = { 1.0, 0.0, 0.0 };
  int NumberOfCandidates = 8;
  int SampledSearchAboveFaces = 15000;
  int MaximumIterations = 50;
  double CompatibilityAngle = 45.0;
  bool ConnectNearbyParts = true;
  double MinimumSymmetricAreaFraction = 0.1;
  int RandomSeed = 1;
  bool DetectRotation = false;
  int MaximumRotationOrder = 64;

  double RotationAxisOrigin[3] = { 0.0, 0.0, 0.0 };
  double RotationAxisDirection[3] = { 0.0, 0.0, 0.0 };
  int RotationOrder = 0;
  bool RotationFound = false;
  bool RotationContinuous = false;
  double RotationalAreaFraction = 0.0;

  double PlaneOrigin[3] = { 0.0, 0.0, 0.0 };
  double PlaneNormal[3] = { 1.0, 0.0, 0.0 };
  double SymmetricAreaFraction = 0.0;
  bool SymmetryFound = false;
  int CoarseIterations = 0;
  int FineIterations = 0;
  double ToleranceLength = 0.0;

  vtkMultiProcessController* Controller = nullptr;
  vtkAbstractCellLocator* Locator = nullptr;

private:
  vtkSymmetryPlaneDetector(const vtkSymmetryPlaneDetector&) = delete;
  void operator=(const vtkSymmetryPlaneDetector&) = delete;
};

#endif
