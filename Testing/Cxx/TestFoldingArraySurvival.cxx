// "Nothing is lost": the user's point, cell and field arrays survive fold + unfold, in memory
// and through a .vtm file (written in the default appended mode, read with
// vtkExpatSafeXMLMultiBlockDataReader, which must report no error), on an exactly mirror-symmetric mesh (a subdivided icosahedron
// scaled to an ellipsoid, float or double points) carrying
// - field arrays (one named like the unfolder's own "Diagonal"): restored on the unfolded mesh,
//   the clashing one as "Diagonal_input";
// - point and cell GlobalIds and active scalars / normals / vectors / tcoords: the ids survive
//   triangulation (detector, builder output 1, leaves, unfolded mesh); the unfolded mesh's
//   active attributes are the input's, except global ids whose values the mirrored copies
//   repeat (kept as arrays, no longer flagged) and scalars (FoldingLeafId: coloured by leaf);
// - an unnamed point array: carried as "UnnamedPointArray0" (with a warning);
// - arrays named like the filters' own (TearMask, ErrorBudget, FoldingCopy, OriginalCellId,
//   SymmetryRegion, FoldingRole): carried renamed "<name>_input" with the user's values (and a
//   warning); the tree-internal ErrorBudget / InputBoundary are not in the unfolded mesh;
// - a vtkVariantArray: left out of the tree (with a warning) so the .vtm reads back;
// - the unfolded points have the input's precision;
// - a cell vector holding each face's centroid: every unfolded face lying exactly on an input
//   face carries that face's centroid (reflected on mirrored copies), also faces re-created when
//   the unfolder removes projected points or thins copies (they take the data of the old face
//   they overlap most).
#include "TestExpect.h"
#include "vtkExpatSafeXMLMultiBlockDataReader.h"
#include "vtkFoldingTreeBuilder.h"
#include "vtkFoldingTreeUnfolder.h"
#include "vtkSymmetryPlaneDetector.h"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataObjectTreeIterator.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkLoopSubdivisionFilter.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPlatonicSolidSource.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkVariant.h>
#include <vtkVariantArray.h>
#include <vtkXMLMultiBlockDataWriter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

