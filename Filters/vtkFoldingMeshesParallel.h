// Parallel (MPI) runs of the FoldingMeshes filters (internal header of FoldingMeshes::Filters).
//
// Symmetry detection and folding look at the whole mesh at once, so a distributed run
// computes once, on rank 0, on the data of all ranks gathered there; the scalar results are
// broadcast so every rank's getters agree; rank 0 holds the outputs, the other ranks have
// empty outputs. A filter's RequestData is one call:
//
//   return foldingmeshes::RunWholeOnRoot(this, this->Controller, inputVector, outputVector,
//     [&](vtkInformationVector** in) { return this->RequestWholeData(request, in, outputVector); },
//     { { &this->Result1 }, { &this->Count }, { &this->Found } });  // doubles, ints, bools
//
// (serial runs call RequestWholeData unchanged; ParallelRun is the collective machinery).
#ifndef vtkFoldingMeshesParallel_h
#define vtkFoldingMeshesParallel_h

#include <vtkSmartPointer.h>

#include <functional>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkDataObject;
class vtkInformationVector;
class vtkMultiBlockDataSet;
class vtkMultiProcessController;
class vtkPolyData;

namespace foldingmeshes
{
/**
 * Appends poly data pieces in order (empty or null pieces are skipped; ghost cells are
 * removed). Points are not merged: the core welds points with identical coordinates.
 * The field data of the first non-empty piece is kept. Never null.
 */
vtkSmartPointer<vtkPolyData> AppendPieces(const std::vector<vtkSmartPointer<vtkPolyData>>& pieces);

/**
 * Merges multiblock pieces of the same tree structure (as a parallel .vtm reader gives:
 * every rank has the structure and block names, each dataset lives on one rank) into one:
 * a copy of the first piece in which every block without a dataset takes the one at the
 * same place in a later piece. Pieces without blocks (a rank where the builder produced
 * nothing) are skipped.
 * Never null.
 */
vtkSmartPointer<vtkMultiBlockDataSet> MergeTreePieces(
  const std::vector<vtkSmartPointer<vtkMultiBlockDataSet>>& pieces);

/**
 * The block structure of a tree (nested multiblocks and block names, not the datasets) as
 * text, and back: SetTreeStructure makes `tree` that structure with no datasets (false, and
 * `tree` empty, when the text is not one TreeStructure wrote).
 */
std::string TreeStructure(vtkMultiBlockDataSet* tree);
bool SetTreeStructure(vtkMultiBlockDataSet* tree, const std::string& structure);

/**
 * One execution of a filter in a possibly parallel run. Parallel means `controller` is
 * non-null and has more than one process, and the request asks `algorithm` for one of
 * several pieces (UPDATE_NUMBER_OF_PIECES > 1: ParaView does so on every rank; a plain
 * Update() asks for the whole data, which then needs no gathering). Then Gather and
 * Broadcast are collective (every rank must call them, in the same order).
 */
class ParallelRun
{
public:
  ParallelRun(vtkAlgorithm* algorithm, vtkMultiProcessController* controller);
  ~ParallelRun();
  ParallelRun(const ParallelRun&) = delete;
  ParallelRun& operator=(const ParallelRun&) = delete;

  bool IsParallel() const { return this->Parallel; }
  /// True on rank 0, and in a serial run.
  bool IsRoot() const { return this->Root; }

  /**
   * Collective: sends the data of every input port (its first connection) of every rank to
   * rank 0. Returns, on rank 0, input vectors (one per port) holding the whole data -- poly
   * data pieces appended (AppendPieces), folding tree pieces merged (MergeTreePieces), other
   * data as rank 0 has it -- to pass to the serial RequestData; nullptr on the other ranks,
   * or if communication failed (the status given to Broadcast then becomes 0).
   */
  vtkInformationVector** Gather(vtkInformationVector** inputVector);

  /**
   * Collective: `status` and `values` of rank 0 replace those of the other ranks, whose
   * outputs (every data object of `outputVector`) are emptied; a multiblock output (the
   * folding tree) keeps rank 0's block structure and names there, without datasets. A
   * failed gather turns the status into 0 on every rank.
   */
  void Broadcast(int& status, std::vector<double>& values, vtkInformationVector* outputVector);

private:
  vtkSmartPointer<vtkDataObject> GatherPort(vtkDataObject* piece);

  vtkMultiProcessController* Controller = nullptr;
  int NumberOfPorts = 0;
  bool Parallel = false;
  bool Root = true;
  bool GatherFailed = false;
  std::vector<vtkSmartPointer<vtkInformationVector>> Whole;
  std::vector<vtkInformationVector*> WholeVectors;
};

/// A filter's result members, sent from rank 0 to the other ranks after a parallel run.
struct ParallelResults
{
  std::vector<double*> doubles;
  std::vector<int*> ints;
  std::vector<bool*> bools;
};

/**
 * A filter's whole RequestData. Serial (see ParallelRun): `whole(inputVector)`. Parallel:
 * gathers the input on rank 0, runs `whole` there, and gives every rank rank 0's status and
 * `results`; the other ranks' outputs are empty.
 */
int RunWholeOnRoot(vtkAlgorithm* algorithm,
  vtkMultiProcessController* controller,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector,
  const std::function<int(vtkInformationVector**)>& whole,
  const ParallelResults& results);
}

#endif
