#include "vtkSymmetryPlaneDetector.h"

#include "Core/MeshPreparation.h"
#include "Core/RotationalSymmetry.h"
#include "Core/SymmetryDetection.h"
#include "vtkAxisGlyph.h"
#include "vtkCellLocatorFaceQuery.h"
#include "vtkFoldingArrays.h"
#include "vtkFoldingDebugTrace.h"
#include "vtkFoldingMeshesParallel.h"
#include "vtkParameterChecks.h"
#include "vtkTriangleMeshAdapter.h"

#include <vtkAbstractCellLocator.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkSymmetryPlaneDetector);
vtkCxxSetObjectMacro(vtkSymmetryPlaneDetector, Controller, vtkMultiProcessController);
vtkCxxSetObjectMacro(vtkSymmetryPlaneDetector, Locator, vtkAbstractCellLocator);

namespace
{
using foldingmeshes::Vec3;

vtkSmartPointer<vtkDoubleArray> MakeTuple(const char* name, const double* values, int n)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(n);
  array->SetNumberOfTuples(1);
  for (int k = 0; k < n; ++k)
    array->SetComponent(0, k, values[k]);
  return array;
}

vtkSmartPointer<vtkDoubleArray> MakeSeries(const char* name, const std::vector<double>& values)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (size_t k = 0; k < values.size(); ++k)
    array->SetValue(static_cast<vtkIdType>(k), values[k]);
  return array;
}

/// A quad on the plane covering the projection of the selected points (10% margin).
void BuildPlaneGlyph(const foldingmeshes::PreparedMesh& mesh,
  const std::vector<char>& faces,
  const foldingmeshes::Plane& plane,
  vtkPolyData* glyph)
{
  const Vec3 n = plane.normal;
  const Vec3 helper = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 u = n.cross(helper).normalized();
  const Vec3 v = n.cross(u);
  double lo[2] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::max() };
  double hi[2] = { -lo[0], -lo[1] };
  bool any = false;
  for (int pass = 0; pass < 2 && !any; ++pass)
    for (int f = 0; f < mesh.NumberOfFaces(); ++f)
      if (pass == 1 || faces[f])
        for (int p : mesh.triangles[f])
        {
          const Vec3 q = mesh.points[p] - plane.origin;
          lo[0] = std::min(lo[0], q.dot(u));
          hi[0] = std::max(hi[0], q.dot(u));
          lo[1] = std::min(lo[1], q.dot(v));
          hi[1] = std::max(hi[1], q.dot(v));
          any = true;
        }
  for (int k = 0; k < 2; ++k)
  {
    const double margin = 0.1 * (hi[k] - lo[k]) + 1e-3 * mesh.diagonal;
    lo[k] -= margin;
    hi[k] += margin;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const double corners[4][2] = {
    { lo[0], lo[1] }, { hi[0], lo[1] }, { hi[0], hi[1] }, { lo[0], hi[1] }
  };
  for (const auto& c : corners)
  {
    const Vec3 p = plane.origin + c[0] * u + c[1] * v;
    points->InsertNextPoint(p.x(), p.y(), p.z());
  }
  vtkNew<vtkCellArray> quads;
  const vtkIdType ids[4] = { 0, 1, 2, 3 };
  quads->InsertNextCell(4, ids);
  glyph->SetPoints(points);
  glyph->SetPolys(quads);
}

/// A line along the axis over the extent of the selected faces' points (all points when none
/// is selected), with a 10% margin.
void BuildAxisGlyph(const foldingmeshes::PreparedMesh& mesh,
  const std::vector<char>& faces,
  const foldingmeshes::RotationAxis& axis,
  vtkPolyData* glyph)
{
  std::vector<Vec3> points;
  for (int pass = 0; pass < 2 && points.empty(); ++pass)
    for (int f = 0; f < mesh.NumberOfFaces(); ++f)
      if (pass == 1 || faces[f])
        for (int p : mesh.triangles[f])
          points.push_back(mesh.points[p]);
  foldingmeshes::SetAxisLineGlyph(axis, points, mesh.diagonal, glyph);
}

/// Names of the rotation's field arrays (output 0 and the axis glyph).
const char* const RotationFieldNames[] = { "RotationAxisOrigin",
  "RotationAxisDirection",
  "RotationOrder",
  "RotationFound",
  "RotationContinuous",
  "RotationalAreaFraction" };

