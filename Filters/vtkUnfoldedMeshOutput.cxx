#include "vtkUnfoldedMeshOutput.h"

#include "vtkFoldingArrays.h"
#include "vtkFoldingTreeIO.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTypeUInt64Array.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <unordered_map>
#include <utility>

namespace foldingmeshes
{
namespace
{
/// Fills `out` (a vtkDataSetAttributes of n tuples) with the arrays `names` of the leaves
/// (leaf name, output name): tuple i comes from leaf leafOf[i], local tuple localOf[i]; vectors are
/// mapped by the linear map of copy copyOf[i].
void CarryArrays(const std::vector<std::pair<std::string, std::string>>& names,
  const std::vector<vtkPolyData*>& leaves,
  bool points,
  const std::vector<int>& leafOf,
  const std::vector<vtkIdType>& localOf,
  const std::vector<int>& copyOf,
  const std::vector<UnfoldCopy>& copies,
  vtkDataSetAttributes* out)
{
  const vtkIdType n = static_cast<vtkIdType>(leafOf.size());
  auto attributes = [points](vtkPolyData* pd) -> vtkDataSetAttributes*
  {
    return points ? static_cast<vtkDataSetAttributes*>(pd->GetPointData())
                  : static_cast<vtkDataSetAttributes*>(pd->GetCellData());
  };
  vtkPolyData* first = nullptr;
  for (vtkPolyData* leaf : leaves)
    if (leaf && !first)
      first = leaf;
  if (!first)
    return;
  for (const auto& pair : names)
  {
    const std::string& name = pair.first;
    vtkAbstractArray* ref = attributes(first)->GetAbstractArray(name.c_str());
    vtkSmartPointer<vtkAbstractArray> array = vtk::TakeSmartPointer(ref->NewInstance());
    array->SetName(pair.second.c_str());
    array->SetNumberOfComponents(ref->GetNumberOfComponents());
    for (int c = 0; c < ref->GetNumberOfComponents(); ++c)
      if (ref->GetComponentName(c))
        array->SetComponentName(c, ref->GetComponentName(c));
    array->SetNumberOfTuples(n);
    vtkDataArray* data = vtkDataArray::SafeDownCast(array);
    const bool vector = data && data->GetNumberOfComponents() == 3 &&
      (data->GetDataType() == VTK_FLOAT || data->GetDataType() == VTK_DOUBLE) &&
      !IsIdOrMaskArrayName(name.c_str());
    std::vector<vtkAbstractArray*> sources(leaves.size(), nullptr);
    for (size_t l = 0; l < leaves.size(); ++l)
      if (leaves[l])
        sources[l] = attributes(leaves[l])->GetAbstractArray(name.c_str());
    for (vtkIdType i = 0; i < n; ++i)
    {
      vtkAbstractArray* source = sources[leafOf[i]];
      array->SetTuple(i, localOf[i], source);
      if (vector)
      {
        const UnfoldCopy& copy = copies[copyOf[i]];
        double v[3];
        data->GetTuple(i, v);
        const Vec3 w = copy.linear * Vec3(v[0], v[1], v[2]);
        data->SetTuple3(i, w.x(), w.y(), w.z());
      }
    }
    out->AddArray(array);
  }
}

/// The leaves' common named arrays as (leaf name, output name) pairs, cell arrays in
/// carried[0], point arrays in carried[1]: renamed, with a warning, where the unfolder writes an
/// array of the same name (only in trees not written by this builder, which renames such input
/// arrays itself).
void CarriedArrayNames(const std::vector<vtkPolyData*>& leaves,
  vtkObject* warner,
  std::vector<std::pair<std::string, std::string>> carried[2])
{
  int unnamed[2] = { 0, 0 };
  for (int points = 0; points < 2; ++points)
  {
    const std::vector<std::string>& own =
      points ? UnfoldedPointArrayNames() : UnfoldedCellArrayNames();
    const std::vector<std::string> names = CommonLeafArrays(leaves, points != 0, unnamed[points]);
    for (const std::string& name : names)
    {
      std::string as = name;
      if (std::find(own.begin(), own.end(), name) != own.end())
      {
        std::vector<std::string> avoid(own);
        avoid.insert(avoid.end(), names.begin(), names.end());
        as = FreeInputName(nullptr, name, avoid);
        vtkWarningWithObjectMacro(warner,
          "The leaves' " << (points ? "point" : "cell") << " array " << name << " is carried as "
                         << as << " (the name is the unfolder's).");
      }
      carried[points].emplace_back(name, as);
    }
  }
  if (unnamed[0] + unnamed[1] > 0)
    vtkWarningWithObjectMacro(warner,
      "Unnamed leaf arrays are not carried (" << unnamed[0] << " point, " << unnamed[1]
                                              << " cell arrays).");
}
}

void AddFieldValue(vtkFieldData* fd, const char* name, double value)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfTuples(1);
  a->SetValue(0, value);
  fd->AddArray(a);
}

