#include "vtkFoldingTreeCompactReader.h"

#include "Core/CompactTreeFormat.h"
#include "vtkFoldingTreeIO.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>

#include <fstream>
#include <iterator>
#include <sstream>

vtkStandardNewMacro(vtkFoldingTreeCompactReader);

namespace
{
bool ReadBytes(const char* fileName, std::string& bytes, size_t limit = std::string::npos)
{
  std::ifstream file(fileName, std::ios::binary);
  if (!file)
    return false;
  if (limit == std::string::npos)
  {
    std::ostringstream all;
    all << file.rdbuf();
    bytes = all.str();
  }
  else
  {
    bytes.assign(limit, '\0');
    file.read(&bytes[0], static_cast<std::streamsize>(limit));
    bytes.resize(static_cast<size_t>(file.gcount()));
  }
  return true;
}

/// The user arrays of the file, added to the leaf blocks of `tree`.
bool AttachArrays(vtkMultiBlockDataSet* tree,
  const std::vector<foldingmeshes::CompactArray>& arrays,
  std::string& error)
{
  foldingmeshes::FoldingTree nodes;
  std::vector<vtkPolyData*> blocks;
  if (!foldingmeshes::MultiBlockToFoldingTree(tree, nodes, &blocks, error))
    return false;
  std::vector<vtkPolyData*> leaves;
  for (size_t i = 0; i < nodes.nodes.size(); ++i)
    if (nodes.nodes[i].kind == foldingmeshes::FoldingNodeKind::Leaf)
      leaves.push_back(blocks[i]);
  for (const foldingmeshes::CompactArray& a : arrays)
    for (size_t l = 0; l < leaves.size() && l < a.leaves.size(); ++l)
    {
      vtkSmartPointer<vtkDataArray> data =
        vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(a.dataType));
      if (!data || data->GetDataTypeSize() != a.elementSize)
      {
        error = "array '" + a.name + "' has a type this VTK cannot make";
        return false;
      }
      data->SetName(a.name.c_str());
      data->SetNumberOfComponents(a.components);
      data->SetNumberOfTuples(
        a.perTriangle ? leaves[l]->GetNumberOfCells() : leaves[l]->GetNumberOfPoints());
      if (static_cast<size_t>(data->GetNumberOfValues()) * a.elementSize != a.leaves[l].size())
      {
        error = "array '" + a.name + "' does not fit a leaf";
        return false;
      }
      std::copy(
        a.leaves[l].begin(), a.leaves[l].end(), static_cast<char*>(data->GetVoidPointer(0)));
      if (a.perTriangle)
        leaves[l]->GetCellData()->AddArray(data);
      else
        leaves[l]->GetPointData()->AddArray(data);
    }
  return true;
}
}

vtkFoldingTreeCompactReader::vtkFoldingTreeCompactReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkFoldingTreeCompactReader::~vtkFoldingTreeCompactReader()
{
  this->SetFileName(nullptr);
}

int vtkFoldingTreeCompactReader::CanReadFile(const char* fileName)
{
  std::string head;
  return fileName && ReadBytes(fileName, head, 4) && foldingmeshes::LooksLikeCompactTree(head) ? 1
                                                                                               : 0;
}

int vtkFoldingTreeCompactReader::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  this->ErrorCode = vtkErrorCode::NoError;
  vtkMultiBlockDataSet* output = vtkMultiBlockDataSet::GetData(outputVector, 0);
  output->Initialize();
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName given.");
    this->ErrorCode = vtkErrorCode::NoFileNameError;
    return 0;
  }
  std::string bytes;
  if (!ReadBytes(this->FileName, bytes))
  {
    vtkErrorMacro("Cannot open " << this->FileName << ".");
    this->ErrorCode = vtkErrorCode::CannotOpenFileError;
    return 0;
  }
  foldingmeshes::FoldingTree tree;
  std::string error;
  double quantizationError = 0.0;
  std::vector<foldingmeshes::CompactArray> arrays;
  if (!foldingmeshes::DecodeCompactTree(bytes, tree, error, &quantizationError, &arrays))
  {
    vtkErrorMacro(<< this->FileName << ": " << error << ".");
    this->ErrorCode = vtkErrorCode::FileFormatError;
    return 0;
  }
  if (!foldingmeshes::FoldingTreeToMultiBlock(tree, nullptr, output, error))
  {
    vtkErrorMacro(<< this->FileName << ": " << error << ".");
    this->ErrorCode = vtkErrorCode::FileFormatError;
    output->Initialize();
    return 0;
  }
  if (!arrays.empty() && !AttachArrays(output, arrays, error))
  {
    vtkErrorMacro(<< this->FileName << ": " << error << ".");
    this->ErrorCode = vtkErrorCode::FileFormatError;
    output->Initialize();
    return 0;
  }
  vtkDataObject* info = output->GetNumberOfBlocks() > 1 ? output->GetBlock(1) : nullptr;
  if (info)
  {
    vtkNew<vtkDoubleArray> q;
    q->SetName("QuantizationError");
    q->InsertNextValue(quantizationError);
    info->GetFieldData()->AddArray(q);
  }
  return 1;
}

void vtkFoldingTreeCompactReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ErrorCode: " << this->ErrorCode << "\n";
}
