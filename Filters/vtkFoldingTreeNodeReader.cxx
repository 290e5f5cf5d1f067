// Reading the node blocks of a folding tree (vtkFoldingTreeNodeReader.h).
#include "vtkFoldingTreeNodeReader.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

namespace foldingmeshes
{
namespace tree_io_detail
{
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

bool Reader::Fail(const std::string& where, const std::string& what)
{
  this->Error = where + ": " + what;
  return false;
}

bool Reader::Int(vtkFieldData* fd, const char* name, const std::string& where, long long& v)
{
  if (!fd || !ReadInteger(fd->GetAbstractArray(name), 0, v))
    return this->Fail(where, std::string("missing or invalid field array \"") + name + "\"");
  return true;
}

bool Reader::Double(vtkFieldData* fd, const char* name, const std::string& where, double* v, int n)
{
  vtkDataArray* a = fd ? vtkDataArray::SafeDownCast(fd->GetAbstractArray(name)) : nullptr;
  if (!a || a->GetNumberOfComponents() != n || a->GetNumberOfTuples() < 1)
    return this->Fail(where,
      std::string("missing field array \"") + name + "\" (" + std::to_string(n) + " component(s))");
  for (int k = 0; k < n; ++k)
    v[k] = a->GetComponent(0, k);
  return true;
}

bool Reader::IntList(vtkFieldData* fd,
  const char* name,
  const std::string& where,
  std::vector<int>& v)
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

bool Reader::Metadata(vtkFieldData* fd, const std::string& where, FoldingNodeKind kind, Item& item)
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
  if (fd->GetAbstractArray("DetectionStarts") && this->Int(fd, "DetectionStarts", where, starts))
    node.detectionStarts = static_cast<int>(starts);
  if (fd->GetAbstractArray("DetectionSeconds"))
    this->Double(fd, "DetectionSeconds", where, &node.detectionSeconds);
  return this->IntList(fd, "FoldingRegionOriginalFaces", where, node.originalFaces);
}

bool Reader::Node(vtkDataObject* object, const std::string& where, int parent, int depth)
{
  if (!object)
    return this->Fail(where, "missing block (null)");
  if (vtkPolyData* leaf = vtkPolyData::SafeDownCast(object))
    return this->ReadLeaf(leaf, where, parent, depth);
  vtkMultiBlockDataSet* mb = vtkMultiBlockDataSet::SafeDownCast(object);
  if (!mb)
    return this->Fail(where,
      std::string("a ") + object->GetClassName() +
        " block, expected vtkPolyData (leaf) or vtkMultiBlockDataSet (folding, "
        "segmentation or rotation node)");
  const unsigned int nb = mb->GetNumberOfBlocks();
  vtkPolyData* last = nb > 0 ? vtkPolyData::SafeDownCast(mb->GetBlock(nb - 1)) : nullptr;
  const char* lastName = nb > 0 && mb->HasMetaData(nb - 1)
    ? mb->GetMetaData(nb - 1)->Get(vtkCompositeDataSet::NAME())
    : nullptr;
  if (!last)
    return this->Fail(where,
      "an inner node whose last block is not its metadata polydata (\"Plane\" for a "
      "folding node, \"Node\" for a segmentation node, \"Axis\" for a rotation node)");
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
        "a folding node must have exactly two blocks (child, plane), found " + std::to_string(nb));
    Item item;
    if (!this->ReadFoldingMetadata(fd, where, item) || !this->CheckDepth(item, where, depth))
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
  else if (kind == static_cast<int>(FoldingNodeKind::Rotation))
  {
    if (nb != 2)
      return this->Fail(where,
        "a rotation node must have exactly two blocks (child, axis), found " + std::to_string(nb));
    Item item;
    if (!this->ReadRotationMetadata(fd, where, item) || !this->CheckDepth(item, where, depth))
      return false;
    item.Parent = parent;
    this->Items[self] = std::move(item);
  }
  else
  {
    return this->Fail(where,
      "wrong node kind " + std::to_string(kind) +
        " in the metadata block of a composite node (1 folding, 2 segmentation, 3 rotation "
        "expected)");
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

/// A folding node's metadata: the common one, its plane and what the fold removed.
bool Reader::ReadFoldingMetadata(vtkFieldData* fd, const std::string& where, Item& item)
{
  if (!this->Metadata(fd, where, FoldingNodeKind::Folding, item))
    return false;
  if (!this->Double(fd, "FoldingPlaneOrigin", where, item.Node.plane.origin.data(), 3) ||
    !this->Double(fd, "FoldingPlaneNormal", where, item.Node.plane.normal.data(), 3))
    return this->Fail(
      where, "folding node without its plane metadata: " + this->Error.substr(where.size() + 2));
  long long discarded = 0, projected = 0;
  if (fd->GetAbstractArray("FoldingDiscardedFaces") &&
    this->Int(fd, "FoldingDiscardedFaces", where, discarded))
    item.Node.discardedFaces = static_cast<int>(discarded);
  if (fd->GetAbstractArray("FoldingProjectedPoints") &&
    this->Int(fd, "FoldingProjectedPoints", where, projected))
    item.Node.projectedPoints = static_cast<int>(projected);
  return this->IntList(
    fd, "FoldingDiscardedOriginalFaces", where, item.Node.discardedOriginalFaces);
}

/// A rotation node's metadata: the common one, its axis and order, what the sector left out.
bool Reader::ReadRotationMetadata(vtkFieldData* fd, const std::string& where, Item& item)
{
  if (!this->Metadata(fd, where, FoldingNodeKind::Rotation, item))
    return false;
  long long order = 0;
  if (!this->Double(fd, "FoldingAxisOrigin", where, item.Node.axis.origin.data(), 3) ||
    !this->Double(fd, "FoldingAxisDirection", where, item.Node.axis.direction.data(), 3) ||
    !this->Int(fd, "FoldingRotationOrder", where, order))
    return this->Fail(
      where, "rotation node without its axis metadata: " + this->Error.substr(where.size() + 2));
  if (order < 2 || order > MaximumRotationNodeOrder)
    return this->Fail(where,
      "FoldingRotationOrder " + std::to_string(order) + " is out of range (2 .. " +
        std::to_string(MaximumRotationNodeOrder) + ")");
  item.Node.rotationOrder = static_cast<int>(order);
  long long discarded = 0;
  if (fd->GetAbstractArray("FoldingDiscardedFaces") &&
    this->Int(fd, "FoldingDiscardedFaces", where, discarded))
    item.Node.discardedFaces = static_cast<int>(discarded);
  return this->IntList(
    fd, "FoldingDiscardedOriginalFaces", where, item.Node.discardedOriginalFaces);
}

bool Reader::CheckDepth(const Item& item, const std::string& where, int depth)
{
  if (item.Node.depth != depth)
    return this->Fail(where,
      "FoldingNodeDepth " + std::to_string(item.Node.depth) + " does not match the block's depth " +
        std::to_string(depth));
  return true;
}

bool Reader::ReadLeaf(vtkPolyData* leaf, const std::string& where, int parent, int depth)
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
  if (!this->ReadLeafGeometry(leaf, where, m) || !this->ReadRequiredLeafArrays(leaf, where, m) ||
    !this->ReadOptionalLeafArrays(leaf, where, m) || !this->ReadMirroredFlags(fd, where, m))
    return false;
  this->Items.push_back(std::move(item));
  return true;
}

/// Points and triangles (a leaf holds triangles only).
bool Reader::ReadLeafGeometry(vtkPolyData* leaf, const std::string& where, FoldingLeafMesh& m)
{
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
  return true;
}

/// The per-point input ids, masks and Projected flags, the per-triangle input ids.
bool Reader::ReadRequiredLeafArrays(vtkPolyData* leaf, const std::string& where, FoldingLeafMesh& m)
{
  const vtkIdType np = static_cast<vtkIdType>(m.points.size());
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
  m.originalFaceIds.resize(nt);
  for (vtkIdType f = 0; f < nt; ++f)
  {
    long long id = 0;
    if (!ReadInteger(cellIds, f, id))
      return this->Fail(where, "invalid OriginalCellId value");
    m.originalFaceIds[f] = static_cast<int>(id);
  }
  return true;
}

/// ErrorBudget, InputBoundary and InputBorderNeighbors (older files lack them).
bool Reader::ReadOptionalLeafArrays(vtkPolyData* leaf, const std::string& where, FoldingLeafMesh& m)
{
  const vtkIdType np = static_cast<vtkIdType>(m.points.size());
  vtkPointData* pd = leaf->GetPointData();
  if (vtkDataArray* budget = vtkDataArray::SafeDownCast(pd->GetAbstractArray("ErrorBudget")))
  {
    if (budget->GetNumberOfTuples() != np || budget->GetNumberOfComponents() != 1)
      return this->Fail(where, "ErrorBudget does not have one value per point");
    m.errorBudget.resize(np);
    for (vtkIdType i = 0; i < np; ++i)
      m.errorBudget[i] = budget->GetTuple1(i);
  }
  // Without it the unfolder treats every boundary loop as possibly the input's own border
  // and fills none (UnfoldOptions::closeHoles).
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
  return true;
}

/// The mirrored-flag records: all four MirroredFlag* arrays or none.
bool Reader::ReadMirroredFlags(vtkFieldData* fd, const std::string& where, FoldingLeafMesh& m)
{
  const char* names[4] = {
    "MirroredFlagPoint", "MirroredFlagLevel", "MirroredFlagKind", "MirroredFlagMask"
  };
  vtkAbstractArray* flags[4];
  int present = 0;
  for (int k = 0; k < 4; ++k)
    present += (flags[k] = fd->GetAbstractArray(names[k])) != nullptr;
  if (present != 0 && present != 4)
    return this->Fail(where, "incomplete mirrored-flag records (MirroredFlag* arrays)");
  if (present == 0)
    return true;
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
  return true;
}

} // namespace tree_io_detail
} // namespace foldingmeshes
