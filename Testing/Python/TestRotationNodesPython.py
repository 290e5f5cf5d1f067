#!/usr/bin/env python3
"""TestRotationNodesPython: rotation nodes of the folding tree (issue 22) from Python.

A closed 6-fold twisted vase (no mirror plane), folded by foldingmeshes.vtkFoldingTreeBuilder
with RotationNodes on:
- the root is a rotation node: its "Axis" block carries FoldingNodeKind 3, FoldingAxisOrigin and
  FoldingAxisDirection (3 components each, the direction along the vase's axis) and
  FoldingRotationOrder 6, and draws the axis as a line; the tree stores about a sixth;
- the tree saved as .vtm (inline binary) and as .fmz reads back and unfolds within the root
  epsilon of the vase (vtkFoldingTreeUnfolder's proved HausdorffToOriginalBound), closed;
- the default is WHEN_AXIAL (since 2026-12-07); RotationNodes off gives no rotation node
  (RotationNodesTried 0); WHEN_AXIAL gives the tree of on for the vase and, for the vase stretched along x (its second moments no
  longer axially symmetric), the tree of off, RotationNodesTried 0;
- a malformed rotation node (order 1; no FoldingAxisDirection) is rejected with an error that
  names it;
- the default on a user's plain vtkSphereSource (64 x 64, triangulated and cleaned): a rotation
  node at the root, at most a tenth of the faces the planes alone store (124 against 1,510 on
  2026-12-07), unfolded within the root epsilon and closed.

Run with /usr/bin/python3 and PYTHONPATH=<build>/lib/python3/dist-packages:
    TestRotationNodesPython.py TEMP_DIR
"""

import math
import os
import sys

from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkFeatureEdges, vtkTriangleFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter

from foldingmeshes import (vtkExpatSafeXMLMultiBlockDataReader, vtkFoldingTreeBuilder,
                           vtkFoldingTreeCompactReader, vtkFoldingTreeCompactWriter,
                           vtkFoldingTreeUnfolder)
from rotation_shapes import make_twisted_vase  # noqa: E402 (beside this script)

failures = []
ORDER = 6


def check(condition, message):
    print(("ok:   " if condition else "FAIL: ") + message)
    if not condition:
        failures.append(message)


def field(data, name, component=0):
    array = data.GetFieldData().GetArray(name) if data is not None else None
    return array.GetComponent(0, component) if array is not None else None


def axis_block(tree):
    """The root node's metadata block (its last block) when the root is an inner node."""
    root = tree.GetBlock(0)
    if root is None or not root.IsA("vtkMultiBlockDataSet"):
        return None
    return root.GetBlock(root.GetNumberOfBlocks() - 1)


def open_edges(mesh):
    edges = vtkFeatureEdges()
    edges.SetInputData(mesh)
    edges.BoundaryEdgesOn()
    edges.FeatureEdgesOff()
    edges.ManifoldEdgesOff()
    edges.NonManifoldEdgesOn()
    edges.Update()
    return edges.GetOutput().GetNumberOfCells()


def unfold_and_check(source, vase, epsilon, label):
    unfolder = vtkFoldingTreeUnfolder()
    unfolder.SetInputConnection(source)
    unfolder.SetOriginalData(vase)
    unfolder.Update()
    mesh = unfolder.GetOutput()
    bound = field(mesh, "HausdorffToOriginalBound")
    check(bound is not None and bound <= epsilon,
          "%s: unfolded within the root epsilon: proved Hausdorff %s, epsilon %s"
          % (label, bound, epsilon))
    check(mesh.GetNumberOfCells() > 0 and open_edges(mesh) == 0,
          "%s: unfolded closed (%d cells, %d open or non-manifold edges)"
          % (label, mesh.GetNumberOfCells(), open_edges(mesh)))


def error_catcher(messages):
    """An ErrorEvent observer that appends the error's text to `messages`."""
    @calldata_type(VTK_STRING)
    def on_error(caller, event, message):
        messages.append(str(message))
    return on_error


