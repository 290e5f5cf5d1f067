// foldingmeshes compress: a mesh folded and written as a compact folding tree (.fmz). Its
// counterpart, decompress, is the unfold command on a .fmz file (FoldCommands.cxx).
#include "FoldCommandSupport.h"
#include "MeshIO.h"
#include "vtkFoldingTreeCompactWriter.h"

#include <vtkNew.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace foldingmeshes
{
namespace cli
{
int Compress(int argc, char* argv[])
{
  // --quantization-bits and --keep-arrays are compress's own; the rest are the fold command's.
  int bits = 0;
  bool keepArrays = false;
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
  vtkNew<vtkFoldingTreeBuilder> builder;
  ConfigureBuilder(builder, f);
  builder->SetInputData(mesh);
  if (!RunFilter(builder, "folding", f.quiet, error))
  {
    std::cerr << "foldingmeshes: " << f.meshPath << ": " << error << "\n";
    return 2;
  }
  const std::string stem = std::filesystem::path(f.meshPath).stem().string();
  const std::string output = (std::filesystem::path(f.outdir) / (stem + ".fmz")).string();
  vtkNew<vtkFoldingTreeCompactWriter> writer;
  writer->SetInputConnection(builder->GetOutputPort(0));
  writer->SetFileName(output.c_str());
  writer->SetQuantizationBits(bits);
  writer->SetStoreUserArrays(keepArrays);
  if (!MakeOutdir(f.outdir, error) || !RunFilter(writer, "writing", true, error))
  {
    std::cerr << "foldingmeshes: " << error << "\n";
    return 3;
  }
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
                "  \"seconds\": %.3f\n}\n",
      JsonString(f.meshPath).c_str(),
      JsonString(output).c_str(),
      bytes,
      original,
      stored,
      epsilon,
      writer->GetQuantizationBitsUsed(),
      writer->GetQuantizationError(),
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
    std::printf("time:                    %.3f s\n", seconds);
    std::printf("wrote:                   %s (%lld bytes)\n", output.c_str(), bytes);
  }
  return 0;
}
}
}
