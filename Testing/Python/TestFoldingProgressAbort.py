#!/usr/bin/env python3
"""TestFoldingProgressAbort: progress events and AbortExecute of the three filters.

What a ParaView progress bar and its Abort rely on, checked on the wrapped classes:

- a full run of vtkSymmetryPlaneDetector (also with DetectRotation: the bar moves during the
  rotation search too, and an abort there leaves no rotation result), vtkFoldingTreeBuilder
  and vtkFoldingTreeUnfolder on the dino reports several ProgressEvents with non-decreasing values in [0, 1], some of
  them strictly between 0 and 1 (the bar moves during the run), ending at 1;
- setting AbortExecute from a progress observer early in the builder's run stops it
  cleanly: Update() returns without a crash, much sooner than the full run, the tree is the
  documented partial one ("Tree" block with Aborted = 1, fewer stored nodes, at most the
  full run's height) and, once the caller clears AbortExecute (VTK 9.1/9.2 do not reset
  it), the next run gives the full result again;
- the same for the unfolder: an abort ends the run early and the output is empty or a
  valid partial mesh (no crash).

Run with /usr/bin/python3 and PYTHONPATH=<build>/lib/python3/dist-packages:
    TestFoldingProgressAbort.py <mesh.off>
"""

import sys
import time

from vtkmodules.vtkCommonCore import vtkCommand

from foldingmeshes import (
    vtkFoldingTreeBuilder,
    vtkFoldingTreeUnfolder,
    vtkOFFReader,
    vtkSymmetryPlaneDetector,
)

failures = []


def check(condition, message):
    print(("ok    " if condition else "FAIL  ") + message)
    if not condition:
        failures.append(message)


class ProgressRecorder:
    """Records ProgressEvents; optionally aborts the algorithm once progress passes a value."""

    def __init__(self, algorithm, abort_after=None):
        self.values = []
        self.abort_after = abort_after
        self.aborted_at = None
        algorithm.AddObserver(vtkCommand.ProgressEvent, self)

    def __call__(self, algorithm, event):
        value = algorithm.GetProgress()
        self.values.append(value)
        if (self.abort_after is not None and self.aborted_at is None and
                0.0 < value and value >= self.abort_after):
            self.aborted_at = value
            algorithm.AbortExecuteOn()


def check_progress(name, values):
    check(len(values) >= 5, "%s: %d progress events (>= 5)" % (name, len(values)))
    check(all(0.0 <= v <= 1.0 for v in values), "%s: progress in [0, 1]" % name)
    check(all(b >= a for a, b in zip(values, values[1:])), "%s: progress never decreases"
          % name)
    inner = [v for v in values if 0.0 < v < 1.0]
    check(len(set(inner)) >= 3, "%s: %d distinct values strictly inside (0, 1)"
          % (name, len(set(inner))))
    check(bool(values) and values[-1] == 1.0, "%s: last progress is 1" % name)


def tree_field(tree, name):
    info = tree.GetBlock(1) if tree.GetNumberOfBlocks() > 1 else None
    array = info.GetFieldData().GetArray(name) if info is not None else None
    return array.GetTuple1(0) if array is not None else None


def timed_update(algorithm):
    """Update() and its duration; the status is the executive's (1: the request succeeded)."""
    start = time.perf_counter()
    status = algorithm.GetExecutive().Update()
    return status, time.perf_counter() - start


