// The compact folding-tree file (.fmz): only what unfolding needs, the leaves' geometry coded
// by Draco at a quantisation the error bound pays for. Layout (all numbers little-endian):
//
//   offset 0   4 bytes  magic "FMZ" 0x1a
//          4   u16      format version (CompactTreeFormatVersion); readers reject others
//          6   u16      flags: bit 0 = an arrays section follows the geometry section; bit 1 =
//                       the points' palette symbols end the tree section (in the order of
//                       CompactPointSymbols.h) instead of being a Draco attribute; bit 2 =
//                       the tree section's nodes and palette are written field by field
//                       (NodeColumn, PaletteColumn in CompactTreeSection.h: each column's
//                       length, then the columns) instead of record by record
//          8   u32      size T of the zlib-compressed tree section, u32 its raw size
//         16   T bytes  tree section (zlib): counts, lengths, quantisation, nodes in preorder
//                       (kind, leaf reason, children, epsilon / root epsilon, fold planes,
//                       rotation axes and orders),
//                       leaves' point / triangle counts, the palette of point data, and
//                       (flag bit 1) each point's palette symbol, leaf by leaf, border first
//     16 + T   u32      size D of the Draco section, then D bytes: one Draco mesh of every
//                       leaf (positions; per point: its leaf and, without flag bit 1, its
//                       palette symbol), faces of each leaf oriented as stored
//   16+T+4+D            with flag bit 0: u32 size A of the zlib-compressed arrays section, u32
//                       its raw size, A bytes: user arrays of the leaves (CompactArray), each
//                       as raw values in the leaves' point / triangle order (the geometry is
//                       then coded sequentially, which keeps that order)
//   end - 4    u32      CRC-32 (zlib) of every byte before it
//
// The tree section is documented field by field in CompactTreeFormat.cxx (WriteTreeSection).
// Positions are quantised on a grid over the stored points' bounding box; the largest move a
// point can get from it (QuantizationError) is subtracted from every point's error budget
// before the budget is stored, so the unfolder's proved bound (root epsilon) still holds:
// quantisation is counted inside the bound, not on top of it. A leaf stores its points'
// smallest budget; a point of a leaf below a rotation node may also carry a budget level in
// its palette entry (2 bits of the entry's flags byte: at least level / 4 of the root epsilon;
// CompactTreeSection.h, BudgetLevels), which files written before levels leave 0.
//
// Not stored (the unfolder does not need them): the input ids of stored points and faces (the
// decoder numbers the stored points and faces 0..n-1), the input's border / non-manifold edge
// lists, the nodes' face lists and detection statistics; user arrays only when given.
#ifndef foldingmeshes_CompactTreeFormat_h
#define foldingmeshes_CompactTreeFormat_h

#include "FoldingTree.h"

#include <string>
#include <vector>

namespace foldingmeshes
{
constexpr int CompactTreeFormatVersion = 1;
/// The position quantisation bits a file may use (CompactTreeOptions::quantizationBits).
constexpr int MinimumQuantizationBits = 6;
constexpr int MaximumQuantizationBits = 24;

struct CompactTreeOptions
{
  /// Position quantisation bits per coordinate on the grid over the stored points' bounding
  /// box (6..24), or 0: automatic - the fewest bits (at least 8) whose quantisation error is at
  /// most half of the smallest error budget of a stored point (1% of the root epsilon when the
  /// tree has no budgets) and at most the seam stitch tolerance of every rotation node
  /// (RotationStitchShare(k) times its epsilon), at most 24.
  int quantizationBits = 0;
  /// Automatic bits only: also at most half of every segmentation node's epsilon (its seams'
  /// stitch tolerance, for two copies of a seam vertex rounded apart), since 2026-12-07 - a
  /// moved bearing's plane tree at 8 bits came back 1.022 epsilon from its mesh (seams that
  /// did not pair, gaps filled flat across 2-3 epsilon), at 10 within 0.23. False: the budgets'
  /// and rotation seams' bits alone, for a caller that proves the file against the mesh and
  /// adds bits where it is not within epsilon (vtkFoldingTreeCompactWriter given the mesh:
  /// the same files as before). Only nodes with seams count (a leaf below has a tear vertex at
  /// their level): of the 29 shared meshes' files without the mesh (compress's fold settings)
  /// only the mech's plane tree changes, 8 -> 9 bits (4,204 -> 4,924 bytes).
  bool segmentationSeamBits = true;
  /// Draco's speed settings to try (0 = slowest ... 10 = fastest; 3 is draco_encoder's -cl 7,
  /// 0 its -cl 10); the smallest result is kept (neither is smallest on every tree).
  std::vector<int> dracoSpeeds{ 3, 0 };
  /// Code the points' palette symbols beside the Draco mesh where Draco gives the leaves back
  /// the same without them (smaller: they are written border by border); false: always as a
  /// Draco attribute (the layout of the first files; tests read both).
  bool symbolsBesideGeometry = true;
  /// Also try the leaves with their common points welded (LeafGeometryCoding::weldPositions:
  /// leaves that meet along a tear coded as one surface), keeping it where it is smaller;
  /// false: never (tests compare both).
  bool weldLeaves = true;
  /// Also try the tree section's nodes and palette field by field (header flag bit 2: all node
  /// kinds, then all child counts, ..., which zlib codes in fewer bytes on trees of more than
  /// a few nodes), keeping it where it is smaller; false: record by record only (the layout
  /// of the first files; tests compare both).
  bool nodeColumns = true;
};

/**
 * A user array of the leaves, opaque to the format: `dataType` and `elementSize` are the
 * caller's (VTK's type id and its size), values raw in the machine's byte order (little-endian).
 */
struct CompactArray
{
  std::string name;
  bool perTriangle = false; ///< else per point
  int dataType = 0;
  int components = 1;
  int elementSize = 4;             ///< bytes of one component (1, 2, 4 or 8)
  std::vector<std::string> leaves; ///< per leaf (preorder): its points' or triangles' values
};

/// What an encoding made (sizes in bytes).
struct CompactTreeStats
{
  size_t bytes = 0;             ///< the whole file
  size_t treeSectionBytes = 0;  ///< compressed tree section
  size_t geometryBytes = 0;     ///< Draco section
  size_t arrayBytes = 0;        ///< compressed arrays section (0: none)
  int quantizationBits = 0;     ///< the bits used
  double quantizationError = 0; ///< largest distance a stored point can move (a length)
  int points = 0;               ///< stored points
  int triangles = 0;            ///< stored triangles
};

/**
 * Encodes `tree` (which must pass FoldingTree::Validate) into `bytes`, with `arrays` (optional,
 * may be empty: then no arrays section) sized for the tree's leaves. False with `error` for an
 * invalid tree, options or arrays.
 */
bool EncodeCompactTree(const FoldingTree& tree,
  const CompactTreeOptions& options,
  std::string& bytes,
  CompactTreeStats* stats,
  std::string& error,
  const std::vector<CompactArray>* arrays = nullptr);

/**
 * Decodes a file written by EncodeCompactTree. False with a description of the first problem
 * for anything else: another format, another version, a truncated or corrupt file (checksum),
 * counts out of range, a decoded tree that fails FoldingTree::Validate. Never crashes on bad
 * bytes. `quantizationError` (optional) receives the stored quantisation error.
 */
bool DecodeCompactTree(const std::string& bytes,
  FoldingTree& tree,
  std::string& error,
  double* quantizationError = nullptr,
  std::vector<CompactArray>* arrays = nullptr);

/// True when `bytes` starts with the compact tree file's magic number.
bool LooksLikeCompactTree(const std::string& bytes);
}

#endif
