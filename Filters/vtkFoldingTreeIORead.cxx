// MultiBlockToFoldingTree: vtkMultiBlockDataSet -> core FoldingTree, with validation.
#include "vtkFoldingTreeIO.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTypeUInt64Array.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

namespace foldingmeshes
{
namespace
{
// ---------------------------------------------------------------- reading helpers
bool ReadInteger(vtkAbstractArray* a, vtkIdType i, long long& value)
{
  vtkDataArray* d = vtkDataArray::SafeDownCast(a);
  if (!d || i < 0 || i >= d->GetNumberOfTuples() || d->GetNumberOfComponents() != 1)
    return false;
  const double v = d->GetTuple1(i);
  // Outside +-2^62 the cast would be undefined; no count or index of a tree is that large.
  if (!std::isfinite(v) || v != std::floor(v) || std::abs(v) > 4.6e18)
    return false;
  value = static_cast<long long>(v);
  return true;
}

/// Unsigned 64-bit values read exactly (the masks do not fit a double).
bool ReadUInt64(vtkAbstractArray* a, vtkIdType i, uint64_t& value)
{
  vtkDataArray* d = vtkDataArray::SafeDownCast(a);
  if (!d || i < 0 || i >= d->GetNumberOfTuples() || d->GetNumberOfComponents() != 1)
    return false;
  const int type = d->GetDataType();
  if ((type == VTK_UNSIGNED_LONG || type == VTK_UNSIGNED_LONG_LONG) && d->GetDataTypeSize() == 8)
  {
    value = static_cast<const uint64_t*>(d->GetVoidPointer(0))[i];
    return true;
  }
  if ((type == VTK_LONG || type == VTK_LONG_LONG || type == VTK_ID_TYPE) &&
    d->GetDataTypeSize() == 8)
  {
    value = static_cast<uint64_t>(static_cast<const int64_t*>(d->GetVoidPointer(0))[i]);
    return true;
  }
  long long v = 0;
  if (!ReadInteger(a, i, v) || v < 0)
    return false;
  value = static_cast<uint64_t>(v);
  return true;
}

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

  bool Fail(const std::string& where, const std::string& what)
  {
    this->Error = where + ": " + what;
    return false;
  }

  bool Int(vtkFieldData* fd, const char* name, const std::string& where, long long& v)
  {
    if (!fd || !ReadInteger(fd->GetAbstractArray(name), 0, v))
      return this->Fail(where, std::string("missing or invalid field array \"") + name + "\"");
    return true;
  }
  bool Double(vtkFieldData* fd, const char* name, const std::string& where, double* v, int n = 1)
  {
    vtkDataArray* a = fd ? vtkDataArray::SafeDownCast(fd->GetAbstractArray(name)) : nullptr;
    if (!a || a->GetNumberOfComponents() != n || a->GetNumberOfTuples() < 1)
      return this->Fail(where,
        std::string("missing field array \"") + name + "\" (" + std::to_string(n) +
          " component(s))");
    for (int k = 0; k < n; ++k)
      v[k] = a->GetComponent(0, k);
    return true;
  }
  bool IntList(vtkFieldData* fd, const char* name, const std::string& where, std::vector<int>& v)
  {
    v.clear();
    vtkAbstractArray* a = fd ? fd->GetAbstractArray(name) : nullptr;
    if (!a)
      return true; // optional (empty lists may not survive every writer)
    v.resize(a->GetNumberOfTuples());
    for (vtkIdType k = 0; k < a->GetNumberOfTuples(); ++k)
    {
      long long x = 0;
      if (!ReadInteger(a, k, x))
        return this->Fail(where, std::string("invalid values in \"") + name + "\"");
      v[k] = static_cast<int>(x);
    }
    return true;
  }