/// The rotation's arrays on output 0 (RotationRegion, RotationDistance, the field arrays)
/// and the axis glyph on output 2. Input arrays of these names are renamed, with a warning.
void AddRotationOutputs(const foldingmeshes::PreparedMesh& mesh,
  const foldingmeshes::RotationResult& rotation,
  vtkPolyData* output,
  vtkPolyData* axisGlyph,
  vtkObject* warner)
{
  {
    std::vector<std::string> renamed;
    foldingmeshes::RenameReservedArrays(output->GetCellData(), { "RotationRegion" }, renamed);
    foldingmeshes::RenameReservedArrays(output->GetPointData(), { "RotationDistance" }, renamed);
    for (const std::string& r : renamed)
      vtkWarningWithObjectMacro(
        warner, "The input's array " << r << " (the name is the detector's).");
  }
  const vtkIdType nf = output->GetNumberOfCells();
  vtkNew<vtkIntArray> region;
  region->SetName("RotationRegion");
  region->SetNumberOfTuples(nf);
  for (vtkIdType f = 0; f < nf; ++f)
    region->SetValue(f, rotation.faceLabel[f]);
  output->GetCellData()->AddArray(region);
  const vtkIdType np = output->GetNumberOfPoints();
  vtkNew<vtkDoubleArray> distance;
  distance->SetName("RotationDistance");
  distance->SetNumberOfTuples(np);
  for (vtkIdType i = 0; i < np; ++i)
  {
    const double d = rotation.distance[mesh.inputToWelded[i]];
    distance->SetValue(i, std::isfinite(d) ? d : std::numeric_limits<double>::quiet_NaN());
  }
  output->GetPointData()->AddArray(distance);

  vtkFieldData* field = output->GetFieldData();
  field->AddArray(MakeTuple("RotationAxisOrigin", rotation.axis.origin.data(), 3));
  field->AddArray(MakeTuple("RotationAxisDirection", rotation.axis.direction.data(), 3));
  const double order = rotation.order, found = rotation.found ? 1.0 : 0.0,
               continuous = rotation.continuous ? 1.0 : 0.0;
  field->AddArray(MakeTuple("RotationOrder", &order, 1));
  field->AddArray(MakeTuple("RotationFound", &found, 1));
  field->AddArray(MakeTuple("RotationContinuous", &continuous, 1));
  field->AddArray(MakeTuple("RotationalAreaFraction", &rotation.symmetricAreaFraction, 1));

  BuildAxisGlyph(mesh, rotation.faceLabel, rotation.axis, axisGlyph);
  vtkNew<vtkFieldData> glyphField;
  for (const char* name : RotationFieldNames)
    glyphField->AddArray(field->GetAbstractArray(name));
  axisGlyph->SetFieldData(glyphField);
}

/// The filter's initial plane, its normal made unit length. False when the origin is not
/// finite or the normal is not finite and non-zero.
bool InitialPlaneOf(vtkSymmetryPlaneDetector* self, Vec3& origin, Vec3& normal)
{
  const double* n = self->GetInitialPlaneNormal();
  const double* o = self->GetInitialPlaneOrigin();
  normal = Vec3(n[0], n[1], n[2]);
  origin = Vec3(o[0], o[1], o[2]);
  // Divide by the largest component first: the norm of (1e300, 1e300, 0) overflows.
  const double largest = normal.cwiseAbs().maxCoeff();
  if (!std::isfinite(largest) || !(largest > 0.0) || !origin.allFinite())
    return false;
  const double norm = normal.norm();
  normal =
    std::isfinite(norm) && norm > 1e-150 ? Vec3(normal / norm) : (normal / largest).normalized();
  return true;
}

