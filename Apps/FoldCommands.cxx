// foldingmeshes fold | unfold: folding trees on the command line (roundtrip:
// RoundtripCommand.cxx).
#include "FoldCommandSupport.h"
#include "MeshIO.h"
#include "vtkFoldingTreeCompactReader.h"
#include "vtkFoldingTreeUnfolder.h"

#include <vtkNew.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>

namespace foldingmeshes
{
namespace cli
{
int Fold(int argc, char* argv[])
{
  const FoldSettings f = ParseFoldArguments(argc, argv);
  if (f.keepProjectedPoints)
    throw std::runtime_error("--keep-projected-points is an option of unfold and roundtrip");
  if (f.keepCopyDensity)
    throw std::runtime_error("--keep-copy-density is an option of unfold and roundtrip");
  if (f.noStitch)
    throw std::runtime_error("--no-stitch is an option of unfold and roundtrip");
  if (f.noCloseHoles)
    throw std::runtime_error("--no-close-holes is an option of unfold and roundtrip");
  if (f.distanceLocator)
    throw std::runtime_error("--distance-locator is an option of roundtrip");
  std::string error;
  vtkSmartPointer<vtkPolyData> mesh = foldingmeshes::ReadMesh(f.meshPath, error);
  if (!mesh)
  {
    std::cerr << "foldingmeshes: " << error << "\n";
    return 2;
  }
  vtkNew<vtkFoldingTreeBuilder> builder;
  ConfigureBuilder(builder, f);
  builder->SetInputData(mesh);
  const auto start = std::chrono::steady_clock::now();
  if (!RunFilter(builder, "folding", f.quiet, error))
  {
    std::cerr << "foldingmeshes: " << f.meshPath << ": " << error << "\n";
    return 2;
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  auto* tree = vtkMultiBlockDataSet::SafeDownCast(builder->GetOutputDataObject(0));
  vtkPolyData* segmentation = builder->GetOutput(1);

  const std::string stem = std::filesystem::path(f.meshPath).stem().string();
  const std::filesystem::path dir(f.outdir);
  const std::string treePath = (dir / (stem + "_tree.vtm")).string();
  const std::string segPath = (dir / (stem + "_segmentation.vtp")).string();
  std::string picture = (dir / (stem + "_segmentation.png")).string();
  if (!MakeOutdir(f.outdir, error) || !WriteTree(tree, treePath, error) ||
    !foldingmeshes::WriteMesh(segmentation, segPath, error) ||
    !WriteCategoryPicture(segmentation, "FoldingLeafId", f.upAxis, picture, error))
  {
    std::cerr << "foldingmeshes: " << error << "\n";
    return 3;
  }

  const int original = static_cast<int>(TreeValue(tree, "OriginalFaces"));
  const int stored = static_cast<int>(TreeValue(tree, "StoredFaces"));
  const double compression = TreeValue(tree, "Compression");
  const int height = static_cast<int>(TreeValue(tree, "TreeHeight"));
  const int folds = static_cast<int>(TreeValue(tree, "NumberOfFolds"));
  const int rotations = static_cast<int>(TreeValue(tree, "NumberOfRotations"));
  const int leaves = static_cast<int>(TreeValue(tree, "NumberOfLeaves"));
  const int nodes = static_cast<int>(TreeValue(tree, "NumberOfNodes"));
  const double epsilon = TreeValue(tree, "RootEpsilon");
  const double requested = TreeValue(tree, "RequestedEpsilon", epsilon);
  const double buildSeconds = TreeValue(tree, "BuildSeconds");
  const double verifiedBound = TreeValue(tree, "VerifiedBound", -1.0);
  const int pinnedFaces = static_cast<int>(TreeValue(tree, "PinnedFaces"));
  const int rounds = static_cast<int>(TreeValue(tree, "VerificationRounds"));
  if (f.json)
  {
    std::printf(
      "{\n  \"mesh\": %s,\n  \"originalFaces\": %d,\n  \"storedFaces\": %d,\n"
      "  \"compression\": %.6f,\n  \"treeHeight\": %d,\n  \"folds\": %d,\n"
      "  \"rotations\": %d,\n  \"leaves\": %d,\n  \"nodes\": %d,\n  \"rootEpsilon\": %.9g,\n"
      "  \"requestedEpsilon\": %.9g,\n  \"verifiedBound\": %.9g,\n  \"pinnedFaces\": %d,\n"
      "  \"verificationRounds\": %d,\n"
      "  \"buildSeconds\": %.3f,\n  \"seconds\": %.3f,\n"
      "  \"outputs\": {\"tree\": %s, \"segmentation\": %s, \"picture\": %s}\n}\n",
      JsonString(f.meshPath).c_str(),
      original,
      stored,
      compression,
      height,
      folds,
      rotations,
      leaves,
      nodes,
      epsilon,
      requested,
      verifiedBound,
      pinnedFaces,
      rounds,
      buildSeconds,
      seconds,
      JsonString(treePath).c_str(),
      JsonString(segPath).c_str(),
      picture.empty() ? "null" : JsonString(picture).c_str());
  }
  else
  {
    std::printf("mesh:                    %s\n", f.meshPath.c_str());
    std::printf(
      "faces:                   %d original, %d stored (non-redundant)\n", original, stored);
    std::printf("compression:             %.1f%%\n", 100.0 * compression);
    std::printf("tree:                    height %d, %d folds, %d rotations, %d leaves, %d "
                "nodes\n",
      height,
      folds,
      rotations,
      leaves,
      nodes);
    if (epsilon < requested)
      std::printf("root epsilon:            %.6g (%.3f of the requested %.6g: the first tree "
                  "was proved a little beyond it and rebuilt at a smaller epsilon)\n",
        epsilon,
        epsilon / requested,
        requested);
    else
      std::printf("root epsilon:            %.6g\n", epsilon);
    if (verifiedBound >= 0.0)
      std::printf("proved bound:            %.6g (unfold vs mesh; %d faces pinned in %d extra "
                  "build(s))\n",
        verifiedBound,
        pinnedFaces,
        rounds);
    else
      std::printf("proved bound:            not verified\n");
    std::printf("time:                    %.3f s (build %.3f s)\n", seconds, buildSeconds);
    std::printf("wrote:                   %s\n                         %s\n",
      treePath.c_str(),
      segPath.c_str());
    if (!picture.empty())
      std::printf("                         %s\n", picture.c_str());
  }
  return 0;
}

namespace
{
/// What unfold / decompress were asked (the unfolder's options go straight to the filter).
struct UnfoldArguments
{
  std::string treePath, outdir = ".", originalPath;
  int upAxis = -1;
  bool json = false, quiet = false;
};

UnfoldArguments ParseUnfoldArguments(int argc, char* argv[], vtkFoldingTreeUnfolder* unfolder)
{
  UnfoldArguments args;
  for (int i = 0; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&](const char* what) -> std::string
    {
      if (i + 1 >= argc)
        throw std::runtime_error(std::string("missing value after ") + what);
      return argv[++i];
    };
    if (arg == "--help" || arg == "-h")
    {
      std::cout << Usage;
      std::exit(0);
    }
    else if (arg == "--outdir")
      args.outdir = value("--outdir");
    else if (arg == "--up")
      args.upAxis = ParseUpAxis(value("--up"));
    else if (arg == "--no-stitch")
      unfolder->StitchOff();
    else if (arg == "--no-close-holes")
      unfolder->CloseHolesOff();
    else if (arg == "--keep-projected-points")
      unfolder->RemoveProjectedPointsOff();
    else if (arg == "--keep-copy-density")
      unfolder->MatchDiscardedDensityOff();
    else if (arg == "--original")
      args.originalPath = value("--original");
    else if (arg == "--json")
      args.json = true;
    else if (arg == "--quiet")
      args.quiet = true;
    else if (!arg.empty() && arg[0] == '-')
      throw std::runtime_error("unknown option '" + arg + "'");
    else if (args.treePath.empty())
      args.treePath = arg;
    else
      throw std::runtime_error("more than one tree given ('" + arg + "')");
  }
  return args;
}

/// What unfold / decompress report, from the unfolded mesh's field data.
struct UnfoldSummary
{
  std::string treePath, meshPath, picture;
  long long inputBytes = 0, faces = 0, points = 0;
  double quantizationError = 0.0, seconds = 0.0;
  int openEdges = 0, nonManifold = 0, misoriented = 0;
  int filledLoops = 0, borderLoops = 0, openLoops = 0;
  double openLoopLength = 0.0;
  int stitched = 0, removedProjected = 0, projectedLeft = 0, thinned = 0, foldExcess = 0;
  int gaps = 0;
  double gapLength = 0.0;
  bool stitch = true, closeHoles = true, removeProjected = true, matchDensity = true;
  bool original = false;
  // With --original: the symmetric Hausdorff distance to it, absolute and / its diagonal.
  double hausdorff = -1.0, hausdorffRelative = -1.0, meanRelative = -1.0, boundRelative = -1.0;
};

UnfoldSummary SummarizeUnfolding(vtkFoldingTreeUnfolder* unfolder, bool original)
{
  UnfoldSummary r;
  vtkPolyData* mesh = unfolder->GetOutput();
  r.faces = static_cast<long long>(mesh->GetNumberOfCells());
  r.points = static_cast<long long>(mesh->GetNumberOfPoints());
  r.openEdges = static_cast<int>(FieldValue(mesh, "OpenEdges"));
  r.nonManifold = static_cast<int>(FieldValue(mesh, "NonManifoldEdges"));
  r.misoriented = static_cast<int>(FieldValue(mesh, "MisorientedEdges"));
  r.filledLoops = static_cast<int>(FieldValue(mesh, "FilledLoops"));
  r.borderLoops = static_cast<int>(FieldValue(mesh, "BorderLoops"));
  r.openLoops = static_cast<int>(FieldValue(mesh, "OpenLoops"));
  r.openLoopLength = FieldValue(mesh, "OpenLoopLength");
  r.stitched = static_cast<int>(FieldValue(mesh, "StitchedVertices"));
  r.removedProjected = static_cast<int>(FieldValue(mesh, "RemovedProjectedPoints"));
  r.projectedLeft = static_cast<int>(FieldValue(mesh, "ProjectedPoints"));
  r.thinned = static_cast<int>(FieldValue(mesh, "ThinnedCopyPoints"));
  r.foldExcess = static_cast<int>(FieldValue(mesh, "FoldExcessFaces"));
  r.gaps = static_cast<int>(FieldValue(mesh, "OpenGapCount"));
  r.gapLength = FieldValue(mesh, "OpenGapLength");
  r.stitch = unfolder->GetStitch();
  r.closeHoles = unfolder->GetCloseHoles();
  r.removeProjected = unfolder->GetRemoveProjectedPoints();
  r.matchDensity = unfolder->GetMatchDiscardedDensity();
  r.original = original;
  if (original)
  {
    r.hausdorff = FieldValue(mesh, "HausdorffToOriginal", -1.0);
    r.hausdorffRelative = FieldValue(mesh, "HausdorffToOriginalRelative", -1.0);
    r.meanRelative = FieldValue(mesh, "MeanDistanceToOriginalRelative", -1.0);
    r.boundRelative = FieldValue(mesh, "HausdorffToOriginalBoundRelative", -1.0);
  }
  return r;
}

void PrintUnfoldJson(const UnfoldSummary& r)
{
  std::printf("{\n  \"tree\": %s,\n  \"bytes\": %lld,\n  \"quantizationError\": %.9g,\n"
              "  \"output\": %s,\n  \"stitch\": %s,\n  \"faces\": %lld,\n"
              "  \"points\": %lld,\n  \"removedProjectedPoints\": %d,\n"
              "  \"projectedPoints\": %d,\n  \"thinnedCopyPoints\": %d,\n"
              "  \"foldExcessFaces\": %d,\n  \"openEdges\": %d,\n  \"nonManifoldEdges\": %d,\n"
              "  \"misorientedEdges\": %d,\n  \"closeHoles\": %s,\n  \"filledLoops\": %d,\n"
              "  \"borderLoops\": %d,\n  \"openLoops\": %d,\n  \"openLoopLength\": %.9g,\n"
              "  \"stitchedVertices\": %d,\n  \"openGapCount\": %d,\n"
              "  \"openGapLength\": %.9g,\n  \"hausdorffToOriginal\": %.9g,\n"
              "  \"hausdorffToOriginalRelative\": %.9g,\n"
              "  \"hausdorffToOriginalBoundRelative\": %.9g,\n"
              "  \"meanDistanceToOriginalRelative\": %.9g,\n  \"seconds\": %.3f,\n"
              "  \"outputs\": {\"mesh\": %s, \"picture\": %s}\n}\n",
    JsonString(r.treePath).c_str(),
    r.inputBytes,
    r.quantizationError,
    JsonString(r.meshPath).c_str(),
    r.stitch ? "true" : "false",
    r.faces,
    r.points,
    r.removedProjected,
    r.projectedLeft,
    r.thinned,
    r.foldExcess,
    r.openEdges,
    r.nonManifold,
    r.misoriented,
    r.closeHoles ? "true" : "false",
    r.filledLoops,
    r.borderLoops,
    r.openLoops,
    r.openLoopLength,
    r.stitched,
    r.gaps,
    r.gapLength,
    r.hausdorff,
    r.hausdorffRelative,
    r.boundRelative,
    r.meanRelative,
    r.seconds,
    JsonString(r.meshPath).c_str(),
    r.picture.empty() ? "null" : JsonString(r.picture).c_str());
}

void PrintUnfoldText(const UnfoldSummary& r)
{
  std::printf("tree:                    %s (%lld bytes)\n", r.treePath.c_str(), r.inputBytes);
  if (r.quantizationError > 0)
    std::printf(
      "quantisation:            points moved up to %.6g (inside the bound)\n", r.quantizationError);
  std::printf("faces:                   %lld (%lld points)\n", r.faces, r.points);
  std::printf("projected points:        %d removed, %d left%s\n",
    r.removedProjected,
    r.projectedLeft,
    r.removeProjected ? "" : " (--keep-projected-points)");
  std::printf("copies thinned:          %d points removed (mirrored and turned copies), %d "
              "faces above the folds' and rotations' regions left%s\n",
    r.thinned,
    r.foldExcess,
    r.matchDensity ? "" : " (--keep-copy-density)");
  std::printf("open edges:              %d (non-manifold %d, misoriented %d)\n",
    r.openEdges,
    r.nonManifold,
    r.misoriented);
  std::printf("repair:                  %d loops filled, %d input border loops kept, %d gaps "
              "left open (length %.6g)%s\n",
    r.filledLoops,
    r.borderLoops,
    r.openLoops,
    r.openLoopLength,
    r.closeHoles && r.stitch ? "" : " (off)");
  std::printf("stitched vertices:       %d%s\n", r.stitched, r.stitch ? "" : " (stitching off)");
  std::printf(
    "stitch gaps:             %d (length %.6g; before the final repair)\n", r.gaps, r.gapLength);
  if (r.original)
    std::printf("distance to original:    Hausdorff %.6g (%.4f of its diagonal; over whole "
                "surfaces, proved: %.4f), mean %.5f\n",
      r.hausdorff,
      r.hausdorffRelative,
      r.boundRelative,
      r.meanRelative);
  std::printf("time:                    %.3f s\n", r.seconds);
  std::printf("wrote:                   %s\n", r.meshPath.c_str());
  if (!r.picture.empty())
    std::printf("                         %s\n", r.picture.c_str());
}

/// unfold (decompress false) and decompress (true): they differ in the input they accept
/// and in the names of their outputs.
int UnfoldTree(int argc, char* argv[], bool decompress)
{
  vtkNew<vtkFoldingTreeUnfolder> unfolder; // options not given keep the filter's defaults
  const UnfoldArguments args = ParseUnfoldArguments(argc, argv, unfolder);
  const std::string& treePath = args.treePath;
  if (treePath.empty())
    throw std::runtime_error(decompress ? "no .fmz file given" : "no tree given");
  if (decompress && !vtkFoldingTreeCompactReader::CanReadFile(treePath.c_str()))
  {
    std::cerr << "foldingmeshes: cannot read '" << treePath
              << "': not a compact folding-tree (.fmz) file (write one with 'foldingmeshes "
                 "compress')\n";
    return 2;
  }

  std::string error;
  vtkSmartPointer<vtkMultiBlockDataSet> tree = ReadTree(treePath, error);
  if (!tree)
  {
    std::cerr << "foldingmeshes: " << error << "\n";
    return 2;
  }
  unfolder->SetInputData(tree);
  vtkSmartPointer<vtkPolyData> original;
  if (!args.originalPath.empty())
  {
    original = foldingmeshes::ReadMesh(args.originalPath, error);
    if (!original)
    {
      std::cerr << "foldingmeshes: " << error << "\n";
      return 2;
    }
    unfolder->SetOriginalData(original);
  }
  const auto start = std::chrono::steady_clock::now();
  if (!RunFilter(unfolder, "unfolding", args.quiet, error))
  {
    std::cerr << "foldingmeshes: " << treePath << ": " << error << "\n";
    return 2;
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  vtkPolyData* mesh = unfolder->GetOutput();

  const std::string stem = TreeStem(treePath);
  const std::filesystem::path dir(args.outdir);
  const std::string suffix = decompress ? "" : "_unfolded";
  const std::string meshPath = (dir / (stem + suffix + ".vtp")).string();
  std::string picture = (dir / (stem + suffix + ".png")).string();
  if (!MakeOutdir(args.outdir, error) || !foldingmeshes::WriteMesh(mesh, meshPath, error) ||
    !WriteCategoryPicture(mesh, "FoldingLeafId", args.upAxis, picture, error))
  {
    std::cerr << "foldingmeshes: " << error << "\n";
    return 3;
  }
  UnfoldSummary summary = SummarizeUnfolding(unfolder, original != nullptr);
  summary.treePath = treePath;
  summary.meshPath = meshPath;
  summary.picture = picture;
  summary.seconds = seconds;
  std::error_code ec;
  summary.inputBytes = static_cast<long long>(std::filesystem::file_size(treePath, ec));
  summary.quantizationError = TreeValue(tree, "QuantizationError", 0.0);
  if (args.json)
    PrintUnfoldJson(summary);
  else
    PrintUnfoldText(summary);
  return 0;
}
}

int Unfold(int argc, char* argv[])
{
  return UnfoldTree(argc, argv, false);
}

int Decompress(int argc, char* argv[])
{
  return UnfoldTree(argc, argv, true);
}
}
}
