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
// pinned faces, the root epsilon over the requested one, the unfolded area over the input's and
// the area of the faces added to close seam gaps and holes over the input's (the unfolder's
// AreaRatio - above 1, surface laid twice, docs/limitations.md - and FilledAreaRatio); then the
// largest detection and fold times of the meshes up to 50k faces against issue 21's goal of 2 s,
// and how many bounds hold. Not a test (times vary by machine); the corpus is built in memory.
//
//   BenchmarkArtistMeshes [--threads N] [--double] [--large] [NAME_SUBSTRING...]
//
// --double: the corpus as built (double coordinates) instead of as written (float).
// --large: also the procedural bilateral blob (Testing/Cxx/ProceduralMeshes.h, one mirror plane,
// under a rigid motion; double coordinates whatever --double says) with 100k and 1M faces, and
// a crate of 84,000 boxes (ArtistMeshes.h, MakeCrate: 1,008,000 faces of many parts), and
// issue 21's other goal: 1M faces under 5 s, for each of the two (about two minutes more at 2
// threads). NAME_SUBSTRING selects meshes of the corpus; --large adds the blobs and the crate.
#include "ArtistMeshes.h"
#include "EdgeTable.h"
#include "ProceduralMeshes.h"
#include "ProcessMemory.h"
#include "vtkFoldingTreeBuilder.h"
#include "vtkFoldingTreeUnfolder.h"
#include "vtkSymmetryPlaneDetector.h"

#include <vtkCellArray.h>
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

/// The goals of issue 21: detection and folding under 2 s up to 50k faces, under 5 s at 1M.
constexpr double GoalSeconds = 2.0;
constexpr int GoalFaces = 50000;
constexpr double LargeGoalSeconds = 5.0;
constexpr int LargeFaces = 1000000;

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

/// A mesh to measure: its input, what it was built with and its open edges.
struct Case
{
  std::string name;
  vtkSmartPointer<vtkPolyData> input;
  int parts = 1;
  size_t openEdges = 0;
  Vec3 normal = Vec3::UnitX(); ///< the mirror plane it was built with
  bool deformed = false;       ///< no plane of the whole: no angle printed
  bool large = false;          ///< a mesh of issue 21's 1M-face goal
};

/// What one line reports, for the summary lines.
struct Measured
{
  bool folded = false; ///< the builder made a tree (its times and bound count)
  bool ok = false;     ///< and the unfolder a mesh
  int faces = 0;
  double detect = 0.0, fold = 0.0, bound = 0.0;
};

/// Open edges of a polydata's triangles.
size_t OpenEdgesOf(vtkPolyData* mesh)
{
  std::vector<foldingmeshes::Triangle> triangles;
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (mesh->GetPolys()->InitTraversal(); mesh->GetPolys()->GetNextCell(n, ids);)
    if (n == 3)
      triangles.push_back(
        { static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]) });
  return foldingmeshes::OpenEdges(triangles).size();
}

/// Detects, folds and unfolds one mesh at default options and prints its line.
Measured Measure(const Case& m)
{
  Measured r;
  r.faces = static_cast<int>(m.input->GetNumberOfCells());
  vtkNew<vtkSymmetryPlaneDetector> detector;
  detector->SetInputData(m.input);
  auto t0 = Clock::now();
  detector->Update();
  r.detect = Seconds(t0);
  vtkFieldData* found = detector->GetOutput()->GetFieldData();
  const Vec3 normal(Field(found, "SymmetryPlaneNormal", 0),
    Field(found, "SymmetryPlaneNormal", 1),
    Field(found, "SymmetryPlaneNormal", 2));
  const double angle = std::acos(std::min(1.0, std::abs(normal.normalized().dot(m.normal)))) *
    180.0 / 3.14159265358979;

  vtkNew<vtkFoldingTreeBuilder> builder;
  builder->SetInputData(m.input);
  t0 = Clock::now();
  builder->Update();
  r.fold = Seconds(t0);
  auto* tree = vtkMultiBlockDataSet::SafeDownCast(builder->GetOutputDataObject(0));
  auto* info =
    tree && tree->GetNumberOfBlocks() > 1 ? vtkPolyData::SafeDownCast(tree->GetBlock(1)) : nullptr;
  if (!info)
  {
    std::printf("%-22s error: folding failed\n", m.name.c_str());
    return r;
  }
  vtkFieldData* treeField = info->GetFieldData();
  r.bound = Field(treeField, "VerifiedBound") / Field(treeField, "RootEpsilon");
  r.folded = true;

  vtkNew<vtkFoldingTreeUnfolder> unfolder;
  unfolder->SetInputData(tree);
  t0 = Clock::now();
  unfolder->Update();
  const double unfold = Seconds(t0);
  r.ok = unfolder->GetOutput()->GetNumberOfCells() > 0;

  std::printf("%-22s %7d %5d %5zu %8.3f %6s %5.1f%% %7.3f %6d %5.1f%% %7.3f %9.4f%s %6d %6d %6.4f "
              "%6.3f %6.3f\n",
    m.name.c_str(),
    r.faces,
    m.parts,
    m.openEdges,
    r.detect,
    m.deformed ? "-" : std::to_string(angle).substr(0, 6).c_str(),
    100.0 * Field(found, "SymmetricAreaFraction"),
    r.fold,
    static_cast<int>(Field(treeField, "StoredFaces")),
    100.0 * Field(treeField, "Compression"),
    unfold,
    r.bound,
    r.bound <= 1.0 ? "" : " !",
    static_cast<int>(Field(treeField, "VerificationRounds")),
    static_cast<int>(Field(treeField, "PinnedFaces")),
    Field(treeField, "RootEpsilon") / Field(treeField, "RequestedEpsilon"),
    Field(unfolder->GetOutput()->GetFieldData(), "AreaRatio"),
    Field(unfolder->GetOutput()->GetFieldData(), "FilledAreaRatio"));
  std::fflush(stdout);
  return r;
}
}

