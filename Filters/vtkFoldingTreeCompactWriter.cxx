#include "vtkFoldingTreeCompactWriter.h"

#include "Core/CompactTreeFormat.h"
#include "Core/CompactTreeProof.h"
#include "Core/FoldingTreeVerification.h"
#include "vtkFoldingTreeIO.h"
#include "vtkTriangleMeshAdapter.h"

#include "vtkFoldingArrays.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>

#include <fstream>

vtkStandardNewMacro(vtkFoldingTreeCompactWriter);

namespace
{
/// The leaves' user arrays (vtkFoldingArrays.h: CommonLeafArrays), numeric ones, as raw values.
std::vector<foldingmeshes::CompactArray> UserArrays(const foldingmeshes::FoldingTree& tree,
  const std::vector<vtkPolyData*>& blocks)
{
  std::vector<vtkPolyData*> leaves;
  for (size_t i = 0; i < tree.nodes.size(); ++i)
    if (tree.nodes[i].kind == foldingmeshes::FoldingNodeKind::Leaf)
      leaves.push_back(i < blocks.size() ? blocks[i] : nullptr);
  std::vector<foldingmeshes::CompactArray> arrays;
  if (std::find(leaves.begin(), leaves.end(), nullptr) != leaves.end())
    return arrays;
  for (const bool points : { true, false })
  {
    int unnamed = 0;
    for (const std::string& name : foldingmeshes::CommonLeafArrays(leaves, points, unnamed))
    {
      foldingmeshes::CompactArray a;
      a.name = name;
      a.perTriangle = !points;
      bool numeric = true;
      for (vtkPolyData* leaf : leaves)
      {
        vtkDataSetAttributes* dsa = points
          ? static_cast<vtkDataSetAttributes*>(leaf->GetPointData())
          : static_cast<vtkDataSetAttributes*>(leaf->GetCellData());
        vtkDataArray* data = vtkDataArray::SafeDownCast(dsa->GetAbstractArray(name.c_str()));
        if (!data || data->GetDataTypeSize() < 1 || data->GetDataTypeSize() > 8 ||
          (!data->HasStandardMemoryLayout()))
        {
          numeric = false;
          break;
        }
        a.dataType = data->GetDataType();
        a.components = data->GetNumberOfComponents();
        a.elementSize = data->GetDataTypeSize();
        const size_t bytes = static_cast<size_t>(data->GetNumberOfValues()) * a.elementSize;
        a.leaves.emplace_back(static_cast<const char*>(data->GetVoidPointer(0)), bytes);
      }
      if (numeric)
        arrays.push_back(std::move(a));
    }
  }
  return arrays;
}
}

namespace
{
/// The bits added per encoding not proved.
constexpr int ProofBitStep = 2;
}

vtkFoldingTreeCompactWriter::vtkFoldingTreeCompactWriter()
{
  this->SetNumberOfInputPorts(2);
}

vtkFoldingTreeCompactWriter::~vtkFoldingTreeCompactWriter()
{
  this->SetFileName(nullptr);
}

int vtkFoldingTreeCompactWriter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1) // the original mesh (SetOriginalData)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  return 1;
}

