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
} // namespace

void TestMalformed(vtkMultiBlockDataSet* good)
{
  {
    vtkNew<vtkMultiBlockDataSet> tree;
    tree->DeepCopy(good);
    vtkMultiBlockDataSet* parent = nullptr;
    unsigned int index = 0;
    EXPECT(FindBlock(tree, false, parent, index), "no plane block to damage");
    if (parent)
    {
      vtkNew<vtkFieldData> empty;
      vtkPolyData::SafeDownCast(parent->GetBlock(index))->SetFieldData(empty);
      ExpectUnfoldFailure(tree, "fold without plane metadata", "plane metadata");
    }
  }
  {
    vtkNew<vtkMultiBlockDataSet> tree;
    tree->DeepCopy(good);
    vtkMultiBlockDataSet* parent = nullptr;
    unsigned int index = 0;
    EXPECT(FindBlock(tree, false, parent, index), "no plane block to damage");
    if (parent)
    {
      vtkPolyData* plane = vtkPolyData::SafeDownCast(parent->GetBlock(index));
      plane->GetFieldData()->RemoveArray("FoldingPlaneNormal");
      ExpectUnfoldFailure(tree, "fold without its normal", "FoldingPlaneNormal");
    }
  }
  {
    vtkNew<vtkMultiBlockDataSet> tree;
    tree->DeepCopy(good);
    vtkMultiBlockDataSet* parent = nullptr;
    unsigned int index = 0;
    EXPECT(FindBlock(tree, true, parent, index), "no leaf block to replace");
    if (parent)
    {
      vtkNew<vtkImageData> image;
      image->SetDimensions(2, 2, 2);
      parent->SetBlock(index, image);
      ExpectUnfoldFailure(tree, "leaf replaced by vtkImageData", "vtkImageData");
    }
  }
  {
    vtkNew<vtkMultiBlockDataSet> tree;
    tree->DeepCopy(good);
    vtkMultiBlockDataSet* parent = nullptr;
    unsigned int index = 0;
    if (FindBlock(tree, true, parent, index))
    {
      vtkPolyData* leaf = vtkPolyData::SafeDownCast(parent->GetBlock(index));
      vtkNew<vtkIntArray> kind;
      kind->SetName("FoldingNodeKind");
      kind->InsertNextValue(2);
      leaf->GetFieldData()->AddArray(kind);
      ExpectUnfoldFailure(tree, "leaf with a wrong node kind", "FoldingNodeKind");
    }
  }
  {
    vtkNew<vtkMultiBlockDataSet> tree;
    tree->DeepCopy(good);
    vtkMultiBlockDataSet* parent = nullptr;
    unsigned int index = 0;
    if (FindBlock(tree, true, parent, index))
    {
      vtkPolyData* leaf = vtkPolyData::SafeDownCast(parent->GetBlock(index));
      leaf->GetPointData()->GetAbstractArray("TearMask")->SetNumberOfTuples(3);
      ExpectUnfoldFailure(tree, "leaf with a short TearMask", "TearMask");
    }
  }
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
