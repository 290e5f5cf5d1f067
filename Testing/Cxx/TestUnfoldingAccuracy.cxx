// unfold(fold(M)) against M, measured through vtkFoldingTreeUnfolder's optional "Original"
// input (port 1, the core's SurfaceDistance):
// - known distances: a cube [-1, 1]^3 tessellated with all its mirror symmetries, folded and
//   unfolded, against the cube scaled by s: DistanceToOriginal is s - max|x_i| at every output
//   point (exactly: the output lies inside the big cube), HausdorffToOriginal sqrt(3) (s - 1)
//   (the big cube's corners), the relative values are divided by the big cube's diagonal; the
//   unscaled cube comes back exactly (Hausdorff ~ 0, closed); without an original there is no
//   DistanceToOriginal; an original without polygons fails the request;
// - procedural meshes (exact and approximate symmetry, asymmetric attachment) and real meshes
//   of ../shared/data/meshes (the small ones, given as arguments): Hausdorff <= the root
//   epsilon (2% of the diagonal, the paper's bound) at the samples and, proved, over whole
//   surfaces (HausdorffToOriginalBound), orientation consistent (interior edges
//   traversed twice in the same direction: at most 0.1% of the edges, at stitched seams),
//   points per face within 5% of M's (no duplicated seam vertices; the face count is twice
//   the kept half's), open and non-manifold edges reported and below 5% of the edges; exact
//   cases closed with M's point count;
// - the final repair (CloseHoles, default on): a closed manifold M (dino, triceratops, fandisk, the
//   procedural meshes) comes back without non-manifold or misoriented edges and with open
//   edges below 1% of the edges (none at all for the real meshes), every open edge in a
//   reported loop (OpenLoopEdges +
//   BorderEdges); an M with a border (teapot, queen) keeps it: at least as many border loops
//   as M has, at least 90% of its length (never filled); with CloseHoles off the closed inputs
//   have more open edges (the repair is what closes them), with it the Hausdorff bound holds;
// - vertex count (RemoveProjectedPoints and MatchDiscardedDensity, default on): the real
//   meshes come back within 0.5% (anchor), 1.5% (teapot), 2% (dino, bearing, hammer, wingnut,
//   triceratops), 3% (fandisk) or 6.5% (queen) of M's point count, the differently tessellated blob
//   within 5%; all of them exceed that with the mirrored copies kept as dense as the kept halves.
// - seam gap fills bounded by the seam's tolerance: the queen at epsilon 0.5% without the
//   final repair stays within it.
// - non-manifold inputs (a fan of 10 triangles on one edge, duplicate faces, a two-sided
//   sphere): the tree lists their non-manifold edges ("InputNonManifoldEdges" on the "Tree"
//   block) and every input face comes back (face count, no face dropped, the input's
//   non-manifold edges, Hausdorff within the root epsilon).
// - the bearing folded with rotation nodes (19 sectors cut along their half-planes) comes back
//   with its area (within 3%; 1.10 before the sectors' seams were stitched within a tenth of
//   the stitch tolerance), closed, within the bound;
// - a fold's mirror image never lies on faces outside its region (a moved octagonal prism,
//   face stop off: the cap came back twice) - area kept, AreaRatio reported; FilledAreaRatio is
//   the FoldingFilled faces' share, and a holed sphere's fill its ring's (UnfoldingFilledArea.h);
// - folds down to single faces (UseMinimumFaces off, and no stop criterion at all): a
//   square, a single triangle and a flat hexagonal fan keep their area, stay within the root
//   epsilon, and the build ends (a fold removing no face is not made).
//
//   TestUnfoldingAccuracy [MESH...]
#include "MeshIO.h"
#include "ProceduralMeshes.h"
#include "TestExpect.h"
#include "UnfoldingAccuracyMeshes.h"
#include "UnfoldingFilledArea.h"
#include "vtkFoldingTreeBuilder.h"
#include "vtkFoldingTreeUnfolder.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkMath.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <sstream>
#include <string>

