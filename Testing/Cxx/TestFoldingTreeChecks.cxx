// Helpers of TestFoldingTreeFilters: tree walking, leaf-array checks, mesh and tree comparison.
#include "TestFoldingTreeChecks.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStaticCellLocator.h>
#include <vtkTypeUInt64Array.h>

#include <cmath>
#include <map>

namespace foldingtreetest
{
int failures = 0;

int UpdateCapturing(vtkAlgorithm* alg, EventLog& log)
{
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(EventLog::Callback);
  callback->SetClientData(&log);
  const unsigned long a = alg->AddObserver(vtkCommand::ErrorEvent, callback);
  const unsigned long b = alg->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, callback);
  const int status = alg->GetExecutive()->Update();
  alg->RemoveObserver(a);
  alg->GetExecutive()->RemoveObserver(b);
  return status;
}

double FieldValue(vtkFieldData* fd, const char* name, int component)
{
  vtkDataArray* a = fd ? vtkDataArray::SafeDownCast(fd->GetAbstractArray(name)) : nullptr;
  if (!a || a->GetNumberOfTuples() < 1 || component >= a->GetNumberOfComponents())
    return std::nan("");
  return a->GetComponent(0, component);
}

const char* BlockName(vtkMultiBlockDataSet* mb, unsigned int b)
{
  return mb->HasMetaData(b) ? mb->GetMetaData(b)->Get(vtkCompositeDataSet::NAME()) : nullptr;
}

Vec3 FaceNormal(vtkPolyData* pd, vtkIdType c)
{
  vtkNew<vtkIdList> ids;
  pd->GetCellPoints(c, ids);
  if (ids->GetNumberOfIds() != 3)
    return Vec3::Zero();
  const Vec3 a(pd->GetPoint(ids->GetId(0)));
  const Vec3 b(pd->GetPoint(ids->GetId(1)));
  const Vec3 d(pd->GetPoint(ids->GetId(2)));
  const Vec3 n = (b - a).cross(d - a);
  return n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::Zero();
}

vtkSmartPointer<vtkPolyData> WithArrays(vtkPolyData* mesh)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->DeepCopy(mesh);
  const vtkIdType np = pd->GetNumberOfPoints(), nc = pd->GetNumberOfCells();
  vtkNew<vtkDoubleArray> temperature, position;
  temperature->SetName("Temperature");
  temperature->SetNumberOfTuples(np);
  position->SetName("Position");
  position->SetNumberOfComponents(3);
  position->SetNumberOfTuples(np);
  for (vtkIdType i = 0; i < np; ++i)
  {
    double p[3];
    pd->GetPoint(i, p);
    temperature->SetValue(i, 1000.0 + i + 0.25 * p[0]);
    position->SetTuple(i, p);
  }
  vtkNew<vtkIntArray> label;
  label->SetName("Label");
  label->SetNumberOfTuples(nc);
  vtkNew<vtkDoubleArray> normal, tripleId;
  normal->SetName("FaceNormal");
  normal->SetNumberOfComponents(3);
  normal->SetNumberOfTuples(nc);
  tripleId->SetName("TripleId"); // named like ids: never reflected
  tripleId->SetNumberOfComponents(3);
  tripleId->SetNumberOfTuples(nc);
  for (vtkIdType c = 0; c < nc; ++c)
  {
    label->SetValue(c, static_cast<int>(7 * c + 3));
    const Vec3 n = FaceNormal(pd, c);
    normal->SetTuple3(c, n.x(), n.y(), n.z());
    tripleId->SetTuple3(c, static_cast<double>(c), 1.0, 2.0);
  }
  pd->GetCellData()->AddArray(normal);
  pd->GetCellData()->AddArray(tripleId);
  pd->GetPointData()->AddArray(temperature);
  pd->GetPointData()->AddArray(position);
  pd->GetPointData()->SetActiveVectors("Position");
  pd->GetCellData()->AddArray(label);
  return pd;
}

