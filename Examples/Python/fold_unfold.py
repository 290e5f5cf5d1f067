#!/usr/bin/env python3
"""Fold a mesh into a folding tree, save it, read it back and unfold it (paper, section 4).

    PYTHONPATH=<build>/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \
        fold_unfold.py MESH [--outdir DIR] [--tolerance F] [--min-area-fraction F] [--rotation]

Writes, in DIR: STEM_tree.vtm (the folding tree; its pieces go to STEM_tree/),
STEM_segmentation.vtp (the mesh with cell arrays FoldingLeafId, FoldingDepth, FoldingRole),
STEM_unfolded.vtp (the mesh rebuilt from the tree read back from STEM_tree.vtm) and
STEM_fold_unfold.png (left: the mesh coloured by the leaf storing each face, grey where a
fold mirrored it away; middle: the leaves and the mirror planes; right: the reconstruction,
coloured by the leaf each face was copied from). Prints a summary.
"""

import argparse
import os
import sys

from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter, vtkXMLPolyDataWriter

from example_scenes import (
    leaf_actors,
    leaf_lookup_table,
    mesh_actor,
    plane_actor,
    read_mesh,
    render_panels,
    root_plane_normal,
    tree_parts,
)
from foldingmeshes import (
    vtkExpatSafeXMLMultiBlockDataReader,
    vtkFoldingTreeBuilder,
    vtkFoldingTreeUnfolder,
)


def field_value(data, name):
    return data.GetFieldData().GetArray(name).GetTuple1(0)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("mesh")
    parser.add_argument("--outdir", default=".")
    parser.add_argument("--tolerance", type=float, default=0.02,
                        help="root epsilon as a fraction of the diagonal (default 0.02)")
    parser.add_argument("--min-area-fraction", type=float, default=0.05,
                        help="leaf when a region's area is below this fraction (default 0.05)")
    parser.add_argument("--rotation", action="store_true",
                        help="rotation nodes on any mesh: keep one sector of a rotational "
                             "symmetry (vtkFoldingTreeBuilder.RotationNodes on; default: only "
                             "where the mesh's second moments are axially symmetric)")
    args = parser.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    stem = os.path.join(args.outdir, os.path.splitext(os.path.basename(args.mesh))[0])

    # Fold: output 0 is the tree, output 1 the input labelled by leaf.
    reader = read_mesh(args.mesh)  # keep a reference: the pipeline does not own it
    builder = vtkFoldingTreeBuilder()
    builder.SetInputConnection(reader.GetOutputPort())
    builder.SetTolerance(args.tolerance)
    builder.SetMinimumAreaFraction(args.min_area_fraction)
    if args.rotation:
        builder.RotationNodesOn()
    if not builder.GetExecutive().Update():
        print("folding failed on %s" % args.mesh, file=sys.stderr)
        return 2
    tree, segmentation = builder.GetOutputDataObject(0), builder.GetOutput(1)
    summary = tree.GetBlock(1)  # the "Tree" block: field data with the tree's numbers
    print("folded: %d faces -> %d stored, compression %.1f%%, tree height %d, "
          "%d folds, %d leaves, %.2f s"
          % (builder.GetOriginalFaces(), builder.GetStoredFaces(),
             100.0 * builder.GetCompression(), builder.GetTreeHeight(),
             field_value(summary, "NumberOfFolds"), field_value(summary, "NumberOfLeaves"),
             field_value(summary, "BuildSeconds")))

    # Inline binary data: Debian 12's ParaView 5.11 (VTK 9.2) cannot read the writers'
    # default appended mode with a current libexpat1 (VTK issue 19258).
    tree_writer = vtkXMLMultiBlockDataWriter()
    tree_writer.SetInputData(tree)
    tree_writer.SetFileName(stem + "_tree.vtm")
    tree_writer.SetDataModeToBinary()
    segmentation_writer = vtkXMLPolyDataWriter()
    segmentation_writer.SetInputData(segmentation)
    segmentation_writer.SetFileName(stem + "_segmentation.vtp")
    segmentation_writer.SetDataModeToBinary()
    if not (tree_writer.Write() and segmentation_writer.Write()):
        print("cannot write in %s" % args.outdir, file=sys.stderr)
        return 3

    # Unfold the tree read back from disk: the file holds everything the unfolder needs.
    # The expat-safe reader also reads trees saved in appended mode.
    tree_reader = vtkExpatSafeXMLMultiBlockDataReader()
    tree_reader.SetFileName(stem + "_tree.vtm")
    unfolder = vtkFoldingTreeUnfolder()
    unfolder.SetInputConnection(tree_reader.GetOutputPort())
    if not unfolder.GetExecutive().Update():
        print("unfolding failed", file=sys.stderr)
        return 2
    unfolded = unfolder.GetOutput()
    print("unfolded: %d faces, %d points, %d open edges, %d stitched vertices, %d open gaps"
          % (unfolded.GetNumberOfPolys(), unfolded.GetNumberOfPoints(), unfolder.GetOpenEdges(),
             unfolder.GetStitchedVertices(), unfolder.GetOpenGapCount()))
    unfolded_writer = vtkXMLPolyDataWriter()
    unfolded_writer.SetInputData(unfolded)
    unfolded_writer.SetFileName(stem + "_unfolded.vtp")
    unfolded_writer.SetDataModeToBinary()
    if not unfolded_writer.Write():
        return 3

    leaves, planes = tree_parts(tree)
    colors = leaf_lookup_table(field_value(leaf, "FoldingNodeIndex") for leaf in leaves)
    panels = [
        [mesh_actor(segmentation, "FoldingLeafId", colors)],
        leaf_actors(leaves, colors) + [plane_actor(plane) for plane in planes],
        [mesh_actor(unfolded, "FoldingLeafId", colors)],
    ]
    render_panels(panels, 1200, 450, stem + "_fold_unfold.png", segmentation.GetBounds(),
                  root_plane_normal(planes))
    print("wrote %s_tree.vtm, %s_segmentation.vtp, %s_unfolded.vtp, %s_fold_unfold.png"
          % (stem, stem, stem, stem))
    return 0


if __name__ == "__main__":
    sys.exit(main())
