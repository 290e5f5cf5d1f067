#include "vtkFoldingTreeUnfolder.h"

#include "vtkAbstractCellLocator.h"
#include "vtkCellLocatorFaceQuery.h"

#include "Core/FoldingTreeUnfolder.h"
#include "Core/SurfaceDistance.h"
#include "vtkFoldingArrays.h"
#include "vtkFoldingMeshesParallel.h"
#include "vtkFoldingTreeIO.h"
#include "vtkTriangleMeshAdapter.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTypeUInt64Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkVariant.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkFoldingTreeUnfolder);
vtkCxxSetObjectMacro(vtkFoldingTreeUnfolder, Controller, vtkMultiProcessController);
vtkCxxSetObjectMacro(vtkFoldingTreeUnfolder, Locator, vtkAbstractCellLocator);

namespace
{
/// HausdorffToOriginalBound is within this fraction of the original's diagonal of the true
/// Hausdorff distance (the branch and bound stops there).
constexpr double BoundTolerance = 1e-5;

using foldingmeshes::Vec3;

void AddValue(vtkFieldData* fd, const char* name, double value)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfTuples(1);
  a->SetValue(0, value);
  fd->AddArray(a);
}

/// Fills `out` (a vtkDataSetAttributes of n tuples) with the arrays `names` of the leaves
/// (leaf name, output name): tuple i comes from leaf leafOf[i], local tuple localOf[i]; vectors are
/// mapped by the linear map of copy copyOf[i].
void CarryArrays(const std::vector<std::pair<std::string, std::string>>& names,
  const std::vector<vtkPolyData*>& leaves,
  bool points,
  const std::vector<int>& leafOf,
  const std::vector<vtkIdType>& localOf,
  const std::vector<int>& copyOf,
  const std::vector<foldingmeshes::UnfoldCopy>& copies,
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
      !foldingmeshes::IsIdOrMaskArrayName(name.c_str());
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
        const foldingmeshes::UnfoldCopy& copy = copies[copyOf[i]];
        double v[3];
        data->GetTuple(i, v);
        const Vec3 w = copy.linear * Vec3(v[0], v[1], v[2]);
        data->SetTuple3(i, w.x(), w.y(), w.z());
      }
    }
    out->AddArray(array);
  }
}

}

//------------------------------------------------------------------------------
vtkFoldingTreeUnfolder::vtkFoldingTreeUnfolder()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(1);
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkFoldingTreeUnfolder::~vtkFoldingTreeUnfolder()
{
  this->SetController(nullptr);
  this->SetLocator(nullptr);
}

//------------------------------------------------------------------------------
int vtkFoldingTreeUnfolder::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  return 1;
}

//------------------------------------------------------------------------------
void vtkFoldingTreeUnfolder::SetOriginalData(vtkPolyData* original)
{
  if (original)
    this->SetInputData(1, original);
  else
    this->SetInputConnection(1, nullptr);
}

