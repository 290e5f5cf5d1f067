// vtkExpatSafeXMLPolyDataReader and vtkExpatSafeXMLMultiBlockDataReader (VTK issue 19258: with
// expat's reparse deferral, Debian 12's current libexpat1, VTK <= 9.2 cannot read files whose
// data is in the XML writers' default appended mode):
// - a mesh with point, cell and field arrays (float, double, id and unsigned char; one array
//   larger than the parser's 64 KB read chunk) written in appended raw, appended base64,
//   inline binary and ASCII, compressed or not, reads back identical with the safe reader,
//   with no error;
// - a multiblock of such meshes, with block names and nested blocks, written in appended and
//   inline binary mode, reads back with the same structure, names and data;
// - the stock reader: where it cannot read an appended file (this machine's expat has reparse
//   deferral), the safe reader's ExpatHasReparseDeferral() must say so (printed either way);
// - bad files fail with an error and no crash: a missing file, a truncated appended file, a
//   .vtm whose piece is missing (the block is left out, not an empty mesh).
#include "TestExpect.h"
#include "vtkExpatSafeXMLMultiBlockDataReader.h"
#include "vtkExpatSafeXMLPolyDataReader.h"

#include <vtkCallbackCommand.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkCompositeDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLMultiBlockDataWriter.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace
{
int failures = 0;
#define EXPECT(cond, msg) FOLDINGMESHES_EXPECT(failures, cond, msg)

/// Counts the ErrorEvents of the algorithms it observes (and keeps them off the console).
struct ErrorCounter
{
  int errors = 0;
  vtkNew<vtkCallbackCommand> command;
  ErrorCounter()
  {
    command->SetClientData(this);
    command->SetCallback([](vtkObject*, unsigned long, void* self, void*)
      { ++static_cast<ErrorCounter*>(self)->errors; });
  }
  void Observe(vtkObject* object) { object->AddObserver(vtkCommand::ErrorEvent, command); }
};

/// A sphere with arrays of several types; `seed` makes the values of two meshes differ.
vtkSmartPointer<vtkPolyData> MakeMesh(int resolution, double seed)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution / 2);
  sphere->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  sphere->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(sphere->GetOutput());
  const vtkIdType n = mesh->GetNumberOfPoints(), m = mesh->GetNumberOfCells();
  vtkNew<vtkFloatArray> pointScalar;
  pointScalar->SetName("PointScalar");
  vtkNew<vtkIdTypeArray> pointIds;
  pointIds->SetName("PointIds");
  for (vtkIdType i = 0; i < n; ++i)
  {
    pointScalar->InsertNextValue(static_cast<float>(seed + 0.001 * i));
    pointIds->InsertNextValue(7 * i + static_cast<vtkIdType>(seed));
  }
  vtkNew<vtkDoubleArray> cellVector;
  cellVector->SetName("CellVector");
  cellVector->SetNumberOfComponents(3);
  vtkNew<vtkUnsignedCharArray> cellColor;
  cellColor->SetName("CellColor");
  for (vtkIdType c = 0; c < m; ++c)
  {
    cellVector->InsertNextTuple3(seed, 1.0 / (c + 1), -0.5 * c);
    cellColor->InsertNextValue(static_cast<unsigned char>((c + static_cast<int>(seed)) % 256));
  }
  vtkNew<vtkDoubleArray> field;
  field->SetName("FieldValue");
  field->InsertNextValue(seed * 3.5);
  mesh->GetPointData()->AddArray(pointScalar);
  mesh->GetPointData()->AddArray(pointIds);
  mesh->GetCellData()->AddArray(cellVector);
  mesh->GetCellData()->AddArray(cellColor);
  mesh->GetFieldData()->AddArray(field);
  return mesh;
}

