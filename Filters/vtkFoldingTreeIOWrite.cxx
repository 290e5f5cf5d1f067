// FoldingTreeToMultiBlock: core FoldingTree -> vtkMultiBlockDataSet (vtkFoldingTreeIO.h).
#include "vtkAxisGlyph.h"
#include "vtkFoldingArrays.h"
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
#include <map>
#include <sstream>

namespace foldingmeshes
{
namespace
{
// ---------------------------------------------------------------- writing helpers
void AddInt(vtkFieldData* fd, const char* name, long long value)
{
  vtkNew<vtkIntArray> a;
  a->SetName(name);
  a->SetNumberOfTuples(1);
  a->SetValue(0, static_cast<int>(value));
  fd->AddArray(a);
}

void AddDouble(vtkFieldData* fd, const char* name, const double* values, int n = 1)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfComponents(n);
  a->SetNumberOfTuples(1);
  for (int k = 0; k < n; ++k)
    a->SetComponent(0, k, values[k]);
  fd->AddArray(a);
}

void AddIntList(vtkFieldData* fd, const char* name, const std::vector<int>& values)
{
  vtkNew<vtkIntArray> a;
  a->SetName(name);
  a->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (size_t k = 0; k < values.size(); ++k)
    a->SetValue(static_cast<vtkIdType>(k), values[k]);
  fd->AddArray(a);
}

void AddString(vtkFieldData* fd, const char* name, const char* value)
{
  vtkNew<vtkStringArray> a;
  a->SetName(name);
  a->InsertNextValue(value);
  fd->AddArray(a);
}

/// Node metadata shared by every kind.
void AddNodeMetadata(vtkFieldData* fd, const FoldingNode& node, int index)
{
  AddInt(fd, "FoldingNodeKind", static_cast<int>(node.kind));
  AddInt(fd, "FoldingNodeIndex", index);
  AddInt(fd, "FoldingNodeDepth", node.depth);
  AddDouble(fd, "FoldingEpsilon", &node.epsilon);
  AddInt(fd, "FoldingFoldsAbove", node.foldsAbove);
  AddInt(fd, "FoldingRegionFaces", node.numberOfFaces);
  AddDouble(fd, "FoldingRegionArea", &node.area);
  AddIntList(fd, "FoldingRegionOriginalFaces", node.originalFaces);
  AddDouble(fd, "SymmetricAreaFraction", &node.symmetricAreaFraction);
  AddInt(fd, "DetectionRun", node.detectionRun ? 1 : 0);
  AddInt(fd, "DetectionStarts", node.detectionStarts);
  AddDouble(fd, "DetectionSeconds", &node.detectionSeconds);
}

/// Copies the arrays of `src` to `dst` (sized n) picking tuple ids[i] for tuple i; active
/// attributes follow.
void CopyArraysById(vtkDataSetAttributes* src,
  vtkDataSetAttributes* dst,
  const std::vector<int>& ids)
{
  const std::vector<vtkIdType> wide(ids.begin(), ids.end());
  CopyTuplesById(src, dst, wide.data(), static_cast<vtkIdType>(wide.size()));
}

/// A list of names joined by ", ".
std::string Join(const std::vector<std::string>& names)
{
  std::string s;
  for (const std::string& n : names)
    s += (s.empty() ? "" : ", ") + n;
  return s;
}

/**
 * The input as the leaves carry it: a shallow copy of `input` whose unnamed point / cell
 * arrays are named, whose arrays VTK's XML files cannot store are left out, and whose arrays
 * named like the tree's or the unfolder's own arrays are renamed (vtkFoldingArrays.h); each
 * change is described in `notes`.
 */
vtkSmartPointer<vtkPolyData> CarriedInput(vtkPolyData* input, std::vector<std::string>& notes)
{
  auto carried = vtkSmartPointer<vtkPolyData>::New();
  carried->ShallowCopy(input);
  vtkNew<vtkFieldData> field;
  field->ShallowCopy(input->GetFieldData());
  carried->SetFieldData(field);
  std::vector<std::string> named, dropped, renamed;
  NameUnnamedArrays(carried->GetPointData(), "UnnamedPointArray", named);
  NameUnnamedArrays(carried->GetCellData(), "UnnamedCellArray", named);
  NameUnnamedArrays(carried->GetFieldData(), "UnnamedFieldArray", named);
  RemoveUnwritableArrays(carried->GetPointData(), dropped);
  RemoveUnwritableArrays(carried->GetCellData(), dropped);
  RemoveUnwritableArrays(carried->GetFieldData(), dropped);
  std::vector<std::string> pointNames = LeafPointArrayNames(), cellNames = LeafCellArrayNames();
  pointNames.insert(
    pointNames.end(), UnfoldedPointArrayNames().begin(), UnfoldedPointArrayNames().end());
  cellNames.insert(
    cellNames.end(), UnfoldedCellArrayNames().begin(), UnfoldedCellArrayNames().end());
  RenameReservedArrays(carried->GetPointData(), pointNames, renamed);
  RenameReservedArrays(carried->GetCellData(), cellNames, renamed);
  if (!named.empty())
    notes.push_back("unnamed input arrays carried as " + Join(named));
  if (!dropped.empty())
    notes.push_back("input arrays VTK's XML files cannot store are not carried: " + Join(dropped));
  if (!renamed.empty())
    notes.push_back("input arrays named like the folding tree's own arrays are carried renamed: " +
      Join(renamed));
  return carried;
}

/// The input's field arrays, active attribute names and point precision on the "Tree" block.
void AddInputRecord(vtkPolyData* carried, vtkFieldData* fd)
{
  vtkFieldData* input = carried->GetFieldData();
  for (int a = 0; input && a < input->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = input->GetAbstractArray(a);
    if (!array)
      continue;
    vtkSmartPointer<vtkAbstractArray> copy = vtk::TakeSmartPointer(array->NewInstance());
    copy->DeepCopy(array);
    copy->SetName(
      (std::string(InputFieldPrefix) + (array->GetName() ? array->GetName() : "")).c_str());
    fd->AddArray(copy);
  }
  fd->AddArray(AttributeRecord(carried->GetPointData(), "InputPointAttributes"));
  fd->AddArray(AttributeRecord(carried->GetCellData(), "InputCellAttributes"));
  if (carried->GetPoints())
    AddInt(fd, "InputPointsDataType", carried->GetPoints()->GetDataType());
}

/// The outline (a closed polyline) of a rectangle on `plane` covering the projection of
/// `points` (10% margin), its one cell labelled FoldingLeafId = `nodeIndex` (the active cell
/// scalars, as on the leaves: ParaView colours a tree by an array only when every block with
/// cells has it). An outline, not a filled quad: planes drawn as surfaces hid the leaves.
void BuildPlaneGlyph(const std::vector<Vec3>& points,
  const Plane& plane,
  double diagonal,
  int nodeIndex,
  vtkPolyData* glyph)
{
  const Vec3 n = plane.normal;
  const Vec3 helper = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 u = n.cross(helper).normalized();
  const Vec3 v = n.cross(u);
  double lo[2] = { 0.0, 0.0 }, hi[2] = { 0.0, 0.0 };
  bool any = false;
  for (const Vec3& p : points)
  {
    const Vec3 q = p - plane.origin;
    const double c[2] = { q.dot(u), q.dot(v) };
    for (int k = 0; k < 2; ++k)
    {
      lo[k] = any ? std::min(lo[k], c[k]) : c[k];
      hi[k] = any ? std::max(hi[k], c[k]) : c[k];
    }
    any = true;
  }
  for (int k = 0; k < 2; ++k)
  {
    const double margin = 0.1 * (hi[k] - lo[k]) + 1e-3 * diagonal;
    lo[k] -= margin;
    hi[k] += margin;
  }
  vtkNew<vtkPoints> corners;
  corners->SetDataTypeToDouble();
  const double uv[4][2] = {
    { lo[0], lo[1] }, { hi[0], lo[1] }, { hi[0], hi[1] }, { lo[0], hi[1] }
  };
  for (const auto& c : uv)
  {
    const Vec3 p = plane.origin + c[0] * u + c[1] * v;
    corners->InsertNextPoint(p.x(), p.y(), p.z());
  }
  vtkNew<vtkCellArray> outline;
  const vtkIdType ids[5] = { 0, 1, 2, 3, 0 };
  outline->InsertNextCell(5, ids);
  glyph->SetPoints(corners);
  glyph->SetLines(outline);
  vtkNew<vtkIntArray> label;
  label->SetName("FoldingLeafId");
  label->InsertNextValue(nodeIndex);
  glyph->GetCellData()->SetScalars(label);
}

/// A rotation node's glyph: a line along its axis over the extent of the subtree's points,
/// labelled like the plane glyphs.
void BuildAxisGlyph(const std::vector<Vec3>& points,
  const RotationAxis& axis,
  double diagonal,
  int nodeIndex,
  vtkPolyData* glyph)
{
  SetAxisLineGlyph(axis, points, diagonal, glyph);
  vtkNew<vtkIntArray> label;
  label->SetName("FoldingLeafId");
  label->InsertNextValue(nodeIndex);
  glyph->GetCellData()->SetScalars(label);
}

/**
 * One point (no cell) at the centroid of `points`: XML multiblock writers skip data sets
 * without points, so the metadata blocks "Node" and "Tree" carry this marker point.
 */
void SetMarkerPoint(const std::vector<Vec3>& points, vtkPolyData* block)
{
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& p : points)
    centroid += p;
  if (!points.empty())
    centroid /= static_cast<double>(points.size());
  vtkNew<vtkPoints> marker;
  marker->SetDataTypeToDouble();
  marker->InsertNextPoint(centroid.data());
  block->SetPoints(marker);
}

