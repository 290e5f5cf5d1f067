// vtkFoldingTreeBuilder on real meshes made by other people (../shared/data/meshes):
// - the first fold of the tree uses the plane vtkSymmetryPlaneDetector finds on the whole mesh
//   (within 1 degree) on meshes with a global plane;
// - every input face is accounted for in output 1: stored in a leaf (role 0/2), mirrored away
//   (role 1) or, with rotation nodes, turned away (role 3), always with a leaf id; the stored
//   ones add up to StoredFaces (with rotation nodes at most: a cut face is stored in pieces);
// - compression at least the paper's Table 1 value where we reach it (dino, table,
//   triceratops: the paper's own 5660-face mesh; below 56.8% before the runner-up planes
//   competed for S, see FoldingTreeBuilder.h);
// - the same tree (stored faces, height, leaf ids) with the Sequential and STDThread backends;
// - rotation nodes (RotationNodes, issue 22) never store more faces than the planes alone, and
//   the proved bound stays within the root epsilon: on the queen (a cut sector of order 15
//   since 2026-12-06, 549 faces against the planes' 812) and the bearing, where a
//   sector of the second order that passes, with a fold below it, stores under three quarters
//   of the planes' faces (184 of 276; the largest order's sector alone stores 264, 96%),
//   and the teapot, whose body (a sector of order 4 of the part the turns map onto itself,
//   spout and handle left out) stores fewer faces than the planes (1440 of 1462);
//   the same tree with both backends.
//
//   TestFoldingTreeRealMeshes MESH_DIR
#include "MeshIO.h"
#include "vtkFoldingTreeBuilder.h"
#include "vtkSymmetryPlaneDetector.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
int Failures = 0;

void Check(bool ok, const std::string& what)
{
  std::printf("  [%s] %s\n", ok ? "ok" : "FAILED", what.c_str());
  Failures += ok ? 0 : 1;
}

/// The plane of the first folding node in preorder (the block named "Plane"); false if none.
bool FirstFoldPlane(vtkMultiBlockDataSet* node, double normal[3])
{
  for (unsigned b = 0; b < node->GetNumberOfBlocks(); ++b)
  {
    const char* name =
      node->HasMetaData(b) ? node->GetMetaData(b)->Get(vtkMultiBlockDataSet::NAME()) : nullptr;
    vtkDataObject* child = node->GetBlock(b);
    if (name && std::string(name) == "Plane" && child)
    {
      vtkDataArray* n = child->GetFieldData()->GetArray("FoldingPlaneNormal");
      if (n)
      {
        n->GetTuple(0, normal);
        return true;
      }
    }
  }
  // Children first in block order: block 0 of a segmentation is fold(S).
  for (unsigned b = 0; b < node->GetNumberOfBlocks(); ++b)
    if (auto* mb = vtkMultiBlockDataSet::SafeDownCast(node->GetBlock(b)))
      if (FirstFoldPlane(mb, normal))
        return true;
  return false;
}

double AngleDegrees(const double a[3], const double b[3])
{
  const double c = std::abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) /
    std::sqrt(
      (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) * (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]));
  return std::acos(std::min(1.0, c)) * 180.0 / 3.14159265358979323846;
}

struct Folded
{
  int stored = -1, original = -1, height = -1;
  double compression = 0.0;
  double verifiedBound = -1.0, rootEpsilon = -1.0; ///< the tree's field data
  std::vector<int> leafIds;
  bool ok = false;
};

Folded Fold(vtkPolyData* mesh,
  const std::string& name,
  double firstPlane[3],
  bool& hasPlane,
  bool rotation = false)
{
  Folded r;
  vtkNew<vtkFoldingTreeBuilder> builder;
  builder->SetInputData(mesh);
  builder->SetRotationNodes(rotation);
  builder->Update();
  auto* tree = vtkMultiBlockDataSet::SafeDownCast(builder->GetOutputDataObject(0));
  auto* segmentation = vtkPolyData::SafeDownCast(builder->GetOutputDataObject(1));
  if (!tree || !segmentation || tree->GetNumberOfBlocks() == 0)
  {
    Check(false, name + ": the builder produced no tree");
    return r;
  }
  r.stored = builder->GetStoredFaces();
  vtkDataObject* treeBlock = tree->GetNumberOfBlocks() > 1 ? tree->GetBlock(1) : nullptr;
  vtkFieldData* fd = treeBlock ? treeBlock->GetFieldData() : nullptr;
  vtkDataArray* bound = fd ? fd->GetArray("VerifiedBound") : nullptr;
  vtkDataArray* rootEpsilon = fd ? fd->GetArray("RootEpsilon") : nullptr;
  r.verifiedBound = bound ? bound->GetTuple1(0) : -1.0;
  r.rootEpsilon = rootEpsilon ? rootEpsilon->GetTuple1(0) : -1.0;
  r.original = builder->GetOriginalFaces();
  r.height = builder->GetTreeHeight();
  r.compression = builder->GetCompression();
  hasPlane = false;
  if (auto* root = vtkMultiBlockDataSet::SafeDownCast(tree->GetBlock(0)))
    hasPlane = FirstFoldPlane(root, firstPlane);

  vtkDataArray* leaf = segmentation->GetCellData()->GetArray("FoldingLeafId");
  vtkDataArray* role = segmentation->GetCellData()->GetArray("FoldingRole");
  if (!leaf || !role)
  {
    Check(false, name + ": output 1 lacks FoldingLeafId/FoldingRole");
    return r;
  }
  int kept = 0, mirrored = 0, turned = 0, unlabelled = 0;
  for (vtkIdType f = 0; f < segmentation->GetNumberOfCells(); ++f)
  {
    const int ro = static_cast<int>(role->GetTuple1(f));
    const int id = static_cast<int>(leaf->GetTuple1(f));
    r.leafIds.push_back(id);
    kept += ro == 0 || ro == 2;
    mirrored += ro == 1;
    turned += ro == 3;
    unlabelled += id < 0 && ro != -1;
  }
  // With rotation nodes a sector's faces may be cut along its half-planes: several stored
  // pieces per kept input face.
  Check(rotation ? kept <= r.stored : kept == r.stored,
    name + ": " + std::to_string(kept) + " faces kept in leaves, StoredFaces " +
      std::to_string(r.stored));
  Check(
    unlabelled == 0 && (rotation || turned == 0) && kept + mirrored + turned > 0.99 * r.original,
    name + ": " + std::to_string(kept + mirrored + turned) + " of " + std::to_string(r.original) +
      " faces kept, mirrored or turned away, " + std::to_string(unlabelled) + " without a leaf");
  r.ok = true;
  return r;
}

