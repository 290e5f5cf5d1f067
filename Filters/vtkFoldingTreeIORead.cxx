// MultiBlockToFoldingTree: vtkMultiBlockDataSet -> core FoldingTree, with validation.
#include "vtkFoldingTreeIO.h"
#include "vtkFoldingTreeNodeReader.h"

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
using tree_io_detail::Reader;

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
  long long tried = 0; // optional: files written before 2026-12-06
  if (fd->GetAbstractArray("RotationNodesTried") &&
    reader.Int(fd, "RotationNodesTried", "Tree", tried))
    tree.rotationNodesTried = tried != 0;
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
