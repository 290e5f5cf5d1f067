#include "vtkExpatSafeXMLDataParser.h"

#include "vtkObjectFactory.h"

#include <dlfcn.h>

vtkStandardNewMacro(vtkExpatSafeXMLDataParser);

namespace
{
// XML_Bool XML_SetReparseDeferralEnabled(XML_Parser parser, XML_Bool enabled), expat >= 2.6
// and Debian's backport; XML_Parser is a pointer and XML_Bool an unsigned char.
using SetReparseDeferralEnabled = unsigned char (*)(void*, unsigned char);

SetReparseDeferralEnabled LookUp()
{
  // The expat that VTK's XML parser uses is already loaded (a dependency of VTK's
  // IOXMLParser library, which this module links). A VTK built with its own copy of
  // expat mangles the names with a vtkexpat_ prefix: then that copy's function is the
  // one to call (another expat in the process, e.g. Python's, must not touch its parser).
  const bool bundled = dlsym(RTLD_DEFAULT, "vtkexpat_XML_ParserCreate") != nullptr;
  return reinterpret_cast<SetReparseDeferralEnabled>(dlsym(RTLD_DEFAULT,
    bundled ? "vtkexpat_XML_SetReparseDeferralEnabled" : "XML_SetReparseDeferralEnabled"));
}

SetReparseDeferralEnabled FindSetReparseDeferralEnabled()
{
  static const SetReparseDeferralEnabled function = LookUp();
  return function;
}
}

bool vtkExpatSafeXMLDataParser::ExpatHasReparseDeferral()
{
  return FindSetReparseDeferralEnabled() != nullptr;
}

int vtkExpatSafeXMLDataParser::CreateParser()
{
  if (!this->Superclass::CreateParser())
  {
    return 0;
  }
  if (SetReparseDeferralEnabled setEnabled = FindSetReparseDeferralEnabled())
  {
    setEnabled(this->Parser, 0);
  }
  return 1;
}
