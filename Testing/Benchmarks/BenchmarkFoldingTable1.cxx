// The paper's Table 1, side by side: per mesh, original faces, non-redundant (stored) faces,
// compression, tree height, build time, unfold time, symmetric Hausdorff distance between
// the input and unfold(fold(input)) as a fraction of the bounding-box diagonal (max, and the
// mean over the vertices of both meshes; then the proved upper bound over every point of both
// surfaces, within 1e-4 of the diagonal, marked '!' when it is proved above the root epsilon
// and '?' when that is not decided within 1e-7 of the diagonal), open, non-manifold and
// misoriented edges before/after (nm, mis), vertices before/after (pts, distinct positions)
// and the change, the unfolded faces and their change, the projected points the unfolder
// removed (rmvd) and the copies of projected points left (proj), the vertices it removed from
// mirrored copies and rotation nodes' sector copies (thin, MatchDiscardedDensity), the unfolded
// surface's area over the input's (area: above 1 where surface lies twice) and the share of it in
// the faces the unfolder added to close seam gaps and holes (fill: the unfolder's FilledAreaRatio;
// over the shared meshes 55% of what area has above 1), and - for the Table 1 models, matched by
// file name - the paper's row. Default builder and unfolder options (root epsilon 2% of the
// diagonal, keep the half with more faces, 5% area stop). Not a test: numbers for humans and
// closing notes.
//
//   BenchmarkFoldingTable1 [--threads N] [--keep fewer] [--tree] [--no-unfold]
//                          [--no-close-holes] [--hole-tolerance F] [--keep-projected-points]
//                          [--keep-copy-density] [--tolerance F]
//                          [--rotation|--no-rotation|--rotation-when-axial]
//                          [--compare-rotation] [--distance-locator static|facetree]
//                          MESH_OR_FOLDER...
//
// --keep fewer: the builder keeps the half with fewer faces; --tree prints each tree's outline
// (node kind, depth, faces, area share, symmetric area fraction, the detection's wall time and
// starts, why a leaf stopped) and the detections' share of the build time;
// --no-unfold skips the unfolding columns; --no-close-holes: the unfolder without its final
// repair; --hole-tolerance: its HoleToleranceScale; --keep-projected-points: the unfolder
// keeps the vertices the builder projected onto fold planes (RemoveProjectedPoints off);
// --keep-copy-density: the mirrored copies keep the kept half's density (MatchDiscardedDensity
// off);
// --tolerance: the root epsilon as a fraction of the diagonal (the builder's Tolerance,
// default 0.02); --rotation, --no-rotation, --rotation-when-axial: the builder's RotationNodes
// on, off, WHEN_AXIAL (issue 22; none: the builder's default, WHEN_AXIAL); --compare-rotation:
// under each mesh's row, a line with rotation nodes on (off where the row has them on):
// stored faces, compression, rotation nodes, build time and the builder's own proved bound
// (VerifiedBound over the diagonal, and whether it is within the root epsilon); --distance-locator:
// what answers the Hausdorff columns' closest-triangle queries, vtkStaticCellLocator (default,
// as the unfolder's DistanceToOriginal) or the core's face tree (the same values, 7-25x faster).
#include "MeshComparison.h"
#include "MeshIO.h"
#include "ProcessMemory.h"
#include "vtkFoldingTreeBuilder.h"
#include "vtkFoldingTreeIO.h"
#include "vtkFoldingTreeUnfolder.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSMPThreadLocalObject.h>
#include <vtkSMPTools.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

struct PaperRow
{
  const char* file; // file stem in ../shared/data/meshes
  const char* model;
  int faces, stored;
  double compression; // percent
  int height;
  double seconds;
};