void vtkFoldingTreeUnfolder::SetOriginalConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
bool vtkFoldingTreeUnfolder::MeasureToOriginal(vtkPolyData* original, vtkPolyData* output)
{
  vtkIdType droppedVerts = 0, droppedLines = 0;
  foldingmeshes::TriangleMesh reference, unfolded;
  std::vector<Vec3> normals;
  std::string error;
  vtkSmartPointer<vtkPolyData> triangles =
    foldingmeshes::TriangulateSurface(original, droppedVerts, droppedLines, error);
  if (!triangles || !foldingmeshes::ToTriangleMesh(triangles, reference, normals, error) ||
    reference.triangles.empty())
  {
    vtkErrorMacro("The original (input port 1) has no usable surface"
      << (error.empty() ? std::string() : ": " + error) << ".");
    return false;
  }
  // Distances would be NaN or infinite: the builder rejects such a mesh, so does this.
  if (!foldingmeshes::CheckExtent(reference, error))
  {
    vtkErrorMacro("The original (input port 1) has no usable surface"
      << (error.empty() ? std::string() : ": " + error) << ".");
    return false;
  }
  unfolded.points.resize(output->GetNumberOfPoints());
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
    output->GetPoint(i, unfolded.points[i].data());
  vtkIdType n = 0;
  const vtkIdType* pts = nullptr;
  vtkCellArray* polys = output->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, pts);)
    unfolded.triangles.push_back(
      { static_cast<int>(pts[0]), static_cast<int>(pts[1]), static_cast<int>(pts[2]) });
  // Closest-face queries through a cell locator (vtkStaticCellLocator unless the user set one).
  const foldingmeshes::ClosestFaceQueryFactory locator =
    foldingmeshes::CellLocatorFaceQueryFactory(this->Locator);
  const foldingmeshes::SurfaceComparison c =
    foldingmeshes::CompareSurfaces(unfolded, reference, locator);

  vtkNew<vtkDoubleArray> distance;
  distance->SetName("DistanceToOriginal");
  distance->SetNumberOfTuples(output->GetNumberOfPoints());
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
    distance->SetValue(i, c.aPointDistances[i]);
  output->GetPointData()->AddArray(distance);

  double bounds[6];
  triangles->GetBounds(bounds);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  vtkFieldData* fd = output->GetFieldData();
  AddValue(fd, "HausdorffToOriginal", c.hausdorff);
  AddValue(fd, "MeanDistanceToOriginal", c.mean);
  AddValue(fd, "OriginalDiagonal", diagonal);
  AddValue(fd, "HausdorffToOriginalRelative", diagonal > 0 ? c.hausdorff / diagonal : 0.0);
  AddValue(fd, "MeanDistanceToOriginalRelative", diagonal > 0 ? c.mean / diagonal : 0.0);
  // Over every point of both surfaces, not only the samples: a proved upper bound.
  const foldingmeshes::HausdorffBounds proved =
    foldingmeshes::SymmetricHausdorffBounds(unfolded, reference, BoundTolerance * diagonal,
      foldingmeshes::DefaultMaximumEvaluations, 0.0, locator);
  if (!proved.converged)
    vtkWarningMacro("HausdorffToOriginalBound: the evaluation budget ran out before the bound "
                    "came within "
      << BoundTolerance << " of the diagonal; it is still an upper bound, only looser.");
  AddValue(fd, "HausdorffToOriginalBound", proved.upper);
  vtkNew<vtkStringArray> locatorName;
  locatorName->SetName("DistanceLocator");
  locatorName->InsertNextValue(this->Locator ? this->Locator->GetClassName() : "vtkStaticCellLocator");
  fd->AddArray(locatorName);
  AddValue(fd, "HausdorffToOriginalBoundRelative", diagonal > 0 ? proved.upper / diagonal : 0.0);
  this->HausdorffToOriginal = c.hausdorff;
  return true;
}

//------------------------------------------------------------------------------
int vtkFoldingTreeUnfolder::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  return foldingmeshes::RunWholeOnRoot(this,
    this->Controller,
    inputVector,
    outputVector,
    [&](vtkInformationVector** in) { return this->RequestWholeData(request, in, outputVector); },
    { { &this->OpenGapLength, &this->HausdorffToOriginal },
      { &this->OpenGapCount, &this->StitchedVertices, &this->OpenEdges },
      {} });
}