void vtkFoldingTreeCompactWriter::WriteData()
{
  this->BytesWritten = 0;
  this->QuantizationBitsUsed = 0;
  this->QuantizationError = 0.0;
  this->ProvedBound = -1.0;
  this->ProofRetries = 0;
  this->OpenEdgesBack = -1;
  this->Proved = false;
  this->OutputString.clear();
  vtkMultiBlockDataSet* input = vtkMultiBlockDataSet::SafeDownCast(this->GetInputDataObject(0, 0));
  if (!this->WriteToOutputString && (!this->FileName || !*this->FileName))
  {
    vtkErrorMacro("No FileName given.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  foldingmeshes::FoldingTree tree;
  std::string error;
  std::vector<vtkPolyData*> leafBlocks;
  if (!input || !foldingmeshes::MultiBlockToFoldingTree(input, tree, &leafBlocks, error))
  {
    vtkErrorMacro("The input is not a folding tree: " << (input ? error : "no input") << ".");
    this->SetErrorCode(vtkErrorCode::UnknownError);
    return;
  }
  foldingmeshes::CompactTreeOptions options;
  options.quantizationBits = this->QuantizationBits;
  // Given the mesh, the file is proved against it below and written with more bits where it
  // is not within epsilon: the segmentation seams' rule is left to the proof.
  options.segmentationSeamBits = this->GetNumberOfInputConnections(1) == 0;
  foldingmeshes::CompactTreeStats stats;
  std::string bytes;
  const std::vector<foldingmeshes::CompactArray> arrays = this->StoreUserArrays
    ? UserArrays(tree, leafBlocks)
    : std::vector<foldingmeshes::CompactArray>();
  if (!foldingmeshes::EncodeCompactTree(tree, options, bytes, &stats, error, &arrays))
  {
    vtkErrorMacro("Cannot encode the tree: " << error << ".");
    this->SetErrorCode(vtkErrorCode::UnknownError);
    return;
  }
  // The file proved against the original, with more bits while it is not within epsilon.
  if (this->GetNumberOfInputConnections(1) > 0)
  {
    // The original read as the builder reads its input (triangulated, checked).
    foldingmeshes::TriangleMesh original;
    std::vector<foldingmeshes::Vec3> normals;
    vtkIdType droppedVerts = 0, droppedLines = 0;
    std::string why;
    if (!foldingmeshes::SurfaceInput(vtkPolyData::SafeDownCast(this->GetInputDataObject(1, 0)),
          "the file cannot be proved against it",
          original,
          normals,
          droppedVerts,
          droppedLines,
          why))
    {
      vtkErrorMacro("The original (input port 1): " << why);
      this->SetErrorCode(vtkErrorCode::UnknownError);
      return;
    }
    const double tolerance = foldingmeshes::ProofToleranceOfDiagonal * tree.diagonal;
    // A closed original comes back closed (as the builder's proof of its tree asks).
    const bool closed = foldingmeshes::WeldedOpenEdges(original) == 0;
    bool proved = false;
    for (;;)
    {
      const foldingmeshes::CompactFileProof proof =
        foldingmeshes::ProveCompactFile(bytes, original, tolerance, tree.rootEpsilon);
      this->ProvedBound = proof.bound;
      this->OpenEdgesBack = proof.openEdges;
      proved = proof.bound <= tree.rootEpsilon + tolerance && (!closed || proof.openEdges == 0);
      if (proved || this->QuantizationBits != 0 ||
        stats.quantizationBits >= foldingmeshes::MaximumQuantizationBits)
        break;
      options.quantizationBits =
        std::min(foldingmeshes::MaximumQuantizationBits, stats.quantizationBits + ProofBitStep);
      if (!foldingmeshes::EncodeCompactTree(tree, options, bytes, &stats, error, &arrays))
      {
        vtkErrorMacro("Cannot encode the tree: " << error << ".");
        this->SetErrorCode(vtkErrorCode::UnknownError);
        return;
      }
      ++this->ProofRetries;
    }
    this->Proved = proved;
    if (!proved) // (a NaN or infinite bound too)
      vtkWarningMacro("The file decompresses "
        << this->ProvedBound << " from the original" << (closed ? ", which is closed, with " : " (")
        << this->OpenEdgesBack << " open edges" << (closed ? "" : ")")
        << ": not proved within the root epsilon " << tree.rootEpsilon << ".");
  }
  if (this->WriteToOutputString)
    this->OutputString = bytes;
  else
  {
    std::ofstream file(this->FileName, std::ios::binary);
    if (!file || !file.write(bytes.data(), static_cast<std::streamsize>(bytes.size())) ||
      !file.flush())
    {
      vtkErrorMacro("Cannot write " << this->FileName << ".");
      this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
      return;
    }
  }
  this->BytesWritten = static_cast<vtkIdType>(bytes.size());
  this->QuantizationBitsUsed = stats.quantizationBits;
  this->QuantizationError = stats.quantizationError;
}

void vtkFoldingTreeCompactWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "QuantizationBits: " << this->QuantizationBits << "\n";
  os << indent << "StoreUserArrays: " << this->StoreUserArrays << "\n";
  os << indent << "WriteToOutputString: " << this->WriteToOutputString << "\n";
  os << indent << "BytesWritten: " << this->BytesWritten << "\n";
  os << indent << "QuantizationBitsUsed: " << this->QuantizationBitsUsed << "\n";
  os << indent << "QuantizationError: " << this->QuantizationError << "\n";
  os << indent << "ProvedBound: " << this->ProvedBound << "\n";
  os << indent << "ProofRetries: " << this->ProofRetries << "\n";
  os << indent << "OpenEdgesBack: " << this->OpenEdgesBack << "\n";
  os << indent << "Proved: " << this->Proved << "\n";
}
