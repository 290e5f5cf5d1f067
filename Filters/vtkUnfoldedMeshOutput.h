#ifndef vtkUnfoldedMeshOutput_h
#define vtkUnfoldedMeshOutput_h

// Private to FoldingMeshes::Filters: the steps that turn the core's UnfoldedMesh into the
// unfolder's vtkPolyData output (vtkFoldingTreeUnfolder::RequestWholeData calls them in order).

#include "Core/FoldingTree.h"
#include "Core/FoldingTreeUnfolder.h"

#include <vtkType.h>

#include <string>
#include <vector>

class vtkFieldData;
class vtkObject;
class vtkPolyData;

namespace foldingmeshes
{
/// One double `value` as the one-tuple field array `name` of `fd`.
void AddFieldValue(vtkFieldData* fd, const char* name, double value);

/// Points and triangles of `mesh` as the output's geometry, the points in the input's precision
/// (the "Tree" block's InputPointsDataType record `info`; double without it).
void SetUnfoldedGeometry(const UnfoldedMesh& mesh, vtkFieldData* info, vtkPolyData* output);

/// The leaves' own point and cell arrays (the user's, carried by the builder) on the output: each
/// output point/face takes the tuple of its leaf's point/face with the same original id; vectors
/// are mapped by the copy's reflection. Active attributes as the builder recorded them in `info`.
/// Names clashing with the unfolder's arrays are renamed with a warning through `warner`. False
/// (with `error`) when an output point or face has no source in the leaves.
bool CarryLeafArrays(const FoldingTree& tree,
  const std::vector<vtkPolyData*>& leaves,
  const UnfoldedMesh& mesh,
  vtkFieldData* info,
  vtkPolyData* output,
  vtkObject* warner,
  std::string& error);

/// The unfolder's own arrays: OriginalPointId; OriginalCellId, FoldingLeafId (active scalars),
/// FoldingCopy, FoldingMirrored, FoldingMirrorMask, FoldingFilled.
void AddUnfoldingArrays(const UnfoldedMesh& mesh, vtkPolyData* output);

/// What the unfolding did, as one-value field arrays (UnfoldedFaces ... Diagonal; see
/// docs/unfolder.md).
void AddUnfoldingSummary(const UnfoldedMesh& mesh, const FoldingTree& tree, vtkFieldData* fd);

/// The input's field arrays the builder stored on the "Tree" block (`info`) under
/// InputFieldPrefix, restored on `fd` under their own names (renamed, with a warning through
/// `warner`, where `fd` already has the name).
void RestoreInputFieldArrays(vtkFieldData* info, vtkFieldData* fd, vtkObject* warner);
}

#endif