void CollectSubtreePoints(const FoldingTree& tree, int index, std::vector<Vec3>& points)
{
  const FoldingNode& node = tree.nodes[index];
  if (node.kind == FoldingNodeKind::Leaf)
    points.insert(points.end(), node.mesh.points.begin(), node.mesh.points.end());
  for (int c : node.children)
    CollectSubtreePoints(tree, c, points);
}

std::string BlockName(const FoldingTree& tree, int index)
{
  const FoldingNode& node = tree.nodes[index];
  std::ostringstream os;
  switch (node.kind)
  {
    case FoldingNodeKind::Leaf:
      os << "Leaf " << index;
      break;
    case FoldingNodeKind::Folding:
      os << "Fold " << index << " (depth " << node.depth << ")";
      break;
    case FoldingNodeKind::Segmentation:
      os << "Segmentation " << index << " (depth " << node.depth << ")";
      break;
    case FoldingNodeKind::Rotation:
      os << "Rotation " << index << " (depth " << node.depth << ", order " << node.rotationOrder
         << ")";
      break;
  }
  return os.str();
}

/// A leaf's points (double precision) and triangles.
vtkSmartPointer<vtkPolyData> LeafGeometry(const FoldingLeafMesh& m)
{
  auto leaf = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(m.NumberOfPoints());
  for (int i = 0; i < m.NumberOfPoints(); ++i)
    points->SetPoint(i, m.points[i].data());
  leaf->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(m.NumberOfFaces(), 3 * m.NumberOfFaces());
  for (const Triangle& t : m.triangles)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    polys->InsertNextCell(3, ids);
  }
  leaf->SetPolys(polys);
  return leaf;
}

