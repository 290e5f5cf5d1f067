// foldingmeshes roundtrip: fold, save, read back, unfold and measure the distance to the input.
#include "FoldCommandSupport.h"
#include "MeshComparison.h"
#include "MeshIO.h"
#include "vtkFoldingTreeUnfolder.h"

#include <vtkNew.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

namespace foldingmeshes
{
namespace cli
{
namespace
{
/// What roundtrip measures of the unfolded mesh against the (triangulated) input.
struct RoundtripResult
{
  std::string meshPath, treePath, unfoldedPath;
  double diagonal = 0.0, epsilon = 0.0, hausdorff = 0.0, mean = 0.0, bound = 0.0;
  bool within = false;
  EdgeCounts before, after;
  long long unfoldedFaces = 0;
  int removedProjected = 0, thinned = 0, original = 0, stored = 0, height = 0, gaps = 0;
  double compression = 0.0, foldSeconds = 0.0, unfoldSeconds = 0.0, measureSeconds = 0.0;
  double areaRatio = 0.0;       ///< unfolded surface area / the input's (the unfolder's AreaRatio)
  double filledAreaRatio = 0.0; ///< of that, in faces added to close gaps (FilledAreaRatio)
  DistanceLocator locator = DistanceLocator::StaticCellLocator;
  double Scale() const { return this->diagonal > 0 ? 1.0 / this->diagonal : 0.0; }
};

RoundtripResult MeasureRoundtrip(vtkPolyData* input,
  vtkPolyData* unfolded,
  vtkMultiBlockDataSet* tree,
  DistanceLocator locator)
{
  const auto t0 = std::chrono::steady_clock::now();
  RoundtripResult r;
  r.locator = locator;
  double bounds[6];
  input->GetBounds(bounds);
  r.diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  foldingmeshes::SymmetricSurfaceDistance(input, unfolded, r.hausdorff, r.mean, locator);
  r.epsilon = TreeValue(tree, "RootEpsilon");
  // Over every point of both surfaces: a proved bound within 1e-5 of the diagonal, and whether
  // it is within epsilon decided to 1e-7 of the diagonal.
  const foldingmeshes::ProvedDistance proved = foldingmeshes::ProvedSurfaceDistance(
    input, unfolded, 1e-5 * r.diagonal, r.epsilon, 1e-7 * r.diagonal, locator);
  r.bound = proved.upper;
  r.within = proved.within > 0;
  r.before = foldingmeshes::CountEdges(input);
  r.after = foldingmeshes::CountEdges(unfolded);
  r.unfoldedFaces = static_cast<long long>(unfolded->GetNumberOfCells());
  r.removedProjected = static_cast<int>(FieldValue(unfolded, "RemovedProjectedPoints"));
  r.thinned = static_cast<int>(FieldValue(unfolded, "ThinnedCopyPoints"));
  r.gaps = static_cast<int>(FieldValue(unfolded, "OpenGapCount"));
  r.areaRatio = FieldValue(unfolded, "AreaRatio");
  r.filledAreaRatio = FieldValue(unfolded, "FilledAreaRatio");
  r.original = static_cast<int>(TreeValue(tree, "OriginalFaces"));
  r.stored = static_cast<int>(TreeValue(tree, "StoredFaces"));
  r.compression = TreeValue(tree, "Compression");
  r.height = static_cast<int>(TreeValue(tree, "TreeHeight"));
  r.measureSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

void PrintRoundtripJson(const RoundtripResult& r)
{
  const double scale = r.Scale();
  std::printf("{\n  \"mesh\": %s,\n  \"originalFaces\": %d,\n  \"storedFaces\": %d,\n"
              "  \"compression\": %.6f,\n  \"treeHeight\": %d,\n  \"unfoldedFaces\": %lld,\n"
              "  \"originalVertices\": %lld,\n  \"unfoldedVertices\": %lld,\n"
              "  \"removedProjectedPoints\": %d,\n  \"thinnedCopyPoints\": %d,\n"
              "  \"diagonal\": %.9g,\n  \"rootEpsilon\": %.9g,\n"
              "  \"rootEpsilonFraction\": %.9g,\n  \"hausdorff\": %.9g,\n"
              "  \"hausdorffFraction\": %.9g,\n  \"hausdorffBoundFraction\": %.9g,\n"
              "  \"meanDistanceFraction\": %.9g,\n"
              "  \"withinBound\": %s,\n  \"openEdgesBefore\": %lld,\n"
              "  \"openEdgesAfter\": %lld,\n  \"openGapCount\": %d,\n  \"areaRatio\": %.6f,\n"
              "  \"filledAreaRatio\": %.6f,\n"
              "  \"foldSeconds\": %.3f,\n  \"unfoldSeconds\": %.3f,\n"
              "  \"distanceLocator\": \"%s\",\n  \"measureSeconds\": %.3f,\n"
              "  \"outputs\": {\"tree\": %s, \"unfolded\": %s}\n}\n",
    JsonString(r.meshPath).c_str(),
    r.original,
    r.stored,
    r.compression,
    r.height,
    r.unfoldedFaces,
    r.before.vertices,
    r.after.vertices,
    r.removedProjected,
    r.thinned,
    r.diagonal,
    r.epsilon,
    r.epsilon * scale,
    r.hausdorff,
    r.hausdorff * scale,
    r.bound * scale,
    r.mean * scale,
    r.within ? "true" : "false",
    static_cast<long long>(r.before.open),
    static_cast<long long>(r.after.open),
    r.gaps,
    r.areaRatio,
    r.filledAreaRatio,
    r.foldSeconds,
    r.unfoldSeconds,
    ToString(r.locator),
    r.measureSeconds,
    JsonString(r.treePath).c_str(),
    JsonString(r.unfoldedPath).c_str());
}

void PrintRoundtripText(const RoundtripResult& r, const FoldSettings& f)
{
  const double scale = r.Scale();
  const long long before = r.before.vertices, after = r.after.vertices;
  std::printf("mesh:                    %s\n", r.meshPath.c_str());
  std::printf("faces:                   %d original, %d stored (%.1f%% compression), "
              "%lld unfolded\n",
    r.original,
    r.stored,
    100.0 * r.compression,
    r.unfoldedFaces);
  std::printf("vertices:                %lld original, %lld unfolded (%+.1f%%; %d projected "
              "points removed%s, %d removed from mirrored copies%s)\n",
    before,
    after,
    before > 0 ? 100.0 * (after - before) / before : 0.0,
    r.removedProjected,
    f.keepProjectedPoints ? " (--keep-projected-points)" : "",
    r.thinned,
    f.keepCopyDensity ? " (--keep-copy-density)" : "");
  std::printf("tree height:             %d\n", r.height);
  std::printf("hausdorff / diagonal:    %.6f max, %.6f mean at vertices and centroids; %.6f "
              "over whole surfaces, proved (bound: root epsilon %.6f) %s\n",
    r.hausdorff * scale,
    r.mean * scale,
    r.bound * scale,
    r.epsilon * scale,
    r.within ? "ok" : "VIOLATED");
  std::printf(
    "open edges:              %lld before, %lld after (%d stitch gaps before the repair)\n",
    static_cast<long long>(r.before.open),
    static_cast<long long>(r.after.open),
    r.gaps);
  std::printf("surface area:            %.4f of the input's (above 1: surface laid twice), "
              "%.4f in faces added to close seam gaps and holes\n",
    r.areaRatio,
    r.filledAreaRatio);
  std::printf("time:                    fold %.3f s, unfold %.3f s, distances %.3f s (%s)\n",
    r.foldSeconds,
    r.unfoldSeconds,
    r.measureSeconds,
    r.locator == DistanceLocator::StaticCellLocator ? "vtkStaticCellLocator" : "face tree");
  std::printf("wrote:                   %s\n                         %s\n",
    r.treePath.c_str(),
    r.unfoldedPath.c_str());
}
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
  if (f.keepProjectedPoints)
    unfolder->RemoveProjectedPointsOff();
  if (f.keepCopyDensity)
    unfolder->MatchDiscardedDensityOff();
  if (f.noStitch)
    unfolder->StitchOff();
  if (f.noCloseHoles)
    unfolder->CloseHolesOff();
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

  RoundtripResult r = MeasureRoundtrip(
    input, unfolded, tree, f.distanceLocator.value_or(DistanceLocator::StaticCellLocator));
  r.meshPath = f.meshPath;
  r.treePath = treePath;
  r.unfoldedPath = unfoldedPath;
  r.foldSeconds = foldSeconds;
  r.unfoldSeconds = unfoldSeconds;
  if (f.json)
    PrintRoundtripJson(r);
  else
    PrintRoundtripText(r, f);
  const bool within = r.within;
  const double bound = r.bound, epsilon = r.epsilon;
  if (!within)
  {
    std::cerr << "foldingmeshes: " << f.meshPath << ": Hausdorff distance up to " << bound
              << " (proved bound) exceeds the root epsilon " << epsilon << "\n";
    return 4;
  }
  return 0;
}
}
}
