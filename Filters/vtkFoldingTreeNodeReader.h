// Reading the blocks of a folding tree's vtkMultiBlockDataSet into core nodes, block by
// block with checks (MultiBlockToFoldingTree assembles them). Internal to
// FoldingMeshes::Filters.
#ifndef vtkFoldingTreeNodeReader_h
#define vtkFoldingTreeNodeReader_h

#include "Core/FoldingTree.h"

#include <vtkType.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

class vtkAbstractArray;
class vtkDataObject;
class vtkFieldData;
class vtkPolyData;

namespace foldingmeshes
{
namespace tree_io_detail
{
/// A single-component integer value (stored as any numeric type, integral and within
/// +-2^62); false otherwise.
bool ReadInteger(vtkAbstractArray* a, vtkIdType i, long long& value);
/// Unsigned 64-bit values read exactly (the masks do not fit a double).
bool ReadUInt64(vtkAbstractArray* a, vtkIdType i, uint64_t& value);

/// Reads node blocks depth first (Node), collecting them in preorder with their parents; the
/// first problem is kept in Error ("where: what").
struct Reader
{
  std::string Error;
  struct Item
  {
    FoldingNode Node;
    int StoredIndex = -1;
    int Parent = -1; // traversal position of the parent
    vtkPolyData* Leaf = nullptr;
  };
  std::vector<Item> Items;                      // in preorder of the blocks
  std::vector<std::pair<int, int>> BorderEdges; // from the leaves' InputBorderNeighbors

  bool Fail(const std::string& where, const std::string& what);
  bool Int(vtkFieldData* fd, const char* name, const std::string& where, long long& v);
  bool Double(vtkFieldData* fd, const char* name, const std::string& where, double* v, int n = 1);
  /// Optional list (empty lists may not survive every writer).
  bool IntList(vtkFieldData* fd, const char* name, const std::string& where, std::vector<int>& v);
  /// Common metadata; `kind` is the kind implied by the block structure.
  bool Metadata(vtkFieldData* fd, const std::string& where, FoldingNodeKind kind, Item& item);
  /// A node block (leaf polydata or inner multiblock) and, recursively, its children.
  bool Node(vtkDataObject* object, const std::string& where, int parent, int depth);
  bool CheckDepth(const Item& item, const std::string& where, int depth);
  bool ReadLeaf(vtkPolyData* leaf, const std::string& where, int parent, int depth);

private:
  bool ReadFoldingMetadata(vtkFieldData* fd, const std::string& where, Item& item);
  bool ReadRotationMetadata(vtkFieldData* fd, const std::string& where, Item& item);
  bool ReadLeafGeometry(vtkPolyData* leaf, const std::string& where, FoldingLeafMesh& m);
  bool ReadRequiredLeafArrays(vtkPolyData* leaf, const std::string& where, FoldingLeafMesh& m);
  bool ReadOptionalLeafArrays(vtkPolyData* leaf, const std::string& where, FoldingLeafMesh& m);
  bool ReadMirroredFlags(vtkFieldData* fd, const std::string& where, FoldingLeafMesh& m);
};
} // namespace tree_io_detail
} // namespace foldingmeshes

#endif
