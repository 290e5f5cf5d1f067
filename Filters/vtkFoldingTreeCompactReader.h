/**
 * @class   vtkFoldingTreeCompactReader
 * @brief   reads a compact .fmz folding tree into the tree vtkFoldingTreeUnfolder takes
 *
 * Reads a file written by vtkFoldingTreeCompactWriter (or `foldingmeshes compress`) and produces
 * the same vtkMultiBlockDataSet encoding as vtkFoldingTreeBuilder's Tree output (block 0 the
 * root node, block 1 the "Tree" information block), with what the compact file keeps (see
 * vtkFoldingTreeCompactWriter for what it does not): the leaves carry the user point and cell
 * arrays when the file was written with StoreUserArrays. The information block also carries
 * "QuantizationError": the largest distance quantisation moved a stored point (already
 * subtracted from the points' error budgets).
 *
 * A missing file, another format, another format version, a truncated or corrupt file
 * (checksum) or a tree that does not validate is reported with vtkErrorMacro, the ErrorCode is
 * set and the output is an empty vtkMultiBlockDataSet.
 *
 * @sa vtkFoldingTreeCompactWriter vtkFoldingTreeUnfolder
 */
#ifndef vtkFoldingTreeCompactReader_h
#define vtkFoldingTreeCompactReader_h

#include "FoldingMeshesFiltersModule.h" // for export macro
#include "vtkMultiBlockDataSetAlgorithm.h"

class FOLDINGMESHESFILTERS_EXPORT vtkFoldingTreeCompactReader : public vtkMultiBlockDataSetAlgorithm
{
public:
  static vtkFoldingTreeCompactReader* New();
  vtkTypeMacro(vtkFoldingTreeCompactReader, vtkMultiBlockDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Name of the .fmz file to read. */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /** 1 if the file starts with the compact tree file's magic number, else 0. */
  static int CanReadFile(const char* fileName);

  /** vtkErrorCode of the last read (0: no error). */
  vtkGetMacro(ErrorCode, unsigned long);

protected:
  vtkFoldingTreeCompactReader();
  ~vtkFoldingTreeCompactReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  unsigned long ErrorCode = 0;

private:
  vtkFoldingTreeCompactReader(const vtkFoldingTreeCompactReader&) = delete;
  void operator=(const vtkFoldingTreeCompactReader&) = delete;
};

#endif
