// foldingmeshes: the command-line front end of FoldingMeshes.
//
//   foldingmeshes detect MESH [options]      planar symmetry plane + symmetric region
//   foldingmeshes fold MESH [options]        folding tree (.vtm) + segmentation + summary
//   foldingmeshes unfold TREE.vtm [options]  mesh reconstructed from a folding tree
//   foldingmeshes roundtrip MESH [options]   fold, save, read back, unfold, Hausdorff check
//   foldingmeshes compress MESH [options]    compact folding tree STEM.fmz (Draco-coded leaves)
//   foldingmeshes decompress FILE.fmz [opts] the mesh unfolded from a compact tree
//   foldingmeshes --help | --version
//
// Exit codes: 0 success, 1 bad command line, 2 unreadable or invalid input, 3 cannot write,
// 4 roundtrip: Hausdorff distance above the root epsilon.
#include "CommandLine.h"
#include "ProcessMemory.h"

#include <vtkSMPTools.h>

#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>

using namespace foldingmeshes::cli;

int main(int argc, char* argv[])
{
  KeepFreedMemoryForReuse();
  // Use both cores unless the user chose an SMP backend (results do not depend on it).
  if (!std::getenv("VTK_SMP_BACKEND_IN_USE"))
    vtkSMPTools::SetBackend("STDThread");
  if (argc < 2)
  {
    std::cerr << Usage;
    return 1;
  }
  const std::string command = argv[1];
  if (command == "--help" || command == "-h" || command == "help")
  {
    std::cout << Usage;
    return 0;
  }
  if (command == "--version")
  {
    std::cout << "foldingmeshes " << FOLDINGMESHES_VERSION << "\n";
    return 0;
  }
  try
  {
    if (command == "detect")
      return Detect(argc - 2, argv + 2);
    if (command == "fold")
      return Fold(argc - 2, argv + 2);
    if (command == "unfold")
      return Unfold(argc - 2, argv + 2);
    if (command == "roundtrip")
      return Roundtrip(argc - 2, argv + 2);
    if (command == "compress")
      return Compress(argc - 2, argv + 2);
    if (command == "decompress")
      return Decompress(argc - 2, argv + 2);
    throw std::runtime_error("unknown command '" + command + "'");
  }
  catch (const std::exception& e)
  {
    std::cerr << "foldingmeshes: " << e.what() << "\n(see foldingmeshes --help)\n";
    return 1;
  }
}