void SetUnfoldedGeometry(const UnfoldedMesh& mesh, vtkFieldData* info, vtkPolyData* output)
{
  const vtkIdType np = mesh.NumberOfPoints();
  const vtkIdType nf = mesh.NumberOfFaces();
  vtkNew<vtkPoints> points;
  // The input's precision (float or double; trees without the record: double).
  vtkDataArray* pointsType =
    vtkDataArray::SafeDownCast(info->GetAbstractArray("InputPointsDataType"));
  points->SetDataType(
    pointsType && pointsType->GetNumberOfTuples() == 1 && pointsType->GetTuple1(0) == VTK_FLOAT
      ? VTK_FLOAT
      : VTK_DOUBLE);
  points->SetNumberOfPoints(np);
  for (vtkIdType i = 0; i < np; ++i)
    points->SetPoint(i, mesh.points[i].data());
  output->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(nf, 3 * nf);
  for (const auto& t : mesh.triangles)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    polys->InsertNextCell(3, ids);
  }
  output->SetPolys(polys);
}

bool CarryLeafArrays(const FoldingTree& tree,
  const std::vector<vtkPolyData*>& leaves,
  const UnfoldedMesh& mesh,
  vtkFieldData* info,
  vtkPolyData* output,
  vtkObject* warner,
  std::string& error)
{
  const vtkIdType np = mesh.NumberOfPoints();
  const vtkIdType nf = mesh.NumberOfFaces();
  // Where every output point / face takes its leaf attributes from.
  const int nn = tree.NumberOfNodes();
  std::vector<std::unordered_map<int, vtkIdType>> pointOf(nn), faceOf(nn);
  std::unordered_map<int, std::pair<int, vtkIdType>> anyPoint;
  for (int l = 0; l < nn; ++l)
  {
    const FoldingLeafMesh& m = tree.nodes[l].mesh;
    for (int i = m.NumberOfPoints() - 1; i >= 0; --i) // the first one wins
    {
      pointOf[l][m.originalPointIds[i]] = i;
      anyPoint[m.originalPointIds[i]] = { l, i };
    }
    for (int f = m.NumberOfFaces() - 1; f >= 0; --f)
      faceOf[l][m.originalFaceIds[f]] = f;
  }
  std::vector<int> pointLeaf(np), pointCopy(np), faceLeaf(nf), faceCopy(nf);
  std::vector<vtkIdType> pointLocal(np), faceLocal(nf);
  for (vtkIdType i = 0; i < np; ++i)
  {
    const int copy = mesh.pointCopy[i];
    int leaf = mesh.copies[copy].leaf;
    auto it = pointOf[leaf].find(mesh.pointOriginalIds[i]);
    vtkIdType local = 0;
    if (it != pointOf[leaf].end())
      local = it->second;
    else
    {
      auto any = anyPoint.find(mesh.pointOriginalIds[i]);
      if (any == anyPoint.end())
      {
        error = "unfolded point " + std::to_string(i) + " has an original id found in no leaf";
        return false;
      }
      leaf = any->second.first;
      local = any->second.second;
    }
    pointLeaf[i] = leaf;
    pointLocal[i] = local;
    pointCopy[i] = copy;
  }
  for (vtkIdType f = 0; f < nf; ++f)
  {
    const int leaf = mesh.faceLeaf[f];
    auto it = faceOf[leaf].find(mesh.faceOriginalIds[f]);
    if (it == faceOf[leaf].end())
    {
      error = "unfolded face " + std::to_string(f) + " has an original id not found in its leaf";
      return false;
    }
    faceLeaf[f] = leaf;
    faceLocal[f] = it->second;
    faceCopy[f] = mesh.faceCopy[f];
  }
  std::vector<std::pair<std::string, std::string>> carried[2];
  CarriedArrayNames(leaves, warner, carried);
  CarryArrays(carried[1],
    leaves,
    true,
    pointLeaf,
    pointLocal,
    pointCopy,
    mesh.copies,
    output->GetPointData());
  CarryArrays(
    carried[0], leaves, false, faceLeaf, faceLocal, faceCopy, mesh.copies, output->GetCellData());
  ApplyActiveAttributes(
    output->GetPointData(), RecordedAttributes(info, "InputPointAttributes", leaves, true));
  ApplyActiveAttributes(
    output->GetCellData(), RecordedAttributes(info, "InputCellAttributes", leaves, false));

  return true;
}