/// The mesh `file` of `dir`, or null (a failed check).
vtkSmartPointer<vtkPolyData> Read(const std::string& dir, const std::string& file)
{
  std::string error;
  vtkSmartPointer<vtkPolyData> mesh = foldingmeshes::ReadMesh(dir + "/" + file, error);
  if (!mesh)
    Check(false, "cannot read " + file + ": " + error);
  return mesh;
}

void TestMesh(const std::string& dir,
  const std::string& file,
  double minimumCompression,
  bool globalPlane)
{
  std::printf("%s\n", file.c_str());
  vtkSmartPointer<vtkPolyData> mesh = Read(dir, file);
  if (!mesh)
    return;
  double plane[3] = { 0, 0, 0 };
  bool hasPlane = false;
  vtkSMPTools::SetBackend("STDThread");
  const Folded a = Fold(mesh, file, plane, hasPlane);
  if (!a.ok)
    return;
  char text[256];
  std::snprintf(text,
    sizeof(text),
    "%s: compression %.1f%% (at least %.1f%%), height %d",
    file.c_str(),
    100.0 * a.compression,
    100.0 * minimumCompression,
    a.height);
  Check(a.compression >= minimumCompression && a.stored < a.original, text);

  if (globalPlane)
  {
    vtkNew<vtkSymmetryPlaneDetector> detector;
    detector->SetInputData(mesh);
    detector->Update();
    const double angle = hasPlane ? AngleDegrees(plane, detector->GetPlaneNormal()) : 180.0;
    std::snprintf(text,
      sizeof(text),
      "%s: first fold %.3f degrees from the detector's plane",
      file.c_str(),
      angle);
    Check(hasPlane && angle < 1.0, text);
  }

  vtkSMPTools::SetBackend("Sequential");
  double plane2[3];
  bool hasPlane2 = false;
  const Folded b = Fold(mesh, file + " (Sequential)", plane2, hasPlane2);
  vtkSMPTools::SetBackend("STDThread");
  Check(b.ok && b.stored == a.stored && b.height == a.height && b.leafIds == a.leafIds,
    file + ": Sequential and STDThread give the same tree");
}

/// Rotation nodes on against off: no more faces (at most `share` of the planes' faces), the
/// proved bound within the root epsilon, the same tree with both backends.
void TestRotationNodes(const std::string& dir, const std::string& file, double share)
{
  std::printf("%s, rotation nodes\n", file.c_str());
  vtkSmartPointer<vtkPolyData> mesh = Read(dir, file);
  if (!mesh)
    return;
  double plane[3];
  bool hasPlane = false;
  vtkSMPTools::SetBackend("STDThread");
  const Folded planes = Fold(mesh, file, plane, hasPlane);
  const Folded turned = Fold(mesh, file + " (rotation nodes)", plane, hasPlane, true);
  char text[256];
  std::snprintf(text,
    sizeof(text),
    "%s: %d faces stored with rotation nodes, %d with planes alone (at most %.2f of them)",
    file.c_str(),
    turned.stored,
    planes.stored,
    share);
  Check(planes.ok && turned.ok && turned.stored <= share * planes.stored, text);
  std::snprintf(text,
    sizeof(text),
    "%s: proved bound %g with rotation nodes, root epsilon %g",
    file.c_str(),
    turned.verifiedBound,
    turned.rootEpsilon);
  Check(turned.verifiedBound >= 0.0 && turned.verifiedBound <= turned.rootEpsilon, text);
  vtkSMPTools::SetBackend("Sequential");
  const Folded serial = Fold(mesh, file + " (rotation nodes, Sequential)", plane, hasPlane, true);
  vtkSMPTools::SetBackend("STDThread");
  Check(serial.ok && serial.stored == turned.stored && serial.leafIds == turned.leafIds,
    file + ": rotation nodes, Sequential and STDThread give the same tree");
}
}

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::printf("usage: TestFoldingTreeRealMeshes MESH_DIR\n");
    return 1;
  }
  const std::string dir = argv[1];
  // Paper's Table 1: dino 52.7%, table 73.7%, triceratops 56.8%.
  TestMesh(dir, "dino_cgal.off", 0.527, true);
  TestMesh(dir, "table_psb152.off", 0.737, true);
  TestMesh(dir, "triceratops_cgal.off", 0.568, true);
  TestMesh(dir, "anchor_cgal.off", 0.40, true);
  TestRotationNodes(dir, "queen_chess_quaddamage.obj", 1.0);
  TestRotationNodes(dir, "bearing_psb341.off", 0.75);
  TestRotationNodes(dir, "teapot_newell.obj", 0.99);
  std::printf(
    "%s\n", Failures ? "TestFoldingTreeRealMeshes FAILED" : "TestFoldingTreeRealMeshes passed");
  return Failures ? 1 : 0;
}
