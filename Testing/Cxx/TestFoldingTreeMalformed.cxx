// Bad-input tests of TestFoldingTreeFilters: malformed trees and an empty builder input.
#include "TestFoldingTreeChecks.h"
#include "vtkFoldingTreeBuilder.h"
#include "vtkFoldingTreeUnfolder.h"

#include <vtkAbstractArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

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

void ExpectUnfoldFailure(vtkMultiBlockDataSet* tree,
  const std::string& label,
  const std::string& mustContain)
{
  vtkNew<vtkFoldingTreeUnfolder> unfolder;
  unfolder->SetInputData(tree);
  EventLog log;
  const int status = UpdateCapturing(unfolder, log);
  EXPECT(status == 0, label << ": Update() returned " << status);
  EXPECT(!log.errors.empty() && log.errors[0].find(mustContain) != std::string::npos,
    label << ": error does not mention \"" << mustContain
          << "\": " << (log.errors.empty() ? "(none)" : log.errors[0]));
  std::printf(
    "%s -> %s", label.c_str(), log.errors.empty() ? "(no error)\n" : log.errors[0].c_str());
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
} // namespace

void TestMalformed(vtkMultiBlockDataSet* good)
{
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