namespace
{
int failures = 0;
#define EXPECT(cond, msg) FOLDINGMESHES_EXPECT(failures, cond, msg)

struct Warnings
{
  std::vector<std::string> messages;
  static void Callback(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    static_cast<Warnings*>(clientData)
      ->messages.push_back(callData ? static_cast<const char*>(callData) : "");
  }
  bool Mentions(const std::string& text) const
  {
    for (const std::string& m : this->messages)
      if (m.find(text) != std::string::npos)
        return true;
    return false;
  }
};

void Capture(vtkAlgorithm* alg, Warnings& log)
{
  vtkNew<vtkCallbackCommand> cb;
  cb->SetCallback(Warnings::Callback);
  cb->SetClientData(&log);
  alg->AddObserver(vtkCommand::WarningEvent, cb);
}

double SymmetricScalar(const double p[3])
{
  return p[0] * p[0] + 2.0 * p[1] * p[1] + 3.0 * p[2] * p[2];
}

vtkSmartPointer<vtkDataArray> Scalar(vtkDataArray* proto, const char* name, vtkIdType n)
{
  vtkSmartPointer<vtkDataArray> a = vtk::TakeSmartPointer(proto->NewInstance());
  if (name)
    a->SetName(name);
  a->SetNumberOfTuples(n);
  return a;
}

/// The decorated ellipsoid (see the file comment).
vtkSmartPointer<vtkPolyData> MakeInput(bool doublePoints)
{
  vtkNew<vtkPlatonicSolidSource> solid;
  solid->SetSolidTypeToIcosahedron();
  vtkNew<vtkLoopSubdivisionFilter> subdivide;
  subdivide->SetNumberOfSubdivisions(2);
  subdivide->SetInputConnection(solid->GetOutputPort());
  subdivide->Update();
  vtkPolyData* s = subdivide->GetOutput();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(doublePoints ? VTK_DOUBLE : VTK_FLOAT);
  const vtkIdType np = s->GetNumberOfPoints();
  points->SetNumberOfPoints(np);
  for (vtkIdType i = 0; i < np; ++i)
  {
    double p[3];
    s->GetPoint(i, p);
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    points->SetPoint(i, p[0] / r, 0.8 * p[1] / r, 0.6 * p[2] / r);
  }
  mesh->SetPoints(points);
  mesh->SetPolys(s->GetPolys());
  const vtkIdType nc = mesh->GetNumberOfCells();

  vtkNew<vtkDoubleArray> dproto;
  vtkNew<vtkFloatArray> fproto;
  vtkNew<vtkIdTypeArray> iproto;
  vtkPointData* pd = mesh->GetPointData();
  auto temperature = Scalar(dproto, "Temperature", np);
  auto unnamed = Scalar(fproto, nullptr, np);
  auto tear = Scalar(dproto, "TearMask", np);
  auto budget = Scalar(dproto, "ErrorBudget", np);
  auto pointIds = Scalar(iproto, "PointIds", np);
  vtkNew<vtkFloatArray> normals, tcoords;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(np);
  tcoords->SetName("UV");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(np);
  vtkNew<vtkVariantArray> variant;
  variant->SetName("Variant");
  variant->SetNumberOfValues(np);
  for (vtkIdType i = 0; i < np; ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    const double v = SymmetricScalar(p);
    temperature->SetTuple1(i, v);
    unnamed->SetTuple1(i, 3.0 * v);
    tear->SetTuple1(i, v + 7.0);
    budget->SetTuple1(i, v + 9.0);
    pointIds->SetTuple1(i, static_cast<double>(i));
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    normals->SetTuple3(i, p[0] / r, p[1] / r, p[2] / r);
    tcoords->SetTuple2(i, p[0] * p[0], p[1] * p[1]);
    variant->SetValue(i, vtkVariant(static_cast<int>(i)));
  }
  pd->SetScalars(temperature);
  pd->AddArray(unnamed);
  pd->AddArray(tear);
  pd->AddArray(budget);
  pd->SetGlobalIds(pointIds);
  pd->SetNormals(normals);
  pd->SetTCoords(tcoords);
  pd->AddArray(variant);

  vtkCellData* cd = mesh->GetCellData();
  auto cellScalar = Scalar(dproto, "CellScalar", nc);
  auto copy = Scalar(dproto, "FoldingCopy", nc);
  auto original = Scalar(dproto, "OriginalCellId", nc);
  auto role = Scalar(dproto, "FoldingRole", nc);
  auto region = Scalar(dproto, "SymmetryRegion", nc);
  auto cellIds = Scalar(iproto, "CellIds", nc);
  vtkNew<vtkDoubleArray> centroid;
  centroid->SetName("Centroid");
  centroid->SetNumberOfComponents(3);
  centroid->SetNumberOfTuples(nc);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < nc; ++c)
  {
    mesh->GetCellPoints(c, ids);
    double m[3] = { 0.0, 0.0, 0.0 };
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      double p[3];
      mesh->GetPoint(ids->GetId(k), p);
      for (int j = 0; j < 3; ++j)
        m[j] += p[j] / static_cast<double>(ids->GetNumberOfIds());
    }
    const double v = SymmetricScalar(m);
    cellScalar->SetTuple1(c, v);
    copy->SetTuple1(c, v + 1.0);
    original->SetTuple1(c, v + 2.0);
    role->SetTuple1(c, v + 3.0);
    region->SetTuple1(c, v + 4.0);
    cellIds->SetTuple1(c, static_cast<double>(c));
    centroid->SetTuple(c, m);
  }
  cd->SetScalars(cellScalar);
  cd->AddArray(copy);
  cd->AddArray(original);
  cd->AddArray(role);
  cd->AddArray(region);
  cd->SetGlobalIds(cellIds);
  cd->SetVectors(centroid);

  vtkNew<vtkDoubleArray> fieldDouble, diagonal;
  fieldDouble->SetName("UserFieldDouble");
  fieldDouble->InsertNextValue(3.25);
  fieldDouble->InsertNextValue(4.5);
  diagonal->SetName("Diagonal");
  diagonal->InsertNextValue(-1.0);
  vtkNew<vtkStringArray> fieldString;
  fieldString->SetName("UserFieldString");
  fieldString->InsertNextValue("hello");
  // Two unnamed field arrays: both come back, named (they once collapsed into one).
  vtkNew<vtkDoubleArray> unnamedField1, unnamedField2;
  unnamedField1->InsertNextValue(1.0);
  unnamedField2->InsertNextValue(2.0);
  mesh->GetFieldData()->AddArray(fieldDouble);
  mesh->GetFieldData()->AddArray(diagonal);
  mesh->GetFieldData()->AddArray(fieldString);
  mesh->GetFieldData()->AddArray(unnamedField1);
  mesh->GetFieldData()->AddArray(unnamedField2);
  return mesh;
}

