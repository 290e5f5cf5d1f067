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

  double bounds[6];
  input->GetBounds(bounds);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  double hausdorff = 0.0, mean = 0.0;
  foldingmeshes::SymmetricSurfaceDistance(input, unfolded, hausdorff, mean);
  const double epsilon = TreeValue(tree, "RootEpsilon");
  // Over every point of both surfaces: a proved bound within 1e-5 of the diagonal, and whether
  // it is within epsilon decided to 1e-7 of the diagonal.
  const foldingmeshes::ProvedDistance proved = foldingmeshes::ProvedSurfaceDistance(
    input, unfolded, 1e-5 * diagonal, epsilon, 1e-7 * diagonal);
  const double bound = proved.upper;
  const bool within = proved.within > 0;
  const foldingmeshes::EdgeCounts before = foldingmeshes::CountEdges(input),
                                  after = foldingmeshes::CountEdges(unfolded);
  const long long openBefore = before.open, openAfter = after.open;
  const int removedProjected = static_cast<int>(FieldValue(unfolded, "RemovedProjectedPoints"));
  const int thinned = static_cast<int>(FieldValue(unfolded, "ThinnedCopyPoints"));
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
                "  \"removedProjectedPoints\": %d,\n  \"thinnedCopyPoints\": %d,\n"
                "  \"diagonal\": %.9g,\n  \"rootEpsilon\": %.9g,\n"
                "  \"rootEpsilonFraction\": %.9g,\n  \"hausdorff\": %.9g,\n"
                "  \"hausdorffFraction\": %.9g,\n  \"hausdorffBoundFraction\": %.9g,\n"
                "  \"meanDistanceFraction\": %.9g,\n"
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
      thinned,
      diagonal,
      epsilon,
      epsilon * scale,
      hausdorff,
      hausdorff * scale,
      bound * scale,
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
                "points removed%s, %d removed from mirrored copies%s)\n",
      before.vertices,
      after.vertices,
      before.vertices > 0 ? 100.0 * (after.vertices - before.vertices) / before.vertices : 0.0,
      removedProjected,
      f.keepProjectedPoints ? " (--keep-projected-points)" : "",
      thinned,
      f.keepCopyDensity ? " (--keep-copy-density)" : "");
    std::printf("tree height:             %d\n", height);
    std::printf("hausdorff / diagonal:    %.6f max, %.6f mean at vertices and centroids; %.6f "
                "over whole surfaces, proved (bound: root epsilon %.6f) %s\n",
      hausdorff * scale,
      mean * scale,
      bound * scale,
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
    std::cerr << "foldingmeshes: " << f.meshPath << ": Hausdorff distance up to " << bound
              << " (proved bound) exceeds the root epsilon " << epsilon << "\n";
    return 4;
  }
  return 0;
}
}
}