  /// Common metadata; `kind` is the kind implied by the block structure.
  bool Metadata(vtkFieldData* fd, const std::string& where, FoldingNodeKind kind, Item& item)
  {
    long long k = -1, depth = 0, index = -1, faces = 0, run = 0;
    if (!this->Int(fd, "FoldingNodeKind", where, k))
      return false;
    if (k != static_cast<int>(kind))
    {
      std::ostringstream os;
      os << "FoldingNodeKind is " << k << " but the block is laid out as a " << ToString(kind)
         << " node (" << static_cast<int>(kind) << ")";
      return this->Fail(where, os.str());
    }
    FoldingNode& node = item.Node;
    node.kind = kind;
    if (!this->Int(fd, "FoldingNodeDepth", where, depth) ||
      !this->Double(fd, "FoldingEpsilon", where, &node.epsilon))
      return false;
    node.depth = static_cast<int>(depth);
    if (fd->GetAbstractArray("FoldingNodeIndex") && this->Int(fd, "FoldingNodeIndex", where, index))
      item.StoredIndex = static_cast<int>(index);
    if (fd->GetAbstractArray("FoldingRegionFaces") &&
      this->Int(fd, "FoldingRegionFaces", where, faces))
      node.numberOfFaces = static_cast<int>(faces);
    if (fd->GetAbstractArray("FoldingRegionArea"))
      this->Double(fd, "FoldingRegionArea", where, &node.area);
    if (fd->GetAbstractArray("SymmetricAreaFraction"))
      this->Double(fd, "SymmetricAreaFraction", where, &node.symmetricAreaFraction);
    if (fd->GetAbstractArray("DetectionRun") && this->Int(fd, "DetectionRun", where, run))
      node.detectionRun = run != 0;
    long long starts = 0;
    if (fd->GetAbstractArray("DetectionStarts") &&
      this->Int(fd, "DetectionStarts", where, starts))
      node.detectionStarts = static_cast<int>(starts);
    if (fd->GetAbstractArray("DetectionSeconds"))
      this->Double(fd, "DetectionSeconds", where, &node.detectionSeconds);
    return this->IntList(fd, "FoldingRegionOriginalFaces", where, node.originalFaces);
  }

  bool Node(vtkDataObject* object, const std::string& where, int parent, int depth)
  {
    if (!object)
      return this->Fail(where, "missing block (null)");
    if (vtkPolyData* leaf = vtkPolyData::SafeDownCast(object))
      return this->ReadLeaf(leaf, where, parent, depth);
    vtkMultiBlockDataSet* mb = vtkMultiBlockDataSet::SafeDownCast(object);
    if (!mb)
      return this->Fail(where,
        std::string("a ") + object->GetClassName() +
          " block, expected vtkPolyData (leaf) or vtkMultiBlockDataSet (folding or "
          "segmentation node)");
    const unsigned int nb = mb->GetNumberOfBlocks();
    vtkPolyData* last = nb > 0 ? vtkPolyData::SafeDownCast(mb->GetBlock(nb - 1)) : nullptr;
    const char* lastName = nb > 0 && mb->HasMetaData(nb - 1)
      ? mb->GetMetaData(nb - 1)->Get(vtkCompositeDataSet::NAME())
      : nullptr;
    if (!last)
      return this->Fail(where,
        "an inner node whose last block is not its metadata polydata (\"Plane\" for a "
        "folding node, \"Node\" for a segmentation node)");
    long long kind = -1;
    vtkFieldData* fd = last->GetFieldData();
    if (!fd || !fd->GetAbstractArray("FoldingNodeKind") ||
      !ReadInteger(fd->GetAbstractArray("FoldingNodeKind"), 0, kind))
    {
      const bool looksLikeFold = lastName && std::strcmp(lastName, "Plane") == 0;
      return this->Fail(where,
        looksLikeFold ? "folding node without its plane metadata (the \"Plane\" block has no "
                        "FoldingNodeKind / FoldingPlaneOrigin / FoldingPlaneNormal field data)"
                      : "inner node without metadata (its last block has no FoldingNodeKind "
                        "field data)");
    }
    const int self = static_cast<int>(this->Items.size());
    this->Items.emplace_back();
    this->Items[self].Parent = parent;
    if (kind == static_cast<int>(FoldingNodeKind::Folding))
    {
      if (nb != 2)
        return this->Fail(where,
          "a folding node must have exactly two blocks (child, plane), found " +
            std::to_string(nb));
      Item item;
      if (!this->Metadata(fd, where, FoldingNodeKind::Folding, item))
        return false;
      if (!this->Double(fd, "FoldingPlaneOrigin", where, item.Node.plane.origin.data(), 3) ||
        !this->Double(fd, "FoldingPlaneNormal", where, item.Node.plane.normal.data(), 3))
        return this->Fail(where,
          "folding node without its plane metadata: " + this->Error.substr(where.size() + 2));
      long long discarded = 0, projected = 0;
      if (fd->GetAbstractArray("FoldingDiscardedFaces") &&
        this->Int(fd, "FoldingDiscardedFaces", where, discarded))
        item.Node.discardedFaces = static_cast<int>(discarded);
      if (fd->GetAbstractArray("FoldingProjectedPoints") &&
        this->Int(fd, "FoldingProjectedPoints", where, projected))
        item.Node.projectedPoints = static_cast<int>(projected);
      if (!this->IntList(
            fd, "FoldingDiscardedOriginalFaces", where, item.Node.discardedOriginalFaces))
        return false;
      if (!this->CheckDepth(item, where, depth))
        return false;
      item.Parent = parent;
      this->Items[self] = std::move(item);
    }
    else if (kind == static_cast<int>(FoldingNodeKind::Segmentation))
    {
      if (nb < 3)
        return this->Fail(where,
          "a segmentation node needs at least two children and its \"Node\" block, found " +
            std::to_string(nb) + " blocks");
      Item item;
      if (!this->Metadata(fd, where, FoldingNodeKind::Segmentation, item) ||
        !this->CheckDepth(item, where, depth))
        return false;
      item.Parent = parent;
      this->Items[self] = std::move(item);
    }
    else
    {
      return this->Fail(where,
        "wrong node kind " + std::to_string(kind) +
          " in the metadata block of a composite node (1 folding, 2 segmentation expected)");
    }
    for (unsigned int b = 0; b + 1 < nb; ++b)
    {
      const char* name =
        mb->HasMetaData(b) ? mb->GetMetaData(b)->Get(vtkCompositeDataSet::NAME()) : nullptr;
      const std::string child = where + " / " + (name ? name : "block " + std::to_string(b));
      if (!this->Node(mb->GetBlock(b), child, self, depth + 1))
        return false;
    }
    return true;
  }