const char* ActiveName(vtkDataSetAttributes* dsa, int attribute)
{
  vtkAbstractArray* a = dsa->GetAbstractAttribute(attribute);
  return a && a->GetName() ? a->GetName() : "";
}

bool Distinct(vtkDataArray* a)
{
  std::set<double> values;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    values.insert(a->GetTuple1(i));
  return static_cast<vtkIdType>(values.size()) == a->GetNumberOfTuples();
}

/// The input value of `inName` at each output tuple's original id equals output `outName`.
int WrongCarried(vtkDataSetAttributes* in,
  const char* inName,
  vtkDataSetAttributes* out,
  const char* outName,
  const char* idName)
{
  vtkDataArray* a = in->GetArray(inName);
  vtkDataArray* b = out->GetArray(outName);
  vtkDataArray* ids = out->GetArray(idName);
  if (!a || !b || !ids)
    return -1;
  int wrong = 0;
  for (vtkIdType i = 0; i < b->GetNumberOfTuples(); ++i)
    wrong += b->GetTuple1(i) != a->GetTuple1(static_cast<vtkIdType>(ids->GetTuple1(i)));
  return wrong;
}

void CheckUnfolded(vtkPolyData* input, vtkPolyData* out, const std::string& label)
{
  vtkPointData* pd = out->GetPointData();
  vtkCellData* cd = out->GetCellData();
  EXPECT(out->GetNumberOfCells() > 0, label << ": nothing unfolded");
  if (out->GetNumberOfCells() == 0)
    return;
  // Field data.
  vtkFieldData* fd = out->GetFieldData();
  vtkDataArray* fieldDouble = fd->GetArray("UserFieldDouble");
  EXPECT(fieldDouble && fieldDouble->GetNumberOfTuples() == 2 &&
      fieldDouble->GetTuple1(0) == 3.25 && fieldDouble->GetTuple1(1) == 4.5,
    label << ": field array UserFieldDouble lost");
  vtkStringArray* fieldString =
    vtkStringArray::SafeDownCast(fd->GetAbstractArray("UserFieldString"));
  EXPECT(
    fieldString && fieldString->GetNumberOfValues() == 1 && fieldString->GetValue(0) == "hello",
    label << ": field array UserFieldString lost");
  vtkDataArray* unnamed0 = fd->GetArray("UnnamedFieldArray0");
  vtkDataArray* unnamed1 = fd->GetArray("UnnamedFieldArray1");
  EXPECT(unnamed0 && unnamed1 && unnamed0->GetTuple1(0) == 1.0 && unnamed1->GetTuple1(0) == 2.0,
    label << ": unnamed field arrays not both carried as UnnamedFieldArray0/1");
  vtkDataArray* userDiagonal = fd->GetArray("Diagonal_input");
  vtkDataArray* diagonal = fd->GetArray("Diagonal");
  EXPECT(
    userDiagonal && userDiagonal->GetTuple1(0) == -1.0 && diagonal && diagonal->GetTuple1(0) > 0.0,
    label << ": field array Diagonal clashes with the unfolder's");
  // Precision.
  EXPECT(out->GetPoints()->GetDataType() == input->GetPoints()->GetDataType(),
    label << ": points " << out->GetPoints()->GetData()->GetDataTypeAsString() << ", input "
          << input->GetPoints()->GetData()->GetDataTypeAsString());
  // Active attributes (global ids: flagged only while unique).
  // Scalars: coloured by leaf (FoldingLeafId active, no active point scalars), the input's
  // scalar arrays kept.
  EXPECT(std::string(ActiveName(pd, vtkDataSetAttributes::SCALARS)).empty() &&
      pd->GetArray("Temperature") && cd->GetArray("CellScalar") &&
      std::string(ActiveName(pd, vtkDataSetAttributes::NORMALS)) == "Normals" &&
      std::string(ActiveName(pd, vtkDataSetAttributes::TCOORDS)) == "UV" &&
      std::string(ActiveName(cd, vtkDataSetAttributes::SCALARS)) == "FoldingLeafId" &&
      std::string(ActiveName(cd, vtkDataSetAttributes::VECTORS)) == "Centroid",
    label << ": active attributes not restored (point scalars '"
          << ActiveName(pd, vtkDataSetAttributes::SCALARS) << "', cell scalars '"
          << ActiveName(cd, vtkDataSetAttributes::SCALARS) << "')");
  for (vtkDataSetAttributes* dsa :
    { static_cast<vtkDataSetAttributes*>(pd), static_cast<vtkDataSetAttributes*>(cd) })
  {
    const char* name = dsa == pd ? "PointIds" : "CellIds";
    vtkDataArray* ids = dsa->GetArray(name);
    EXPECT(ids, label << ": global ids " << name << " lost");
    if (ids)
      EXPECT((dsa->GetGlobalIds() == ids) == Distinct(ids),
        label << ": " << name << " flagged as global ids: " << (dsa->GetGlobalIds() == ids)
              << ", unique: " << Distinct(ids));
  }
  EXPECT(!Distinct(pd->GetArray("PointIds")) || out->GetNumberOfPoints() == 0,
    label << ": the mirrored copies were expected to repeat point ids");
  // Carried values, renamed arrays, unnamed arrays, tree-internal arrays.
  vtkPointData* ipd = input->GetPointData();
  vtkCellData* icd = input->GetCellData();
  EXPECT(WrongCarried(ipd, "Temperature", pd, "Temperature", "OriginalPointId") == 0,
    label << ": Temperature");
  EXPECT(WrongCarried(ipd, "TearMask", pd, "TearMask_input", "OriginalPointId") == 0,
    label << ": the input's TearMask not carried as TearMask_input");
  EXPECT(WrongCarried(ipd, "ErrorBudget", pd, "ErrorBudget_input", "OriginalPointId") == 0,
    label << ": the input's ErrorBudget not carried as ErrorBudget_input");
  vtkDataArray* inUnnamed = nullptr;
  for (int a = 0; a < ipd->GetNumberOfArrays(); ++a)
    if (ipd->GetArray(a) && !ipd->GetArray(a)->GetName())
      inUnnamed = ipd->GetArray(a);
  vtkDataArray* outUnnamed = pd->GetArray("UnnamedPointArray0");
  EXPECT(inUnnamed && outUnnamed, label << ": unnamed point array not carried");
  if (inUnnamed && outUnnamed)
  {
    vtkDataArray* ids = pd->GetArray("OriginalPointId");
    int wrong = 0;
    for (vtkIdType i = 0; ids && i < out->GetNumberOfPoints(); ++i)
      wrong +=
        outUnnamed->GetTuple1(i) != inUnnamed->GetTuple1(static_cast<vtkIdType>(ids->GetTuple1(i)));
    EXPECT(ids && wrong == 0, label << ": UnnamedPointArray0 wrong at " << wrong << " points");
  }
  EXPECT(!pd->GetArray("TearMask") && !pd->GetArray("ErrorBudget") &&
      !pd->GetArray("InputBoundary") && !pd->GetArray("InputBorderNeighbors"),
    label << ": tree-internal point arrays in the unfolded mesh");
  EXPECT(WrongCarried(icd, "FoldingCopy", cd, "FoldingCopy_input", "OriginalCellId") == 0,
    label << ": the input's FoldingCopy not carried as FoldingCopy_input");
  EXPECT(WrongCarried(icd, "OriginalCellId", cd, "OriginalCellId_input", "OriginalCellId") == 0,
    label << ": the input's OriginalCellId not carried as OriginalCellId_input");
  EXPECT(WrongCarried(icd, "CellScalar", cd, "CellScalar", "OriginalCellId") == 0,
    label << ": CellScalar not the input's at OriginalCellId");

  // Faces lying exactly on an input face carry that face's centroid.
  std::vector<std::array<double, 3>> inputCentroids;
  vtkDataArray* inCentroid = icd->GetArray("Centroid");
  for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
  {
    std::array<double, 3> m;
    inCentroid->GetTuple(c, m.data());
    inputCentroids.push_back(m);
  }
  vtkDataArray* carried = cd->GetArray("Centroid");
  EXPECT(carried, label << ": Centroid not carried");
  int matching = 0, wrong = 0;
  vtkNew<vtkIdList> ids;
  const double tolerance = 1e-5;
  for (vtkIdType f = 0; carried && f < out->GetNumberOfCells(); ++f)
  {
    out->GetCellPoints(f, ids);
    double m[3] = { 0.0, 0.0, 0.0 };
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      double p[3];
      out->GetPoint(ids->GetId(k), p);
      for (int j = 0; j < 3; ++j)
        m[j] += p[j] / 3.0;
    }
    bool onInputFace = false;
    for (const auto& c : inputCentroids)
      onInputFace = onInputFace ||
        std::max({ std::abs(c[0] - m[0]), std::abs(c[1] - m[1]), std::abs(c[2] - m[2]) }) <
          tolerance;
    if (!onInputFace)
      continue;
    ++matching;
    double v[3];
    carried->GetTuple(f, v);
    wrong +=
      std::max({ std::abs(v[0] - m[0]), std::abs(v[1] - m[1]), std::abs(v[2] - m[2]) }) > tolerance;
  }
  std::printf("%s: %d of %lld unfolded faces lie on an input face, %d of them carry another "
              "face's data\n",
    label.c_str(),
    matching,
    static_cast<long long>(out->GetNumberOfCells()),
    wrong);
  EXPECT(matching > out->GetNumberOfCells() / 2,
    label << ": only " << matching << " faces lie on an input face");
  EXPECT(wrong == 0, label << ": " << wrong << " faces carry another face's cell data");
}

