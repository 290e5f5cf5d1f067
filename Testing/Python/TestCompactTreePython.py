#!/usr/bin/env python3
"""TestCompactTreePython: the compact folding tree (.fmz) from Python.

A sphere folded by foldingmeshes.vtkFoldingTreeBuilder is written with
vtkFoldingTreeCompactWriter (smaller than the .vtm of the same tree, the bits and quantisation
error reported), read back with vtkFoldingTreeCompactReader (QuantizationError in the "Tree"
block) and unfolded: the same number of stored triangles, the unfolded mesh within the root
epsilon of the sphere (vtkFoldingTreeUnfolder's proved HausdorffToOriginalBound). Given the
sphere (SetOriginalData) the writer proves its file within the root epsilon and closed with no
bits added;
given the sphere moved by three epsilons it raises the bits to 24 and reports the bound it
could not prove; without one it proves nothing. User arrays
come back (exactly in the leaves) only with StoreUserArrays. A file that is not a .fmz gives an
error and an empty output.

Run with /usr/bin/python3 and PYTHONPATH=<build>/lib/python3/dist-packages:
    TestCompactTreePython.py TEMP_DIR
"""

import os
import sys

from vtkmodules.vtkFiltersCore import vtkElevationFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource
try:
    from vtkmodules.vtkFiltersCore import vtkGenerateIds
except ImportError:  # VTK < 9.3
    from vtkmodules.vtkFiltersCore import vtkIdFilter as vtkGenerateIds
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter

from foldingmeshes import (vtkExpatSafeXMLMultiBlockDataReader, vtkFoldingTreeBuilder, vtkFoldingTreeCompactReader,
                           vtkFoldingTreeCompactWriter, vtkFoldingTreeUnfolder)

failures = []


def check(condition, message):
    print(("ok:   " if condition else "FAIL: ") + message)
    if not condition:
        failures.append(message)


def leaves_of(tree):
    """The non-empty vtkPolyData blocks of a tree, in traversal order."""
    iterator = tree.NewTreeIterator()
    iterator.InitTraversal()
    blocks = []
    while not iterator.IsDoneWithTraversal():
        data = iterator.GetCurrentDataObject()
        if data is not None and data.IsA("vtkPolyData") and data.GetNumberOfCells() > 0:
            blocks.append(data)
        iterator.GoToNextItem()
    return blocks


def field(data, name):
    array = data.GetFieldData().GetArray(name)
    return array.GetTuple1(0) if array is not None else None


