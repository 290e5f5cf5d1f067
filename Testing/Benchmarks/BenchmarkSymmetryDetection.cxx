// Prints, per mesh: faces, starts tried, iterations (coarse/fine), seconds per phase,
// peak memory and the plane; with --rotation also the rotational symmetry search (as
// vtkSymmetryPlaneDetector's DetectRotation runs it, after the plane search): its seconds,
// order ("c" after it: continuous), found, region and axis. With --locator-ab every mesh is
// detected twice in one run, the second time with the vtkStaticCellLocator fast path of the
// fine distances (SymmetryOptions::closestFaceFastPath, issue 19), and a line compares them.
// Not a test: numbers for humans and closing notes.
//
//   BenchmarkSymmetryDetection [--threads N] [--procedural] [--rotation] [--locator-ab] MESH...
#include "Core/MeshPreparation.h"
#include "Core/RotationalSymmetry.h"
#include "Core/SymmetryDetection.h"
#include "MeshIO.h"
#include "ProceduralMeshes.h"
#include "vtkCellLocatorFaceQuery.h"
#include "vtkTriangleMeshAdapter.h"

#include <vtkPolyData.h>
#include <vtkSMPTools.h>

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace
{
using namespace foldingmeshes;
using Clock = std::chrono::steady_clock;

double PeakMemoryMiB()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

/// The rotation search after the plane search: seconds, order, found, region, axis.
void PrintRotation(const PreparedMesh& mesh, const SymmetryResult& planes, double epsilon)
{
  RotationOptions options;
  options.epsilon = epsilon;
  options.mirrorPlanes = planes.finalists;
  options.mirrorPlanes.push_back(planes.plane);
  const auto t0 = Clock::now();
  const RotationResult r = DetectRotationalSymmetry(mesh, options);
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  std::printf(" | rot %6.3f s k=%d%s %-3s %5.1f%% a=(%+.4f %+.4f %+.4f)",
    seconds,
    r.order,
    r.continuous ? "c" : "",
    r.found ? "yes" : "no",
    100.0 * r.symmetricAreaFraction,
    r.axis.direction.x(),
    r.axis.direction.y(),
    r.axis.direction.z());
}

bool rotation = false;
bool locatorAB = false;

/// One detection, one line; the result for the comparison of --locator-ab.
SymmetryResult Run(const std::string& name, vtkPolyData* input, bool fastPath)
{
  const auto t0 = Clock::now();
  vtkIdType droppedVerts = 0, droppedLines = 0;
  TriangleMesh soup;
  std::vector<Vec3> normals;
  PreparedMesh mesh;
  std::string error;
  auto surface = TriangulateSurface(input, droppedVerts, droppedLines, error);
  if (!surface || !ToTriangleMesh(surface, soup, normals, error) ||
    !PrepareMesh(soup, normals, mesh, error))
  {
    std::printf("%-28s error: %s\n", name.c_str(), error.c_str());
    return SymmetryResult();
  }
  SymmetryOptions options;
  options.epsilon = 0.02 * mesh.diagonal;
  if (fastPath)
    options.closestFaceFastPath = CellLocatorFaceQueryFactory(nullptr);
  LinkNearbyParts(mesh, options.epsilon);
  const double prepare = std::chrono::duration<double>(Clock::now() - t0).count();
  const auto t1 = Clock::now();
  const SymmetryResult r = DetectSymmetry(mesh, options);
  const double detect = std::chrono::duration<double>(Clock::now() - t1).count();
  std::printf("%-28s %8d %6d %4d/%-4d %7.3f %7.3f %7.3f %7.3f %7.3f %8.1f %6.1f%% %5.3f %-3s "
              "n=(%+.4f %+.4f %+.4f) o=(%.4g %.4g %.4g)",
    name.c_str(),
    mesh.NumberOfFaces(),
    r.startsTried,
    r.coarseIterations,
    r.fineIterations,
    prepare,
    r.candidateSeconds,
    r.coarseSeconds,
    r.fineSeconds,
    prepare + detect,
    PeakMemoryMiB(),
    100.0 * r.symmetricAreaFraction,
    r.rmsResidual / options.epsilon,
    r.found ? "yes" : "no",
    r.plane.normal.x(),
    r.plane.normal.y(),
    r.plane.normal.z(),
    r.plane.origin.x(),
    r.plane.origin.y(),
    r.plane.origin.z());
  if (rotation)
    PrintRotation(mesh, r, options.epsilon);
  std::printf("\n");
  std::fflush(stdout);
  return r;
}

/// Both detections of --locator-ab (face tree, then the locator's fast path) and whether the
/// plane and the region agree.
void Run(const std::string& name, vtkPolyData* input)
{
  const SymmetryResult tree = Run(name, input, false);
  if (!locatorAB)
    return;
  const SymmetryResult fast = Run(name + " +locator", input, true);
  const double dn = (tree.plane.normal - fast.plane.normal).norm();
  const double dd = (tree.plane.origin - fast.plane.origin).norm();
  std::printf("%-28s same plane %s (|dn| %.1e, |do| %.1e), same region %s\n",
    "",
    dn == 0.0 && dd == 0.0 ? "yes" : "no",
    dn,
    dd,
    tree.faceLabel == fast.faceLabel ? "yes" : "no");
}
}

int main(int argc, char* argv[])
{
  std::vector<std::string> meshes;
  bool procedural = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--threads" && i + 1 < argc)
    {
      vtkSMPTools::SetBackend("STDThread");
      vtkSMPTools::Initialize(std::atoi(argv[++i]));
    }
    else if (arg == "--procedural")
      procedural = true;
    else if (arg == "--rotation")
      rotation = true;
    else if (arg == "--locator-ab")
      locatorAB = true;
    else
    {
      const std::vector<std::string> found = foldingmeshes::MeshFiles(arg);
      meshes.insert(meshes.end(), found.begin(), found.end());
    }
  }
  std::printf("SMP backend %s, %d threads\n",
    vtkSMPTools::GetBackend(),
    vtkSMPTools::GetEstimatedNumberOfThreads());
  std::printf("%-28s %8s %6s %9s %7s %7s %7s %7s %7s %8s %7s %-3s %s\n",
    "mesh",
    "faces",
    "starts",
    "iter c/f",
    "prep s",
    "cand s",
    "coarse",
    "fine s",
    "total s",
    "peak MiB",
    "region",
    "rms/eps sym",
    "plane");
  for (const std::string& path : meshes)
  {
    std::string error;
    auto mesh = ReadMesh(path, error);
    if (!mesh)
    {
      std::printf("%-28s error: %s\n", path.c_str(), error.c_str());
      continue;
    }
    Run(std::filesystem::path(path).filename().string(), mesh);
  }
  if (procedural)
  {
    for (int faces : { 10000, 100000, 1000000 })
    {
      auto shape = testing::MakeBilateralBlob(faces, 7);
      testing::ApplyRigidMotion(shape, testing::RandomRigidMotion(11));
      Run("blob_" + std::to_string(faces), shape.mesh);
    }
  }
  return 0;
}