  bool CheckDepth(const Item& item, const std::string& where, int depth)
  {
    if (item.Node.depth != depth)
      return this->Fail(where,
        "FoldingNodeDepth " + std::to_string(item.Node.depth) +
          " does not match the block's depth " + std::to_string(depth));
    return true;
  }

  bool ReadLeaf(vtkPolyData* leaf, const std::string& where, int parent, int depth)
  {
    Item item;
    item.Parent = parent;
    item.Leaf = leaf;
    vtkFieldData* fd = leaf->GetFieldData();
    if (!fd || !fd->GetAbstractArray("FoldingNodeKind"))
      return this->Fail(where, "a vtkPolyData block without leaf metadata (FoldingNodeKind)");
    if (!this->Metadata(fd, where, FoldingNodeKind::Leaf, item) ||
      !this->CheckDepth(item, where, depth))
      return false;
    long long reason = 0;
    if (fd->GetAbstractArray("LeafReason") && this->Int(fd, "LeafReason", where, reason))
    {
      if (reason < 0 || reason > static_cast<int>(LeafReason::Aborted))
        return this->Fail(where, "LeafReason out of range");
      item.Node.leafReason = static_cast<LeafReason>(reason);
    }
    FoldingLeafMesh& m = item.Node.mesh;
    const vtkIdType np = leaf->GetNumberOfPoints();
    m.points.resize(np);
    for (vtkIdType i = 0; i < np; ++i)
    {
      double p[3];
      leaf->GetPoint(i, p);
      m.points[i] = Vec3(p[0], p[1], p[2]);
    }
    if (leaf->GetNumberOfVerts() + leaf->GetNumberOfLines() + leaf->GetNumberOfStrips() > 0)
      return this->Fail(where, "a leaf must hold triangles only (found verts, lines or strips)");
    m.triangles.clear();
    m.triangles.reserve(leaf->GetNumberOfPolys());
    if (leaf->GetPolys())
    {
      auto it = vtk::TakeSmartPointer(leaf->GetPolys()->NewIterator());
      for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
      {
        vtkIdType n;
        const vtkIdType* ids;
        it->GetCurrentCell(n, ids);
        if (n != 3)
          return this->Fail(where, "a leaf cell is not a triangle");
        m.triangles.push_back(
          { static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]) });
      }
    }
    const vtkIdType nt = static_cast<vtkIdType>(m.triangles.size());
    vtkPointData* pd = leaf->GetPointData();
    vtkCellData* cd = leaf->GetCellData();
    auto sized = [&](vtkAbstractArray* a, vtkIdType n, const char* name, bool& ok)
    {
      ok = a && a->GetNumberOfComponents() == 1 && a->GetNumberOfTuples() == n;
      if (!ok)
      {
        std::ostringstream os;
        os << (a ? "bad size of" : "missing") << " array \"" << name << "\" (expected " << n
           << " single-component values";
        if (a)
          os << ", found " << a->GetNumberOfTuples() << " x " << a->GetNumberOfComponents();
        os << ")";
        this->Fail(where, os.str());
      }
      return a;
    };
    bool ok = true;
    vtkAbstractArray* pointIds =
      sized(pd->GetAbstractArray("OriginalPointId"), np, "OriginalPointId", ok);
    if (!ok)
      return false;
    vtkAbstractArray* tear = sized(pd->GetAbstractArray("TearMask"), np, "TearMask", ok);
    if (!ok)
      return false;
    vtkAbstractArray* plane = sized(pd->GetAbstractArray("PlaneMask"), np, "PlaneMask", ok);
    if (!ok)
      return false;
    vtkAbstractArray* projected = sized(pd->GetAbstractArray("Projected"), np, "Projected", ok);
    if (!ok)
      return false;
    vtkAbstractArray* cellIds =
      sized(cd->GetAbstractArray("OriginalCellId"), nt, "OriginalCellId", ok);
    if (!ok)
      return false;
    m.originalPointIds.resize(np);
    m.tearMask.resize(np);
    m.planeMask.resize(np);
    m.projected.resize(np);
    for (vtkIdType i = 0; i < np; ++i)
    {
      long long id = 0, pr = 0;
      if (!ReadInteger(pointIds, i, id) || !ReadUInt64(tear, i, m.tearMask[i]) ||
        !ReadUInt64(plane, i, m.planeMask[i]) || !ReadInteger(projected, i, pr))
        return this->Fail(where, "invalid per-point tree values (ids, masks or Projected)");
      m.originalPointIds[i] = static_cast<int>(id);
      m.projected[i] = pr ? 1 : 0;
    }
    // Optional (older files have none).
    if (vtkDataArray* budget = vtkDataArray::SafeDownCast(pd->GetAbstractArray("ErrorBudget")))
    {
      if (budget->GetNumberOfTuples() != np || budget->GetNumberOfComponents() != 1)
        return this->Fail(where, "ErrorBudget does not have one value per point");
      m.errorBudget.resize(np);
      for (vtkIdType i = 0; i < np; ++i)
        m.errorBudget[i] = budget->GetTuple1(i);
    }
    // Optional too: without it the unfolder treats every boundary loop as possibly the
    // input's own border and fills none (UnfoldOptions::closeHoles).
    if (vtkDataArray* border = vtkDataArray::SafeDownCast(pd->GetAbstractArray("InputBoundary")))
    {
      if (border->GetNumberOfTuples() != np || border->GetNumberOfComponents() != 1)
        return this->Fail(where, "InputBoundary does not have one value per point");
      m.inputBoundary.resize(np);
      for (vtkIdType i = 0; i < np; ++i)
        m.inputBoundary[i] = border->GetTuple1(i) != 0.0 ? 1 : 0;
    }
    if (vtkDataArray* nb = vtkDataArray::SafeDownCast(pd->GetAbstractArray("InputBorderNeighbors")))
    {
      if (nb->GetNumberOfTuples() != np || nb->GetNumberOfComponents() != 4)
        return this->Fail(where, "InputBorderNeighbors does not have four values per point");
      for (vtkIdType i = 0; i < np; ++i)
        for (int k = 0; k < 4; ++k)
        {
          const int o = m.originalPointIds[i], x = static_cast<int>(nb->GetComponent(i, k));
          if (x >= 0)
            this->BorderEdges.push_back({ std::min(o, x), std::max(o, x) });
        }
    }
    m.originalFaceIds.resize(nt);
    for (vtkIdType f = 0; f < nt; ++f)
    {
      long long id = 0;
      if (!ReadInteger(cellIds, f, id))
        return this->Fail(where, "invalid OriginalCellId value");
      m.originalFaceIds[f] = static_cast<int>(id);
    }
    // Mirrored flags: all four arrays or none.
    const char* names[4] = {
      "MirroredFlagPoint", "MirroredFlagLevel", "MirroredFlagKind", "MirroredFlagMask"
    };
    vtkAbstractArray* flags[4];
    int present = 0;
    for (int k = 0; k < 4; ++k)
      present += (flags[k] = fd->GetAbstractArray(names[k])) != nullptr;
    if (present != 0 && present != 4)
      return this->Fail(where, "incomplete mirrored-flag records (MirroredFlag* arrays)");
    if (present == 4)
    {
      const vtkIdType nf = flags[0]->GetNumberOfTuples();
      for (int k = 1; k < 4; ++k)
        if (flags[k]->GetNumberOfTuples() != nf)
          return this->Fail(where, "MirroredFlag* arrays of different sizes");
      m.mirroredFlags.resize(nf);
      for (vtkIdType k = 0; k < nf; ++k)
      {
        long long point = 0, level = 0, kind = 0;
        MirroredFlag& f = m.mirroredFlags[k];
        if (!ReadInteger(flags[0], k, point) || !ReadInteger(flags[1], k, level) ||
          !ReadInteger(flags[2], k, kind) || !ReadUInt64(flags[3], k, f.mirrorMask) ||
          (kind != 0 && kind != 1))
          return this->Fail(where, "invalid mirrored-flag record");
        f.point = static_cast<int>(point);
        f.level = static_cast<int>(level);
        f.flag = kind == 0 ? LevelFlag::Tear : LevelFlag::Plane;
      }
    }
    this->Items.push_back(std::move(item));
    return true;
  }
};
}