namespace
{
using namespace foldingmeshes::testing;

int Failures = 0;
#define EXPECT(cond, msg) FOLDINGMESHES_EXPECT(Failures, cond, msg)

double Field(vtkPolyData* pd, const char* name)
{
  vtkDataArray* a = pd->GetFieldData()->GetArray(name);
  return a && a->GetNumberOfTuples() > 0 ? a->GetTuple1(0) : std::nan("");
}

/// unfold(fold(mesh)) with `mesh` as the Original; the builder and the unfolder as the
/// optional callbacks set them (defaults otherwise); the tree in `tree` if given.
vtkSmartPointer<vtkPolyData> FoldAndUnfold(vtkPolyData* mesh,
  const std::function<void(vtkFoldingTreeBuilder*)>& setBuilder = {},
  const std::function<void(vtkFoldingTreeUnfolder*)>& setUnfolder = {},
  vtkSmartPointer<vtkDataObject>* tree = nullptr)
{
  vtkNew<vtkFoldingTreeBuilder> builder;
  builder->SetInputData(mesh);
  if (setBuilder)
    setBuilder(builder);
  vtkNew<vtkFoldingTreeUnfolder> unfolder;
  unfolder->SetInputConnection(builder->GetOutputPort(0));
  unfolder->SetOriginalData(mesh);
  if (setUnfolder)
    setUnfolder(unfolder);
  unfolder->Update();
  if (tree)
    *tree = builder->GetOutputDataObject(0);
  return unfolder->GetOutput();
}

/// Folds and unfolds `mesh` (default options) with `mesh` as the original; checks the bound,
/// orientation and point count; returns the unfolded mesh.
vtkSmartPointer<vtkPolyData> RoundTrip(const std::string& name,
  vtkPolyData* mesh,
  bool exact,
  double* seconds = nullptr,
  bool closesCompletely = false,
  double maximumPointExcess = -1.0)
{
  const auto start = std::chrono::steady_clock::now();
  vtkSmartPointer<vtkDataObject> tree;
  const vtkSmartPointer<vtkPolyData> out = FoldAndUnfold(mesh, {}, {}, &tree);
  if (seconds)
    *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT(out->GetNumberOfCells() > 0, name << ": nothing unfolded");
  if (out->GetNumberOfCells() == 0)
    return out;
  const double epsilon = Field(out, "RootEpsilon"), diagonal = Field(out, "OriginalDiagonal");
  const double h = Field(out, "HausdorffToOriginal");
  const EdgeCounts input = CountEdges(mesh), edges = CountEdges(out);
  const long long points = out->GetNumberOfPoints(), welded = WeldedPointCount(mesh);
  std::printf("%-24s H/diag %.4f (eps %.4f) mean/diag %.5f | points %lld (M %lld, %+.1f%%) faces "
              "%lld (M %lld) | open %lld (M %lld) non-manifold %lld (M %lld) misoriented %lld | "
              "gaps %g (length/diag %.3f)\n",
    name.c_str(),
    h / diagonal,
    epsilon / diagonal,
    Field(out, "MeanDistanceToOriginalRelative"),
    points,
    welded,
    100.0 * (points - welded) / welded,
    static_cast<long long>(out->GetNumberOfCells()),
    TriangleCount(mesh),
    edges.open,
    input.open,
    edges.nonManifold,
    input.nonManifold,
    edges.misoriented,
    Field(out, "OpenGapCount"),
    Field(out, "OpenGapLength") / diagonal);
  std::fflush(stdout);
  EXPECT(h <= epsilon, name << ": Hausdorff " << h << " above the root epsilon " << epsilon);
  // ... over every point of both surfaces, not only at the samples (a proved bound, within
  // 1e-5 of the diagonal of the true distance).
  const double bound = Field(out, "HausdorffToOriginalBound");
  EXPECT(bound >= h && bound <= epsilon + 1e-5 * diagonal,
    name << ": proved Hausdorff bound " << bound / diagonal << " of the diagonal (sampled "
         << h / diagonal << "), above the root epsilon " << epsilon / diagonal);
  // Orientation: consistent but for a few stitched seam edges (reported).
  EXPECT(edges.misoriented <= 0.001 * edges.edges,
    name << ": " << edges.misoriented << " misoriented edges of " << edges.edges);
  // Point count: as dense as M (points per face within 5% of M's: no duplicated seam
  // vertices). The face count itself is 2 x the kept half's per fold, more than M's where the
  // two halves were tessellated differently (the builder keeps the half with more faces).
  const double faces = static_cast<double>(out->GetNumberOfCells());
  const double density = points / faces,
               inputDensity = welded / static_cast<double>(TriangleCount(mesh));
  EXPECT(std::abs(density - inputDensity) <= 0.05 * inputDensity,
    name << ": " << density << " points per face, M " << inputDensity);
  if (exact)
    EXPECT(points == welded, name << ": exact case, " << points << " points, M " << welded);
  // Vertex count (RemoveProjectedPoints, MatchDiscardedDensity): the vertices the builder
  // projected onto fold planes are removed again, and the mirrored copy of a fold whose halves
  // are tessellated differently is thinned to the discarded half's face count; what is left
  // off M's count comes mostly from seams.
  if (maximumPointExcess >= 0.0)
    EXPECT(std::abs(points - welded) <= maximumPointExcess * welded,
      name << ": " << points << " points, M " << welded << " (more than "
           << 100.0 * maximumPointExcess << "% off)");
  EXPECT(edges.open <= input.open + 0.05 * edges.edges,
    name << ": " << edges.open << " open edges of " << edges.edges);
  if (exact)
  {
    EXPECT(h <= 1e-9 * diagonal, name << ": exact case, Hausdorff " << h);
    EXPECT(edges.open == input.open && edges.nonManifold == input.nonManifold,
      name << ": exact case not closed");
  }
  // The final repair (CloseHoles): every open edge lies in a reported loop (the input's
  // border, or a gap that could not be closed: count and length).
  const double borderEdges = Field(out, "BorderEdges"), openLoopEdges = Field(out, "OpenLoopEdges");
  std::printf("%-24s repair: dropped %g flipped %g filled %g loops; border %g loops %g edges; "
              "open %g loops %g edges (length/diag %.4f); area %.4f of M's, %.4f filled\n",
    "",
    Field(out, "RepairDroppedFaces"),
    Field(out, "RepairFlippedFaces"),
    Field(out, "FilledLoops"),
    Field(out, "BorderLoops"),
    borderEdges,
    Field(out, "OpenLoops"),
    openLoopEdges,
    Field(out, "OpenLoopLength") / diagonal,
    Field(out, "AreaRatio"),
    Field(out, "FilledAreaRatio"));
  // FilledAreaRatio as a share of AreaRatio's, to the float points' rounding (about 1e-7).
  const double filledShare = FilledArea(out) / TotalArea(out);
  EXPECT(std::abs(Field(out, "FilledAreaRatio") / Field(out, "AreaRatio") - filledShare) <=
        1e-5 * filledShare + 1e-9 &&
      Field(out, "FilledAreaRatio") >= 0.0,
    name << ": FilledAreaRatio " << Field(out, "FilledAreaRatio") << " of AreaRatio "
         << Field(out, "AreaRatio") << ", measured share " << filledShare);
  if (exact)
    EXPECT(Field(out, "FilledAreaRatio") == 0.0, name << ": exact case, faces filled");
  EXPECT(edges.open == Field(out, "OpenEdges") &&
      edges.nonManifold == Field(out, "NonManifoldEdges") &&
      edges.misoriented == Field(out, "MisorientedEdges"),
    name << ": the edge report differs from the mesh");
  EXPECT(edges.open <= borderEdges + openLoopEdges,
    name << ": " << edges.open << " open edges, only " << borderEdges + openLoopEdges
         << " in reported loops");
  EXPECT((Field(out, "OpenLoops") > 0) == (openLoopEdges > 0) &&
      (openLoopEdges > 0) == (Field(out, "OpenLoopLength") > 0),
    name << ": open loops, edges and length disagree");
  const bool closedInput = input.open == 0 && input.nonManifold == 0;
  if (closedInput)
  {
    EXPECT(edges.nonManifold == 0 && edges.misoriented == 0,
      name << ": closed input, " << edges.nonManifold << " non-manifold and " << edges.misoriented
           << " misoriented edges after the repair");
    EXPECT(edges.open <= (closesCompletely ? 0.0 : 0.01 * edges.edges),
      name << ": closed input, " << edges.open << " open edges of " << edges.edges);
    EXPECT(Field(out, "BorderLoops") == 0, name << ": closed input, border loops reported");
  }
  else if (input.open > 0)
  {
    const Border border = InputBorder(mesh);
    // Kept: never filled (the loops along it may be longer where a seam gap opens into it).
    std::printf("%-24s input border: %lld loops, length/diag %.4f; kept as %g loops, length/diag "
                "%.4f\n",
      "",
      border.loops,
      border.length / diagonal,
      Field(out, "BorderLoops"),
      Field(out, "BorderLength") / diagonal);
    EXPECT(Field(out, "BorderLoops") >= border.loops &&
        Field(out, "BorderLength") >= 0.9 * border.length,
      name << ": border of " << border.loops << " loops, length " << border.length << " not kept: "
           << Field(out, "BorderLoops") << " loops, length " << Field(out, "BorderLength"));
  }
  // Without the repair the seams of approximate folds stay open where it closes them.
  vtkNew<vtkFoldingTreeUnfolder> raw;
  raw->SetInputData(tree);
  raw->CloseHolesOff();
  raw->Update();
  const EdgeCounts rawEdges = CountEdges(raw->GetOutput());
  std::printf("%-24s without the repair: open %lld non-manifold %lld misoriented %lld\n",
    "",
    rawEdges.open,
    rawEdges.nonManifold,
    rawEdges.misoriented);
  if (closedInput && !exact)
    EXPECT(rawEdges.open + rawEdges.nonManifold + rawEdges.misoriented == 0 ||
        edges.open + edges.nonManifold + edges.misoriented <
          rawEdges.open + rawEdges.nonManifold + rawEdges.misoriented,
      name << ": the repair closes nothing");
  return out;
}

void KnownDistances()
{
  const vtkSmartPointer<vtkPolyData> cube = Cube(4, 1.0);
  const vtkSmartPointer<vtkPolyData> unfolded = RoundTrip("cube", cube, true);
  const double s = 1.2;
  vtkNew<vtkFoldingTreeBuilder> builder;
  builder->SetInputData(cube);
  vtkNew<vtkFoldingTreeUnfolder> unfolder;
  unfolder->SetInputConnection(builder->GetOutputPort(0));
  unfolder->Update();
  vtkPolyData* out = unfolder->GetOutput();
  EXPECT(!out->GetPointData()->GetArray("DistanceToOriginal") &&
      !out->GetFieldData()->GetArray("HausdorffToOriginal") &&
      unfolder->GetHausdorffToOriginal() == -1.0,
    "cube: distance arrays without an original");
  const vtkSmartPointer<vtkPolyData> big = Scaled(cube, s);
  unfolder->SetOriginalData(big);
  unfolder->Update();
  out = unfolder->GetOutput();
  vtkDataArray* d = out->GetPointData()->GetArray("DistanceToOriginal");
  EXPECT(d && d->GetNumberOfTuples() == out->GetNumberOfPoints(), "cube: no DistanceToOriginal");
  if (d)
  {
    double worst = 0.0;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      double p[3];
      out->GetPoint(i, p);
      const double expected = s - std::max({ std::abs(p[0]), std::abs(p[1]), std::abs(p[2]) });
      worst = std::max(worst, std::abs(d->GetTuple1(i) - expected));
    }
    EXPECT(worst < 1e-12, "cube: DistanceToOriginal off by " << worst);
  }
  const double h = Field(out, "HausdorffToOriginal"), expected = std::sqrt(3.0) * (s - 1.0);
  const double diagonal = 2.0 * s * std::sqrt(3.0);
  EXPECT(std::abs(h - expected) < 1e-9, "cube: Hausdorff " << h << " != " << expected);
  EXPECT(unfolder->GetHausdorffToOriginal() == h, "cube: GetHausdorffToOriginal");
  EXPECT(std::abs(Field(out, "OriginalDiagonal") - diagonal) < 1e-12, "cube: OriginalDiagonal");
  EXPECT(std::abs(Field(out, "HausdorffToOriginalRelative") - h / diagonal) < 1e-15,
    "cube: HausdorffToOriginalRelative");
  const double mean = Field(out, "MeanDistanceToOriginal");
  EXPECT(mean > s - 1.0 - 1e-12 && mean < expected &&
      std::abs(Field(out, "MeanDistanceToOriginalRelative") - mean / diagonal) < 1e-15,
    "cube: mean distance " << mean << " outside (s - 1, sqrt(3)(s - 1))");

