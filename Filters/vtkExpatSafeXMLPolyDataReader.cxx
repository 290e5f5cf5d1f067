#include "vtkExpatSafeXMLPolyDataReader.h"

#include "vtkExpatSafeXMLDataParser.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkExpatSafeXMLPolyDataReader);

bool vtkExpatSafeXMLPolyDataReader::ExpatHasReparseDeferral()
{
  return vtkExpatSafeXMLDataParser::ExpatHasReparseDeferral();
}

void vtkExpatSafeXMLPolyDataReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ExpatReparseDeferralSwitchedOff: "
     << (vtkExpatSafeXMLDataParser::ExpatHasReparseDeferral() ? "yes" : "no (expat has none)")
     << "\n";
}

void vtkExpatSafeXMLPolyDataReader::CreateXMLParser()
{
  // As vtkXMLReader::CreateXMLParser, with the deferral-free parser.
  if (this->XMLParser)
  {
    this->DestroyXMLParser();
  }
  this->XMLParser = vtkExpatSafeXMLDataParser::New();
}