def expect_rejected(tree, damage, must_contain, label):
    """A deep copy of `tree` with its root's axis block damaged: the unfolder fails, naming it."""
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet
    copy = vtkMultiBlockDataSet()
    copy.DeepCopy(tree)
    damage(axis_block(copy))
    unfolder = vtkFoldingTreeUnfolder()
    messages = []
    unfolder.AddObserver("ErrorEvent", error_catcher(messages))
    unfolder.SetInputData(copy)
    unfolder.Update()
    text = "\n".join(messages)
    check(unfolder.GetOutput().GetNumberOfCells() == 0 and must_contain in text,
          "%s: rejected, the error names it (%r in the error)" % (label, must_contain))


def sphere_default():
    """RotationNodes at its default on a VTK sphere, against the planes alone."""
    source = vtkSphereSource()
    source.SetThetaResolution(64)
    source.SetPhiResolution(64)
    clean = vtkCleanPolyData()  # the source repeats its poles' and seam's points
    clean.SetInputConnection(source.GetOutputPort())
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(clean.GetOutputPort())
    triangles.Update()
    sphere = triangles.GetOutput()
    stored = {}
    for mode in (None, vtkFoldingTreeBuilder.ROTATION_NODES_OFF):
        builder = vtkFoldingTreeBuilder()
        builder.SetInputData(sphere)
        if mode is not None:
            builder.SetRotationNodes(mode)
        builder.Update()
        tree = builder.GetOutputDataObject(0)
        stored[mode] = builder.GetStoredFaces()
        if mode is None:
            block = axis_block(tree)
            check(block is not None and field(block, "FoldingNodeKind") == 3,
                  "default on a vtkSphereSource: the root is a rotation node")
            epsilon = field(tree.GetBlock(1), "RootEpsilon")
            unfold_and_check(builder.GetOutputPort(0), sphere, epsilon, "default sphere")
    check(10 * stored[None] <= stored[vtkFoldingTreeBuilder.ROTATION_NODES_OFF],
          "default on a vtkSphereSource: %d faces stored, %d with the planes alone"
          % (stored[None], stored[vtkFoldingTreeBuilder.ROTATION_NODES_OFF]))


