// Bytes of a mesh in the usual containers and coders next to its compact folding tree (.fmz),
// with the proved Hausdorff distance of the decompressed mesh (issue 18). Prints numbers; not
// a test. Usage:
//   BenchmarkCompression [--threads N] [--bits N] [--rotation] [--search] [--fold-defaults]
//                        [--min-faces N] DIR_OR_MESH...
// The fold as `foldingmeshes compress` folds: its own defaults for --keep and --min-faces
// (CompressionSearch.h; --fold-defaults: the fold command's instead; --min-faces N: that
// MinimumFaces instead of compress's, as `compress --min-faces N`; compress's rotation rule,
// --rotation-when-axial - the fold command's default too since 2026-12-07 - and a tree with
// rotation nodes also folded without them, unless --rotation).
// --rotation: the builder's RotationNodes on, issue 22. --search: as `foldingmeshes compress
// --search`, the fold settings of CompressionSearch.h are tried too and the smallest file is kept;
// the last column names the settings that made it, t_c counts every fold. Columns: faces; binary
// PLY; zlib'd VTP (inline binary); Draco at draco_encoder's defaults (11 position bits, -cl 7);
// Draco at the tree's bits; the .fmz; the ratio .fmz / Draco at the same bits; the .fmz's
// quantisation bits; the encodings the writer's proof added (pr: every candidate written with
// the mesh as its original, vtkFoldingTreeCompactWriter::SetOriginalData, as compress does);
// proved Hausdorff of the decompressed mesh to the input over the diagonal (root epsilon:
// 0.02); compress (fold + encode + the writer's proof) and decompress (decode + unfold)
// seconds; the decompressed mesh's faces over the input's.
#include "CompressionSearch.h"
#include "MeshIO.h"
#include "ProcessMemory.h"
#include "vtkFoldingTreeBuilder.h"
#include "vtkFoldingTreeCompactReader.h"
#include "vtkFoldingTreeCompactWriter.h"
#include "vtkFoldingTreeUnfolder.h"

#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPLYWriter.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkTriangleFilter.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;
double Since(Clock::time_point t)
{
  return std::chrono::duration<double>(Clock::now() - t).count();
}

/// Draco bytes of the mesh's positions and triangles (what draco_encoder makes of a PLY).
size_t DracoBytes(vtkPolyData* mesh, int bits)
{
  draco::Mesh d;
  const vtkIdType np = mesh->GetNumberOfPoints();
  d.set_num_points(static_cast<uint32_t>(np));
  draco::GeometryAttribute ga;
  ga.Init(draco::GeometryAttribute::POSITION, nullptr, 3, draco::DT_FLOAT32, false, 12, 0);
  const int id = d.AddAttribute(ga, true, static_cast<uint32_t>(np));
  for (vtkIdType i = 0; i < np; ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    const float f[3] = { float(p[0]), float(p[1]), float(p[2]) };
    d.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(static_cast<uint32_t>(i)), f);
  }
  auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    if (n != 3)
      continue;
    draco::Mesh::Face face;
    for (int k = 0; k < 3; ++k)
      face[k] = draco::PointIndex(static_cast<uint32_t>(ids[k]));
    d.AddFace(face);
  }
  d.DeduplicateAttributeValues();
  d.DeduplicatePointIds();
  draco::Encoder encoder;
  encoder.SetSpeedOptions(3, 3); // draco_encoder -cl 7 (its default)
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, bits);
  draco::EncoderBuffer buffer;
  if (!encoder.EncodeMeshToBuffer(d, &buffer).ok())
    return 0;
  return buffer.size();
}

size_t PlyBytes(vtkPolyData* mesh)
{
  const std::string file = (std::filesystem::temp_directory_path() / "benchmark.ply").string();
  vtkNew<vtkPolyData> bare; // positions and triangles only
  bare->SetPoints(mesh->GetPoints());
  bare->SetPolys(mesh->GetPolys());
  vtkNew<vtkPLYWriter> w;
  w->SetInputData(bare);
  w->SetFileTypeToBinary();
  w->SetFileName(file.c_str());
  w->Write();
  std::error_code ec;
  const size_t size = static_cast<size_t>(std::filesystem::file_size(file, ec));
  std::filesystem::remove(file, ec);
  return size;
}

size_t VtpBytes(vtkPolyData* mesh)
{
  vtkNew<vtkPolyData> bare; // positions and triangles only, like the others
  bare->SetPoints(mesh->GetPoints());
  bare->SetPolys(mesh->GetPolys());
  vtkNew<vtkXMLPolyDataWriter> w;
  w->SetInputData(bare);
  w->SetDataModeToBinary();
  w->WriteToOutputStringOn();
  w->Write();
  return w->GetOutputString().size();
}

double Field(vtkPolyData* mesh, const char* name)
{
  vtkDataArray* a = mesh->GetFieldData()->GetArray(name);
  return a ? a->GetTuple1(0) : -1.0;
}

