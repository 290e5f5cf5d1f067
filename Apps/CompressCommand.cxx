// foldingmeshes compress: a mesh folded and written as a compact folding tree (.fmz), with
// compress's own defaults for --keep and --min-faces (CompressionSearch.h). Its counterpart,
// decompress, is the unfold command on a .fmz file (FoldCommands.cxx). With --search, a few
// other fold settings are tried as well and the smallest file is kept.
#include "CompressionSearch.h"
#include "FoldCommandSupport.h"
#include "MeshIO.h"
#include "vtkFoldingTreeCompactWriter.h"

#include <vtkNew.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace foldingmeshes
{
namespace cli
{
namespace
{
/// One fold and write: the builder (for the tree's numbers) and the writer (bytes, bits).
struct CompressedCandidate
{
  vtkSmartPointer<vtkFoldingTreeBuilder> builder;
  vtkSmartPointer<vtkFoldingTreeCompactWriter> writer;
  long long bytes = 0;
};

/// A builder with `f`'s settings and (if any) `variant`'s.
vtkSmartPointer<vtkFoldingTreeBuilder> MakeBuilder(const FoldSettings& f,
  const FoldSearchVariant* variant)
{
  auto builder = vtkSmartPointer<vtkFoldingTreeBuilder>::New();
  ConfigureBuilder(builder, f);
  if (variant)
    ApplyFoldSearchVariant(builder, *variant);
  return builder;
}

/// Folds `mesh` with c.builder's settings and writes the tree to `path`; false with `error`
/// (and `code`: 2 the fold failed, 3 the file could not be written).
bool FoldAndWrite(vtkPolyData* mesh,
  const FoldSettings& f,
  int bits,
  bool keepArrays,
  const std::string& path,
  CompressedCandidate& c,
  std::string& error,
  int& code)
{
  c.builder->SetInputData(mesh);
  if (!RunFilter(c.builder, "folding", f.quiet, error))
  {
    error = f.meshPath + ": " + error;
    code = 2;
    return false;
  }
  c.writer = vtkSmartPointer<vtkFoldingTreeCompactWriter>::New();
  c.writer->SetInputConnection(c.builder->GetOutputPort(0));
  c.writer->SetFileName(path.c_str());
  c.writer->SetQuantizationBits(bits);
  c.writer->SetStoreUserArrays(keepArrays);
  if (!MakeOutdir(f.outdir, error) || !RunFilter(c.writer, "writing", true, error))
  {
    code = 3;
    return false;
  }
  c.bytes = static_cast<long long>(c.writer->GetBytesWritten());
  return true;
}
}

int Compress(int argc, char* argv[])
{
  // --quantization-bits and --keep-arrays are compress's own; the rest are the fold command's.
  int bits = 0;
  bool keepArrays = false, search = false;
  std::vector<char*> foldArguments;
  for (int i = 0; i < argc; ++i)
  {
    if (std::string(argv[i]) == "--quantization-bits")
    {
      if (i + 1 >= argc)
        throw std::runtime_error("missing value after --quantization-bits");
      const std::string value = argv[++i];
      bits = value == "auto" ? 0 : ParseInteger("--quantization-bits", value, 6, 24);
    }
    else if (std::string(argv[i]) == "--keep-arrays")
      keepArrays = true;
    else if (std::string(argv[i]) == "--search")
      search = true;
    else
      foldArguments.push_back(argv[i]);
  }
  const FoldSettings f =
    ParseFoldArguments(static_cast<int>(foldArguments.size()), foldArguments.data());
  if (f.keepProjectedPoints || f.keepCopyDensity || f.noStitch || f.noCloseHoles)
    throw std::runtime_error("unfolding options belong to decompress, not compress");
  if (f.distanceLocator)
    throw std::runtime_error("--distance-locator is an option of roundtrip");
  std::string error;
  vtkSmartPointer<vtkPolyData> mesh = foldingmeshes::ReadMesh(f.meshPath, error);
  if (!mesh)
  {
    std::cerr << "foldingmeshes: " << error << "\n";
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  const std::string stem = std::filesystem::path(f.meshPath).stem().string();
  const std::string output = (std::filesystem::path(f.outdir) / (stem + ".fmz")).string();
  CompressedCandidate best;
  best.builder = MakeBuilder(f, nullptr);
  // JSON "foldOptions": what compress added to the options given.
  std::string chosen =
    ApplyCompressFoldDefaults(best.builder, f.keep.has_value(), f.minFaces.has_value());
  int code = 0;
  if (!FoldAndWrite(mesh, f, bits, keepArrays, output, best, error, code))
  {
    std::cerr << "foldingmeshes: " << error << "\n";
    return code;
  }
  // --search: the other settings, each written beside the output; a smaller file replaces it.
  // A variant that fails is skipped (the output holds the smallest file so far).
  const std::string ownOptions = chosen;
  int tried = 1;
  const std::string candidatePath = output + ".candidate";
  std::set<FoldSearchKey> folded{ FoldSettingsKey(best.builder) };
  for (const FoldSearchVariant& v : FoldSearchVariants)
  {
    if (!search)
      break;
    CompressedCandidate c;
    c.builder = MakeBuilder(f, &v);
    if (!folded.insert(FoldSettingsKey(c.builder)).second)
      continue;
    ++tried;
    if (!FoldAndWrite(mesh, f, bits, keepArrays, candidatePath, c, error, code))
    {
      std::cerr << "foldingmeshes: --search, "
                << (*v.options ? v.options : "the options given alone") << ": " << error
                << " (skipped)\n";
      continue;
    }
    std::error_code renamed;
    if (c.bytes < best.bytes)
    {
      std::filesystem::rename(candidatePath, output, renamed);
      if (renamed)
      {
        std::cerr << "foldingmeshes: cannot replace " << output << ": " << renamed.message()
                  << "\n";
        std::filesystem::remove(candidatePath, renamed);
        return 3;
      }
      best = c;
      chosen = v.options;
    }
  }
  std::error_code removed;
  std::filesystem::remove(candidatePath, removed);
  vtkFoldingTreeBuilder* builder = best.builder;
  vtkFoldingTreeCompactWriter* writer = best.writer;
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  auto* tree = vtkMultiBlockDataSet::SafeDownCast(builder->GetOutputDataObject(0));
  const int original = static_cast<int>(TreeValue(tree, "OriginalFaces"));
  const int stored = static_cast<int>(TreeValue(tree, "StoredFaces"));
  const double epsilon = TreeValue(tree, "RootEpsilon");
  const long long bytes = static_cast<long long>(writer->GetBytesWritten());
  if (f.json)
    std::printf("{\n  \"mesh\": %s,\n  \"output\": %s,\n  \"bytes\": %lld,\n"
                "  \"originalFaces\": %d,\n  \"storedFaces\": %d,\n  \"rootEpsilon\": %.9g,\n"
                "  \"quantizationBits\": %d,\n  \"quantizationError\": %.9g,\n"
                "  \"foldSettingsTried\": %d,\n  \"foldOptions\": %s,\n"
                "  \"seconds\": %.3f\n}\n",
      JsonString(f.meshPath).c_str(),
      JsonString(output).c_str(),
      bytes,
      original,
      stored,
      epsilon,
      writer->GetQuantizationBitsUsed(),
      writer->GetQuantizationError(),
      tried,
      JsonString(chosen).c_str(),
      seconds);
  else
  {
    std::printf("mesh:                    %s\n", f.meshPath.c_str());
    std::printf("faces:                   %d original, %d stored\n", original, stored);
    std::printf("quantisation:            %d bits, points moved up to %.6g (root epsilon "
                "%.6g, the bound it stays inside)\n",
      writer->GetQuantizationBitsUsed(),
      writer->GetQuantizationError(),
      epsilon);
    if (search)
      std::printf("fold settings:           %d tried, the smallest file with %s\n",
        tried,
        chosen.empty() ? "the options given alone" : chosen.c_str());
    else if (!ownOptions.empty())
      std::printf(
        "fold settings:           compress's %s on top of the options given\n", ownOptions.c_str());
    std::printf("time:                    %.3f s\n", seconds);
    std::printf("wrote:                   %s (%lld bytes)\n", output.c_str(), bytes);
  }
  return 0;
}
}
}
