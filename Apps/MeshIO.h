/**
 * @file    MeshIO.h
 * @brief   reads and writes surface meshes by file extension (FoldingMeshes apps)
 *
 * Extensions are case-insensitive. Reading: .vtp (XML poly data, also appended-mode files
 * on Debian 12's current expat: vtkExpatSafeXMLPolyDataReader), .vtk (legacy;
 * other legacy datasets are reduced to their surface), .ply, .obj, .stl and .off
 * (vtkOFFReader). Writing: .vtp (inline binary, zlib), .vtk (legacy binary),
 * .ply (binary; a point array "Colors" is written as vertex colours), .stl
 * (binary) and .obj. VTK errors and warnings raised while reading or writing
 * are not printed: they are captured, and explain a failure in `error`.
 */
#ifndef foldingmeshes_MeshIO_h
#define foldingmeshes_MeshIO_h

#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

namespace foldingmeshes
{
/**
 * Reads the mesh at `path`. Returns nullptr and sets `error` (e.g. "cannot read
 * 'x': no such file") when the file is missing, its extension is unsupported,
 * the reader fails or the mesh has no points or no cells.
 */
vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path, std::string& error);

/**
 * The mesh files (.off .obj .ply .vtp .stl) directly in the folder `path`, sorted; `path`
 * itself when it is not a folder (for benchmark command lines: folders and files mixed).
 */
std::vector<std::string> MeshFiles(const std::string& path);

/** Writes `mesh` to `path`. Returns false and sets `error` on failure. */
bool WriteMesh(vtkPolyData* mesh, const std::string& path, std::string& error);
}

#endif