bool SameAttributes(vtkFieldData* a, vtkFieldData* b)
{
  if (a->GetNumberOfArrays() != b->GetNumberOfArrays())
    return false;
  for (int k = 0; k < a->GetNumberOfArrays(); ++k)
  {
    vtkDataArray* x = a->GetArray(k);
    vtkDataArray* y = x ? b->GetArray(x->GetName()) : nullptr;
    if (!x || !y || x->GetNumberOfTuples() != y->GetNumberOfTuples() ||
      x->GetNumberOfComponents() != y->GetNumberOfComponents())
      return false;
    for (vtkIdType i = 0; i < x->GetNumberOfTuples(); ++i)
      for (int c = 0; c < x->GetNumberOfComponents(); ++c)
        if (x->GetComponent(i, c) != y->GetComponent(i, c))
          return false;
  }
  return true;
}

/// Points, polygons and every array equal (values compared exactly).
bool SameMesh(vtkPolyData* a, vtkPolyData* b)
{
  if (!a || !b || a->GetNumberOfPoints() != b->GetNumberOfPoints() ||
    a->GetNumberOfCells() != b->GetNumberOfCells())
    return false;
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    if (p[0] != q[0] || p[1] != q[1] || p[2] != q[2])
      return false;
  }
  vtkNew<vtkIdList> x, y;
  for (vtkIdType c = 0; c < a->GetNumberOfCells(); ++c)
  {
    a->GetCellPoints(c, x);
    b->GetCellPoints(c, y);
    if (x->GetNumberOfIds() != y->GetNumberOfIds())
      return false;
    for (vtkIdType k = 0; k < x->GetNumberOfIds(); ++k)
      if (x->GetId(k) != y->GetId(k))
        return false;
  }
  return SameAttributes(a->GetPointData(), b->GetPointData()) &&
    SameAttributes(a->GetCellData(), b->GetCellData()) &&
    SameAttributes(a->GetFieldData(), b->GetFieldData());
}

struct WriteMode
{
  const char* name;
  int dataMode;
  bool encodeAppended;
  bool compress;
};

const WriteMode modes[] = {
  { "appended-raw", vtkXMLWriter::Appended, false, true },
  { "appended-raw-uncompressed", vtkXMLWriter::Appended, false, false },
  { "appended-base64", vtkXMLWriter::Appended, true, true },
  { "binary", vtkXMLWriter::Binary, false, true },
  { "ascii", vtkXMLWriter::Ascii, false, false },
};

void Configure(vtkXMLWriter* writer, const WriteMode& mode)
{
  writer->SetDataMode(mode.dataMode);
  writer->SetEncodeAppendedData(mode.encodeAppended);
  if (mode.compress)
    writer->SetCompressorTypeToZLib();
  else
    writer->SetCompressorTypeToNone();
}

void TestPolyData(const std::string& dir)
{
  // 300 x 150 points: the PointIds array alone is 350 KB, beyond one 64 KB parser chunk.
  vtkSmartPointer<vtkPolyData> mesh = MakeMesh(300, 2.0);
  int stockFailures = 0;
  for (const WriteMode& mode : modes)
  {
    const std::string file = dir + "/TestExpatSafeXMLReaders_" + mode.name + ".vtp";
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(mesh);
    writer->SetFileName(file.c_str());
    Configure(writer, mode);
    EXPECT(writer->Write() == 1, mode.name << ": cannot write " << file);

    vtkNew<vtkExpatSafeXMLPolyDataReader> reader;
    ErrorCounter errors;
    errors.Observe(reader);
    errors.Observe(reader->GetExecutive());
    reader->SetFileName(file.c_str());
    reader->Update();
    EXPECT(
      errors.errors == 0, mode.name << ": the safe reader raised " << errors.errors << " errors");
    EXPECT(SameMesh(mesh, reader->GetOutput()),
      mode.name << ": read back " << reader->GetOutput()->GetNumberOfPoints() << " points / "
                << reader->GetOutput()->GetNumberOfCells() << " cells, not the mesh written");

    vtkNew<vtkXMLPolyDataReader> stock;
    ErrorCounter stockErrors;
    stockErrors.Observe(stock);
    stockErrors.Observe(stock->GetExecutive());
    stock->SetFileName(file.c_str());
    stock->Update();
    const bool stockRead = stockErrors.errors == 0 && SameMesh(mesh, stock->GetOutput());
    stockFailures += !stockRead;
    std::printf("%-26s safe reader %s, stock vtkXMLPolyDataReader %s\n",
      mode.name,
      SameMesh(mesh, reader->GetOutput()) ? "ok" : "FAILED",
      stockRead ? "ok" : "cannot read it");
    if (mode.dataMode != vtkXMLWriter::Appended)
      EXPECT(stockRead, mode.name << ": the stock reader cannot read an inline file");
  }
  const bool deferral = vtkExpatSafeXMLPolyDataReader::ExpatHasReparseDeferral();
  std::printf("expat reparse deferral: %s; the stock reader failed on %d of %d files\n",
    deferral ? "present (switched off by the safe readers)" : "absent",
    stockFailures,
    static_cast<int>(sizeof(modes) / sizeof(modes[0])));
  EXPECT(stockFailures == 0 || deferral,
    "the stock reader failed but the safe reader saw no reparse deferral to switch off");
}