int Walk(vtkDataObject* object,
  const std::string& name,
  int depth,
  double parentEpsilon,
  int parentKind,
  std::vector<NodeInfo>& nodes,
  const std::string& label)
{
  const int self = static_cast<int>(nodes.size());
  nodes.emplace_back();
  nodes[self].name = name;
  vtkFieldData* fd = nullptr;
  vtkMultiBlockDataSet* mb = vtkMultiBlockDataSet::SafeDownCast(object);
  if (vtkPolyData* leaf = vtkPolyData::SafeDownCast(object))
  {
    nodes[self].leaf = leaf;
    fd = leaf->GetFieldData();
  }
  else if (mb && mb->GetNumberOfBlocks() > 0)
  {
    vtkPolyData* meta = vtkPolyData::SafeDownCast(mb->GetBlock(mb->GetNumberOfBlocks() - 1));
    EXPECT(meta, label << ": " << name << ": last block is not polydata");
    if (!meta)
      return self;
    fd = meta->GetFieldData();
    const char* metaName = BlockName(mb, mb->GetNumberOfBlocks() - 1);
    const int kind = static_cast<int>(FieldValue(fd, "FoldingNodeKind"));
    EXPECT(metaName && std::string(metaName) == (kind == 1 ? "Plane" : "Node"),
      label << ": " << name << ": metadata block named " << (metaName ? metaName : "(none)"));
    if (kind == 1)
    {
      EXPECT(mb->GetNumberOfBlocks() == 2,
        label << ": " << name << ": fold with " << mb->GetNumberOfBlocks() << " blocks");
      EXPECT(meta->GetNumberOfLines() == 1 && meta->GetNumberOfCells() == 1 &&
          meta->GetNumberOfPoints() == 4 && meta->GetLines()->GetCellSize(0) == 5,
        label << ": " << name << ": plane glyph is not a closed outline of 4 corners");
      vtkDataArray* planeLabel = meta->GetCellData()->GetScalars();
      EXPECT(planeLabel && planeLabel->GetName() &&
          std::string(planeLabel->GetName()) == "FoldingLeafId" &&
          planeLabel->GetTuple1(0) == FieldValue(fd, "FoldingNodeIndex"),
        label << ": " << name << ": plane outline not labelled FoldingLeafId = its node index");
      Vec3 n(FieldValue(fd, "FoldingPlaneNormal", 0),
        FieldValue(fd, "FoldingPlaneNormal", 1),
        FieldValue(fd, "FoldingPlaneNormal", 2));
      EXPECT(std::abs(n.norm() - 1.0) < 1e-9, label << ": " << name << ": normal not unit");
      EXPECT(std::isfinite(FieldValue(fd, "FoldingPlaneOrigin", 2)),
        label << ": " << name << ": no plane origin");
    }
    else
    {
      EXPECT(kind == 2 && mb->GetNumberOfBlocks() >= 3,
        label << ": " << name << ": kind " << kind << " with " << mb->GetNumberOfBlocks()
              << " blocks");
    }
  }
  else
  {
    EXPECT(false, label << ": " << name << ": unexpected block type");
    return self;
  }
  NodeInfo& info = nodes[self];
  info.kind = static_cast<int>(FieldValue(fd, "FoldingNodeKind"));
  info.index = static_cast<int>(FieldValue(fd, "FoldingNodeIndex"));
  info.depth = static_cast<int>(FieldValue(fd, "FoldingNodeDepth"));
  info.epsilon = FieldValue(fd, "FoldingEpsilon");
  EXPECT(info.depth == depth, label << ": " << name << ": depth " << info.depth << " != " << depth);
  if (parentKind >= 0)
  {
    const double expected = parentKind == 1 ? 0.5 * parentEpsilon : parentEpsilon;
    EXPECT(std::abs(info.epsilon - expected) <= 1e-12 * expected,
      label << ": " << name << ": epsilon " << info.epsilon << ", expected " << expected);
  }
  std::ostringstream expectedName;
  if (info.kind == 0)
    expectedName << "Leaf " << info.index;
  else if (info.kind == 1)
    expectedName << "Fold " << info.index << " (depth " << depth << ")";
  else
    expectedName << "Segmentation " << info.index << " (depth " << depth << ")";
  EXPECT(name == expectedName.str(),
    label << ": block named \"" << name << "\", expected \"" << expectedName.str() << "\"");
  if (info.kind == 0)
  {
    EXPECT(std::isfinite(FieldValue(fd, "LeafReason")), label << ": " << name << ": no LeafReason");
    EXPECT(fd->GetAbstractArray("MirroredFlagPoint") && fd->GetAbstractArray("MirroredFlagMask"),
      label << ": " << name << ": no mirrored-flag records");
  }
  if (mb)
  {
    const double epsilon = info.epsilon;
    const int kind = info.kind;
    for (unsigned int b = 0; b + 1 < mb->GetNumberOfBlocks(); ++b)
    {
      const char* childName = BlockName(mb, b);
      const int child =
        Walk(mb->GetBlock(b), childName ? childName : "", depth + 1, epsilon, kind, nodes, label);
      nodes[self].children.push_back(child);
    }
  }
  return self;
}

