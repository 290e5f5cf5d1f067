// Builder::Trim's incremental state against computing everything from scratch, bit for bit,
// over a region S that shrinks step by step (a few random faces, a small ball of faces - the
// closest faces of nearby mirror images -, a large part; each time its largest connected part,
// as Trim keeps it), with one plane near the symmetry plane of a blob:
// - ShrinkingSubsetDistances: S prepared (PrepareFaceSubset) and the fine mirror distances of
//   its vertices (MirrorDistance on it), on the blob with its own normals (the incremental path:
//   a single full update) and with random input normals (the signs of the subset's normals
//   change as faces go: full updates again, still the same distances);
// - ShrinkingMirrorBudget: the limits by definition (every point of S tested for each partner);
// - a region that grows again (not a subset): everything starts over, still the same;
// - a preparation of S made elsewhere with its queries (Builder::Polish's, Adopt): used when
//   it is S's (one adopted update), dropped when it is another subset's; the distances the
//   same bit for bit either way.
#include "CoreTestUtilities.h"
#include "FaceTree.h"
#include "MirrorDistance.h"
#include "ProceduralMeshes.h"
#include "RegionGrowing.h"
#include "ShrinkingMirrorBudget.h"
#include "ShrinkingSubsetDistances.h"
#include "SubsetPreparation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>

using namespace foldingmeshes;