void AddUnfoldingArrays(const UnfoldedMesh& mesh, vtkPolyData* output)
{
  const vtkIdType np = mesh.NumberOfPoints();
  const vtkIdType nf = mesh.NumberOfFaces();
  vtkNew<vtkIdTypeArray> pointIds, cellIds;
  pointIds->SetName("OriginalPointId");
  pointIds->SetNumberOfTuples(np);
  for (vtkIdType i = 0; i < np; ++i)
    pointIds->SetValue(i, mesh.pointOriginalIds[i]);
  output->GetPointData()->AddArray(pointIds);
  cellIds->SetName("OriginalCellId");
  cellIds->SetNumberOfTuples(nf);
  vtkNew<vtkIntArray> leafId, copyId;
  vtkNew<vtkUnsignedCharArray> mirrored, filled;
  leafId->SetName("FoldingLeafId");
  copyId->SetName("FoldingCopy");
  mirrored->SetName("FoldingMirrored");
  filled->SetName("FoldingFilled");
  leafId->SetNumberOfTuples(nf);
  copyId->SetNumberOfTuples(nf);
  mirrored->SetNumberOfTuples(nf);
  filled->SetNumberOfTuples(nf);
  // FoldingCopy numbers the copies of each leaf by increasing mirror mask (0 = the stored
  // leaf itself, mask 0).
  std::vector<int> copyRank(mesh.copies.size(), 0);
  for (size_t c = 0; c < mesh.copies.size(); ++c)
    for (size_t d = 0; d < mesh.copies.size(); ++d)
      if (mesh.copies[d].leaf == mesh.copies[c].leaf &&
        (mesh.copies[d].mirrorMask < mesh.copies[c].mirrorMask ||
          (mesh.copies[d].mirrorMask == mesh.copies[c].mirrorMask && d < c)))
        ++copyRank[c];
  vtkNew<vtkTypeUInt64Array> mirrorMask;
  mirrorMask->SetName("FoldingMirrorMask");
  mirrorMask->SetNumberOfTuples(nf);
  for (vtkIdType f = 0; f < nf; ++f)
  {
    cellIds->SetValue(f, mesh.faceOriginalIds[f]);
    leafId->SetValue(f, mesh.faceLeaf[f]);
    copyId->SetValue(f, copyRank[mesh.faceCopy[f]]);
    mirrorMask->SetValue(f, mesh.copies[mesh.faceCopy[f]].mirrorMask);
    mirrored->SetValue(f, mesh.faceMirrored[f] ? 1 : 0);
    filled->SetValue(f, f < static_cast<vtkIdType>(mesh.faceFilled.size()) && mesh.faceFilled[f]);
  }
  output->GetCellData()->AddArray(cellIds);
  output->GetCellData()->AddArray(leafId);
  // Viewers colour the unfolded mesh by leaf, as the builder's segmentation output: the
  // input's scalars stay as arrays, but are not the active ones (ParaView prefers active
  // point scalars over cell scalars).
  output->GetCellData()->SetActiveScalars("FoldingLeafId");
  output->GetPointData()->SetActiveScalars(nullptr);
  output->GetCellData()->AddArray(copyId);
  output->GetCellData()->AddArray(mirrored);
  output->GetCellData()->AddArray(mirrorMask);
  output->GetCellData()->AddArray(filled);
}