/// OriginalPointId, TearMask, PlaneMask, Projected and (when known) ErrorBudget.
void AddTreePointArrays(const FoldingLeafMesh& m, vtkPointData* pd)
{
  vtkNew<vtkIdTypeArray> pointIds;
  pointIds->SetName("OriginalPointId");
  pointIds->SetNumberOfTuples(m.NumberOfPoints());
  vtkNew<vtkTypeUInt64Array> tear, plane;
  tear->SetName("TearMask");
  plane->SetName("PlaneMask");
  tear->SetNumberOfTuples(m.NumberOfPoints());
  plane->SetNumberOfTuples(m.NumberOfPoints());
  vtkNew<vtkUnsignedCharArray> projected;
  projected->SetName("Projected");
  projected->SetNumberOfTuples(m.NumberOfPoints());
  for (int i = 0; i < m.NumberOfPoints(); ++i)
  {
    pointIds->SetValue(i, m.originalPointIds[i]);
    tear->SetValue(i, m.tearMask[i]);
    plane->SetValue(i, m.planeMask[i]);
    projected->SetValue(i, m.projected[i] ? 1 : 0);
  }
  pd->AddArray(pointIds);
  pd->AddArray(tear);
  pd->AddArray(plane);
  pd->AddArray(projected);
  if (!m.errorBudget.empty())
  {
    vtkNew<vtkDoubleArray> budget;
    budget->SetName("ErrorBudget");
    budget->SetNumberOfTuples(m.NumberOfPoints());
    for (int i = 0; i < m.NumberOfPoints(); ++i)
      budget->SetValue(i, m.errorBudget[i]);
    pd->AddArray(budget);
  }
}

