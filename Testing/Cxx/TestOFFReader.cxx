// Tests vtkOFFReader on small generated OFF files and, if a folder is given as argv[1],
// on the real meshes there (dino_cgal.off must have 7828 faces; every *.off must read).
#include "vtkOFFReader.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{
int Failures = 0;

void Check(bool ok, const std::string& what)
{
  std::cout << (ok ? "  ok:     " : "  FAILED: ") << what << "\n";
  Failures += ok ? 0 : 1;
}

struct ReadResult
{
  bool Ok = false;
  int Errors = 0;         // ErrorEvents of the reader and its executive
  std::string FirstError; // text of the reader's first error
  vtkSmartPointer<vtkPolyData> Mesh;
};

void CountError(vtkObject* caller, unsigned long, void* clientData, void* callData)
{
  auto* result = static_cast<ReadResult*>(clientData);
  if (result->Errors++ == 0 && callData && vtkOFFReader::SafeDownCast(caller))
  {
    result->FirstError = static_cast<const char*>(callData);
  }
}

ReadResult Read(const fs::path& file)
{
  ReadResult result;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(CountError);
  onError->SetClientData(&result);
  vtkNew<vtkOFFReader> reader;
  reader->AddObserver(vtkCommand::ErrorEvent, onError);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, onError);
  reader->SetFileName(file.string().c_str());
  result.Ok = reader->GetExecutive()->Update() != 0;
  result.Mesh = reader->GetOutput();
  return result;
}

fs::path WriteFile(const fs::path& dir, const std::string& name, const std::string& text)
{
  const fs::path file = dir / name;
  std::ofstream(file, std::ios::binary) << text;
  return file;
}

bool Near(double a, double b)
{
  return std::abs(a - b) < 1e-6;
}

// Sizes of the polygons of `mesh`, in order.
std::vector<vtkIdType> PolySizes(vtkPolyData* mesh)
{
  std::vector<vtkIdType> sizes;
  for (vtkIdType c = 0; c < mesh->GetPolys()->GetNumberOfCells(); ++c)
  {
    sizes.push_back(mesh->GetPolys()->GetCellSize(c));
  }
  return sizes;
}

void CheckFailure(const fs::path& file, const std::string& what, const std::string& expected)
{
  const ReadResult r = Read(file);
  Check(!r.Ok && r.Errors >= 1, what + ": Update fails with an error");
  Check(r.Mesh->GetNumberOfPoints() == 0 && r.Mesh->GetNumberOfCells() == 0,
    what + ": output is empty");
  Check(r.FirstError.find(expected) != std::string::npos,
    what + ": message contains '" + expected + "'");
}

