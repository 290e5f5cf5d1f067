#!/usr/bin/env python3
"""TestDetectorLocatorPython: the cell locator fast path of vtkSymmetryPlaneDetector (issue 19).

A sphere with an asymmetric cone attached (so that some reflected vertices find a compatible
triangle and some do not) is detected with the defaults (Locator None: the core's face tree
alone) and again with a user-set vtkStaticCellLocator and vtkCellLocator as the fast path of
the fine mirror distances. The fast path only bounds the face tree's search, so the plane, the
region labels, the distances and the weights must be bit for bit the same.

Run with /usr/bin/python3 and PYTHONPATH=<build>/lib/python3/dist-packages:
    TestDetectorLocatorPython.py
"""

import math
import sys

from vtkmodules.vtkCommonDataModel import vtkCellLocator, vtkStaticCellLocator
from vtkmodules.vtkFiltersCore import vtkAppendPolyData
from vtkmodules.vtkFiltersSources import vtkConeSource, vtkSphereSource

from foldingmeshes import vtkSymmetryPlaneDetector

failures = []


def check(condition, message):
    print(("ok:   " if condition else "FAIL: ") + message)
    if not condition:
        failures.append(message)


def same(a, b):
    """Equal tuples, NaN equal to NaN (SymmetryDistance is NaN where a point was not measured)."""
    return len(a) == len(b) and all(
        len(x) == len(y) and all(u == v or (math.isnan(u) and math.isnan(v)) for u, v in zip(x, y))
        for x, y in zip(a, b))


def result(detector):
    """The detector's plane, region labels, distances and weights as plain lists."""
    out = detector.GetOutput()
    fd = out.GetFieldData()

    def values(array):
        return [array.GetTuple(i) for i in range(array.GetNumberOfTuples())]

    return {
        "plane": values(fd.GetArray("SymmetryPlaneOrigin")) + values(fd.GetArray("SymmetryPlaneNormal")),
        "region": values(out.GetCellData().GetArray("SymmetryRegion")),
        "distance": values(out.GetPointData().GetArray("SymmetryDistance")),
        "weight": values(out.GetPointData().GetArray("SymmetryWeight")),
    }


def main():
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(32)
    cone = vtkConeSource()
    cone.SetResolution(12)
    cone.SetCenter(0.45, 0.25, 0.1)
    cone.SetDirection(1.0, 0.7, 0.2)
    cone.SetHeight(0.4)
    cone.SetRadius(0.12)
    append = vtkAppendPolyData()
    append.AddInputConnection(sphere.GetOutputPort())
    append.AddInputConnection(cone.GetOutputPort())

    detector = vtkSymmetryPlaneDetector()
    detector.SetInputConnection(append.GetOutputPort())
    check(detector.GetLocator() is None, "Locator defaults to None (the face tree alone)")
    detector.Update()
    reference = result(detector)
    region = reference["region"]
    check(detector.GetSymmetryFound(), "default: a symmetry is found")
    check(any(r[0] == 2 for r in region) and any(r[0] != 2 for r in region),
          "default: the region holds some faces and leaves some out (the cone)")

    for locator in (vtkStaticCellLocator(), vtkCellLocator()):
        detector.SetLocator(locator)
        check(detector.GetLocator() is locator, "SetLocator keeps %s" % locator.GetClassName())
        detector.Update()
        other = result(detector)
        for key in ("plane", "region", "distance", "weight"):
            check(same(other[key], reference[key]),
                  "%s fast path: the same %s as the face tree alone" % (locator.GetClassName(), key))

    detector.SetLocator(None)
    detector.Update()
    again = result(detector)
    check(all(same(again[key], reference[key]) for key in reference),
          "Locator None again: the same result")

    print("TestDetectorLocatorPython: %s" % ("%d failure(s)" % len(failures) if failures
                                             else "all checks passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
