// A procedural corpus of artist-like meshes (issue 21): furniture, a rack, a biplane, a figure
// and a soup, each assembled from many separate primitives (boxes, cylinders, spheres, thin
// plates) that touch and interpenetrate, with open parts (cylinders without caps), flipped parts,
// exact duplicate faces and large triangles spanning the model. Every mesh is mirror-symmetric
// about x = 0 as built; each comes in three variants: as built, under a random rigid motion
// (the plane moves with it), and with an asymmetric deformation of the parts on one side and in
// the middle (about 60% of the area), which no plane folds within 2% of the diagonal.
//
//   GenerateArtistMeshes OUTDIR
//
// writes OUTDIR/<name>_<variant>.ply (binary) and prints name, faces, parts, open edges and the
// plane (origin, normal) of each. Not a test: the input of BenchmarkFoldingTable1 and
// BenchmarkSymmetryDetection, e.g.
//   build/bin/GenerateArtistMeshes /tmp/artist && build/bin/BenchmarkFoldingTable1 --threads 2
//   /tmp/artist
#include "ArtistMeshes.h"
#include "EdgeTable.h"

#include <vtkNew.h>
#include <vtkPLYWriter.h>

#include <cstdio>
#include <string>

namespace
{
bool Write(const foldingmeshes::TriangleMesh& a, const std::string& path)
{
  vtkNew<vtkPLYWriter> writer;
  writer->SetInputData(foldingmeshes::artist::ToPolyData(a));
  writer->SetFileName(path.c_str());
  writer->SetFileTypeToBinary();
  return writer->Write() == 1;
}
}

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: %s OUTDIR\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  std::printf("%-22s %7s %6s %6s  plane origin / normal\n", "mesh", "faces", "parts", "open");
  for (const foldingmeshes::artist::ArtistMesh& m : foldingmeshes::artist::MakeArtistCorpus())
  {
    if (!Write(m.mesh, dir + "/" + m.name + ".ply"))
    {
      std::fprintf(stderr, "cannot write %s/%s.ply\n", dir.c_str(), m.name.c_str());
      return 1;
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
  }
  return 0;
}
