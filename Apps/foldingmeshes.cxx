// foldingmeshes: the command-line front end of FoldingMeshes.
//
//   foldingmeshes detect MESH [options]      planar symmetry plane + symmetric region
//   foldingmeshes fold MESH [options]        folding tree (.vtm) + segmentation + summary
//   foldingmeshes unfold TREE.vtm [options]  mesh reconstructed from a folding tree
//   foldingmeshes roundtrip MESH [options]   fold, save, read back, unfold, Hausdorff check
//
// Exit codes: 0 success, 1 bad command line, 2 unreadable or invalid input, 3 cannot write,
// 4 roundtrip: Hausdorff distance above the root epsilon.
#include "MeshIO.h"
#include "MeshPicture.h"
#include "vtkFoldingTreeBuilder.h"
#include "vtkFoldingTreeUnfolder.h"
#include "vtkSymmetryPlaneDetector.h"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkSMPThreadLocal.h>
#include <vtkSMPThreadLocalObject.h>
#include <vtkSMPTools.h>
#include <vtkStaticCellLocator.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLMultiBlockDataWriter.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
const char* const Usage = R"(usage: foldingmeshes detect MESH [options]
       foldingmeshes fold MESH [fold options]
       foldingmeshes unfold TREE.vtm [unfold options]
       foldingmeshes roundtrip MESH [fold options]

MESH is a .vtp .vtk .ply .obj .stl or .off file; outputs are named after its stem.

detect: finds the dominant planar reflection symmetry of a triangle mesh and the largest
connected region that has it (Folding meshes, SGP 2006, section 3).
  --tolerance F            epsilon as a fraction of the bounding-box diagonal (default 0.02)
  --absolute-tolerance L   epsilon as a length (overrides --tolerance)
  --method robust|paper    several starts judged by final region (default) or the paper's one start
  --initial-plane OX,OY,OZ,NX,NY,NZ
                           start from this plane instead of the principal axes
  --candidates N           voted candidate planes tried by the robust method (default 8)
  --separate-parts         regions never span separate parts (default: parts touching within
                           epsilon are connected)
  --output FILE            labelled mesh (default: MESH stem + "_symmetry.vtp" in --outdir)
  --plane-output FILE      plane glyph (default: MESH stem + "_plane.vtp" in --outdir)
  --picture FILE           PNG picture (default: MESH stem + "_symmetry.png" in --outdir)
  --outdir DIR             folder for default outputs (default: current folder)
  --no-files               write nothing, only print
  --json                   print the result as JSON
  --quiet                  no progress on stderr
  --help                   this text