// Table 1 of Folding meshes (SGP 2006).
const PaperRow PaperTable[] = {
  { "dino_cgal", "Dino", 6638, 3142, 52.7, 3, 152 },
  { "horse_psb397", "Horse", 3306, 2672, 19.2, 3, 24 },
  { "chair_psb108", "Chair", 5736, 2460, 57.1, 4, 58 },
  { "table_psb152", "Table", 5056, 1332, 73.7, 2, 160 },
  { "hammer_oded_dec4360", "Hammer", 4360, 677, 84.5, 7, 174 },
  { "triceratops_cgal", "Triceratops", 5660, 2447, 56.8, 7, 202 },
  { "eagle_psb258", "Eagle", 33072, 15808, 52.2, 6, 936 },
  { "queen_chess_quaddamage", "Queen", 3360, 600, 82.1, 4, 120 },
};

const PaperRow* FindPaperRow(const std::string& stem)
{
  for (const PaperRow& row : PaperTable)
    if (stem == row.file)
      return &row;
  return nullptr;
}

double TreeValue(vtkMultiBlockDataSet* tree, const char* name)
{
  auto* info = vtkPolyData::SafeDownCast(tree->GetBlock(1));
  vtkDataArray* a = info ? info->GetFieldData()->GetArray(name) : nullptr;
  return a && a->GetNumberOfTuples() > 0 ? a->GetTuple1(0) : 0.0;
}

double FieldValue(vtkPolyData* mesh, const char* name)
{
  vtkDataArray* a = mesh->GetFieldData()->GetArray(name);
  return a && a->GetNumberOfTuples() > 0 ? a->GetTuple1(0) : 0.0;
}

struct Settings
{
  bool keepFewer = false;
  bool printTree = false;
  bool unfold = true;
  bool closeHoles = true;
  bool removeProjectedPoints = true;
  bool matchDiscardedDensity = true;
  double holeToleranceScale = -1.0; // < 0: the filter's default
  double tolerance = -1.0;          // root epsilon / diagonal; < 0: the builder's default
  int rotationNodes = -1;           ///< RotationNodes; < 0: the builder's default
  bool compareRotation = false;
  foldingmeshes::DistanceLocator locator = foldingmeshes::DistanceLocator::StaticCellLocator;
};

/// The builder's options from the command line (RotationNodes as `rotation` says; < 0: the
/// builder's default).
void Configure(vtkFoldingTreeBuilder* builder, const Settings& settings, int rotation)
{
  if (settings.keepFewer)
    builder->SetKeepSide(vtkFoldingTreeBuilder::FEWER_FACES);
  if (settings.tolerance >= 0.0)
    builder->SetTolerance(settings.tolerance);
  if (rotation >= 0)
    builder->SetRotationNodes(rotation);
}

/// The --compare-rotation line's RotationNodes: on, or off where the row has them on.
int OtherRotationNodes(const Settings& settings)
{
  return settings.rotationNodes == vtkFoldingTreeBuilder::ROTATION_NODES_ON
    ? vtkFoldingTreeBuilder::ROTATION_NODES_OFF
    : vtkFoldingTreeBuilder::ROTATION_NODES_ON;
}

/// The --compare-rotation line: the mesh folded with RotationNodes OtherRotationNodes.
void CompareRotation(vtkPolyData* mesh, const Settings& settings)
{
  vtkNew<vtkFoldingTreeBuilder> builder;
  builder->SetInputData(mesh);
  const bool on = OtherRotationNodes(settings) == vtkFoldingTreeBuilder::ROTATION_NODES_ON;
  Configure(builder, settings, OtherRotationNodes(settings));
  const auto t0 = Clock::now();
  builder->Update();
  const double build = std::chrono::duration<double>(Clock::now() - t0).count();
  auto* tree = vtkMultiBlockDataSet::SafeDownCast(builder->GetOutputDataObject(0));
  foldingmeshes::FoldingTree folded;
  std::string error;
  if (!tree || !foldingmeshes::MultiBlockToFoldingTree(tree, folded, error))
  {
    std::printf("  rotation nodes %s: folding failed %s\n", on ? "on" : "off", error.c_str());
    return;
  }
  int rotations = 0;
  for (const foldingmeshes::FoldingNode& node : folded.nodes)
    rotations += node.kind == foldingmeshes::FoldingNodeKind::Rotation;
  std::printf("  rotation nodes %-3s %7d stored %6.1f%% %3d rotation nodes, build %7.3f s, "
              "proved %7.4f%s of the diagonal\n",
    on ? "on" : "off",
    folded.StoredFaces(),
    100.0 * folded.Compression(),
    rotations,
    build,
    folded.verifiedBound / folded.diagonal,
    folded.verifiedBound >= 0.0 && folded.verifiedBound <= folded.rootEpsilon ? " " : "!");
  std::fflush(stdout);
}

