// Baseline-image regression tests of what a person sees of a folding tree, on the bundled
// dinosaur: the segmentation view (the input coloured by FoldingLeafId; a face mirrored away
// takes the colour of the leaf it mirrors, as in the paper's Figures 1 and 4), the mesh
// unfolded from the tree, and the unfolded mesh next to the input.
//
//   TestFoldingTreeImages MESH BASELINE_DIR TEMP_DIR
#include "MeshPicture.h"
#include "vtkFoldingTreeBuilder.h"
#include "vtkFoldingTreeUnfolder.h"
#include "vtkOFFReader.h"

#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkTesting.h>

#include <cstdio>
#include <string>

namespace
{
bool Compare(vtkRenderWindow* window, const std::string& baseline, const std::string& temp)
{
  window->Render();
  vtkNew<vtkTesting> testing;
  testing->AddArgument("-V");
  testing->AddArgument(baseline.c_str());
  testing->AddArgument("-T");
  testing->AddArgument(temp.c_str());
  testing->SetRenderWindow(window);
  const bool ok = testing->RegressionTest(15.0) == vtkTesting::PASSED;
  std::printf("%s: %s\n", baseline.c_str(), ok ? "passed" : "FAILED");
  return ok;
}
}

int main(int argc, char* argv[])
{
  if (argc != 4)
  {
    std::fprintf(stderr, "usage: %s MESH.off BASELINE_DIR TEMP_DIR\n", argv[0]);
    return 1;
  }
  vtkNew<vtkOFFReader> reader;
  reader->SetFileName(argv[1]);
  vtkNew<vtkFoldingTreeBuilder> builder;
  builder->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkFoldingTreeUnfolder> unfolder;
  unfolder->SetInputConnection(builder->GetOutputPort(0));
  unfolder->Update();
  builder->Update();
  vtkPolyData* segmentation = vtkPolyData::SafeDownCast(builder->GetOutputDataObject(1));
  vtkPolyData* unfolded = unfolder->GetOutput();
  if (!segmentation || !unfolded || unfolded->GetNumberOfCells() == 0)
  {
    std::fprintf(stderr, "no segmentation or unfolded mesh\n");
    return 1;
  }
  const std::string baselines = argv[2], temp = argv[3];
  bool ok = Compare(foldingmeshes::MakeCategoryScene(segmentation, "FoldingLeafId", 400, 300),
    baselines + "/TestFoldingTreeSegmentation.png",
    temp);
  ok = Compare(foldingmeshes::MakeCategoryScene(unfolded, "FoldingLeafId", 400, 300),
         baselines + "/TestFoldingTreeUnfolded.png",
         temp) &&
    ok;
  // unfold(fold(M)) (right, coloured by leaf) next to M (left, grey), same camera.
  vtkPolyData* original = reader->GetOutput();
  ok = Compare(
         foldingmeshes::MakeSideBySideScene(original, nullptr, unfolded, "FoldingLeafId", 600, 300),
         baselines + "/TestFoldingTreeUnfoldedNextToOriginal.png",
         temp) &&
    ok;
  return ok ? 0 : 1;
}
