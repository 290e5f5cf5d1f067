#!/usr/bin/env python3
"""TestBuilderLocatorPython: the cell locator behind vtkFoldingTreeBuilder's VerifyBound (issue 19).

A sphere folded with the defaults names the core's FaceTree in the tree's "Tree" block
(VerificationLocator) and proves its bound; with a user-set vtkStaticCellLocator or
vtkCellLocator the same tree comes out, the block names the class and the proved bound agrees to
1e-9 of the diagonal (the distances are exact point-to-triangle distances whichever structure
finds the triangle); with VerifyBound off the name is empty and VerifiedBound is -1. The locator
also answers each fold's mirrored-face proof: the bundled dinosaur, which is not exactly
symmetric (so the proof subdivides faces and asks for closest triangles), folds to the same
tree and bound with vtkStaticCellLocator as with the face tree.

Run with /usr/bin/python3 and PYTHONPATH=<build>/lib/python3/dist-packages:
    TestBuilderLocatorPython.py
"""

import os
import sys

from vtkmodules.vtkCommonDataModel import vtkCellLocator, vtkStaticCellLocator
from vtkmodules.vtkFiltersSources import vtkSphereSource

from foldingmeshes import vtkFoldingTreeBuilder, vtkOFFReader

DINO = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Data", "dino.off")

failures = []


def check(condition, message):
    print(("ok:   " if condition else "FAIL: ") + message)
    if not condition:
        failures.append(message)


def info(builder):
    """(VerificationLocator, VerifiedBound, Diagonal, StoredFaces) of the builder's tree."""
    block = builder.GetOutputDataObject(0).GetBlock(1)
    fd = block.GetFieldData()
    name = fd.GetAbstractArray("VerificationLocator")
    return (name.GetValue(0) if name is not None else None,
            fd.GetArray("VerifiedBound").GetTuple1(0), fd.GetArray("Diagonal").GetTuple1(0),
            builder.GetStoredFaces())


def main():
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(40)
    sphere.SetPhiResolution(30)
    builder = vtkFoldingTreeBuilder()
    builder.SetInputConnection(sphere.GetOutputPort())
    check(builder.GetLocator() is None, "Locator defaults to None (the core's face tree)")
    builder.Update()
    name, bound, diagonal, stored = info(builder)
    check(name == "FaceTree", "default: VerificationLocator %r" % name)
    check(0.0 <= bound <= 0.02 * diagonal + 1e-9 * diagonal,
          "default: proved bound %g within epsilon %g" % (bound, 0.02 * diagonal))

    for locator in (vtkStaticCellLocator(), vtkCellLocator()):
        builder.SetLocator(locator)
        builder.Update()
        name2, bound2, _, stored2 = info(builder)
        check(name2 == locator.GetClassName(), "user-set locator: VerificationLocator %r" % name2)
        check(stored2 == stored and abs(bound2 - bound) <= 1e-9 * diagonal,
              "%s: the same tree (%d faces) and bound (%.12g vs %.12g)"
              % (name2, stored2, bound2, bound))

    dino = vtkOFFReader()
    dino.SetFileName(DINO)
    folder = vtkFoldingTreeBuilder()
    folder.SetInputConnection(dino.GetOutputPort())
    folder.Update()
    _, dinoBound, dinoDiagonal, dinoStored = info(folder)
    folder.SetLocator(vtkStaticCellLocator())
    folder.Update()
    name4, dinoBound2, _, dinoStored2 = info(folder)
    check(dinoStored > 0 and name4 == "vtkStaticCellLocator" and dinoStored2 == dinoStored
          and abs(dinoBound2 - dinoBound) <= 1e-9 * dinoDiagonal,
          "dino with vtkStaticCellLocator (mirrored-face proofs too): %d stored faces and bound "
          "%.12g, face tree %d and %.12g" % (dinoStored2, dinoBound2, dinoStored, dinoBound))

    builder.SetLocator(None)
    builder.VerifyBoundOff()
    builder.Update()
    name3, bound3, _, _ = info(builder)
    check(name3 == "" and bound3 == -1.0,
          "VerifyBound off: VerificationLocator %r, VerifiedBound %g" % (name3, bound3))

    print("TestBuilderLocatorPython: %s" % ("%d failure(s)" % len(failures) if failures
                                            else "all checks passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