def main(temp_dir):
    os.makedirs(temp_dir, exist_ok=True)
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(40)
    sphere.SetPhiResolution(30)
    builder = vtkFoldingTreeBuilder()
    builder.SetInputConnection(sphere.GetOutputPort())
    builder.Update()
    check(builder.GetStoredFaces() < builder.GetOriginalFaces(), "the sphere folds")

    fmz = os.path.join(temp_dir, "TestCompactTreePython.fmz")
    writer = vtkFoldingTreeCompactWriter()
    writer.SetInputConnection(builder.GetOutputPort(0))
    writer.SetFileName(fmz)
    check(writer.Write() == 1 and os.path.isfile(fmz), "wrote " + fmz)
    check(writer.GetBytesWritten() == os.path.getsize(fmz), "BytesWritten is the file size")
    check(8 <= writer.GetQuantizationBitsUsed() <= 24 and writer.GetQuantizationError() > 0,
          "automatic quantisation: %d bits, error %g" % (writer.GetQuantizationBitsUsed(),
                                                          writer.GetQuantizationError()))
    check(writer.GetProvedBound() == -1 and writer.GetProofRetries() == 0,
          "no original mesh: the file is not proved (ProvedBound %g)" % writer.GetProvedBound())

    # The proof against the mesh folded (SetOriginalData): the file decompressed and proved
    # within the root epsilon, no bits added; against the sphere moved by three epsilons it
    # cannot be: two more bits per encoding up to 24, a file still written, a warning.
    root_epsilon = field(builder.GetOutputDataObject(0).GetBlock(1), "RootEpsilon")
    proved = vtkFoldingTreeCompactWriter()
    proved.SetInputConnection(builder.GetOutputPort(0))
    proved.SetOriginalConnection(sphere.GetOutputPort())
    proved.WriteToOutputStringOn()
    proved.Write()
    diagonal = field(builder.GetOutputDataObject(0).GetBlock(1), "Diagonal")
    check(0 <= proved.GetProvedBound() <= root_epsilon + 1e-7 * diagonal and
          proved.GetProofRetries() == 0 and proved.GetOpenEdgesBack() == 0 and
          proved.GetProved() and
          proved.GetBytesWritten() == os.path.getsize(fmz) and
          proved.GetQuantizationBitsUsed() == writer.GetQuantizationBitsUsed(),
          "proved against the sphere: %g (epsilon %g), the same bytes, %d encodings added" %
          (proved.GetProvedBound(), root_epsilon, proved.GetProofRetries()))
    shift = vtkTransform()
    shift.Translate(3.0 * root_epsilon, 0.0, 0.0)
    moved = vtkTransformPolyDataFilter()
    moved.SetInputConnection(sphere.GetOutputPort())
    moved.SetTransform(shift)
    wrong = vtkFoldingTreeCompactWriter()
    wrong.SetInputConnection(builder.GetOutputPort(0))
    wrong.SetOriginalConnection(moved.GetOutputPort())
    wrong.WriteToOutputStringOn()
    warnings = []
    wrong.AddObserver("WarningEvent", lambda caller, event: warnings.append(event))
    wrong.Write()
    first_bits = writer.GetQuantizationBitsUsed()
    check(wrong.GetProvedBound() > root_epsilon and wrong.GetQuantizationBitsUsed() == 24 and
          wrong.GetProofRetries() == (24 - first_bits + 1) // 2 and wrong.GetBytesWritten() > 0
          and len(warnings) == 1 and not wrong.GetProved(),
          "not proved against a moved sphere: %g, %d bits after %d encodings added (from %d), "
          "%d warning" % (wrong.GetProvedBound(), wrong.GetQuantizationBitsUsed(),
                          wrong.GetProofRetries(), first_bits, len(warnings)))

    vtm = os.path.join(temp_dir, "TestCompactTreePython.vtm")
    vtm_writer = vtkXMLMultiBlockDataWriter()
    vtm_writer.SetInputConnection(builder.GetOutputPort(0))
    vtm_writer.SetDataModeToBinary()
    vtm_writer.SetFileName(vtm)
    vtm_writer.Write()
    vtm_bytes = os.path.getsize(vtm) + sum(
        os.path.getsize(os.path.join(d, f)) for d, _, files in
        os.walk(os.path.join(temp_dir, "TestCompactTreePython")) for f in files)
    check(os.path.getsize(fmz) * 5 < vtm_bytes,
          ".fmz %d bytes, the .vtm tree %d" % (os.path.getsize(fmz), vtm_bytes))

    # .vtm -> .fmz: the tree read back from the .vtm gives the same bytes.
    vtm_reader = vtkExpatSafeXMLMultiBlockDataReader()
    vtm_reader.SetFileName(vtm)
    from_vtm = vtkFoldingTreeCompactWriter()
    from_vtm.SetInputConnection(vtm_reader.GetOutputPort())
    from_vtm.WriteToOutputStringOn()
    from_vtm.Write()
    check(from_vtm.GetBytesWritten() == os.path.getsize(fmz),
          ".vtm -> .fmz: %d bytes, as from the builder" % from_vtm.GetBytesWritten())

    reader = vtkFoldingTreeCompactReader()
    check(vtkFoldingTreeCompactReader.CanReadFile(fmz) == 1, "CanReadFile(.fmz)")
    check(vtkFoldingTreeCompactReader.CanReadFile(vtm) == 0, "not CanReadFile(.vtm)")
    reader.SetFileName(fmz)
    unfolder = vtkFoldingTreeUnfolder()
    unfolder.SetInputConnection(reader.GetOutputPort())
    unfolder.SetOriginalConnection(sphere.GetOutputPort())
    unfolder.Update()
    tree = reader.GetOutput()
    info = tree.GetBlock(1)
    check(info is not None and field(info, "StoredFaces") == builder.GetStoredFaces(),
          "the read tree stores the builder's %d triangles" % builder.GetStoredFaces())
    check(info is not None and field(info, "QuantizationError") == writer.GetQuantizationError(),
          "QuantizationError in the Tree block")
    mesh = unfolder.GetOutput()
    bound = field(mesh, "HausdorffToOriginalBound")
    epsilon = field(info, "RootEpsilon") if info is not None else None
    check(bound is not None and epsilon is not None and bound <= epsilon,
          "unfolded within the root epsilon: proved Hausdorff %s, epsilon %s" % (bound, epsilon))

    # .fmz -> .vtm: the read tree saved as .vtm unfolds to the same mesh.
    back_vtm = os.path.join(temp_dir, "TestCompactTreePython_back.vtm")
    back_writer = vtkXMLMultiBlockDataWriter()
    back_writer.SetInputConnection(reader.GetOutputPort())
    back_writer.SetDataModeToBinary()
    back_writer.SetFileName(back_vtm)
    back_writer.Write()
    back_reader = vtkExpatSafeXMLMultiBlockDataReader()
    back_reader.SetFileName(back_vtm)
    back_unfolder = vtkFoldingTreeUnfolder()
    back_unfolder.SetInputConnection(back_reader.GetOutputPort())
    back_unfolder.Update()
    back = back_unfolder.GetOutput()
    check(back.GetNumberOfCells() == mesh.GetNumberOfCells() and
          back.GetNumberOfPoints() == mesh.GetNumberOfPoints() and
          all(back.GetPoint(i) == mesh.GetPoint(i) for i in range(back.GetNumberOfPoints())),
          ".fmz -> .vtm unfolds to the same mesh (%d cells)" % back.GetNumberOfCells())

    # User arrays: dropped by default, kept with StoreUserArrays (values exact, as from the
    # .vtm: the unfolder carries them), at the cost of a larger file.
    elevation = vtkElevationFilter()
    elevation.SetInputConnection(sphere.GetOutputPort())
    cell_ids = vtkGenerateIds()
    cell_ids.SetInputConnection(elevation.GetOutputPort())
    cell_ids.PointIdsOff()
    cell_ids.CellIdsOn()
    cell_ids.SetCellIdsArrayName("Patch")
    builder.SetInputConnection(cell_ids.GetOutputPort())
    builder.Update()
    sizes = {}
    for store in (False, True):
        writer.SetStoreUserArrays(store)
        writer.Write()
        sizes[store] = os.path.getsize(fmz)
        reader.Modified()
        unfolder.SetOriginalData(None)
        unfolder.Update()
        out = unfolder.GetOutput()
        elevation_out = out.GetPointData().GetArray("Elevation")
        patch_out = out.GetCellData().GetArray("Patch")
        if not store:
            check(elevation_out is None and patch_out is None,
                  "without StoreUserArrays: no user arrays (%d bytes)" % sizes[store])
            continue
        check(elevation_out is not None and patch_out is not None,
              "with StoreUserArrays: Elevation and Patch come back (%d bytes)" % sizes[store])
        # In the tree: every leaf's values exactly as the builder's tree has them.
        same, compared = True, 0
        for mine, theirs in zip(leaves_of(reader.GetOutput()), leaves_of(builder.GetOutputDataObject(0))):
            for name, attrs in (("Elevation", lambda d: d.GetPointData()),
                                ("Patch", lambda d: d.GetCellData())):
                a, b = attrs(mine).GetArray(name), attrs(theirs).GetArray(name)
                if b is None:  # not a leaf (a fold plane's glyph)
                    continue
                same = same and a is not None and \
                    a.GetDataType() == b.GetDataType() and \
                    a.GetNumberOfValues() == b.GetNumberOfValues() and \
                    all(a.GetValue(i) == b.GetValue(i) for i in range(a.GetNumberOfValues()))
                compared += 1
        check(same and compared > 0, "with StoreUserArrays: the leaves' arrays are exact "
              "(%d compared)" % compared)
        # In the unfolded mesh: one tuple per point / cell, values from the input's.
        ref_e = cell_ids.GetOutput().GetPointData().GetArray("Elevation").GetRange()
        ref_p = cell_ids.GetOutput().GetCellData().GetArray("Patch").GetRange()
        check(elevation_out is not None and patch_out is not None and
              elevation_out.GetNumberOfTuples() == out.GetNumberOfPoints() and
              patch_out.GetNumberOfTuples() == out.GetNumberOfCells() and
              ref_e[0] <= elevation_out.GetRange()[0] <= elevation_out.GetRange()[1] <= ref_e[1]
              and ref_p[0] <= patch_out.GetRange()[0] <= patch_out.GetRange()[1] <= ref_p[1],
              "with StoreUserArrays: Elevation and Patch in the unfolded mesh, values from the "
              "input's (%s, %s)" % (elevation_out.GetRange() if elevation_out else None,
                                    patch_out.GetRange() if patch_out else None))
    check(sizes[True] > sizes[False], "the arrays cost bytes: %d > %d" % (sizes[True], sizes[False]))

    bad = vtkFoldingTreeCompactReader()
    errors = []
    bad.AddObserver("ErrorEvent", lambda caller, event: errors.append(event))
    bad.SetFileName(vtm)
    bad.Update()
    check(errors and bad.GetOutput().GetNumberOfBlocks() == 0 and bad.GetErrorCode() != 0,
          "a .vtm given to the compact reader: an error and an empty tree")

    print("TestCompactTreePython: %s" % ("%d failure(s)" % len(failures) if failures
                                         else "all checks passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
