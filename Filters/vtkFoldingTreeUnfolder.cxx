#include "vtkFoldingTreeUnfolder.h"

#include "vtkAbstractCellLocator.h"
#include "vtkCellLocatorFaceQuery.h"

#include "Core/FoldingTreeUnfolder.h"
#include "Core/SurfaceDistance.h"
#include "vtkFoldingArrays.h"
#include "vtkFoldingDebugTrace.h"
#include "vtkFoldingMeshesParallel.h"
#include "vtkFoldingTreeIO.h"
#include "vtkParameterChecks.h"
#include "vtkTriangleMeshAdapter.h"
#include "vtkUnfoldedMeshOutput.h"

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

/// The filter's parameters as the core's options; progress goes to 90% of the filter's bar.
foldingmeshes::UnfoldOptions UnfoldOptionsOf(vtkFoldingTreeUnfolder* self)
{
  foldingmeshes::UnfoldOptions options;
  options.stitch = self->GetStitch();
  options.stitchToleranceScale = self->GetStitchToleranceScale();
  options.zipper = self->GetZipper();
  options.fillSeamGaps = self->GetFillSeamGaps();
  options.smoothingIterations = self->GetSmoothingIterations();
  options.smoothingWeight = self->GetSmoothingWeight();
  options.respectErrorBudget = self->GetRespectErrorBudget();
  options.removeProjectedPoints = self->GetRemoveProjectedPoints();
  options.matchDiscardedDensity = self->GetMatchDiscardedDensity();
  options.weldBoundaries = self->GetWeldBoundaries();
  options.weldToleranceScale = self->GetWeldToleranceScale();
  options.closeHoles = self->GetCloseHoles();
  options.holeToleranceScale = self->GetHoleToleranceScale();
  options.maximumHoleEdges = self->GetMaximumHoleEdges();
  options.trace = foldingmeshes::DebugTrace(self);
  options.progress = [self](double p)
  {
    self->UpdateProgress(0.9 * p);
    return !self->GetAbortExecute();
  };
  return options;
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
  foldingmeshes::AddFieldValue(fd, "HausdorffToOriginal", c.hausdorff);
  foldingmeshes::AddFieldValue(fd, "MeanDistanceToOriginal", c.mean);
  foldingmeshes::AddFieldValue(fd, "OriginalDiagonal", diagonal);
  foldingmeshes::AddFieldValue(
    fd, "HausdorffToOriginalRelative", diagonal > 0 ? c.hausdorff / diagonal : 0.0);
  foldingmeshes::AddFieldValue(
    fd, "MeanDistanceToOriginalRelative", diagonal > 0 ? c.mean / diagonal : 0.0);
  // Over every point of both surfaces, not only the samples: a proved upper bound.
  const foldingmeshes::HausdorffBounds proved = foldingmeshes::SymmetricHausdorffBounds(unfolded,
    reference,
    BoundTolerance * diagonal,
    foldingmeshes::DefaultMaximumEvaluations,
    0.0,
    locator);
  if (!proved.converged)
    vtkWarningMacro("HausdorffToOriginalBound: the evaluation budget ran out before the bound "
                    "came within "
      << BoundTolerance << " of the diagonal; it is still an upper bound, only looser.");
  foldingmeshes::AddFieldValue(fd, "HausdorffToOriginalBound", proved.upper);
  vtkNew<vtkStringArray> locatorName;
  locatorName->SetName("DistanceLocator");
  locatorName->InsertNextValue(
    this->Locator ? this->Locator->GetClassName() : "vtkStaticCellLocator");
  fd->AddArray(locatorName);
  foldingmeshes::AddFieldValue(
    fd, "HausdorffToOriginalBoundRelative", diagonal > 0 ? proved.upper / diagonal : 0.0);
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
  std::string error;
  if (!foldingmeshes::CheckParameters({},
        { { "StitchToleranceScale", this->StitchToleranceScale },
          { "SmoothingWeight", this->SmoothingWeight },
          { "WeldToleranceScale", this->WeldToleranceScale },
          { "HoleToleranceScale", this->HoleToleranceScale } },
        error))
  {
    vtkErrorMacro(<< error << ".");
    return 0;
  }
  foldingmeshes::FoldingTree tree;
  std::vector<vtkPolyData*> leaves;
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
    vtkWarningMacro(<< emptyLeaves
                    << " leaves of the tree store no triangles: their regions are "
                       "missing from the output.");
  }

  const foldingmeshes::UnfoldOptions options = UnfoldOptionsOf(this);
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

  // The output: geometry, the user's arrays, the unfolder's arrays, the summary, the distances
  // to the Original input (when given), the input's field arrays.
  foldingmeshes::SetUnfoldedGeometry(mesh, info, output);
  if (!foldingmeshes::CarryLeafArrays(tree, leaves, mesh, info, output, this, error))
  {
    vtkErrorMacro("Could not carry the leaves' arrays: " << error << ".");
    return 0;
  }
  foldingmeshes::AddUnfoldingArrays(mesh, output);
  foldingmeshes::AddUnfoldingSummary(mesh, tree, output->GetFieldData());
  this->OpenGapCount = mesh.gapEdges;
  this->OpenGapLength = mesh.gapLength;
  this->StitchedVertices = mesh.stitchedVertices;
  this->OpenEdges = mesh.openEdges;
  if (vtkPolyData* original = vtkPolyData::GetData(inputVector[1], 0))
    if (!this->MeasureToOriginal(original, output))
      return 0;
  foldingmeshes::RestoreInputFieldArrays(info, output->GetFieldData(), this);
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
