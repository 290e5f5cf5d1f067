// Shared parts of the fold / unfold / roundtrip commands: arguments, running a filter with
// progress and error capture, tree files, field values, pictures.
#include "FoldCommandSupport.h"

#include "MeshPicture.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkExpatSafeXMLMultiBlockDataReader.h>
#include <vtkFieldData.h>
#include <vtkFoldingTreeCompactReader.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkXMLMultiBlockDataWriter.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace foldingmeshes
{
namespace cli
{
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
    }
    else if (arg == "--absolute-tolerance")
    {
      f.absoluteTolerance = ParseNumber(arg, value("--absolute-tolerance"), 1e-12, 1e30, true);
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
      f.maxFolds = ParseInteger(arg, value("--max-folds"), 0, 63);
    else if (arg == "--min-faces")
      f.minFaces = ParseInteger(arg, value("--min-faces"), 1, 1000000000);
    else if (arg == "--method")
    {
      const std::string m = value("--method");
      if (m != "robust" && m != "paper")
        throw std::runtime_error("--method must be robust or paper, got '" + m + "'");
      f.method = m == "paper" ? vtkFoldingTreeBuilder::PAPER : vtkFoldingTreeBuilder::ROBUST;
    }
    else if (arg == "--seed")
      f.randomSeed = ParseInteger(arg, value("--seed"), -2147483647, 2147483647);
    else if (arg == "--tight-symmetry")
      f.tightSymmetry = true;
    else if (arg == "--no-verify-bound")
      f.noVerifyBound = true;
    else if (arg == "--separate-parts")
      f.separateParts = true;
    else if (arg == "--rotation")
      f.rotationNodes = true;
    else if (arg == "--rotation-when-axial")
      f.rotationWhenAxial = true;
    else if (arg == "--no-rotation")
      f.noRotation = true;
    else if (arg == "--max-rotation-order")
      f.maxRotationOrder = ParseInteger(arg, value("--max-rotation-order"), 2, 360);
    else if (arg == "--sampled-search-above")
      f.sampledSearchAboveFaces = ParseInteger(arg, value("--sampled-search-above"), 0, 1000000000);
    else if (arg == "--keep-projected-points")
      f.keepProjectedPoints = true;
    else if (arg == "--keep-copy-density")
      f.keepCopyDensity = true;
    else if (arg == "--no-stitch")
      f.noStitch = true;
    else if (arg == "--no-close-holes")
      f.noCloseHoles = true;
    else if (arg == "--distance-locator")
    {
      const std::string which = value("--distance-locator");
      if (which != "static" && which != "facetree")
        throw std::runtime_error(
          "--distance-locator must be static or facetree, not '" + which + "'");
      f.distanceLocator =
        which == "static" ? DistanceLocator::StaticCellLocator : DistanceLocator::FaceTree;
    }
    else if (arg == "--outdir")
      f.outdir = value("--outdir");
    else if (arg == "--up")
      f.upAxis = ParseUpAxis(value("--up"));
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
  if (int(f.rotationNodes) + int(f.rotationWhenAxial) + int(f.noRotation) > 1)
    throw std::runtime_error(
      "--rotation, --rotation-when-axial and --no-rotation exclude each other");
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
  if (f.absoluteTolerance)
  {
    builder->SetTolerance(*f.absoluteTolerance);
    builder->SetToleranceMode(vtkFoldingTreeBuilder::ABSOLUTE);
  }
  else if (f.tolerance)
  {
    builder->SetTolerance(*f.tolerance);
    builder->SetToleranceMode(vtkFoldingTreeBuilder::RELATIVE_TO_DIAGONAL);
  }
  if (f.keep)
    builder->SetKeepSide(*f.keep);
  if (f.minAreaFraction)
    builder->SetMinimumAreaFraction(*f.minAreaFraction);
  if (f.maxFolds)
    builder->SetMaximumFolds(*f.maxFolds);
  if (f.minFaces)
    builder->SetMinimumFaces(*f.minFaces);
  if (f.method)
    builder->SetMethod(*f.method);
  if (f.randomSeed)
    builder->SetRandomSeed(*f.randomSeed);
  if (f.sampledSearchAboveFaces)
    builder->SetSampledSearchAboveFaces(*f.sampledSearchAboveFaces);
  if (f.tightSymmetry)
    builder->RequireTightSymmetryOn();
  if (f.noVerifyBound)
    builder->VerifyBoundOff();
  if (f.separateParts)
    builder->ConnectNearbyPartsOff();
  if (f.rotationNodes)
    builder->SetRotationNodes(vtkFoldingTreeBuilder::ROTATION_NODES_ON);
  else if (f.rotationWhenAxial)
    builder->SetRotationNodes(vtkFoldingTreeBuilder::ROTATION_NODES_WHEN_AXIAL);
  else if (f.noRotation)
    builder->SetRotationNodes(vtkFoldingTreeBuilder::ROTATION_NODES_OFF);
  if (f.maxRotationOrder)
    builder->SetMaximumRotationOrder(*f.maxRotationOrder);
}

/// A number of the tree's "Tree" information block (block 1), or `fallback`.
double TreeValue(vtkMultiBlockDataSet* tree, const char* name, double fallback)
{
  auto* info = tree ? vtkPolyData::SafeDownCast(tree->GetBlock(1)) : nullptr;
  vtkDataArray* a = info ? info->GetFieldData()->GetArray(name) : nullptr;
  return a && a->GetNumberOfTuples() > 0 ? a->GetTuple1(0) : fallback;
}

double FieldValue(vtkPolyData* mesh, const char* name, double fallback)
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
  // Inline binary pieces (see WriteMesh in MeshIO.cxx): readable by every VTK reader.
  writer->SetDataModeToBinary();
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
  vtkSmartPointer<vtkAlgorithm> reader;
  if (vtkFoldingTreeCompactReader::CanReadFile(path.c_str()))
  {
    vtkNew<vtkFoldingTreeCompactReader> compact;
    compact->SetFileName(path.c_str());
    reader = compact;
  }
  else
  {
    vtkNew<vtkExpatSafeXMLMultiBlockDataReader> xml;
    if (!xml->CanReadFile(path.c_str()))
    {
      error = "cannot read '" + path +
        "': neither a VTK XML multiblock (.vtm) tree nor a compact (.fmz) tree (write one with "
        "'foldingmeshes fold' or 'foldingmeshes compress')";
      return nullptr;
    }
    xml->SetFileName(path.c_str());
    reader = xml;
  }
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
  int upAxis,
  std::string& picture,
  std::string& error)
{
  if (!std::getenv("DISPLAY"))
  {
    std::cerr << "foldingmeshes: no display, picture skipped (run under xvfb-run -a)\n";
    picture.clear();
    return true;
  }
  auto window = foldingmeshes::MakeCategoryScene(mesh, arrayName, 800, 600, upAxis);
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
}