void Run(bool doublePoints, const std::string& tempDir)
{
  const std::string label = doublePoints ? "double points" : "float points";
  vtkSmartPointer<vtkPolyData> input = MakeInput(doublePoints);

  // Detector: cell GlobalIds survive triangulation; SymmetryRegion renamed.
  vtkNew<vtkSymmetryPlaneDetector> detector;
  Warnings detectorLog;
  Capture(detector, detectorLog);
  detector->SetInputData(input);
  detector->Update();
  vtkPolyData* detected = detector->GetOutput(0);
  EXPECT(detected->GetCellData()->GetGlobalIds() &&
      std::string(ActiveName(detected->GetCellData(), vtkDataSetAttributes::GLOBALIDS)) ==
        "CellIds",
    label << ": detector output lost the cell global ids");
  EXPECT(WrongCarried(input->GetCellData(),
           "SymmetryRegion",
           detected->GetCellData(),
           "SymmetryRegion_input",
           "CellIds") == 0 &&
      detectorLog.Mentions("SymmetryRegion_input"),
    label << ": the input's SymmetryRegion not renamed (with a warning) by the detector");
  EXPECT(input->GetCellData()->GetArray("SymmetryRegion") &&
      !input->GetCellData()->GetArray("SymmetryRegion_input"),
    label << ": the detector renamed its input's array");

  // Builder.
  vtkNew<vtkFoldingTreeBuilder> builder;
  Warnings builderLog;
  Capture(builder, builderLog);
  builder->SetInputData(input);
  builder->Update();
  vtkPolyData* segmentation = vtkPolyData::SafeDownCast(builder->GetOutputDataObject(1));
  vtkMultiBlockDataSet* tree = vtkMultiBlockDataSet::SafeDownCast(builder->GetOutputDataObject(0));
  EXPECT(segmentation && segmentation->GetCellData()->GetGlobalIds(),
    label << ": builder output 1 lost the cell global ids");
  EXPECT(segmentation &&
      WrongCarried(input->GetCellData(),
        "FoldingRole",
        segmentation->GetCellData(),
        "FoldingRole_input",
        "CellIds") == 0,
    label << ": the input's FoldingRole not renamed in builder output 1");
  EXPECT(builderLog.Mentions("UnnamedPointArray0") && builderLog.Mentions("Variant") &&
      builderLog.Mentions("TearMask -> TearMask_input"),
    label << ": the builder did not warn about the unnamed, variant and renamed arrays");
  int leaves = 0, leavesWithIds = 0;
  vtkNew<vtkDataObjectTreeIterator> it;
  it->SetDataSet(tree);
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    if (vtkPolyData* leaf = vtkPolyData::SafeDownCast(it->GetCurrentDataObject()))
      if (leaf->GetFieldData()->GetAbstractArray("LeafReason"))
      {
        ++leaves;
        leavesWithIds += leaf->GetCellData()->GetArray("CellIds") != nullptr &&
          leaf->GetPointData()->GetArray("UnnamedPointArray0") != nullptr &&
          !leaf->GetPointData()->GetAbstractArray("Variant") &&
          std::string(ActiveName(leaf->GetCellData(), vtkDataSetAttributes::SCALARS)) ==
            "FoldingLeafId";
      }
  EXPECT(leaves > 0 && leavesWithIds == leaves,
    label << ": " << leavesWithIds << " of " << leaves << " leaves carry the expected arrays");

  vtkNew<vtkFoldingTreeUnfolder> unfolder;
  unfolder->SetInputData(tree);
  unfolder->Update();
  CheckUnfolded(input, unfolder->GetOutput(), label + " (in memory)");

  const std::string file =
    tempDir + "/TestFoldingArraySurvival_" + (doublePoints ? "double" : "float") + ".vtm";
  vtkNew<vtkXMLMultiBlockDataWriter> writer;
  writer->SetInputData(tree);
  writer->SetFileName(file.c_str());
  EXPECT(writer->Write() == 1, label << ": could not write " << file);
  vtkNew<vtkExpatSafeXMLMultiBlockDataReader> reader;
  reader->SetFileName(file.c_str());
  int readErrors = 0;
  vtkNew<vtkCallbackCommand> countErrors;
  countErrors->SetClientData(&readErrors);
  countErrors->SetCallback(
    [](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
  reader->AddObserver(vtkCommand::ErrorEvent, countErrors);
  reader->Update();
  EXPECT(readErrors == 0, label << ": reading " << file << " raised " << readErrors << " errors");
  if (readErrors != 0)
    return;
  vtkNew<vtkFoldingTreeUnfolder> unfolderRead;
  unfolderRead->SetInputConnection(reader->GetOutputPort());
  unfolderRead->Update();
  CheckUnfolded(input, unfolderRead->GetOutput(), label + " (.vtm)");
}
}

int main(int argc, char* argv[])
{
  const std::string tempDir = argc > 1 ? argv[1] : ".";
  Run(false, tempDir);
  Run(true, tempDir);
  if (failures)
    std::printf("TestFoldingArraySurvival: %d failure(s)\n", failures);
  else
    std::printf("TestFoldingArraySurvival passed\n");
  return failures ? 1 : 0;
}