def main(mesh_file):
    reader = vtkOFFReader()
    reader.SetFileName(mesh_file)
    reader.Update()
    mesh = reader.GetOutput()
    check(mesh.GetNumberOfPolys() > 0, "read %s" % mesh_file)

    # ---- full runs: the bar moves and ends at 1 ----
    detector = vtkSymmetryPlaneDetector()
    detector.SetInputData(mesh)
    recorder = ProgressRecorder(detector)
    detector.Update()
    check_progress("detector", recorder.values)

    # With DetectRotation the rotation search continues the bar after the plane search, and
    # an abort during it ends the run without a crash and without rotation results.
    detector = vtkSymmetryPlaneDetector()
    detector.SetInputData(mesh)
    detector.DetectRotationOn()
    recorder = ProgressRecorder(detector)
    detector.Update()
    check_progress("detector with rotation", recorder.values)
    check(any(0.4 < v < 1.0 for v in recorder.values),
          "detector with rotation: progress reported during the rotation search")
    check(detector.GetOutput(2).GetNumberOfPoints() == 2, "detector with rotation: axis glyph")
    aborting = vtkSymmetryPlaneDetector()
    aborting.SetInputData(mesh)
    aborting.DetectRotationOn()
    recorder = ProgressRecorder(aborting, abort_after=0.5)
    aborting.GetExecutive().Update()
    check(recorder.aborted_at is not None, "detector with rotation: abort requested at %s"
          % recorder.aborted_at)
    check(aborting.GetRotationOrder() == 0 and aborting.GetOutput(2).GetNumberOfPoints() == 0,
          "detector with rotation: an abort during the rotation search leaves no rotation result")

    builder = vtkFoldingTreeBuilder()
    builder.SetInputData(mesh)
    recorder = ProgressRecorder(builder)
    status, full_seconds = timed_update(builder)
    check(status, "builder: full run succeeds (%.2f s)" % full_seconds)
    check_progress("builder", recorder.values)
    full_tree = builder.GetOutputDataObject(0)
    full_nodes = tree_field(full_tree, "NumberOfNodes")
    full_height = builder.GetTreeHeight()
    full_stored = builder.GetStoredFaces()
    check(tree_field(full_tree, "Aborted") == 0, "builder: full run Aborted = 0")

    unfolder = vtkFoldingTreeUnfolder()
    unfolder.SetInputData(full_tree)
    recorder = ProgressRecorder(unfolder)
    status, unfold_seconds = timed_update(unfolder)
    check(status and unfolder.GetOutput().GetNumberOfCells() > 0, "unfolder: full run succeeds")
    check_progress("unfolder", recorder.values)
    full_unfolded = unfolder.GetOutput().GetNumberOfCells()

    # ---- abort the builder early from a progress observer ----
    aborting = vtkFoldingTreeBuilder()
    aborting.SetInputData(mesh)
    recorder = ProgressRecorder(aborting, abort_after=0.05)
    status, abort_seconds = timed_update(aborting)
    check(recorder.aborted_at is not None, "builder: abort requested at progress %s"
          % recorder.aborted_at)
    events_after = [v for v in recorder.values if v > recorder.aborted_at] \
        if recorder.aborted_at is not None else []
    print("      abort at %s: %d more progress events, %.2f s instead of %.2f s"
          % (recorder.aborted_at, len(events_after), abort_seconds, full_seconds))
    check(abort_seconds < 0.5 * full_seconds, "builder: aborted run %.2f s < half of %.2f s"
          % (abort_seconds, full_seconds))
    tree = aborting.GetOutputDataObject(0)
    aborted_flag = tree_field(tree, "Aborted")
    nodes = tree_field(tree, "NumberOfNodes")
    if tree.GetNumberOfBlocks() == 0:
        check(True, "builder: aborted output is empty")
    else:
        check(aborted_flag == 1, "builder: partial tree has Aborted = 1 (%s)" % aborted_flag)
        check(nodes is not None and nodes < full_nodes, "builder: partial tree has %s < %s nodes"
              % (nodes, full_nodes))
        check(aborting.GetTreeHeight() <= full_height, "builder: partial height %d <= %d"
              % (aborting.GetTreeHeight(), full_height))
        check(aborting.GetStoredFaces() >= full_stored,
              "builder: partial tree stores %d >= %d faces (less is folded)"
              % (aborting.GetStoredFaces(), full_stored))

    # VTK 9.1/9.2 leave AbortExecute on until the caller clears it (the pipeline does not
    # reset it); cleared, the next update runs to the end.
    recorder.abort_after = None
    aborting.AbortExecuteOff()
    aborting.Modified()
    status, again_seconds = timed_update(aborting)
    again = aborting.GetOutputDataObject(0)
    check(status and tree_field(again, "Aborted") == 0 and
          tree_field(again, "NumberOfNodes") == full_nodes,
          "builder: the next run is complete again (%s nodes)" % tree_field(again, "NumberOfNodes"))

    # ---- abort the unfolder ----
    aborting_unfolder = vtkFoldingTreeUnfolder()
    aborting_unfolder.SetInputData(full_tree)
    recorder = ProgressRecorder(aborting_unfolder, abort_after=0.01)
    status, seconds = timed_update(aborting_unfolder)
    output = aborting_unfolder.GetOutput()
    check(recorder.aborted_at is not None, "unfolder: abort requested at progress %s"
          % recorder.aborted_at)
    check(output.GetNumberOfCells() < full_unfolded,
          "unfolder: aborted output has %d < %d faces (empty or partial)"
          % (output.GetNumberOfCells(), full_unfolded))
    check(seconds <= unfold_seconds + 0.5, "unfolder: aborted run %.2f s, full %.2f s"
          % (seconds, unfold_seconds))

    return 1 if failures else 0


if __name__ == "__main__":
    status = main(sys.argv[1])
    if failures:
        print("%d check(s) failed:\n  %s" % (len(failures), "\n  ".join(failures)))
    sys.exit(status)
