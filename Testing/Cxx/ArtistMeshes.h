// A procedural corpus of artist-like meshes (issue 21): furniture, a rack, a biplane, a figure
// and a soup, each assembled from many separate primitives (boxes, cylinders, spheres, thin
// plates) that touch and interpenetrate, with open parts (cylinders without caps), flipped parts,
// exact duplicate faces and large triangles spanning the model. Every mesh is mirror-symmetric
// about x = 0 as built; each comes in three variants: as built, under a random rigid motion
// (the plane moves with it), and with an asymmetric deformation of the parts on one side and in
// the middle (about 60% of the area), which no plane folds within 2% of the diagonal.
// Used by GenerateArtistMeshes (writes them) and BenchmarkArtistMeshes (times them).
#ifndef foldingmeshes_ArtistMeshes_h
#define foldingmeshes_ArtistMeshes_h

#include "TriangleMesh.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

namespace foldingmeshes
{
namespace artist
{
struct ArtistMesh
{
  std::string name; ///< model_variant, e.g. chair_dense_moved
  TriangleMesh mesh;
  int parts = 0;         ///< primitives assembled
  Vec3 origin, normal;   ///< the mirror plane (for the deformed variant: of the undeformed side)
  bool deformed = false; ///< one side deformed: no plane folds the whole within epsilon
};

/// The 21 meshes: chair, chair_dense, bench_slats, rack, biplane, figure, soup, each exact,
/// moved and deformed (the same meshes on every call).
std::vector<ArtistMesh> MakeArtistCorpus();

/// A crate of `pairs` pairs of closed boxes of varied sizes on a grid (12 faces a box),
/// mirror-symmetric about x = 0 as built, then under a random rigid motion: the many-parts
/// mesh of issue 21's million-face goal (`BenchmarkArtistMeshes --large`: 42,000 pairs,
/// 1,008,000 faces), where a connected blob would not show what separate parts cost.
ArtistMesh MakeCrate(int pairs);
/// The crate's pairs for the million-face goal (GenerateArtistMeshes and BenchmarkArtistMeshes
/// --large).
constexpr int LargeCratePairs = 42000;

/// The mesh as a vtkPolyData with float points (what a PLY file holds: GenerateArtistMeshes
/// writes these, BenchmarkArtistMeshes times them), or double ones (the corpus as built; the
/// dense chair folds worse there, docs/benchmarks.md).
vtkSmartPointer<vtkPolyData> ToPolyData(const TriangleMesh& mesh, bool doublePoints = false);
}
}

#endif
