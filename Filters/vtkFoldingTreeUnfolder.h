/**
 * @class   vtkFoldingTreeUnfolder
 * @brief   reconstructs the mesh from a folding tree: postorder unfolding, closed fold
 *          lines, stitched and smoothed tears (Folding meshes, SGP 2006, section 4.3)
 *
 * Input: a folding tree as vtkFoldingTreeBuilder writes it (output 0), directly or read back
 * from a .vtm file (the encoding is documented in vtkFoldingTreeBuilder.h). The core unfolder
 * (Filters/Core/FoldingTreeUnfolder.h) mirrors every folding node's child through its plane
 * (reversing the mirrored triangles and merging the fold-line vertices; then it removes the
 * vertices the builder projected onto the plane, RemoveProjectedPoints, and thins the mirrored
 * copy to the face count of the fold's region, MatchDiscardedDensity: a fold whose halves are
 * tessellated differently keeps the denser half, whose mirror image would otherwise double
 * that density), unites the children of segmentation nodes and, with Stitch on, stitches and
 * smooths their tears.
 *
 * Output (vtkPolyData):
 * - every point and cell array the leaves carry (those present in all leaves with the same
 *   type and number of components) on every copy. Floating-point 3-component arrays are
 *   vectors: they are multiplied by the copy's linear map (reflected on mirrored copies),
 *   except arrays named like ids or masks (names ending in Id/Ids/ID/IDs or containing
 *   Mask). The builder's own point arrays (TearMask, PlaneMask, Projected, ErrorBudget,
 *   InputBoundary, InputBorderNeighbors) are not carried; a leaf array named like one of the
 *   unfolder's own arrays is carried as "<name>_input" (with a warning). The input's active
 *   attributes (recorded on the tree's "Tree" block; older trees: the first leaf's) are active
 *   again, except global and pedigree ids whose values the mirrored copies repeat (those stay
 *   plain arrays) and scalars: the active cell scalars are "FoldingLeafId" and no point
 *   scalars are active, so viewers colour the mesh by leaf (the input's scalar arrays stay). A
 *   point merged by stitching takes the values of its lowest copy.
 * - the input's point precision (float or double; trees without the record: double) and its
 *   field arrays (one named like the unfolder's own field data comes back as "<name>_input").
 * - point array "OriginalPointId" (input point id), cell arrays "OriginalCellId",
 *   "FoldingLeafId" (node index of the leaf), "FoldingCopy" (rank of the copy among the
 *   copies of that leaf ordered by mirror mask: 0 = the stored leaf itself),
 *   "FoldingMirrorMask" (vtkTypeUInt64Array, bit d set when the copy was reflected by the
 *   folding node at depth d), "FoldingMirrored" (1 for an odd number of reflections),
 *   "FoldingFilled" (1: a triangle added to fill a seam gap or a hole; its ids and copy are
 *   those of a neighbouring face; a triangle re-triangulated after a point removal only where
 *   every face of the removed star was one).
 * - field data: "UnfoldedFaces", "UnfoldedPoints", "UnfoldedArea", "AreaRatio" (over the
 *   input's area: above 1 where surface lies twice), "FilledAreaRatio" (the area of the
 *   FoldingFilled faces over the input's), "NumberOfCopies", "PlaneMergedVertices",
 *   "RemovedProjectedPoints" and "ProjectedPoints" (RemoveProjectedPoints: removed, left),
 *   "ThinnedCopyPoints" and "FoldExcessFaces" (MatchDiscardedDensity: vertices removed from
 *   mirrored copies and rotation nodes' copies of their sectors, and the faces the folding and
 *   rotation nodes' results still have above the face counts of their regions, summed over
 *   them),
 *   "StitchedVertices", "UnmatchedTearVertices", "OpenGapCount" (boundary edges left between
 *   tear vertices by stitching, before the final repair), "OpenGapLength", "FilledFaces",
 *   "OpenEdges", "NonManifoldEdges", "MisorientedEdges" (edges whose two faces traverse them
 *   in the same direction), "WeldedVertices" (merged or zipped by the final boundary weld),
 *   "BudgetRejectedClusters" (stitches not made: no position within the error budgets), the
 *   final repair's (CloseHoles) "RepairDroppedFaces", "RepairFlippedFaces", "FilledLoops",
 *   "BorderLoops", "BorderEdges" and "BorderLength" (the input's own border, kept open),
 *   "OpenLoops", "OpenLoopEdges" and "OpenLoopLength" (gaps that could not be closed),
 *   "UnknownBorderLoops" (not filled: the tree has no InputBoundary flags), and the tree's
 *   "RootEpsilon" and "Diagonal".
 * Every vertex move (fold-line merges, stitching, zipper, smoothing and a final weld of the
 * open boundaries of different copies within half the root epsilon) is bounded by the error
 * budgets the builder stores in the leaves ("ErrorBudget"; UnfoldOptions in
 * Core/FoldingTreeUnfolder.h), so the output stays within the root epsilon of the input.
 *
 * Optional input port 1, "Original" (vtkPolyData: the mesh the tree was built from; polygons
 * and strips are triangulated, other cells ignored): when connected, the output also gets
 * - point array "DistanceToOriginal": the distance of every output point to the original
 *   surface (exact point-to-triangle distances);
 * - field data "HausdorffToOriginal" (the symmetric Hausdorff distance between the output and
 *   the original, sampled at the vertices and face centroids of both), "MeanDistanceToOriginal"
 *   (the mean of those sampled distances), the same divided by the original's bounding-box
 *   diagonal, "HausdorffToOriginalRelative" and "MeanDistanceToOriginalRelative", and
 *   "OriginalDiagonal";
 * - field data "HausdorffToOriginalBound" (and "HausdorffToOriginalBoundRelative"): the
 *   symmetric Hausdorff distance over every point of both surfaces, not only the samples - a
 *   proved upper bound, within 1e-5 of the diagonal of the true distance (the core's
 *   SymmetricHausdorffBounds: branch and bound over subdivided triangles; if its evaluation
 *   budget runs out first - not seen on real meshes - a warning says the bound is looser).
 * The measure is the core's CompareSurfaces (Filters/Core/SurfaceDistance.h), the one the
 * command line's roundtrip and the Table 1 benchmark use. The paper's bound: with the builder's
 * defaults, HausdorffToOriginal <= RootEpsilon. An original without triangles, with a
 * triangle that refers to a point that does not exist, or with NaN or infinite point
 * coordinates is an error (the request fails), as it is for the builder.
 *
 * A malformed tree (missing plane metadata, wrong node kinds, a block that is not polydata,
 * wrong array sizes; a Diagonal or RootEpsilon that is not positive and finite, differs from
 * the root's epsilon or does not match the extent of the stored points; negative counts;
 * PlaneMask / TearMask bits for levels without a folding / segmentation node above the leaf;
 * no stored triangle at all: FoldingTree::Validate) is reported with vtkErrorMacro and the
 * request fails; NaN parameters too. Leaves without triangles in an otherwise valid tree give
 * a warning (their regions are missing from the output).
 *
 * Parallel runs (pvbatch or pvserver under MPI): when Controller (by default the global
 * controller) has more than one process and the pipeline asks for one of several pieces
 * (ParaView does; a plain Update() asks for the whole data, so nothing is gathered), the tree
 * pieces of all ranks are merged on rank 0 (the builder's tree lives on rank 0; a .vtm read in
 * parallel spreads its blocks over the ranks) and the filter runs once there, so the unfolded mesh
 * does not depend on how the data is distributed. Rank 0 holds the output; the outputs of the other
 * ranks are empty (an empty tree there is not an error); the result getters give the same values on
 * every rank.
 */
