#include "vtkFoldingTreeBuilder.h"

#include "Core/FoldingSegmentation.h"
#include "Core/FoldingTreeBuilder.h"
#include "vtkCellLocatorFaceQuery.h"
#include "vtkFoldingArrays.h"
#include "vtkFoldingDebugTrace.h"
#include "vtkFoldingMeshesParallel.h"
#include "vtkFoldingTreeIO.h"
#include "vtkParameterChecks.h"
#include "vtkTriangleMeshAdapter.h"

#include <vtkAbstractCellLocator.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkFoldingTreeBuilder);
vtkCxxSetObjectMacro(vtkFoldingTreeBuilder, Controller, vtkMultiProcessController);
vtkCxxSetObjectMacro(vtkFoldingTreeBuilder, Locator, vtkAbstractCellLocator);

namespace
{
/// The filter's parameters as the core's options; progress goes to 95% of the filter's bar.
foldingmeshes::FoldingTreeOptions FoldingTreeOptionsOf(vtkFoldingTreeBuilder* self, double epsilon)
{
  foldingmeshes::FoldingTreeOptions options;
  options.epsilon = epsilon;
  options.symmetry.robust = self->GetMethod() == vtkFoldingTreeBuilder::ROBUST;
  options.symmetry.seed = static_cast<unsigned>(self->GetRandomSeed());
  options.sampledSearchAboveFaces = self->GetSampledSearchAboveFaces();
  options.useMinimumFaces = self->GetUseMinimumFaces();
  options.minimumFaces = self->GetMinimumFaces();
  options.useMinimumAreaFraction = self->GetUseMinimumAreaFraction();
  options.minimumAreaFraction = self->GetMinimumAreaFraction();
  options.useMaximumFolds = self->GetUseMaximumFolds();
  options.maximumFolds = self->GetMaximumFolds();
  options.requireMeaningfulSymmetry = self->GetRequireMeaningfulSymmetry();
  options.requireTightSymmetry = self->GetRequireTightSymmetry();
  options.verifyBound = self->GetVerifyBound();
  if (self->GetLocator()) // else the core's face tree: the same distances, 1.4-2x faster builds
    options.verificationQueries = foldingmeshes::CellLocatorFaceQueryFactory(self->GetLocator());
  options.keepSide = self->GetKeepSide() == vtkFoldingTreeBuilder::FEWER_FACES
    ? foldingmeshes::KeepSide::FewerFaces
    : foldingmeshes::KeepSide::MoreFaces;
  options.connectNearbyParts = self->GetConnectNearbyParts();
  options.rotationNodes = self->GetRotationNodes() == vtkFoldingTreeBuilder::ROTATION_NODES_ON;
  options.rotationNodesWhenAxial =
    self->GetRotationNodes() == vtkFoldingTreeBuilder::ROTATION_NODES_WHEN_AXIAL;
  options.maximumRotationOrder = self->GetMaximumRotationOrder();
  options.trace = foldingmeshes::DebugTrace(self);
  options.progress = [self](double p)
  {
    self->UpdateProgress(0.95 * p);
    return !self->GetAbortExecute();
  };
  return options;
}

/// The builder's arrays on the segmentation output (the triangulated input): FoldingLeafId
/// (active scalars), FoldingDepth and FoldingRole per face. Input arrays of these names are
/// renamed, with a warning through `warner`.
void AddSegmentationArrays(const foldingmeshes::FoldingTree& folding,
  const foldingmeshes::TriangleMesh& soup,
  vtkPolyData* segmentation,
  vtkObject* warner)
{
  std::vector<std::string> renamed;
  foldingmeshes::RenameReservedArrays(
    segmentation->GetCellData(), { "FoldingLeafId", "FoldingDepth", "FoldingRole" }, renamed);
  for (const std::string& r : renamed)
    vtkWarningWithObjectMacro(warner,
      "Segmentation output: the input's cell array " << r << " (the name is the builder's).");
  const vtkIdType nf = segmentation->GetNumberOfCells();
  vtkNew<vtkIntArray> leafId, depth, role;
  leafId->SetName("FoldingLeafId");
  depth->SetName("FoldingDepth");
  role->SetName("FoldingRole");
  for (vtkIntArray* a : { leafId.GetPointer(), depth.GetPointer(), role.GetPointer() })
  {
    a->SetNumberOfTuples(nf);
    a->FillValue(-1);
  }
  const foldingmeshes::FoldingSegmentation labels =
    foldingmeshes::LabelFacesByLeaf(folding, soup.points, soup.triangles);
  for (vtkIdType f = 0; f < nf && f < static_cast<vtkIdType>(labels.leaf.size()); ++f)
  {
    leafId->SetValue(f, labels.leaf[f]);
    depth->SetValue(f, labels.depth[f]);
    role->SetValue(f, labels.role[f]);
  }
  segmentation->GetCellData()->AddArray(leafId);
  segmentation->GetCellData()->AddArray(depth);
  segmentation->GetCellData()->AddArray(role);
  segmentation->GetCellData()->SetActiveScalars("FoldingLeafId");
  // Viewers colour by active point scalars before cell scalars: keep the input's point
  // scalars (e.g. COFF Colors) as plain arrays so the leaves are what is shown.
  segmentation->GetPointData()->SetActiveScalars(nullptr);
}
}