/// The filter's parameters as the core's options (the initial plane already checked; the
/// progress callback is the caller's).
foldingmeshes::SymmetryOptions SymmetryOptionsOf(vtkSymmetryPlaneDetector* self,
  double epsilon,
  const Vec3& origin,
  const Vec3& normal)
{
  foldingmeshes::SymmetryOptions options;
  options.epsilon = epsilon;
  options.robust = self->GetMethod() == vtkSymmetryPlaneDetector::ROBUST;
  options.useInitialPlane = self->GetUseInitialPlane();
  if (self->GetUseInitialPlane())
  {
    options.initialPlane.origin = origin;
    options.initialPlane.normal = normal;
  }
  options.numberOfCandidates = self->GetNumberOfCandidates();
  options.sampledSearchAboveFaces = self->GetSampledSearchAboveFaces();
  options.maximumIterations = self->GetMaximumIterations();
  options.compatibilityAngle = self->GetCompatibilityAngle();
  options.minimumSymmetricAreaFraction = self->GetMinimumSymmetricAreaFraction();
  options.seed = static_cast<unsigned>(self->GetRandomSeed());
  options.trace = foldingmeshes::DebugTrace(self);
  if (self->GetLocator()) // else the face tree alone: the same answers, faster
    options.closestFaceFastPath = foldingmeshes::CellLocatorFaceQueryFactory(self->GetLocator());
  return options;
}

/// The detector's arrays on output 0 (the triangulated input): SymmetryRegion (cell, active
/// scalars), SymmetryDistance and SymmetryWeight (point). Input arrays of these names are renamed,
/// with a warning through `warner`.
void AddDetectionArrays(const foldingmeshes::PreparedMesh& mesh,
  const foldingmeshes::SymmetryResult& result,
  vtkPolyData* output,
  vtkObject* warner)
{
  {
    std::vector<std::string> renamed;
    foldingmeshes::RenameReservedArrays(output->GetCellData(), { "SymmetryRegion" }, renamed);
    foldingmeshes::RenameReservedArrays(
      output->GetPointData(), { "SymmetryDistance", "SymmetryWeight" }, renamed);
    for (const std::string& r : renamed)
      vtkWarningWithObjectMacro(
        warner, "The input's array " << r << " (the name is the detector's).");
  }
  const vtkIdType nf = output->GetNumberOfCells();
  vtkNew<vtkIntArray> region;
  region->SetName("SymmetryRegion");
  region->SetNumberOfTuples(nf);
  for (vtkIdType f = 0; f < nf; ++f)
    region->SetValue(f, result.faceLabel[f]);
  output->GetCellData()->AddArray(region);
  output->GetCellData()->SetActiveScalars("SymmetryRegion");
  // Active point scalars (e.g. vertex colours) would hide the region colouring in ParaView;
  // the array stays, it is just no longer the active one.
  output->GetPointData()->SetActiveAttribute(-1, vtkDataSetAttributes::SCALARS);

  const vtkIdType np = output->GetNumberOfPoints();
  vtkNew<vtkDoubleArray> distance, weight;
  distance->SetName("SymmetryDistance");
  weight->SetName("SymmetryWeight");
  distance->SetNumberOfTuples(np);
  weight->SetNumberOfTuples(np);
  for (vtkIdType i = 0; i < np; ++i)
  {
    const int v = mesh.inputToWelded[i];
    const double d = result.distance[v];
    distance->SetValue(i, std::isfinite(d) ? d : std::numeric_limits<double>::quiet_NaN());
    weight->SetValue(i, result.weight[v]);
  }
  output->GetPointData()->AddArray(distance);
  output->GetPointData()->AddArray(weight);
}

/// Output 0's field data: the input's field arrays first, so that ours replace stale ones of
/// the same name (running the detector on its own output), then the plane, the symmetric
/// area fraction, whether a symmetry was found, the tolerance length, the iterations and the
/// cost history.
vtkSmartPointer<vtkFieldData> DetectionFieldData(vtkPolyData* input,
  const foldingmeshes::SymmetryResult& result,
  double epsilon)
{
  vtkNew<vtkFieldData> field;
  for (int a = 0; a < input->GetFieldData()->GetNumberOfArrays(); ++a)
    field->AddArray(input->GetFieldData()->GetAbstractArray(a));
  const double origin[3] = {
    result.plane.origin[0], result.plane.origin[1], result.plane.origin[2]
  };
  const double normal[3] = {
    result.plane.normal[0], result.plane.normal[1], result.plane.normal[2]
  };
  field->AddArray(MakeTuple("SymmetryPlaneOrigin", origin, 3));
  field->AddArray(MakeTuple("SymmetryPlaneNormal", normal, 3));
  field->AddArray(MakeTuple("SymmetricAreaFraction", &result.symmetricAreaFraction, 1));
  const double found = result.found ? 1.0 : 0.0;
  field->AddArray(MakeTuple("SymmetryFound", &found, 1));
  field->AddArray(MakeTuple("SymmetryTolerance", &epsilon, 1));
  const double iterations[2] = { static_cast<double>(result.coarseIterations),
    static_cast<double>(result.fineIterations) };
  field->AddArray(MakeTuple("SymmetryIterations", iterations, 2));
  field->AddArray(MakeSeries("SymmetryCostHistory", result.costHistory));
  return field;
}

