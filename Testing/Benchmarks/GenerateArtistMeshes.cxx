// A procedural corpus of artist-like meshes (issue 21): furniture, a rack, a biplane, a figure
// and a soup, each assembled from many separate primitives (boxes, cylinders, spheres, thin
// plates) that touch and interpenetrate, with open parts (cylinders without caps), flipped parts,
// exact duplicate faces and large triangles spanning the model. Every mesh is mirror-symmetric
// about x = 0 as built; each comes in three variants: as built, under a random rigid motion
// (the plane moves with it), and with an asymmetric deformation of the parts on one side and in
// the middle (about 60% of the area), which no plane folds within 2% of the diagonal.
//
//   GenerateArtistMeshes OUTDIR [--large]
//
// writes OUTDIR/<name>_<variant>.ply (binary) and prints name, faces, parts, open edges and the
// plane (origin, normal) of each; --large also the procedural bilateral blobs of 100k and 1M
// faces and the crate of 84,000 boxes that `BenchmarkArtistMeshes --large` times
// (blob_100000.ply, blob_1000000.ply, crate_1008000.ply: the same meshes, under the same rigid
// motions), to profile them with the command-line program. Not a test:
// the input of BenchmarkFoldingTable1 and BenchmarkSymmetryDetection, e.g.
//   build/bin/GenerateArtistMeshes /tmp/artist && build/bin/BenchmarkFoldingTable1 --threads 2
//   /tmp/artist
#include "ArtistMeshes.h"
#include "EdgeTable.h"
#include "ProceduralMeshes.h"

#include <vtkNew.h>
#include <vtkPLYWriter.h>
#include <vtkPolyData.h>

#include <cstdio>
#include <string>

namespace
{
bool Write(vtkPolyData* mesh, const std::string& path)
{
  vtkNew<vtkPLYWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(path.c_str());
  writer->SetFileTypeToBinary();
  return writer->Write() == 1;
}

/// Writes DIR/<name>.ply and prints its line; false (with a message) if it cannot.
bool WriteArtistMesh(const foldingmeshes::artist::ArtistMesh& m, const std::string& dir)
{
  if (!Write(foldingmeshes::artist::ToPolyData(m.mesh), dir + "/" + m.name + ".ply"))
  {
    std::fprintf(stderr, "cannot write %s/%s.ply\n", dir.c_str(), m.name.c_str());
    return false;
  }
  std::printf("%-22s %7zu %6d %6zu  (%.4f %.4f %.4f) / (%.4f %.4f %.4f)%s\n",
    m.name.c_str(),
    m.mesh.triangles.size(),
    m.parts,
    foldingmeshes::OpenEdges(m.mesh.triangles).size(),
    m.origin.x(),
    m.origin.y(),
    m.origin.z(),
    m.normal.x(),
    m.normal.y(),
    m.normal.z(),
    m.deformed ? " (one side deformed)" : "");
  return true;
}
}

int main(int argc, char* argv[])
{
  const bool large = argc == 3 && std::string(argv[2]) == "--large";
  if (argc != 2 && !large)
  {
    std::fprintf(stderr, "usage: %s OUTDIR [--large]\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  std::printf("%-22s %7s %6s %6s  plane origin / normal\n", "mesh", "faces", "parts", "open");
  for (const foldingmeshes::artist::ArtistMesh& m : foldingmeshes::artist::MakeArtistCorpus())
    if (!WriteArtistMesh(m, dir))
      return 1;
  for (int faces : { 100000, 1000000 }) // as BenchmarkArtistMeshes --large makes them
  {
    if (!large)
      break;
    auto blob = foldingmeshes::testing::MakeBilateralBlob(faces, 7);
    foldingmeshes::testing::ApplyRigidMotion(blob, foldingmeshes::testing::RandomRigidMotion(11));
    const std::string name = "blob_" + std::to_string(faces);
    if (!Write(blob.mesh, dir + "/" + name + ".ply"))
    {
      std::fprintf(stderr, "cannot write %s/%s.ply\n", dir.c_str(), name.c_str());
      return 1;
    }
    const foldingmeshes::testing::KnownPlane& p = blob.planes.at(0);
    std::printf("%-22s %7lld %6d %6s  (%.4f %.4f %.4f) / (%.4f %.4f %.4f)\n",
      name.c_str(),
      static_cast<long long>(blob.mesh->GetNumberOfCells()),
      1,
      "-",
      p.origin.x(),
      p.origin.y(),
      p.origin.z(),
      p.normal.x(),
      p.normal.y(),
      p.normal.z());
  }
  // The many-parts million-face mesh, as BenchmarkArtistMeshes --large makes it.
  if (large &&
    !WriteArtistMesh(foldingmeshes::artist::MakeCrate(foldingmeshes::artist::LargeCratePairs), dir))
    return 1;
  return 0;
}