int main(int argc, char* argv[])
{
  foldingmeshes::cli::KeepFreedMemoryForReuse(); // as the command-line program does
  std::vector<std::string> filters;
  bool doublePoints = false, large = false;
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
    else if (arg == "--large")
      large = true;
    else if (arg == "--help" || arg == "-h")
    {
      std::printf("usage: %s [--threads N] [--double] [--large] [NAME_SUBSTRING...]\n", argv[0]);
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
  std::printf("%-22s %7s %5s %5s %8s %6s %6s %7s %6s %6s %7s %9s %6s %6s %6s %6s %6s\n",
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
    "eps/rq",
    "area",
    "fill");
  double maxDetect = 0.0, maxFold = 0.0;
  std::string maxDetectMesh, maxFoldMesh;
  int meshes = 0, within = 0, failed = 0;
  std::vector<Case> cases;
  for (const foldingmeshes::artist::ArtistMesh& m : foldingmeshes::artist::MakeArtistCorpus())
  {
    bool selected = filters.empty();
    for (const std::string& f : filters)
      selected = selected || m.name.find(f) != std::string::npos;
    if (selected)
      cases.push_back({ m.name,
        foldingmeshes::artist::ToPolyData(m.mesh, doublePoints),
        m.parts,
        foldingmeshes::OpenEdges(m.mesh.triangles).size(),
        m.normal,
        m.deformed });
  }
  if (large)
    for (int faces : { 100000, LargeFaces })
    {
      auto blob = foldingmeshes::testing::MakeBilateralBlob(faces, 7);
      foldingmeshes::testing::ApplyRigidMotion(blob, foldingmeshes::testing::RandomRigidMotion(11));
      Case c{
        "blob_" + std::to_string(faces), blob.mesh, 1, 0, blob.planes.at(0).normal, false, false
      };
      c.large = faces == LargeFaces;
      c.openEdges = OpenEdgesOf(blob.mesh);
      cases.push_back(std::move(c));
    }
  if (large)
  {
    const foldingmeshes::artist::ArtistMesh crate =
      foldingmeshes::artist::MakeCrate(foldingmeshes::artist::LargeCratePairs);
    Case c{ crate.name,
      foldingmeshes::artist::ToPolyData(crate.mesh, doublePoints),
      crate.parts,
      foldingmeshes::OpenEdges(crate.mesh.triangles).size(),
      crate.normal,
      false };
    c.large = true;
    cases.push_back(std::move(c));
  }
  std::vector<std::pair<std::string, const Measured*>> largest;
  std::vector<Measured> results;
  results.reserve(cases.size());
  for (const Case& c : cases)
  {
    ++meshes;
    results.push_back(Measure(c));
    const Measured& r = results.back();
    failed += !r.ok;
    if (!r.folded)
      continue;
    within += r.bound <= 1.0;
    if (r.faces <= GoalFaces && r.detect > maxDetect)
    {
      maxDetect = r.detect;
      maxDetectMesh = c.name;
    }
    if (r.faces <= GoalFaces && r.fold > maxFold)
    {
      maxFold = r.fold;
      maxFoldMesh = c.name;
    }
    if (c.large)
      largest.emplace_back(c.name, &r);
  }
  if (!maxDetectMesh.empty())
    std::printf(
      "up to %d faces: max detection %.3f s (%s), max fold %.3f s (%s); goal %.0f s: %s\n",
      GoalFaces,
      maxDetect,
      maxDetectMesh.c_str(),
      maxFold,
      maxFoldMesh.c_str(),
      GoalSeconds,
      maxDetect < GoalSeconds && maxFold < GoalSeconds ? "met" : "not met");
  for (const auto& [name, r] : largest)
    std::printf("%s, %d faces: detection %.3f s, fold %.3f s; goal %.0f s: %s\n",
      name.c_str(),
      r->faces,
      r->detect,
      r->fold,
      LargeGoalSeconds,
      r->detect < LargeGoalSeconds && r->fold < LargeGoalSeconds ? "met" : "not met");
  std::printf("proved bound within epsilon: %d of %d meshes%s\n",
    within,
    meshes,
    failed ? " (some failed)" : "");
  return failed ? 1 : 0;
}
