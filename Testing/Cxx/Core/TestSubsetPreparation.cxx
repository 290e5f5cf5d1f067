// PrepareFaceSubset returns exactly (every field, bit for bit) what PrepareMesh returns for
// the soup of the selected faces with the mesh's vertex normals as input normals:
// - a closed bilateral blob: all faces (a closed part), random faces (many small open
//   parts), balls of faces around random points (one open part, holes);
// - the same blob prepared with random input normals (the subset decides their signs);
// - a strip with slivers: a collinear face, and a face below the area floor of the whole
//   strip's diagonal but above that of a small subset's;
// - a "book" of three faces on one edge (non-manifold; two pages may turn a face against
//   the other) and a Moebius strip (no consistent orientation), every subset of their faces;
// - a face with a repeated vertex; an empty selection and a zero-area one fail;
// - everywhere, the same with the mesh's table of edge uses (ComputeFaceEdgeUses, what
//   Builder::Trim's repeated preparations use) as without it.
#include "CoreTestUtilities.h"

#include "../ProceduralMeshes.h"
#include "SubsetPreparation.h"

#include <cmath>
#include <random>
#include <string>

using foldingmeshes::PreparedMesh;
using foldingmeshes::PrepareFaceSubset;
using foldingmeshes::PrepareMesh;
using foldingmeshes::Triangle;
using foldingmeshes::TriangleMesh;
using foldingmeshes::Vec3;
using foldingmeshes::testing::MakeBilateralBlob;

namespace
{
/// PrepareMesh on the soup of the selected faces and their points (increasing order), with
/// mesh's vertex normals as input normals: PrepareFaceSubset's definition.
bool Reference(const PreparedMesh& mesh, const std::vector<char>& mask, PreparedMesh& out)
{
  TriangleMesh soup;
  std::vector<Vec3> normals;
  std::vector<int> id(mesh.NumberOfPoints(), -1);
  for (int f = 0; f < mesh.NumberOfFaces(); ++f)
    if (mask[f])
      for (int v : mesh.triangles[f])
        id[v] = 0;
  for (int v = 0; v < mesh.NumberOfPoints(); ++v)
    if (id[v] == 0)
    {
      id[v] = static_cast<int>(soup.points.size());
      soup.points.push_back(mesh.points[v]);
      normals.push_back(mesh.vertexNormals[v]);
    }
  for (int f = 0; f < mesh.NumberOfFaces(); ++f)
    if (mask[f])
      soup.triangles.push_back(
        { id[mesh.triangles[f][0]], id[mesh.triangles[f][1]], id[mesh.triangles[f][2]] });
  std::string error;
  return PrepareMesh(soup, normals, out, error);
}

/// The name of the first field that differs ("" if none).
std::string FirstDifference(const PreparedMesh& a, const PreparedMesh& b)
{
#define FIELD(name)                                                                                \
  if (!(a.name == b.name))                                                                         \
    return #name;
  FIELD(points)
  FIELD(triangles)
  FIELD(inputToWelded)
  FIELD(weldedToInput)
  FIELD(faceNormals)
  FIELD(vertexNormals)
  FIELD(faceCentroids)
  FIELD(faceAreas)
  FIELD(vertexAreas)
  FIELD(faceDegenerate)
  FIELD(faceNeighborOffsets)
  FIELD(faceNeighbors)
  FIELD(vertexFaceOffsets)
  FIELD(vertexFaces)
  FIELD(facePart)
  FIELD(numberOfParts)
  FIELD(proximityLinks)
  FIELD(numberOfBoundaryEdges)
  FIELD(numberOfNonManifoldEdges)
  FIELD(numberOfFlippedFaces)
  FIELD(boundsMin)
  FIELD(boundsMax)
  FIELD(diagonal)
  FIELD(totalArea)
#undef FIELD
  return "";
}

void ExpectSame(const PreparedMesh& mesh, const std::vector<char>& mask, const std::string& what)
{
  PreparedMesh expected, got;
  const bool expectedOk = Reference(mesh, mask, expected);
  const bool gotOk = PrepareFaceSubset(mesh, mask, got);
  EXPECT(gotOk == expectedOk, what << ": returned " << gotOk << ", PrepareMesh " << expectedOk);
  if (gotOk && expectedOk)
  {
    const std::string field = FirstDifference(expected, got);
    EXPECT(field.empty(), what << ": " << field << " differs from PrepareMesh's");
  }
  PreparedMesh withUses;
  const bool withUsesOk =
    PrepareFaceSubset(mesh, mask, withUses, foldingmeshes::ComputeFaceEdgeUses(mesh));
  EXPECT(withUsesOk == expectedOk,
    what << ": with the edge uses returned " << withUsesOk << ", PrepareMesh " << expectedOk);
  if (withUsesOk && expectedOk)
  {
    const std::string field = FirstDifference(expected, withUses);
    EXPECT(field.empty(), what << ": with the edge uses, " << field << " differs");
  }
}

/// Every subset of the faces of a small mesh.
void ExpectSameForAllSubsets(const PreparedMesh& mesh, const std::string& what)
{
  const int nf = mesh.NumberOfFaces();
  for (int bits = 0; bits < (1 << nf); ++bits)
  {
    std::vector<char> mask(nf);
    for (int f = 0; f < nf; ++f)
      mask[f] = (bits >> f) & 1;
    ExpectSame(mesh, mask, what + " subset " + std::to_string(bits));
  }
}

void CheckBlob(const PreparedMesh& mesh, const std::string& what, unsigned seed)
{
  const int nf = mesh.NumberOfFaces();
  ExpectSame(mesh, std::vector<char>(nf, 1), what + ": all faces");
  std::mt19937 rng(seed);
  for (int trial = 0; trial < 20; ++trial)
  {
    std::vector<char> mask(nf);
    for (char& m : mask)
      m = rng() % 3 != 0;
    ExpectSame(mesh, mask, what + ": random faces " + std::to_string(trial));
  }
  for (int trial = 0; trial < 20; ++trial)
  {
    const Vec3 center = mesh.points[rng() % mesh.NumberOfPoints()];
    const double radius = mesh.diagonal * (0.05 + 0.5 * (rng() % 100) / 100.0);
    std::vector<char> mask(nf);
    for (int f = 0; f < nf; ++f)
      mask[f] = (mesh.faceCentroids[f] - center).norm() < radius && rng() % 50 != 0;
    ExpectSame(mesh, mask, what + ": ball " + std::to_string(trial));
  }
}
}

