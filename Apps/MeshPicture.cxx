#include "MeshPicture.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkLookupTable.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <vtkWindowToImageFilter.h>

#include <vtkVariant.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace foldingmeshes
{
namespace
{
/**
 * Places the camera, already aimed with its view up set, at the distance along its view
 * direction where all eight corners of the visible props' bounding box fit in a view of the
 * given aspect ratio
 * (width / height) with a small margin. vtkRenderer::ResetCamera fits the bounding sphere
 * and, before the window is sized, assumes a square view: a long mesh standing up in a
 * 4:3 picture (a hammer) came out cut off at the top and bottom once zoomed.
 */
void FitCameraToVisibleProps(vtkRenderer* renderer, double aspect)
{
  double bounds[6];
  renderer->ComputeVisiblePropBounds(bounds);
  if (!vtkMath::AreBoundsInitialized(bounds))
  {
    renderer->ResetCamera();
    return;
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  double focal[3], position[3], up[3];
  camera->GetFocalPoint(focal);
  camera->GetPosition(position);
  camera->OrthogonalizeViewUp();
  camera->GetViewUp(up);
  double view[3] = { focal[0] - position[0], focal[1] - position[1], focal[2] - position[2] };
  vtkMath::Normalize(view);
  vtkMath::Normalize(up);
  double right[3];
  vtkMath::Cross(view, up, right);
  const double margin = 1.06; // the box fills 1/1.06 of the picture's height or width
  const double halfTan = std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2.0);
  double distance = 0.0;
  for (int corner = 0; corner < 8; ++corner)
  {
    const double offset[3] = { bounds[(corner & 1) ? 1 : 0] - focal[0],
      bounds[(corner & 2) ? 3 : 2] - focal[1],
      bounds[(corner & 4) ? 5 : 4] - focal[2] };
    const double x = std::abs(vtkMath::Dot(offset, right));
    const double y = std::abs(vtkMath::Dot(offset, up));
    const double depth = vtkMath::Dot(offset, view); // towards the camera is negative
    distance = std::max(distance, margin * y / halfTan - depth);
    distance = std::max(distance, margin * x / (halfTan * std::max(aspect, 1e-6)) - depth);
  }
  if (!(distance > 0.0))
  {
    renderer->ResetCamera();
    return;
  }
  camera->SetPosition(
    focal[0] - distance * view[0], focal[1] - distance * view[1], focal[2] - distance * view[2]);
  renderer->ResetCameraClippingRange();
}
}

vtkSmartPointer<vtkRenderWindow> MakeSymmetryScene(vtkPolyData* labelledMesh,
  vtkPolyData* planeGlyph,
  int width,
  int height,
  int upAxis,
  vtkPolyData* axisGlyph)
{
  vtkNew<vtkLookupTable> colors;
  colors->SetNumberOfTableValues(3);
  colors->SetTableRange(0, 2);
  colors->SetTableValue(0, 0.62, 0.62, 0.64, 1.0); // outside
  colors->SetTableValue(1, 0.95, 0.85, 0.25, 1.0); // support only
  colors->SetTableValue(2, 0.30, 0.72, 0.35, 1.0); // symmetric region
  colors->Build();

  vtkNew<vtkPolyDataMapper> meshMapper;
  meshMapper->SetInputData(labelledMesh);
  if (labelledMesh->GetCellData()->GetArray("SymmetryRegion"))
  {
    meshMapper->SetScalarModeToUseCellFieldData();
    meshMapper->SelectColorArray("SymmetryRegion");
    meshMapper->SetLookupTable(colors);
    meshMapper->SetScalarRange(0, 2);
    meshMapper->ScalarVisibilityOn();
  }
  else
  {
    meshMapper->ScalarVisibilityOff();
  }
  vtkNew<vtkActor> meshActor;
  meshActor->SetMapper(meshMapper);
  meshActor->GetProperty()->SetInterpolationToFlat();

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(meshActor);
  renderer->SetBackground(1.0, 1.0, 1.0);
  if (planeGlyph && planeGlyph->GetNumberOfPoints() > 0)
  {
    vtkNew<vtkPolyDataMapper> planeMapper;
    planeMapper->SetInputData(planeGlyph);
    planeMapper->ScalarVisibilityOff();
    vtkNew<vtkActor> planeActor;
    planeActor->SetMapper(planeMapper);
    planeActor->GetProperty()->SetColor(0.25, 0.45, 0.9);
    planeActor->GetProperty()->SetOpacity(0.35);
    renderer->AddActor(planeActor);
  }

  // Camera: oblique across the plane (normal from field data when present).
  double n[3] = { 1, 0, 0 };
  if (vtkDataArray* normal = labelledMesh->GetFieldData()->GetArray("SymmetryPlaneNormal"))
    normal->GetTuple(0, n);
  double bounds[6];
  labelledMesh->GetBounds(bounds);
  const double center[3] = {
    0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5])
  };
  // Up: the given axis, else the coordinate axis along which the mesh is longest, among those
  // lying in the plane.
  double up[3] = { 0, 0, 1 };
  double bestScore = -1.0;
  for (int k = 0; k < 3; ++k)
  {
    const double score = upAxis >= 0 && upAxis <= 2
      ? (k == upAxis ? 1.0 : 0.0)
      : (bounds[2 * k + 1] - bounds[2 * k]) * (1.0 - std::abs(n[k]));
    if (score > bestScore + 1e-12)
    {
      bestScore = score;
      up[0] = up[1] = up[2] = 0.0;
      up[k] = 1.0;
    }
  }
  // In-plane direction perpendicular to up and n (a plane across the up axis: any
  // direction across up).
  double side[3] = {
    up[1] * n[2] - up[2] * n[1], up[2] * n[0] - up[0] * n[2], up[0] * n[1] - up[1] * n[0]
  };
  double len = std::sqrt(side[0] * side[0] + side[1] * side[1] + side[2] * side[2]);
  if (len < 1e-6)
  {
    const int across = up[0] != 0.0 ? 1 : 0;
    side[0] = side[1] = side[2] = 0.0;
    side[across] = 1.0;
    len = 1.0;
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(center);
  double dir[3];
  for (int k = 0; k < 3; ++k)
    dir[k] = (len > 0 ? side[k] / len : 0.0) + 0.6 * n[k] + 0.35 * up[k];
  camera->SetPosition(center[0] + dir[0], center[1] + dir[1], center[2] + dir[2]);
  camera->SetViewUp(up);
  FitCameraToVisibleProps(renderer, static_cast<double>(width) / height);

  vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  window->AddRenderer(renderer);
  if (axisGlyph && axisGlyph->GetNumberOfPoints() > 0)
  {
    // The axis runs through the inside of the mesh: drawn in a layer over it, same camera.
    vtkNew<vtkPolyDataMapper> axisMapper;
    axisMapper->SetInputData(axisGlyph);
    axisMapper->ScalarVisibilityOff();
    vtkNew<vtkActor> axisActor;
    axisActor->SetMapper(axisMapper);
    axisActor->GetProperty()->SetColor(0.85, 0.15, 0.1);
    axisActor->GetProperty()->SetLineWidth(4.0);
    vtkNew<vtkRenderer> overlay;
    overlay->SetLayer(1);
    overlay->SetActiveCamera(camera);
    overlay->AddActor(axisActor);
    window->SetNumberOfLayers(2);
    window->AddRenderer(overlay);
  }
  return window;
}