vtkSmartPointer<vtkMultiBlockDataSet> MakeTree()
{
  auto root = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  vtkNew<vtkMultiBlockDataSet> inner;
  inner->SetNumberOfBlocks(2);
  inner->SetBlock(0, MakeMesh(40, 3.0));
  inner->GetMetaData(0u)->Set(vtkCompositeDataSet::NAME(), "Leaf 2");
  inner->SetBlock(1, MakeMesh(24, 4.0));
  inner->GetMetaData(1u)->Set(vtkCompositeDataSet::NAME(), "Leaf 3");
  root->SetNumberOfBlocks(2);
  root->SetBlock(0, inner);
  root->GetMetaData(0u)->Set(vtkCompositeDataSet::NAME(), "Fold 1 (depth 1)");
  root->SetBlock(1, MakeMesh(200, 5.0));
  root->GetMetaData(1u)->Set(vtkCompositeDataSet::NAME(), "Tree");
  return root;
}

bool SameTree(vtkMultiBlockDataSet* a, vtkMultiBlockDataSet* b, const std::string& label)
{
  if (!a || !b || a->GetNumberOfBlocks() != b->GetNumberOfBlocks())
    return false;
  for (unsigned int k = 0; k < a->GetNumberOfBlocks(); ++k)
  {
    const char* na = a->HasMetaData(k) ? a->GetMetaData(k)->Get(vtkCompositeDataSet::NAME()) : "";
    const char* nb = b->HasMetaData(k) ? b->GetMetaData(k)->Get(vtkCompositeDataSet::NAME()) : "";
    if (std::string(na ? na : "") != std::string(nb ? nb : ""))
      return false;
    auto* ma = vtkMultiBlockDataSet::SafeDownCast(a->GetBlock(k));
    auto* mb = vtkMultiBlockDataSet::SafeDownCast(b->GetBlock(k));
    if (ma || mb)
    {
      if (!SameTree(ma, mb, label))
        return false;
    }
    else if (!SameMesh(vtkPolyData::SafeDownCast(a->GetBlock(k)),
               vtkPolyData::SafeDownCast(b->GetBlock(k))))
      return false;
  }
  return true;
}

void TestMultiBlock(const std::string& dir)
{
  vtkSmartPointer<vtkMultiBlockDataSet> tree = MakeTree();
  for (const WriteMode& mode : modes)
  {
    const std::string file = dir + "/TestExpatSafeXMLReaders_tree_" + mode.name + ".vtm";
    vtkNew<vtkXMLMultiBlockDataWriter> writer;
    writer->SetInputData(tree);
    writer->SetFileName(file.c_str());
    Configure(writer, mode);
    EXPECT(writer->Write() == 1, mode.name << ": cannot write " << file);
    vtkNew<vtkExpatSafeXMLMultiBlockDataReader> reader;
    ErrorCounter errors;
    errors.Observe(reader);
    errors.Observe(reader->GetExecutive());
    reader->SetFileName(file.c_str());
    reader->Update();
    EXPECT(errors.errors == 0, mode.name << " .vtm: " << errors.errors << " errors");
    EXPECT(SameTree(tree, vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput()), mode.name),
      mode.name << " .vtm: the tree read back differs (structure, names or data)");
  }
}

