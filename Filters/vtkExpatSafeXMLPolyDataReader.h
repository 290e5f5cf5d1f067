/**
 * @class   vtkExpatSafeXMLPolyDataReader
 * @brief   vtkXMLPolyDataReader that also reads appended-mode files on a current expat
 *
 * The same reader as vtkXMLPolyDataReader, with one difference: its XML parser switches
 * off expat's reparse deferral (vtkExpatSafeXMLDataParser). With Debian 12's current
 * libexpat1 (2.5.0-1+deb12u2 and later, expat >= 2.6 elsewhere) the XML readers of
 * VTK <= 9.2 (ParaView 5.11) cannot read `.vtp` files whose data is in the writers'
 * default appended mode (VTK issue 19258); this one can. Files with inline binary or
 * ASCII data read the same with either reader.
 *
 * @sa vtkExpatSafeXMLMultiBlockDataReader vtkXMLPolyDataReader
 */
#ifndef vtkExpatSafeXMLPolyDataReader_h
#define vtkExpatSafeXMLPolyDataReader_h

#include "FoldingMeshesFiltersModule.h" // for export macro
#include "vtkXMLPolyDataReader.h"

class FOLDINGMESHESFILTERS_EXPORT vtkExpatSafeXMLPolyDataReader : public vtkXMLPolyDataReader
{
public:
  static vtkExpatSafeXMLPolyDataReader* New();
  vtkTypeMacro(vtkExpatSafeXMLPolyDataReader, vtkXMLPolyDataReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * True when the expat this process runs has reparse deferral (the readers switch it
   * off), false when it has none (nothing to do: VTK's own readers work as well).
   */
  static bool ExpatHasReparseDeferral();

protected:
  vtkExpatSafeXMLPolyDataReader() = default;
  ~vtkExpatSafeXMLPolyDataReader() override = default;

  void CreateXMLParser() override;

private:
  vtkExpatSafeXMLPolyDataReader(const vtkExpatSafeXMLPolyDataReader&) = delete;
  void operator=(const vtkExpatSafeXMLPolyDataReader&) = delete;
};

#endif