/// InputBoundary, and the tree's input border edges (FoldingTree::inputBorderEdges) at their
/// end points: InputBorderNeighbors, the input ids of up to four border neighbours of the
/// point's input point, -1 padded.
void AddInputBorderArrays(const FoldingLeafMesh& m,
  const std::vector<std::pair<int, int>>& borderEdges,
  vtkPointData* pd)
{
  vtkNew<vtkUnsignedCharArray> border;
  border->SetName("InputBoundary");
  border->SetNumberOfTuples(m.NumberOfPoints());
  for (int i = 0; i < m.NumberOfPoints(); ++i)
    border->SetValue(i, m.inputBoundary[i] ? 1 : 0);
  pd->AddArray(border);
  vtkNew<vtkIdTypeArray> neighbours;
  neighbours->SetName("InputBorderNeighbors");
  neighbours->SetNumberOfComponents(4);
  neighbours->SetNumberOfTuples(m.NumberOfPoints());
  std::map<int, std::vector<int>> around;
  for (const auto& e : borderEdges)
  {
    around[e.first].push_back(e.second);
    around[e.second].push_back(e.first);
  }
  for (int i = 0; i < m.NumberOfPoints(); ++i)
  {
    int k = 0;
    auto it = around.find(m.originalPointIds[i]);
    if (m.inputBoundary[i] && it != around.end())
      for (size_t j = 0; j < it->second.size() && k < 4; ++j)
        neighbours->SetTypedComponent(i, k++, it->second[j]);
    for (; k < 4; ++k)
      neighbours->SetTypedComponent(i, k, -1);
  }
  pd->AddArray(neighbours);
}

/// OriginalCellId, and the leaf's node index on every face, active: viewers colour the tree
/// by leaf, with the same numbers as the segmentation view's FoldingLeafId (the unfolder
/// does not carry it).
void AddTreeCellArrays(const FoldingLeafMesh& m, int index, vtkCellData* cd)
{
  vtkNew<vtkIdTypeArray> cellIds;
  cellIds->SetName("OriginalCellId");
  cellIds->SetNumberOfTuples(m.NumberOfFaces());
  for (int f = 0; f < m.NumberOfFaces(); ++f)
    cellIds->SetValue(f, m.originalFaceIds[f]);
  cd->AddArray(cellIds);
  vtkNew<vtkIntArray> leafIds;
  leafIds->SetName("FoldingLeafId");
  leafIds->SetNumberOfTuples(m.NumberOfFaces());
  leafIds->FillValue(index);
  cd->AddArray(leafIds);
  cd->SetActiveScalars("FoldingLeafId");
}

/// The mirrored-flag records as four field arrays (MirroredFlagPoint / Level / Kind / Mask).
void AddMirroredFlags(const FoldingLeafMesh& m, vtkFieldData* fd)
{
  const size_t nf = m.mirroredFlags.size();
  vtkNew<vtkIntArray> flagPoint, flagLevel, flagKind;
  vtkNew<vtkTypeUInt64Array> flagMask;
  flagPoint->SetName("MirroredFlagPoint");
  flagLevel->SetName("MirroredFlagLevel");
  flagKind->SetName("MirroredFlagKind");
  flagMask->SetName("MirroredFlagMask");
  for (auto* a : { static_cast<vtkDataArray*>(flagPoint),
         static_cast<vtkDataArray*>(flagLevel),
         static_cast<vtkDataArray*>(flagKind),
         static_cast<vtkDataArray*>(flagMask) })
  {
    a->SetNumberOfTuples(static_cast<vtkIdType>(nf));
    fd->AddArray(a);
  }
  for (size_t k = 0; k < nf; ++k)
  {
    const MirroredFlag& f = m.mirroredFlags[k];
    flagPoint->SetValue(k, f.point);
    flagLevel->SetValue(k, f.level);
    flagKind->SetValue(k, f.flag == LevelFlag::Tear ? 0 : 1);
    flagMask->SetValue(k, f.mirrorMask);
  }
}