  // An original without polygons fails the request.
  vtkNew<vtkPolyData> empty;
  empty->SetPoints(big->GetPoints());
  unfolder->SetOriginalData(empty);
  vtkObject::GlobalWarningDisplayOff();
  const int ok = unfolder->GetExecutive()->Update();
  vtkObject::GlobalWarningDisplayOn();
  EXPECT(ok == 0, "cube: an original without polygons did not fail the request");
  unfolder->SetOriginalData(nullptr);
  unfolder->Update();
  EXPECT(unfolder->GetNumberOfInputConnections(1) == 0 &&
      !unfolder->GetOutput()->GetPointData()->GetArray("DistanceToOriginal"),
    "cube: SetOriginalData(nullptr) did not disconnect");
}

/// Seam gap fills are bounded by the seam's tolerance (FillWithinTolerance): the queen at a
/// root epsilon of 0.5% of the diagonal, without the final repair, stays within it (a flat
/// fill of a six-edge gap across its curved crown was 0.0074 of the diagonal away).
void SeamGapFillsWithinTolerance(const std::string& name, vtkPolyData* mesh)
{
  const vtkSmartPointer<vtkPolyData> out = FoldAndUnfold(
    mesh,
    [](vtkFoldingTreeBuilder* b) { b->SetTolerance(0.005); },
    [](vtkFoldingTreeUnfolder* u) { u->SetCloseHoles(false); });
  const double epsilon = Field(out, "RootEpsilon"), diagonal = Field(out, "OriginalDiagonal");
  const double h = Field(out, "HausdorffToOriginal");
  std::printf("%-24s at eps 0.5%%, CloseHoles off: H/diag %.4f (eps %.4f)\n",
    name.c_str(),
    h / diagonal,
    epsilon / diagonal);
  EXPECT(std::abs(epsilon / diagonal - 0.005) < 1e-9, name << ": root epsilon not 0.5%");
  EXPECT(h <= epsilon, name << ": seam gap fills beyond epsilon 0.5%: " << h / diagonal);
}

