// Per-point symbols of the compact tree file in border order (CompactPointSymbols.h).
#include "CompactPointSymbols.h"

#include <algorithm>
#include <utility>

namespace foldingmeshes
{
namespace compact_detail
{
std::vector<int> SymbolOrder(const DecodedLeaf& leaf)
{
  const int n = static_cast<int>(leaf.points.size());
  std::vector<std::pair<int, int>> edges;
  edges.reserve(3 * leaf.triangles.size());
  for (const Triangle& t : leaf.triangles)
    for (int k = 0; k < 3; ++k)
      edges.emplace_back(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  std::vector<std::vector<int>> borderNeighbours(static_cast<size_t>(n));
  for (size_t i = 0; i < edges.size();)
  {
    size_t j = i;
    while (j < edges.size() && edges[j] == edges[i])
      ++j;
    const auto [a, b] = edges[i];
    if (j - i == 1 && a != b && a >= 0 && b < n)
    {
      borderNeighbours[a].push_back(b);
      borderNeighbours[b].push_back(a);
    }
    i = j;
  }
  std::vector<int> order;
  order.reserve(static_cast<size_t>(n));
  std::vector<char> visited(static_cast<size_t>(n), 0);
  for (int start = 0; start < n; ++start)
  {
    if (visited[start] || borderNeighbours[start].empty())
      continue;
    int current = start;
    while (current >= 0)
    {
      visited[current] = 1;
      order.push_back(current);
      int next = -1;
      for (int w : borderNeighbours[current]) // lowest unvisited border neighbour
        if (!visited[w] && (next < 0 || w < next))
          next = w;
      current = next;
    }
  }
  for (int v = 0; v < n; ++v)
    if (!visited[v])
      order.push_back(v);
  return order;
}

bool TransferSymbols(const std::vector<DecodedLeaf>& withSymbols, std::vector<DecodedLeaf>& leaves)
{
  if (withSymbols.size() != leaves.size())
    return false;
  for (size_t l = 0; l < leaves.size(); ++l)
    if (withSymbols[l].points != leaves[l].points ||
      withSymbols[l].triangles != leaves[l].triangles ||
      withSymbols[l].symbols.size() != leaves[l].points.size())
      return false;
  for (size_t l = 0; l < leaves.size(); ++l)
    leaves[l].symbols = withSymbols[l].symbols;
  return true;
}

void WritePointSymbols(const std::vector<DecodedLeaf>& leaves, ByteWriter& w)
{
  for (const DecodedLeaf& leaf : leaves)
    for (int v : SymbolOrder(leaf))
      w.VarUInt(leaf.symbols[v]);
}

void ReadPointSymbols(ByteReader& r, size_t paletteSize, std::vector<DecodedLeaf>& leaves)
{
  for (DecodedLeaf& leaf : leaves)
  {
    leaf.symbols.assign(leaf.points.size(), 0);
    for (int v : SymbolOrder(leaf))
    {
      const uint64_t symbol = r.VarUInt();
      if (symbol >= paletteSize)
        throw CompactFormatError("tree section: a point's palette entry is out of range");
      leaf.symbols[v] = static_cast<uint32_t>(symbol);
    }
  }
}
} // namespace compact_detail
} // namespace foldingmeshes