//------------------------------------------------------------------------------
namespace
{
/// The input's non-manifold edges listed in the "Tree" block (optional: older files have
/// none, and then the repair keeps no non-manifold edge).
bool ReadInputNonManifoldEdges(vtkFieldData* fd, FoldingTree& tree, std::string& error)
{
  vtkAbstractArray* a = fd->GetAbstractArray("InputNonManifoldEdges");
  if (!a)
    return true;
  const long long most = std::numeric_limits<int>::max();
  vtkDataArray* nm = vtkDataArray::SafeDownCast(a);
  if (!nm || nm->GetNumberOfComponents() != 3)
  {
    error = "\"Tree\": InputNonManifoldEdges does not have three values per edge";
    return false;
  }
  for (vtkIdType k = 0; k < nm->GetNumberOfTuples(); ++k)
  {
    double v[3] = { 0.0, 0.0, 0.0 };
    for (int c = 0; c < 3; ++c)
    {
      v[c] = nm->GetComponent(k, c);
      if (!std::isfinite(v[c]) || v[c] != std::floor(v[c]) || v[c] < 0.0 ||
        v[c] > static_cast<double>(most))
      {
        error = "\"Tree\": invalid values in InputNonManifoldEdges";
        return false;
      }
    }
    tree.inputNonManifoldEdges.push_back(
      { static_cast<int>(v[0]), static_cast<int>(v[1]), static_cast<int>(v[2]) });
  }
  std::sort(tree.inputNonManifoldEdges.begin(), tree.inputNonManifoldEdges.end());
  return true;
}

/// The tree-wide values of the "Tree" block's field data.
bool ReadTreeInfo(vtkPolyData* info, Reader& reader, FoldingTree& tree, std::string& error)
{
  vtkFieldData* fd = info->GetFieldData();
  long long faces = 0, points = 0, dropped = 0, aborted = 0;
  if (!reader.Int(fd, "OriginalFaces", "Tree", faces) ||
    !reader.Double(fd, "RootEpsilon", "Tree", &tree.rootEpsilon) ||
    !reader.Double(fd, "Diagonal", "Tree", &tree.diagonal))
  {
    error = reader.Error;
    return false;
  }
  if ((fd->GetAbstractArray("OriginalPoints") &&
        !reader.Int(fd, "OriginalPoints", "Tree", points)) ||
    (fd->GetAbstractArray("DroppedFaces") && !reader.Int(fd, "DroppedFaces", "Tree", dropped)))
  {
    error = reader.Error;
    return false;
  }
  const long long most = std::numeric_limits<int>::max();
  if (faces < 0 || faces > most || points < 0 || points > most || dropped < 0 || dropped > most)
  {
    error = "\"Tree\": OriginalFaces, OriginalPoints or DroppedFaces is negative or too large";
    return false;
  }
  tree.numberOfOriginalFaces = static_cast<int>(faces);
  tree.numberOfOriginalPoints = static_cast<int>(points);
  tree.numberOfDroppedFaces = static_cast<int>(dropped);
  if (fd->GetAbstractArray("OriginalArea"))
    reader.Double(fd, "OriginalArea", "Tree", &tree.originalArea);
  if (fd->GetAbstractArray("BuildSeconds"))
    reader.Double(fd, "BuildSeconds", "Tree", &tree.buildSeconds);
  if (fd->GetAbstractArray("Aborted") && reader.Int(fd, "Aborted", "Tree", aborted))
    tree.aborted = aborted != 0;
  // Optional (files written before the builder verified its bound): not verified.
  if (fd->GetAbstractArray("VerifiedBound"))
    reader.Double(fd, "VerifiedBound", "Tree", &tree.verifiedBound);
  long long pinned = 0, rounds = 0;
  if (fd->GetAbstractArray("PinnedFaces") && reader.Int(fd, "PinnedFaces", "Tree", pinned) &&
    pinned >= 0 && pinned <= faces)
    tree.pinnedFaces = static_cast<int>(pinned);
  if (fd->GetAbstractArray("VerificationRounds") &&
    reader.Int(fd, "VerificationRounds", "Tree", rounds) && rounds >= 0 && rounds <= most)
    tree.verificationRounds = static_cast<int>(rounds);
  return ReadInputNonManifoldEdges(fd, tree, error);
}

/// The nodes the reader collected, in the tree: indexed by their stored indices if those
/// are a permutation (else the block preorder), children in block order, foldsAbove from
/// the structure.
void AssembleNodes(Reader& reader, FoldingTree& tree, std::vector<vtkPolyData*>* leafBlocks)
{
  const int n = static_cast<int>(reader.Items.size());
  std::vector<int> index(n);
  std::vector<char> seen(n, 0);
  bool stored = true;
  for (int i = 0; i < n && stored; ++i)
  {
    const int s = reader.Items[i].StoredIndex;
    stored = s >= 0 && s < n && !seen[s];
    if (stored)
      seen[s] = 1;
  }
  for (int i = 0; i < n; ++i)
    index[i] = stored ? reader.Items[i].StoredIndex : i;
  tree.nodes.resize(n);
  if (leafBlocks)
    leafBlocks->assign(n, nullptr);
  for (int i = 0; i < n; ++i)
  {
    Reader::Item& item = reader.Items[i];
    FoldingNode& node = tree.nodes[index[i]];
    node = std::move(item.Node);
    node.children.clear();
    node.parent = item.Parent < 0 ? -1 : index[item.Parent];
    if (leafBlocks)
      (*leafBlocks)[index[i]] = item.Leaf;
  }
  tree.inputBorderEdges = std::move(reader.BorderEdges);
  std::sort(tree.inputBorderEdges.begin(), tree.inputBorderEdges.end());
  tree.inputBorderEdges.erase(
    std::unique(tree.inputBorderEdges.begin(), tree.inputBorderEdges.end()),
    tree.inputBorderEdges.end());
  for (int i = 0; i < n; ++i) // children in block order
    if (reader.Items[i].Parent >= 0)
      tree.nodes[index[reader.Items[i].Parent]].children.push_back(index[i]);
  // foldsAbove from the structure (preorder: parents come first once Validate has passed the
  // parent check; compute in block order, which is a preorder too).
  for (int i = 0; i < n; ++i)
  {
    FoldingNode& node = tree.nodes[index[i]];
    node.foldsAbove = 0;
    if (node.parent >= 0)
    {
      const FoldingNode& parent = tree.nodes[node.parent];
      node.foldsAbove = parent.foldsAbove + (parent.kind == FoldingNodeKind::Folding ? 1 : 0);
    }
  }
}
}