fold: folds the mesh into a folding tree (section 4.1-4.2) and writes, in --outdir,
STEM_tree.vtm (the tree, XML multiblock; its pieces go to the folder STEM_tree/),
STEM_segmentation.vtp (the mesh with cell arrays FoldingLeafId, FoldingDepth, FoldingRole)
and STEM_segmentation.png (coloured by FoldingLeafId; grey: faces mirrored away); prints
original and stored faces, compression, tree height, folds, leaves and time.
  --tolerance F            root epsilon as a fraction of the diagonal (default 0.02), halved
                           below every fold
  --absolute-tolerance L   root epsilon as a length (overrides --tolerance)
  --keep more|fewer        a fold keeps the half with more faces (default, the paper's) or
                           fewer (less storage)
  --min-area-fraction F    leaf when a region's area is below F of the mesh's (default 0.05)
  --max-folds N            leaf when N folds lie above a region (default 8, at most 63)
  --outdir DIR             folder for the outputs (default: current folder)
  --json                   print the result as JSON
  --quiet                  no progress on stderr

unfold: reconstructs the mesh from a tree written by fold (section 4.3) and writes, in
--outdir, STEM_unfolded.vtp and STEM_unfolded.png (coloured by FoldingLeafId), where STEM is
the tree's file stem without a trailing "_tree"; prints faces, open edges, stitched vertices
and open gaps.
  --no-stitch              the raw union of the copies: no stitching or smoothing of tears
  --outdir DIR             folder for the outputs (default: current folder)
  --json, --quiet          as for fold

roundtrip: folds MESH (fold options), writes STEM_tree.vtm, reads it back, unfolds it, writes
STEM_unfolded.vtp and reports the symmetric Hausdorff distance between the (triangulated)
input and the unfolded mesh as a fraction of the input's bounding-box diagonal: the maximum
and the mean over the vertices of both meshes of the distance to the other surface. Also
prints the open (boundary) edges before and after (vertices at identical positions counted
as one). Fails with exit code 4 when the Hausdorff distance exceeds the root epsilon. No
pictures.

Pictures need a display: without $DISPLAY they are skipped with a message (use xvfb-run -a).

exit codes: 0 success, 1 bad command line, 2 unreadable or invalid input, 3 cannot write,
            4 roundtrip: Hausdorff distance above the root epsilon (the paper's bound)
)";

struct ErrorCollector
{
  std::string messages;
  static void OnError(vtkObject*, unsigned long, void* self, void* data)
  {
    auto* collector = static_cast<ErrorCollector*>(self);
    if (data)
    {
      std::string text = static_cast<const char*>(data);
      const auto pos = text.find("): ");
      collector->messages += (pos != std::string::npos ? text.substr(pos + 3) : text);
    }
  }
};

struct ProgressPrinter
{
  const char* label = "detecting symmetry";
  int lastPercent = -1;
  static void OnProgress(vtkObject*, unsigned long, void* self, void* data)
  {
    auto* printer = static_cast<ProgressPrinter*>(self);
    const int percent = static_cast<int>(100.0 * *static_cast<double*>(data));
    if (percent != printer->lastPercent)
    {
      printer->lastPercent = percent;
      std::fprintf(stderr, "\r%s: %3d%%", printer->label, percent);
      std::fflush(stderr);
    }
  }
};

bool ParseNumbers(const std::string& text, std::vector<double>& values)
{
  std::stringstream in(text);
  std::string item;
  values.clear();
  while (std::getline(in, item, ','))
  {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (end == item.c_str() || *end != '\0')
      return false;
    values.push_back(v);
  }
  return true;
}

std::string JsonString(const std::string& s)
{
  std::string out = "\"";
  for (char c : s)
  {
    if (c == '"' || c == '\\')
      out += '\\';
    out += c;
  }
  return out + "\"";
}

int Detect(int argc, char* argv[])
{
  std::string meshPath, output, planeOutput, picture, outdir = ".";
  bool json = false, quiet = false, noFiles = false;
  vtkNew<vtkSymmetryPlaneDetector> detector;
  for (int i = 0; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&](const char* what) -> std::string
    {
      if (i + 1 >= argc)
        throw std::runtime_error(std::string("missing value after ") + what);
      return argv[++i];
    };
    auto number = [&](const char* what)
    {
      const std::string v = value(what);
      char* end = nullptr;
      const double x = std::strtod(v.c_str(), &end);
      if (end == v.c_str() || *end != '\0' || !(x > 0.0))
        throw std::runtime_error(std::string(what) + " needs a positive number, got '" + v + "'");
      return x;
    };
    if (arg == "--help" || arg == "-h")
    {
      std::cout << Usage;
      std::exit(0);
    }
    else if (arg == "--tolerance")
    {
      detector->SetTolerance(number("--tolerance"));
      detector->SetToleranceMode(vtkSymmetryPlaneDetector::RELATIVE_TO_DIAGONAL);
    }
    else if (arg == "--absolute-tolerance")
    {
      detector->SetTolerance(number("--absolute-tolerance"));
      detector->SetToleranceMode(vtkSymmetryPlaneDetector::ABSOLUTE);
    }
    else if (arg == "--method")
    {
      const std::string m = value("--method");
      if (m != "robust" && m != "paper")
        throw std::runtime_error("--method must be robust or paper, got '" + m + "'");
      detector->SetMethod(
        m == "paper" ? vtkSymmetryPlaneDetector::PAPER : vtkSymmetryPlaneDetector::ROBUST);
    }
    else if (arg == "--initial-plane")
    {
      std::vector<double> v;
      if (!ParseNumbers(value("--initial-plane"), v) || v.size() != 6)
        throw std::runtime_error("--initial-plane needs six comma-separated numbers");
      detector->UseInitialPlaneOn();
      detector->SetInitialPlaneOrigin(v[0], v[1], v[2]);
      detector->SetInitialPlaneNormal(v[3], v[4], v[5]);
    }
    else if (arg == "--candidates")
      detector->SetNumberOfCandidates(std::atoi(value("--candidates").c_str()));
    else if (arg == "--separate-parts")
      detector->ConnectNearbyPartsOff();
    else if (arg == "--output")
      output = value("--output");
    else if (arg == "--plane-output")
      planeOutput = value("--plane-output");
    else if (arg == "--picture")
      picture = value("--picture");
    else if (arg == "--outdir")
      outdir = value("--outdir");
    else if (arg == "--no-files")
      noFiles = true;
    else if (arg == "--json")
      json = true;
    else if (arg == "--quiet")
      quiet = true;
    else if (!arg.empty() && arg[0] == '-')
      throw std::runtime_error("unknown option '" + arg + "'");
    else if (meshPath.empty())
      meshPath = arg;
    else
      throw std::runtime_error("more than one mesh given ('" + arg + "')");
  }
  if (meshPath.empty())
    throw std::runtime_error("no mesh given");

  std::string error;
  vtkSmartPointer<vtkPolyData> mesh = foldingmeshes::ReadMesh(meshPath, error);
  if (!mesh)
  {
    std::cerr << "foldingmeshes: " << error << "\n";
    return 2;
  }

  ErrorCollector errors;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(&ErrorCollector::OnError);
  onError->SetClientData(&errors);
  detector->AddObserver(vtkCommand::ErrorEvent, onError);
  ProgressPrinter progress;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetCallback(&ProgressPrinter::OnProgress);
  onProgress->SetClientData(&progress);
  if (!quiet)
    detector->AddObserver(vtkCommand::ProgressEvent, onProgress);

  detector->SetInputData(mesh);
  const auto start = std::chrono::steady_clock::now();
  const int ok = detector->GetExecutive()->Update();
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!quiet)
    std::fprintf(stderr, "\n");
  if (!ok || !errors.messages.empty())
  {
    std::cerr << "foldingmeshes: " << meshPath << ": "
              << (errors.messages.empty() ? "symmetry detection failed" : errors.messages);
    if (errors.messages.empty() || errors.messages.back() != '\n')
      std::cerr << "\n";
    return 2;
  }

  const std::string stem = std::filesystem::path(meshPath).stem().string();
  const std::filesystem::path dir(outdir);
  if (!noFiles)
  {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (output.empty())
      output = (dir / (stem + "_symmetry.vtp")).string();
    if (planeOutput.empty())
      planeOutput = (dir / (stem + "_plane.vtp")).string();
    if (picture.empty())
      picture = (dir / (stem + "_symmetry.png")).string();
    if (!foldingmeshes::WriteMesh(detector->GetOutput(0), output, error) ||
      !foldingmeshes::WriteMesh(detector->GetOutput(1), planeOutput, error))
    {
      std::cerr << "foldingmeshes: " << error << "\n";
      return 3;
    }
    if (!std::getenv("DISPLAY"))
    {
      std::cerr << "foldingmeshes: no display, picture skipped (run under xvfb-run -a)\n";
      picture.clear();
    }
    else
    {
      auto window =
        foldingmeshes::MakeSymmetryScene(detector->GetOutput(0), detector->GetOutput(1), 800, 600);
      if (!foldingmeshes::WritePicture(window, picture, error))
      {
        std::cerr << "foldingmeshes: " << error << "\n";
        return 3;
      }
    }
  }

  const double* o = detector->GetPlaneOrigin();
  const double* n = detector->GetPlaneNormal();
  const vtkIdType faces = detector->GetOutput(0)->GetNumberOfCells();
  if (json)
  {
    std::printf("{\n  \"mesh\": %s,\n  \"faces\": %lld,\n  \"tolerance\": %.9g,\n"
                "  \"plane\": {\"origin\": [%.9g, %.9g, %.9g], \"normal\": [%.9g, %.9g, %.9g]},\n"
                "  \"symmetricAreaFraction\": %.6f,\n  \"symmetryFound\": %s,\n"
                "  \"iterations\": {\"coarse\": %d, \"fine\": %d},\n  \"seconds\": %.3f",
      JsonString(meshPath).c_str(),
      static_cast<long long>(faces),
      detector->GetToleranceLength(),
      o[0],
      o[1],
      o[2],
      n[0],
      n[1],
      n[2],
      detector->GetSymmetricAreaFraction(),
      detector->GetSymmetryFound() ? "true" : "false",
      detector->GetCoarseIterations(),
      detector->GetFineIterations(),
      seconds);
    if (!noFiles)
      std::printf(",\n  \"outputs\": {\"mesh\": %s, \"plane\": %s, \"picture\": %s}",
        JsonString(output).c_str(),
        JsonString(planeOutput).c_str(),
        picture.empty() ? "null" : JsonString(picture).c_str());
    std::printf("\n}\n");
  }
  else
  {
    std::printf("mesh:                    %s (%lld faces)\n",
      meshPath.c_str(),
      static_cast<long long>(faces));
    std::printf("tolerance (epsilon):     %.6g\n", detector->GetToleranceLength());
    std::printf("plane origin:            %.6g %.6g %.6g\n", o[0], o[1], o[2]);
    std::printf("plane normal:            %.6f %.6f %.6f\n", n[0], n[1], n[2]);
    std::printf("symmetric area fraction: %.1f%%\n", 100.0 * detector->GetSymmetricAreaFraction());
    std::printf("symmetry found:          %s\n", detector->GetSymmetryFound() ? "yes" : "no");
    std::printf("iterations:              %d coarse, %d fine\n",
      detector->GetCoarseIterations(),
      detector->GetFineIterations());
    std::printf("time:                    %.3f s\n", seconds);
    if (!noFiles)
    {
      std::printf("wrote:                   %s\n                         %s\n",
        output.c_str(),
        planeOutput.c_str());
      if (!picture.empty())
        std::printf("                         %s\n", picture.c_str());
    }
  }
  return 0;
}
//------------------------------------------------------------------------------
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

