// The tree section of the compact folding-tree file (CompactTreeSection.h).
#include "CompactTreeSection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace foldingmeshes
{
namespace compact_detail
{
namespace
{
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

/// Whether a node lies below a rotation node.
bool BelowRotation(const FoldingTree& tree, const FoldingNode& node)
{
  for (int a = node.parent; a >= 0; a = tree.nodes[a].parent)
    if (tree.nodes[a].kind == FoldingNodeKind::Rotation)
      return true;
  return false;
}

/// The budget level of a point's budget less the quantisation error (rounded down), or 0
/// where that level gives no more than the leaf's budget.
uint8_t BudgetLevel(double budget, double leafBudget, double rootEpsilon)
{
  const double level = std::floor(budget / rootEpsilon * BudgetLevels);
  if (!(level >= 1.0))
    return 0;
  const int l = static_cast<int>(std::min<double>(BudgetLevels - 1, level));
  return l * rootEpsilon / BudgetLevels > leafBudget ? static_cast<uint8_t>(l) : 0;
}
} // namespace

Palette MakePalette(const FoldingTree& tree, double quantizationError)
{
  std::map<PointData, std::pair<size_t, size_t>> seen; // data -> (count, first occurrence)
  std::vector<std::vector<const PointData*>> keys;
  size_t order = 0;
  for (const FoldingNode& node : tree.nodes)
  {
    if (node.kind != FoldingNodeKind::Leaf)
      continue;
    const FoldingLeafMesh& m = node.mesh;
    const bool levels = !m.errorBudget.empty() && BelowRotation(tree, node);
    const double leafBudget =
      LeafBudgetCode(m, tree.rootEpsilon, quantizationError) * tree.rootEpsilon / BudgetCodes;
    std::vector<PointData> data(m.points.size());
    for (size_t v = 0; v < data.size(); ++v)
    {
      data[v].tear = m.tearMask[v];
      data[v].plane = m.planeMask[v];
      data[v].projected = static_cast<uint8_t>(m.projected[v] & 3);
      data[v].boundary = !m.inputBoundary.empty() && m.inputBoundary[v] ? 1 : 0;
      if (levels)
        data[v].budgetLevel =
          BudgetLevel(m.errorBudget[v] - quantizationError, leafBudget, tree.rootEpsilon);
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
  bool columns,
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
  // Nodes in preorder: kind and leaf reason, children, epsilon, statistics, planes, rotation
  // axes and orders (kind 3), leaf sizes; node by node, or (`columns`) field by field.
  w.VarUInt(tree.nodes.size());
  ColumnWriter c(w, columns, NodeColumnCount);
  for (size_t i = 0; i < tree.nodes.size(); ++i)
  {
    const FoldingNode& node = tree.nodes[i];
    c[NodeKinds].U8(
      static_cast<uint8_t>(static_cast<int>(node.kind) | (static_cast<int>(node.leafReason) << 2)));
    if (node.kind != FoldingNodeKind::Leaf)
      c[NodeChildren].VarUInt(node.children.size());
    if (i > 0)
      WriteEpsilon(node.epsilon / tree.rootEpsilon, c[NodeEpsilons]);
    c[NodeFaces].VarUInt(static_cast<uint64_t>(std::max(0, node.numberOfFaces)));
    if (node.kind == FoldingNodeKind::Folding)
    {
      // Single-precision normal (renormalised when read; PlaneError bounds what that moves),
      // double-precision offset from the grid's corner.
      c[FoldNormals].F32(static_cast<float>(node.plane.normal.x()));
      c[FoldNormals].F32(static_cast<float>(node.plane.normal.y()));
      c[FoldNormals].F32(static_cast<float>(node.plane.normal.z()));
      c[FoldOffsets].F64(node.plane.normal.dot(node.plane.origin - coding.origin));
      c[FoldCounts].VarUInt(static_cast<uint64_t>(std::max(0, node.discardedFaces)));
      c[FoldCounts].VarUInt(static_cast<uint64_t>(std::max(0, node.projectedPoints)));
    }
    if (node.kind == FoldingNodeKind::Rotation)
    {
      // Double precision: a turn moves a point by its radius times the direction's error.
      for (int k = 0; k < 3; ++k)
        c[RotationAxes].F64(node.axis.origin[k]);
      for (int k = 0; k < 3; ++k)
        c[RotationAxes].F64(node.axis.direction[k]);
      c[RotationAxes].VarUInt(static_cast<uint64_t>(node.rotationOrder));
      c[RotationAxes].VarUInt(static_cast<uint64_t>(std::max(0, node.discardedFaces)));
    }
    if (node.kind == FoldingNodeKind::Leaf)
    {
      const FoldingLeafMesh& m = node.mesh;
      c[LeafFlagBytes].U8(
        static_cast<uint8_t>(LeafHasBudget | (m.inputBoundary.empty() ? 0 : LeafHasInputBoundary)));
      c[LeafPoints].VarUInt(static_cast<uint64_t>(m.NumberOfPoints()));
      c[LeafTriangles].VarUInt(static_cast<uint64_t>(m.NumberOfFaces()));
      c[LeafBudgets].U16(LeafBudgetCode(m, tree.rootEpsilon, quantizationError));
    }
  }
  c.Finish();
  // The palette of point data (PointData), the most frequent entry first.
  w.VarUInt(palette.entries.size());
  ColumnWriter p(w, columns, PaletteColumnCount);
  for (const PointData& d : palette.entries)
  {
    p[PaletteTears].VarUInt(d.tear);
    p[PalettePlanes].VarUInt(d.plane);
    p[PaletteFlags].U8(
      static_cast<uint8_t>(d.projected | (d.boundary << 2) | (d.budgetLevel << 3)));
    p[PaletteRecordCounts].VarUInt(d.mirrored.size());
    for (const auto& record : d.mirrored)
    {
      p[PaletteRecords].U8(static_cast<uint8_t>(std::get<0>(record)));
      p[PaletteRecords].U8(static_cast<uint8_t>(std::get<1>(record)));
      p[PaletteMasks].VarUInt(std::get<2>(record));
    }
  }
  p.Finish();
}

/// The palette of point data (WriteTreeSection's last part).
static void ReadPalette(ByteReader& r, bool columns, std::vector<PointData>& palette)
{
  const size_t entries =
    r.Count(std::min<uint64_t>(MaximumCount, r.Remaining()), "palette entries");
  ColumnReader c(r, columns, PaletteColumnCount, "tree section");
  for (size_t e = 0; e < entries; ++e)
  {
    PointData d;
    d.tear = c[PaletteTears].VarUInt();
    d.plane = c[PalettePlanes].VarUInt();
    const uint8_t flags = c[PaletteFlags].U8();
    d.projected = flags & 3;
    d.boundary = (flags >> 2) & 1;
    d.budgetLevel = (flags >> 3) & (BudgetLevels - 1); // 0 in files written before levels
    const size_t records =
      c[PaletteRecordCounts].Count(2 * MaximumFoldingTreeLevels, "mirrored-flag records");
    for (size_t k = 0; k < records; ++k)
    {
      const int level = c[PaletteRecords].U8(), flag = c[PaletteRecords].U8();
      if (flag > static_cast<int>(LevelFlag::Plane))
        throw CompactFormatError("tree section: unknown mirrored flag");
      d.mirrored.emplace_back(level, flag, c[PaletteMasks].VarUInt());
    }
    palette.push_back(std::move(d));
  }
  c.Finish();
}

void ReadTreeSection(ByteReader& r,
  bool columns,
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
  ColumnReader c(r, columns, NodeColumnCount, "tree section");
  for (size_t i = 0; i < n; ++i)
  {
    FoldingNode& node = tree.nodes[i];
    const uint8_t kindAndReason = c[NodeKinds].U8();
    const int kind = kindAndReason & 3, reason = kindAndReason >> 2;
    if (kind > static_cast<int>(FoldingNodeKind::Rotation) ||
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
      const size_t children = c[NodeChildren].Count(n - 1, "children");
      if (children == 0)
        throw CompactFormatError("tree section: an inner node without children");
      open.emplace_back(static_cast<int>(i), children);
    }
    node.epsilon = i > 0 ? ReadEpsilon(c[NodeEpsilons]) * tree.rootEpsilon : tree.rootEpsilon;
    node.numberOfFaces = static_cast<int>(c[NodeFaces].Count(MaximumCount - 1, "node faces"));
    if (node.kind == FoldingNodeKind::Folding)
    {
      const double nx = c[FoldNormals].F32(), ny = c[FoldNormals].F32(), nz = c[FoldNormals].F32(),
                   offset = c[FoldOffsets].F64();
      node.plane.normal = Vec3(nx, ny, nz);
      if (!node.plane.normal.allFinite() || !(node.plane.normal.norm() > 0.5) ||
        !(node.plane.normal.norm() < 2.0) || !std::isfinite(offset))
        throw CompactFormatError("tree section: invalid fold plane");
      node.plane.normal.normalize();
      // Any point of the plane will do: the one nearest the grid's centre.
      const Vec3 centre = coding.origin + Vec3::Constant(0.5 * coding.range);
      node.plane.origin = coding.origin + offset * node.plane.normal;
      node.plane.origin = node.plane.Project(centre);
      node.discardedFaces =
        static_cast<int>(c[FoldCounts].Count(MaximumCount - 1, "discarded faces"));
      node.projectedPoints =
        static_cast<int>(c[FoldCounts].Count(MaximumCount - 1, "projected points"));
    }
    if (node.kind == FoldingNodeKind::Rotation)
    {
      for (int k = 0; k < 3; ++k)
        node.axis.origin[k] = c[RotationAxes].F64();
      for (int k = 0; k < 3; ++k)
        node.axis.direction[k] = c[RotationAxes].F64();
      if (!node.axis.origin.allFinite() || !node.axis.direction.allFinite() ||
        std::abs(node.axis.direction.norm() - 1.0) > 1e-6)
        throw CompactFormatError("tree section: invalid rotation axis");
      const size_t order = c[RotationAxes].Count(MaximumRotationNodeOrder, "rotation order");
      if (order < 2)
        throw CompactFormatError("tree section: rotation order below 2");
      node.rotationOrder = static_cast<int>(order);
      node.discardedFaces =
        static_cast<int>(c[RotationAxes].Count(MaximumCount - 1, "discarded faces"));
    }
    if (node.kind == FoldingNodeKind::Leaf)
    {
      LeafHeader leaf;
      leaf.node = static_cast<int>(i);
      leaf.flags = c[LeafFlagBytes].U8();
      leaf.points = c[LeafPoints].Count(MaximumCount - 1, "leaf points");
      leaf.triangles = c[LeafTriangles].Count(MaximumCount - 1, "leaf triangles");
      if (leaf.flags & LeafHasBudget)
        leaf.budget = c[LeafBudgets].U16() * tree.rootEpsilon / BudgetCodes;
      leaves.push_back(leaf);
    }
  }
  if (!open.empty())
    throw CompactFormatError("tree section: fewer nodes than the children listed");
  c.Finish();
  ReadPalette(r, columns, palette);
}

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
    const bool hasBudget = (leaves[l].flags & LeafHasBudget) != 0;
    if (hasBudget)
      m.errorBudget.assign(np, leaves[l].budget);
    for (size_t v = 0; v < np; ++v)
    {
      if (leaf.symbols[v] >= palette.size())
        throw CompactFormatError("geometry section: a point's palette entry is out of range");
      const PointData& d = palette[leaf.symbols[v]];
      m.tearMask[v] = d.tear;
      m.planeMask[v] = d.plane;
      m.projected[v] = static_cast<char>(d.projected);
      m.inputBoundary[v] = static_cast<char>(d.boundary);
      if (hasBudget)
        m.errorBudget[v] =
          std::max(m.errorBudget[v], d.budgetLevel * tree.rootEpsilon / BudgetLevels);
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
} // namespace compact_detail
} // namespace foldingmeshes