/// Leaves carry the input arrays with the values of their original ids.
void CheckLeafArrays(const std::vector<NodeInfo>& nodes,
  vtkPolyData* input,
  const std::string& label)
{
  vtkDataArray* temperature = input->GetPointData()->GetArray("Temperature");
  vtkDataArray* position = input->GetPointData()->GetArray("Position");
  vtkDataArray* cellLabel = input->GetCellData()->GetArray("Label");
  for (const NodeInfo& n : nodes)
  {
    if (!n.leaf)
      continue;
    vtkPointData* pd = n.leaf->GetPointData();
    vtkDataArray* ids = pd->GetArray("OriginalPointId");
    vtkDataArray* t = pd->GetArray("Temperature");
    vtkDataArray* p = pd->GetArray("Position");
    vtkDataArray* cids = n.leaf->GetCellData()->GetArray("OriginalCellId");
    vtkDataArray* l = n.leaf->GetCellData()->GetArray("Label");
    EXPECT(ids && t && p && cids && l, label << ": " << n.name << ": arrays missing");
    EXPECT(vtkTypeUInt64Array::SafeDownCast(pd->GetAbstractArray("TearMask")) &&
        vtkTypeUInt64Array::SafeDownCast(pd->GetAbstractArray("PlaneMask")) &&
        pd->GetAbstractArray("Projected"),
      label << ": " << n.name << ": TearMask/PlaneMask/Projected missing or not uint64");
    EXPECT(pd->GetVectors() && std::string(pd->GetVectors()->GetName()) == "Position",
      label << ": " << n.name << ": active vectors not kept");
    if (!(ids && t && p && cids && l))
      continue;
    int bad = 0;
    for (vtkIdType i = 0; i < n.leaf->GetNumberOfPoints(); ++i)
    {
      const vtkIdType o = static_cast<vtkIdType>(ids->GetTuple1(i));
      double a[3], b[3];
      p->GetTuple(i, a);
      position->GetTuple(o, b);
      bad += t->GetTuple1(i) != temperature->GetTuple1(o) || a[0] != b[0] || a[1] != b[1] ||
        a[2] != b[2];
    }
    for (vtkIdType c = 0; c < n.leaf->GetNumberOfCells(); ++c)
      bad += l->GetTuple1(c) != cellLabel->GetTuple1(static_cast<vtkIdType>(cids->GetTuple1(c)));
    EXPECT(bad == 0, label << ": " << n.name << ": " << bad << " values differ from the input");
  }
}

double MaximumVertexDistance(vtkPolyData* from, vtkPolyData* to)
{
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(to);
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  double worst = 0.0;
  for (vtkIdType i = 0; i < from->GetNumberOfPoints(); ++i)
  {
    double p[3], closest[3], d2 = 0.0;
    vtkIdType cellId;
    int subId;
    from->GetPoint(i, p);
    locator->FindClosestPoint(p, closest, cell, cellId, subId, d2);
    worst = std::max(worst, std::sqrt(d2));
  }
  return worst;
}

/// Boundary and non-manifold edges.
void CountEdges(vtkPolyData* mesh, int& open, int& nonManifold)
{
  std::map<std::pair<vtkIdType, vtkIdType>, int> uses;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      vtkIdType a = ids->GetId(k), b = ids->GetId((k + 1) % ids->GetNumberOfIds());
      if (a > b)
        std::swap(a, b);
      ++uses[{ a, b }];
    }
  }
  open = nonManifold = 0;
  for (const auto& e : uses)
  {
    open += e.second == 1;
    nonManifold += e.second > 2;
  }
}