void PrintOutline(vtkMultiBlockDataSet* blocks)
{
  foldingmeshes::FoldingTree tree;
  std::string error;
  if (!foldingmeshes::MultiBlockToFoldingTree(blocks, tree, error))
  {
    std::printf("  (tree not readable: %s)\n", error.c_str());
    return;
  }
  double detection = 0.0;
  int detections = 0, starts = 0;
  for (const foldingmeshes::FoldingNode& node : tree.nodes)
  {
    if (node.detectionRun)
    {
      detection += node.detectionSeconds;
      starts += node.detectionStarts;
      ++detections;
    }
    std::printf("  %*s%-12s faces %6d area %5.1f%%",
      2 * node.depth,
      "",
      foldingmeshes::ToString(node.kind),
      node.numberOfFaces,
      100.0 * node.area / tree.originalArea);
    if (node.detectionRun)
      std::printf(" S %5.1f%% detect %.3f s %2d starts",
        100.0 * node.symmetricAreaFraction,
        node.detectionSeconds,
        node.detectionStarts);
    if (node.kind == foldingmeshes::FoldingNodeKind::Folding)
      std::printf(" n (%6.3f %6.3f %6.3f) discarded %d",
        node.plane.normal.x(),
        node.plane.normal.y(),
        node.plane.normal.z(),
        node.discardedFaces);
    if (node.kind == foldingmeshes::FoldingNodeKind::Rotation)
      std::printf(" axis (%6.3f %6.3f %6.3f) order %d discarded %d",
        node.axis.direction.x(),
        node.axis.direction.y(),
        node.axis.direction.z(),
        node.rotationOrder,
        node.discardedFaces);
    if (node.kind == foldingmeshes::FoldingNodeKind::Leaf)
      std::printf(
        " stored %d (%s)", node.mesh.NumberOfFaces(), foldingmeshes::ToString(node.leafReason));
    std::printf("\n");
  }
  std::printf("  %d detections (%d starts) took %.3f s of the %.3f s build (%.0f%%)\n",
    detections,
    starts,
    detection,
    tree.buildSeconds,
    tree.buildSeconds > 0.0 ? 100.0 * detection / tree.buildSeconds : 0.0);
}

