// foldingmeshes fold | unfold | roundtrip: folding trees on the command line.
#include "CommandLine.h"
#include "MeshComparison.h"
#include "MeshIO.h"
#include "MeshPicture.h"
#include "vtkFoldingTreeBuilder.h"
#include "vtkFoldingTreeUnfolder.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLMultiBlockDataWriter.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace foldingmeshes
{
namespace cli
{
namespace
{
// fold / unfold / roundtrip

struct FoldSettings
{
  std::string meshPath, outdir = ".";
  bool json = false, quiet = false;
  double tolerance = 0.02;
  bool absolute = false;
  int keep = vtkFoldingTreeBuilder::MORE_FACES;
  double minAreaFraction = 0.05;
  int maxFolds = 8;
  bool tightSymmetry = false;
  bool keepProjectedPoints = false; // roundtrip's unfolder: RemoveProjectedPoints off
};

double ParseNumber(const std::string& what,
  const std::string& v,
  double lo,
  double hi,
  bool positive)
{
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (end == v.c_str() || *end != '\0' || !(x >= lo && x <= hi) || (positive && !(x > 0.0)))
  {
    std::ostringstream msg;
    msg << what << " needs a number" << (positive ? " > 0" : "") << " in [" << lo << ", " << hi
        << "], got '" << v << "'";
    throw std::runtime_error(msg.str());
  }
  return x;
}

FoldSettings ParseFoldArguments(int argc, char* argv[])
{
  FoldSettings f;
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
    else if (arg == "--tolerance")
    {
      f.tolerance = ParseNumber(arg, value("--tolerance"), 1e-12, 1.0, true);
      f.absolute = false;
    }
    else if (arg == "--absolute-tolerance")
    {
      f.tolerance = ParseNumber(arg, value("--absolute-tolerance"), 1e-12, 1e30, true);
      f.absolute = true;
    }
    else if (arg == "--keep")
    {
      const std::string k = value("--keep");
      if (k != "more" && k != "fewer")
        throw std::runtime_error("--keep must be more or fewer, got '" + k + "'");
      f.keep =
        k == "fewer" ? vtkFoldingTreeBuilder::FEWER_FACES : vtkFoldingTreeBuilder::MORE_FACES;
    }
    else if (arg == "--min-area-fraction")
      f.minAreaFraction = ParseNumber(arg, value("--min-area-fraction"), 0.0, 1.0, false);
    else if (arg == "--max-folds")
    {
      const std::string v = value("--max-folds");
      const double n = ParseNumber(arg, v, 0, 63, false);
      if (n != std::floor(n))
        throw std::runtime_error("--max-folds needs an integer in [0, 63], got '" + v + "'");
      f.maxFolds = static_cast<int>(n);
    }
    else if (arg == "--tight-symmetry")
      f.tightSymmetry = true;
    else if (arg == "--keep-projected-points")
      f.keepProjectedPoints = true;
    else if (arg == "--outdir")
      f.outdir = value("--outdir");
    else if (arg == "--json")
      f.json = true;
    else if (arg == "--quiet")
      f.quiet = true;
    else if (!arg.empty() && arg[0] == '-')
      throw std::runtime_error("unknown option '" + arg + "'");
    else if (f.meshPath.empty())
      f.meshPath = arg;
    else
      throw std::runtime_error("more than one mesh given ('" + arg + "')");
  }
  if (f.meshPath.empty())
    throw std::runtime_error("no mesh given");
  return f;
}

/// Runs `algorithm` with error capture and optional progress; false with the message.
bool RunFilter(vtkAlgorithm* algorithm, const char* label, bool quiet, std::string& error)
{
  ErrorCollector errors;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(&ErrorCollector::OnError);
  onError->SetClientData(&errors);
  const unsigned long errorTag = algorithm->AddObserver(vtkCommand::ErrorEvent, onError);
  ProgressPrinter progress;
  progress.label = label;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetCallback(&ProgressPrinter::OnProgress);
  onProgress->SetClientData(&progress);
  unsigned long progressTag = 0;
  if (!quiet)
    progressTag = algorithm->AddObserver(vtkCommand::ProgressEvent, onProgress);
  const int ok = algorithm->GetExecutive()->Update();
  if (!quiet)
  {
    std::fprintf(stderr, "\n");
    algorithm->RemoveObserver(progressTag);
  }
  algorithm->RemoveObserver(errorTag);
  if (!ok || !errors.messages.empty())
  {
    error = errors.messages.empty() ? std::string(label) + " failed" : errors.messages;
    while (!error.empty() && error.back() == '\n')
      error.pop_back();
    return false;
  }
  return true;
}

void ConfigureBuilder(vtkFoldingTreeBuilder* builder, const FoldSettings& f)
{
  builder->SetTolerance(f.tolerance);
  builder->SetToleranceMode(
    f.absolute ? vtkFoldingTreeBuilder::ABSOLUTE : vtkFoldingTreeBuilder::RELATIVE_TO_DIAGONAL);
  builder->SetKeepSide(f.keep);
  builder->SetMinimumAreaFraction(f.minAreaFraction);
  builder->SetMaximumFolds(f.maxFolds);
  builder->SetRequireTightSymmetry(f.tightSymmetry);
}

/// A number of the tree's "Tree" information block (block 1), or `fallback`.
double TreeValue(vtkMultiBlockDataSet* tree, const char* name, double fallback = 0.0)
{
  auto* info = tree ? vtkPolyData::SafeDownCast(tree->GetBlock(1)) : nullptr;
  vtkDataArray* a = info ? info->GetFieldData()->GetArray(name) : nullptr;
  return a && a->GetNumberOfTuples() > 0 ? a->GetTuple1(0) : fallback;
}

double FieldValue(vtkPolyData* mesh, const char* name, double fallback = 0.0)
{
  vtkDataArray* a = mesh->GetFieldData()->GetArray(name);
  return a && a->GetNumberOfTuples() > 0 ? a->GetTuple1(0) : fallback;
}

bool WriteTree(vtkMultiBlockDataSet* tree, const std::string& path, std::string& error)
{
  vtkNew<vtkXMLMultiBlockDataWriter> writer;
  ErrorCollector errors;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(&ErrorCollector::OnError);
  onError->SetClientData(&errors);
  writer->AddObserver(vtkCommand::ErrorEvent, onError);
  writer->SetFileName(path.c_str());
  writer->SetInputData(tree);
  writer->SetDataModeToAppended();
  writer->SetCompressorTypeToZLib();
  if (!writer->Write() || !errors.messages.empty())
  {
    error = "cannot write '" + path + "'" + (errors.messages.empty() ? "" : ": " + errors.messages);
    return false;
  }
  return true;
}

vtkSmartPointer<vtkMultiBlockDataSet> ReadTree(const std::string& path, std::string& error)
{
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
  {
    error = "cannot read '" + path + "': no such file";
    return nullptr;
  }
  vtkNew<vtkXMLMultiBlockDataReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    error = "cannot read '" + path +
      "': not a VTK XML multiblock (.vtm) file (write a tree with 'foldingmeshes fold')";
    return nullptr;
  }
  reader->SetFileName(path.c_str());
  if (!RunFilter(reader, "reading tree", true, error))
  {
    error = "cannot read '" + path + "': " + error;
    return nullptr;
  }
  auto* tree = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  if (!tree || tree->GetNumberOfBlocks() == 0)
  {
    error = "cannot read '" + path + "': not a multiblock data set";
    return nullptr;
  }
  vtkSmartPointer<vtkMultiBlockDataSet> copy = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  copy->ShallowCopy(tree);
  return copy;
}

/// Writes a picture of `mesh` coloured by the cell array `arrayName`; skipped without a
/// display (the returned path is then empty). False (with error) when it cannot be written.
bool WriteCategoryPicture(vtkPolyData* mesh,
  const char* arrayName,
  std::string& picture,
  std::string& error)
{
  if (!std::getenv("DISPLAY"))
  {
    std::cerr << "foldingmeshes: no display, picture skipped (run under xvfb-run -a)\n";
    picture.clear();
    return true;
  }
  auto window = foldingmeshes::MakeCategoryScene(mesh, arrayName, 800, 600);
  return foldingmeshes::WritePicture(window, picture, error);
}

std::string TreeStem(const std::string& path)
{
  std::string stem = std::filesystem::path(path).stem().string();
  const std::string suffix = "_tree";
  if (stem.size() > suffix.size() &&
    stem.compare(stem.size() - suffix.size(), suffix.size(), suffix) == 0)
    stem.erase(stem.size() - suffix.size());
  return stem;
}

bool MakeOutdir(const std::string& outdir, std::string& error)
{
  std::error_code ec;
  std::filesystem::create_directories(outdir, ec);
  if (ec || !std::filesystem::is_directory(outdir))
  {
    error = "cannot create folder '" + outdir + "'" + (ec ? ": " + ec.message() : "");
    return false;
  }
  return true;
}

}