const std::map<std::string, std::string> Table1 = { { "dino_cgal", "Dino" },
  { "horse_psb397", "Horse" },
  { "chair_psb108", "Chair" },
  { "table_psb152", "Table" },
  { "hammer_oded_dec4360", "Hammer" },
  { "triceratops_cgal", "Triceratops" },
  { "eagle_psb258", "Eagle" },
  { "queen_chess_quaddamage", "Queen" } };
}

int main(int argc, char* argv[])
{
  foldingmeshes::cli::KeepFreedMemoryForReuse(); // as the command-line program does
  vtkSMPTools::SetBackend("STDThread");
  int bits = 0;
  bool rotation = false, search = false, foldDefaults = false;
  int minimumFaces = 0; // --min-faces N: the first fold's MinimumFaces (0: as compress)
  std::vector<std::string> paths;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--threads" && i + 1 < argc)
      vtkSMPTools::Initialize(std::atoi(argv[++i]));
    else if (a == "--bits" && i + 1 < argc)
      bits = std::atoi(argv[++i]);
    else if (a == "--rotation")
      rotation = true;
    else if (a == "--search")
      search = true;
    else if (a == "--fold-defaults")
      foldDefaults = true;
    else if (a == "--min-faces" && i + 1 < argc)
      minimumFaces = std::atoi(argv[++i]);
    else
    {
      const std::vector<std::string> found = foldingmeshes::MeshFiles(a);
      paths.insert(paths.end(), found.begin(), found.end());
    }
  }
  if (paths.empty())
  {
    std::fprintf(stderr,
      "usage: %s [--threads N] [--bits N] [--rotation] [--search] [--fold-defaults] "
      "[--min-faces N] DIR_OR_MESH...\n",
      argv[0]);
    return 1;
  }
  std::printf("%-28s %7s %9s %9s %8s %8s %8s %6s %4s %2s %8s %6s %6s %6s %s\n",
    "mesh",
    "faces",
    "PLY",
    "VTP",
    "Draco11",
    "DracoQ",
    "fmz",
    "fmz/Dq",
    "Q",
    "pr",
    "Hmax/dg",
    "t_c",
    "t_d",
    "dec/in",
    "fold settings added (none: the fold command's defaults)");
  std::vector<double> ratios, table1Ratios;
  std::vector<std::string> table1Rows;
  for (const std::string& path : paths)
  {
    std::string error;
    vtkSmartPointer<vtkPolyData> input = foldingmeshes::ReadMesh(path, error);
    if (!input)
    {
      std::printf("%-28s unreadable: %s\n", path.c_str(), error.c_str());
      continue;
    }
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputData(input);
    triangles->PassVertsOff();
    triangles->PassLinesOff();
    triangles->Update();
    vtkPolyData* mesh = triangles->GetOutput();
    const std::string stem = std::filesystem::path(path).stem().string();

    auto start = Clock::now();
    // compress's own settings (or --fold-defaults), a tree that got rotation nodes by
    // compress's rotation rule also without them, then (--search) the variants whose settings
    // were not folded yet; the smallest file wins, the earlier on ties.
    std::string bytes, chosen;
    int q = 0;
    vtkSmartPointer<vtkFoldingTreeCompactWriter> chosenWriter;
    std::set<foldingmeshes::FoldSearchKey> folded; // RotationNodes WHEN_AXIAL as decided
    bool axial = false;                            // ... by the first fold
    // Folds and encodes with `builder` (unless its settings were folded); false: skipped.
    auto fold = [&](vtkFoldingTreeBuilder* builder, const std::string& label)
    {
      if (folded.count(foldingmeshes::DecidedKey(foldingmeshes::FoldSettingsKey(builder), axial)))
        return false;
      auto writer = vtkSmartPointer<vtkFoldingTreeCompactWriter>::New();
      writer->SetInputConnection(builder->GetOutputPort(0));
      writer->WriteToOutputStringOn();
      writer->SetQuantizationBits(bits);
      writer->SetOriginalData(mesh); // as compress: proved, more bits where needed
      writer->Write();
      if (folded.empty())
        axial = foldingmeshes::TriedRotationNodes(builder);
      folded.insert(foldingmeshes::DecidedKey(foldingmeshes::FoldSettingsKey(builder), axial));
      const std::string candidate = writer->GetOutputString();
      if (!candidate.empty() && (bytes.empty() || candidate.size() < bytes.size()))
      {
        bytes = candidate;
        q = writer->GetQuantizationBitsUsed();
        chosen = label;
        chosenWriter = writer;
      }
      return true;
    };
    // The user's settings: the fold command's defaults and --rotation / --min-faces, then
    // compress's own (`rotationRule`: its --rotation-when-axial) unless --fold-defaults.
    auto ownSettings = [&](vtkFoldingTreeBuilder* builder, bool rotationRule)
    {
      builder->SetInputData(mesh);
      if (rotation || !rotationRule) // else the rule's (or the fold command's) WHEN_AXIAL
        builder->SetRotationNodes(rotation);
      std::string label;
      if (minimumFaces > 0)
      {
        builder->SetUseMinimumFaces(true);
        builder->SetMinimumFaces(minimumFaces);
        label = "--min-faces " + std::to_string(minimumFaces);
      }
      const std::string added = foldDefaults
        ? std::string()
        : foldingmeshes::ApplyCompressFoldDefaults(
            builder, false, minimumFaces > 0, rotation || !rotationRule);
      return label + (label.empty() || added.empty() ? "" : " ") + added;
    };
    vtkNew<vtkFoldingTreeBuilder> first;
    fold(first, ownSettings(first, true));
    const bool rotationTree = foldingmeshes::KeptRotationNodes(first);
    if (!rotationTree) // looked for rotation nodes and kept none: the fold without them too
      folded.insert(foldingmeshes::DecidedKey(foldingmeshes::FoldSettingsKey(first), false));
    // Labelled as the options that fold them again: rotation nodes off differs from the fold
    // command's default on an axial mesh.
    if (!rotation && rotationTree)
    {
      vtkNew<vtkFoldingTreeBuilder> without;
      fold(without, foldingmeshes::WithoutRotationNodes(ownSettings(without, false)));
    }
    for (size_t k = 0; search && k < std::size(foldingmeshes::FoldSearchVariants); ++k)
    {
      vtkNew<vtkFoldingTreeBuilder> builder;
      builder->SetInputData(mesh);
      builder->SetRotationNodes(rotation);
      if (minimumFaces > 0) // as compress: the variants on top of the options given
      {
        builder->SetUseMinimumFaces(true);
        builder->SetMinimumFaces(minimumFaces);
      }
      const foldingmeshes::FoldSearchVariant& v = foldingmeshes::FoldSearchVariants[k];
      foldingmeshes::ApplyFoldSearchVariant(builder, v);
      const bool off = !rotation && !v.rotationNodes && !v.rotationWhenAxial;
      fold(builder, off && axial ? foldingmeshes::WithoutRotationNodes(v.options) : v.options);
    }
    if (bytes.empty())
    {
      std::printf("%-28s compress failed\n", stem.c_str());
      continue;
    }
    const int proofRetries = chosenWriter ? chosenWriter->GetProofRetries() : 0;
    const double compressSeconds = Since(start);
    const std::string file = (std::filesystem::temp_directory_path() / (stem + ".fmz")).string();
    std::ofstream(file, std::ios::binary).write(bytes.data(), bytes.size());
    start = Clock::now();
    vtkNew<vtkFoldingTreeCompactReader> reader;
    reader->SetFileName(file.c_str());
    vtkNew<vtkFoldingTreeUnfolder> unfolder;
    unfolder->SetInputConnection(reader->GetOutputPort());
    unfolder->Update();
    const double decompressSeconds = Since(start);
    // The decompressed mesh's faces for the input's (a rotation tree's sector cut along its
    // half-planes comes back with more where the budgets do not let the unfolder thin it).
    const double facesBack = double(unfolder->GetOutput()->GetNumberOfCells()) /
      double(std::max<vtkIdType>(1, mesh->GetNumberOfCells()));
    unfolder->SetOriginalData(mesh); // the proved bound, outside the timing
    unfolder->Update();
    const double bound = Field(unfolder->GetOutput(), "HausdorffToOriginalBoundRelative");
    std::filesystem::remove(file);

    const size_t draco11 = DracoBytes(mesh, 11), dracoQ = DracoBytes(mesh, q);
    const double ratio = dracoQ ? double(bytes.size()) / double(dracoQ) : 0.0;
    ratios.push_back(ratio);
    char row[512];
    std::snprintf(row,
      sizeof(row),
      "%-28s %7lld %9zu %9zu %8zu %8zu %8zu %6.3f %4d %2d %8.4f %6.3f %6.3f %6.3f %s",
      stem.c_str(),
      static_cast<long long>(mesh->GetNumberOfCells()),
      PlyBytes(mesh),
      VtpBytes(mesh),
      draco11,
      dracoQ,
      bytes.size(),
      ratio,
      q,
      proofRetries,
      bound,
      compressSeconds,
      decompressSeconds,
      facesBack,
      chosen.c_str());
    std::printf("%s\n", row);
    std::fflush(stdout);
    const auto t = Table1.find(stem);
    if (t != Table1.end())
    {
      table1Ratios.push_back(ratio);
      table1Rows.push_back(t->second + std::string(": ") + row);
    }
  }
  auto median = [](std::vector<double> v)
  {
    if (v.empty())
      return 0.0;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
  };
  std::printf("\nall %zu meshes: fmz / Draco at the same bits: median %.3f, max %.3f\n",
    ratios.size(),
    median(ratios),
    ratios.empty() ? 0.0 : *std::max_element(ratios.begin(), ratios.end()));
  if (!table1Rows.empty())
  {
    std::printf("Table 1 stand-ins (%zu): median %.3f, max %.3f\n",
      table1Rows.size(),
      median(table1Ratios),
      *std::max_element(table1Ratios.begin(), table1Ratios.end()));
    for (const std::string& r : table1Rows)
      std::printf("  %s\n", r.c_str());
  }
  return 0;
}
