#!/usr/bin/env python3
"""TestCompactTreePython: the compact folding tree (.fmz) from Python.

A sphere folded by foldingmeshes.vtkFoldingTreeBuilder is written with
vtkFoldingTreeCompactWriter (smaller than the .vtm of the same tree, the bits and quantisation
error reported), read back with vtkFoldingTreeCompactReader (QuantizationError in the "Tree"
block) and unfolded: the same number of stored triangles, the unfolded mesh within the root
epsilon of the sphere (vtkFoldingTreeUnfolder's proved HausdorffToOriginalBound). A file that
is not a .fmz gives an error and an empty output.

Run with /usr/bin/python3 and PYTHONPATH=<build>/lib/python3/dist-packages:
    TestCompactTreePython.py TEMP_DIR
"""

import os
import sys

from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter

from foldingmeshes import (vtkFoldingTreeBuilder, vtkFoldingTreeCompactReader,
                           vtkFoldingTreeCompactWriter, vtkFoldingTreeUnfolder)

failures = []


def check(condition, message):
    print(("ok:   " if condition else "FAIL: ") + message)
    if not condition:
        failures.append(message)


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
