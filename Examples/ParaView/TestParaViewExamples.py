"""Runs the ParaView examples and checks what they write (driver of their ctest tests).

    xvfb-run -a /usr/bin/python3 TestParaViewExamples.py dino   --pvpython P --plugin SO
        --work-dir DIR --mesh dino.off
    xvfb-run -a /usr/bin/python3 TestParaViewExamples.py folder --pvbatch P --plugin SO
        --work-dir DIR --mesh A.off --mesh B.ply ...

dino:   fold_dino.py must exit 0, report a found plane and a positive compression, and
        write four PNG screenshots that are not blank.
folder: the meshes (and a broken .off and a text file) are copied into DIR/meshes;
        fold_folder.py must exit 1 (the broken mesh), write one CSV row per mesh file in name
        order, an error only for the broken one, and sane values for the others: faces equal
        to the triangles of the file, 0 < stored faces < faces, compression = 1 - stored/faces,
        a unit plane normal, unfolded faces within 0.5 to 2 times the faces, positive times;
        the broken mesh's row holds only its name and the error.
"""

import argparse
import csv
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
failures = []


def check(condition, message):
    print(("ok    " if condition else "FAIL  ") + message)
    if not condition:
        failures.append(message)


def run(command):
    print("run   " + " ".join(command))
    process = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             universal_newlines=True, timeout=900)
    print(process.stdout)
    return process.returncode, process.stdout


def count_triangles(path):
    """Triangles of a mesh file after triangulation, read with VTK (independent of ParaView)."""
    from vtkmodules.vtkFiltersCore import vtkTriangleFilter
    from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
    from vtkmodules.vtkIOPLY import vtkPLYReader
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    extension = os.path.splitext(path)[1].lower()
    if extension == ".off":  # one vertex or face per line, as in the test meshes
        with open(path) as stream:
            lines = [l.split("#")[0].split() for l in stream]
        lines = [l for l in lines if l]
        head, body = lines[0], lines[1:]
        if head[0].upper().endswith("OFF"):
            head = head[1:]
        if not head:
            head, body = body[0], body[1:]
        points, faces = int(head[0]), int(head[1])
        return sum(int(face[0]) - 2 for face in body[points:points + faces])
    reader = {".obj": vtkOBJReader, ".stl": vtkSTLReader, ".ply": vtkPLYReader,
              ".vtp": vtkXMLPolyDataReader}[extension]()
    reader.SetFileName(path)
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(reader.GetOutputPort())
    triangles.PassVertsOff()
    triangles.PassLinesOff()
    triangles.Update()
    return triangles.GetOutput().GetNumberOfPolys()


def png_is_picture(path):
    """A PNG whose pixels are not all the same colour."""
    from vtkmodules.vtkIOImage import vtkPNGReader
    if not os.path.isfile(path):
        return False
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    scalars = reader.GetOutput().GetPointData().GetScalars()
    if scalars is None:
        return False
    return any(scalars.GetRange(c)[0] != scalars.GetRange(c)[1]
               for c in range(scalars.GetNumberOfComponents()))


def test_dino(args):
    out = os.path.join(args.work_dir, "dino")
    shutil.rmtree(out, ignore_errors=True)
    status, output = run([args.pvpython, os.path.join(HERE, "fold_dino.py"),
                          "--plugin", args.plugin, "--mesh", args.mesh[0],
                          "--output-dir", out])
    check(status == 0, "fold_dino.py exit status %d == 0" % status)
    found = re.search(r"plane found (\d)", output)
    check(found is not None and found.group(1) == "1", "fold_dino.py: plane found")
    match = re.search(r"faces (\d+), stored faces (\d+), compression ([0-9.]+)", output)
    check(match is not None, "fold_dino.py prints faces, stored faces and compression")
    if match:
        faces, stored, compression = int(match.group(1)), int(match.group(2)), float(match.group(3))
        check(faces == count_triangles(args.mesh[0]), "faces %d == triangles of the file" % faces)
        check(0 < stored < faces and compression > 0.0, "stored %d < faces, compression %g > 0"
              % (stored, compression))
    name = os.path.splitext(os.path.basename(args.mesh[0]))[0]
    for suffix in ("symmetry", "tree", "segmentation", "unfolded"):
        path = os.path.join(out, "%s_%s.png" % (name, suffix))
        check(png_is_picture(path), "%s is a picture" % path)