/// Edges used by exactly one triangle, vertices at identical positions counted as one.
long long CountOpenEdges(vtkPolyData* mesh)
{
  std::map<std::array<double, 3>, vtkIdType> unique;
  std::vector<vtkIdType> id(mesh->GetNumberOfPoints());
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
  {
    std::array<double, 3> x;
    mesh->GetPoint(p, x.data());
    id[p] = unique.emplace(x, static_cast<vtkIdType>(unique.size())).first->second;
  }
  std::map<std::pair<vtkIdType, vtkIdType>, int> edges;
  vtkCellArray* polys = mesh->GetPolys();
  if (!polys)
    return 0;
  vtkIdType n = 0;
  const vtkIdType* pts = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(n, pts);)
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType a = id[pts[k]], b = id[pts[(k + 1) % n]];
      if (a != b)
        ++edges[{ std::min(a, b), std::max(a, b) }];
    }
  long long open = 0;
  for (const auto& e : edges)
    open += e.second == 1;
  return open;
}

struct Distances
{
  double max = 0.0, sum = 0.0;
  vtkIdType count = 0;
};

/// Distances from every point of `from` to the surface `to` (vtkStaticCellLocator).
Distances PointsToSurface(vtkPolyData* from, vtkPolyData* to)
{
  Distances result;
  if (from->GetNumberOfPoints() == 0 || to->GetNumberOfCells() == 0)
    return result;
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(to);
  locator->BuildLocator();
  std::vector<double> d(from->GetNumberOfPoints(), 0.0);
  vtkSMPThreadLocalObject<vtkGenericCell> cells;
  vtkSMPTools::For(0,
    from->GetNumberOfPoints(),
    [&](vtkIdType begin, vtkIdType end)
    {
      vtkGenericCell* cell = cells.Local();
      double x[3], closest[3], dist2 = 0.0;
      vtkIdType cellId = -1;
      int subId = 0;
      for (vtkIdType p = begin; p < end; ++p)
      {
        from->GetPoint(p, x);
        locator->FindClosestPoint(x, closest, cell, cellId, subId, dist2);
        d[p] = std::sqrt(dist2);
      }
    });
  for (double v : d)
  {
    result.max = std::max(result.max, v);
    result.sum += v;
  }
  result.count = static_cast<vtkIdType>(d.size());
  return result;
}

