// The compact folding-tree file (CompactTreeFormat.h): file header, tree section, checksum.
#include "CompactTreeFormat.h"

#include "CompactByteStream.h"
#include "CompactLeafGeometry.h"
#include "CompactTreeArrays.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace foldingmeshes
{
namespace
{
static_assert(sizeof(double) == 8 && sizeof(float) == 4, "IEEE numbers expected");

const char Magic[4] = { 'F', 'M', 'Z', 0x1a };
constexpr size_t HeaderBytes = 16;
// Limits that keep a corrupt count from allocating without bound (a tree this large would
// not fit in memory anyway).
constexpr uint64_t MaximumCount = uint64_t(1) << 31;

/// Everything a point carries besides its position and budget; the tree section lists the
/// distinct ones (the palette), the geometry section gives each point its entry's index.
struct PointData
{
  uint64_t tear = 0, plane = 0;
  uint8_t projected = 0, boundary = 0;
  std::vector<std::tuple<int, int, uint64_t>> mirrored; ///< (level, flag, mask) records
  bool operator<(const PointData& o) const
  {
    return std::tie(tear, plane, projected, boundary, mirrored) <
      std::tie(o.tear, o.plane, o.projected, o.boundary, o.mirrored);
  }
};

/// The palette: distinct point data, the most frequent first (small indices code cheaply),
/// and each point's index.
struct Palette
{
  std::vector<PointData> entries;
  std::vector<std::vector<uint32_t>> symbols; ///< per leaf, per point
};

Palette MakePalette(const FoldingTree& tree)
{
  std::map<PointData, std::pair<size_t, size_t>> seen; // data -> (count, first occurrence)
  std::vector<std::vector<const PointData*>> keys;
  size_t order = 0;
  for (const FoldingNode& node : tree.nodes)
  {
    if (node.kind != FoldingNodeKind::Leaf)
      continue;
    const FoldingLeafMesh& m = node.mesh;
    std::vector<PointData> data(m.points.size());
    for (size_t v = 0; v < data.size(); ++v)
    {
      data[v].tear = m.tearMask[v];
      data[v].plane = m.planeMask[v];
      data[v].projected = static_cast<uint8_t>(m.projected[v] & 3);
      data[v].boundary = !m.inputBoundary.empty() && m.inputBoundary[v] ? 1 : 0;
    }
    for (const MirroredFlag& f : m.mirroredFlags)
      data[f.point].mirrored.emplace_back(f.level, static_cast<int>(f.flag), f.mirrorMask);
    keys.emplace_back();
    for (const PointData& d : data)
    {
      auto it = seen.emplace(d, std::make_pair(size_t(0), order++)).first;
      ++it->second.first;
      keys.back().push_back(&it->first);
    }
  }
  std::vector<const std::pair<const PointData, std::pair<size_t, size_t>>*> byCount;
  for (const auto& e : seen)
    byCount.push_back(&e);
  std::sort(byCount.begin(),
    byCount.end(),
    [](const auto* a, const auto* b)
    {
      return a->second.first != b->second.first ? a->second.first > b->second.first
                                                : a->second.second < b->second.second;
    });
  Palette palette;
  std::map<const PointData*, uint32_t> index;
  for (const auto* e : byCount)
  {
    index[&e->first] = static_cast<uint32_t>(palette.entries.size());
    palette.entries.push_back(e->first);
  }
  for (const auto& leaf : keys)
  {
    palette.symbols.emplace_back();
    for (const PointData* d : leaf)
      palette.symbols.back().push_back(index[d]);
  }
  return palette;
}

enum LeafFlags : uint8_t
{
  LeafHasBudget = 1,
  LeafHasInputBoundary = 2
};

/// The quantisation bits: the user's, or the fewest (>= 8) whose error is at most half of the
/// smallest error budget of a stored point (1% of the root epsilon without budgets).
int ChooseBits(const FoldingTree& tree, LeafGeometryCoding coding, int requested)
{
  if (requested > 0)
    return requested;
  double smallest = std::numeric_limits<double>::infinity();
  for (const FoldingNode& node : tree.nodes)
    for (double b : node.mesh.errorBudget)
      if (b > 0.0)
        smallest = std::min(smallest, b);
  const double target = std::isfinite(smallest) ? 0.5 * smallest : 0.01 * tree.rootEpsilon;
  for (coding.bits = 8; coding.bits < 24; ++coding.bits)
    if (coding.QuantizationError() <= target)
      break;
  return coding.bits;
}

constexpr double BudgetCodes = 65535.0;

/// A leaf's error budget as stored: the smallest budget of its points minus the quantisation
/// error, rounded down to a multiple of root epsilon / 65535 (the unfolder gets it for every
/// point of the leaf: it may move them less than the .vtm allows, never more).
uint16_t LeafBudgetCode(const FoldingLeafMesh& m, double rootEpsilon, double quantizationError)
{
  // A leaf without budgets (an older tree) may move up to the root epsilon: store what is
  // left of it, so that the quantisation stays inside the bound there too.
  const double smallest = m.errorBudget.empty()
    ? rootEpsilon
    : *std::min_element(m.errorBudget.begin(), m.errorBudget.end());
  const double left = std::max(0.0, smallest - quantizationError);
  return static_cast<uint16_t>(std::min(BudgetCodes, std::floor(left / rootEpsilon * BudgetCodes)));
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

/// A node's epsilon relative to the root's: the exponent k when it is exactly 2^-k (the
/// builder halves epsilon per fold), else 255 and the single-precision ratio.
void WriteEpsilon(double ratio, ByteWriter& w)
{
  int exponent = 0;
  const double mantissa = std::frexp(ratio, &exponent); // ratio = mantissa * 2^exponent
  if (mantissa == 0.5 && exponent <= 1 && exponent > -250)
    w.U8(static_cast<uint8_t>(1 - exponent));
  else
  {
    w.U8(255);
    w.F32(static_cast<float>(ratio));
  }
}

double ReadEpsilon(ByteReader& r)
{
  const uint8_t k = r.U8();
  const double ratio = k == 255 ? static_cast<double>(r.F32()) : std::ldexp(1.0, -k);
  if (!std::isfinite(ratio) || ratio < 0)
    throw CompactFormatError("tree section: invalid epsilon");
  return ratio;
}

void WriteTreeSection(const FoldingTree& tree,
  const LeafGeometryCoding& coding,
  double quantizationError,
  const Palette& palette,
  ByteWriter& w)
{
  // Counts and lengths of the input.
  w.VarUInt(static_cast<uint64_t>(tree.numberOfOriginalFaces));
  w.VarUInt(static_cast<uint64_t>(tree.numberOfOriginalPoints));
  w.VarUInt(static_cast<uint64_t>(tree.numberOfDroppedFaces));
  w.F64(tree.originalArea);
  w.F64(tree.diagonal);
  w.F64(tree.rootEpsilon);
  w.U8(tree.aborted ? 1 : 0);
  // The geometry coding.
  w.F64(coding.origin.x());
  w.F64(coding.origin.y());
  w.F64(coding.origin.z());
  w.F64(coding.range);
  w.U8(static_cast<uint8_t>(coding.bits));
  // Nodes in preorder: kind and leaf reason, children, epsilon, statistics, planes, leaf sizes.
  w.VarUInt(tree.nodes.size());
  for (size_t i = 0; i < tree.nodes.size(); ++i)
  {
    const FoldingNode& node = tree.nodes[i];
    w.U8(
      static_cast<uint8_t>(static_cast<int>(node.kind) | (static_cast<int>(node.leafReason) << 2)));
    if (node.kind != FoldingNodeKind::Leaf)
      w.VarUInt(node.children.size());
    if (i > 0)
      WriteEpsilon(node.epsilon / tree.rootEpsilon, w);
    w.VarUInt(static_cast<uint64_t>(std::max(0, node.numberOfFaces)));
    if (node.kind == FoldingNodeKind::Folding)
    {
      // Single-precision normal (renormalised when read; PlaneError bounds what that moves),
      // double-precision offset from the grid's corner.
      w.F32(static_cast<float>(node.plane.normal.x()));
      w.F32(static_cast<float>(node.plane.normal.y()));
      w.F32(static_cast<float>(node.plane.normal.z()));
      w.F64(node.plane.normal.dot(node.plane.origin - coding.origin));
      w.VarUInt(static_cast<uint64_t>(std::max(0, node.discardedFaces)));
      w.VarUInt(static_cast<uint64_t>(std::max(0, node.projectedPoints)));
    }
    if (node.kind == FoldingNodeKind::Leaf)
    {
      const FoldingLeafMesh& m = node.mesh;
      w.U8(
        static_cast<uint8_t>(LeafHasBudget | (m.inputBoundary.empty() ? 0 : LeafHasInputBoundary)));
      w.VarUInt(static_cast<uint64_t>(m.NumberOfPoints()));
      w.VarUInt(static_cast<uint64_t>(m.NumberOfFaces()));
      w.U16(LeafBudgetCode(m, tree.rootEpsilon, quantizationError));
    }
  }
  // The palette of point data (PointData), the most frequent entry first.
  w.VarUInt(palette.entries.size());
  for (const PointData& d : palette.entries)
  {
    w.VarUInt(d.tear);
    w.VarUInt(d.plane);
    w.U8(static_cast<uint8_t>(d.projected | (d.boundary << 2)));
    w.VarUInt(d.mirrored.size());
    for (const auto& record : d.mirrored)
    {
      w.U8(static_cast<uint8_t>(std::get<0>(record)));
      w.U8(static_cast<uint8_t>(std::get<1>(record)));
      w.VarUInt(std::get<2>(record));
    }
  }
}

struct LeafHeader
{
  int node = -1;
  uint8_t flags = 0;
  size_t points = 0, triangles = 0;
  double budget = 0.0; ///< the leaf's error budget (if flags & LeafHasBudget)
};

void ReadTreeSection(ByteReader& r,
  FoldingTree& tree,
  LeafGeometryCoding& coding,
  std::vector<LeafHeader>& leaves,
  std::vector<PointData>& palette)
{
  tree.numberOfOriginalFaces = static_cast<int>(r.Count(MaximumCount - 1, "original faces"));
  tree.numberOfOriginalPoints = static_cast<int>(r.Count(MaximumCount - 1, "original points"));
  tree.numberOfDroppedFaces = static_cast<int>(r.Count(MaximumCount - 1, "dropped faces"));
  tree.originalArea = r.F64();
  tree.diagonal = r.F64();
  tree.rootEpsilon = r.F64();
  tree.aborted = r.U8() != 0;
  const double x = r.F64(), y = r.F64(), z = r.F64();
  coding.origin = Vec3(x, y, z);
  coding.range = r.F64();
  coding.bits = r.U8();
  if (!coding.origin.allFinite() || !std::isfinite(coding.range) || !(coding.range > 0) ||
    coding.bits < 1 || coding.bits > 30 || !std::isfinite(tree.rootEpsilon))
    throw CompactFormatError("tree section: invalid geometry coding");

  // A node takes at least two bytes of the section.
  const size_t n = r.Count(std::min<uint64_t>(MaximumCount, r.Remaining() / 2), "nodes");
  if (n == 0)
    throw CompactFormatError("tree section: no nodes");
  tree.nodes.assign(n, FoldingNode());
  std::vector<std::pair<int, size_t>> open; // (node, children still to come)
  for (size_t i = 0; i < n; ++i)
  {
    FoldingNode& node = tree.nodes[i];
    const uint8_t kindAndReason = r.U8();
    const int kind = kindAndReason & 3, reason = kindAndReason >> 2;
    if (kind > static_cast<int>(FoldingNodeKind::Segmentation) ||
      reason > static_cast<int>(LeafReason::Aborted))
      throw CompactFormatError("tree section: unknown node kind or leaf reason");
    node.kind = static_cast<FoldingNodeKind>(kind);
    node.leafReason = static_cast<LeafReason>(reason);
    // Parent: the latest node still waiting for children (preorder).
    if (i > 0)
    {
      if (open.empty())
        throw CompactFormatError("tree section: more nodes than the children listed");
      node.parent = open.back().first;
      FoldingNode& parent = tree.nodes[node.parent];
      parent.children.push_back(static_cast<int>(i));
      node.depth = parent.depth + 1;
      node.foldsAbove = parent.foldsAbove + (parent.kind == FoldingNodeKind::Folding ? 1 : 0);
      if (--open.back().second == 0)
        open.pop_back();
    }
    if (node.depth >= MaximumFoldingTreeLevels)
      throw CompactFormatError("tree section: deeper than the supported number of levels");
    if (node.kind != FoldingNodeKind::Leaf)
    {
      const size_t children = r.Count(n - 1, "children");
      if (children == 0)
        throw CompactFormatError("tree section: an inner node without children");
      open.emplace_back(static_cast<int>(i), children);
    }
    node.epsilon = i > 0 ? ReadEpsilon(r) * tree.rootEpsilon : tree.rootEpsilon;
    node.numberOfFaces = static_cast<int>(r.Count(MaximumCount - 1, "node faces"));
    if (node.kind == FoldingNodeKind::Folding)
    {
      const double nx = r.F32(), ny = r.F32(), nz = r.F32(), offset = r.F64();
      node.plane.normal = Vec3(nx, ny, nz);
      if (!node.plane.normal.allFinite() || !(node.plane.normal.norm() > 0.5) ||
        !(node.plane.normal.norm() < 2.0) || !std::isfinite(offset))
        throw CompactFormatError("tree section: invalid fold plane");
      node.plane.normal.normalize();
      // Any point of the plane will do: the one nearest the grid's centre.
      const Vec3 centre = coding.origin + Vec3::Constant(0.5 * coding.range);
      node.plane.origin = coding.origin + offset * node.plane.normal;
      node.plane.origin = node.plane.Project(centre);
      node.discardedFaces = static_cast<int>(r.Count(MaximumCount - 1, "discarded faces"));
      node.projectedPoints = static_cast<int>(r.Count(MaximumCount - 1, "projected points"));
    }
    if (node.kind == FoldingNodeKind::Leaf)
    {
      LeafHeader leaf;
      leaf.node = static_cast<int>(i);
      leaf.flags = r.U8();
      leaf.points = r.Count(MaximumCount - 1, "leaf points");
      leaf.triangles = r.Count(MaximumCount - 1, "leaf triangles");
      if (leaf.flags & LeafHasBudget)
        leaf.budget = r.U16() * tree.rootEpsilon / BudgetCodes;
      leaves.push_back(leaf);
    }
  }
  if (!open.empty())
    throw CompactFormatError("tree section: fewer nodes than the children listed");
  const size_t entries =
    r.Count(std::min<uint64_t>(MaximumCount, r.Remaining()), "palette entries");
  for (size_t e = 0; e < entries; ++e)
  {
    PointData d;
    d.tear = r.VarUInt();
    d.plane = r.VarUInt();
    const uint8_t flags = r.U8();
    d.projected = flags & 3;
    d.boundary = (flags >> 2) & 1;
    const size_t records = r.Count(2 * MaximumFoldingTreeLevels, "mirrored-flag records");
    for (size_t k = 0; k < records; ++k)
    {
      const int level = r.U8(), flag = r.U8();
      if (flag > static_cast<int>(LevelFlag::Plane))
        throw CompactFormatError("tree section: unknown mirrored flag");
      d.mirrored.emplace_back(level, flag, r.VarUInt());
    }
    palette.push_back(std::move(d));
  }
  if (r.Remaining() != 0)
    throw CompactFormatError("tree section: unexpected bytes after its end");
}

/// Moves the decoded leaves into the tree with their point data; their input ids become
/// running numbers.
void AttachLeaves(FoldingTree& tree,
  std::vector<DecodedLeaf>& decoded,
  const std::vector<LeafHeader>& leaves,
  const std::vector<PointData>& palette)
{
  int pointId = 0, faceId = 0;
  for (size_t l = 0; l < leaves.size(); ++l)
  {
    DecodedLeaf& leaf = decoded[l];
    FoldingLeafMesh& m = tree.nodes[leaves[l].node].mesh;
    if (leaf.triangles.size() != leaves[l].triangles)
      throw CompactFormatError("geometry section: a leaf's triangle count differs from the tree's");
    m.points = std::move(leaf.points);
    m.triangles = std::move(leaf.triangles);
    const size_t np = m.points.size();
    m.tearMask.resize(np);
    m.planeMask.resize(np);
    m.projected.resize(np);
    m.inputBoundary.resize(np);
    for (size_t v = 0; v < np; ++v)
    {
      if (leaf.symbols[v] >= palette.size())
        throw CompactFormatError("geometry section: a point's palette entry is out of range");
      const PointData& d = palette[leaf.symbols[v]];
      m.tearMask[v] = d.tear;
      m.planeMask[v] = d.plane;
      m.projected[v] = static_cast<char>(d.projected);
      m.inputBoundary[v] = static_cast<char>(d.boundary);
      for (const auto& record : d.mirrored)
      {
        MirroredFlag f;
        f.point = static_cast<int>(v);
        f.level = std::get<0>(record);
        f.flag = static_cast<LevelFlag>(std::get<1>(record));
        f.mirrorMask = std::get<2>(record);
        m.mirroredFlags.push_back(f);
      }
    }
    if (!(leaves[l].flags & LeafHasInputBoundary))
      m.inputBoundary.clear();
    if (leaves[l].flags & LeafHasBudget)
      m.errorBudget.assign(np, leaves[l].budget);
    m.originalPointIds.resize(np);
    for (int& id : m.originalPointIds)
      id = pointId++;
    m.originalFaceIds.resize(m.triangles.size());
    for (int& id : m.originalFaceIds)
      id = faceId++;
    std::sort(m.mirroredFlags.begin(),
      m.mirroredFlags.end(),
      [](const MirroredFlag& a, const MirroredFlag& b)
      {
        return std::tie(a.point, a.level, a.flag, a.mirrorMask) <
          std::tie(b.point, b.level, b.flag, b.mirrorMask);
      });
  }
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
    (options.quantizationBits < 6 || options.quantizationBits > 24))
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
  coding.bits = ChooseBits(tree, coding, options.quantizationBits);
  const double quantizationError = coding.QuantizationError() + PlaneError(tree);

  // Per leaf: points, triangles and palette symbols.
  const Palette palette = MakePalette(tree);
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

  std::string geometry;
  if (!EncodeLeafGeometry(leaves, coding, options.dracoSpeed, geometry, error))
    return false;
  ByteWriter section;
  WriteTreeSection(tree, coding, quantizationError, palette, section);
  const std::string packed = Deflate(section.Bytes);
  if (packed.empty())
  {
    error = "zlib cannot compress the tree section";
    return false;
  }

  if (packed.size() > 0xffffffffu || section.Bytes.size() > 0xffffffffu ||
    geometry.size() > 0xffffffffu)
  {
    error = "the tree is too large for the compact format (a section over 4 GB)";
    return false;
  }
  ByteWriter file;
  file.Raw(std::string(Magic, 4));
  file.U8(static_cast<uint8_t>(CompactTreeFormatVersion & 0xff));
  file.U8(static_cast<uint8_t>(CompactTreeFormatVersion >> 8));
  file.U8(withArrays ? 1 : 0); // flags: bit 0 = arrays section
  file.U8(0);
  file.U32(static_cast<uint32_t>(packed.size()));
  file.U32(static_cast<uint32_t>(section.Bytes.size()));
  file.Raw(packed);
  file.U32(static_cast<uint32_t>(geometry.size()));
  file.Raw(geometry);
  std::string packedArrays;
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
  if (stats)
  {
    stats->bytes = bytes.size();
    stats->treeSectionBytes = packed.size();
    stats->geometryBytes = geometry.size();
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
    if (flags & ~1)
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
    ReadTreeSection(section, tree, coding, leaves, palette);
    std::vector<DecodedLeaf> decoded;
    if (!DecodeLeafGeometry(
          geometry, geometrySize, coding, static_cast<int>(leaves.size()), decoded, error))
      throw CompactFormatError(error);
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
