/**
 * @class   vtkFoldingTreeBuilder
 * @brief   folds a triangle mesh into a folding tree of non-redundant leaves and mirror
 *          planes (Folding meshes, SGP 2006, sections 4.1-4.2)
 *
 * The filter triangulates its vtkPolyData input and runs the core builder
 * (Filters/Core/FoldingTreeBuilder.h): in preorder, a region that meets a stop criterion
 * becomes a leaf; otherwise the largest connected symmetric region S and its plane p are
 * detected (vtkSymmetryPlaneDetector's algorithm) with the node's tolerance epsilon; when S
 * is the whole region the node is a folding node (the kept half is built recursively with
 * epsilon / 2), else a segmentation node with children fold(S) and one subtree per connected
 * component of the remaining faces. See the core header for the exact rules (trimming,
 * plane snapping, the "no meaningful symmetry" rule).
 *
 * Output 0 (vtkMultiBlockDataSet), the folding tree. Names and arrays below are API
 * (vtkFoldingTreeUnfolder reads them; a tree read back from a .vtm file is the same):
 * - top level: block 0 = the root node, block 1 = "Tree", a vtkPolyData holding one marker
 *   point (the centroid of the stored points, no cell) whose field data holds OriginalFaces,
 * OriginalPoints, DroppedFaces, StoredFaces, StoredPoints, Compression (1 - stored/original),
 * TreeHeight, NumberOfNodes, NumberOfLeaves, NumberOfFolds, NumberOfRotations,
 * RotationNodesTried (1 where rotation nodes were looked for: RotationNodes on, or
 * WHEN_AXIAL and the input's second moments axially symmetric; 0 in a tree read from .fmz),
 * MaximumFoldsOnPath, OriginalArea,
 * BuildSeconds, RootEpsilon, Diagonal, Aborted, VerifiedBound, PinnedFaces and
 * VerificationRounds (see VerifyBound; optional on reading), RequestedEpsilon (the builder's
 * Tolerance as a length; RootEpsilon is smaller after a near-miss rebuild; not read back),
 * InputNonManifoldEdges (vtkIdType, 3
 * components per edge of the input used by more than two faces: its input point ids a < b and
 * the number of faces; only when there are any; optional on reading: the tree's
 * inputNonManifoldEdges, whose faces the unfolder's repair keeps), and what the unfolder
 * restores of the input:
 * its field arrays (each under "InputField:" + its name), "InputPointAttributes" and
 * "InputCellAttributes" (string arrays, an entry "k:name" per vtkDataSetAttributes attribute
 * type k: the name of its active scalars, vectors, normals, tcoords, tensors, global ids,
 * pedigree ids, ...; "k:" for none) and "InputPointsDataType" (VTK type id of its points).
 * - every node block is named after its node index i (preorder, as in the core tree):
 *   "Leaf i", "Fold i (depth d)", "Segmentation i (depth d)", "Rotation i (depth d, order k)".
 * - a leaf is a vtkPolyData (the leaf mesh: double points, triangles) carrying every point
 *   and cell array of the triangulated input (values copied by original id, active point
 *   attributes kept; unnamed arrays named "UnnamedPointArray<k>" / "UnnamedCellArray<k>";
 *   arrays VTK's XML files cannot store, e.g. vtkVariantArray, left out; an input array named
 *   like one of the tree's or the unfolder's own arrays carried as "<name>_input"; each with a
 *   warning), point arrays "OriginalPointId" (vtkIdType), "TearMask" and
 *   "PlaneMask" (vtkTypeUInt64Array, bit d = tree level d, see Core/FoldingTree.h),
 *   "Projected" (unsigned char 0/1), "ErrorBudget" (double: how far the unfolder may still
 *   move the point without breaking the root epsilon bound; optional on reading),
 *   "InputBoundary" (unsigned char 1: a copy of a point on the input's own border; optional
 *   on reading: without it the unfolder fills no hole), "InputBorderNeighbors" (vtkIdType, 4
 *   components: input ids of the point's neighbours along the input's border, -1 padded; the
 *   tree's inputBorderEdges), cell arrays
 *   "OriginalCellId" (vtkIdType) and "FoldingLeafId" (int, the leaf's node index on every
 *   face, the active cell scalars, so viewers colour the tree by leaf like the segmentation
 *   output), and field data
 *   FoldingNodeKind = 0, FoldingNodeIndex, FoldingNodeDepth, FoldingEpsilon,
 *   FoldingFoldsAbove, FoldingRegionFaces, FoldingRegionArea, FoldingRegionOriginalFaces,
 *   SymmetricAreaFraction, DetectionRun, DetectionStarts (starts the detection tried),
 *   DetectionSeconds (its wall time: a measurement, like the tree's BuildSeconds; the
 *   detection statistics are optional on reading), LeafReason (int, Core's LeafReason enum),
 *   LeafReasonName (string) and the mirrored-flag records MirroredFlagPoint,
 *   MirroredFlagLevel, MirroredFlagKind (0 tear, 1 plane), MirroredFlagMask (uint64).
 * - a folding node is a vtkMultiBlockDataSet of two blocks: 0 = the child subtree, 1 =
 *   "Plane", a vtkPolyData outline (one closed polyline of 4 corners) of a rectangle on the
 *   plane covering the child's projection (10% margin; the unfolder ignores its geometry;
 *   an outline so that a surface view of the tree does not hide the leaves), its cell
 *   labelled "FoldingLeafId" = the folding node's index (the active cell scalars, as on the
 *   leaves, so ParaView colours the whole tree by FoldingLeafId) whose field data holds the node's
 * metadata: FoldingNodeKind = 1, the common node arrays above, FoldingPlaneOrigin,
 *   FoldingPlaneNormal (3 components, the normal points into the kept half),
 *   FoldingDiscardedFaces, FoldingProjectedPoints, FoldingDiscardedOriginalFaces.
 * - a segmentation node is a vtkMultiBlockDataSet of its children (fold(S) first) followed by
 *   "Node", a vtkPolyData with one marker point (the centroid of the node's stored points, no
 *   cell) carrying the node's metadata (FoldingNodeKind = 2 and the common node arrays).
 *   Metadata lives on polydata blocks because XML multiblock writers drop the field data of
 *   composite nodes, and those blocks are not empty because vtkXMLMultiBlockDataWriter skips
 *   data sets without points.
 * - a rotation node (RotationNodes) is a vtkMultiBlockDataSet of two blocks: 0 = the child
 *   subtree (one sector of 360/k degrees), 1 = "Axis", a vtkPolyData line along the axis over
 *   the subtree's extent (10% margin; labelled "FoldingLeafId" like the plane outlines) whose
 *   field data holds FoldingNodeKind = 3, the common node arrays, FoldingAxisOrigin,
 *   FoldingAxisDirection (3 components, unit; turns are right-handed about it),
 *   FoldingRotationOrder (k, 2..360), FoldingDiscardedFaces, FoldingDiscardedOriginalFaces.
 *   The sector's seam vertices carry the node's depth in TearMask.
 * - readers identify nodes by structure and FoldingNodeKind, not by block names; node indices
 *   come from FoldingNodeIndex (see vtkFoldingTreeIO.h).
 *
 * Output 1 (vtkPolyData): the triangulated input (an input cell array named FoldingLeafId,
 * FoldingDepth or FoldingRole renamed "<name>_input", with a warning) with cell arrays
 * "FoldingLeafId" (node index
 * of the leaf that reproduces the face: the leaf storing it, or, for a face removed by a fold,
 * the leaf holding the face whose mirror image it is - matched by the nearest mirrored
 * centroid and followed through nested folds, see Core/FoldingSegmentation.h - so a mirrored
 * half is coloured like the half it mirrors, as in the paper's Figures 1 and 4),
 * "FoldingDepth" (depth of that leaf, or of the folding node that removed the face),
 * "FoldingRole" (0 kept in a leaf, 1 removed by a fold - mirrored away, or collapsed by the
 * projection onto the plane -, 2 kept and touching a segmentation boundary (a vertex with a
 * segmentation's tear bit), 3 removed by a rotation node (its leaf: the one holding the face
 * it is a turned copy of), -1 not stored: an input triangle with a repeated vertex). Active
 * scalars: FoldingLeafId (the input's point arrays are kept, but none is active, so viewers colour
 * by leaf).
 *
 * Bad input (no points, no polygons, invalid mesh) and bad parameters (NaN, which the clamping
 * setters let through; a tolerance length that is not positive and finite) are reported with
 * vtkErrorMacro and the request fails. An abort (AbortExecute) keeps the tree built so far (Aborted
 * = 1).
 *
 * Parallel runs (pvbatch or pvserver under MPI): when Controller (by default the global
 * controller) has more than one process and the pipeline asks for one of several pieces
 * (ParaView does; a plain Update() asks for the whole data, so nothing is gathered), the input
 * pieces of all ranks are gathered on rank 0 and the filter runs once there, so the tree does not
 * depend on how the data is distributed. Rank 0 holds the outputs; the outputs of the other ranks
 * are empty (an empty input piece there is not an error); the result getters give the same values
 * on every rank.
 */