int Fold(int argc, char* argv[])
{
  const FoldSettings f = ParseFoldArguments(argc, argv);
  if (f.keepProjectedPoints)
    throw std::runtime_error("--keep-projected-points is an option of unfold and roundtrip");
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
    !WriteCategoryPicture(segmentation, "FoldingLeafId", picture, error))
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
  if (f.json)
  {
    std::printf("{\n  \"mesh\": %s,\n  \"originalFaces\": %d,\n  \"storedFaces\": %d,\n"
                "  \"compression\": %.6f,\n  \"treeHeight\": %d,\n  \"folds\": %d,\n"
                "  \"leaves\": %d,\n  \"nodes\": %d,\n  \"rootEpsilon\": %.9g,\n"
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
    std::printf("time:                    %.3f s (build %.3f s)\n", seconds, buildSeconds);
    std::printf("wrote:                   %s\n                         %s\n",
      treePath.c_str(),
      segPath.c_str());
    if (!picture.empty())
      std::printf("                         %s\n", picture.c_str());
  }
  return 0;
}

int Unfold(int argc, char* argv[])
{
  std::string treePath, outdir = ".", originalPath;
  bool json = false, quiet = false, stitch = true, closeHoles = true, removeProjected = true;
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
    else if (arg == "--no-stitch")
      stitch = false;
    else if (arg == "--no-close-holes")
      closeHoles = false;
    else if (arg == "--keep-projected-points")
      removeProjected = false;
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
    throw std::runtime_error("no tree given");

  std::string error;
  vtkSmartPointer<vtkMultiBlockDataSet> tree = ReadTree(treePath, error);
  if (!tree)
  {
    std::cerr << "foldingmeshes: " << error << "\n";
    return 2;
  }
  vtkNew<vtkFoldingTreeUnfolder> unfolder;
  unfolder->SetStitch(stitch);
  unfolder->SetCloseHoles(closeHoles);
  unfolder->SetRemoveProjectedPoints(removeProjected);
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
  const std::string meshPath = (dir / (stem + "_unfolded.vtp")).string();
  std::string picture = (dir / (stem + "_unfolded.png")).string();
  if (!MakeOutdir(outdir, error) || !foldingmeshes::WriteMesh(mesh, meshPath, error) ||
    !WriteCategoryPicture(mesh, "FoldingLeafId", picture, error))
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
  const int gaps = static_cast<int>(FieldValue(mesh, "OpenGapCount"));
  const double gapLength = FieldValue(mesh, "OpenGapLength");
  // With --original: the symmetric Hausdorff distance to it, absolute and / its diagonal.
  const double hausdorff = original ? FieldValue(mesh, "HausdorffToOriginal", -1.0) : -1.0;
  const double hausdorffRelative =
    original ? FieldValue(mesh, "HausdorffToOriginalRelative", -1.0) : -1.0;
  const double meanRelative =
    original ? FieldValue(mesh, "MeanDistanceToOriginalRelative", -1.0) : -1.0;
  if (json)
  {
    std::printf("{\n  \"tree\": %s,\n  \"stitch\": %s,\n  \"faces\": %lld,\n"
                "  \"points\": %lld,\n  \"removedProjectedPoints\": %d,\n"
                "  \"projectedPoints\": %d,\n  \"openEdges\": %d,\n  \"nonManifoldEdges\": %d,\n"
                "  \"misorientedEdges\": %d,\n  \"closeHoles\": %s,\n  \"filledLoops\": %d,\n"
                "  \"borderLoops\": %d,\n  \"openLoops\": %d,\n  \"openLoopLength\": %.9g,\n"
                "  \"stitchedVertices\": %d,\n  \"openGapCount\": %d,\n"
                "  \"openGapLength\": %.9g,\n  \"hausdorffToOriginal\": %.9g,\n"
                "  \"hausdorffToOriginalRelative\": %.9g,\n"
                "  \"meanDistanceToOriginalRelative\": %.9g,\n  \"seconds\": %.3f,\n"
                "  \"outputs\": {\"mesh\": %s, \"picture\": %s}\n}\n",
      JsonString(treePath).c_str(),
      stitch ? "true" : "false",
      faces,
      static_cast<long long>(mesh->GetNumberOfPoints()),
      removedProjected,
      projectedLeft,
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
      meanRelative,
      seconds,
      JsonString(meshPath).c_str(),
      picture.empty() ? "null" : JsonString(picture).c_str());
  }
  else
  {
    std::printf("tree:                    %s\n", treePath.c_str());
    std::printf("faces:                   %lld (%lld points)\n",
      faces,
      static_cast<long long>(mesh->GetNumberOfPoints()));
    std::printf("projected points:        %d removed, %d left%s\n",
      removedProjected,
      projectedLeft,
      removeProjected ? "" : " (--keep-projected-points)");
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
      std::printf("distance to original:    Hausdorff %.6g (%.4f of its diagonal), mean %.5f\n",
        hausdorff,
        hausdorffRelative,
        meanRelative);
    std::printf("time:                    %.3f s\n", seconds);
    std::printf("wrote:                   %s\n", meshPath.c_str());
    if (!picture.empty())
      std::printf("                         %s\n", picture.c_str());
  }
  return 0;
}