//------------------------------------------------------------------------------
vtkFoldingTreeBuilder::vtkFoldingTreeBuilder()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(2);
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkFoldingTreeBuilder::~vtkFoldingTreeBuilder()
{
  this->SetController(nullptr);
  this->SetLocator(nullptr);
}

//------------------------------------------------------------------------------
int vtkFoldingTreeBuilder::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkFoldingTreeBuilder::FillOutputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkMultiBlockDataSet");
    return 1;
  }
  return this->Superclass::FillOutputPortInformation(port, info);
}

//------------------------------------------------------------------------------
int vtkFoldingTreeBuilder::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  return foldingmeshes::RunWholeOnRoot(this,
    this->Controller,
    inputVector,
    outputVector,
    [&](vtkInformationVector** in) { return this->RequestWholeData(request, in, outputVector); },
    { { &this->ToleranceLength, &this->Compression },
      { &this->OriginalFaces, &this->StoredFaces, &this->TreeHeight },
      {} });
}

//------------------------------------------------------------------------------
int vtkFoldingTreeBuilder::RequestWholeData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkMultiBlockDataSet* tree = vtkMultiBlockDataSet::GetData(outputVector, 0);
  vtkPolyData* segmentation = vtkPolyData::GetData(outputVector, 1);
  this->ToleranceLength = 0.0;
  this->OriginalFaces = this->StoredFaces = this->TreeHeight = 0;
  this->Compression = 0.0;
  if (!input || !tree || !segmentation)
  {
    vtkErrorMacro("Missing input poly data or outputs.");
    return 0;
  }
  std::string error;
  if (!foldingmeshes::CheckParameters({ { "Tolerance", this->Tolerance } },
        { { "MinimumAreaFraction", this->MinimumAreaFraction } },
        error))
  {
    vtkErrorMacro(<< error << ".");
    return 0;
  }
  foldingmeshes::TriangleMesh soup;
  std::vector<foldingmeshes::Vec3> normals;
  vtkIdType droppedVerts = 0, droppedLines = 0;
  vtkSmartPointer<vtkPolyData> surface = foldingmeshes::SurfaceInput(
    input, "a folding tree needs a surface mesh", soup, normals, droppedVerts, droppedLines, error);
  if (droppedVerts + droppedLines > 0)
  {
    vtkWarningMacro("Ignoring " << droppedVerts << " vertex and " << droppedLines
                                << " line cells: only polygons are folded.");
  }
  if (!surface)
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  if (soup.triangles.empty())
  {
    vtkErrorMacro("The input has no triangles after triangulation.");
    return 0;
  }

  // Bounding-box diagonal of the points used by triangles.
  foldingmeshes::Vec3 lo = foldingmeshes::Vec3::Constant(std::numeric_limits<double>::max());
  foldingmeshes::Vec3 hi = -lo;
  for (const auto& t : soup.triangles)
    for (int v : t)
    {
      lo = lo.cwiseMin(soup.points[v]);
      hi = hi.cwiseMax(soup.points[v]);
    }
  double epsilon = 0.0;
  if (!foldingmeshes::ToleranceLengthOf(
        this->ToleranceMode == ABSOLUTE, this->Tolerance, (hi - lo).norm(), epsilon, error))
  {
    vtkErrorMacro(<< error << ".");
    return 0;
  }
  this->ToleranceLength = epsilon;

  const foldingmeshes::FoldingTreeOptions options = FoldingTreeOptionsOf(this, epsilon);

  foldingmeshes::FoldingTree folding;
  if (!foldingmeshes::BuildFoldingTree(soup, normals, options, folding, error))
  {
    vtkErrorMacro("Could not build the folding tree: " << error << ".");
    return 0;
  }
  if (folding.aborted)
  {
    vtkWarningMacro("Folding aborted: the tree is incomplete (unfinished regions are leaves).");
  }
  std::vector<std::string> notes;
  if (!foldingmeshes::FoldingTreeToMultiBlock(folding, surface, tree, error, &notes))
  {
    vtkErrorMacro("The builder produced an invalid folding tree: " << error << ".");
    return 0;
  }
  for (const std::string& note : notes)
    vtkWarningMacro("Folding tree: " << note << ".");
  if (vtkPolyData* info = vtkPolyData::SafeDownCast(tree->GetBlock(1)))
  {
    vtkNew<vtkStringArray> locator;
    locator->SetName("VerificationLocator");
    locator->InsertNextValue(!this->VerifyBound ? ""
        : this->Locator                         ? this->Locator->GetClassName()
                                                : "FaceTree");
    info->GetFieldData()->AddArray(locator);
    // The epsilon asked for (Tolerance): the tree's RootEpsilon is smaller after a near-miss
    // rebuild of VerifyBound.
    vtkNew<vtkDoubleArray> requested;
    requested->SetName("RequestedEpsilon");
    requested->InsertNextValue(epsilon);
    info->GetFieldData()->AddArray(requested);
  }
  this->OriginalFaces = folding.numberOfOriginalFaces;
  this->StoredFaces = folding.StoredFaces();
  this->Compression = folding.Compression();
  this->TreeHeight = folding.Height();

  // Output 1: the segmentation view.
  segmentation->ShallowCopy(surface);
  AddSegmentationArrays(folding, soup, segmentation, this);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkFoldingTreeBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "Locator: " << this->Locator << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent
     << "ToleranceMode: " << (this->ToleranceMode == ABSOLUTE ? "Absolute" : "RelativeToDiagonal")
     << "\n";
  os << indent << "KeepSide: " << (this->KeepSide == FEWER_FACES ? "FewerFaces" : "MoreFaces")
     << "\n";
  os << indent << "UseMinimumFaces: " << this->UseMinimumFaces << "\n";
  os << indent << "MinimumFaces: " << this->MinimumFaces << "\n";
  os << indent << "UseMinimumAreaFraction: " << this->UseMinimumAreaFraction << "\n";
  os << indent << "MinimumAreaFraction: " << this->MinimumAreaFraction << "\n";
  os << indent << "UseMaximumFolds: " << this->UseMaximumFolds << "\n";
  os << indent << "MaximumFolds: " << this->MaximumFolds << "\n";
  os << indent << "RequireMeaningfulSymmetry: " << this->RequireMeaningfulSymmetry << "\n";
  os << indent << "RequireTightSymmetry: " << this->RequireTightSymmetry << "\n";
  os << indent << "VerifyBound: " << this->VerifyBound << "\n";
  os << indent << "ConnectNearbyParts: " << this->ConnectNearbyParts << "\n";
  os << indent << "RotationNodes: "
     << (this->RotationNodes == ROTATION_NODES_WHEN_AXIAL ? "WhenAxial"
            : this->RotationNodes == ROTATION_NODES_ON    ? "On"
                                                          : "Off")
     << "\n";
  os << indent << "MaximumRotationOrder: " << this->MaximumRotationOrder << "\n";
  os << indent << "Method: " << (this->Method == PAPER ? "Paper" : "Robust") << "\n";
  os << indent << "SampledSearchAboveFaces: " << this->SampledSearchAboveFaces << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "ToleranceLength: " << this->ToleranceLength << "\n";
  os << indent << "OriginalFaces: " << this->OriginalFaces << "\n";
  os << indent << "StoredFaces: " << this->StoredFaces << "\n";
  os << indent << "Compression: " << this->Compression << "\n";
  os << indent << "TreeHeight: " << this->TreeHeight << "\n";
}
