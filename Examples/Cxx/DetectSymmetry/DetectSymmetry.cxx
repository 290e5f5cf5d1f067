// Finds the mirror plane of an OFF mesh with FoldingMeshes and prints it.
//   DetectSymmetry mesh.off
#include <vtkOFFReader.h>
#include <vtkSymmetryPlaneDetector.h>

#include <vtkNew.h>

#include <cstdio>

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: %s mesh.off\n", argv[0]);
    return 1;
  }
  vtkNew<vtkOFFReader> reader;
  reader->SetFileName(argv[1]);
  vtkNew<vtkSymmetryPlaneDetector> detector;
  detector->SetInputConnection(reader->GetOutputPort());
  detector->Update();
  const double* o = detector->GetPlaneOrigin();
  const double* n = detector->GetPlaneNormal();
  std::printf("plane origin %g %g %g normal %g %g %g, symmetric area %.1f%%, found %s\n",
    o[0],
    o[1],
    o[2],
    n[0],
    n[1],
    n[2],
    100.0 * detector->GetSymmetricAreaFraction(),
    detector->GetSymmetryFound() ? "yes" : "no");
  return detector->GetSymmetryFound() ? 0 : 2;
}
