// Bad-input tests of TestFoldingTreeFilters: malformed trees (structure, and metadata: Diagonal,
// RootEpsilon, OriginalFaces, level-flag bits, leaves without triangles, InputNonManifoldEdges
// with a bad layout or values), an unusable Original,
// NaN parameters, and builder inputs that are empty or refer to points that do not exist.
#include "TestFoldingTreeChecks.h"
#include "vtkFoldingTreeBuilder.h"
#include "vtkFoldingTreeUnfolder.h"

#include <vtkAbstractArray.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeUInt64Array.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <sstream>

namespace foldingtreetest
{
namespace
{
/// The first folding node's plane block / the first leaf block (with their parents).
bool FindBlock(vtkMultiBlockDataSet* mb,
  bool leaf,
  vtkMultiBlockDataSet*& parent,
  unsigned int& index)
{
  for (unsigned int b = 0; b < mb->GetNumberOfBlocks(); ++b)
  {
    vtkDataObject* child = mb->GetBlock(b);
    const char* name = BlockName(mb, b);
    const std::string n = name ? name : "";
    if ((leaf && n.rfind("Leaf", 0) == 0) || (!leaf && n == "Plane"))
    {
      parent = mb;
      index = b;
      return true;
    }
    if (auto* inner = vtkMultiBlockDataSet::SafeDownCast(child))
      if (FindBlock(inner, leaf, parent, index))
        return true;
  }
  return false;
}

/// The unfolder with `configure` applied and `original` on port 1 must fail with `mustContain`.
void ExpectUnfolderFails(vtkMultiBlockDataSet* good,
  vtkPolyData* original,
  const std::function<void(vtkFoldingTreeUnfolder*)>& configure,
  const std::string& label,
  const std::string& mustContain)
{
  vtkNew<vtkFoldingTreeUnfolder> unfolder;
  unfolder->SetInputData(good);
  if (original)
    unfolder->SetOriginalData(original);
  if (configure)
    configure(unfolder);
  EventLog log;
  const int status = UpdateCapturing(unfolder, log);
  EXPECT(status == 0, label << ": Update() returned " << status);
  EXPECT(!log.errors.empty() && log.errors[0].find(mustContain) != std::string::npos,
    label << ": error does not mention \"" << mustContain
          << "\": " << (log.errors.empty() ? "(none)" : log.errors[0]));
  std::printf(
    "%s -> %s", label.c_str(), log.errors.empty() ? "(no error)\n" : log.errors[0].c_str());
}

void ExpectUnfoldFailure(vtkMultiBlockDataSet* tree,
  const std::string& label,
  const std::string& mustContain)
{
  ExpectUnfolderFails(tree, nullptr, nullptr, label, mustContain);
}

enum class Must
{
  Exist,  ///< a missing block is a failure of its own
  MayMiss ///< the damage is skipped without the block
};

/// A copy of `good` whose first plane block (leaf false) or leaf block (leaf true) is damaged by
/// damage(parent, index) must fail to unfold with an error naming `mustContain`.
template <typename Damage>
void ExpectDamagedTreeFails(vtkMultiBlockDataSet* good,
  bool leaf,
  Must must,
  const std::string& label,
  const std::string& mustContain,
  Damage damage)
{
  vtkNew<vtkMultiBlockDataSet> tree;
  tree->DeepCopy(good);
  vtkMultiBlockDataSet* parent = nullptr;
  unsigned int index = 0;
  const bool found = FindBlock(tree, leaf, parent, index);
  if (must == Must::Exist)
    EXPECT(found, (leaf ? "no leaf block to replace" : "no plane block to damage"));
  if (!found)
    return;
  damage(parent, index);
  ExpectUnfoldFailure(tree, label, mustContain);
}
/// Sets component 0 of the field array `name` of the "Tree" block of `tree`.
void SetTreeValue(vtkMultiBlockDataSet* tree, const char* name, double value)
{
  vtkPolyData* info = vtkPolyData::SafeDownCast(tree->GetBlock(1));
  vtkDataArray* a = info ? info->GetFieldData()->GetArray(name) : nullptr;
  EXPECT(a, "the Tree block has no " << name);
  if (a)
    a->SetComponent(0, 0, value);
}

/// The leaf blocks of a tree node, in block order.
void LeafBlocks(vtkDataObject* node, std::vector<vtkPolyData*>& leaves)
{
  if (auto* mb = vtkMultiBlockDataSet::SafeDownCast(node))
  {
    for (unsigned int b = 0; b < mb->GetNumberOfBlocks(); ++b)
    {
      const char* name = BlockName(mb, b);
      if (name && std::string(name).rfind("Leaf", 0) == 0)
        leaves.push_back(vtkPolyData::SafeDownCast(mb->GetBlock(b)));
      else
        LeafBlocks(mb->GetBlock(b), leaves);
    }
  }
}

/// Removes the triangles (and cell arrays) of a leaf block, keeping an empty OriginalCellId.
void EmptyLeaf(vtkPolyData* leaf)
{
  vtkNew<vtkCellArray> none;
  leaf->SetPolys(none);
  leaf->GetCellData()->Initialize();
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("OriginalCellId");
  leaf->GetCellData()->AddArray(ids);
}

/// A copy of `good` damaged by damage(copy) must fail to unfold with `mustContain`.
void ExpectTreeFails(vtkMultiBlockDataSet* good,
  const std::string& label,
  const std::string& mustContain,
  const std::function<void(vtkMultiBlockDataSet*)>& damage)
{
  vtkNew<vtkMultiBlockDataSet> tree;
  tree->DeepCopy(good);
  damage(tree);
  ExpectUnfoldFailure(tree, label, mustContain);
}


vtkSmartPointer<vtkPolyData> Tetrahedron(vtkIdType lastId, double lastX = 0.0, double scale = 1.0)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(scale, 0, 0);
  points->InsertNextPoint(0, scale, 0);
  points->InsertNextPoint(scale * lastX, 0, scale);
  pd->SetPoints(points);
  vtkNew<vtkCellArray> cells;
  const vtkIdType t[4][3] = { { 0, 2, 1 }, { 0, 1, 3 }, { 1, 2, 3 }, { 0, 3, lastId } };
  for (const auto& c : t)
    cells->InsertNextCell(3, c);
  pd->SetPolys(cells);
  return pd;
}

std::string Str(double v)
{
  std::ostringstream os;
  os << v;
  return os.str();
}

/// Metadata damage: each must be rejected by FoldingTree::Validate or the reader.
void TestMalformedMetadata(vtkMultiBlockDataSet* good)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double diagonal : { 1e300, nan, 0.0, -5.0, std::numeric_limits<double>::infinity() })
    ExpectTreeFails(good,
      "Diagonal " + Str(diagonal),
      "diagonal",
      [&](vtkMultiBlockDataSet* t) { SetTreeValue(t, "Diagonal", diagonal); });
  // 1e-3 of the true diagonal: the stored points reach beyond four diagonals.
  {
    const double diagonal =
      FieldValue(vtkPolyData::SafeDownCast(good->GetBlock(1))->GetFieldData(), "Diagonal");
    ExpectTreeFails(good,
      "Diagonal / 1000",
      "diagonal",
      [&](vtkMultiBlockDataSet* t) { SetTreeValue(t, "Diagonal", 1e-3 * diagonal); });
  }
  for (double epsilon : { nan, 0.0, 1e300 })
    ExpectTreeFails(good,
      "RootEpsilon " + Str(epsilon),
      "root epsilon",
      [&](vtkMultiBlockDataSet* t) { SetTreeValue(t, "RootEpsilon", epsilon); });
  for (const char* name : { "OriginalFaces", "OriginalPoints" })
    for (double count : { -7.0, 1e15 })
      ExpectTreeFails(good,
        std::string(name) + " " + Str(count),
        name,
        [&](vtkMultiBlockDataSet* t) { SetTreeValue(t, name, count); });
  // The input's non-manifold edges (optional: a good tree may have none): wrong layout, a
  // point id out of range, a < b broken, at most two faces, a fraction.
  {
    struct Damage
    {
      const char* label;
      int components;
      double a, b, faces;
      const char* error;
    };
    const Damage damages[] = {
      { "InputNonManifoldEdges with 2 components", 2, 0, 1, 3, "three values per edge" },
      { "InputNonManifoldEdges point out of range", 3, 0, 1e9, 3, "non-manifold edge" },
      { "InputNonManifoldEdges a > b", 3, 2, 1, 3, "non-manifold edge" },
      { "InputNonManifoldEdges 2 faces", 3, 0, 1, 2, "non-manifold edge" },
      { "InputNonManifoldEdges negative id", 3, -1, 1, 3, "InputNonManifoldEdges" },
      { "InputNonManifoldEdges fraction", 3, 0, 1, 3.5, "InputNonManifoldEdges" },
    };
    for (const Damage& d : damages)
      ExpectTreeFails(good,
        d.label,
        d.error,
        [&](vtkMultiBlockDataSet* t)
        {
          vtkPolyData* info = vtkPolyData::SafeDownCast(t->GetBlock(1));
          vtkNew<vtkIdTypeArray> edges;
          edges->SetName("InputNonManifoldEdges");
          edges->SetNumberOfComponents(d.components);
          edges->SetNumberOfTuples(1);
          const double v[3] = { d.a, d.b, d.faces };
          for (int c = 0; c < d.components; ++c)
            edges->SetComponent(0, c, v[c]);
          if (d.faces == 3.5) // (an integer array cannot hold it)
          {
            vtkNew<vtkDoubleArray> fraction;
            fraction->DeepCopy(edges);
            fraction->SetName("InputNonManifoldEdges");
            fraction->SetComponent(0, 2, 3.5);
            info->GetFieldData()->AddArray(fraction);
            return;
          }
          info->GetFieldData()->AddArray(edges);
        });
  }
  // Level flags for the leaf's own depth (no node above it there) and beyond.
  for (const char* mask : { "PlaneMask", "TearMask" })
    for (int extra : { 0, 5 })
      ExpectTreeFails(good,
        std::string(mask) + " bit at leaf depth + " + std::to_string(extra),
        mask,
        [&](vtkMultiBlockDataSet* t)
        {
          std::vector<vtkPolyData*> leaves;
          LeafBlocks(t->GetBlock(0), leaves);
          EXPECT(!leaves.empty(), "no leaf");
          if (leaves.empty())
            return;
          vtkPolyData* leaf = leaves[0];
          const int depth =
            static_cast<int>(FieldValue(leaf->GetFieldData(), "FoldingNodeDepth")) + extra;
          vtkDataArray* a = leaf->GetPointData()->GetArray(mask);
          vtkTypeUInt64Array* bits = vtkTypeUInt64Array::SafeDownCast(a);
          EXPECT(bits, "leaf without a vtkTypeUInt64Array " << mask);
          for (vtkIdType i = 0; bits && i < bits->GetNumberOfTuples(); ++i)
            bits->SetValue(i, bits->GetValue(i) | (uint64_t(1) << depth));
        });
  ExpectTreeFails(good,
    "every leaf without triangles",
    "no triangles",
    [](vtkMultiBlockDataSet* t)
    {
      std::vector<vtkPolyData*> leaves;
      LeafBlocks(t->GetBlock(0), leaves);
      for (vtkPolyData* leaf : leaves)
        EmptyLeaf(leaf);
    });
  // One empty leaf among others: a warning, the rest unfolds.
  {
    vtkNew<vtkMultiBlockDataSet> tree;
    tree->DeepCopy(good);
    std::vector<vtkPolyData*> leaves;
    LeafBlocks(tree->GetBlock(0), leaves);
    EXPECT(leaves.size() >= 2, "the test tree has fewer than two leaves");
    if (!leaves.empty())
      EmptyLeaf(leaves[0]);
    vtkNew<vtkFoldingTreeUnfolder> unfolder;
    unfolder->SetInputData(tree);
    EventLog warnings;
    vtkNew<vtkCallbackCommand> callback;
    callback->SetCallback(EventLog::Callback);
    callback->SetClientData(&warnings);
    unfolder->AddObserver(vtkCommand::WarningEvent, callback);
    EventLog log;
    const int status = UpdateCapturing(unfolder, log);
    EXPECT(status == 1 && unfolder->GetOutput()->GetNumberOfCells() > 0,
      "one empty leaf: status " << status << ", "
                                << unfolder->GetOutput()->GetNumberOfCells() << " faces");
    EXPECT(warnings.errors.size() == 1 &&
        warnings.errors[0].find("store no triangles") != std::string::npos,
      "one empty leaf: no warning");
  }

  // An unusable Original (port 1), and NaN parameters.
  for (vtkIdType bad : { vtkIdType(-100000), vtkIdType(4), vtkIdType(5000000) })
    ExpectUnfolderFails(good,
      Tetrahedron(bad),
      nullptr,
      "Original with point id " + std::to_string(static_cast<long long>(bad)),
      "a triangle refers to a point that does not exist");
  ExpectUnfolderFails(
    good, Tetrahedron(2, nan), nullptr, "Original with a NaN point", "NaN or infinite");
  ExpectUnfolderFails(good,
    nullptr,
    [&](vtkFoldingTreeUnfolder* u) { u->SetStitchToleranceScale(nan); },
    "StitchToleranceScale NaN",
    "must be finite");
  ExpectUnfolderFails(good,
    nullptr,
    [&](vtkFoldingTreeUnfolder* u) { u->SetHoleToleranceScale(nan); },
    "HoleToleranceScale NaN",
    "must be finite");

  // The builder: points that do not exist, a NaN tolerance.
  for (vtkIdType bad : { vtkIdType(-1000000), vtkIdType(-1), vtkIdType(4), vtkIdType(7) })
  {
    vtkNew<vtkFoldingTreeBuilder> builder;
    builder->SetInputData(Tetrahedron(bad));
    EventLog log;
    EXPECT(UpdateCapturing(builder, log) == 0 && !log.errors.empty() &&
        log.errors[0].find("a triangle refers to a point that does not exist") !=
          std::string::npos,
      "builder, point id " << bad << ": no clear error");
  }
  // Scale: beyond the supported diagonals [1e-60, 1e60] a clear error (it used to be "zero
  // area", "non-finite coordinates" or an empty tree), within them a tree.
  for (double scale : { 1e-100, 1e-62, 1e62, 1e150, 1e200, 1e300, 1e-59, 1e59 })
  {
    vtkNew<vtkFoldingTreeBuilder> builder;
    builder->SetInputData(Tetrahedron(2, 0.0, scale));
    EventLog log;
    const int status = UpdateCapturing(builder, log);
    if (scale < 1e-60 || scale > 1e60)
      EXPECT(status == 0 && !log.errors.empty() &&
          log.errors[0].find("outside the supported range") != std::string::npos,
        "builder, tetrahedron scaled by " << scale << ": "
                                          << (log.errors.empty() ? "(no error)" : log.errors[0]));
    else
      EXPECT(status == 1 && builder->GetStoredFaces() == 4,
        "builder, tetrahedron scaled by " << scale << ": status " << status << ", "
                                          << builder->GetStoredFaces() << " faces stored");
  }
  // A collapsed triangle (three points at one position, dropped by the builder) far from the
  // stored ones stretches the input's diagonal: the tree is still valid and unfolds.
  {
    vtkSmartPointer<vtkPolyData> mesh = Tetrahedron(2);
    vtkPoints* points = mesh->GetPoints();
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      double p[3];
      points->GetPoint(i, p);
      points->SetPoint(i, p[0] + 100.0, p[1] + 100.0, p[2] + 100.0);
    }
    const vtkIdType collapsed[3] = { points->InsertNextPoint(0, 0, 0),
      points->InsertNextPoint(0, 0, 0), points->InsertNextPoint(0, 0, 0) };
    mesh->GetPolys()->InsertNextCell(3, collapsed);
    vtkNew<vtkFoldingTreeBuilder> builder;
    builder->SetInputData(mesh);
    EventLog log;
    const int built = UpdateCapturing(builder, log);
    vtkNew<vtkFoldingTreeUnfolder> unfolder;
    unfolder->SetInputConnection(builder->GetOutputPort(0));
    EventLog unfoldLog;
    const int unfolded = built ? UpdateCapturing(unfolder, unfoldLog) : 0;
    EXPECT(built == 1 && unfolded == 1 && unfolder->GetOutput()->GetNumberOfCells() == 4,
      "a far collapsed triangle: built " << built << ", unfolded " << unfolded << ": "
                                         << (log.errors.empty() ? "" : log.errors[0])
                                         << (unfoldLog.errors.empty() ? "" : unfoldLog.errors[0]));
  }
  {
    vtkNew<vtkFoldingTreeBuilder> builder;
    builder->SetInputData(Tetrahedron(2));
    builder->SetTolerance(nan);
    EventLog log;
    EXPECT(UpdateCapturing(builder, log) == 0 && !log.errors.empty() &&
        log.errors[0].find("Tolerance must be a positive, finite number") != std::string::npos,
      "builder, Tolerance NaN: " << (log.errors.empty() ? "(no error)" : log.errors[0]));
  }
}
} // namespace

