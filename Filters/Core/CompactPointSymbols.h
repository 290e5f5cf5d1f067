// The compact tree file's per-point palette symbols (CompactTreeFormat.h), coded beside the
// Draco mesh instead of inside it. Almost every point that carries data (a tear, a fold line,
// a mirrored flag) lies on its leaf's border, and neighbours along a border mostly carry the
// same data; so the symbols are written in an order both sides can compute from the decoded
// geometry alone: each leaf's border points walk by walk, then its other points. zlib (the
// tree section's) then codes the runs. Internal to the compact format.
#ifndef foldingmeshes_CompactPointSymbols_h
#define foldingmeshes_CompactPointSymbols_h

#include "CompactByteStream.h"
#include "CompactLeafGeometry.h"

#include <vector>

namespace foldingmeshes
{
namespace compact_detail
{
/**
 * The order in which a decoded leaf's symbols are written: its border points (on an edge of
 * one triangle), walking from the lowest unvisited one to its lowest unvisited border
 * neighbour, then every other point by index. A function of the points' count and the
 * triangles only.
 */
std::vector<int> SymbolOrder(const DecodedLeaf& leaf);

/**
 * Gives `leaves` (decoded from a Draco mesh without the symbol attribute) the symbols of
 * `withSymbols` (decoded from the same leaves coded with it) when Draco gave back the same
 * points in the same order and the same triangles; false (nothing changed) otherwise: the
 * caller then keeps the symbols in Draco.
 */
bool TransferSymbols(const std::vector<DecodedLeaf>& withSymbols, std::vector<DecodedLeaf>& leaves);

/// Writes the decoded leaves' symbols in SymbolOrder.
void WritePointSymbols(const std::vector<DecodedLeaf>& leaves, ByteWriter& w);

/// Reads what WritePointSymbols wrote into `leaves` (decoded, symbols empty); symbols at or
/// beyond `paletteSize` throw CompactFormatError.
void ReadPointSymbols(ByteReader& r, size_t paletteSize, std::vector<DecodedLeaf>& leaves);
} // namespace compact_detail
} // namespace foldingmeshes

#endif