bool MultiBlockToFoldingTree(vtkMultiBlockDataSet* in,
  FoldingTree& tree,
  std::vector<vtkPolyData*>* leafBlocks,
  std::string& error)
{
  tree = FoldingTree();
  if (leafBlocks)
    leafBlocks->clear();
  if (!in)
  {
    error = "no input multiblock";
    return false;
  }
  if (in->GetNumberOfBlocks() != 2)
  {
    error = "a folding tree has two top-level blocks (the root node and \"Tree\"), found " +
      std::to_string(in->GetNumberOfBlocks());
    return false;
  }
  vtkPolyData* info = vtkPolyData::SafeDownCast(in->GetBlock(1));
  Reader reader;
  if (!info)
  {
    error = "top-level block 1 (\"Tree\") is missing or not a vtkPolyData";
    return false;
  }
  if (!ReadTreeInfo(info, reader, tree, error))
    return false;
  const char* rootName =
    in->HasMetaData(0u) ? in->GetMetaData(0u)->Get(vtkCompositeDataSet::NAME()) : nullptr;
  if (!reader.Node(in->GetBlock(0), rootName ? rootName : "root", -1, 0))
  {
    error = reader.Error;
    return false;
  }
  AssembleNodes(reader, tree, leafBlocks);
  error = tree.Validate();
  if (!error.empty())
  {
    error = "invalid folding tree: " + error;
    tree = FoldingTree();
    if (leafBlocks)
      leafBlocks->clear();
    return false;
  }
  return true;
}
}