def main(temp_dir):
    os.makedirs(temp_dir, exist_ok=True)
    vase = make_twisted_vase(ORDER, segments_per_lobe=8, amplitude=0.25)
    builder = vtkFoldingTreeBuilder()
    builder.SetInputData(vase)
    check(builder.GetRotationNodes() == vtkFoldingTreeBuilder.ROTATION_NODES_WHEN_AXIAL and
          builder.GetMaximumRotationOrder() == 64,
          "defaults: RotationNodes WHEN_AXIAL, MaximumRotationOrder 64")
    builder.RotationNodesOff()
    builder.Update()
    off = axis_block(builder.GetOutputDataObject(0))
    check(off is None or field(off, "FoldingNodeKind") != 3, "RotationNodes off: no rotation root")

    check(field(builder.GetOutputDataObject(0).GetBlock(1), "RotationNodesTried") == 0,
          "RotationNodes off: RotationNodesTried 0")
    off_stored = builder.GetStoredFaces()

    # WHEN_AXIAL (the default): on for the vase (6-fold: its second moments are axially
    # symmetric) ...
    builder.SetRotationNodes(vtkFoldingTreeBuilder.ROTATION_NODES_WHEN_AXIAL)
    builder.Update()
    when_axial = builder.GetOutputDataObject(0)
    when_stored = builder.GetStoredFaces()
    block = axis_block(when_axial)
    check(block is not None and field(block, "FoldingRotationOrder") == ORDER and
          field(when_axial.GetBlock(1), "RotationNodesTried") == 1,
          "RotationNodes WHEN_AXIAL on the vase: a rotation root of order %s, tried" %
          field(block, "FoldingRotationOrder"))
    # ... off for the vase stretched along x (its second moments no longer axial; only 2-fold
    # left, which RotationNodes on would use): as off.
    stretched = vtkPolyData()
    stretched.DeepCopy(vase)
    points = stretched.GetPoints()
    for i in range(points.GetNumberOfPoints()):
        x, y, z = points.GetPoint(i)
        points.SetPoint(i, 1.3 * x, y, z)
    stretched_builder = vtkFoldingTreeBuilder()
    stretched_builder.SetInputData(stretched)
    stretched_builder.SetRotationNodes(vtkFoldingTreeBuilder.ROTATION_NODES_WHEN_AXIAL)
    stretched_builder.Update()
    stretched_info = stretched_builder.GetOutputDataObject(0).GetBlock(1)
    stretched_tried = field(stretched_info, "RotationNodesTried")
    stretched_rotations = field(stretched_info, "NumberOfRotations")
    stretched_faces = stretched_builder.GetStoredFaces()
    stretched_builder.SetRotationNodes(0)  # the builder refills its output: read above
    stretched_builder.Update()
    check(stretched_tried == 0 and stretched_rotations == 0 and
          stretched_faces == stretched_builder.GetStoredFaces(),
          "RotationNodes WHEN_AXIAL on the stretched vase: not tried, the tree of off (%d faces)" %
          stretched_faces)

    builder.RotationNodesOn()
    builder.Update()
    tree = builder.GetOutputDataObject(0)
    info = tree.GetBlock(1)
    check(builder.GetStoredFaces() == when_stored and when_stored < off_stored,
          "RotationNodes on stores what WHEN_AXIAL stored (%d faces; off: %d)" %
          (when_stored, off_stored))
    epsilon = field(info, "RootEpsilon")
    block = axis_block(tree)
    check(block is not None and field(block, "FoldingNodeKind") == 3,
          "the root is a rotation node (FoldingNodeKind 3)")
    check(field(block, "FoldingRotationOrder") == ORDER,
          "FoldingRotationOrder %s" % field(block, "FoldingRotationOrder"))
    direction = [field(block, "FoldingAxisDirection", c) for c in range(3)]
    origin = [field(block, "FoldingAxisOrigin", c) for c in range(3)]
    check(None not in direction and abs(abs(direction[2]) - 1.0) < 1e-4,
          "FoldingAxisDirection along z: %s" % direction)
    check(None not in origin and math.hypot(origin[0], origin[1]) < 0.01,
          "FoldingAxisOrigin on the z axis: %s" % origin)
    check(block is not None and block.GetNumberOfLines() == 1, "the Axis block draws a line")
    stored = builder.GetStoredFaces()
    check(stored <= vase.GetNumberOfCells() // ORDER + 60,
          "stores %d of %d faces (a sixth: %d)" % (stored, vase.GetNumberOfCells(),
                                                   vase.GetNumberOfCells() // ORDER))
    unfold_and_check(builder.GetOutputPort(0), vase, epsilon, "in memory")

    vtm = os.path.join(temp_dir, "TestRotationNodesPython.vtm")
    writer = vtkXMLMultiBlockDataWriter()
    writer.SetInputData(tree)
    writer.SetDataModeToBinary()
    writer.SetFileName(vtm)
    check(writer.Write() == 1, "wrote " + vtm)
    reader = vtkExpatSafeXMLMultiBlockDataReader()
    reader.SetFileName(vtm)
    unfold_and_check(reader.GetOutputPort(), vase, epsilon, ".vtm")

    fmz = os.path.join(temp_dir, "TestRotationNodesPython.fmz")
    compact = vtkFoldingTreeCompactWriter()
    compact.SetInputData(tree)
    compact.SetFileName(fmz)
    check(compact.Write() == 1, "wrote %s (%d bytes)" % (fmz, compact.GetBytesWritten()))
    compact_reader = vtkFoldingTreeCompactReader()
    compact_reader.SetFileName(fmz)
    compact_reader.Update()
    read_block = axis_block(compact_reader.GetOutput())
    check(field(read_block, "FoldingRotationOrder") == ORDER, ".fmz keeps the rotation node")
    unfold_and_check(compact_reader.GetOutputPort(), vase, epsilon, ".fmz")

    expect_rejected(tree, lambda b: b.GetFieldData().GetArray("FoldingRotationOrder").SetTuple1(0, 1),
                    "FoldingRotationOrder 1", "order 1")
    expect_rejected(tree, lambda b: b.GetFieldData().RemoveArray("FoldingAxisDirection"),
                    "rotation node without its axis metadata", "no FoldingAxisDirection")

    sphere_default()

    print("TestRotationNodesPython: %s" % ("%d failure(s)" % len(failures) if failures
                                           else "all checks passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