//------------------------------------------------------------------------------
int vtkFoldingTreeUnfolder::RequestWholeData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkMultiBlockDataSet* input = vtkMultiBlockDataSet::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->OpenGapCount = this->StitchedVertices = this->OpenEdges = 0;
  this->OpenGapLength = 0.0;
  this->HausdorffToOriginal = -1.0;
  if (!input || !output)
  {
    vtkErrorMacro("Missing input multiblock or output poly data.");
    return 0;
  }
  // NaN passes vtkSetClampMacro: check the floating-point parameters here.
  if (!std::isfinite(this->StitchToleranceScale) || !std::isfinite(this->SmoothingWeight) ||
    !std::isfinite(this->WeldToleranceScale) || !std::isfinite(this->HoleToleranceScale))
  {
    vtkErrorMacro("StitchToleranceScale, SmoothingWeight, WeldToleranceScale and "
                  "HoleToleranceScale must be finite numbers (they are "
      << this->StitchToleranceScale << ", " << this->SmoothingWeight << ", "
      << this->WeldToleranceScale << " and " << this->HoleToleranceScale << ").");
    return 0;
  }
  foldingmeshes::FoldingTree tree;
  std::vector<vtkPolyData*> leaves;
  std::string error;
  if (!foldingmeshes::MultiBlockToFoldingTree(input, tree, &leaves, error))
  {
    vtkErrorMacro("Malformed folding tree: " << error << ".");
    return 0;
  }
  int emptyLeaves = 0;
  for (int l : tree.Leaves())
    emptyLeaves += tree.nodes[l].mesh.triangles.empty() ? 1 : 0;
  if (emptyLeaves > 0)
  {
    vtkWarningMacro(<< emptyLeaves << " leaves of the tree store no triangles: their regions are "
                                      "missing from the output.");
  }

  foldingmeshes::UnfoldOptions options;
  options.stitch = this->Stitch;
  options.stitchToleranceScale = this->StitchToleranceScale;
  options.zipper = this->Zipper;
  options.fillSeamGaps = this->FillSeamGaps;
  options.smoothingIterations = this->SmoothingIterations;
  options.smoothingWeight = this->SmoothingWeight;
  options.respectErrorBudget = this->RespectErrorBudget;
  options.removeProjectedPoints = this->RemoveProjectedPoints;
  options.matchDiscardedDensity = this->MatchDiscardedDensity;
  options.weldBoundaries = this->WeldBoundaries;
  options.weldToleranceScale = this->WeldToleranceScale;
  options.closeHoles = this->CloseHoles;
  options.holeToleranceScale = this->HoleToleranceScale;
  options.maximumHoleEdges = this->MaximumHoleEdges;
  options.progress = [this](double p)
  {
    this->UpdateProgress(0.9 * p);
    return !this->GetAbortExecute();
  };
  foldingmeshes::UnfoldedMesh mesh;
  if (!foldingmeshes::UnfoldFoldingTree(tree, options, mesh, error))
  {
    vtkErrorMacro("Could not unfold the folding tree: " << error << ".");
    return 0;
  }
  if (mesh.aborted)
  {
    vtkWarningMacro("Unfolding aborted.");
    return 1;
  }

  // The "Tree" block (validated above): what the builder recorded of its input.
  vtkPolyData* infoBlock = vtkPolyData::SafeDownCast(input->GetBlock(1));
  vtkFieldData* info = infoBlock ? infoBlock->GetFieldData() : nullptr;
  vtkNew<vtkFieldData> noInfo;
  if (!info)
    info = noInfo;

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

  // Where every output point / face takes its leaf attributes from.
  const int nn = tree.NumberOfNodes();
  std::vector<std::unordered_map<int, vtkIdType>> pointOf(nn), faceOf(nn);
  std::unordered_map<int, std::pair<int, vtkIdType>> anyPoint;
  for (int l = 0; l < nn; ++l)
  {
    const foldingmeshes::FoldingLeafMesh& m = tree.nodes[l].mesh;
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
        vtkErrorMacro("Unfolded point " << i << " has an original id found in no leaf.");
        return 0;
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
      vtkErrorMacro("Unfolded face " << f << " has an original id not found in its leaf.");
      return 0;
    }
    faceLeaf[f] = leaf;
    faceLocal[f] = it->second;
    faceCopy[f] = mesh.faceCopy[f];
  }
  // The leaves' arrays, renamed where the unfolder writes an array of the same name (only in
  // trees not written by this builder, which renames such input arrays itself).
  int unnamed[2] = { 0, 0 };
  std::vector<std::pair<std::string, std::string>> carried[2];
  for (int points = 0; points < 2; ++points)
  {
    const std::vector<std::string>& own =
      points ? foldingmeshes::UnfoldedPointArrayNames() : foldingmeshes::UnfoldedCellArrayNames();
    const std::vector<std::string> names =
      foldingmeshes::CommonLeafArrays(leaves, points != 0, unnamed[points]);
    for (const std::string& name : names)
    {
      std::string as = name;
      if (std::find(own.begin(), own.end(), name) != own.end())
      {
        std::vector<std::string> avoid(own);
        avoid.insert(avoid.end(), names.begin(), names.end());
        as = foldingmeshes::FreeInputName(nullptr, name, avoid);
        vtkWarningMacro("The leaves' " << (points ? "point" : "cell") << " array " << name
                                       << " is carried as " << as
                                       << " (the name is the unfolder's).");
      }
      carried[points].emplace_back(name, as);
    }
  }
  if (unnamed[0] + unnamed[1] > 0)
    vtkWarningMacro("Unnamed leaf arrays are not carried (" << unnamed[0] << " point, "
                                                            << unnamed[1] << " cell arrays).");
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
  foldingmeshes::ApplyActiveAttributes(output->GetPointData(),
    foldingmeshes::RecordedAttributes(info, "InputPointAttributes", leaves, true));
  foldingmeshes::ApplyActiveAttributes(output->GetCellData(),
    foldingmeshes::RecordedAttributes(info, "InputCellAttributes", leaves, false));

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

  vtkFieldData* fd = output->GetFieldData();
  AddValue(fd, "UnfoldedFaces", static_cast<double>(nf));
  AddValue(fd, "UnfoldedPoints", static_cast<double>(np));
  AddValue(fd, "NumberOfCopies", static_cast<double>(mesh.copies.size()));
  AddValue(fd, "PlaneMergedVertices", mesh.planeMergedVertices);
  AddValue(fd, "RemovedProjectedPoints", mesh.removedProjectedPoints);
  AddValue(fd, "ProjectedPoints", mesh.projectedPoints);
  AddValue(fd, "ThinnedCopyPoints", mesh.thinnedCopyPoints);
  AddValue(fd, "FoldExcessFaces", mesh.foldExcessFaces);
  AddValue(fd, "StitchedVertices", mesh.stitchedVertices);
  AddValue(fd, "UnmatchedTearVertices", mesh.unmatchedTearVertices);
  AddValue(fd, "OpenGapCount", mesh.gapEdges);
  AddValue(fd, "OpenGapLength", mesh.gapLength);
  AddValue(fd, "FilledFaces", mesh.filledFaces);
  AddValue(fd, "OpenEdges", mesh.openEdges);
  AddValue(fd, "NonManifoldEdges", mesh.nonManifoldEdges);
  AddValue(fd, "MisorientedEdges", mesh.misorientedEdges);
  AddValue(fd, "WeldedVertices", mesh.weld.stitchedVertices);
  AddValue(fd, "BudgetRejectedClusters", mesh.budgetRejectedClusters);
  AddValue(fd, "RepairDroppedFaces", mesh.repair.droppedFaces);
  AddValue(fd, "RepairFlippedFaces", mesh.repair.flippedFaces);
  AddValue(fd, "FilledLoops", mesh.repair.filledLoops);
  AddValue(fd, "BorderLoops", mesh.repair.borderLoops);
  AddValue(fd, "BorderEdges", mesh.repair.borderEdges);
  AddValue(fd, "BorderLength", mesh.repair.borderLength);
  AddValue(fd, "OpenLoops", mesh.repair.openLoops);
  AddValue(fd, "OpenLoopEdges", mesh.repair.openEdges);
  AddValue(fd, "OpenLoopLength", mesh.repair.openLength);
  AddValue(fd, "UnknownBorderLoops", mesh.repair.unknownLoops);
  AddValue(fd, "RootEpsilon", tree.rootEpsilon);
  AddValue(fd, "Diagonal", tree.diagonal);

  this->OpenGapCount = mesh.gapEdges;
  this->OpenGapLength = mesh.gapLength;
  this->StitchedVertices = mesh.stitchedVertices;
  this->OpenEdges = mesh.openEdges;
  if (vtkPolyData* original = vtkPolyData::GetData(inputVector[1], 0))
    if (!this->MeasureToOriginal(original, output))
      return 0;

  // The input's field arrays, stored on the "Tree" block with a prefix; renamed where the
  // unfolder's own field data has the name.
  const std::string prefix = foldingmeshes::InputFieldPrefix;
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
      as = foldingmeshes::FreeInputName(fd, name);
      vtkWarningMacro("The input's field array " << name << " is restored as " << as
                                                 << " (the name is the unfolder's).");
    }
    vtkSmartPointer<vtkAbstractArray> copy = vtk::TakeSmartPointer(stored->NewInstance());
    copy->DeepCopy(stored);
    copy->SetName(as.c_str());
    fd->AddArray(copy);
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkFoldingTreeUnfolder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "Locator: " << this->Locator << "\n";
  os << indent << "Stitch: " << this->Stitch << "\n";
  os << indent << "StitchToleranceScale: " << this->StitchToleranceScale << "\n";
  os << indent << "Zipper: " << this->Zipper << "\n";
  os << indent << "FillSeamGaps: " << this->FillSeamGaps << "\n";
  os << indent << "SmoothingIterations: " << this->SmoothingIterations << "\n";
  os << indent << "SmoothingWeight: " << this->SmoothingWeight << "\n";
  os << indent << "RespectErrorBudget: " << this->RespectErrorBudget << "\n";
  os << indent << "RemoveProjectedPoints: " << this->RemoveProjectedPoints << "\n";
  os << indent << "MatchDiscardedDensity: " << this->MatchDiscardedDensity << "\n";
  os << indent << "WeldBoundaries: " << this->WeldBoundaries << "\n";
  os << indent << "WeldToleranceScale: " << this->WeldToleranceScale << "\n";
  os << indent << "CloseHoles: " << this->CloseHoles << "\n";
  os << indent << "HoleToleranceScale: " << this->HoleToleranceScale << "\n";
  os << indent << "MaximumHoleEdges: " << this->MaximumHoleEdges << "\n";
  os << indent << "OpenGapCount: " << this->OpenGapCount << "\n";
  os << indent << "OpenGapLength: " << this->OpenGapLength << "\n";
  os << indent << "StitchedVertices: " << this->StitchedVertices << "\n";
  os << indent << "OpenEdges: " << this->OpenEdges << "\n";
  os << indent << "HausdorffToOriginal: " << this->HausdorffToOriginal << "\n";
}
