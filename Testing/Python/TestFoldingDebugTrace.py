#!/usr/bin/env python3
"""TestFoldingDebugTrace: the algorithm's diagnostics go through VTK's debug output.

- With DebugOn() the detector reports its runs ("iterations ... region ... rms/eps"), the
  builder its folds ("[fold] node ... mirror error") and the unfolder its repair ("repair
  before: open border ...") as debug messages of that filter (vtkDebugMacro: in VTK 9.2 these
  go to vtkLogger, i.e. stderr, and ParaView's Log Viewer);
- with Debug off (the default) none of these lines is made;
- nothing of it is written to stdout (the library never prints).

Run with /usr/bin/python3 and PYTHONPATH=<build>/lib/python3/dist-packages:
    TestFoldingDebugTrace.py <mesh.off>
"""

import os
import sys
import tempfile

from foldingmeshes import (
    vtkFoldingTreeBuilder,
    vtkFoldingTreeUnfolder,
    vtkOFFReader,
    vtkSymmetryPlaneDetector,
)

failures = []


def check(condition, message):
    if not condition:
        print("FAIL  " + message)
        failures.append(message)


def captured(fd, action):
    """What the C/C++ side writes to file descriptor fd (1 stdout, 2 stderr) during action()."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = os.dup(fd)
    with tempfile.TemporaryFile() as capture:
        os.dup2(capture.fileno(), fd)
        try:
            action()
        finally:
            os.dup2(saved, fd)
            os.close(saved)
        capture.seek(0)
        return capture.read().decode(errors="replace")


def run(mesh_file, debug):
    """The three filters on the mesh with Debug on or off: (stderr, stdout) of the run."""
    reader = vtkOFFReader()
    reader.SetFileName(mesh_file)
    detector = vtkSymmetryPlaneDetector()
    detector.SetInputConnection(reader.GetOutputPort())
    builder = vtkFoldingTreeBuilder()
    builder.SetInputConnection(reader.GetOutputPort())
    unfolder = vtkFoldingTreeUnfolder()
    unfolder.SetInputConnection(builder.GetOutputPort())
    for f in (detector, builder, unfolder):
        f.SetDebug(debug)
    out = []

    def update():
        out.append(captured(1, lambda: (detector.Update(), unfolder.Update())))

    err = captured(2, update)
    for f in (detector, builder, unfolder):
        f.SetDebug(False)
    return err, out[0]


def main():
    mesh_file = sys.argv[1]
    lines = {
        "detector runs": "rms/eps",
        "builder folds": "[fold] node",
        "unfolder repair": "repair before: open border",
    }
    text, stdout = run(mesh_file, True)
    for what, marker in lines.items():
        check(marker in text, "DebugOn: %s (%r) in VTK's debug output" % (what, marker))
    check("vtkFoldingTreeBuilder" in text and "vtkFoldingTreeUnfolder" in text,
          "DebugOn: the messages name their filter")
    for what, marker in lines.items():
        check(marker not in stdout, "DebugOn: %s not on stdout" % what)
    text, stdout = run(mesh_file, False)
    for what, marker in lines.items():
        check(marker not in text and marker not in stdout,
              "Debug off: no %s (%r)" % (what, marker))
    print("%d check(s) failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