vtkSmartPointer<vtkRenderWindow> MakeCategoryScene(vtkPolyData* mesh,
  const char* cellArrayName,
  int width,
  int height,
  int upAxis)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  mapper->ScalarVisibilityOff();
  vtkNew<vtkLookupTable> colors;
  vtkDataArray* labels = cellArrayName ? mesh->GetCellData()->GetArray(cellArrayName) : nullptr;
  if (labels && labels->GetNumberOfComponents() == 1)
  {
    // A qualitative palette (ColorBrewer Set1/Set3-like), cycled for many categories.
    static const double palette[][3] = { { 0.89, 0.10, 0.11 },
      { 0.22, 0.49, 0.72 },
      { 0.30, 0.69, 0.29 },
      { 0.60, 0.31, 0.64 },
      { 1.00, 0.50, 0.00 },
      { 0.90, 0.80, 0.20 },
      { 0.65, 0.34, 0.16 },
      { 0.97, 0.51, 0.75 },
      { 0.40, 0.76, 0.65 },
      { 0.55, 0.63, 0.80 },
      { 0.65, 0.85, 0.33 },
      { 0.17, 0.30, 0.45 } };
    const int paletteSize = static_cast<int>(sizeof(palette) / sizeof(palette[0]));
    std::set<long long> values;
    for (vtkIdType i = 0; i < labels->GetNumberOfTuples(); ++i)
      values.insert(static_cast<long long>(std::llround(labels->GetTuple1(i))));
    colors->IndexedLookupOn();
    colors->SetNumberOfTableValues(static_cast<vtkIdType>(std::max<size_t>(values.size(), 1)));
    int index = 0, colour = 0;
    for (long long v : values)
    {
      colors->SetAnnotation(vtkVariant(v), std::to_string(v));
      if (v < 0)
        colors->SetTableValue(index, 0.80, 0.80, 0.82, 1.0);
      else
      {
        const double* c = palette[colour++ % paletteSize];
        colors->SetTableValue(index, c[0], c[1], c[2], 1.0);
      }
      ++index;
    }
    colors->SetNanColor(0.80, 0.80, 0.82, 1.0);
    mapper->SetLookupTable(colors);
    mapper->SetScalarModeToUseCellFieldData();
    mapper->SelectColorArray(cellArrayName);
    mapper->UseLookupTableScalarRangeOn();
    mapper->ScalarVisibilityOn();
  }
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetInterpolationToFlat();
  if (!mapper->GetScalarVisibility())
    actor->GetProperty()->SetColor(0.62, 0.62, 0.64);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(1.0, 1.0, 1.0);

  double bounds[6];
  mesh->GetBounds(bounds);
  const double center[3] = {
    0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5])
  };
  // Up: the given axis, else +Y (the convention of most mesh files) unless Y is the mesh's
  // thinnest extent, then +Z; view: mostly along the thinner horizontal axis, turned towards the
  // longer one and slightly from above, so a side view of animals and furniture with visible depth.
  const double extent[3] = { bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] };
  if (upAxis < 0 || upAxis > 2)
    upAxis = (extent[1] <= extent[0] && extent[1] <= extent[2]) ? 2 : 1;
  const int h1 = upAxis == 0 ? 1 : 0, h2 = upAxis == 2 ? 1 : 2;
  const int thin = extent[h1] <= extent[h2] ? h1 : h2, wide = thin == h1 ? h2 : h1;
  double up[3] = { 0, 0, 0 }, dir[3] = { 0, 0, 0 };
  up[upAxis] = 1.0;
  dir[thin] = 1.0;
  dir[wide] = 0.5;
  dir[upAxis] = 0.35;
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(center);
  camera->SetPosition(center[0] + dir[0], center[1] + dir[1], center[2] + dir[2]);
  camera->SetViewUp(up);
  FitCameraToVisibleProps(renderer, static_cast<double>(width) / height);

  vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  window->AddRenderer(renderer);
  return window;
}

