// Internal to the compact tree file (CompactTreeFormat.cxx): its tree section - the counts,
// the nodes (kind, plane, epsilon), the leaves' headers and the palette of point data.
#ifndef foldingmeshes_CompactTreeSection_h
#define foldingmeshes_CompactTreeSection_h

#include "CompactByteStream.h"
#include "CompactLeafGeometry.h"
#include "FoldingTree.h"

#include <cstdint>
#include <tuple>
#include <vector>

namespace foldingmeshes
{
namespace compact_detail
{
// Limits that keep a corrupt count from allocating without bound (a tree this large would
// not fit in memory anyway).
constexpr uint64_t MaximumCount = uint64_t(1) << 31;
/// A leaf's error budget is stored in units of root epsilon / BudgetCodes (16 bits).
constexpr double BudgetCodes = 65535.0;

/// A point of a leaf below a rotation node may carry a budget level: its error budget is at
/// least level / BudgetLevels of the root epsilon (level 0: its leaf's budget alone). A sector's
/// points differ in what the turns charged them, and the unfolder thins the sector's k copies
/// within these budgets: with the leaf's smallest alone the queen came back with 9,545 faces.
constexpr int BudgetLevels = 4;

/// Everything a point carries besides its position; the tree section lists the distinct ones
/// (the palette), the geometry section gives each point its entry's index.
struct PointData
{
  uint64_t tear = 0, plane = 0;
  uint8_t projected = 0, boundary = 0;
  uint8_t budgetLevel = 0;                              ///< 0..BudgetLevels - 1 (see BudgetLevels)
  std::vector<std::tuple<int, int, uint64_t>> mirrored; ///< (level, flag, mask) records
  bool operator<(const PointData& o) const
  {
    return std::tie(tear, plane, projected, boundary, budgetLevel, mirrored) <
      std::tie(o.tear, o.plane, o.projected, o.boundary, o.budgetLevel, o.mirrored);
  }
};

/// The palette: distinct point data, the most frequent first (small indices code cheaply),
/// and each point's index.
struct Palette
{
  std::vector<PointData> entries;
  std::vector<std::vector<uint32_t>> symbols; ///< per leaf, per point
};

enum LeafFlags : uint8_t
{
  LeafHasBudget = 1,
  LeafHasInputBoundary = 2
};

/// The columns of the nodes and of the palette when the tree section is written field by
/// field (ColumnWriter; header flag bit 2 of the file). The order is the file's.
enum NodeColumn
{
  NodeKinds,     ///< u8 per node: kind | leaf reason << 2
  NodeChildren,  ///< varint per inner node
  NodeEpsilons,  ///< per node but the root: u8 k (epsilon = 2^-k root), 255 + f32 ratio
  NodeFaces,     ///< varint per node
  FoldNormals,   ///< 3 f32 per fold
  FoldOffsets,   ///< f64 per fold: the plane's offset from the grid's corner
  FoldCounts,    ///< 2 varints per fold: discarded faces, projected points
  RotationAxes,  ///< per rotation node: 3 + 3 f64, varint order, varint discarded faces
  LeafFlagBytes, ///< u8 per leaf (LeafFlags)
  LeafPoints,    ///< varint per leaf
  LeafTriangles, ///< varint per leaf
  LeafBudgets,   ///< u16 per leaf (units of root epsilon / BudgetCodes)
  NodeColumnCount
};
enum PaletteColumn
{
  PaletteTears,        ///< varint per entry
  PalettePlanes,       ///< varint per entry
  PaletteFlags,        ///< u8 per entry: projected | boundary << 2 | budget level << 3
  PaletteRecordCounts, ///< varint per entry: its mirrored-flag records
  PaletteRecords,      ///< 2 u8 per record: level, flag
  PaletteMasks,        ///< varint per record
  PaletteColumnCount
};

/// What the tree section says of a leaf before its geometry is decoded.
struct LeafHeader
{
  int node = -1;
  uint8_t flags = 0;
  size_t points = 0, triangles = 0;
  double budget = 0.0; ///< the leaf's error budget (if flags & LeafHasBudget)
};

/// The palette of `tree`'s point data, the most frequent first; budget levels (less
/// `quantizationError`) for the points of leaves below a rotation node where they add to the
/// leaf's budget.
Palette MakePalette(const FoldingTree& tree, double quantizationError);

/// Writes the tree section: counts, nodes, leaf headers (with each leaf's stored error budget,
/// less `quantizationError`) and the palette; the nodes and the palette record by record, or
/// (`columns`) field by field (NodeColumn, PaletteColumn).
void WriteTreeSection(const FoldingTree& tree,
  const LeafGeometryCoding& coding,
  double quantizationError,
  const Palette& palette,
  bool columns,
  ByteWriter& w);

/// Reads what WriteTreeSection wrote (throws CompactFormatError on malformed input); the
/// point symbols may follow (the caller checks the section's end).
void ReadTreeSection(ByteReader& r,
  bool columns,
  FoldingTree& tree,
  LeafGeometryCoding& coding,
  std::vector<LeafHeader>& leaves,
  std::vector<PointData>& palette);

/// Moves the decoded leaves into the tree with their point data; their input ids become
/// running numbers.
void AttachLeaves(FoldingTree& tree,
  std::vector<DecodedLeaf>& decoded,
  const std::vector<LeafHeader>& leaves,
  const std::vector<PointData>& palette);
} // namespace compact_detail
} // namespace foldingmeshes

#endif
