// The artist-like corpus of issue 21 (Testing/Cxx/ArtistMeshes.h: furniture, a rack, a biplane, a
// figure and a soup of many separate parts, each as built, moved and deformed), timed as a user
// meets it: detection (vtkSymmetryPlaneDetector), fold (vtkFoldingTreeBuilder, its proof of the
// bound included) and unfold (vtkFoldingTreeUnfolder), all at default options. One line per mesh:
// faces, parts, open edges, detection s, the detected plane's angle to the built one (degrees;
// '-' for the deformed variants, whose whole has no plane; 45 or 90 where the detector reports
// another plane the mesh also has: the chair's square seat; the rack, the bench and the biplane
// front to back), symmetric area, fold s, stored faces,
// compression, unfold s, the builder's proved bound over the tree's root epsilon (smaller than
// the requested one after a near-miss rebuild), the proof's extra builds (VerificationRounds),
// pinned faces and the root epsilon over the requested one; then the largest detection
// and fold times of the meshes up to 50k faces against issue 21's goal of 2 s, and how many
// bounds hold. Not a test (times vary by machine); the corpus is built in memory.
//
//   BenchmarkArtistMeshes [--threads N] [--double] [NAME_SUBSTRING...]
//
// --double: the corpus as built (double coordinates) instead of as written (float).
#include "ArtistMeshes.h"
#include "EdgeTable.h"
#include "ProcessMemory.h"
#include "vtkFoldingTreeBuilder.h"
#include "vtkFoldingTreeUnfolder.h"
#include "vtkSymmetryPlaneDetector.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;
using foldingmeshes::Vec3;

/// The goal of issue 21: detection and folding under 2 s up to 50k faces.
constexpr double GoalSeconds = 2.0;
constexpr int GoalFaces = 50000;

double Seconds(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// First tuple of a field-data array (component c), NaN if absent.
double Field(vtkFieldData* field, const char* name, int c = 0)
{
  vtkDataArray* a = field ? field->GetArray(name) : nullptr;
  return a && a->GetNumberOfTuples() > 0 && c < a->GetNumberOfComponents() ? a->GetComponent(0, c)
                                                                           : std::nan("");
}
}