/// Symmetric Hausdorff distance (max) and mean point-to-surface distance over both meshes.
void SymmetricDistance(vtkPolyData* a, vtkPolyData* b, double& hausdorff, double& mean)
{
  const Distances ab = PointsToSurface(a, b), ba = PointsToSurface(b, a);
  hausdorff = std::max(ab.max, ba.max);
  mean = ab.count + ba.count > 0 ? (ab.sum + ba.sum) / static_cast<double>(ab.count + ba.count) : 0;
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

int Fold(int argc, char* argv[])
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
  std::string treePath, outdir = ".";
  bool json = false, quiet = false, stitch = true;
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
  unfolder->SetInputData(tree);
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
  const int stitched = static_cast<int>(FieldValue(mesh, "StitchedVertices"));
  const int gaps = static_cast<int>(FieldValue(mesh, "OpenGapCount"));
  const double gapLength = FieldValue(mesh, "OpenGapLength");
  if (json)
  {
    std::printf("{\n  \"tree\": %s,\n  \"stitch\": %s,\n  \"faces\": %lld,\n"
                "  \"points\": %lld,\n  \"openEdges\": %d,\n  \"nonManifoldEdges\": %d,\n"
                "  \"stitchedVertices\": %d,\n  \"openGapCount\": %d,\n"
                "  \"openGapLength\": %.9g,\n  \"seconds\": %.3f,\n"
                "  \"outputs\": {\"mesh\": %s, \"picture\": %s}\n}\n",
      JsonString(treePath).c_str(),
      stitch ? "true" : "false",
      faces,
      static_cast<long long>(mesh->GetNumberOfPoints()),
      openEdges,
      nonManifold,
      stitched,
      gaps,
      gapLength,
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
    std::printf("open edges:              %d (non-manifold %d)\n", openEdges, nonManifold);
    std::printf("stitched vertices:       %d%s\n", stitched, stitch ? "" : " (stitching off)");
    std::printf("open gaps:               %d (length %.6g)\n", gaps, gapLength);
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
  SymmetricDistance(input, unfolded, hausdorff, mean);
  const double epsilon = TreeValue(tree, "RootEpsilon");
  const bool within = hausdorff <= epsilon;
  const long long openBefore = CountOpenEdges(input), openAfter = CountOpenEdges(unfolded);
  const double scale = diagonal > 0 ? 1.0 / diagonal : 0.0;
  const int original = static_cast<int>(TreeValue(tree, "OriginalFaces"));
  const int stored = static_cast<int>(TreeValue(tree, "StoredFaces"));
  const double compression = TreeValue(tree, "Compression");
  const int height = static_cast<int>(TreeValue(tree, "TreeHeight"));
  if (f.json)
  {
    std::printf("{\n  \"mesh\": %s,\n  \"originalFaces\": %d,\n  \"storedFaces\": %d,\n"
                "  \"compression\": %.6f,\n  \"treeHeight\": %d,\n  \"unfoldedFaces\": %lld,\n"
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
    std::printf("tree height:             %d\n", height);
    std::printf("hausdorff / diagonal:    %.6f max, %.6f mean (bound: root epsilon %.6f) %s\n",
      hausdorff * scale,
      mean * scale,
      epsilon * scale,
      within ? "ok" : "VIOLATED");
    std::printf("open edges:              %lld before, %lld after (%d open gaps)\n",
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

int main(int argc, char* argv[])
{
  // Use both cores unless the user chose an SMP backend (results do not depend on it).
  if (!std::getenv("VTK_SMP_BACKEND_IN_USE"))
    vtkSMPTools::SetBackend("STDThread");
  if (argc < 2)
  {
    std::cerr << Usage;
    return 1;
  }
  const std::string command = argv[1];
  if (command == "--help" || command == "-h" || command == "help")
  {
    std::cout << Usage;
    return 0;
  }
  try
  {
    if (command == "detect")
      return Detect(argc - 2, argv + 2);
    if (command == "fold")
      return Fold(argc - 2, argv + 2);
    if (command == "unfold")
      return Unfold(argc - 2, argv + 2);
    if (command == "roundtrip")
      return Roundtrip(argc - 2, argv + 2);
    throw std::runtime_error("unknown command '" + command + "'");
  }
  catch (const std::exception& e)
  {
    std::cerr << "foldingmeshes: " << e.what() << "\n(see foldingmeshes --help)\n";
    return 1;
  }
}
