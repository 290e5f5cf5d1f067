// The compact folding-tree file (CompactTreeFormat.h): file header, tree section, checksum.
#include "CompactTreeFormat.h"

#include "CompactByteStream.h"
#include "CompactLeafGeometry.h"
#include "CompactPointSymbols.h"
#include "CompactTreeArrays.h"
#include "CompactTreeSection.h"
#include "ParallelTasks.h"
#include "RotationAxis.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace foldingmeshes
{
using namespace compact_detail;
namespace
{
static_assert(sizeof(double) == 8 && sizeof(float) == 4, "IEEE numbers expected");

const char Magic[4] = { 'F', 'M', 'Z', 0x1a };
constexpr size_t HeaderBytes = 16;
/// The quantisation bits: the user's, or the fewest (>= 8) whose error is at most half of the
/// smallest error budget of a stored point (1% of the root epsilon without budgets), and at
/// most the stitch tolerance of every rotation node's seams (at the unfolder's default scale,
/// RotationStitchShare): quantisation parts the seams of a sector, which the unfolder stitches
/// within that tolerance - the bearing's 64 sectors at 8 bits came back with 10,981 faces for
/// its 3,322 (535 bytes; 6,592 seam edges left open), at the 10 bits of this rule with 3,322
/// (659 bytes; none open). A measured choice, not a guarantee (partners are quantised apart by
/// up to twice the error; at 11 bits the bearing left 448 seam edges to the repair):
/// docs/compression.md. With `segmentationSeams` (CompactTreeOptions::segmentationSeamBits)
/// also at most SegmentationSeamShare of the epsilon of every segmentation node with seams (a
/// leaf below it has a tear vertex at its level): the unfolder stitches its seams within its
/// epsilon (at the default StitchToleranceScale, 1), and two copies of a seam vertex rounded
/// apart are up to twice the error apart - a ceiling, measured (the moved bearing), not a
/// guarantee: mirrored copies add their planes' rounding.
constexpr double SegmentationSeamShare = 0.5;

/// Per node: a segmentation node with seams - a leaf below it has a vertex (or a mirrored
/// vertex's record) on a tear of its level.
std::vector<char> SegmentationsWithSeams(const FoldingTree& tree)
{
  std::vector<char> seamed(tree.nodes.size(), 0);
  for (const FoldingNode& leaf : tree.nodes)
  {
    if (leaf.kind != FoldingNodeKind::Leaf)
      continue;
    uint64_t tears = 0;
    for (uint64_t m : leaf.mesh.tearMask)
      tears |= m;
    for (const MirroredFlag& f : leaf.mesh.mirroredFlags)
      if (f.flag == LevelFlag::Tear && f.level >= 0 && f.level < 64)
        tears |= uint64_t(1) << f.level;
    for (int a = leaf.parent; a >= 0; a = tree.nodes[a].parent)
    {
      const FoldingNode& node = tree.nodes[a];
      if (node.kind == FoldingNodeKind::Segmentation && node.depth >= 0 && node.depth < 64 &&
        (tears >> node.depth) & 1)
        seamed[a] = 1;
    }
  }
  return seamed;
}
int ChooseBits(const FoldingTree& tree,
  LeafGeometryCoding coding,
  int requested,
  bool segmentationSeams)
{
  if (requested > 0)
    return requested;
  double smallest = std::numeric_limits<double>::infinity();
  double seams = std::numeric_limits<double>::infinity();
  const std::vector<char> seamed =
    segmentationSeams ? SegmentationsWithSeams(tree) : std::vector<char>(tree.nodes.size(), 0);
  for (size_t i = 0; i < tree.nodes.size(); ++i)
  {
    const FoldingNode& node = tree.nodes[i];
    for (double b : node.mesh.errorBudget)
      if (b > 0.0)
        smallest = std::min(smallest, b);
    if (node.kind == FoldingNodeKind::Rotation && node.epsilon > 0.0)
      seams = std::min(seams, RotationStitchShare(node.rotationOrder) * node.epsilon);
    if (seamed[i] && node.epsilon > 0.0)
      seams = std::min(seams, SegmentationSeamShare * node.epsilon);
  }
  const double target =
    std::min(std::isfinite(smallest) ? 0.5 * smallest : 0.01 * tree.rootEpsilon, seams);
  for (coding.bits = 8; coding.bits < MaximumQuantizationBits; ++coding.bits)
    if (coding.QuantizationError() <= target)
      break;
  return coding.bits;
}

/// The most a fold plane stored with a single-precision normal can move a reflected point, on
/// all the folds of a path: each reflection moves a point at distance r from the plane's
/// origin by at most 2 r |dn| + its offset's rounding; r is at most four diagonals
/// (FoldingTree::Validate), |dn| a few single-precision units.
double PlaneError(const FoldingTree& tree)
{
  const double perFold = 2.0 * 4.0 * tree.diagonal * 4.0 * std::ldexp(1.0, -24);
  int folds = 0;
  for (const FoldingNode& node : tree.nodes)
    folds = std::max(folds, node.foldsAbove);
  return folds * perFold;
}

/// The tree and geometry sections as they will be written.
struct SectionsToWrite
{
  std::string packedTree; ///< zlib'd tree section
  size_t rawTreeBytes = 0;
  bool columns = false; ///< the tree section's nodes and palette field by field
  std::string geometry; ///< Draco section
  bool symbolsBeside = false;
};

/// What every way of coding the leaves starts from.
struct EncodingInput
{
  const FoldingTree& tree;
  const CompactTreeOptions& options;
  const LeafGeometryCoding& coding;
  double quantizationError;
  const Palette& palette;
  const std::vector<LeafToEncode>& leaves;
};

/**
 * One way of coding the leaves (a Draco speed setting, with or without welding the leaves'
 * common points): the symbols beside the Draco mesh where Draco gives back the same leaves
 * without them (else in it), and the smaller of the tree section's two layouts. False with
 * `error` when Draco fails.
 */
bool EncodeVariant(const EncodingInput& in,
  int speed,
  bool weld,
  SectionsToWrite& candidate,
  std::string& error)
{
  const CompactTreeOptions& options = in.options;
  const std::vector<LeafToEncode>& leaves = in.leaves;
  LeafGeometryCoding withAttribute = in.coding;
  withAttribute.weldPositions = weld;
  LeafGeometryCoding beside = withAttribute;
  beside.symbolAttribute = false;
  std::vector<DecodedLeaf> decoded, besideDecoded;
  std::string besideGeometry, besideError;
  if (!EncodeLeafGeometry(leaves, withAttribute, speed, candidate.geometry, decoded, error))
    return false;
  candidate.symbolsBeside = options.symbolsBesideGeometry &&
    EncodeLeafGeometry(leaves, beside, speed, besideGeometry, besideDecoded, besideError) &&
    TransferSymbols(decoded, besideDecoded);
  if (candidate.symbolsBeside)
    candidate.geometry = std::move(besideGeometry);
  // The tree section record by record and (nodeColumns) field by field: the smaller kept
  // (columns cost their lengths, more than they save on trees of a few nodes).
  for (const bool columns : { false, true })
  {
    if (columns && !options.nodeColumns)
      continue;
    ByteWriter section;
    WriteTreeSection(in.tree,
      candidate.symbolsBeside ? beside : withAttribute,
      in.quantizationError,
      in.palette,
      columns,
      section);
    if (candidate.symbolsBeside)
      WritePointSymbols(besideDecoded, section);
    std::string packed = Deflate(section.Bytes);
    if (candidate.packedTree.empty() ||
      (!packed.empty() && packed.size() < candidate.packedTree.size()))
    {
      candidate.packedTree = std::move(packed);
      candidate.rawTreeBytes = section.Bytes.size();
      candidate.columns = columns;
    }
  }
  if (candidate.packedTree.empty())
  {
    error = "zlib cannot compress the tree section";
    return false;
  }
  return true;
}

/**
 * Codes the leaves every way the options allow - each Draco speed setting, with and without
 * welding the leaves' common points (EncodeVariant) - and keeps the smallest tree + geometry
 * sections. The variants are coded in parallel (each on its own data) and judged in a fixed
 * order, so the file is the same for any thread count.
 */
bool EncodeSmallestSections(const EncodingInput& in, SectionsToWrite& best, std::string& error)
{
  std::vector<std::pair<int, bool>> variants; // (speed, weld)
  for (const bool weld : { true, false })
    for (const int speed : in.options.dracoSpeeds)
      if (!weld || (in.options.weldLeaves && !in.coding.keepOrder))
        variants.emplace_back(speed, weld);
  std::vector<SectionsToWrite> candidates(variants.size());
  std::vector<std::string> errors(variants.size());
  std::vector<char> coded(variants.size(), 0);
  RunTasksInParallel(variants.size(),
    [&](size_t i) {
      coded[i] = EncodeVariant(in, variants[i].first, variants[i].second, candidates[i], errors[i]);
    });
  bool any = false;
  for (size_t i = 0; i < variants.size(); ++i)
  {
    if (!coded[i])
    {
      error = errors[i];
      if (candidates[i].geometry.empty())
        continue;   // Draco failed: try the other variants
      return false; // zlib failed
    }
    if (!any ||
      candidates[i].packedTree.size() + candidates[i].geometry.size() <
        best.packedTree.size() + best.geometry.size())
      best = std::move(candidates[i]);
    any = true;
  }
  if (any)
    error.clear();
  return any; // else error says why Draco failed
}

/// The file: header, the sections, the arrays section (if `arrays` has any), checksum.
bool AssembleFile(const SectionsToWrite& sections,
  const std::vector<CompactArray>* arrays,
  std::string& bytes,
  std::string& packedArrays,
  std::string& error)
{
  const bool withArrays = arrays && !arrays->empty();
  const std::string& packed = sections.packedTree;
  const std::string& geometry = sections.geometry;
  const size_t rawSectionSize = sections.rawTreeBytes;
  if (packed.size() > 0xffffffffu || rawSectionSize > 0xffffffffu || geometry.size() > 0xffffffffu)
  {
    error = "the tree is too large for the compact format (a section over 4 GB)";
    return false;
  }
  ByteWriter file;
  file.Raw(std::string(Magic, 4));
  file.U8(static_cast<uint8_t>(CompactTreeFormatVersion & 0xff));
  file.U8(static_cast<uint8_t>(CompactTreeFormatVersion >> 8));
  file.U8(static_cast<uint8_t>(
    (withArrays ? 1 : 0) | (sections.symbolsBeside ? 2 : 0) | (sections.columns ? 4 : 0)));
  file.U8(0);
  file.U32(static_cast<uint32_t>(packed.size()));
  file.U32(static_cast<uint32_t>(rawSectionSize));
  file.Raw(packed);
  file.U32(static_cast<uint32_t>(geometry.size()));
  file.Raw(geometry);
  if (withArrays)
  {
    ByteWriter values;
    WriteArrays(*arrays, values);
    packedArrays = Deflate(values.Bytes);
    if (packedArrays.empty() || packedArrays.size() > 0xffffffffu ||
      values.Bytes.size() > 0xffffffffu)
    {
      error = "the arrays cannot be compressed into the compact format (over 4 GB?)";
      return false;
    }
    file.U32(static_cast<uint32_t>(packedArrays.size()));
    file.U32(static_cast<uint32_t>(values.Bytes.size()));
    file.Raw(packedArrays);
  }
  file.U32(Crc(file.Bytes.data(), file.Bytes.size()));
  bytes = std::move(file.Bytes);
  return true;
}

}

bool LooksLikeCompactTree(const std::string& bytes)
{
  return bytes.size() >= 4 && std::equal(Magic, Magic + 4, bytes.begin());
}

bool EncodeCompactTree(const FoldingTree& tree,
  const CompactTreeOptions& options,
  std::string& bytes,
  CompactTreeStats* stats,
  std::string& error,
  const std::vector<CompactArray>* arrays)
{
  error = tree.Validate();
  if (!error.empty())
  {
    error = "invalid tree: " + error;
    return false;
  }
  if (options.quantizationBits != 0 &&
    (options.quantizationBits < MinimumQuantizationBits ||
      options.quantizationBits > MaximumQuantizationBits))
  {
    error = "quantization bits must be 0 (automatic) or 6..24";
    return false;
  }
  // The grid over the stored points.
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (const FoldingNode& node : tree.nodes)
    for (const Vec3& p : node.mesh.points)
    {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  const bool withArrays = arrays && !arrays->empty();
  if (withArrays)
  {
    error = CheckArrays(*arrays, tree);
    if (!error.empty())
      return false;
  }
  LeafGeometryCoding coding;
  coding.keepOrder = withArrays;
  coding.origin = lo;
  coding.range = std::max((hi - lo).maxCoeff(), 1e-9 * tree.diagonal);
  coding.bits = ChooseBits(tree, coding, options.quantizationBits, options.segmentationSeamBits);
  const double quantizationError = coding.QuantizationError() + PlaneError(tree);

  // Per leaf: points, triangles and palette symbols.
  const Palette palette = MakePalette(tree, quantizationError);
  std::vector<LeafToEncode> leaves;
  for (const FoldingNode& node : tree.nodes)
  {
    if (node.kind != FoldingNodeKind::Leaf)
      continue;
    LeafToEncode leaf;
    leaf.mesh = &node.mesh;
    leaf.symbols = palette.symbols[leaves.size()];
    leaves.push_back(std::move(leaf));
  }

  SectionsToWrite sections;
  const EncodingInput input{ tree, options, coding, quantizationError, palette, leaves };
  if (!EncodeSmallestSections(input, sections, error))
    return false;
  std::string packedArrays;
  if (!AssembleFile(sections, arrays, bytes, packedArrays, error))
    return false;
  if (stats)
  {
    stats->bytes = bytes.size();
    stats->treeSectionBytes = sections.packedTree.size();
    stats->geometryBytes = sections.geometry.size();
    stats->arrayBytes = packedArrays.size();
    stats->quantizationBits = coding.bits;
    stats->quantizationError = quantizationError;
    stats->points = tree.StoredPoints();
    stats->triangles = tree.StoredFaces();
  }
  return true;
}

bool DecodeCompactTree(const std::string& bytes,
  FoldingTree& tree,
  std::string& error,
  double* quantizationError,
  std::vector<CompactArray>* arrays)
{
  if (arrays)
    arrays->clear();
  tree = FoldingTree();
  try
  {
    if (!LooksLikeCompactTree(bytes))
      throw CompactFormatError("not a compact folding-tree file (no FMZ magic number)");
    ByteReader header(bytes.data(), bytes.size(), "header");
    header.Take(4);
    const int version = header.U8() | (header.U8() << 8);
    if (version != CompactTreeFormatVersion)
      throw CompactFormatError("format version " + std::to_string(version) +
        " is not supported (this reader reads version " + std::to_string(CompactTreeFormatVersion) +
        ")");
    const uint8_t flags = header.U8();
    header.Take(1);
    if (flags & ~7)
      throw CompactFormatError("unknown flags in the header");
    if (bytes.size() < HeaderBytes + 8)
      throw CompactFormatError("truncated");
    ByteReader tail(bytes.data() + bytes.size() - 4, 4, "checksum");
    if (tail.U32() != Crc(bytes.data(), bytes.size() - 4))
      throw CompactFormatError("checksum mismatch: the file is truncated or corrupt");
    const uint32_t packedSize = header.U32(), rawSize = header.U32();
    if (rawSize > 64 * (static_cast<uint64_t>(packedSize) + 64))
      throw CompactFormatError("tree section: implausible size");
    const std::string raw = Inflate(header.Take(packedSize), packedSize, rawSize);
    const uint32_t geometrySize = header.U32();
    const char* geometry = header.Take(geometrySize);
    std::string rawArrays;
    if (flags & 1)
    {
      const uint32_t packedArrays = header.U32(), rawArraysSize = header.U32();
      if (rawArraysSize > 1100 * (static_cast<uint64_t>(packedArrays) + 64))
        throw CompactFormatError("arrays section: implausible size");
      rawArrays = Inflate(header.Take(packedArrays), packedArrays, rawArraysSize);
    }
    if (header.Remaining() != 4)
      throw CompactFormatError("unexpected bytes after the last section");

    ByteReader section(raw.data(), raw.size(), "tree section");
    LeafGeometryCoding coding;
    std::vector<LeafHeader> leaves;
    std::vector<PointData> palette;
    coding.symbolAttribute = !(flags & 2);
    ReadTreeSection(section, (flags & 4) != 0, tree, coding, leaves, palette);
    std::vector<DecodedLeaf> decoded;
    if (!DecodeLeafGeometry(
          geometry, geometrySize, coding, static_cast<int>(leaves.size()), decoded, error))
      throw CompactFormatError(error);
    if (!coding.symbolAttribute)
      ReadPointSymbols(section, palette.size(), decoded);
    if (section.Remaining() != 0)
      throw CompactFormatError("tree section: unexpected bytes after its end");
    AttachLeaves(tree, decoded, leaves, palette);
    if (flags & 1)
    {
      ByteReader arraySection(rawArrays.data(), rawArrays.size(), "arrays section");
      std::vector<CompactArray> read = ReadArrays(arraySection, tree);
      if (arrays)
        *arrays = std::move(read);
    }
    if (quantizationError)
      *quantizationError = coding.QuantizationError() + PlaneError(tree);
  }
  catch (const std::exception& e) // CompactFormatError, and bad_alloc or length_error
  {
    error = e.what();
    tree = FoldingTree();
    if (arrays)
      arrays->clear();
    return false;
  }
  const std::string invalid = tree.Validate();
  if (!invalid.empty())
  {
    error = "the decoded tree is invalid: " + invalid;
    tree = FoldingTree();
    if (arrays)
      arrays->clear();
    return false;
  }
  return true;
}
}