#ifndef vtkFoldingTreeBuilder_h
#define vtkFoldingTreeBuilder_h

#include "FoldingMeshesFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class vtkAbstractCellLocator;
class vtkMultiProcessController;

class FOLDINGMESHESFILTERS_EXPORT vtkFoldingTreeBuilder : public vtkPolyDataAlgorithm
{
public:
  static vtkFoldingTreeBuilder* New();
  vtkTypeMacro(vtkFoldingTreeBuilder, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ToleranceModes
  {
    RELATIVE_TO_DIAGONAL = 0,
    ABSOLUTE = 1
  };
  enum KeepSides
  {
    MORE_FACES = 0,
    FEWER_FACES = 1
  };
  enum Methods
  {
    ROBUST = 0,
    PAPER = 1
  };
  enum RotationNodeModes
  {
    ROTATION_NODES_OFF = 0,
    ROTATION_NODES_ON = 1,
    ROTATION_NODES_WHEN_AXIAL = 2
  };

  ///@{
  /**
   * The root tolerance epsilon (halved below every folding node). With ToleranceMode
   * RELATIVE_TO_DIAGONAL (default) a fraction of the bounding-box diagonal (default 0.02,
   * the paper's 2%); with ABSOLUTE a length. Clamped to [1e-12, 1e30].
   */
  vtkSetClampMacro(Tolerance, double, 1e-12, 1e30);
  vtkGetMacro(Tolerance, double);
  vtkSetClampMacro(ToleranceMode, int, RELATIVE_TO_DIAGONAL, ABSOLUTE);
  vtkGetMacro(ToleranceMode, int);
  ///@}

  ///@{
  /** Which half a fold keeps: MORE_FACES (default, the paper's) or FEWER_FACES (storage). */
  vtkSetClampMacro(KeepSide, int, MORE_FACES, FEWER_FACES);
  vtkGetMacro(KeepSide, int);
  ///@}

  ///@{
  /** Leaf when a region has fewer than MinimumFaces faces (default on, 50; range 1..1e9). */
  vtkSetMacro(UseMinimumFaces, bool);
  vtkGetMacro(UseMinimumFaces, bool);
  vtkBooleanMacro(UseMinimumFaces, bool);
  vtkSetClampMacro(MinimumFaces, int, 1, 1000000000);
  vtkGetMacro(MinimumFaces, int);
  ///@}

  ///@{
  /**
   * Leaf when a region's area is below MinimumAreaFraction of the input's area (default on,
   * 0.05, the paper's 5%; range 0..1).
   */
  vtkSetMacro(UseMinimumAreaFraction, bool);
  vtkGetMacro(UseMinimumAreaFraction, bool);
  vtkBooleanMacro(UseMinimumAreaFraction, bool);
  vtkSetClampMacro(MinimumAreaFraction, double, 0.0, 1.0);
  vtkGetMacro(MinimumAreaFraction, double);
  ///@}

  ///@{
  /**
   * Leaf when MaximumFolds folds lie above a region (default on, 8; range 0..63). Whatever
   * the criteria, the tree has at most 48 levels (folding and segmentation nodes count; a
   * deeper region becomes a leaf with LeafReason "MaximumDepth"), which bounds the recursion.
   */
  vtkSetMacro(UseMaximumFolds, bool);
  vtkGetMacro(UseMaximumFolds, bool);
  vtkBooleanMacro(UseMaximumFolds, bool);
  vtkSetClampMacro(MaximumFolds, int, 0, 63);
  vtkGetMacro(MaximumFolds, int);
  ///@}

  ///@{
  /**
   * Leaf when no meaningful symmetric region is found (default on; the rule is documented in
   * Core/FoldingTreeBuilder.h: S covers at least 10% of the region's area and has at least
   * MinimumFaces faces, and its plane is not already used on the path). Off: any non-empty S
   * is folded.
   */
  vtkSetMacro(RequireMeaningfulSymmetry, bool);
  vtkGetMacro(RequireMeaningfulSymmetry, bool);
  vtkBooleanMacro(RequireMeaningfulSymmetry, bool);
  ///@}

  ///@{
  /**
   * With RequireMeaningfulSymmetry, also require the detector's residual rule (the RMS of
   * the mirror distances over S at most 0.35 epsilon, as vtkSymmetryPlaneDetector's
   * SymmetryFound), so that only clear symmetries are folded (default off, as in the paper:
   * every epsilon-symmetric region large enough is folded, which compresses more and stays
   * within the error bound).
   */
  vtkSetMacro(RequireTightSymmetry, bool);
  vtkGetMacro(RequireTightSymmetry, bool);
  vtkBooleanMacro(RequireTightSymmetry, bool);
  ///@}

  ///@{
  /**
   * Prove the error bound after building (default on): unfold the tree with the unfolder's
   * defaults and bound its Hausdorff distance to the input over every point of both surfaces;
   * where a point is not proved within epsilon, keep the input faces there out of every fold
   * and build again (at most four times, then the input is stored whole) - but a first tree
   * proved at most 1.25 epsilon away is built again at 0.97 epsilon^2 / bound instead, without
   * pinning, and reports that smaller epsilon as its RootEpsilon (if that tree misses it too,
   * the rounds go on at epsilon with the first tree's pins); a closed input that
   * comes back with holes gets the faces there kept out of every fold too (at most two more
   * builds, each kept when it stores at most a tenth of the input's faces, or 250, more). The
   * tree's "VerifiedBound" (the proved bound; -1 when off), "PinnedFaces" and
   * "VerificationRounds" say what happened. Off: the tree the error budgets give, unverified,
   * one unfold and proof faster (docs/builder.md).
   */
  vtkSetMacro(VerifyBound, bool);
  vtkGetMacro(VerifyBound, bool);
  vtkBooleanMacro(VerifyBound, bool);
  ///@}

  ///@{
  /** Let regions and components span parts that touch within epsilon (default on). */
  vtkSetMacro(ConnectNearbyParts, bool);
  vtkGetMacro(ConnectNearbyParts, bool);
  vtkBooleanMacro(ConnectNearbyParts, bool);
  ///@}

  ///@{
  /**
   * Rotation nodes (default ROTATION_NODES_WHEN_AXIAL; issue 22): where no fold lies above a
   * region, look for a rotational symmetry of order k (2..MaximumRotationOrder, default 64,
   * range 2..360) and, when turning one sector of 360/k degrees k times reproduces the whole region within
   * epsilon / 2, store that sector only (a node of kind 3 with FoldingAxisOrigin,
   * FoldingAxisDirection and FoldingRotationOrder); the sector is built with epsilon / 2 and
   * may fold again (a dihedral part becomes rotation + fold). Surfaces of revolution get the
   * largest k whose sector has whole faces. The rule: docs/builder.md, "Rotation nodes".
   * ROTATION_NODES_OFF (0, false), ROTATION_NODES_ON (1, true), or
   * ROTATION_NODES_WHEN_AXIAL (2, the default since 2026-12-07): on only for an input whose
   * surface's second moments are axially symmetric (two eigenvalues within 2% of the larger),
   * as a rotational symmetry of order 3 or more of the whole surface makes them - no rotation
   * detection cost elsewhere (of the 29 shared meshes: the bearing, mech and queen, each stored
   * smaller; the other 26 as with OFF). ON looks everywhere: four more of the 29 smaller
   * (teapot, fandisk, octopus, horse_walk), none larger, builds 1.8 times as long.
   */
  vtkSetClampMacro(RotationNodes, int, ROTATION_NODES_OFF, ROTATION_NODES_WHEN_AXIAL);
  vtkGetMacro(RotationNodes, int);
  vtkBooleanMacro(RotationNodes, int);
  vtkSetClampMacro(MaximumRotationOrder, int, 2, 360);
  vtkGetMacro(MaximumRotationOrder, int);
  ///@}

  ///@{
  /** Symmetry detection: ROBUST (default, several starts) or PAPER (one start). */
  vtkSetClampMacro(Method, int, ROBUST, PAPER);
  vtkGetMacro(Method, int);
  ///@}

  ///@{
  /**
   * With the ROBUST method, regions with more faces than this search their candidate planes
   * on a sampled copy with a quarter of the faces (its points are vertices of the region,
   * its distances are measured to the full region) and only score the copy's finalists on the
   * full region; the trim and the polish of the plane on S refine the plane anyway (default
   * 1000: about half the build time of the shared meshes at the same mean compression). 0:
   * every region; a value above the input's face count: the full search everywhere.
   */
  vtkSetClampMacro(SampledSearchAboveFaces, int, 0, 1000000000);
  vtkGetMacro(SampledSearchAboveFaces, int);
  ///@}

  ///@{
  /** Seed of the detection's candidate sampling (default 1); deterministic for a seed. */
  vtkSetMacro(RandomSeed, int);
  vtkGetMacro(RandomSeed, int);
  ///@}

  ///@{
  /**
   * Results of the last run: the requested root epsilon as a length (Tolerance; the tree's
   * RootEpsilon is smaller after a near-miss rebuild, see VerifyBound), faces, stored faces,
   * compression.
   */
  vtkGetMacro(ToleranceLength, double);
  vtkGetMacro(OriginalFaces, int);
  vtkGetMacro(StoredFaces, int);
  vtkGetMacro(Compression, double);
  vtkGetMacro(TreeHeight, int);
  ///@}

  ///@{
  /**
   * A cell locator to answer the builder's plain closest-triangle queries: VerifyBound's
   * distances (unfold(tree) against the input and back, over every point of both surfaces)
   * and the proof that every mirrored face stays within its limit at every point (per fold,
   * over the node's region). nullptr (the default): the core's face tree, which gives the same
   * distances (exact point-to-triangle distances; the trees can differ only where triangles
   * tie for the closest) and builds the Table 1 meshes 1.4-2x faster than
   * vtkStaticCellLocator (docs/benchmarks.md, issue 19). A locator
   * set here is not used itself: a new instance of its class is built per surface (its
   * settings are not copied); locators other than vtkStaticCellLocator are queried by one
   * thread at a time. The tree's "Tree" block names what answered in "VerificationLocator"
   * ("FaceTree", the locator's class, or empty without VerifyBound). C++ and Python only:
   * ParaView keeps the default.
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
  vtkFoldingTreeBuilder();
  ~vtkFoldingTreeBuilder() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /** RequestData of a serial run, or of rank 0 on the gathered input. */
  int RequestWholeData(vtkInformation*, vtkInformationVector**, vtkInformationVector*);

  double Tolerance = 0.02;
  int ToleranceMode = RELATIVE_TO_DIAGONAL;
  int KeepSide = MORE_FACES;
  bool UseMinimumFaces = true;
  int MinimumFaces = 50;
  bool UseMinimumAreaFraction = true;
  double MinimumAreaFraction = 0.05;
  bool UseMaximumFolds = true;
  int MaximumFolds = 8;
  bool RequireMeaningfulSymmetry = true;
  bool RequireTightSymmetry = false;
  bool VerifyBound = true;
  bool ConnectNearbyParts = true;
  int RotationNodes = ROTATION_NODES_WHEN_AXIAL;
  int MaximumRotationOrder = 64; // the core's DefaultMaximumRotationOrder
  int Method = ROBUST;
  int SampledSearchAboveFaces = 1000;
  int RandomSeed = 1;

  double ToleranceLength = 0.0;
  int OriginalFaces = 0;
  int StoredFaces = 0;
  double Compression = 0.0;
  int TreeHeight = 0;

  vtkMultiProcessController* Controller = nullptr;
  vtkAbstractCellLocator* Locator = nullptr;

private:
  vtkFoldingTreeBuilder(const vtkFoldingTreeBuilder&) = delete;
  void operator=(const vtkFoldingTreeBuilder&) = delete;
};

#endif
