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
  const int leaves = static_cast<int>(TreeValue(tree, "NumberOfLeaves"));
  const int nodes = static_cast<int>(TreeValue(tree, "NumberOfNodes"));
  const double epsilon = TreeValue(tree, "RootEpsilon");
  const double buildSeconds = TreeValue(tree, "BuildSeconds");
  const double verifiedBound = TreeValue(tree, "VerifiedBound", -1.0);
  const int pinnedFaces = static_cast<int>(TreeValue(tree, "PinnedFaces"));
  const int rounds = static_cast<int>(TreeValue(tree, "VerificationRounds"));
  if (f.json)
  {
    std::printf("{\n  \"mesh\": %s,\n  \"originalFaces\": %d,\n  \"storedFaces\": %d,\n"
                "  \"compression\": %.6f,\n  \"treeHeight\": %d,\n  \"folds\": %d,\n"
                "  \"leaves\": %d,\n  \"nodes\": %d,\n  \"rootEpsilon\": %.9g,\n"
                "  \"verifiedBound\": %.9g,\n  \"pinnedFaces\": %d,\n"
                "  \"verificationRounds\": %d,\n"
                "  \"buildSeconds\": %.3f,\n  \"seconds\": %.3f,\n"
                "  \"outputs\": {\"tree\": %s, \"segmentation\": %s, \"picture\": %s}\n}\n",
      JsonString(f.meshPath).c_str(),
      original,
      stored,
      compression,
      height,
      folds,
      leaves,
      nodes,
      epsilon,
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
    std::printf("tree:                    height %d, %d folds, %d leaves, %d nodes\n",
      height,
      folds,
      leaves,
      nodes);
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
/// unfold (decompress false) and decompress (true): they differ in the input they accept
/// and in the names of their outputs.
int UnfoldTree(int argc, char* argv[], bool decompress)
{
  std::string treePath, outdir = ".", originalPath;
  int upAxis = -1;
  bool json = false, quiet = false;
  vtkNew<vtkFoldingTreeUnfolder> unfolder; // options not given keep the filter's defaults
  for (int i = 0; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h")
    {
      std::cout << Usage;
      std::exit(0);
    }
    else if (arg == "--outdir")
    {
      if (i + 1 >= argc)
        throw std::runtime_error("missing value after --outdir");
      outdir = argv[++i];
    }
    else if (arg == "--up")
    {
      if (i + 1 >= argc)
        throw std::runtime_error("missing value after --up");
      upAxis = ParseUpAxis(argv[++i]);
    }
    else if (arg == "--no-stitch")
      unfolder->StitchOff();
    else if (arg == "--no-close-holes")
      unfolder->CloseHolesOff();
    else if (arg == "--keep-projected-points")
      unfolder->RemoveProjectedPointsOff();
    else if (arg == "--keep-copy-density")
      unfolder->MatchDiscardedDensityOff();
    else if (arg == "--original")
    {
      if (i + 1 >= argc)
        throw std::runtime_error("missing value after --original");
      originalPath = argv[++i];
    }
    else if (arg == "--json")
      json = true;
    else if (arg == "--quiet")
      quiet = true;
    else if (!arg.empty() && arg[0] == '-')
      throw std::runtime_error("unknown option '" + arg + "'");
    else if (treePath.empty())
      treePath = arg;
    else
      throw std::runtime_error("more than one tree given ('" + arg + "')");
  }
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
  if (!originalPath.empty())
  {
    original = foldingmeshes::ReadMesh(originalPath, error);
    if (!original)
    {
      std::cerr << "foldingmeshes: " << error << "\n";
      return 2;
    }
    unfolder->SetOriginalData(original);
  }
  const auto start = std::chrono::steady_clock::now();
  if (!RunFilter(unfolder, "unfolding", quiet, error))
  {
    std::cerr << "foldingmeshes: " << treePath << ": " << error << "\n";
    return 2;
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  vtkPolyData* mesh = unfolder->GetOutput();

  const std::string stem = TreeStem(treePath);
  const std::filesystem::path dir(outdir);
  const std::string suffix = decompress ? "" : "_unfolded";
  const std::string meshPath = (dir / (stem + suffix + ".vtp")).string();
  std::string picture = (dir / (stem + suffix + ".png")).string();
  if (!MakeOutdir(outdir, error) || !foldingmeshes::WriteMesh(mesh, meshPath, error) ||
    !WriteCategoryPicture(mesh, "FoldingLeafId", upAxis, picture, error))
  {
    std::cerr << "foldingmeshes: " << error << "\n";
    return 3;
  }
  const long long faces = static_cast<long long>(mesh->GetNumberOfCells());
  const int openEdges = static_cast<int>(FieldValue(mesh, "OpenEdges"));
  const int nonManifold = static_cast<int>(FieldValue(mesh, "NonManifoldEdges"));
  const int misoriented = static_cast<int>(FieldValue(mesh, "MisorientedEdges"));
  const int filledLoops = static_cast<int>(FieldValue(mesh, "FilledLoops"));
  const int borderLoops = static_cast<int>(FieldValue(mesh, "BorderLoops"));
  const int openLoops = static_cast<int>(FieldValue(mesh, "OpenLoops"));
  const double openLoopLength = FieldValue(mesh, "OpenLoopLength");
  const int stitched = static_cast<int>(FieldValue(mesh, "StitchedVertices"));
  const int removedProjected = static_cast<int>(FieldValue(mesh, "RemovedProjectedPoints"));
  const int projectedLeft = static_cast<int>(FieldValue(mesh, "ProjectedPoints"));
  const int thinned = static_cast<int>(FieldValue(mesh, "ThinnedCopyPoints"));
  const int foldExcess = static_cast<int>(FieldValue(mesh, "FoldExcessFaces"));
  const int gaps = static_cast<int>(FieldValue(mesh, "OpenGapCount"));
  const double gapLength = FieldValue(mesh, "OpenGapLength");
  const bool stitch = unfolder->GetStitch(), closeHoles = unfolder->GetCloseHoles();
  const bool removeProjected = unfolder->GetRemoveProjectedPoints();
  const bool matchDensity = unfolder->GetMatchDiscardedDensity();
  // With --original: the symmetric Hausdorff distance to it, absolute and / its diagonal.
  const double hausdorff = original ? FieldValue(mesh, "HausdorffToOriginal", -1.0) : -1.0;
  const double hausdorffRelative =
    original ? FieldValue(mesh, "HausdorffToOriginalRelative", -1.0) : -1.0;
  const double meanRelative =
    original ? FieldValue(mesh, "MeanDistanceToOriginalRelative", -1.0) : -1.0;
  const double boundRelative =
    original ? FieldValue(mesh, "HausdorffToOriginalBoundRelative", -1.0) : -1.0;
  std::error_code ec;
  const auto inputBytes = static_cast<long long>(std::filesystem::file_size(treePath, ec));
  const double quantizationError = TreeValue(tree, "QuantizationError", 0.0);
  if (json)
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
      JsonString(treePath).c_str(),
      inputBytes,
      quantizationError,
      JsonString(meshPath).c_str(),
      stitch ? "true" : "false",
      faces,
      static_cast<long long>(mesh->GetNumberOfPoints()),
      removedProjected,
      projectedLeft,
      thinned,
      foldExcess,
      openEdges,
      nonManifold,
      misoriented,
      closeHoles ? "true" : "false",
      filledLoops,
      borderLoops,
      openLoops,
      openLoopLength,
      stitched,
      gaps,
      gapLength,
      hausdorff,
      hausdorffRelative,
      boundRelative,
      meanRelative,
      seconds,
      JsonString(meshPath).c_str(),
      picture.empty() ? "null" : JsonString(picture).c_str());
  }
  else
  {
    std::printf("tree:                    %s (%lld bytes)\n", treePath.c_str(), inputBytes);
    if (quantizationError > 0)
      std::printf("quantisation:            points moved up to %.6g (inside the bound)\n",
        quantizationError);
    std::printf("faces:                   %lld (%lld points)\n",
      faces,
      static_cast<long long>(mesh->GetNumberOfPoints()));
    std::printf("projected points:        %d removed, %d left%s\n",
      removedProjected,
      projectedLeft,
      removeProjected ? "" : " (--keep-projected-points)");
    std::printf("mirrored copies thinned: %d points removed, %d faces above the folds' regions "
                "left%s\n",
      thinned,
      foldExcess,
      matchDensity ? "" : " (--keep-copy-density)");
    std::printf("open edges:              %d (non-manifold %d, misoriented %d)\n",
      openEdges,
      nonManifold,
      misoriented);
    std::printf("repair:                  %d loops filled, %d input border loops kept, %d gaps "
                "left open (length %.6g)%s\n",
      filledLoops,
      borderLoops,
      openLoops,
      openLoopLength,
      closeHoles && stitch ? "" : " (off)");
    std::printf("stitched vertices:       %d%s\n", stitched, stitch ? "" : " (stitching off)");
    std::printf(
      "stitch gaps:             %d (length %.6g; before the final repair)\n", gaps, gapLength);
    if (original)
      std::printf("distance to original:    Hausdorff %.6g (%.4f of its diagonal; over whole "
                  "surfaces, proved: %.4f), mean %.5f\n",
        hausdorff,
        hausdorffRelative,
        boundRelative,
        meanRelative);
    std::printf("time:                    %.3f s\n", seconds);
    std::printf("wrote:                   %s\n", meshPath.c_str());
    if (!picture.empty())
      std::printf("                         %s\n", picture.c_str());
  }
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