vtkSmartPointer<vtkRenderWindow> MakeSideBySideScene(vtkPolyData* left,
  const char* leftCellArrayName,
  vtkPolyData* right,
  const char* rightCellArrayName,
  int width,
  int height,
  int upAxis)
{
  vtkSmartPointer<vtkRenderWindow> a =
    MakeCategoryScene(left, leftCellArrayName, width / 2, height, upAxis);
  vtkSmartPointer<vtkRenderWindow> b =
    MakeCategoryScene(right, rightCellArrayName, width / 2, height, upAxis);
  vtkSmartPointer<vtkRenderer> l = a->GetRenderers()->GetFirstRenderer();
  vtkSmartPointer<vtkRenderer> r = b->GetRenderers()->GetFirstRenderer();
  a->RemoveRenderer(l);
  b->RemoveRenderer(r);
  l->SetViewport(0.0, 0.0, 0.5, 1.0);
  r->SetViewport(0.5, 0.0, 1.0, 1.0);
  r->SetActiveCamera(l->GetActiveCamera());
  vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  window->AddRenderer(l);
  window->AddRenderer(r);
  return window;
}

bool WritePicture(vtkRenderWindow* window, const std::string& path, std::string& error)
{
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    error = "cannot write picture '" + path + "'";
    return false;
  }
  return true;
}
}