/// Output 1: the plane glyph over the symmetric region, with the plane's field arrays of
/// output 0 (`field`).
void SetPlaneGlyphOutput(const foldingmeshes::PreparedMesh& mesh,
  const foldingmeshes::SymmetryResult& result,
  vtkFieldData* field,
  vtkPolyData* glyph)
{
  std::vector<char> symmetric(mesh.NumberOfFaces());
  for (int f = 0; f < mesh.NumberOfFaces(); ++f)
    symmetric[f] = result.faceLabel[f] == 2;
  BuildPlaneGlyph(mesh, symmetric, result.plane, glyph);
  vtkNew<vtkFieldData> glyphField;
  for (const char* name : { "SymmetryPlaneOrigin",
         "SymmetryPlaneNormal",
         "SymmetricAreaFraction",
         "SymmetryFound",
         "SymmetryTolerance" })
    glyphField->AddArray(field->GetAbstractArray(name));
  glyph->SetFieldData(glyphField);
}
}

//------------------------------------------------------------------------------
vtkSymmetryPlaneDetector::vtkSymmetryPlaneDetector()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(3);
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkSymmetryPlaneDetector::~vtkSymmetryPlaneDetector()
{
  this->SetController(nullptr);
  this->SetLocator(nullptr);
}

//------------------------------------------------------------------------------
int vtkSymmetryPlaneDetector::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkSymmetryPlaneDetector::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  return foldingmeshes::RunWholeOnRoot(this,
    this->Controller,
    inputVector,
    outputVector,
    [&](vtkInformationVector** in) { return this->RequestWholeData(request, in, outputVector); },
    { { &this->PlaneOrigin[0],
        &this->PlaneOrigin[1],
        &this->PlaneOrigin[2],
        &this->PlaneNormal[0],
        &this->PlaneNormal[1],
        &this->PlaneNormal[2],
        &this->SymmetricAreaFraction,
        &this->ToleranceLength,
        &this->RotationAxisOrigin[0],
        &this->RotationAxisOrigin[1],
        &this->RotationAxisOrigin[2],
        &this->RotationAxisDirection[0],
        &this->RotationAxisDirection[1],
        &this->RotationAxisDirection[2],
        &this->RotationalAreaFraction },
      { &this->CoarseIterations, &this->FineIterations, &this->RotationOrder },
      { &this->SymmetryFound, &this->RotationFound, &this->RotationContinuous } });
}

