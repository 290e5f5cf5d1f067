#!/usr/bin/env python3
"""Runs one example script and checks, from the files it wrote, that it did its job.

    TestPythonExample.py EXAMPLE.py WORKDIR [example arguments...]

The example runs with --outdir WORKDIR (a fresh folder) and must exit with 0. Then, by
example: every output file exists and reads back; the meshes have the arrays the example's
docstring promises; numbers the example printed agree with the files; a tree written to
.vtm unfolds to the same mesh the example wrote; PNGs have the expected size, every panel
shows something (not just background) and figures stay below 200 KB.
"""

import os
import re
import shutil
import subprocess
import sys

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataReader, vtkXMLPolyDataReader

from foldingmeshes import vtkFoldingTreeUnfolder

FAILURES = []


def check(condition, message):
    print("check %-70s %s" % (message, "ok" if condition else "FAILED"))
    if not condition:
        FAILURES.append(message)
    return condition


def read_polydata(path):
    check(os.path.isfile(path), "%s exists" % os.path.basename(path))
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    check(data.GetNumberOfCells() > 0, "%s has cells" % os.path.basename(path))
    return data


def check_arrays(data, name, cell=(), point=(), field=()):
    for attributes, names in ((data.GetCellData(), cell), (data.GetPointData(), point),
                              (data.GetFieldData(), field)):
        for array in names:
            check(attributes.GetArray(array) is not None, "%s has array %s" % (name, array))


def check_png(path, width, height, panels=1, max_bytes=None):
    """Size as expected and every panel (equal vertical strips) shows > 3% non-white pixels."""
    if not check(os.path.isfile(path), "%s exists" % os.path.basename(path)):
        return
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    dims = reader.GetOutput().GetDimensions()
    check(dims[:2] == (width, height), "%s is %dx%d (got %dx%d)"
          % (os.path.basename(path), width, height, dims[0], dims[1]))
    pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())
    rgb = pixels[:, :3].reshape(dims[1], dims[0], 3)
    foreground = (rgb < 250).any(axis=2)
    strip = dims[0] // panels
    for i in range(panels):
        fraction = foreground[:, i * strip:(i + 1) * strip].mean()
        check(fraction > 0.03, "%s panel %d shows the mesh (%.1f%% foreground)"
              % (os.path.basename(path), i + 1, 100.0 * fraction))
    if max_bytes:
        size = os.path.getsize(path)
        check(size < max_bytes, "%s is below %d KB (%d KB)"
              % (os.path.basename(path), max_bytes // 1024, size // 1024))


def check_detect_symmetry(stem, output):
    mesh = read_polydata(stem + "_symmetry.vtp")
    check_arrays(mesh, "labelled mesh", cell=["SymmetryRegion"],
                 point=["SymmetryDistance", "SymmetryWeight"],
                 field=["SymmetryPlaneOrigin", "SymmetryPlaneNormal", "SymmetricAreaFraction"])
    region = mesh.GetCellData().GetArray("SymmetryRegion")
    if region is not None:
        check(region.GetRange()[1] == 2, "the symmetric region is not empty")
    plane = read_polydata(stem + "_plane.vtp")
    check(plane.GetNumberOfPoints() == 4, "the plane glyph is a quad")
    printed = re.search(r"normal (\S+) (\S+) (\S+)", output)
    normal = mesh.GetFieldData().GetArray("SymmetryPlaneNormal")
    if check(printed is not None and normal is not None, "the plane normal was printed"):
        check(all(abs(float(printed.group(k + 1)) - normal.GetComponent(0, k)) < 1e-3
                  for k in range(3)), "printed normal == SymmetryPlaneNormal in the file")
    check_png(stem + "_symmetry.png", 600, 500)


def check_fold_unfold(stem, output):
    segmentation = read_polydata(stem + "_segmentation.vtp")
    check_arrays(segmentation, "segmentation", cell=["FoldingLeafId", "FoldingDepth",
                                                     "FoldingRole"])
    unfolded = read_polydata(stem + "_unfolded.vtp")
    check_arrays(unfolded, "unfolded mesh", point=["OriginalPointId"],
                 cell=["FoldingLeafId", "FoldingCopy", "FoldingMirrored"],
                 field=["OpenEdges", "OpenGapCount"])
    faces = segmentation.GetNumberOfCells()
    check(abs(unfolded.GetNumberOfCells() - faces) <= 0.10 * faces,
          "unfolded faces (%d) within 10%% of the input's (%d)"
          % (unfolded.GetNumberOfCells(), faces))

    reader = vtkXMLMultiBlockDataReader()
    reader.SetFileName(stem + "_tree.vtm")
    reader.Update()
    tree = reader.GetOutput()
    check(tree.GetNumberOfBlocks() == 2, "the tree file has the root and the Tree block")
    summary = tree.GetBlock(1).GetFieldData() if tree.GetNumberOfBlocks() == 2 else None
    printed = re.search(r"(\d+) faces -> (\d+) stored", output)
    if check(summary is not None and printed is not None, "the fold summary was printed"):
        check(int(printed.group(1)) == int(summary.GetArray("OriginalFaces").GetTuple1(0))
              and int(printed.group(2)) == int(summary.GetArray("StoredFaces").GetTuple1(0)),
              "printed face counts == the tree file's OriginalFaces/StoredFaces")
        check(int(printed.group(2)) < int(printed.group(1)), "the tree stores fewer faces")
    unfolder = vtkFoldingTreeUnfolder()
    unfolder.SetInputData(tree)
    unfolder.Update()
    check(unfolder.GetOutput().GetNumberOfCells() == unfolded.GetNumberOfCells()
          and unfolder.GetOutput().GetNumberOfPoints() == unfolded.GetNumberOfPoints(),
          "the .vtm tree unfolds to the mesh in _unfolded.vtp")
    check_png(stem + "_fold_unfold.png", 1200, 450, panels=3)


def check_paper_figures(outdir, output):
    check(output.count("compression") == 2, "one summary line per figure")
    check_png(os.path.join(outdir, "paper_fig1_dino.png"), 5 * 300, 300, panels=5,
              max_bytes=200 * 1024)
    check_png(os.path.join(outdir, "paper_fig4_horse.png"), 4 * 300, 300, panels=4,
              max_bytes=200 * 1024)


def main():
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        return 1
    example, workdir, arguments = sys.argv[1], sys.argv[2], sys.argv[3:]
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(workdir)
    run = subprocess.run([sys.executable, example, *arguments, "--outdir", workdir],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(run.stdout)
    if not check(run.returncode == 0, "%s exits with 0 (got %d)"
                 % (os.path.basename(example), run.returncode)):
        return 1
    name = os.path.basename(example)
    mesh = next((a for a in arguments if not a.startswith("-")), "")
    stem = os.path.join(workdir, os.path.splitext(os.path.basename(mesh))[0])
    if name == "detect_symmetry.py":
        check_detect_symmetry(stem, run.stdout)
    elif name == "fold_unfold.py":
        check_fold_unfold(stem, run.stdout)
    elif name == "make_paper_figures.py":
        check_paper_figures(workdir, run.stdout)
    else:
        check(False, "known example")
    print("%d check(s) failed" % len(FAILURES) if FAILURES else "all checks passed")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