bool SameArrays(vtkFieldData* a, vtkFieldData* b, const std::string& what, const std::string& label)
{
  bool same = a->GetNumberOfArrays() == b->GetNumberOfArrays();
  EXPECT(same,
    label << ": " << what << ": " << a->GetNumberOfArrays() << " vs " << b->GetNumberOfArrays()
          << " arrays");
  for (int k = 0; k < a->GetNumberOfArrays() && same; ++k)
  {
    vtkDataArray* x = a->GetArray(k);
    vtkDataArray* y = x ? b->GetArray(x->GetName()) : nullptr;
    if (!x)
      continue;
    if (!y || x->GetNumberOfTuples() != y->GetNumberOfTuples() ||
      x->GetNumberOfComponents() != y->GetNumberOfComponents())
    {
      EXPECT(false, label << ": " << what << " array " << x->GetName() << " differs in shape");
      return false;
    }
    for (vtkIdType i = 0; i < x->GetNumberOfTuples(); ++i)
      for (int c = 0; c < x->GetNumberOfComponents(); ++c)
        if (x->GetComponent(i, c) != y->GetComponent(i, c))
        {
          EXPECT(false, label << ": " << what << " array " << x->GetName() << " differs at " << i);
          return false;
        }
  }
  return same;
}

void ExpectIdentical(vtkPolyData* a, vtkPolyData* b, const std::string& label)
{
  EXPECT(a->GetNumberOfPoints() == b->GetNumberOfPoints() &&
      a->GetNumberOfCells() == b->GetNumberOfCells(),
    label << ": read-back unfolds to " << b->GetNumberOfPoints() << " points / "
          << b->GetNumberOfCells() << " cells, in memory " << a->GetNumberOfPoints() << " / "
          << a->GetNumberOfCells());
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints() ||
    a->GetNumberOfCells() != b->GetNumberOfCells())
    return;
  int differ = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    differ += p[0] != q[0] || p[1] != q[1] || p[2] != q[2];
  }
  vtkNew<vtkIdList> x, y;
  for (vtkIdType c = 0; c < a->GetNumberOfCells(); ++c)
  {
    a->GetCellPoints(c, x);
    b->GetCellPoints(c, y);
    bool same = x->GetNumberOfIds() == y->GetNumberOfIds();
    for (vtkIdType k = 0; same && k < x->GetNumberOfIds(); ++k)
      same = x->GetId(k) == y->GetId(k);
    differ += !same;
  }
  EXPECT(differ == 0, label << ": " << differ << " points/cells differ after the .vtm round trip");
  SameArrays(a->GetPointData(), b->GetPointData(), "point", label);
  SameArrays(a->GetCellData(), b->GetCellData(), "cell", label);
  SameArrays(a->GetFieldData(), b->GetFieldData(), "field", label);
}

void CompareTrees(vtkMultiBlockDataSet* a, vtkMultiBlockDataSet* b, const std::string& label)
{
  EXPECT(a->GetNumberOfBlocks() == b->GetNumberOfBlocks(),
    label << ": " << a->GetNumberOfBlocks() << " vs " << b->GetNumberOfBlocks() << " blocks");
  for (unsigned int k = 0; k < a->GetNumberOfBlocks() && k < b->GetNumberOfBlocks(); ++k)
  {
    const char* na = BlockName(a, k);
    const char* nb = BlockName(b, k);
    const std::string where = label + " / " + (na ? na : "?");
    EXPECT(na && nb && std::string(na) == nb, where << ": block names differ");
    auto* ma = vtkMultiBlockDataSet::SafeDownCast(a->GetBlock(k));
    auto* mb = vtkMultiBlockDataSet::SafeDownCast(b->GetBlock(k));
    auto* pa = vtkPolyData::SafeDownCast(a->GetBlock(k));
    auto* pb = vtkPolyData::SafeDownCast(b->GetBlock(k));
    if (ma && mb)
      CompareTrees(ma, mb, where);
    else if (pa && pb)
      ExpectIdentical(pa, pb, where);
    else
      EXPECT(false, where << ": block types differ");
  }
}
} // namespace foldingtreetest