def test_folder(args):
    folder = os.path.join(args.work_dir, "meshes")
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    for mesh in args.mesh:
        shutil.copy(mesh, folder)
    with open(os.path.join(folder, "broken.off"), "w") as stream:
        stream.write("OFF\n4 2 0\n0 0 0\n1 0 0\n")  # truncated: 2 of 4 points, no faces
    with open(os.path.join(folder, "notes.txt"), "w") as stream:
        stream.write("not a mesh: must be ignored\n")
    table = os.path.join(args.work_dir, "summary.csv")
    if os.path.exists(table):
        os.remove(table)
    status, _ = run([args.pvbatch, os.path.join(HERE, "fold_folder.py"), folder,
                     "--plugin", args.plugin, "--csv", table])
    check(status == 1, "fold_folder.py exit status %d == 1 (one broken mesh)" % status)
    check(os.path.isfile(table), "fold_folder.py wrote " + table)
    if not os.path.isfile(table):
        return
    with open(table, newline="") as stream:
        reader = csv.DictReader(stream)
        header = reader.fieldnames
        rows = list(reader)
    expected_files = sorted([os.path.basename(m) for m in args.mesh] + ["broken.off"])
    check([row["file"] for row in rows] == expected_files,
          "one row per mesh file in name order: %s" % [row["file"] for row in rows])
    for name in ("file", "faces", "plane_found", "stored_faces", "compression", "tree_height",
                 "detect_seconds", "build_seconds", "unfold_seconds", "hausdorff", "error"):
        check(name in header, "column " + name)
    for row in rows:
        name = row["file"]
        if name == "broken.off":
            check(row["error"] != "", "broken.off: error reported (%s)" % row["error"])
            check(row["faces"] == row["compression"] == "", "broken.off: no partial values")
            continue
        check(row["error"] == "", "%s: no error (%s)" % (name, row["error"]))
        if row["error"]:
            continue
        faces, stored = int(row["faces"]), int(row["stored_faces"])
        compression = float(row["compression"])
        triangles = count_triangles(os.path.join(folder, name))
        check(faces == triangles, "%s: faces %d == triangles of the file %d"
              % (name, faces, triangles))
        check(0 < stored < faces, "%s: 0 < stored %d < faces" % (name, stored))
        check(abs(compression - (1.0 - stored / faces)) < 1e-3,
              "%s: compression %g == 1 - stored/faces" % (name, compression))
        check(int(row["tree_height"]) >= 1, "%s: tree height %s >= 1" % (name, row["tree_height"]))
        check(row["plane_found"] in ("0", "1"), "%s: plane_found is 0 or 1" % name)
        normal = [float(row[k]) for k in ("normal_x", "normal_y", "normal_z")]
        check(abs(sum(c * c for c in normal) - 1.0) < 1e-4, "%s: unit plane normal" % name)
        unfolded = int(row["unfolded_faces"])
        # Loose bounds: imprecise folds can duplicate faces where mirrored halves overlap
        # (the hammer scan unfolds to about 1.4 times its faces).
        check(0.5 * faces <= unfolded <= 2.0 * faces, "%s: unfolded faces %d within [0.5, 2] x %d"
              % (name, unfolded, faces))
        check(all(float(row[k]) > 0 for k in ("detect_seconds", "build_seconds",
                                              "unfold_seconds")), "%s: positive times" % name)
        check(row["hausdorff"] == "" or float(row["hausdorff"]) >= 0.0,
              "%s: hausdorff empty or >= 0 (%s)" % (name, row["hausdorff"]))
    dino = [row for row in rows if row["file"].startswith("dino")]
    check(not dino or dino[0]["plane_found"] == "1", "dino: plane found")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("mode", choices=("dino", "folder"))
    parser.add_argument("--pvpython")
    parser.add_argument("--pvbatch")
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--work-dir", required=True)
    parser.add_argument("--mesh", action="append", required=True)
    args = parser.parse_args()
    os.makedirs(args.work_dir, exist_ok=True)
    test_dino(args) if args.mode == "dino" else test_folder(args)
    if failures:
        print("%d check(s) failed:\n  %s" % (len(failures), "\n  ".join(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