#ifndef vtkFoldingTreeUnfolder_h
#define vtkFoldingTreeUnfolder_h

#include "FoldingMeshesFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class vtkAbstractCellLocator;
class vtkAlgorithmOutput;
class vtkMultiProcessController;
class vtkPolyData;

class FOLDINGMESHESFILTERS_EXPORT vtkFoldingTreeUnfolder : public vtkPolyDataAlgorithm
{
public:
  static vtkFoldingTreeUnfolder* New();
  vtkTypeMacro(vtkFoldingTreeUnfolder, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Stitch and smooth the tears at segmentation nodes (default on); off: the raw union of the
   * copies, with no final weld (WeldBoundaries) or repair (CloseHoles) either.
   */
  vtkSetMacro(Stitch, bool);
  vtkGetMacro(Stitch, bool);
  vtkBooleanMacro(Stitch, bool);
  ///@}

  ///@{
  /**
   * Tear vertices of different children closer than StitchToleranceScale times the
   * segmentation node's epsilon may be merged (default 1, range 0..100); between the sectors of
   * a rotation node, a tenth of that (their seams were made to meet by the builder; above order
   * 31, sin(180/k) of it).
   */
  vtkSetClampMacro(StitchToleranceScale, double, 0.0, 100.0);
  vtkGetMacro(StitchToleranceScale, double);
  ///@}

  ///@{
  /** Insert unpaired tear vertices into open seam edges (default on). */
  vtkSetMacro(Zipper, bool);
  vtkGetMacro(Zipper, bool);
  vtkBooleanMacro(Zipper, bool);
  ///@}

  ///@{
  /** Fill the small boundary loops left along seams (default on). */
  vtkSetMacro(FillSeamGaps, bool);
  vtkGetMacro(FillSeamGaps, bool);
  vtkBooleanMacro(FillSeamGaps, bool);
  ///@}

  ///@{
  /** Constrained Laplacian smoothing of the seams: iterations (default 3, range 0..1000). */
  vtkSetClampMacro(SmoothingIterations, int, 0, 1000);
  vtkGetMacro(SmoothingIterations, int);
  /** ... and the step weight per iteration (default 0.5, range 0..1). */
  vtkSetClampMacro(SmoothingWeight, double, 0.0, 1.0);
  vtkGetMacro(SmoothingWeight, double);
  ///@}

  ///@{
  /**
   * Bound every vertex move (fold-line merges, stitches, zipper, smoothing, the final weld)
   * by the leaf point's ErrorBudget, what the folds above left of the root tolerance, so the
   * result stays within it (default on). Off: seams close more, the bound may break.
   */
  vtkSetMacro(RespectErrorBudget, bool);
  vtkGetMacro(RespectErrorBudget, bool);
  vtkBooleanMacro(RespectErrorBudget, bool);
  ///@}

  ///@{
  /**
   * After mirroring at a fold, remove the vertices the builder projected onto its plane
   * (the leaves' "Projected" point array) and re-triangulate their 1-rings (default on): a
   * face straddling the fold line then comes back as one face across it, as in the input,
   * instead of two (itself with a vertex on the plane, and its mirror image). A vertex stays
   * where the new faces would flip, repeat an edge, or move the surface by more than the
   * point's error budget (UnfoldOptions::removeProjectedPoints). Reported in the field data
   * ("RemovedProjectedPoints", and "ProjectedPoints": copies of projected points left).
   */
  vtkSetMacro(RemoveProjectedPoints, bool);
  vtkGetMacro(RemoveProjectedPoints, bool);
  vtkBooleanMacro(RemoveProjectedPoints, bool);
  ///@}

  ///@{
  /**
   * After mirroring at a fold, thin the mirrored copy until the fold's result has about the
   * face count of its region S (default on): a fold whose two halves were tessellated
   * differently keeps the half with more faces, and its mirror image would double that
   * half's density where the discarded half was coarser. Interior vertices of the copy are
   * removed and their 1-rings re-triangulated as for RemoveProjectedPoints, each move
   * bounded by the point's error budget; the kept half, seams and fold lines stay as they
   * are (UnfoldOptions::matchDiscardedDensity). A folding root's copy is thinned once more
   * after the final repair (CloseHoles), where seam gaps it closed had kept points of the copy
   * on open edges, never below the input's point count. A rotation node's k copies of its
   * sector are thinned the same way towards its region's face count (a sector cut along its
   * half-planes holds more faces than its share), after its seams are stitched (they are
   * thinned with the copies, interior by then). Reported in the field data ("ThinnedCopyPoints",
   * and "FoldExcessFaces": faces the folds' and rotations' results still have above their regions'
   * counts).
   */
  vtkSetMacro(MatchDiscardedDensity, bool);
  vtkGetMacro(MatchDiscardedDensity, bool);
  vtkBooleanMacro(MatchDiscardedDensity, bool);
  ///@}

  ///@{
  /**
   * Finally weld the open boundaries of different copies once more (default on): a vertex on
   * an open edge may merge with, or be zipped into, one of another copy within
   * WeldToleranceScale x the root tolerance (default 0.5, range 0..10); two open vertices of
   * one copy merge only within a hundredth of the root tolerance (or the weld tolerance if
   * smaller): the two sides of a fold-line sliver, or an input crack that narrow. No gaps are
   * filled. Only with Stitch on: Stitch off gives the raw union of the copies.
   */
  vtkSetMacro(WeldBoundaries, bool);
  vtkGetMacro(WeldBoundaries, bool);
  vtkBooleanMacro(WeldBoundaries, bool);
  vtkSetClampMacro(WeldToleranceScale, double, 0.0, 10.0);
  vtkGetMacro(WeldToleranceScale, double);
  ///@}

  ///@{
  /**
   * Finally repair the mesh (default on): drop the faces that make an edge non-manifold
   * (except at the input's own non-manifold edges, the tree's "InputNonManifoldEdges": they
   * keep up to as many faces as the input edge had), orient every connected component
   * consistently, and fill each boundary loop that is not
   * the input's own border (the leaves' "InputBoundary" point array; trees without it: no
   * loop is filled) by a minimal-area triangulation of its vertices, when every new face
   * stays within HoleToleranceScale x the root tolerance of the loop (default 1, range
   * 0..10) and the loop has at most MaximumHoleEdges edges (default 400, range 3..100000).
   * Loops left open are reported ("OpenLoops", "OpenLoopEdges", "OpenLoopLength"). Only with
   * Stitch on: Stitch off gives the raw union of the copies.
   */
  vtkSetMacro(CloseHoles, bool);
  vtkGetMacro(CloseHoles, bool);
  vtkBooleanMacro(CloseHoles, bool);
  vtkSetClampMacro(HoleToleranceScale, double, 0.0, 10.0);
  vtkGetMacro(HoleToleranceScale, double);
  vtkSetClampMacro(MaximumHoleEdges, int, 3, 100000);
  vtkGetMacro(MaximumHoleEdges, int);
  ///@}

  ///@{
  /**
   * The optional original mesh (input port 1) to measure the output against; see above.
   * SetOriginalData(nullptr) disconnects it.
   */
  void SetOriginalData(vtkPolyData* original);
  void SetOriginalConnection(vtkAlgorithmOutput* output);
  ///@}

  ///@{
  /**
   * The cell locator that answers the point-to-surface distance queries against the original
   * (DistanceToOriginal, HausdorffToOriginal and the proved HausdorffToOriginalBound, both
   * ways). nullptr (the default): a vtkStaticCellLocator. A locator set here is not used
   * itself: a new instance of its class is built per surface (its settings are not copied);
   * locators other than vtkStaticCellLocator are queried by one thread at a time. The field
   * data "DistanceLocator" names the class used.
   */
  virtual void SetLocator(vtkAbstractCellLocator*);
  vtkGetObjectMacro(Locator, vtkAbstractCellLocator);
  ///@}

  ///@{
  /** Results of the last run. */
  vtkGetMacro(OpenGapCount, int);
  vtkGetMacro(OpenGapLength, double);
  vtkGetMacro(StitchedVertices, int);
  vtkGetMacro(OpenEdges, int);
  /** With an original: its Hausdorff distance to the output (-1 without one). */
  vtkGetMacro(HausdorffToOriginal, double);
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
  vtkFoldingTreeUnfolder();
  ~vtkFoldingTreeUnfolder() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /** RequestData of a serial run, or of rank 0 on the gathered input. */
  int RequestWholeData(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  /// Adds DistanceToOriginal and the *ToOriginal field data; false on an unusable original.
  bool MeasureToOriginal(vtkPolyData* original, vtkPolyData* output);

  bool Stitch = true;
  double StitchToleranceScale = 1.0;
  bool Zipper = true;
  bool FillSeamGaps = true;
  int SmoothingIterations = 3;
  double SmoothingWeight = 0.5;
  bool RespectErrorBudget = true;
  bool RemoveProjectedPoints = true;
  bool MatchDiscardedDensity = true;
  bool WeldBoundaries = true;
  double WeldToleranceScale = 0.5;
  bool CloseHoles = true;
  double HoleToleranceScale = 1.0;
  int MaximumHoleEdges = 400;

  int OpenGapCount = 0;
  double OpenGapLength = 0.0;
  int StitchedVertices = 0;
  int OpenEdges = 0;
  double HausdorffToOriginal = -1.0;

  vtkMultiProcessController* Controller = nullptr;
  vtkAbstractCellLocator* Locator = nullptr;

private:
  vtkFoldingTreeUnfolder(const vtkFoldingTreeUnfolder&) = delete;
  void operator=(const vtkFoldingTreeUnfolder&) = delete;
};

#endif
