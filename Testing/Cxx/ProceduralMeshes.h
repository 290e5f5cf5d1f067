// Procedural test meshes whose symmetry ground truth is exact, for accuracy tests and benchmarks.
//
// Every generator returns a vtkPolyData made of triangles only, with double-precision points, no
// duplicate or unused points, edge-manifold and closed, consistently oriented with outward normals
// (positive signed volume, per connected component). Everything is deterministic: randomness comes
// from std::mt19937 with explicit seeds, turned into numbers by our own code (not by the
// implementation-defined std::*_distribution), so a seed gives bit-identical meshes.
//
// "Exact" planes: for MakeBilateralBlob, MakeThreePlaneShape, MakeSphere, MakeCylinder,
// MakeMultiPartSymmetric (and the symmetric part of the two composite generators) every vertex
// reflected through every listed plane lands on a vertex, and the triangles map onto triangles, up
// to floating-point round-off (~1e-15 relative; exactly before any motion, except for the rotated
// sub-part of MakeAsymmetricBodyWithSymmetricPart).
//
// Continuous symmetry: a sphere is symmetric about EVERY plane through its centre and a cylinder
// about EVERY plane containing its axis (and its mid plane). `planes` then lists only a few exact
// ones; `family`, `center` and `axis` describe the whole set, and a test must accept any plane
// through the centre (sphere) or containing the axis (cylinder): use BestPlaneMatch, which does.
#ifndef foldingmeshes_testing_ProceduralMeshes_h
#define foldingmeshes_testing_ProceduralMeshes_h

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <Eigen/Geometry>

#include <vector>

