// The arrays section of the compact tree file (CompactTreeArrays.h).
#include "CompactTreeArrays.h"

#include <utility>

namespace foldingmeshes
{
namespace
{
/// The leaves' point / triangle counts, in preorder.
std::vector<std::pair<size_t, size_t>> LeafSizes(const FoldingTree& tree)
{
  std::vector<std::pair<size_t, size_t>> sizes;
  for (const FoldingNode& node : tree.nodes)
    if (node.kind == FoldingNodeKind::Leaf)
      sizes.emplace_back(node.mesh.points.size(), node.mesh.triangles.size());
  return sizes;
}

size_t ArrayLeafBytes(const CompactArray& a, const std::pair<size_t, size_t>& leaf)
{
  return (a.perTriangle ? leaf.second : leaf.first) * static_cast<size_t>(a.components) *
    static_cast<size_t>(a.elementSize);
}
}

std::string CheckArrays(const std::vector<CompactArray>& arrays, const FoldingTree& tree)
{
  const auto sizes = LeafSizes(tree);
  for (const CompactArray& a : arrays)
  {
    if (a.name.empty() || a.components < 1 || a.components > 1024 ||
      (a.elementSize != 1 && a.elementSize != 2 && a.elementSize != 4 && a.elementSize != 8))
      return "array '" + a.name + "': invalid name, components or element size";
    if (a.leaves.size() != sizes.size())
      return "array '" + a.name + "': not one value block per leaf";
    for (size_t l = 0; l < sizes.size(); ++l)
      if (a.leaves[l].size() != ArrayLeafBytes(a, sizes[l]))
        return "array '" + a.name + "': a leaf's values do not match its points or triangles";
  }
  return std::string();
}

void WriteArrays(const std::vector<CompactArray>& arrays, ByteWriter& w)
{
  w.VarUInt(arrays.size());
  for (const CompactArray& a : arrays)
  {
    w.VarUInt(a.name.size());
    w.Raw(a.name);
    w.U8(a.perTriangle ? 1 : 0);
    w.VarUInt(static_cast<uint64_t>(a.dataType));
    w.VarUInt(static_cast<uint64_t>(a.components));
    w.U8(static_cast<uint8_t>(a.elementSize));
    for (const std::string& values : a.leaves)
      w.Raw(values);
  }
}

std::vector<CompactArray> ReadArrays(ByteReader& r, const FoldingTree& tree)
{
  const auto sizes = LeafSizes(tree);
  // An array record takes at least five bytes.
  const size_t count = r.Count(r.Remaining() / 5, "arrays");
  std::vector<CompactArray> arrays;
  for (size_t k = 0; k < count; ++k)
  {
    arrays.emplace_back();
    CompactArray& a = arrays.back();
    const size_t length = r.Count(r.Remaining(), "array name length");
    a.name.assign(r.Take(length), length);
    a.perTriangle = r.U8() != 0;
    a.dataType = static_cast<int>(r.Count(1 << 20, "array type"));
    a.components = static_cast<int>(r.Count(1024, "array components"));
    a.elementSize = r.U8();
    if (a.components < 1 ||
      (a.elementSize != 1 && a.elementSize != 2 && a.elementSize != 4 && a.elementSize != 8))
      throw CompactFormatError("arrays section: invalid components or element size");
    for (const auto& leaf : sizes)
    {
      const size_t bytes = ArrayLeafBytes(a, leaf);
      a.leaves.emplace_back(r.Take(bytes), bytes);
    }
  }
  if (r.Remaining() != 0)
    throw CompactFormatError("arrays section: unexpected bytes after its end");
  return arrays;
}
}
