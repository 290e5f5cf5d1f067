#!/usr/bin/env python3
"""Reproduce the paper's Figures 1 (dino) and 4 (horse) as PNGs for the README.

    PYTHONPATH=<build>/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \
        make_paper_figures.py [--outdir docs/images] [--dino MESH] [--horse MESH]
                              [--horse-up X,Y,Z]

Writes OUTDIR/paper_fig1_dino.png, five panels like the paper's Figure 1: the original mesh;
the detected global symmetry plane (blue) with the symmetric region (green) and the support
region (yellow); the mesh coloured by the tree leaf that stands for each face (a face mirrored
away takes the colour of the leaf holding its mirror image); the leaves (the non-redundant geometry) with the mirror planes; the mesh reconstructed
from leaves and planes, coloured by the leaf each face was copied from. And
OUTDIR/paper_fig4_horse.png, the same without the detection panel (the paper's Figure 4:
original, segmentation, leaves, reconstruction). Default options of every filter; the
meshes default to Data/dino.off and ../shared/data/meshes/horse_walk_psb396.off (a walking
horse: like the paper's, not exactly symmetric, so its legs become segments of their own;
the standing horse_psb397.off folds once and stops). The camera looks across the root
folding plane from the kept half. Prints one summary line per figure.
"""

import argparse
import os
import sys

from example_scenes import (
    leaf_actors,
    leaf_lookup_table,
    mesh_actor,
    plane_actor,
    read_mesh,
    region_lookup_table,
    render_panels,
    root_plane_normal,
    tree_parts,
)
from foldingmeshes import (
    vtkFoldingTreeBuilder,
    vtkFoldingTreeUnfolder,
    vtkSymmetryPlaneDetector,
)

REPOSITORY = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
DEFAULT_DINO = os.path.join(REPOSITORY, "Data", "dino.off")
DEFAULT_HORSE = os.path.join(REPOSITORY, "..", "shared", "data", "meshes", "horse_walk_psb396.off")
PANEL_WIDTH, PANEL_HEIGHT = 300, 300


def update(algorithm, what):
    if not algorithm.GetExecutive().Update():
        raise RuntimeError(what + " failed")


def make_figure(mesh_path, png_path, with_detection, up=None, flip=False):
    """Detect, fold, unfold one mesh and render the panels; returns a summary string."""
    reader = read_mesh(mesh_path)
    detector = vtkSymmetryPlaneDetector()
    detector.SetInputConnection(reader.GetOutputPort())
    update(detector, "symmetry detection of " + mesh_path)
    builder = vtkFoldingTreeBuilder()
    builder.SetInputConnection(reader.GetOutputPort())
    update(builder, "folding of " + mesh_path)
    unfolder = vtkFoldingTreeUnfolder()
    unfolder.SetInputConnection(builder.GetOutputPort(0))
    update(unfolder, "unfolding of " + mesh_path)

    labelled, glyph = detector.GetOutput(0), detector.GetOutput(1)
    segmentation, unfolded = builder.GetOutput(1), unfolder.GetOutput()
    leaves, planes = tree_parts(builder.GetOutputDataObject(0))
    colors = leaf_lookup_table(
        leaf.GetFieldData().GetArray("FoldingNodeIndex").GetTuple1(0) for leaf in leaves)

    panels = [[mesh_actor(labelled)]]
    if with_detection:
        panels.append([mesh_actor(labelled, "SymmetryRegion", region_lookup_table()),
                       plane_actor(glyph)])
    panels += [
        [mesh_actor(segmentation, "FoldingLeafId", colors)],
        leaf_actors(leaves, colors) + [plane_actor(plane) for plane in planes],
        [mesh_actor(unfolded, "FoldingLeafId", colors)],
    ]
    render_panels(panels, PANEL_WIDTH * len(panels), PANEL_HEIGHT, png_path,
                  labelled.GetBounds(), root_plane_normal(planes, detector.GetPlaneNormal()), up, flip)
    return ("%s: plane found %s (%.0f%% of the area), %d -> %d faces (compression %.1f%%), "
            "height %d, %d leaves, %d planes; unfolded %d faces, %d open edges -> %s"
            % (os.path.basename(mesh_path), "yes" if detector.GetSymmetryFound() else "no",
               100.0 * detector.GetSymmetricAreaFraction(), builder.GetOriginalFaces(),
               builder.GetStoredFaces(), 100.0 * builder.GetCompression(),
               builder.GetTreeHeight(), len(leaves), len(planes),
               unfolded.GetNumberOfPolys(), unfolder.GetOpenEdges(), png_path))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--outdir", default=os.path.join(REPOSITORY, "docs", "images"))
    parser.add_argument("--dino", default=DEFAULT_DINO)
    parser.add_argument("--horse", default=DEFAULT_HORSE)
    parser.add_argument("--horse-up", default="0,1,0",
                        help="the horse's up direction in the picture (default 0,1,0)")
    args = parser.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    horse_up = [float(x) for x in args.horse_up.split(",")]
    # (mesh, picture, detection panel, up, camera on the other side of the up x normal axis)
    figures = ((args.dino, "paper_fig1_dino.png", True, None, True),
               (args.horse, "paper_fig4_horse.png", False, horse_up, False))
    for mesh, name, with_detection, up, flip in figures:
        if not os.path.isfile(mesh):
            print("no such mesh: %s" % mesh, file=sys.stderr)
            return 2
        print(make_figure(mesh, os.path.join(args.outdir, name), with_detection, up, flip))
    return 0


if __name__ == "__main__":
    sys.exit(main())