/// Folds and unfolds a non-manifold `mesh`: every face comes back (see the header).
void NonManifoldRoundTrip(const std::string& name, vtkPolyData* mesh)
{
  vtkSmartPointer<vtkDataObject> treeObject;
  const vtkSmartPointer<vtkPolyData> out = FoldAndUnfold(mesh, {}, {}, &treeObject);
  const EdgeCounts input = CountEdges(mesh), edges = CountEdges(out);
  auto* tree = vtkMultiBlockDataSet::SafeDownCast(treeObject);
  auto* info = tree ? vtkPolyData::SafeDownCast(tree->GetBlock(1)) : nullptr;
  vtkDataArray* listed = info ? info->GetFieldData()->GetArray("InputNonManifoldEdges") : nullptr;
  const double epsilon = Field(out, "RootEpsilon"), h = Field(out, "HausdorffToOriginal");
  std::printf("%-24s faces %lld (M %lld), non-manifold %lld (M %lld, listed %lld), dropped %g, "
              "H/diag %.2e (eps %.4f)\n",
    name.c_str(),
    static_cast<long long>(out->GetNumberOfCells()),
    TriangleCount(mesh),
    edges.nonManifold,
    input.nonManifold,
    listed ? static_cast<long long>(listed->GetNumberOfTuples()) : -1LL,
    Field(out, "RepairDroppedFaces"),
    h / Field(out, "OriginalDiagonal"),
    epsilon / Field(out, "OriginalDiagonal"));
  EXPECT(listed && listed->GetNumberOfComponents() == 3 &&
      listed->GetNumberOfTuples() == input.nonManifold,
    name << ": the tree does not list the input's " << input.nonManifold << " non-manifold edges");
  EXPECT(out->GetNumberOfCells() == TriangleCount(mesh) && Field(out, "RepairDroppedFaces") == 0,
    name << ": " << out->GetNumberOfCells() << " faces of " << TriangleCount(mesh) << " unfolded, "
         << Field(out, "RepairDroppedFaces") << " dropped");
  EXPECT(edges.nonManifold == input.nonManifold,
    name << ": " << edges.nonManifold << " non-manifold edges, M " << input.nonManifold);
  EXPECT(h <= epsilon, name << ": Hausdorff " << h << " above the root epsilon " << epsilon);
}