int main()
{
  const TriangleMesh blob = coretest::ToTriangleMesh(MakeBilateralBlob(3000, 4).mesh);
  CheckBlob(coretest::Prepare(blob), "blob", 1);
  {
    std::mt19937 rng(9);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<Vec3> inputNormals(blob.points.size());
    for (Vec3& n : inputNormals)
      n = Vec3(normal(rng), normal(rng), normal(rng));
    inputNormals[0] = Vec3::Zero(); // not a direction: the computed normal stays
    PreparedMesh mesh;
    std::string error;
    REQUIRE(PrepareMesh(blob, inputNormals, mesh, error), error);
    CheckBlob(mesh, "blob with input normals", 2);
  }
  {
    // A strip of unit squares, one collinear face and one sliver of area 2.5e-11 (above the
    // area floor of a three-face subset's diagonal, below the floor of the strip's).
    TriangleMesh soup;
    for (int i = 0; i <= 1000; ++i)
    {
      soup.points.push_back(Vec3(i, 0, 0));
      soup.points.push_back(Vec3(i, 1, 0));
    }
    for (int i = 0; i < 1000; ++i)
    {
      soup.triangles.push_back({ 2 * i, 2 * i + 2, 2 * i + 1 });
      soup.triangles.push_back({ 2 * i + 1, 2 * i + 2, 2 * i + 3 });
    }
    const int n = static_cast<int>(soup.points.size());
    soup.points.push_back(Vec3(0.5, 0, 0));
    soup.triangles.push_back({ 0, n, 2 }); // collinear, on the strip's first edge
    soup.points.push_back(Vec3(0.5, -1e-10, 0));
    soup.triangles.push_back({ 0, n + 1, n }); // area 2.5e-11
    const PreparedMesh mesh = coretest::Prepare(soup);
    const int nf = mesh.NumberOfFaces();
    EXPECT(mesh.faceDegenerate[nf - 1] && mesh.faceDegenerate[nf - 2],
      "the slivers are degenerate in the whole strip");
    std::vector<char> mask(nf, 0);
    mask[0] = mask[nf - 1] = mask[nf - 2] = 1;
    PreparedMesh small;
    REQUIRE(PrepareFaceSubset(mesh, mask, small), "the three faces at the strip's start");
    EXPECT(!small.faceDegenerate[2] && small.faceDegenerate[1],
      "the 2.5e-11 sliver is regular in a small subset, the collinear face degenerate");
    ExpectSame(mesh, mask, "slivers");
    ExpectSame(mesh, std::vector<char>(nf, 1), "strip");
  }
  {
    // Three pages on the edge 0-1; the third one's input orientation runs 0 -> 1 like the
    // first's, so the pair (first, third) must be turned by the orientation walk.
    TriangleMesh soup;
    soup.points = {
      Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, 1, 1)
    };
    soup.triangles = { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 }, { 1, 5, 4 } };
    ExpectSameForAllSubsets(coretest::Prepare(soup), "book");
  }
  {
    // Moebius strip of 8 quads.
    TriangleMesh soup;
    const int quads = 8;
    const double pi = 3.14159265358979323846;
    for (int i = 0; i < quads; ++i)
    {
      const double a = 2 * pi * i / quads;
      const Vec3 c(std::cos(a), std::sin(a), 0.0);
      const Vec3 w = 0.3 *
        (std::cos(a / 2) * Vec3(std::cos(a), std::sin(a), 0.0) + std::sin(a / 2) * Vec3::UnitZ());
      soup.points.push_back(c + w);
      soup.points.push_back(c - w);
    }
    for (int i = 0; i < quads; ++i)
    {
      const int a = 2 * i, b = 2 * i + 1;
      // The last quad joins the first with the sides exchanged.
      const int c = i + 1 < quads ? 2 * i + 2 : 1, d = i + 1 < quads ? 2 * i + 3 : 0;
      soup.triangles.push_back({ a, c, b });
      soup.triangles.push_back({ b, c, d });
    }
    const PreparedMesh mesh = coretest::Prepare(soup);
    std::mt19937 rng(3);
    for (int trial = 0; trial < 2000; ++trial)
    {
      std::vector<char> mask(mesh.NumberOfFaces());
      for (char& m : mask)
        m = rng() % 4 != 0;
      ExpectSame(mesh, mask, "moebius " + std::to_string(trial));
    }
  }
  {
    TriangleMesh soup;
    soup.points = { Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0) };
    soup.triangles = { { 0, 1, 2 }, { 2, 1, 3 }, { 1, 1, 3 } };
    const PreparedMesh mesh = coretest::Prepare(soup);
    ExpectSameForAllSubsets(mesh, "repeated vertex");
    PreparedMesh out;
    EXPECT(!PrepareFaceSubset(mesh, { 0, 0, 0 }, out), "no face selected");
    EXPECT(!PrepareFaceSubset(mesh, { 0, 0, 1 }, out), "only a zero-area face selected");
  }
  return coretest::Finish("TestSubsetPreparation");
}