namespace foldingmeshes
{
namespace testing
{

struct KnownPlane
{
  Eigen::Vector3d origin; // a point of the plane
  Eigen::Vector3d normal; // unit
};

enum class SymmetryFamily
{
  None,                  // only the listed planes
  AnyPlaneThroughCenter, // sphere: every plane through `center`
  AnyPlaneContainingAxis // cylinder: every plane containing the line (center, axis), + listed
};

struct ProceduralMesh
{
  vtkSmartPointer<vtkPolyData> mesh;
  std::vector<KnownPlane> planes;  // all exact mirror planes of the symmetric part (may be empty)
  std::vector<char> symmetricFace; // per cell: 1 in the truly symmetric part, 0 otherwise
  SymmetryFamily family = SymmetryFamily::None;
  Eigen::Vector3d center = Eigen::Vector3d::Zero(); // for the families (kept up to date by
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // the transformations below)
};

// ---- generators (approxFaces: target number of triangles, 500 .. 1,000,000) ----

// Closed "creature", about 2.5 long along y, exactly symmetric about x = 0 and far from
// symmetric about any other plane (also at a tolerance of 2% of the bounding-box diagonal): a
// big head with ears, eyes and a narrowing snout towards +y, a thin tail curling up towards -y,
// a pear-shaped trunk with wide flat hips, a flat belly (-z) and a domed back with a dorsal
// sail (+z), four stubby legs and random bumps (10-30% of the local radius) in mirror pairs.
// The half x >= 0 is tessellated (equal-area octahedral grid, seam on x = 0) and mirrored,
// seam vertices shared: exactly symmetric as a vertex set and as a triangle set.
// Faces 0..F/2-1 are the half x >= 0, face i + F/2 is the mirror of face i.
ProceduralMesh MakeBilateralBlob(int approxFaces, unsigned seed = 1);
// The same analytic surface, the half x < 0 sampled on a finer grid (about 1.3x the resolution)
// stitched to the shared seam by a zipper strip: symmetric as a surface, not as a vertex set.
ProceduralMesh MakeBilateralBlobDifferentTessellation(int approxFaces, unsigned seed = 1);
// Rounded box, extents 2 x 1.4 x 0.8, edge radius 0.2, centred at 0: planes x=0, y=0, z=0.
ProceduralMesh MakeThreePlaneShape(int approxFaces);
// MakeBilateralBlob(seed) with a horn welded by a collar into a hole cut in the upper x > 0 flank:
// one connected manifold component. The horn has no symmetry, not even in parts: it winds
// along a helix (a corkscrew, non-planar), its elliptic sections twist, it swells and tapers and
// carries one-sided bumps. symmetricFace is 0 on the horn and collar and on the body faces
// mirroring the removed hole; the area of the 0 faces is about attachmentAreaFraction
// (0.02 .. 0.7) of the total (within 0.01 from 2k faces up; on coarser meshes the smallest weld,
// a hole of 1.5 edge lengths, may exceed a tiny request).
ProceduralMesh MakeBlobWithAsymmetricPart(int approxFaces,
  double attachmentAreaFraction,
  unsigned seed = 1);
// The lumpy asymmetric body of MakeAsymmetricBlob with an exactly symmetric sub-part welded into
// a hole: a "head" with ONE mirror plane, a short neck flaring into a wide, bent, crested head
// with eyes, closed by a dome; its plane is `planes[0]`, symmetricFace marks its faces (about
// symmetricAreaFraction, 0.02 .. 0.6, of the area). The collar joining it to the body is
// marked 0. The part sits where the body looks least symmetric about the part's plane.
ProceduralMesh MakeAsymmetricBodyWithSymmetricPart(int approxFaces,
  double symmetricAreaFraction,
  unsigned seed = 1);
// A random lumpy blob with no mirror symmetry, not even approximately (planes empty,
// symmetricFace all 0): big lopsided lobes at random directions and a rough skin of random
// waves, so that no plane maps much of it onto itself within 2% of the diagonal.
ProceduralMesh MakeAsymmetricBlob(int approxFaces, unsigned seed = 1);
// Unit sphere at 0 (equal-area octahedral grid). Any plane through 0 is a symmetry plane;
// `planes` lists x=0, y=0, z=0, which are also exact for the vertex set.
ProceduralMesh MakeSphere(int approxFaces);
// Capped cylinder along z, radius 0.6, z in [-1, 1]. Any plane containing the z axis and z = 0
// are symmetry planes; `planes` lists x=0, y=0, x=y, x=-y and z=0, exact for the vertex set.
ProceduralMesh MakeCylinder(int approxFaces);
// Three closed components: the bilateral creature (seed 7) and two lumpy "ears" (each
// asymmetric, one the mirror image of the other) that interpenetrate its head. Plane x = 0;
// symmetricFace all 1.
ProceduralMesh MakeMultiPartSymmetric(int approxFaces);

// ---- transformations (mesh, planes and family consistently) ----
Eigen::Isometry3d RandomRigidMotion(unsigned seed); // uniform rotation, translation in [-5,5]^3
void ApplyRigidMotion(ProceduralMesh& m, const Eigen::Isometry3d& T);
void ScaleUniformly(ProceduralMesh& m, double s); // about the world origin, s > 0
// Gaussian noise of standard deviation sigmaFraction * bounding-box diagonal, along the
// area-weighted vertex normals (or isotropic: that deviation on each coordinate). The planes stay.
void AddGaussianNoise(ProceduralMesh& m,
  double sigmaFraction,
  unsigned seed,
  bool alongNormals = true);

// ---- measures ----
double BoundsDiagonal(vtkPolyData* mesh);
Eigen::Vector3d AreaCentroid(vtkPolyData* mesh); // area-weighted centroid of the surface
std::vector<double> FaceAreas(vtkPolyData* mesh);
double MaskAreaFraction(vtkPolyData* mesh, const std::vector<char>& mask); // area(mask)/area
// Angle between the plane normals in degrees, sign-insensitive: 0..90.
double PlaneAngleDegrees(const Eigen::Vector3d& n1, const Eigen::Vector3d& n2);
// Distance from the point of the true plane nearest to `at` (use the mesh centroid) to the found
// plane (origin, normal), divided by `diagonal` (use the bounding-box diagonal).
double PlaneOffsetError(const KnownPlane& truth,
  const Eigen::Vector3d& origin,
  const Eigen::Vector3d& normal,
  const Eigen::Vector3d& at,
  double diagonal);
struct PlaneMatch
{
  int index = -1; // into m.planes; -1: a member of m.family (or no plane at all)
  double angleDegrees = 90;
  double offsetError = 1e300; // PlaneOffsetError at the area centroid, relative to the diagonal
};
// Best match of a found plane over all the known planes and the continuous family (minimum
// angle, then minimum offset among the planes within 1e-6 degrees of that angle).
PlaneMatch BestPlaneMatch(const ProceduralMesh& m,
  const Eigen::Vector3d& origin,
  const Eigen::Vector3d& normal);
// Area-weighted intersection over union of two face masks (sizes must equal the cell count, else
// std::invalid_argument); 1 when both are empty.
double RegionIoU(vtkPolyData* mesh, const std::vector<char>& found, const std::vector<char>& truth);

} // namespace testing
} // namespace foldingmeshes

#endif
