// foldingmeshes compress: a mesh folded and written as a compact folding tree (.fmz), with
// compress's own defaults for --keep, --min-faces and the rotation rule (CompressionSearch.h). Its
// counterpart, decompress, is the unfold command on a .fmz file (FoldCommands.cxx). With --search,
// a few other fold settings are tried as well and the smallest file is kept.
#include "CompressionSearch.h"
#include "FoldCommandSupport.h"
#include "MeshIO.h"
#include "vtkFoldingTreeCompactWriter.h"

#include <vtkNew.h>

#include <chrono>
#include <cmath>
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
  {
    // --search's settings fold without rotation nodes unless the variant or the user asks for
    // them (the builder's default, WHEN_AXIAL, is compress's own fold, compared already with
    // the same fold without them).
    if (!f.rotationNodes && !f.rotationWhenAxial && !f.noRotation)
      builder->SetRotationNodes(vtkFoldingTreeBuilder::ROTATION_NODES_OFF);
    ApplyFoldSearchVariant(builder, *variant);
  }
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
  // The file decompressed and proved against the mesh, with more bits while it is not within
  // the root epsilon (automatic bits; vtkFoldingTreeCompactWriter::SetOriginalData): the
  // candidates are compared as proved.
  c.writer->SetOriginalData(mesh);
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
  const bool rotationGiven = f.rotationNodes || f.rotationWhenAxial || f.noRotation;
  std::string chosen = ApplyCompressFoldDefaults(
    best.builder, f.keep.has_value(), f.minFaces.has_value(), rotationGiven);
  int code = 0;
  if (!FoldAndWrite(mesh, f, bits, keepArrays, output, best, error, code))
  {
    std::cerr << "foldingmeshes: " << error << "\n";
    return code;
  }
  int tried = 1;
  const std::string candidatePath = output + ".candidate";
  // Settings folded, RotationNodes WHEN_AXIAL as the first fold decided it for this mesh.
  const bool axial = TriedRotationNodes(best.builder);
  const bool rotationTree = KeptRotationNodes(best.builder);
  std::set<FoldSearchKey> folded{ DecidedKey(FoldSettingsKey(best.builder), axial) };
  // A tree that looked for rotation nodes and kept none is the fold without them too.
  if (!rotationTree)
    folded.insert(DecidedKey(FoldSettingsKey(best.builder), false));
  // Another fold, written beside the output: a smaller file replaces it (ties keep the
  // output). A fold that fails is skipped (the output holds the smallest file so far); false
  // only when the output cannot be replaced.
  auto tryFold = [&](CompressedCandidate& c, const char* options) -> bool
  {
    if (!folded.insert(DecidedKey(FoldSettingsKey(c.builder), axial)).second)
      return true;
    ++tried;
    if (!FoldAndWrite(mesh, f, bits, keepArrays, candidatePath, c, error, code))
    {
      std::cerr << "foldingmeshes: " << (*options ? options : "the options given alone") << ": "
                << error << " (skipped)\n";
      return true;
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
        return false;
      }
      best = c;
      chosen = options;
    }
    return true;
  };
  // compress's rotation rule (CompressFoldDefaults): a tree that got rotation nodes is
  // compared with the same fold without them (a rotation tree can cost more bytes than the
  // faces it saves: mech).
  std::string withoutRotation;
  if (!rotationGiven && rotationTree)
  {
    CompressedCandidate c;
    c.builder = MakeBuilder(f, nullptr);
    withoutRotation =
      ApplyCompressFoldDefaults(c.builder, f.keep.has_value(), f.minFaces.has_value(), true);
    c.builder->SetRotationNodes(vtkFoldingTreeBuilder::ROTATION_NODES_OFF); // not the default
    withoutRotation = WithoutRotationNodes(withoutRotation);
    if (!tryFold(c, withoutRotation.c_str()))
      return 3;
  }
  // --search: the other settings.
  for (const FoldSearchVariant& v : FoldSearchVariants)
  {
    if (!search)
      break;
    if (f.noRotation && v.rotationNodes)
      continue;
    CompressedCandidate c;
    c.builder = MakeBuilder(f, &v);
    // The options that fold it again: MakeBuilder turned rotation nodes off, which on an axial
    // mesh differs from the fold command's default.
    const bool off = !rotationGiven && !v.rotationNodes && !v.rotationWhenAxial;
    const std::string options = off && axial ? WithoutRotationNodes(v.options) : v.options;
    if (!tryFold(c, options.c_str()))
      return 3;
  }
  std::error_code removed;
  std::filesystem::remove(candidatePath, removed);
  vtkFoldingTreeBuilder* builder = best.builder;
  vtkFoldingTreeCompactWriter* writer = best.writer;
  auto* tree = vtkMultiBlockDataSet::SafeDownCast(builder->GetOutputDataObject(0));
  const int original = static_cast<int>(TreeValue(tree, "OriginalFaces"));
  const int stored = static_cast<int>(TreeValue(tree, "StoredFaces"));
  const double epsilon = TreeValue(tree, "RootEpsilon");
  // Every candidate's writer proved its file against the mesh (FoldAndWrite).
  const int proofRetries = writer->GetProofRetries();
  const double proved = writer->GetProvedBound();
  const bool within = writer->GetProved(); // (within epsilon, and closed where the mesh is)
  // JSON: null where the file could not be decompressed (an infinite bound).
  char provedJson[32] = "null";
  if (std::isfinite(proved))
    std::snprintf(provedJson, sizeof(provedJson), "%.9g", proved);
  // (Not within: the writer warns; the line below says it too.)
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const long long bytes = static_cast<long long>(writer->GetBytesWritten());
  if (f.json)
    std::printf("{\n  \"mesh\": %s,\n  \"output\": %s,\n  \"bytes\": %lld,\n"
                "  \"originalFaces\": %d,\n  \"storedFaces\": %d,\n  \"rootEpsilon\": %.9g,\n"
                "  \"quantizationBits\": %d,\n  \"quantizationError\": %.9g,\n"
                "  \"foldSettingsTried\": %d,\n  \"foldOptions\": %s,\n"
                "  \"provedBound\": %s,\n  \"provedWithin\": %s,\n  \"proofRetries\": %d,\n"
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
      provedJson,
      within ? "true" : "false",
      proofRetries,
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
    if (tried > 1)
      std::printf("fold settings:           %d tried, the smallest file with %s\n",
        tried,
        chosen.empty() ? "the options given alone" : chosen.c_str());
    else if (!chosen.empty())
      std::printf(
        "fold settings:           compress's %s on top of the options given\n", chosen.c_str());
    std::printf("proved bound:            %.6g (decompressed vs mesh; %s; %d more encoding%s)\n",
      proved,
      within ? "within the root epsilon" : "NOT proved within the root epsilon (or not closed)",
      proofRetries,
      proofRetries == 1 ? "" : "s");
    std::printf("time:                    %.3f s\n", seconds);
    std::printf("wrote:                   %s (%lld bytes)\n", output.c_str(), bytes);
  }
  return 0;
}
}
}
