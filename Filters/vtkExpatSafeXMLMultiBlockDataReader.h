/**
 * @class   vtkExpatSafeXMLMultiBlockDataReader
 * @brief   vtkXMLMultiBlockDataReader that also reads appended-mode pieces on a current expat
 *
 * Reads a `.vtm` file like vtkXMLMultiBlockDataReader (a folding tree saved by
 * vtkXMLMultiBlockDataWriter, ParaView's Save Data or `foldingmeshes fold`), but its
 * `.vtp` pieces are read with vtkExpatSafeXMLPolyDataReader, so pieces in the writers'
 * default appended mode read back with Debian 12's current libexpat1 too (VTK issue
 * 19258; see vtkExpatSafeXMLDataParser). Pieces of other types are read as the
 * superclass reads them.
 *
 * Differences from the superclass, all for reading whole trees: every array of a `.vtp`
 * piece is read (the superclass's array selections are not offered: collecting them
 * means reading every piece's header with a stock reader); no composite meta-data is
 * announced in RequestInformation (for the same reason; pieces are still spread over the
 * processes of a parallel run as the superclass spreads them);
 * a `.vtp` piece that cannot be read is left out (a null block) with an error instead of
 * becoming an empty block.
 *
 * @sa vtkExpatSafeXMLPolyDataReader vtkXMLMultiBlockDataReader vtkFoldingTreeUnfolder
 */
#ifndef vtkExpatSafeXMLMultiBlockDataReader_h
#define vtkExpatSafeXMLMultiBlockDataReader_h

#include "FoldingMeshesFiltersModule.h" // for export macro
#include "vtkNew.h"                     // for vtkNew
#include "vtkXMLMultiBlockDataReader.h"

class vtkExpatSafeXMLPolyDataReader;

class FOLDINGMESHESFILTERS_EXPORT vtkExpatSafeXMLMultiBlockDataReader
  : public vtkXMLMultiBlockDataReader
{
public:
  static vtkExpatSafeXMLMultiBlockDataReader* New();
  vtkTypeMacro(vtkExpatSafeXMLMultiBlockDataReader, vtkXMLMultiBlockDataReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkExpatSafeXMLMultiBlockDataReader();
  ~vtkExpatSafeXMLMultiBlockDataReader() override;

  void CreateXMLParser() override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  vtkDataSet* ReadDataset(vtkXMLDataElement* xmlElem, const char* filePath) override;
  vtkDataObject* ReadDataObject(vtkXMLDataElement* xmlElem, const char* filePath) override;

private:
  vtkExpatSafeXMLMultiBlockDataReader(const vtkExpatSafeXMLMultiBlockDataReader&) = delete;
  void operator=(const vtkExpatSafeXMLMultiBlockDataReader&) = delete;

  vtkNew<vtkExpatSafeXMLPolyDataReader> PieceReader;
};

#endif
