/**
 * @file    MeshPicture.h
 * @brief   off-screen pictures of FoldingMeshes results (used by the apps and image tests)
 */
#ifndef foldingmeshes_MeshPicture_h
#define foldingmeshes_MeshPicture_h

#include "vtkSmartPointer.h"

#include <string>

class vtkPolyData;
class vtkRenderWindow;

namespace foldingmeshes
{
/**
 * A render window (off-screen, fixed size, no multisampling) showing a mesh coloured by
 * its cell array "SymmetryRegion" (outside grey, support yellow, symmetric green, as in
 * the paper's Figure 2) and, when given, the plane glyph as a translucent blue quad. The
 * camera looks at the mesh obliquely across the plane so both halves are visible. Up:
 * `upAxis` (0, 1, 2: +X, +Y, +Z; files differ in which axis is up), or with -1 the longest
 * axis of the mesh's box among those lying in the plane. With `axisGlyph` (the detector's
 * rotation axis line, output 2) that line too, thick and red, drawn over the mesh.
 */
vtkSmartPointer<vtkRenderWindow> MakeSymmetryScene(vtkPolyData* labelledMesh,
  vtkPolyData* planeGlyph,
  int width,
  int height,
  int upAxis = -1,
  vtkPolyData* axisGlyph = nullptr);

/**
 * A render window (off-screen, fixed size, no multisampling) showing `mesh` coloured by its
 * integer cell array `cellArrayName` with a categorical lookup table (indexed lookup: every
 * distinct value gets its own colour from a fixed palette; negative values, e.g. faces not
 * stored in any leaf, are light grey). Without that array the mesh is plain grey. The camera
 * looks obliquely at the mesh, up along `upAxis` (0, 1, 2: +X, +Y, +Z), or with -1 along +Y
 * (+Z when Y is the thinnest extent).
 */
vtkSmartPointer<vtkRenderWindow> MakeCategoryScene(vtkPolyData* mesh,
  const char* cellArrayName,
  int width,
  int height,
  int upAxis = -1);

/**
 * Two meshes side by side (left and right half of one off-screen window, one shared camera
 * placed for the left mesh as MakeCategoryScene places it), each coloured as
 * MakeCategoryScene does (a null array name: plain grey). For "this is unfold(fold(M)) next to
 * M" pictures.
 */
vtkSmartPointer<vtkRenderWindow> MakeSideBySideScene(vtkPolyData* left,
  const char* leftCellArrayName,
  vtkPolyData* right,
  const char* rightCellArrayName,
  int width,
  int height,
  int upAxis = -1);

/// Renders the scene to a PNG file. Returns false and sets error on failure.
bool WritePicture(vtkRenderWindow* window, const std::string& path, std::string& error);
}

#endif
