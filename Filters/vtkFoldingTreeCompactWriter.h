/**
 * @class   vtkFoldingTreeCompactWriter
 * @brief   writes a folding tree as a compact .fmz file (Draco-coded leaves)
 *
 * Takes the tree of vtkFoldingTreeBuilder (or a .vtm tree read back) and writes only what
 * vtkFoldingTreeUnfolder needs: the nodes, their planes and epsilons, the leaves' points and
 * triangles (coded with Draco), the per-point tear / fold-line flags, projected and input-border
 * flags and error budgets, and the mirrored-flag records. Positions are quantised on a grid of
 * QuantizationBits bits over the stored points' bounding box; the quantisation error is
 * subtracted from every point's error budget. That does not by itself keep the file's unfold
 * within the root epsilon (some unfolder steps do not answer to the budgets when positions
 * move); given the mesh folded (SetOriginalData) the writer proves it, with more bits where
 * needed. The layout is documented in Core/CompactTreeFormat.h. Read it with
 * vtkFoldingTreeCompactReader.
 *
 * What the user gives up against the .vtm: user point and cell arrays unless StoreUserArrays is
 * on, the input ids of stored points and faces (the unfolded mesh's OriginalPointId /
 * OriginalFaceId are running numbers), the nodes' face lists and detection statistics, the
 * input's field data and active-attribute records, and the input's border / non-manifold edge
 * lists (the unfolder then relies on the points' input-border flags alone).
 *
 * An invalid tree or a file that cannot be written is reported with vtkErrorMacro and the
 * writer's ErrorCode; nothing is written.
 *
 * @sa vtkFoldingTreeCompactReader vtkFoldingTreeBuilder vtkFoldingTreeUnfolder
 */
#ifndef vtkFoldingTreeCompactWriter_h
#define vtkFoldingTreeCompactWriter_h

#include "FoldingMeshesFiltersModule.h" // for export macro
#include "vtkWriter.h"

#include <string> // for the output string

class FOLDINGMESHESFILTERS_EXPORT vtkFoldingTreeCompactWriter : public vtkWriter
{
public:
  static vtkFoldingTreeCompactWriter* New();
  vtkTypeMacro(vtkFoldingTreeCompactWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Name of the .fmz file to write. */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * Position quantisation bits per coordinate (6..24), or 0 (the default): automatic - the
   * fewest bits (at least 8) whose quantisation error is at most half of the smallest error
   * budget of a stored point (1% of the root epsilon for trees without budgets) and, in trees
   * with rotation nodes, at most the stitch tolerance of their seams; without an original
   * (SetOriginalData) also at most half the epsilon of every segmentation node with seams, as
   * nothing proves the file then (docs/compression.md).
   */
  vtkSetClampMacro(QuantizationBits, int, 0, 24);
  vtkGetMacro(QuantizationBits, int);
  ///@}

  ///@{
  /**
   * Also store the leaves' user point and cell arrays (those present in every leaf, numeric),
   * losslessly, so that they survive unfolding as from a .vtm. Default off: the arrays are
   * stored raw (zlib) and the geometry is then coded in the leaves' order (Draco's sequential
   * coding), both larger.
   */
  vtkSetMacro(StoreUserArrays, bool);
  vtkGetMacro(StoreUserArrays, bool);
  vtkBooleanMacro(StoreUserArrays, bool);
  ///@}

  ///@{
  /** Write to OutputString instead of FileName (for Python and tests). Default off. */
  vtkSetMacro(WriteToOutputString, bool);
  vtkGetMacro(WriteToOutputString, bool);
  vtkBooleanMacro(WriteToOutputString, bool);
  ///@}
  /** The bytes written by the last Write() when WriteToOutputString is on. */
  const std::string& GetOutputString() const { return this->OutputString; }

  ///@{
  /**
   * The mesh the tree was folded from (optional, input port 1). With it the file is
   * decompressed (decoded, unfolded with the default options) and its distance to this mesh
   * proved over every point of both surfaces (ProvedBound), and a closed original must come
   * back closed (OpenEdgesBack); with automatic bits, while either fails the tree is written
   * again with two more bits, up to 24
   * (ProofRetries): a compact file's quantisation can move the unfolded surface farther than
   * the error budgets account for (the moved bearing at 8 bits: 1.02 epsilon;
   * docs/limitations.md). Without it the file is not proved (ProvedBound -1).
   */
  void SetOriginalData(vtkDataObject* mesh) { this->SetInputData(1, mesh); }
  void SetOriginalConnection(vtkAlgorithmOutput* port) { this->SetInputConnection(1, port); }
  ///@}

  ///@{
  /**
   * Results of the last Write(): file size, bits used, largest quantisation move (a length),
   * the proved distance of the decompressed file (unfolded with the default options) to the
   * original (a length, decided against the root epsilon: proved within it when at most
   * epsilon + 1e-7 of the diagonal, not the tightest bound; a bound not converged counts as not
   * within; infinite: the file did not unfold; -1: no original), the encodings added, and the
   * open edges of the file's unfold (points at identical positions counted as one; -1: not
   * proved) - a closed original must come back with none to be proved.
   */
  vtkGetMacro(BytesWritten, vtkIdType);
  vtkGetMacro(QuantizationBitsUsed, int);
  vtkGetMacro(QuantizationError, double);
  vtkGetMacro(ProvedBound, double);
  vtkGetMacro(ProofRetries, int);
  vtkGetMacro(OpenEdgesBack, int);
  /** Whether the last Write() proved its file (within epsilon and, the original closed, closed). */
  vtkGetMacro(Proved, bool);
  ///@}

protected:
  vtkFoldingTreeCompactWriter();
  ~vtkFoldingTreeCompactWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  char* FileName = nullptr;
  int QuantizationBits = 0;
  bool StoreUserArrays = false;
  bool WriteToOutputString = false;
  std::string OutputString;
  vtkIdType BytesWritten = 0;
  int QuantizationBitsUsed = 0;
  double QuantizationError = 0.0;
  double ProvedBound = -1.0;
  int ProofRetries = 0;
  int OpenEdgesBack = -1;
  bool Proved = false;

private:
  vtkFoldingTreeCompactWriter(const vtkFoldingTreeCompactWriter&) = delete;
  void operator=(const vtkFoldingTreeCompactWriter&) = delete;
};

#endif