void NonManifoldInputs()
{
  // A fan of 10 triangles on one edge (one leaf, no fold).
  std::vector<std::array<double, 3>> points{ { 0, 0, 0 }, { 0, 0, 1 } };
  std::vector<std::array<vtkIdType, 3>> fan;
  for (int j = 0; j < 10; ++j)
  {
    const double a = 2.0 * vtkMath::Pi() * j / 10.0;
    points.push_back({ std::cos(a), std::sin(a), 0.5 });
    fan.push_back({ 0, 1, 2 + j });
  }
  NonManifoldRoundTrip("fan of 10", Triangles(points, fan));
  // Duplicate faces: two copies of a square's triangle, one reversed copy.
  NonManifoldRoundTrip("duplicate faces",
    Triangles({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 } },
      { { 0, 1, 2 }, { 0, 1, 2 }, { 1, 3, 2 }, { 2, 1, 0 } }));
  // A two-sided sphere (every face also reversed: every edge used by four faces).
  const vtkSmartPointer<vtkPolyData> sphere = foldingmeshes::testing::MakeSphere(500).mesh;
  std::vector<std::array<double, 3>> sp(sphere->GetNumberOfPoints());
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
    sphere->GetPoint(i, sp[i].data());
  std::vector<std::array<vtkIdType, 3>> two;
  vtkIdType n = 0;
  const vtkIdType* pts = nullptr;
  vtkCellArray* polys = sphere->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, pts);)
    if (n == 3)
    {
      two.push_back({ pts[0], pts[1], pts[2] });
      two.push_back({ pts[0], pts[2], pts[1] });
    }
  NonManifoldRoundTrip("two-sided sphere", Triangles(sp, two));
}
}