int main(int argc, char* argv[])
{
  foldingmeshes::cli::KeepFreedMemoryForReuse(); // as the command-line program does
  std::vector<std::string> filters;
  bool doublePoints = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--threads" && i + 1 < argc)
    {
      vtkSMPTools::SetBackend("STDThread");
      vtkSMPTools::Initialize(std::atoi(argv[++i]));
    }
    else if (arg == "--double")
      doublePoints = true;
    else if (arg == "--help" || arg == "-h")
    {
      std::printf("usage: %s [--threads N] [--double] [NAME_SUBSTRING...]\n", argv[0]);
      return 0;
    }
    else
      filters.push_back(arg);
  }
  std::printf("SMP backend %s, %d threads; default options (epsilon 2%% of the diagonal); %s "
              "coordinates\n",
    vtkSMPTools::GetBackend(),
    vtkSMPTools::GetEstimatedNumberOfThreads(),
    doublePoints ? "double" : "float");
  std::printf("%-22s %6s %5s %5s %8s %6s %6s %7s %6s %6s %7s %8s %6s %6s %6s\n",
    "mesh",
    "faces",
    "parts",
    "open",
    "detect s",
    "angle",
    "region",
    "fold s",
    "stored",
    "compr",
    "unfld s",
    "bound/eps",
    "rounds",
    "pinned",
    "eps/rq");
  double maxDetect = 0.0, maxFold = 0.0;
  std::string maxDetectMesh, maxFoldMesh;
  int meshes = 0, within = 0, failed = 0;
  for (const foldingmeshes::artist::ArtistMesh& m : foldingmeshes::artist::MakeArtistCorpus())
  {
    bool selected = filters.empty();
    for (const std::string& f : filters)
      selected = selected || m.name.find(f) != std::string::npos;
    if (!selected)
      continue;
    ++meshes;
    vtkSmartPointer<vtkPolyData> input = foldingmeshes::artist::ToPolyData(m.mesh, doublePoints);
    const int faces = static_cast<int>(m.mesh.triangles.size());

    vtkNew<vtkSymmetryPlaneDetector> detector;
    detector->SetInputData(input);
    auto t0 = Clock::now();
    detector->Update();
    const double detect = Seconds(t0);
    vtkFieldData* found = detector->GetOutput()->GetFieldData();
    const Vec3 normal(Field(found, "SymmetryPlaneNormal", 0),
      Field(found, "SymmetryPlaneNormal", 1),
      Field(found, "SymmetryPlaneNormal", 2));
    const double angle = std::acos(std::min(1.0, std::abs(normal.normalized().dot(m.normal)))) *
      180.0 / 3.14159265358979;

    vtkNew<vtkFoldingTreeBuilder> builder;
    builder->SetInputData(input);
    t0 = Clock::now();
    builder->Update();
    const double fold = Seconds(t0);
    auto* tree = vtkMultiBlockDataSet::SafeDownCast(builder->GetOutputDataObject(0));
    auto* info = tree && tree->GetNumberOfBlocks() > 1
      ? vtkPolyData::SafeDownCast(tree->GetBlock(1))
      : nullptr;
    if (!info)
    {
      std::printf("%-22s error: folding failed\n", m.name.c_str());
      ++failed;
      continue;
    }
    vtkFieldData* treeField = info->GetFieldData();
    const double bound = Field(treeField, "VerifiedBound") / Field(treeField, "RootEpsilon");

    vtkNew<vtkFoldingTreeUnfolder> unfolder;
    unfolder->SetInputData(tree);
    t0 = Clock::now();
    unfolder->Update();
    const double unfold = Seconds(t0);
    if (unfolder->GetOutput()->GetNumberOfCells() == 0)
      ++failed;

    std::printf(
      "%-22s %6d %5d %5zu %8.3f %6s %5.1f%% %7.3f %6d %5.1f%% %7.3f %8.4f%s %6d %6d %6.4f\n",
      m.name.c_str(),
      faces,
      m.parts,
      foldingmeshes::OpenEdges(m.mesh.triangles).size(),
      detect,
      m.deformed ? "-" : std::to_string(angle).substr(0, 6).c_str(),
      100.0 * Field(found, "SymmetricAreaFraction"),
      fold,
      static_cast<int>(Field(treeField, "StoredFaces")),
      100.0 * Field(treeField, "Compression"),
      unfold,
      bound,
      bound <= 1.0 ? "" : " !",
      static_cast<int>(Field(treeField, "VerificationRounds")),
      static_cast<int>(Field(treeField, "PinnedFaces")),
      Field(treeField, "RootEpsilon") / Field(treeField, "RequestedEpsilon"));
    std::fflush(stdout);
    within += bound <= 1.0;
    if (faces <= GoalFaces && detect > maxDetect)
    {
      maxDetect = detect;
      maxDetectMesh = m.name;
    }
    if (faces <= GoalFaces && fold > maxFold)
    {
      maxFold = fold;
      maxFoldMesh = m.name;
    }
  }
  std::printf("up to %d faces: max detection %.3f s (%s), max fold %.3f s (%s); goal %.0f s: %s\n",
    GoalFaces,
    maxDetect,
    maxDetectMesh.c_str(),
    maxFold,
    maxFoldMesh.c_str(),
    GoalSeconds,
    maxDetect < GoalSeconds && maxFold < GoalSeconds ? "met" : "not met");
  std::printf("proved bound within epsilon: %d of %d meshes%s\n",
    within,
    meshes,
    failed ? " (some failed)" : "");
  return failed ? 1 : 0;
}
