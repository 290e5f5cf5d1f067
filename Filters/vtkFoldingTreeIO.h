// Conversions between the core FoldingTree and its vtkMultiBlockDataSet encoding (internal
// header of FoldingMeshes::Filters; the encoding itself is documented in
// vtkFoldingTreeBuilder.h, where it is public API).
#ifndef vtkFoldingTreeIO_h
#define vtkFoldingTreeIO_h

#include "Core/FoldingTree.h"

#include <string>
#include <vector>

class vtkMultiBlockDataSet;
class vtkPolyData;

namespace foldingmeshes
{
/**
 * Encodes `tree` into `out` (cleared first): block 0 is the root node, block 1 the "Tree"
 * information block. Leaves carry the point and cell arrays of `triangulatedInput` (the
 * triangulated input the tree was built from: leaf original point / face ids index its
 * points / cells), copied by original id; it may be null (then only the tree's own arrays).
 * Unnamed input arrays are named ("UnnamedPointArray0", ...), arrays VTK's XML files cannot
 * store (vtkVariantArray) are left out, arrays named like the tree's or the unfolder's own
 * are renamed (vtkFoldingArrays.h); `notes` (optional) receives a sentence per kind of change.
 * The "Tree" block records the input's field arrays (prefixed "InputField:"), its active
 * attribute names ("InputPointAttributes" / "InputCellAttributes") and its point data type
 * ("InputPointsDataType") for the unfolder.
 * False when the tree is invalid (FoldingTree::Validate) or the ids do not fit the input.
 */
bool FoldingTreeToMultiBlock(const FoldingTree& tree,
  vtkPolyData* triangulatedInput,
  vtkMultiBlockDataSet* out,
  std::string& error,
  std::vector<std::string>* notes = nullptr);
/// The same without the error message.
bool FoldingTreeToMultiBlock(const FoldingTree& tree,
  vtkPolyData* triangulatedInput,
  vtkMultiBlockDataSet* out);

/**
 * Decodes a tree written by FoldingTreeToMultiBlock (directly, or read back from a .vtm file).
 * Node indices are the stored "FoldingNodeIndex" values when every node has one and they are a
 * permutation (so leaf ids survive), else the preorder of the blocks. `leafBlocks` (optional)
 * receives, per node index, the leaf's vtkPolyData (null for inner nodes) so a caller can read
 * the leaves' other arrays. False with a description of the first problem for a malformed tree
 * (missing plane or node metadata, wrong kinds, a leaf that is not vtkPolyData, array sizes).
 */
bool MultiBlockToFoldingTree(vtkMultiBlockDataSet* in,
  FoldingTree& tree,
  std::vector<vtkPolyData*>* leafBlocks,
  std::string& error);
inline bool MultiBlockToFoldingTree(vtkMultiBlockDataSet* in, FoldingTree& tree, std::string& error)
{
  return MultiBlockToFoldingTree(in, tree, nullptr, error);
}

/// True for array names the filters treat as ids or bit masks (never reflected, never
/// interpolated): names ending in "Id"/"Ids"/"ID"/"IDs" or containing "Mask".
bool IsIdOrMaskArrayName(const char* name);
}

#endif