struct Writer
{
  const FoldingTree& Tree;
  vtkPolyData* Input;

  vtkSmartPointer<vtkDataObject> Node(int index)
  {
    const FoldingNode& node = this->Tree.nodes[index];
    if (node.kind == FoldingNodeKind::Leaf)
      return this->Leaf(index);
    auto block = vtkSmartPointer<vtkMultiBlockDataSet>::New();
    unsigned int b = 0;
    for (int c : node.children)
    {
      block->SetBlock(b, this->Node(c));
      block->GetMetaData(b)->Set(vtkCompositeDataSet::NAME(), BlockName(this->Tree, c).c_str());
      ++b;
    }
    vtkNew<vtkPolyData> meta;
    AddNodeMetadata(meta->GetFieldData(), node, index);
    std::vector<Vec3> points;
    CollectSubtreePoints(this->Tree, index, points);
    if (node.kind == FoldingNodeKind::Segmentation)
    {
      SetMarkerPoint(points, meta);
    }
    else if (node.kind == FoldingNodeKind::Rotation)
    {
      BuildAxisGlyph(points, node.axis, this->Tree.diagonal, index, meta);
      vtkFieldData* fd = meta->GetFieldData();
      AddDouble(fd, "FoldingAxisOrigin", node.axis.origin.data(), 3);
      AddDouble(fd, "FoldingAxisDirection", node.axis.direction.data(), 3);
      AddInt(fd, "FoldingRotationOrder", node.rotationOrder);
      AddInt(fd, "FoldingDiscardedFaces", node.discardedFaces);
      AddIntList(fd, "FoldingDiscardedOriginalFaces", node.discardedOriginalFaces);
    }
    else
    {
      BuildPlaneGlyph(points, node.plane, this->Tree.diagonal, index, meta);
      vtkFieldData* fd = meta->GetFieldData();
      AddDouble(fd, "FoldingPlaneOrigin", node.plane.origin.data(), 3);
      AddDouble(fd, "FoldingPlaneNormal", node.plane.normal.data(), 3);
      AddInt(fd, "FoldingDiscardedFaces", node.discardedFaces);
      AddInt(fd, "FoldingProjectedPoints", node.projectedPoints);
      AddIntList(fd, "FoldingDiscardedOriginalFaces", node.discardedOriginalFaces);
    }
    block->SetBlock(b, meta);
    block->GetMetaData(b)->Set(vtkCompositeDataSet::NAME(),
      node.kind == FoldingNodeKind::Folding      ? "Plane"
        : node.kind == FoldingNodeKind::Rotation ? "Axis"
                                                 : "Node");
    return block;
  }

  vtkSmartPointer<vtkDataObject> Leaf(int index)
  {
    const FoldingNode& node = this->Tree.nodes[index];
    const FoldingLeafMesh& m = node.mesh;
    vtkSmartPointer<vtkPolyData> leaf = LeafGeometry(m);
    if (this->Input)
    {
      CopyArraysById(this->Input->GetPointData(), leaf->GetPointData(), m.originalPointIds);
      CopyArraysById(this->Input->GetCellData(), leaf->GetCellData(), m.originalFaceIds);
    }
    AddTreePointArrays(m, leaf->GetPointData());
    if (!m.inputBoundary.empty())
      AddInputBorderArrays(m, this->Tree.inputBorderEdges, leaf->GetPointData());
    AddTreeCellArrays(m, index, leaf->GetCellData());
    vtkFieldData* fd = leaf->GetFieldData();
    AddNodeMetadata(fd, node, index);
    AddInt(fd, "LeafReason", static_cast<int>(node.leafReason));
    AddString(fd, "LeafReasonName", ToString(node.leafReason));
    AddMirroredFlags(m, fd);
    return leaf;
  }
};
}

