/**
 * @class   vtkOFFReader
 * @brief   reads Geomview OFF polygon files (OFF, COFF, NOFF, CNOFF)
 *
 * vtkOFFReader reads the ASCII Object File Format of Geomview, the usual
 * exchange format of geometry-processing benchmarks (Princeton, CGAL, ...):
 *
 * @code
 * [C][N]OFF [nv nf ne]   # keyword; the counts may also come on the next line
 * x y z [nx ny nz] [r g b [a]]                        # nv vertex lines
 * n i0 i1 ... i(n-1) [r g b [a]]                      # nf face lines
 * @endcode
 *
 * - `COFF`: vertex colours become the point array "Colors" (unsigned char,
 *   3 or 4 components as on the first vertex line, also the active scalars).
 *   If every colour value of the file is at most 1, the values are taken as
 *   floats in [0,1] and scaled by 255; otherwise as integers in 0..255.
 * - `NOFF`: vertex normals become the point normals "Normals".
 * - Faces of any size are stored as polygons, not triangulated (faces with
 *   1 or 2 vertices become verts/lines). Face colours and the edge count are
 *   ignored, and so are extra values at the end of a vertex line.
 * - `#` comments and blank lines may appear anywhere. Each vertex and face
 *   must be on one line.
 *
 * Points are single precision. Numbers are parsed with strtod/strtol (the C
 * locale's decimal point is expected). Binary OFF and the 4OFF/nOFF/STOFF
 * variants are not supported.
 *
 * Errors (missing file, bad header, a number that does not parse or is not
 * finite, a face index out of range, a truncated file) are reported with
 * vtkErrorMacro as "file:line: message", the ErrorCode is set and the request
 * fails with an empty output.
 *
 * @sa
 * vtkPLYReader vtkOBJReader vtkSTLReader
 */
#ifndef vtkOFFReader_h
#define vtkOFFReader_h

#include "FoldingMeshesFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class FOLDINGMESHESFILTERS_EXPORT vtkOFFReader : public vtkPolyDataAlgorithm
{
public:
  static vtkOFFReader* New();
  vtkTypeMacro(vtkOFFReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Name of the OFF file to read. */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /**
   * Returns 1 if the first keyword of the file (after comments and blank
   * lines) is OFF, COFF, NOFF or CNOFF, else 0.
   */
  static int CanReadFile(const char* fname);

protected:
  vtkOFFReader();
  ~vtkOFFReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;

private:
  vtkOFFReader(const vtkOFFReader&) = delete;
  void operator=(const vtkOFFReader&) = delete;
};

#endif