void TestGeneratedFiles(const fs::path& dir)
{
  std::cout << "Generated files in " << dir.string() << "\n";

  const fs::path cube = WriteFile(dir,
    "cube.off",
    "# a unit cube\n"
    "OFF 8 6 12   # counts on the keyword line\n"
    "\n"
    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
    "# top\n"
    "0 0 1\n1 0 1\n1 1 1\n0 1 1\r\n"
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n"
    "\n"
    "4 1 2 6 5\n4 2 3 7 6  # comment after a face\n4 3 0 4 7");
  ReadResult r = Read(cube);
  Check(r.Ok && r.Errors == 0, "cube.off reads without error");
  Check(r.Mesh->GetNumberOfPoints() == 8, "cube.off has 8 points");
  Check(r.Mesh->GetNumberOfPolys() == 6, "cube.off has 6 polys");
  Check(PolySizes(r.Mesh) == std::vector<vtkIdType>(6, 4), "cube.off polys are quads");
  double p[3];
  r.Mesh->GetPoint(6, p);
  Check(Near(p[0], 1) && Near(p[1], 1) && Near(p[2], 1), "cube.off point 6 is (1,1,1)");
  Check(vtkOFFReader::CanReadFile(cube.string().c_str()) == 1, "CanReadFile(cube.off) == 1");

  const fs::path coff = WriteFile(dir,
    "colors.off",
    "COFF\n3 1 0\n"
    "0 0 0 1 0 0 1\n"
    "1 0 0 0 0.5 1 0.25\n"
    "0 1 0 0 0 0\n" // no alpha: opaque
    "3 0 1 2 0.1 0.2 0.3\n");
  r = Read(coff);
  auto* colors = vtkUnsignedCharArray::SafeDownCast(r.Mesh->GetPointData()->GetArray("Colors"));
  Check(r.Ok && colors && colors->GetNumberOfComponents() == 4,
    "COFF float colours -> \"Colors\" unsigned char, 4 components");
  const unsigned char expected[12] = { 255, 0, 0, 255, 0, 128, 255, 64, 0, 0, 0, 255 };
  Check(colors && colors->GetNumberOfTuples() == 3 &&
      std::equal(expected, expected + 12, colors->GetPointer(0)),
    "COFF float colours scaled to 0..255 (alpha 255 when missing)");
  Check(r.Mesh->GetNumberOfPolys() == 1, "COFF face colour values ignored");
  Check(vtkOFFReader::CanReadFile(coff.string().c_str()) == 1, "CanReadFile(COFF) == 1");

  r = Read(WriteFile(
    dir, "colors_int.off", "COFF\n3 1 0\n0 0 0 255 128 0\n1 0 0 10 20 30\n0 1 0 0 0 1\n3 0 1 2\n"));
  colors = vtkUnsignedCharArray::SafeDownCast(r.Mesh->GetPointData()->GetArray("Colors"));
  const unsigned char expectedInt[9] = { 255, 128, 0, 10, 20, 30, 0, 0, 1 };
  Check(r.Ok && colors && colors->GetNumberOfComponents() == 3 &&
      std::equal(expectedInt, expectedInt + 9, colors->GetPointer(0)),
    "COFF integer colours -> 3 components, values kept");

  r = Read(WriteFile(
    dir, "normals.off", "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 -1\n3 0 1 2\n"));
  vtkDataArray* normals = r.Mesh->GetPointData()->GetNormals();
  Check(r.Ok && normals && std::string(normals->GetName()) == "Normals" &&
      Near(normals->GetComponent(2, 2), -1),
    "NOFF -> point normals \"Normals\"");

  r = Read(WriteFile(dir,
    "cnoff.off",
    "CNOFF\n3 1 0\n0 0 0 0 0 1 1 1 1\n1 0 0 0 0 1 1 1 1\n0 1 0 0 0 1 1 1 1\n3 0 1 2\n"));
  Check(r.Ok && r.Mesh->GetPointData()->GetNormals() && r.Mesh->GetPointData()->GetArray("Colors"),
    "CNOFF -> normals and colours");

  r = Read(WriteFile(dir,
    "mixed.off",
    "OFF\n6 3\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n2 1 0\n"
    "3 0 1 2\n4 0 1 2 3\n5 0 1 4 5 2\n"));
  Check(r.Ok && PolySizes(r.Mesh) == std::vector<vtkIdType>({ 3, 4, 5 }),
    "mixed 3/4/5-gons kept as polys (no edge count in header)");

  const fs::path badIndex =
    WriteFile(dir, "bad_index.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 3\n");
  CheckFailure(badIndex, "face index out of range", "bad_index.off:7: vertex index 3 out of range");
  Check(vtkOFFReader::CanReadFile(badIndex.string().c_str()) == 1, "CanReadFile(bad_index) == 1");

  CheckFailure(dir / "missing.off", "missing file", "missing.off: cannot open");
  Check(vtkOFFReader::CanReadFile((dir / "missing.off").string().c_str()) == 0,
    "CanReadFile(missing) == 0");
  CheckFailure(WriteFile(dir, "truncated.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n"),
    "truncated vertices",
    "unexpected end of file after 3 of 4 vertices");
  CheckFailure(WriteFile(dir, "few_faces.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
    "truncated faces",
    "unexpected end of file after 1 of 2 faces");
  CheckFailure(WriteFile(dir, "short_face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n"),
    "face with missing index",
    "short_face.off:6: missing vertex index");
  CheckFailure(WriteFile(dir, "bad_number.off", "OFF\n3 1 0\n0 0 0\n1 x2 0\n0 1 0\n3 0 1 2\n"),
    "unparsable coordinate",
    "bad_number.off:4: invalid y coordinate 'x2'");
  CheckFailure(WriteFile(dir, "nan.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 nan 0\n3 0 1 2\n"),
    "NaN coordinate",
    "nan.off:5: invalid y coordinate 'nan'");
  CheckFailure(
    WriteFile(dir, "huge.off", "OFF\n100000000 1 0\n0 0 0\n"), "absurd counts", "invalid counts");
  const fs::path ply = WriteFile(dir, "not_off.off", "ply\nformat ascii 1.0\n");
  CheckFailure(ply, "wrong header", "not an OFF file");
  Check(vtkOFFReader::CanReadFile(ply.string().c_str()) == 0, "CanReadFile(ply header) == 0");
  CheckFailure(WriteFile(dir, "empty.off", "# nothing\n"), "empty file", "empty file");
}

void TestRealMeshes(const fs::path& dir)
{
  std::cout << "Real meshes in " << dir.string() << "\n";
  if (!fs::is_directory(dir))
  {
    Check(false, dir.string() + " is a directory");
    return;
  }
  ReadResult dino = Read(dir / "dino_cgal.off");
  Check(dino.Ok && dino.Errors == 0, "dino_cgal.off reads without error");
  Check(dino.Mesh->GetNumberOfPolys() == 7828, "dino_cgal.off has 7828 polys");
  Check(dino.Mesh->GetNumberOfPoints() == 3916, "dino_cgal.off has 3916 points");
  auto* colors = vtkUnsignedCharArray::SafeDownCast(dino.Mesh->GetPointData()->GetArray("Colors"));
  Check(colors && colors->GetNumberOfComponents() == 4 && colors->GetValue(0) == 192 &&
      colors->GetValue(3) == 255,
    "dino_cgal.off (COFF) colours are (192,192,192,255)");

  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir))
  {
    if (entry.path().extension() == ".off")
    {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files)
  {
    std::string keyword;
    long nv = -1, nf = -1;
    std::ifstream(file) >> keyword >> nv >> nf; // header of these files: keyword, nv nf ne
    const auto start = std::chrono::steady_clock::now();
    const ReadResult r = Read(file);
    const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::cout << "  " << file.filename().string() << ": " << r.Mesh->GetNumberOfPoints()
              << " points, " << r.Mesh->GetNumberOfPolys() << " polys (" << ms << " ms)\n";
    Check(r.Ok && r.Errors == 0 && r.Mesh->GetNumberOfPoints() == nv &&
        r.Mesh->GetNumberOfPolys() == nf,
      file.filename().string() + " matches its header counts");
  }
}
}

int main(int argc, char* argv[])
{
  const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
  const fs::path dir = fs::temp_directory_path() / ("TestOFFReader-" + std::to_string(stamp));
  fs::create_directories(dir);
  TestGeneratedFiles(dir);
  if (argc > 1)
  {
    TestRealMeshes(argv[1]);
  }
  fs::remove_all(dir);
  std::cout << (Failures ? std::to_string(Failures) + " check(s) FAILED" : "all checks passed")
            << "\n";
  return Failures ? 1 : 0;
}
