#include "vtkFoldingTreeCompactWriter.h"

#include "Core/CompactTreeFormat.h"
#include "vtkFoldingTreeIO.h"

#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"

#include <fstream>

vtkStandardNewMacro(vtkFoldingTreeCompactWriter);

vtkFoldingTreeCompactWriter::vtkFoldingTreeCompactWriter() = default;

vtkFoldingTreeCompactWriter::~vtkFoldingTreeCompactWriter()
{
  this->SetFileName(nullptr);
}

int vtkFoldingTreeCompactWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  return 1;
}

void vtkFoldingTreeCompactWriter::WriteData()
{
  this->BytesWritten = 0;
  this->QuantizationBitsUsed = 0;
  this->QuantizationError = 0.0;
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
  if (!input || !foldingmeshes::MultiBlockToFoldingTree(input, tree, error))
  {
    vtkErrorMacro("The input is not a folding tree: " << (input ? error : "no input") << ".");
    this->SetErrorCode(vtkErrorCode::UnknownError);
    return;
  }
  foldingmeshes::CompactTreeOptions options;
  options.quantizationBits = this->QuantizationBits;
  foldingmeshes::CompactTreeStats stats;
  std::string bytes;
  if (!foldingmeshes::EncodeCompactTree(tree, options, bytes, &stats, error))
  {
    vtkErrorMacro("Cannot encode the tree: " << error << ".");
    this->SetErrorCode(vtkErrorCode::UnknownError);
    return;
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
  os << indent << "WriteToOutputString: " << this->WriteToOutputString << "\n";
  os << indent << "BytesWritten: " << this->BytesWritten << "\n";
  os << indent << "QuantizationBitsUsed: " << this->QuantizationBitsUsed << "\n";
  os << indent << "QuantizationError: " << this->QuantizationError << "\n";
}