void Run(const std::string& path, vtkPolyData* mesh, const Settings& settings)
{
  const std::string stem = std::filesystem::path(path).stem().string();
  vtkNew<vtkFoldingTreeBuilder> builder;
  builder->SetInputData(mesh);
  Configure(builder, settings, settings.rotationNodes);
  const auto t0 = Clock::now();
  builder->Update();
  const double build = std::chrono::duration<double>(Clock::now() - t0).count();
  auto* tree = vtkMultiBlockDataSet::SafeDownCast(builder->GetOutputDataObject(0));
  vtkPolyData* input = builder->GetOutput(1);
  if (!tree || tree->GetNumberOfBlocks() < 2 || input->GetNumberOfCells() == 0)
  {
    std::printf("%-26s error: folding failed\n", stem.c_str());
    return;
  }
  if (!settings.unfold)
  {
    std::printf("%-26s %7d %7d %6.1f%% %3d %7.3f\n",
      stem.c_str(),
      static_cast<int>(TreeValue(tree, "OriginalFaces")),
      static_cast<int>(TreeValue(tree, "StoredFaces")),
      100.0 * TreeValue(tree, "Compression"),
      static_cast<int>(TreeValue(tree, "TreeHeight")),
      build);
    if (settings.printTree)
      PrintOutline(tree);
    std::fflush(stdout);
    return;
  }
  vtkNew<vtkFoldingTreeUnfolder> unfolder;
  unfolder->SetInputData(tree);
  unfolder->SetCloseHoles(settings.closeHoles);
  unfolder->SetRemoveProjectedPoints(settings.removeProjectedPoints);
  unfolder->SetMatchDiscardedDensity(settings.matchDiscardedDensity);
  if (settings.holeToleranceScale >= 0.0)
    unfolder->SetHoleToleranceScale(settings.holeToleranceScale);
  const auto t1 = Clock::now();
  unfolder->Update();
  const double unfold = std::chrono::duration<double>(Clock::now() - t1).count();
  vtkPolyData* unfolded = unfolder->GetOutput();
  if (unfolded->GetNumberOfCells() == 0)
  {
    std::printf("%-26s error: unfolding failed\n", stem.c_str());
    return;
  }

  double bounds[6];
  input->GetBounds(bounds);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  double hausdorff = 0.0, mean = 0.0;
  foldingmeshes::SymmetricSurfaceDistance(input, unfolded, hausdorff, mean, settings.locator);
  hausdorff /= diagonal;
  mean /= diagonal;
  // The proved bound, within 1e-4 of the diagonal; whether it is within epsilon decided to
  // 1e-7 of the diagonal where that is closer ('?': still undecided).
  const foldingmeshes::ProvedDistance proved = foldingmeshes::ProvedSurfaceDistance(input,
    unfolded,
    1e-4 * diagonal,
    TreeValue(tree, "RootEpsilon"),
    1e-7 * diagonal,
    settings.locator);
  const char* verdict = proved.within > 0 ? " " : proved.within < 0 ? "!" : "?";
  const double upperBound = proved.upper / diagonal;
  const double epsilon = TreeValue(tree, "RootEpsilon") / diagonal;

  const foldingmeshes::EdgeCounts before = foldingmeshes::CountEdges(input);
  const foldingmeshes::EdgeCounts after = foldingmeshes::CountEdges(unfolded);
  std::printf("%-26s %7d %7d %6.1f%% %3d %7.3f %7.3f %7.4f%s %8.5f %7.4f%s %6lld %6lld %4lld %4lld "
              "%4lld %4lld "
              "%6lld %6lld %+6.1f%% %7lld %+6.1f%% %5d %5d %5d %6.3f %6.3f",
    stem.c_str(),
    static_cast<int>(TreeValue(tree, "OriginalFaces")),
    static_cast<int>(TreeValue(tree, "StoredFaces")),
    100.0 * TreeValue(tree, "Compression"),
    static_cast<int>(TreeValue(tree, "TreeHeight")),
    build,
    unfold,
    hausdorff,
    hausdorff <= epsilon ? " " : "!",
    mean,
    upperBound,
    verdict,
    before.open,
    after.open,
    before.nonManifold,
    after.nonManifold,
    before.misoriented,
    after.misoriented,
    before.vertices,
    after.vertices,
    before.vertices > 0 ? 100.0 * (after.vertices - before.vertices) / before.vertices : 0.0,
    static_cast<long long>(unfolded->GetNumberOfCells()),
    100.0 * (unfolded->GetNumberOfCells() - input->GetNumberOfCells()) /
      std::max<vtkIdType>(1, input->GetNumberOfCells()),
    static_cast<int>(FieldValue(unfolded, "RemovedProjectedPoints")),
    static_cast<int>(FieldValue(unfolded, "ProjectedPoints")),
    static_cast<int>(FieldValue(unfolded, "ThinnedCopyPoints")),
    FieldValue(unfolded, "AreaRatio"),
    FieldValue(unfolded, "FilledAreaRatio"));
  if (const PaperRow* row = FindPaperRow(stem))
    std::printf("  | %-11s %6d %6d %5.1f%% %3d %5.0f",
      row->model,
      row->faces,
      row->stored,
      row->compression,
      row->height,
      row->seconds);
  std::printf("\n");
  if (settings.printTree)
    PrintOutline(tree);
  std::fflush(stdout);
}
}