//------------------------------------------------------------------------------
bool FoldingTreeToMultiBlock(const FoldingTree& tree,
  vtkPolyData* triangulatedInput,
  vtkMultiBlockDataSet* out,
  std::string& error,
  std::vector<std::string>* notes)
{
  if (!out)
  {
    error = "no output multiblock";
    return false;
  }
  out->Initialize();
  error = tree.Validate();
  if (!error.empty())
    return false;
  if (triangulatedInput)
  {
    const vtkIdType np = triangulatedInput->GetNumberOfPoints();
    const vtkIdType nc = triangulatedInput->GetNumberOfCells();
    for (const FoldingNode& node : tree.nodes)
    {
      for (int id : node.mesh.originalPointIds)
        if (id < 0 || id >= np)
        {
          error = "a leaf point's original id is out of the input's point range";
          return false;
        }
      for (int id : node.mesh.originalFaceIds)
        if (id < 0 || id >= nc)
        {
          error = "a leaf face's original id is out of the input's cell range";
          return false;
        }
    }
  }
  vtkSmartPointer<vtkPolyData> carried;
  if (triangulatedInput)
  {
    std::vector<std::string> ignored;
    carried = CarriedInput(triangulatedInput, notes ? *notes : ignored);
  }
  Writer writer{ tree, carried };
  out->SetNumberOfBlocks(2);
  out->SetBlock(0, writer.Node(0));
  out->GetMetaData(0u)->Set(vtkCompositeDataSet::NAME(), BlockName(tree, 0).c_str());

  vtkNew<vtkPolyData> info;
  {
    std::vector<Vec3> points;
    CollectSubtreePoints(tree, 0, points);
    SetMarkerPoint(points, info);
  }
  vtkFieldData* fd = info->GetFieldData();
  AddInt(fd, "OriginalFaces", tree.numberOfOriginalFaces);
  AddInt(fd, "OriginalPoints", tree.numberOfOriginalPoints);
  AddInt(fd, "DroppedFaces", tree.numberOfDroppedFaces);
  AddInt(fd, "StoredFaces", tree.StoredFaces());
  AddInt(fd, "StoredPoints", tree.StoredPoints());
  const double compression = tree.Compression();
  AddDouble(fd, "Compression", &compression);
  AddInt(fd, "TreeHeight", tree.Height());
  AddInt(fd, "NumberOfNodes", tree.NumberOfNodes());
  AddInt(fd, "NumberOfLeaves", tree.NumberOfLeaves());
  AddInt(fd, "NumberOfFolds", tree.NumberOfFolds());
  AddInt(fd, "NumberOfRotations", tree.NumberOfRotations());
  AddInt(fd, "RotationNodesTried", tree.rotationNodesTried ? 1 : 0);
  AddInt(fd, "MaximumFoldsOnPath", tree.MaximumFoldsOnPath());
  AddDouble(fd, "OriginalArea", &tree.originalArea);
  AddDouble(fd, "BuildSeconds", &tree.buildSeconds);
  AddDouble(fd, "RootEpsilon", &tree.rootEpsilon);
  AddDouble(fd, "Diagonal", &tree.diagonal);
  AddInt(fd, "Aborted", tree.aborted ? 1 : 0);
  AddDouble(fd, "VerifiedBound", &tree.verifiedBound);
  AddInt(fd, "PinnedFaces", tree.pinnedFaces);
  AddInt(fd, "VerificationRounds", tree.verificationRounds);
  if (!tree.inputNonManifoldEdges.empty())
  {
    // FoldingTree::inputNonManifoldEdges: (input point id a, b, faces) per edge.
    vtkNew<vtkIdTypeArray> edges;
    edges->SetName("InputNonManifoldEdges");
    edges->SetNumberOfComponents(3);
    edges->SetNumberOfTuples(static_cast<vtkIdType>(tree.inputNonManifoldEdges.size()));
    for (size_t k = 0; k < tree.inputNonManifoldEdges.size(); ++k)
    {
      const InputNonManifoldEdge& e = tree.inputNonManifoldEdges[k];
      edges->SetTypedComponent(static_cast<vtkIdType>(k), 0, e.a);
      edges->SetTypedComponent(static_cast<vtkIdType>(k), 1, e.b);
      edges->SetTypedComponent(static_cast<vtkIdType>(k), 2, e.faces);
    }
    fd->AddArray(edges);
  }
  if (carried)
    AddInputRecord(carried, fd);
  out->SetBlock(1, info);
  out->GetMetaData(1u)->Set(vtkCompositeDataSet::NAME(), "Tree");
  return true;
}

bool FoldingTreeToMultiBlock(const FoldingTree& tree,
  vtkPolyData* triangulatedInput,
  vtkMultiBlockDataSet* out)
{
  std::string error;
  return FoldingTreeToMultiBlock(tree, triangulatedInput, out, error);
}
}
