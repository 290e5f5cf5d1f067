/**
 * @class   vtkExpatSafeXMLDataParser
 * @brief   vtkXMLDataParser that switches off expat's reparse deferral
 *
 * Expat 2.6 (and Debian 12's libexpat1 from 2.5.0-1+deb12u2 on, where it was backported)
 * defers the parsing of a partial token until "enough" new bytes have arrived. VTK's XML
 * readers up to 9.2 (ParaView 5.11) stop feeding the parser at `<AppendedData` and end the
 * document by hand; with the deferral the closing tags are never processed, the reader
 * keeps feeding the appended binary data and fails ("junk after document element",
 * "not well-formed (invalid token)"). VTK issue 19258; upstream VTK switches the deferral
 * off in vtkXMLParser. This parser does the same for the readers built on it
 * (vtkExpatSafeXMLPolyDataReader, vtkExpatSafeXMLMultiBlockDataReader).
 *
 * XML_SetReparseDeferralEnabled() is looked up at run time, so the same binary works
 * with an expat that lacks it (nothing to switch off there). Private to the module.
 */
#ifndef vtkExpatSafeXMLDataParser_h
#define vtkExpatSafeXMLDataParser_h

#include "vtkXMLDataParser.h"

class vtkExpatSafeXMLDataParser : public vtkXMLDataParser
{
public:
  static vtkExpatSafeXMLDataParser* New();
  vtkTypeMacro(vtkExpatSafeXMLDataParser, vtkXMLDataParser);

  /**
   * True when the running expat has reparse deferral (and this parser switches it off),
   * false when it has none (older expat: nothing to do).
   */
  static bool ExpatHasReparseDeferral();

protected:
  vtkExpatSafeXMLDataParser() = default;
  ~vtkExpatSafeXMLDataParser() override = default;

  // Creates the expat parser (as vtkXMLParser does), then switches its deferral off.
  int CreateParser() override;

private:
  vtkExpatSafeXMLDataParser(const vtkExpatSafeXMLDataParser&) = delete;
  void operator=(const vtkExpatSafeXMLDataParser&) = delete;
};

#endif