int main(int argc, char* argv[])
{
  foldingmeshes::cli::KeepFreedMemoryForReuse(); // as the command-line program does
  std::vector<std::string> meshes;
  Settings settings;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--no-close-holes")
      settings.closeHoles = false;
    else if (arg == "--keep-projected-points")
      settings.removeProjectedPoints = false;
    else if (arg == "--keep-copy-density")
      settings.matchDiscardedDensity = false;
    else if (arg == "--hole-tolerance" && i + 1 < argc)
      settings.holeToleranceScale = std::atof(argv[++i]);
    else if (arg == "--tolerance" && i + 1 < argc)
      settings.tolerance = std::atof(argv[++i]);
    else if (arg == "--threads" && i + 1 < argc)
    {
      vtkSMPTools::SetBackend("STDThread");
      vtkSMPTools::Initialize(std::atoi(argv[++i]));
    }
    else if (arg == "--keep" && i + 1 < argc)
      settings.keepFewer = std::string(argv[++i]) == "fewer";
    else if (arg == "--rotation")
      settings.rotationNodes = vtkFoldingTreeBuilder::ROTATION_NODES_ON;
    else if (arg == "--no-rotation")
      settings.rotationNodes = vtkFoldingTreeBuilder::ROTATION_NODES_OFF;
    else if (arg == "--rotation-when-axial")
      settings.rotationNodes = vtkFoldingTreeBuilder::ROTATION_NODES_WHEN_AXIAL;
    else if (arg == "--compare-rotation")
      settings.compareRotation = true;
    else if (arg == "--tree")
      settings.printTree = true;
    else if (arg == "--no-unfold")
      settings.unfold = false;
    else if (arg == "--distance-locator" && i + 1 < argc)
    {
      const std::string which = argv[++i];
      if (which != "static" && which != "facetree")
      {
        std::fprintf(
          stderr, "--distance-locator must be static or facetree, not '%s'\n", which.c_str());
        return 1;
      }
      settings.locator = which == "facetree" ? foldingmeshes::DistanceLocator::FaceTree
                                             : foldingmeshes::DistanceLocator::StaticCellLocator;
    }
    else
    {
      const std::vector<std::string> found = foldingmeshes::MeshFiles(arg);
      meshes.insert(meshes.end(), found.begin(), found.end());
    }
  }
  std::printf("SMP backend %s, %d threads; root epsilon %g%% of the diagonal ('!' after a "
              "Hausdorff distance: above it; Hmax: proved bound over whole surfaces); "
              "distances through %s\n",
    vtkSMPTools::GetBackend(),
    vtkSMPTools::GetEstimatedNumberOfThreads(),
    100.0 * (settings.tolerance >= 0.0 ? settings.tolerance : 0.02),
    settings.locator == foldingmeshes::DistanceLocator::StaticCellLocator ? "vtkStaticCellLocator"
                                                                          : "the face tree");
  std::printf("%-26s %7s %7s %7s %3s %7s %7s %8s %8s %8s %6s %6s %4s %4s %4s %4s %6s %6s %7s %7s "
              "%7s %5s %5s %5s %6s %6s  | "
              "%-11s %6s %6s %6s %3s %5s\n",
    "mesh",
    "faces",
    "stored",
    "compr",
    "h",
    "build s",
    "unfld s",
    "H/diag",
    "mean/dg",
    "Hmax/dg",
    "open<",
    "open>",
    "nm<",
    "nm>",
    "mis<",
    "mis>",
    "pts<",
    "pts>",
    "pts+",
    "faces>",
    "faces+",
    "rmvd",
    "proj",
    "thin",
    "area",
    "fill",
    "paper",
    "faces",
    "stored",
    "compr",
    "h",
    "s");
  for (const std::string& path : meshes)
  {
    std::string error;
    auto mesh = foldingmeshes::ReadMesh(path, error);
    if (!mesh)
    {
      std::printf("%-26s error: %s\n", path.c_str(), error.c_str());
      continue;
    }
    Run(path, mesh, settings);
    if (settings.compareRotation)
      CompareRotation(mesh, settings);
  }
  return 0;
}