int Roundtrip(int argc, char* argv[])
{
  const FoldSettings f = ParseFoldArguments(argc, argv);
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
  auto t0 = std::chrono::steady_clock::now();
  if (!RunFilter(builder, "folding", f.quiet, error))
  {
    std::cerr << "foldingmeshes: " << f.meshPath << ": " << error << "\n";
    return 2;
  }
  const double foldSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  auto* tree = vtkMultiBlockDataSet::SafeDownCast(builder->GetOutputDataObject(0));
  vtkPolyData* input = builder->GetOutput(1); // the triangulated input

  const std::string stem = std::filesystem::path(f.meshPath).stem().string();
  const std::filesystem::path dir(f.outdir);
  const std::string treePath = (dir / (stem + "_tree.vtm")).string();
  const std::string unfoldedPath = (dir / (stem + "_unfolded.vtp")).string();
  if (!MakeOutdir(f.outdir, error) || !WriteTree(tree, treePath, error))
  {
    std::cerr << "foldingmeshes: " << error << "\n";
    return 3;
  }
  vtkSmartPointer<vtkMultiBlockDataSet> readBack = ReadTree(treePath, error);
  if (!readBack)
  {
    std::cerr << "foldingmeshes: " << error << "\n";
    return 2;
  }
  vtkNew<vtkFoldingTreeUnfolder> unfolder;
  unfolder->SetRemoveProjectedPoints(!f.keepProjectedPoints);
  unfolder->SetInputData(readBack);
  t0 = std::chrono::steady_clock::now();
  if (!RunFilter(unfolder, "unfolding", f.quiet, error))
  {
    std::cerr << "foldingmeshes: " << treePath << ": " << error << "\n";
    return 2;
  }
  const double unfoldSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  vtkPolyData* unfolded = unfolder->GetOutput();
  if (!foldingmeshes::WriteMesh(unfolded, unfoldedPath, error))
  {
    std::cerr << "foldingmeshes: " << error << "\n";
    return 3;
  }

  double bounds[6];
  input->GetBounds(bounds);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  double hausdorff = 0.0, mean = 0.0;
  foldingmeshes::SymmetricSurfaceDistance(input, unfolded, hausdorff, mean);
  const double epsilon = TreeValue(tree, "RootEpsilon");
  const bool within = hausdorff <= epsilon;
  const foldingmeshes::EdgeCounts before = foldingmeshes::CountEdges(input),
                                  after = foldingmeshes::CountEdges(unfolded);
  const long long openBefore = before.open, openAfter = after.open;
  const int removedProjected = static_cast<int>(FieldValue(unfolded, "RemovedProjectedPoints"));
  const double scale = diagonal > 0 ? 1.0 / diagonal : 0.0;
  const int original = static_cast<int>(TreeValue(tree, "OriginalFaces"));
  const int stored = static_cast<int>(TreeValue(tree, "StoredFaces"));
  const double compression = TreeValue(tree, "Compression");
  const int height = static_cast<int>(TreeValue(tree, "TreeHeight"));
  if (f.json)
  {
    std::printf("{\n  \"mesh\": %s,\n  \"originalFaces\": %d,\n  \"storedFaces\": %d,\n"
                "  \"compression\": %.6f,\n  \"treeHeight\": %d,\n  \"unfoldedFaces\": %lld,\n"
                "  \"originalVertices\": %lld,\n  \"unfoldedVertices\": %lld,\n"
                "  \"removedProjectedPoints\": %d,\n"
                "  \"diagonal\": %.9g,\n  \"rootEpsilon\": %.9g,\n"
                "  \"rootEpsilonFraction\": %.9g,\n  \"hausdorff\": %.9g,\n"
                "  \"hausdorffFraction\": %.9g,\n  \"meanDistanceFraction\": %.9g,\n"
                "  \"withinBound\": %s,\n  \"openEdgesBefore\": %lld,\n"
                "  \"openEdgesAfter\": %lld,\n  \"openGapCount\": %d,\n"
                "  \"foldSeconds\": %.3f,\n  \"unfoldSeconds\": %.3f,\n"
                "  \"outputs\": {\"tree\": %s, \"unfolded\": %s}\n}\n",
      JsonString(f.meshPath).c_str(),
      original,
      stored,
      compression,
      height,
      static_cast<long long>(unfolded->GetNumberOfCells()),
      before.vertices,
      after.vertices,
      removedProjected,
      diagonal,
      epsilon,
      epsilon * scale,
      hausdorff,
      hausdorff * scale,
      mean * scale,
      within ? "true" : "false",
      openBefore,
      openAfter,
      static_cast<int>(FieldValue(unfolded, "OpenGapCount")),
      foldSeconds,
      unfoldSeconds,
      JsonString(treePath).c_str(),
      JsonString(unfoldedPath).c_str());
  }
  else
  {
    std::printf("mesh:                    %s\n", f.meshPath.c_str());
    std::printf("faces:                   %d original, %d stored (%.1f%% compression), "
                "%lld unfolded\n",
      original,
      stored,
      100.0 * compression,
      static_cast<long long>(unfolded->GetNumberOfCells()));
    std::printf("vertices:                %lld original, %lld unfolded (%+.1f%%; %d projected "
                "points removed%s)\n",
      before.vertices,
      after.vertices,
      before.vertices > 0 ? 100.0 * (after.vertices - before.vertices) / before.vertices : 0.0,
      removedProjected,
      f.keepProjectedPoints ? ", --keep-projected-points" : "");
    std::printf("tree height:             %d\n", height);
    std::printf("hausdorff / diagonal:    %.6f max, %.6f mean (bound: root epsilon %.6f) %s\n",
      hausdorff * scale,
      mean * scale,
      epsilon * scale,
      within ? "ok" : "VIOLATED");
    std::printf(
      "open edges:              %lld before, %lld after (%d stitch gaps before the repair)\n",
      openBefore,
      openAfter,
      static_cast<int>(FieldValue(unfolded, "OpenGapCount")));
    std::printf(
      "time:                    fold %.3f s, unfold %.3f s\n", foldSeconds, unfoldSeconds);
    std::printf("wrote:                   %s\n                         %s\n",
      treePath.c_str(),
      unfoldedPath.c_str());
  }
  if (!within)
  {
    std::cerr << "foldingmeshes: " << f.meshPath << ": Hausdorff distance " << hausdorff
              << " exceeds the root epsilon " << epsilon << "\n";
    return 4;
  }
  return 0;
}
}
}
