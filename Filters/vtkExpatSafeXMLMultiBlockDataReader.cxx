#include "vtkExpatSafeXMLMultiBlockDataReader.h"

#include "vtkCommand.h"
#include "vtkDataArraySelection.h"
#include "vtkDataSet.h"
#include "vtkEventForwarderCommand.h"
#include "vtkExecutive.h"
#include "vtkExpatSafeXMLDataParser.h"
#include "vtkExpatSafeXMLPolyDataReader.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <string>

vtkStandardNewMacro(vtkExpatSafeXMLMultiBlockDataReader);

vtkExpatSafeXMLMultiBlockDataReader::vtkExpatSafeXMLMultiBlockDataReader() = default;
vtkExpatSafeXMLMultiBlockDataReader::~vtkExpatSafeXMLMultiBlockDataReader() = default;

void vtkExpatSafeXMLMultiBlockDataReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ExpatReparseDeferralSwitchedOff: "
     << (vtkExpatSafeXMLDataParser::ExpatHasReparseDeferral() ? "yes" : "no (expat has none)")
     << "\n";
}

void vtkExpatSafeXMLMultiBlockDataReader::CreateXMLParser()
{
  if (this->XMLParser)
  {
    this->DestroyXMLParser();
  }
  this->XMLParser = vtkExpatSafeXMLDataParser::New();
}

int vtkExpatSafeXMLMultiBlockDataReader::RequestInformation(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  // vtkXMLMultiBlockDataReader::RequestInformation would fill the composite meta-data and
  // the array selections by reading each piece's header with a stock vtkXMLPolyDataReader,
  // which fails on appended pieces: skip to vtkXMLCompositeDataReader's (the .vtm itself).
  return this->vtkXMLCompositeDataReader::RequestInformation(request, inputVector, outputVector);
}

vtkDataSet* vtkExpatSafeXMLMultiBlockDataReader::ReadDataset(vtkXMLDataElement* xmlElem,
  const char* filePath)
{
  return vtkDataSet::SafeDownCast(this->ReadDataObject(xmlElem, filePath));
}

vtkDataObject* vtkExpatSafeXMLMultiBlockDataReader::ReadDataObject(vtkXMLDataElement* xmlElem,
  const char* filePath)
{
  const std::string fileName = this->GetFileNameFromXML(xmlElem, filePath);
  const std::string extension = ".vtp";
  const bool isPolyData = fileName.size() > extension.size() &&
    fileName.compare(fileName.size() - extension.size(), extension.size(), extension) == 0;
  if (!isPolyData)
  {
    return this->Superclass::ReadDataObject(xmlElem, filePath);
  }
  // As vtkXMLCompositeDataReader::ReadDataObject, with the expat-safe piece reader; in
  // addition a piece that fails to read is left out (nullptr) with an error, instead of
  // becoming an empty block.
  vtkExpatSafeXMLPolyDataReader* reader = this->PieceReader;
  if (this->HasObserver(vtkCommand::ErrorEvent) && !reader->HasObserver(vtkCommand::ErrorEvent))
  {
    vtkNew<vtkEventForwarderCommand> forward; // the piece's own message reaches our observers
    forward->SetTarget(this);
    reader->AddObserver(vtkCommand::ErrorEvent, forward);
  }
  reader->SetFileName(fileName.c_str());
  // Every array: the piece reader's own selection, filled from the piece's header.
  reader->GetPointDataArraySelection()->RemoveAllArrays();
  reader->GetCellDataArraySelection()->RemoveAllArrays();
  const int status = reader->GetExecutive()->Update();
  vtkPolyData* output = reader->GetOutput();
  if (!status || !output)
  {
    vtkErrorMacro("Could not read the piece " << fileName);
    return nullptr;
  }
  vtkPolyData* copy = vtkPolyData::New();
  copy->ShallowCopy(output);
  return copy;
}