namespace
{
const double kInf = std::numeric_limits<double>::infinity();
const double kPi = 3.14159265358979323846;
const double kCompatibilityAngle = 45.0;

bool BitIdentical(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

/// Builder's limits from scratch, by definition: a point's partner is the lowest (distance, id)
/// among the points of `ids` within eps of its mirror image, every point tested.
std::vector<double> FreshLimits(const std::vector<Vec3>& points,
  const std::vector<double>& budget,
  const std::vector<int>& ids,
  const Plane& plane,
  double eps)
{
  double least = eps;
  for (int v : ids)
    least = std::min(least, budget[v]);
  std::vector<double> limit(ids.size());
  for (size_t k = 0; k < ids.size(); ++k)
  {
    const int v = ids[k];
    const Vec3 image = plane.Reflect(points[v]);
    int p = -1;
    double best = eps;
    for (int q : ids) // increasing ids: the first of equal distances is the lowest id
    {
      const double d = (points[q] - image).norm();
      if (d <= best && (p < 0 || d < best))
      {
        best = d;
        p = q;
      }
    }
    limit[k] = std::min({ eps, budget[v], p >= 0 ? budget[p] : least });
  }
  return limit;
}

/// One region's worth of Trim's inputs: the incremental state and everything from scratch.
class Comparison
{
public:
  Comparison(const PreparedMesh& mesh, const Plane& plane, double eps, const std::string& name)
    : Mesh(mesh)
    , Mirror(plane)
    , Eps(eps)
    , Name(name)
    , Distances(mesh, plane, kCompatibilityAngle, eps)
    , Budget(mesh.points, this->PointBudget, plane, eps)
  {
    // Budgets from a third to 1.5 times eps: partners' budgets matter.
    std::mt19937 rng(5);
    for (int v = 0; v < mesh.NumberOfPoints(); ++v)
      this->PointBudget.push_back(eps * (0.33 + 1.2 * (rng() % 1000) / 1000.0));
  }

  /// Compares everything for S; false when S has no prepared subset.
  bool Check(const std::vector<char>& S, const std::string& step)
  {
    const std::string what = this->Name + ", " + step;
    PreparedMesh expected;
    const bool prepared = PrepareFaceSubset(this->Mesh, S, expected);
    const bool updated = this->Distances.Update(S);
    EXPECT(
      prepared == updated, what << ": Update " << updated << ", PrepareFaceSubset " << prepared);
    if (!prepared || !updated)
      return false;
    const PreparedMesh& spm = this->Distances.Subset();
    EXPECT(spm.triangles == expected.triangles && spm.vertexNormals == expected.vertexNormals,
      what << ": the subset differs from PrepareFaceSubset's");
    std::vector<double> d;
    MirrorDistance(expected, kCompatibilityAngle)
      .Compute(this->Mirror, DistanceMetric::Fine, this->Eps, d);
    const std::vector<double>& got = this->Distances.Distances();
    EXPECT(BitIdentical(got, d), what << ": the distances differ from a new MirrorDistance's");
    for (double x : d)
      this->Finite += std::isfinite(x);

    // Trim's budgets.
    std::vector<int> ids;
    std::vector<char> inS(this->Mesh.NumberOfPoints(), 0);
    for (int f = 0; f < this->Mesh.NumberOfFaces(); ++f)
      if (S[f])
        for (int v : this->Mesh.triangles[f])
          inS[v] = 1;
    for (int v = 0; v < this->Mesh.NumberOfPoints(); ++v)
      if (inS[v])
        ids.push_back(v);
    const std::vector<double> limit = this->Budget.Limits(ids);
    EXPECT(BitIdentical(limit,
             FreshLimits(this->Mesh.points, this->PointBudget, ids, this->Mirror, this->Eps)),
      what << ": the budget limits differ from those by definition");
    return true;
  }

  int FullUpdates() const { return this->Distances.FullUpdates(); }
  /// Counts over all checks, to see that the cases occurred.
  int Finite = 0;

private:
  const PreparedMesh& Mesh;
  const Plane Mirror;
  const double Eps;
  const std::string Name;
  std::vector<double> PointBudget;
  ShrinkingSubsetDistances Distances;
  ShrinkingMirrorBudget Budget;
};

/// Shrinks S the ways Trim does, checking every step; then lets it grow back once.
void Run(const PreparedMesh& mesh, const Plane& plane, const std::string& name, int expectedFull)
{
  const double eps = 0.02 * mesh.diagonal;
  Comparison comparison(mesh, plane, eps, name);
  std::mt19937 rng(7);
  const int nf = mesh.NumberOfFaces();
  std::vector<char> S(nf, 1);
  int steps = 0;
  for (int step = 0; step < 12; ++step)
  {
    if (!comparison.Check(S, "step " + std::to_string(step)))
      break;
    ++steps;
    std::vector<int> faces;
    for (int f = 0; f < nf; ++f)
      if (S[f])
        faces.push_back(f);
    if (step % 3 == 0)
    {
      for (int j = 0; j < 12; ++j)
        S[faces[rng() % faces.size()]] = 0;
    }
    else
    {
      const Vec3 center = mesh.faceCentroids[faces[rng() % faces.size()]];
      const double radius = (step == 5 ? 0.3 : 0.03) * mesh.diagonal;
      for (int f : faces)
        if ((mesh.faceCentroids[f] - center).norm() < radius)
          S[f] = 0;
    }
    S = LargestConnectedRegion(mesh, S);
  }
  EXPECT(steps == 12, name << ": only " << steps << " steps");
  const int shrinking = comparison.FullUpdates();
  if (expectedFull > 0)
    EXPECT(shrinking == expectedFull,
      name << ": " << shrinking << " full updates, expected " << expectedFull);
  else
    EXPECT(shrinking > 1, name << ": the subsets all matched the first: no full update tested");
  comparison.Check(std::vector<char>(nf, 1), "grown back");
  EXPECT(comparison.FullUpdates() == shrinking + 1, name << ": a larger S did not start over");
  EXPECT(comparison.Finite > 0, name << ": no finite distance: a case did not occur");
  std::printf("%s: %d full updates in %d steps; %d finite distances\n",
    name.c_str(),
    shrinking,
    steps,
    comparison.Finite);
}
}

int main()
{
  const auto t0 = std::chrono::steady_clock::now();
  using namespace foldingmeshes::testing;
  ProceduralMesh blob = MakeBilateralBlob(4000, 3);
  ApplyRigidMotion(blob, RandomRigidMotion(11));
  const TriangleMesh soup = coretest::ToTriangleMesh(blob.mesh);
  REQUIRE(blob.planes.size() == 1, "the bilateral blob should have one plane");
  // The symmetry plane tilted by 1.5 degrees: mirror images up to about 1.3% of the diagonal
  // off the surface, so distances, partners and mirrored faces vary within eps = 2%.
  const PreparedMesh mesh = coretest::Prepare(soup);
  Vec3 center = Vec3::Zero();
  for (const Vec3& p : mesh.points)
    center += p / mesh.NumberOfPoints();
  Plane plane;
  plane.normal = Eigen::AngleAxisd(1.5 * kPi / 180.0, blob.planes[0].normal.unitOrthogonal()) *
    blob.planes[0].normal.normalized();
  plane.origin = center;
  Run(mesh, plane, "blob", 1);
  {
    // Random input normals: their signs follow the subset's own faces, which change.
    std::mt19937 rng(9);
    std::vector<Vec3> normals(soup.points.size());
    for (Vec3& n : normals)
      n = Vec3(double(rng() % 2001) - 1000.0,
        double(rng() % 2001) - 1000.0,
        double(rng() % 2001) - 1000.0);
    PreparedMesh random;
    std::string error;
    REQUIRE(PrepareMesh(soup, normals, random, error), error);
    Run(random, plane, "blob with random normals", 0);
  }
  {
    // Adopt: Polish's preparation of S and its queries start Trim's distances.
    const double eps = 0.02 * mesh.diagonal;
    std::vector<char> S(mesh.NumberOfFaces(), 1), other(mesh.NumberOfFaces(), 1);
    for (int f = 0; f < mesh.NumberOfFaces(); f += 7)
      other[f] = 0;
    other = LargestConnectedRegion(mesh, other);
    std::vector<double> fresh;
    {
      ShrinkingSubsetDistances alone(mesh, plane, kCompatibilityAngle, eps);
      REQUIRE(alone.Update(S), "a subset of the blob");
      fresh = alone.Distances();
    }
    for (int k = 0; k < 2; ++k)
    {
      const std::vector<char>& preparedFaces = k == 0 ? S : other;
      PreparedSubsetQueries prepared;
      prepared.subset = std::make_unique<PreparedMesh>();
      REQUIRE(PrepareFaceSubset(mesh, preparedFaces, *prepared.subset), "the prepared subset");
      prepared.queries = std::make_unique<MirrorDistance>(*prepared.subset, kCompatibilityAngle);
      std::vector<double> warm; // the queries used once already, as Polish leaves them
      prepared.queries->Compute(plane, DistanceMetric::Fine, eps, warm);
      ShrinkingSubsetDistances distances(mesh, plane, kCompatibilityAngle, eps);
      distances.Adopt(std::move(prepared));
      REQUIRE(distances.Update(S), "a subset of the blob");
      const char* what = k == 0 ? "S's own preparation" : "another subset's preparation";
      EXPECT(distances.AdoptedUpdates() == (k == 0 ? 1 : 0),
        what << ": " << distances.AdoptedUpdates() << " adopted updates");
      EXPECT(BitIdentical(distances.Distances(), fresh), what << ": the distances differ");
    }
  }
  std::printf("TestShrinkingRegion: %.2f s\n", coretest::Seconds(t0));
  return coretest::Finish("TestShrinkingRegion");
}
