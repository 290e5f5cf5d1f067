// Shared check helpers of TestProceduralMeshes: failure counter, EXPECT, mesh checks, measures.
#ifndef TestProceduralMeshesChecks_h
#define TestProceduralMeshesChecks_h

#include "ProceduralMeshes.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <Eigen/Core>

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace foldingmeshes::testing;
using Vec3 = Eigen::Vector3d;
using Tri = std::array<vtkIdType, 3>;

namespace tpm
{
extern int failures;
extern bool quiet;               // while checking that the checks catch broken meshes
extern std::string firstFailure; // ... the first message then

#define EXPECT(cond, msg)                                                                          \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
    {                                                                                              \
      std::ostringstream os_;                                                                      \
      os_ << msg;                                                                                  \
      if (!quiet)                                                                                  \
        std::printf("FAIL: %s\n", os_.str().c_str());                                              \
      else if (firstFailure.empty())                                                               \
        firstFailure = os_.str();                                                                  \
      ++failures;                                                                                  \
    }                                                                                              \
  } while (0)

inline double Seconds(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Soup
{
  std::vector<Vec3> p;
  std::vector<Tri> t;
};

// Triangles-only check + extraction.
bool Extract(const std::string& name, vtkPolyData* pd, Soup& s);

struct TopoInfo
{
  int components = 0;
  double minAreaRatio = 0; // smallest face area / mean face area
};

// Closed, edge-manifold, consistently oriented (each directed edge once, its reverse once),
// vertex-manifold (one fan per vertex), no unused or duplicate points, no degenerate faces,
// positive signed volume per connected component.
TopoInfo CheckTopology(const std::string& name, vtkPolyData* pd, const Soup& s);

Vec3 Reflect(const Vec3& x, const KnownPlane& p);

// Max distance (relative to the diagonal) from each reflected vertex of the masked faces to the
// nearest vertex; counts the masked faces whose reflection is not a face; fraction of vertices
// whose reflection is within tol of a vertex.
struct Reflection
{
  double maxDist = 0;
  size_t unmatchedFaces = 0;
  double matchedFraction = 0;
};
Reflection ReflectVertices(vtkPolyData* pd,
  const Soup& s,
  const KnownPlane& pl,
  const std::vector<char>* mask);

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection 5.1.5).
Vec3 ClosestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

// Brute force (with bounding-sphere rejection) distances from points to the surface.
std::vector<double> SurfaceDistances(const Soup& s, const std::vector<Vec3>& q);

// RMS surface distance of the reflected vertices for the three principal planes through the
// area centroid, relative to the diagonal.
std::array<std::pair<Vec3, double>, 3> PrincipalPlaneResiduals(vtkPolyData* pd, const Soup& s);

struct Gen
{
  std::string name;
  std::function<ProceduralMesh(int)> make;
  bool exactVertices;  // every listed plane maps the (masked) vertex set onto itself
  bool exactTriangles; // ... and the masked triangles onto triangles
  int components;
};

// Full check of one mesh; returns its reflection error (max over planes).
double CheckMesh(const Gen& g,
  const ProceduralMesh& m,
  const std::string& name,
  int approxFaces,
  double seconds = -1);

vtkSmartPointer<vtkPolyData> FromSoup(const Soup& s);

// Runs the checks on a deliberately broken copy of m; they must report a failure.
void ExpectCaught(const Gen& g,
  const ProceduralMesh& m,
  const std::string& what,
  const std::function<void(Soup&)>& breakIt);

bool SamePoints(vtkPolyData* a, vtkPolyData* b);
} // namespace tpm

#endif