void AddUnfoldingSummary(const UnfoldedMesh& mesh, const FoldingTree& tree, vtkFieldData* fd)
{
  const vtkIdType np = mesh.NumberOfPoints();
  const vtkIdType nf = mesh.NumberOfFaces();
  AddFieldValue(fd, "UnfoldedFaces", static_cast<double>(nf));
  AddFieldValue(fd, "UnfoldedPoints", static_cast<double>(np));
  // The surface area against the input's (the tree's OriginalArea): above 1 where the
  // unfolding laid surface twice (overlapping copies, fills over existing faces), below where
  // it left gaps - what the Hausdorff distance cannot see.
  // FilledAreaRatio: the share of it in faces the unfolder added to close seam gaps and holes
  // (FoldingFilled), over the input's area - over the 29 shared meshes 55% of the excess.
  double area = 0.0, filledArea = 0.0;
  for (size_t f = 0; f < mesh.triangles.size(); ++f)
  {
    const auto& t = mesh.triangles[f];
    const double a = 0.5 *
      (mesh.points[t[1]] - mesh.points[t[0]]).cross(mesh.points[t[2]] - mesh.points[t[0]]).norm();
    area += a;
    if (f < mesh.faceFilled.size() && mesh.faceFilled[f])
      filledArea += a;
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  AddFieldValue(fd, "UnfoldedArea", area);
  AddFieldValue(fd, "AreaRatio", tree.originalArea > 0.0 ? area / tree.originalArea : nan);
  AddFieldValue(
    fd, "FilledAreaRatio", tree.originalArea > 0.0 ? filledArea / tree.originalArea : nan);
  AddFieldValue(fd, "NumberOfCopies", static_cast<double>(mesh.copies.size()));
  AddFieldValue(fd, "PlaneMergedVertices", mesh.planeMergedVertices);
  AddFieldValue(fd, "RemovedProjectedPoints", mesh.removedProjectedPoints);
  AddFieldValue(fd, "ProjectedPoints", mesh.projectedPoints);
  AddFieldValue(fd, "ThinnedCopyPoints", mesh.thinnedCopyPoints);
  AddFieldValue(fd, "FoldExcessFaces", mesh.foldExcessFaces);
  AddFieldValue(fd, "StitchedVertices", mesh.stitchedVertices);
  AddFieldValue(fd, "UnmatchedTearVertices", mesh.unmatchedTearVertices);
  AddFieldValue(fd, "OpenGapCount", mesh.gapEdges);
  AddFieldValue(fd, "OpenGapLength", mesh.gapLength);
  AddFieldValue(fd, "FilledFaces", mesh.filledFaces);
  AddFieldValue(fd, "OpenEdges", mesh.openEdges);
  AddFieldValue(fd, "NonManifoldEdges", mesh.nonManifoldEdges);
  AddFieldValue(fd, "MisorientedEdges", mesh.misorientedEdges);
  AddFieldValue(fd, "WeldedVertices", mesh.weld.stitchedVertices);
  AddFieldValue(fd, "BudgetRejectedClusters", mesh.budgetRejectedClusters);
  AddFieldValue(fd, "RepairDroppedFaces", mesh.repair.droppedFaces);
  AddFieldValue(fd, "RepairFlippedFaces", mesh.repair.flippedFaces);
  AddFieldValue(fd, "FilledLoops", mesh.repair.filledLoops);
  AddFieldValue(fd, "BorderLoops", mesh.repair.borderLoops);
  AddFieldValue(fd, "BorderEdges", mesh.repair.borderEdges);
  AddFieldValue(fd, "BorderLength", mesh.repair.borderLength);
  AddFieldValue(fd, "OpenLoops", mesh.repair.openLoops);
  AddFieldValue(fd, "OpenLoopEdges", mesh.repair.openEdges);
  AddFieldValue(fd, "OpenLoopLength", mesh.repair.openLength);
  AddFieldValue(fd, "UnknownBorderLoops", mesh.repair.unknownLoops);
  AddFieldValue(fd, "RootEpsilon", tree.rootEpsilon);
  AddFieldValue(fd, "Diagonal", tree.diagonal);
}

void RestoreInputFieldArrays(vtkFieldData* info, vtkFieldData* fd, vtkObject* warner)
{
  // The input's field arrays, stored on the "Tree" block with a prefix; renamed where the
  // unfolder's own field data has the name.
  const std::string prefix = InputFieldPrefix;
  for (int a = 0; a < info->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* stored = info->GetAbstractArray(a);
    if (!stored || !stored->GetName() ||
      std::strncmp(stored->GetName(), prefix.c_str(), prefix.size()) != 0)
      continue;
    const std::string name = stored->GetName() + prefix.size();
    std::string as = name;
    if (fd->GetAbstractArray(name.c_str()))
    {
      as = FreeInputName(fd, name);
      vtkWarningWithObjectMacro(warner,
        "The input's field array " << name << " is restored as " << as
                                   << " (the name is the unfolder's).");
    }
    vtkSmartPointer<vtkAbstractArray> copy = vtk::TakeSmartPointer(stored->NewInstance());
    copy->DeepCopy(stored);
    copy->SetName(as.c_str());
    fd->AddArray(copy);
  }
}
}