//------------------------------------------------------------------------------
int vtkSymmetryPlaneDetector::RequestWholeData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* glyph = vtkPolyData::GetData(outputVector, 1);
  vtkPolyData* axisGlyph = vtkPolyData::GetData(outputVector, 2);
  this->SymmetricAreaFraction = 0.0;
  this->RotationOrder = 0;
  this->RotationFound = this->RotationContinuous = false;
  this->RotationalAreaFraction = 0.0;
  for (int k = 0; k < 3; ++k)
    this->RotationAxisOrigin[k] = this->RotationAxisDirection[k] = 0.0;
  this->SymmetryFound = false;
  this->CoarseIterations = this->FineIterations = 0;
  this->ToleranceLength = 0.0;
  for (int k = 0; k < 3; ++k)
    this->PlaneOrigin[k] = this->PlaneNormal[k] = 0.0;
  if (!input || !output || !glyph || !axisGlyph)
  {
    vtkErrorMacro("Missing input or output poly data.");
    return 0;
  }
  std::string error;
  if (!foldingmeshes::CheckParameters({ { "Tolerance", this->Tolerance } },
        { { "CompatibilityAngle", this->CompatibilityAngle },
          { "MinimumSymmetricAreaFraction", this->MinimumSymmetricAreaFraction } },
        error))
  {
    vtkErrorMacro(<< error << ".");
    return 0;
  }
  Vec3 initialOrigin, initialNormal;
  if (this->UseInitialPlane && !InitialPlaneOf(this, initialOrigin, initialNormal))
  {
    vtkErrorMacro("The initial plane needs a finite origin and a finite, non-zero normal.");
    return 0;
  }

  foldingmeshes::TriangleMesh soup;
  std::vector<Vec3> normals;
  vtkIdType droppedVerts = 0, droppedLines = 0;
  vtkSmartPointer<vtkPolyData> surface = foldingmeshes::SurfaceInput(input,
    "symmetry detection needs a surface mesh",
    soup,
    normals,
    droppedVerts,
    droppedLines,
    error);
  if (droppedVerts + droppedLines > 0)
    vtkWarningMacro("Ignoring " << droppedVerts << " vertex and " << droppedLines
                                << " line cells: only polygons are used.");
  if (!surface)
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  foldingmeshes::PreparedMesh mesh;
  if (!foldingmeshes::PrepareMesh(soup, normals, mesh, error))
  {
    vtkErrorMacro("Invalid input mesh: " << error << ".");
    return 0;
  }

  double epsilon = 0.0;
  if (!foldingmeshes::ToleranceLengthOf(
        this->ToleranceMode == ABSOLUTE, this->Tolerance, mesh.diagonal, epsilon, error))
  {
    vtkErrorMacro(<< error << ".");
    return 0;
  }
  this->ToleranceLength = epsilon;
  if (this->ConnectNearbyParts)
    foldingmeshes::LinkNearbyParts(mesh, epsilon);

  foldingmeshes::SymmetryOptions options =
    SymmetryOptionsOf(this, epsilon, initialOrigin, initialNormal);
  // With the rotation search after it, the plane search reports the first 40% of the progress.
  const double planeShare = this->DetectRotation ? 0.4 : 1.0;
  options.progress = [this, planeShare](double p)
  {
    this->UpdateProgress(planeShare * p);
    return !this->GetAbortExecute();
  };
  const foldingmeshes::FaceTree faces(mesh);
  const foldingmeshes::SymmetryResult result = foldingmeshes::DetectSymmetry(mesh, options, &faces);
  if (result.aborted)
  {
    vtkWarningMacro("Symmetry detection aborted.");
    return 1;
  }
  if (result.faceLabel.size() != static_cast<size_t>(mesh.NumberOfFaces()) ||
    result.distance.size() != static_cast<size_t>(mesh.NumberOfPoints()) ||
    result.weight.size() != static_cast<size_t>(mesh.NumberOfPoints()) ||
    !result.plane.normal.allFinite() || !result.plane.origin.allFinite())
  {
    vtkErrorMacro("Symmetry detection produced no result for this mesh.");
    return 0;
  }

  std::copy(result.plane.origin.data(), result.plane.origin.data() + 3, this->PlaneOrigin);
  std::copy(result.plane.normal.data(), result.plane.normal.data() + 3, this->PlaneNormal);
  this->SymmetricAreaFraction = result.symmetricAreaFraction;
  this->SymmetryFound = result.found;
  this->CoarseIterations = result.coarseIterations;
  this->FineIterations = result.fineIterations;

  // Output 0: the triangulated input with the labels; output 1: the plane glyph.
  output->ShallowCopy(surface);
  AddDetectionArrays(mesh, result, output, this);
  output->SetFieldData(DetectionFieldData(input, result, epsilon));
  SetPlaneGlyphOutput(mesh, result, output->GetFieldData(), glyph);

  if (this->DetectRotation)
  {
    foldingmeshes::RotationOptions rotationOptions;
    rotationOptions.epsilon = epsilon;
    rotationOptions.maximumOrder = this->MaximumRotationOrder;
    rotationOptions.compatibilityAngle = this->CompatibilityAngle;
    rotationOptions.minimumSymmetricAreaFraction = this->MinimumSymmetricAreaFraction;
    rotationOptions.mirrorPlanes = result.finalists;
    rotationOptions.mirrorPlanes.push_back(result.plane);
    rotationOptions.progress = [this, planeShare](double p)
    {
      this->UpdateProgress(planeShare + (1.0 - planeShare) * p);
      return !this->GetAbortExecute();
    };
    const foldingmeshes::RotationResult rotation =
      foldingmeshes::DetectRotationalSymmetry(mesh, rotationOptions, &faces);
    if (rotation.aborted)
    {
      vtkWarningMacro("Rotational symmetry detection aborted.");
      return 1;
    }
    std::copy(
      rotation.axis.origin.data(), rotation.axis.origin.data() + 3, this->RotationAxisOrigin);
    std::copy(rotation.axis.direction.data(),
      rotation.axis.direction.data() + 3,
      this->RotationAxisDirection);
    this->RotationOrder = rotation.order;
    this->RotationFound = rotation.found;
    this->RotationContinuous = rotation.continuous;
    this->RotationalAreaFraction = rotation.symmetricAreaFraction;
    AddRotationOutputs(mesh, rotation, output, axisGlyph, this);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkSymmetryPlaneDetector::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "Locator: " << this->Locator << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent
     << "ToleranceMode: " << (this->ToleranceMode == ABSOLUTE ? "Absolute" : "RelativeToDiagonal")
     << "\n";
  os << indent << "Method: " << (this->Method == PAPER ? "Paper" : "Robust") << "\n";
  os << indent << "UseInitialPlane: " << this->UseInitialPlane << "\n";
  os << indent << "InitialPlaneOrigin: " << this->InitialPlaneOrigin[0] << " "
     << this->InitialPlaneOrigin[1] << " " << this->InitialPlaneOrigin[2] << "\n";
  os << indent << "InitialPlaneNormal: " << this->InitialPlaneNormal[0] << " "
     << this->InitialPlaneNormal[1] << " " << this->InitialPlaneNormal[2] << "\n";
  os << indent << "NumberOfCandidates: " << this->NumberOfCandidates << "\n";
  os << indent << "SampledSearchAboveFaces: " << this->SampledSearchAboveFaces << "\n";
  os << indent << "MaximumIterations: " << this->MaximumIterations << "\n";
  os << indent << "CompatibilityAngle: " << this->CompatibilityAngle << "\n";
  os << indent << "ConnectNearbyParts: " << this->ConnectNearbyParts << "\n";
  os << indent << "MinimumSymmetricAreaFraction: " << this->MinimumSymmetricAreaFraction << "\n";
  os << indent << "RandomSeed: " << this->RandomSeed << "\n";
  os << indent << "DetectRotation: " << this->DetectRotation << "\n";
  os << indent << "MaximumRotationOrder: " << this->MaximumRotationOrder << "\n";
  os << indent << "RotationAxisOrigin: " << this->RotationAxisOrigin[0] << " "
     << this->RotationAxisOrigin[1] << " " << this->RotationAxisOrigin[2] << "\n";
  os << indent << "RotationAxisDirection: " << this->RotationAxisDirection[0] << " "
     << this->RotationAxisDirection[1] << " " << this->RotationAxisDirection[2] << "\n";
  os << indent << "RotationOrder: " << this->RotationOrder << "\n";
  os << indent << "RotationFound: " << this->RotationFound << "\n";
  os << indent << "RotationContinuous: " << this->RotationContinuous << "\n";
  os << indent << "RotationalAreaFraction: " << this->RotationalAreaFraction << "\n";
  os << indent << "PlaneOrigin: " << this->PlaneOrigin[0] << " " << this->PlaneOrigin[1] << " "
     << this->PlaneOrigin[2] << "\n";
  os << indent << "PlaneNormal: " << this->PlaneNormal[0] << " " << this->PlaneNormal[1] << " "
     << this->PlaneNormal[2] << "\n";
  os << indent << "SymmetricAreaFraction: " << this->SymmetricAreaFraction << "\n";
  os << indent << "SymmetryFound: " << this->SymmetryFound << "\n";
  os << indent << "CoarseIterations: " << this->CoarseIterations << "\n";
  os << indent << "FineIterations: " << this->FineIterations << "\n";
  os << indent << "ToleranceLength: " << this->ToleranceLength << "\n";
}
