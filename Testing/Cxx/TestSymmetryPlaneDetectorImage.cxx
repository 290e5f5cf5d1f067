// Baseline-image regression test of what a person sees: the bundled dinosaur coloured by
// SymmetryRegion with the translucent plane glyph (vtkTesting image comparison).
//
//   TestSymmetryPlaneDetectorImage MESH -V BASELINE.png -T TEMPDIR
#include "MeshPicture.h"
#include "vtkOFFReader.h"
#include "vtkSymmetryPlaneDetector.h"

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkTesting.h>

#include <cstdio>

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::fprintf(stderr, "usage: %s MESH.off -V BASELINE -T TEMPDIR\n", argv[0]);
    return 1;
  }
  vtkNew<vtkOFFReader> reader;
  reader->SetFileName(argv[1]);
  vtkNew<vtkSymmetryPlaneDetector> detector;
  detector->SetInputConnection(reader->GetOutputPort());
  detector->Update();
  if (detector->GetSymmetricAreaFraction() < 0.9)
  {
    std::fprintf(
      stderr, "unexpected symmetric area fraction %g\n", detector->GetSymmetricAreaFraction());
    return 1;
  }
  auto window =
    foldingmeshes::MakeSymmetryScene(detector->GetOutput(0), detector->GetOutput(1), 400, 300);
  window->Render();

  vtkNew<vtkTesting> testing;
  for (int i = 2; i < argc; ++i)
    testing->AddArgument(argv[i]);
  testing->SetRenderWindow(window);
  // Threshold as in VTK's own tests (legacy image difference metric).
  const int result = testing->RegressionTest(15.0);
  std::printf("image comparison: %s\n", result == vtkTesting::PASSED ? "passed" : "FAILED");
  return result == vtkTesting::PASSED ? 0 : 1;
}
