#include "vtkFoldingMeshesParallel.h"

#include <vtkAlgorithm.h>
#include <vtkAppendPolyData.h>
#include <vtkCommunicator.h>
#include <vtkDataObject.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <string>

namespace foldingmeshes
{
namespace
{
/// The same tree of vtkMultiBlockDataSet (block metadata and field data copied), sharing
/// the datasets: the merge below must not modify the pipeline's input.
vtkSmartPointer<vtkMultiBlockDataSet> CopyTree(vtkMultiBlockDataSet* source)
{
  auto copy = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  copy->SetNumberOfBlocks(source->GetNumberOfBlocks());
  copy->SetFieldData(source->GetFieldData());
  for (unsigned int b = 0; b < source->GetNumberOfBlocks(); ++b)
  {
    vtkDataObject* block = source->GetBlock(b);
    if (auto child = vtkMultiBlockDataSet::SafeDownCast(block))
      copy->SetBlock(b, CopyTree(child));
    else
      copy->SetBlock(b, block);
    if (source->HasMetaData(b))
      copy->GetMetaData(b)->Copy(source->GetMetaData(b));
  }
  return copy;
}

/// Blocks of `target` without a dataset take the one at the same place in `source`.
void FillMissingBlocks(vtkMultiBlockDataSet* target, vtkMultiBlockDataSet* source)
{
  const unsigned int n = std::min(target->GetNumberOfBlocks(), source->GetNumberOfBlocks());
  for (unsigned int b = 0; b < n; ++b)
  {
    vtkDataObject* from = source->GetBlock(b);
    if (!from)
      continue;
    vtkDataObject* to = target->GetBlock(b);
    auto toTree = vtkMultiBlockDataSet::SafeDownCast(to);
    auto fromTree = vtkMultiBlockDataSet::SafeDownCast(from);
    if (toTree && fromTree)
      FillMissingBlocks(toTree, fromTree);
    else if (!to)
      target->SetBlock(b, fromTree ? CopyTree(fromTree).GetPointer() : from);
  }
}
}

//------------------------------------------------------------------------------
std::string TreeStructure(vtkMultiBlockDataSet* tree)
{
  // "M<n>;" then per block "<length>:<name>" and the child: a nested "M..." or "L" (leaf).
  std::string text = "M" + std::to_string(tree->GetNumberOfBlocks()) + ";";
  for (unsigned int b = 0; b < tree->GetNumberOfBlocks(); ++b)
  {
    const char* name = tree->HasMetaData(b)
      ? tree->GetMetaData(b)->Get(vtkCompositeDataSet::NAME())
      : nullptr;
    const std::string blockName = name ? name : "";
    text += std::to_string(blockName.size()) + ":" + blockName;
    if (auto child = vtkMultiBlockDataSet::SafeDownCast(tree->GetBlock(b)))
      text += TreeStructure(child);
    else
      text += "L";
  }
  return text;
}

namespace
{
/// Reads a number followed by `end` at `pos`; false when the text does not continue so.
bool ReadCount(const std::string& text, size_t& pos, char end, size_t& value)
{
  const size_t stop = text.find(end, pos);
  if (stop == std::string::npos || stop == pos || stop - pos > 9)
    return false;
  value = 0;
  for (size_t i = pos; i < stop; ++i)
  {
    if (text[i] < '0' || text[i] > '9')
      return false;
    value = 10 * value + static_cast<size_t>(text[i] - '0');
  }
  pos = stop + 1;
  return true;
}

bool ReadStructure(const std::string& text, size_t& pos, vtkMultiBlockDataSet* tree, int depth)
{
  size_t blocks = 0;
  if (depth > 1000 || pos >= text.size() || text[pos++] != 'M' ||
    !ReadCount(text, pos, ';', blocks) || blocks > text.size())
    return false;
  tree->SetNumberOfBlocks(static_cast<unsigned int>(blocks));
  for (unsigned int b = 0; b < blocks; ++b)
  {
    size_t length = 0;
    if (!ReadCount(text, pos, ':', length) || length > text.size() - pos)
      return false;
    const std::string name = text.substr(pos, length);
    pos += length;
    if (pos >= text.size())
      return false;
    if (text[pos] == 'M')
    {
      vtkNew<vtkMultiBlockDataSet> child;
      if (!ReadStructure(text, pos, child, depth + 1))
        return false;
      tree->SetBlock(b, child);
    }
    else if (text[pos++] != 'L')
      return false;
    if (!name.empty())
      tree->GetMetaData(b)->Set(vtkCompositeDataSet::NAME(), name.c_str());
  }
  return true;
}
}

bool SetTreeStructure(vtkMultiBlockDataSet* tree, const std::string& structure)
{
  tree->Initialize();
  size_t pos = 0;
  if (ReadStructure(structure, pos, tree, 0) && pos == structure.size())
    return true;
  tree->Initialize();
  return false;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> AppendPieces(const std::vector<vtkSmartPointer<vtkPolyData>>& pieces)
{
  std::vector<vtkSmartPointer<vtkPolyData>> nonEmpty;
  for (const auto& piece : pieces)
  {
    if (!piece || piece->GetNumberOfCells() == 0)
      continue;
    auto copy = vtkSmartPointer<vtkPolyData>::New();
    copy->ShallowCopy(piece);
    if (copy->HasAnyGhostCells())
      copy->RemoveGhostCells();
    nonEmpty.push_back(copy);
  }
  if (nonEmpty.size() == 1)
    return nonEmpty[0];
  auto whole = vtkSmartPointer<vtkPolyData>::New();
  if (nonEmpty.empty())
    return whole;
  vtkNew<vtkAppendPolyData> append;
  for (const auto& piece : nonEmpty)
    append->AddInputData(piece);
  append->Update();
  whole->ShallowCopy(append->GetOutput());
  whole->SetFieldData(nonEmpty[0]->GetFieldData());
  return whole;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkMultiBlockDataSet> MergeTreePieces(
  const std::vector<vtkSmartPointer<vtkMultiBlockDataSet>>& pieces)
{
  vtkSmartPointer<vtkMultiBlockDataSet> whole;
  for (const auto& piece : pieces)
  {
    if (!piece || piece->GetNumberOfBlocks() == 0)
      continue;
    if (!whole)
      whole = CopyTree(piece);
    else
      FillMissingBlocks(whole, piece);
  }
  return whole ? whole : vtkSmartPointer<vtkMultiBlockDataSet>::New();
}

//------------------------------------------------------------------------------
ParallelRun::ParallelRun(vtkAlgorithm* algorithm, vtkMultiProcessController* controller)
  : Controller(controller)
  , NumberOfPorts(algorithm->GetNumberOfInputPorts())
{
  // Distributed only if the pipeline asks for pieces (as ParaView does on every rank): a
  // plain Update() on one rank, or on each rank of an MPI script, asks for the whole data.
  vtkInformation* request = algorithm->GetNumberOfOutputPorts() > 0
    ? algorithm->GetExecutive()->GetOutputInformation(0)
    : nullptr;
  const int pieces =
    request && request->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    ? request->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    : 1;
  this->Parallel = controller && controller->GetNumberOfProcesses() > 1 && pieces > 1;
  this->Root = !this->Parallel || controller->GetLocalProcessId() == 0;
}

ParallelRun::~ParallelRun() = default;

//------------------------------------------------------------------------------
vtkSmartPointer<vtkDataObject> ParallelRun::GatherPort(vtkDataObject* piece)
{
  std::vector<vtkSmartPointer<vtkDataObject>> received;
  if (!this->Controller->Gather(piece, received, 0))
  {
    this->GatherFailed = true;
    return nullptr;
  }
  if (!this->Root)
    return nullptr;
  if (received.size() > 0)
    received[0] = piece; // rank 0's own data, as it is (e.g. block names)
  vtkDataObject* first = nullptr;
  for (const auto& object : received)
    if (object && !first)
      first = object;
  if (vtkPolyData::SafeDownCast(first))
  {
    std::vector<vtkSmartPointer<vtkPolyData>> pieces;
    for (const auto& object : received)
      pieces.push_back(vtkPolyData::SafeDownCast(object));
    return AppendPieces(pieces);
  }
  if (vtkMultiBlockDataSet::SafeDownCast(first))
  {
    std::vector<vtkSmartPointer<vtkMultiBlockDataSet>> pieces;
    for (const auto& object : received)
      pieces.push_back(vtkMultiBlockDataSet::SafeDownCast(object));
    return MergeTreePieces(pieces);
  }
  return piece;
}

//------------------------------------------------------------------------------
vtkInformationVector** ParallelRun::Gather(vtkInformationVector** inputVector)
{
  this->Whole.clear();
  this->WholeVectors.clear();
  for (int port = 0; port < this->NumberOfPorts; ++port)
  {
    auto vector = vtkSmartPointer<vtkInformationVector>::New();
    // Optional ports without a connection have none on every rank: nothing to gather.
    if (inputVector[port]->GetNumberOfInformationObjects() > 0)
    {
      vtkSmartPointer<vtkDataObject> whole =
        this->GatherPort(vtkDataObject::GetData(inputVector[port], 0));
      vtkNew<vtkInformation> info;
      info->Set(vtkDataObject::DATA_OBJECT(), whole);
      vector->Append(info);
    }
    this->Whole.push_back(vector);
    this->WholeVectors.push_back(vector);
  }
  if (!this->Root || this->GatherFailed)
    return nullptr;
  return this->WholeVectors.data();
}

//------------------------------------------------------------------------------
void ParallelRun::Broadcast(int& status,
  std::vector<double>& values,
  vtkInformationVector* outputVector)
{
  // The status first, then the number of values, then the values.
  int header[2] = { this->GatherFailed ? 0 : status, static_cast<int>(values.size()) };
  int failures = 0;
  const int local = this->GatherFailed ? 1 : 0;
  this->Controller->Reduce(&local, &failures, 1, vtkCommunicator::SUM_OP, 0);
  if (failures > 0)
    header[0] = 0;
  this->Controller->Broadcast(header, 2, 0);
  status = header[0];
  values.resize(static_cast<size_t>(header[1]));
  if (header[1] > 0)
    this->Controller->Broadcast(values.data(), header[1], 0);
  for (int i = 0; i < outputVector->GetNumberOfInformationObjects(); ++i)
  {
    vtkDataObject* output = vtkDataObject::GetData(outputVector, i);
    // A tree output keeps rank 0's block structure (names, no datasets) on the other ranks,
    // as a parallel .vtm reader gives it: collective writers such as
    // vtkXMLPMultiBlockDataWriter need the same structure on every rank.
    auto* tree = vtkMultiBlockDataSet::SafeDownCast(output);
    std::string structure = this->Root && tree && status ? TreeStructure(tree) : std::string();
    vtkIdType length = static_cast<vtkIdType>(structure.size());
    if (tree)
    {
      this->Controller->Broadcast(&length, 1, 0);
      structure.resize(static_cast<size_t>(length));
      if (length > 0)
        this->Controller->Broadcast(&structure[0], length, 0);
    }
    if (this->Root || !output)
      continue;
    if (tree && length > 0)
      SetTreeStructure(tree, structure);
    else
      output->Initialize();
  }
}

int RunWholeOnRoot(vtkAlgorithm* algorithm,
  vtkMultiProcessController* controller,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector,
  const std::function<int(vtkInformationVector**)>& whole,
  const ParallelResults& results)
{
  ParallelRun parallel(algorithm, controller);
  if (!parallel.IsParallel())
  {
    return whole(inputVector);
  }
  vtkInformationVector** gathered = parallel.Gather(inputVector);
  int status = 1;
  std::vector<double> values;
  if (parallel.IsRoot())
  {
    status = gathered ? whole(gathered) : 0;
    for (double* d : results.doubles)
      values.push_back(*d);
    for (int* i : results.ints)
      values.push_back(static_cast<double>(*i));
    for (bool* b : results.bools)
      values.push_back(*b ? 1.0 : 0.0);
  }
  parallel.Broadcast(status, values, outputVector);
  const size_t n = results.doubles.size() + results.ints.size() + results.bools.size();
  if (!parallel.IsRoot() && values.size() == n)
  {
    size_t k = 0;
    for (double* d : results.doubles)
      *d = values[k++];
    for (int* i : results.ints)
      *i = static_cast<int>(values[k++]);
    for (bool* b : results.bools)
      *b = values[k++] != 0.0;
  }
  return status;
}
}