/// Tiny meshes with the face stop off (only the paper's area stop) or no stop at all: a
/// square (two triangles) and a single triangle come back with their whole area, within the
/// root epsilon, and at most twice their faces (a fold that removes no face, a single
/// triangle's, is not made: it was repeated down to the depth bound, 2^folds faces).
/// Before 2026-12-02 the square also lost a whole triangle (Hausdorff 25 epsilon).
void FoldsDownToSingleFaces()
{
  const std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>> meshes{
    { "square",
      Triangles(
        { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 } }, { { 0, 1, 2 }, { 1, 3, 2 } }) },
    { "single triangle", Triangles({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, 1, 2 } }) },
    // A flat hexagon of six triangles around its centre (the option sweep's fan6): its two
    // one-face leaves once made the seam-gap filler take the disc's own border for a gap,
    // and the repair then capped it: twice the area, 14 faces.
    { "hexagonal fan",
      Triangles({ { 0, 0, 0 },
                  { 1, 0, 0 },
                  { 0.5, 0.8660254037844386, 0 },
                  { -0.5, 0.8660254037844386, 0 },
                  { -1, 0, 0 },
                  { -0.5, -0.8660254037844386, 0 },
                  { 0.5, -0.8660254037844386, 0 } },
        { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 3, 4 }, { 0, 4, 5 }, { 0, 5, 6 }, { 0, 6, 1 } }) },
  };
  for (const bool noStop : { false, true })
    for (const auto& [name, mesh] : meshes)
    {
      const vtkSmartPointer<vtkPolyData> out = FoldAndUnfold(mesh,
        [noStop](vtkFoldingTreeBuilder* b)
        {
          b->UseMinimumFacesOff();
          if (noStop)
          {
            b->UseMinimumAreaFractionOff();
            b->UseMaximumFoldsOff();
          }
        });
      const double area = TotalArea(out), inputArea = TotalArea(mesh);
      const double epsilon = Field(out, "RootEpsilon"), h = Field(out, "HausdorffToOriginal");
      std::printf("%-24s (%s) faces %lld, area %.6f of %.6f, H/eps %.2e\n",
        name.c_str(),
        noStop ? "no stop criteria" : "face stop off",
        static_cast<long long>(out->GetNumberOfCells()),
        area,
        inputArea,
        h / epsilon);
      EXPECT(std::abs(area - inputArea) <= 1e-9 * inputArea,
        name << ": area " << area << " unfolded, input " << inputArea);
      EXPECT(h <= epsilon, name << ": Hausdorff " << h << " above the root epsilon " << epsilon);
      EXPECT(out->GetNumberOfCells() <= 2 * mesh->GetNumberOfCells(),
        name << ": " << out->GetNumberOfCells() << " faces unfolded from "
             << mesh->GetNumberOfCells() << " (folds of single triangles)");
    }
}

/**
 * A closed box with a bump, folded with the default stops and with UseMinimumFaces off (the
 * area stop alone, as in the paper), in float and in double coordinates (the plane estimates,
 * and so the trees, differ), comes back closed, with the input's area, within the bound. Its
 * folds' planes pass 3e-4 (0.008 epsilon) beside a row of vertices, which stay beside their
 * neighbours' projections: sliver strips. Two defects this catches: (float, face stop off)
 * the slivers met the box's sides at non-manifold edges and the final repair kept them and
 * dropped 36 side faces (area 0.89, 48 open edges, bound 1.8 epsilon); (double, both
 * settings) the seam around the bump reached both sides of a strip, two vertices of one copy
 * 2e-4 apart that the final weld never merged (16 open edges).
 */
void SmallFoldsOfAClosedBox()
{
  for (const bool doublePoints : { false, true })
    for (const bool faceStop : { true, false })
    {
      const vtkSmartPointer<vtkPolyData> mesh = BumpBox(6, 0.3, doublePoints);
      const vtkSmartPointer<vtkPolyData> out = FoldAndUnfold(
        mesh, [faceStop](vtkFoldingTreeBuilder* b) { b->SetUseMinimumFaces(faceStop); });
      const EdgeCounts edges = CountEdges(out);
      const double area = TotalArea(out), inputArea = TotalArea(mesh);
      const double epsilon = Field(out, "RootEpsilon");
      const double bound = Field(out, "HausdorffToOriginalBound");
      const std::string name = std::string("bump box (") + (doublePoints ? "double" : "float") +
        (faceStop ? ", defaults)" : ", face stop off)");
      std::printf("%s: %lld faces, area %.4f of %.4f, open %lld, non-manifold %lld, misoriented "
                  "%lld, bound/eps %.3f, repair dropped %g, welded %g\n",
        name.c_str(),
        static_cast<long long>(out->GetNumberOfCells()),
        area,
        inputArea,
        edges.open,
        edges.nonManifold,
        edges.misoriented,
        bound / epsilon,
        Field(out, "RepairDroppedFaces"),
        Field(out, "WeldedVertices"));
      EXPECT(edges.open == 0 && edges.nonManifold == 0 && edges.misoriented == 0,
        name << ": " << edges.open << " open, " << edges.nonManifold << " non-manifold, "
             << edges.misoriented << " misoriented edges (closed input)");
      EXPECT(std::abs(area - inputArea) <= 0.01 * inputArea,
        name << ": area " << area << " unfolded, input " << inputArea);
      EXPECT(bound <= epsilon, name << ": proved bound " << bound << " above epsilon " << epsilon);
    }
}

/**
 * An octagonal prism (vtkCylinderSource, 8 sides, welded) under a rigid motion, its
 * coordinates float values (held as doubles), folded with the face stop off (the option sweep's
 * cyl8 case). A fold kept nine faces of a region of seventeen: the mirror image of a cap face lay
 * on two cap faces outside the fold's region S (a leaf of their own), whose vertices are S's, so
 * the vertex distances passed and the mirrored-face proof, measured to the whole node, did too;
 * unfolded, the cap was there twice (area 1.079, 36 faces; the repair's fills on top). The proof
 * now measures to S itself. Also: the unfolder's AreaRatio is the unfolded area over the input's.
 */