void TestMalformed(vtkMultiBlockDataSet* good)
{
  TestMalformedMetadata(good);
  ExpectDamagedTreeFails(good,
    false,
    Must::Exist,
    "fold without plane metadata",
    "plane metadata",
    [](vtkMultiBlockDataSet* parent, unsigned int index)
    {
      vtkNew<vtkFieldData> empty;
      vtkPolyData::SafeDownCast(parent->GetBlock(index))->SetFieldData(empty);
    });
  ExpectDamagedTreeFails(good,
    false,
    Must::Exist,
    "fold without its normal",
    "FoldingPlaneNormal",
    [](vtkMultiBlockDataSet* parent, unsigned int index)
    {
      vtkPolyData::SafeDownCast(parent->GetBlock(index))
        ->GetFieldData()
        ->RemoveArray("FoldingPlaneNormal");
    });
  ExpectDamagedTreeFails(good,
    true,
    Must::Exist,
    "leaf replaced by vtkImageData",
    "vtkImageData",
    [](vtkMultiBlockDataSet* parent, unsigned int index)
    {
      vtkNew<vtkImageData> image;
      image->SetDimensions(2, 2, 2);
      parent->SetBlock(index, image);
    });
  ExpectDamagedTreeFails(good,
    true,
    Must::MayMiss,
    "leaf with a wrong node kind",
    "FoldingNodeKind",
    [](vtkMultiBlockDataSet* parent, unsigned int index)
    {
      vtkNew<vtkIntArray> kind;
      kind->SetName("FoldingNodeKind");
      kind->InsertNextValue(2);
      vtkPolyData::SafeDownCast(parent->GetBlock(index))->GetFieldData()->AddArray(kind);
    });
  ExpectDamagedTreeFails(good,
    true,
    Must::MayMiss,
    "leaf with a short TearMask",
    "TearMask",
    [](vtkMultiBlockDataSet* parent, unsigned int index)
    {
      vtkPolyData::SafeDownCast(parent->GetBlock(index))
        ->GetPointData()
        ->GetAbstractArray("TearMask")
        ->SetNumberOfTuples(3);
    });
  {
    vtkNew<vtkMultiBlockDataSet> tree;
    ExpectUnfoldFailure(tree, "empty multiblock", "two top-level blocks");
  }
  {
    vtkNew<vtkPolyData> empty;
    vtkNew<vtkFoldingTreeBuilder> builder;
    builder->SetInputData(empty);
    EventLog log;
    EXPECT(UpdateCapturing(builder, log) == 0 && !log.errors.empty(),
      "builder on an empty mesh did not fail");
  }
}
} // namespace foldingtreetest
