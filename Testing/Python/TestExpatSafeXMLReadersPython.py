#!/usr/bin/env python3
"""TestExpatSafeXMLReadersPython: the wrapped expat-safe XML readers from Python.

A sphere with a point array, written by vtkXMLPolyDataWriter in its default appended mode
(the mode VTK <= 9.2 cannot read back with Debian 12's current libexpat1, VTK issue 19258),
reads back point for point with foldingmeshes.vtkExpatSafeXMLPolyDataReader, and as a
block of a .vtm with foldingmeshes.vtkExpatSafeXMLMultiBlockDataReader, without errors.

Run with /usr/bin/python3 and PYTHONPATH=<build>/lib/python3/dist-packages:
    TestExpatSafeXMLReadersPython.py TEMP_DIR
"""

import os
import sys

from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet
from vtkmodules.vtkFiltersCore import vtkElevationFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter, vtkXMLPolyDataWriter

from foldingmeshes import vtkExpatSafeXMLMultiBlockDataReader, vtkExpatSafeXMLPolyDataReader


def errors_of(vtk_object):
    messages = []
    vtk_object.AddObserver("ErrorEvent", lambda caller, event: messages.append(event))
    return messages


def same_points(a, b):
    return (a.GetNumberOfPoints() == b.GetNumberOfPoints() and
            all(a.GetPoint(i) == b.GetPoint(i) for i in range(a.GetNumberOfPoints())))


def main(temp_dir):
    failures = []

    def check(condition, message):
        print("check %-66s %s" % (message, "ok" if condition else "FAILED"))
        if not condition:
            failures.append(message)

    sphere = vtkSphereSource()
    sphere.SetThetaResolution(160)
    sphere.SetPhiResolution(80)
    elevation = vtkElevationFilter()
    elevation.SetInputConnection(sphere.GetOutputPort())
    elevation.Update()
    mesh = elevation.GetOutput()

    vtp = os.path.join(temp_dir, "TestExpatSafeXMLReadersPython.vtp")
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(mesh)
    writer.SetFileName(vtp)
    writer.SetDataModeToAppended()
    check(writer.Write() == 1, "wrote an appended .vtp")
    reader = vtkExpatSafeXMLPolyDataReader()
    errors = errors_of(reader)
    reader.SetFileName(vtp)
    reader.Update()
    out = reader.GetOutput()
    check(not errors, "the appended .vtp reads without errors")
    check(same_points(mesh, out), "the same %d points" % mesh.GetNumberOfPoints())
    check(out.GetPointData().GetArray("Elevation") is not None, "the point array survives")
    print("expat reparse deferral present (switched off):",
          vtkExpatSafeXMLPolyDataReader.ExpatHasReparseDeferral())

    blocks = vtkMultiBlockDataSet()
    blocks.SetNumberOfBlocks(1)
    blocks.SetBlock(0, mesh)
    vtm = os.path.join(temp_dir, "TestExpatSafeXMLReadersPython.vtm")
    tree_writer = vtkXMLMultiBlockDataWriter()
    tree_writer.SetInputData(blocks)
    tree_writer.SetFileName(vtm)
    check(tree_writer.Write() == 1, "wrote a .vtm with an appended piece")
    tree_reader = vtkExpatSafeXMLMultiBlockDataReader()
    tree_errors = errors_of(tree_reader)
    tree_reader.SetFileName(vtm)
    tree_reader.Update()
    tree = tree_reader.GetOutput()
    check(not tree_errors, "the .vtm reads without errors")
    check(tree.GetNumberOfBlocks() == 1 and same_points(mesh, tree.GetBlock(0)),
          "its block has the same points")

    print("TestExpatSafeXMLReadersPython: %s" % ("%d failure(s)" % len(failures) if failures
                                                  else "passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