void MirrorImagesOutsideTheRegion()
{
  const vtkSmartPointer<vtkPolyData> mesh =
    Triangles({ { -2.7645309f, -5.46642017f, 0.278567165f },
                { -2.59576392f, -4.62338877f, -0.232134014f },
                { -2.44866276f, -5.62105227f, 0.127693549f },
                { -2.27989578f, -4.77802038f, -0.383007646f },
                { -2.07953167f, -5.6343317f, 0.227756202f },
                { -1.91076469f, -4.7913003f, -0.282944977f },
                { -1.87336981f, -5.49847984f, 0.520139813f },
                { -1.70460284f, -4.65544844f, 0.00943864509f },
                { -1.95094395f, -5.29307699f, 0.833570063f },
                { -1.78217697f, -4.45004511f, 0.322868854f },
                { -2.26681209f, -5.1384449f, 0.984443665f },
                { -2.09804511f, -4.29541349f, 0.473742485f },
                { -2.63594317f, -5.12516546f, 0.884380996f },
                { -2.4671762f, -4.28213406f, 0.373679817f },
                { -2.84210515f, -5.26101732f, 0.591997385f },
                { -2.67333817f, -4.41798592f, 0.0812961981f } },
      { { 0, 1, 2 },
        { 3, 2, 1 },
        { 2, 3, 4 },
        { 5, 4, 3 },
        { 4, 5, 6 },
        { 7, 6, 5 },
        { 6, 7, 8 },
        { 9, 8, 7 },
        { 8, 9, 10 },
        { 11, 10, 9 },
        { 10, 11, 12 },
        { 13, 12, 11 },
        { 12, 13, 14 },
        { 15, 14, 13 },
        { 14, 15, 0 },
        { 1, 0, 15 },
        { 0, 2, 14 },
        { 14, 2, 12 },
        { 12, 2, 10 },
        { 10, 2, 8 },
        { 2, 4, 8 },
        { 6, 8, 4 },
        { 13, 11, 15 },
        { 15, 11, 1 },
        { 1, 11, 3 },
        { 3, 11, 5 },
        { 11, 9, 5 },
        { 7, 5, 9 } });
  const vtkSmartPointer<vtkPolyData> out =
    FoldAndUnfold(mesh, [](vtkFoldingTreeBuilder* b) { b->UseMinimumFacesOff(); });
  const EdgeCounts edges = CountEdges(out);
  const double area = TotalArea(out), inputArea = TotalArea(mesh);
  const double epsilon = Field(out, "RootEpsilon");
  const double bound = Field(out, "HausdorffToOriginalBound");
  std::printf("moved octagonal prism (face stop off): %lld faces, area %.6f of %.6f (AreaRatio "
              "%.6f), open %lld, bound/eps %.3f\n",
    static_cast<long long>(out->GetNumberOfCells()),
    area,
    inputArea,
    Field(out, "AreaRatio"),
    edges.open,
    bound / epsilon);
  EXPECT(std::abs(area - inputArea) <= 0.01 * inputArea,
    "octagonal prism: area " << area << " unfolded, input " << inputArea << " (surface twice)");
  EXPECT(std::abs(Field(out, "AreaRatio") - area / inputArea) <= 1e-9,
    "octagonal prism: AreaRatio " << Field(out, "AreaRatio") << ", measured " << area / inputArea);
  EXPECT(edges.open == 0 && edges.nonManifold == 0,
    "octagonal prism: " << edges.open << " open, " << edges.nonManifold
                        << " non-manifold edges (closed input)");
  EXPECT(bound <= epsilon, "octagonal prism: proved bound " << bound << " above " << epsilon);
}

/**
 * The bearing folded with rotation nodes (a sector of order 19, cut along its half-planes,
 * folded once more below) comes back with its own area, closed and within the bound: the
 * sectors' seams are stitched within a tenth of the stitch tolerance (near the axis the full
 * tolerance reached the next half-plane, and the unfolded bearing had 1.10 times its area).
 */
/// The largest FoldingRotationOrder of the tree's blocks (0: no rotation node).
double LargestRotationOrder(vtkDataObject* object)
{
  double order = 0.0;
  if (vtkDataArray* a = object->GetFieldData()->GetArray("FoldingRotationOrder"))
    if (a->GetNumberOfTuples() > 0)
      order = a->GetTuple1(0);
  if (auto* blocks = vtkMultiBlockDataSet::SafeDownCast(object))
    for (unsigned b = 0; b < blocks->GetNumberOfBlocks(); ++b)
      if (vtkDataObject* child = blocks->GetBlock(b))
        order = std::max(order, LargestRotationOrder(child));
  return order;
}