void TestBadFiles(const std::string& dir)
{
  namespace fs = std::filesystem;
  // A missing file.
  {
    vtkNew<vtkExpatSafeXMLPolyDataReader> reader;
    ErrorCounter errors;
    errors.Observe(reader);
    errors.Observe(reader->GetExecutive());
    reader->SetFileName((dir + "/no_such_file.vtp").c_str());
    reader->Update();
    EXPECT(errors.errors > 0, "a missing .vtp raised no error");
    EXPECT(reader->GetOutput()->GetNumberOfPoints() == 0, "a missing .vtp gave points");
  }
  // A truncated appended file: the header is complete, the binary data cut short.
  {
    const std::string whole = dir + "/TestExpatSafeXMLReaders_appended-raw.vtp";
    const std::string cut = dir + "/TestExpatSafeXMLReaders_truncated.vtp";
    std::ifstream in(whole, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT(bytes.size() > 1000, "no appended file to truncate");
    std::ofstream(cut, std::ios::binary).write(bytes.data(), bytes.size() / 2);
    vtkNew<vtkExpatSafeXMLPolyDataReader> reader;
    ErrorCounter errors;
    errors.Observe(reader);
    errors.Observe(reader->GetExecutive());
    reader->SetFileName(cut.c_str());
    reader->Update();
    EXPECT(errors.errors > 0, "a truncated appended .vtp raised no error");
  }
  // A .vtm whose piece is gone: the block is left out (null) with an error.
  {
    const std::string file = dir + "/TestExpatSafeXMLReaders_tree_appended-raw.vtm";
    const std::string copy = dir + "/TestExpatSafeXMLReaders_tree_missing.vtm";
    const std::string pieces = dir + "/TestExpatSafeXMLReaders_tree_missing";
    std::error_code ec;
    fs::remove_all(pieces, ec);
    fs::copy(dir + "/TestExpatSafeXMLReaders_tree_appended-raw", pieces, ec);
    EXPECT(!ec, "cannot copy the pieces: " << ec.message());
    std::ifstream in(file);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string from = "TestExpatSafeXMLReaders_tree_appended-raw/";
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at))
      text.replace(at, from.size(), "TestExpatSafeXMLReaders_tree_missing/");
    std::ofstream(copy) << text;
    fs::remove(pieces + "/TestExpatSafeXMLReaders_tree_appended-raw_1.vtp", ec);
    EXPECT(!ec, "cannot remove a piece: " << ec.message());
    vtkNew<vtkExpatSafeXMLMultiBlockDataReader> reader;
    ErrorCounter errors;
    errors.Observe(reader);
    errors.Observe(reader->GetExecutive());
    reader->SetFileName(copy.c_str());
    reader->Update();
    auto* out = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
    EXPECT(errors.errors > 0, "a .vtm with a missing piece raised no error");
    int nullLeaves = 0;
    auto* inner = out && out->GetNumberOfBlocks() == 2
      ? vtkMultiBlockDataSet::SafeDownCast(out->GetBlock(0))
      : nullptr;
    if (inner)
      for (unsigned int k = 0; k < inner->GetNumberOfBlocks(); ++k)
        nullLeaves += inner->GetBlock(k) == nullptr;
    EXPECT(nullLeaves == 1, "the missing piece is not a null block (" << nullLeaves << " null)");
  }
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string dir = argc > 1 ? argv[1] : ".";
  TestPolyData(dir);
  TestMultiBlock(dir);
  TestBadFiles(dir);
  if (failures)
    std::printf("TestExpatSafeXMLReaders: %d failure(s)\n", failures);
  else
    std::printf("TestExpatSafeXMLReaders passed\n");
  return failures ? 1 : 0;
}