void RotationSeamsKeepTheArea(const std::string& name, vtkPolyData* mesh)
{
  vtkSmartPointer<vtkDataObject> tree;
  const vtkSmartPointer<vtkPolyData> out = FoldAndUnfold(
    mesh, [](vtkFoldingTreeBuilder* b) { b->RotationNodesOn(); }, {}, &tree);
  const double epsilon = Field(out, "RootEpsilon"), bound = Field(out, "HausdorffToOriginalBound");
  const double ratio = Field(out, "AreaRatio"), copies = Field(out, "NumberOfCopies");
  const EdgeCounts edges = CountEdges(out);
  const double order = LargestRotationOrder(tree);
  std::printf("%s with rotation nodes: order %g, %g copies, area ratio %.4f, bound %.4g of "
              "epsilon %.4g, open %lld\n",
    name.c_str(),
    order,
    copies,
    ratio,
    bound,
    epsilon,
    edges.open);
  EXPECT(order >= 19 && copies >= order,
    name << ": rotation order " << order << ", " << copies
         << " copies (a sector of order 19 or more expected)");
  EXPECT(ratio >= 0.98 && ratio <= 1.03,
    name << ": rotation nodes, unfolded area " << ratio << " times the input's");
  EXPECT(bound <= epsilon, name << ": rotation nodes, proved bound " << bound << " > " << epsilon);
  EXPECT(edges.open == 0, name << ": rotation nodes, " << edges.open << " open edges");
}

int main(int argc, char* argv[])
{
  namespace pm = foldingmeshes::testing;
  KnownDistances();
  Failures += CheckFilledArea();
  NonManifoldInputs();
  FoldsDownToSingleFaces();
  SmallFoldsOfAClosedBox();
  MirrorImagesOutsideTheRegion();
  RoundTrip("bilateral blob", pm::MakeBilateralBlob(3000).mesh, false);
  // +0.3% (+44% with the mirrored copies kept dense: the finer half doubled; +9.6% without
  // the root's thinning after the final repair, see TestMatchDiscardedDensity).
  RoundTrip("different tessellation",
    pm::MakeBilateralBlobDifferentTessellation(3000).mesh,
    false,
    nullptr,
    false,
    0.05);
  RoundTrip("three planes", pm::MakeThreePlaneShape(3000).mesh, false);
  RoundTrip("asymmetric attachment", pm::MakeBlobWithAsymmetricPart(3000, 0.2).mesh, false);
  for (int i = 1; i < argc; ++i)
  {
    std::string error;
    vtkSmartPointer<vtkPolyData> mesh = foldingmeshes::ReadMesh(argv[i], error);
    EXPECT(mesh, argv[i] << ": " << error);
    if (!mesh)
      continue;
    double seconds = 0.0;
    // The shared real meshes: closed inputs come back closed (measured on all 29). Vertex
    // count (benchmark's count as it is / with the mirrored copies kept dense,
    // --keep-copy-density): anchor +0.0% / +0.8%, dino +1.2% / +3.4%, teapot +0.0% / +1.6%;
    // bearing -0.9% / +7.9%, hammer_dec4360 +0.3% / +22.6%, wingnut -0.1% / +3.2%;
    // triceratops +0.0% / +13.3% (+3.1% without the root's thinning after the final
    // repair); queen +4.3% / +17.9% (+4.1% before the repair kept its non-manifold edges;
    // this test counts a little differently: dino +1.3%, triceratops +0.2%, queen +4.5%).
    // Each bound failed with the copies kept dense. Since fold images must lie on the fold's
    // own region (2026-12-05, MirrorImagesOutsideTheRegion) the trees changed: queen +5.7% /
    // +18.8% (this test +6.0%), teapot -1.3% either way (its new tree thins nothing).
    // fandisk (a CAD part) came back with an 18-edge hole with that change: the builder's
    // verification now rebuilds a closed input that comes back open (closing rounds); +1.9%.
    const std::string name = std::filesystem::path(argv[i]).stem().string();
    const double excess = name == "anchor_cgal" ? 0.005
      : name == "teapot_newell"                 ? 0.015
      : name == "queen_chess_quaddamage"        ? 0.065
      : name == "fandisk_alec"                  ? 0.03
                                                : 0.02;
    RoundTrip(name, mesh, false, &seconds, true, excess);
    std::printf("  (%.1f s)\n", seconds);
    if (name == "queen_chess_quaddamage")
      SeamGapFillsWithinTolerance(name, mesh);
    if (name == "bearing_psb341")
      RotationSeamsKeepTheArea(name, mesh);
  }
  if (Failures > 0)
    std::printf("TestUnfoldingAccuracy: %d check(s) FAILED\n", Failures);
  else
    std::printf("TestUnfoldingAccuracy: all checks passed\n");
  return Failures > 0 ? 1 : 0;
}
