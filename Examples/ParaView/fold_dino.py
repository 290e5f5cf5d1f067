"""Detect, fold and unfold a mesh with the FoldingMeshes ParaView plugin (pvpython).

    pvpython fold_dino.py [--plugin FoldingMeshes.so] [--mesh dino.off] [--output-dir DIR]

Without --plugin the plugin must already be loaded (PV_PLUGIN_PATH=<its folder>). Writes
four screenshots to the output folder: <name>_symmetry.png (the mesh coloured by
SymmetryRegion and the mirror plane), <name>_tree.png (the folding tree: leaves and fold
planes, one colour per node), <name>_segmentation.png (faces coloured by the leaf that
reproduces them) and <name>_unfolded.png (the mesh rebuilt from the tree), and prints the
results. Under a headless session run it with `xvfb-run -a pvpython ...`.
"""

import argparse
import os
import sys

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_MESH = os.path.join(HERE, "..", "..", "Data", "dino.off")


def front_camera(view, bounds):
    """Look along +y at the mesh (the dino faces -y and stands along +z)."""
    centre = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2,
              (bounds[4] + bounds[5]) / 2]
    size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
    view.CameraFocalPoint = centre
    view.CameraPosition = [centre[0] + 0.5 * size, centre[1] - 2.4 * size,
                           centre[2] + 0.5 * size]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0


def show_only(view, sources, color_by=None):
    """Shows the (source, port) pairs alone in the view; returns their displays."""
    for representation in GetRepresentations().values():
        representation.Visibility = 0
    displays = []
    for source, port in sources:
        display = Show(OutputPort(source, port), view)
        if color_by:
            ColorBy(display, color_by)
            display.SetScalarBarVisibility(view, False)
        displays.append(display)
    return displays


def save(view, bounds, path):
    Render(view)
    front_camera(view, bounds)
    SaveScreenshot(path, view, ImageResolution=[600, 450])
    print("wrote %s" % path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--plugin", help="path of FoldingMeshes.so (default: already loaded)")
    parser.add_argument("--mesh", default=DEFAULT_MESH, help="surface mesh to fold")
    parser.add_argument("--output-dir", default=".", help="folder of the screenshots")
    args = parser.parse_args()

    if args.plugin:
        LoadPlugin(args.plugin, remote=False, ns=globals())
    if "FoldingTreeBuilder" not in globals():
        sys.exit("The FoldingMeshes plugin is not loaded: pass --plugin or set PV_PLUGIN_PATH.")
    os.makedirs(args.output_dir, exist_ok=True)
    name = os.path.splitext(os.path.basename(args.mesh))[0]

    # The pipeline: reader -> detector -> builder -> unfolder.
    reader = OpenDataFile(args.mesh)
    if reader is None:
        sys.exit("ParaView cannot read " + args.mesh)
    detector = SymmetryPlaneDetector(Input=reader)
    builder = FoldingTreeBuilder(Input=OutputPort(detector, 0))
    unfolder = FoldingTreeUnfolder(Input=OutputPort(builder, 0))
    unfolder.UpdatePipeline()

    # Results: read-only properties (pulled from the server) and field data.
    for proxy in (detector, builder, unfolder):
        proxy.UpdatePropertyInformation()
    normal = list(detector.PlaneNormal)
    print("mesh %s" % args.mesh)
    print("plane found %d, normal (%.3f, %.3f, %.3f), symmetric area %.1f%%"
          % (detector.SymmetryFound, normal[0], normal[1], normal[2],
             100.0 * detector.SymmetricAreaFraction))
    print("faces %d, stored faces %d, compression %.3f, tree height %d"
          % (builder.OriginalFaces, builder.StoredFaces, builder.Compression,
             builder.TreeHeight))
    unfolded = servermanager.Fetch(unfolder)
    print("unfolded faces %d, open edges %d" % (unfolded.GetNumberOfCells(),
                                                unfolder.OpenEdges))

    # Pictures.
    view = CreateView("RenderView")
    view.OrientationAxesVisibility = 0
    bounds = reader.GetDataInformation().GetBounds()
    # Categorical colours: SymmetryRegion 0 outside, 1 support only, 2 symmetric.
    regions = GetColorTransferFunction("SymmetryRegion")
    regions.InterpretValuesAsCategories = 1
    regions.Annotations = ["0", "outside", "1", "support", "2", "symmetric"]
    regions.IndexedColors = [0.70, 0.70, 0.70, 0.95, 0.55, 0.15, 0.25, 0.50, 0.85]
    leaves = GetColorTransferFunction("FoldingLeafId")
    leaves.ApplyPreset("Rainbow Uniform", True)
    leaf_range = OutputPort(builder, 1).GetDataInformation().GetCellDataInformation() \
        .GetArrayInformation("FoldingLeafId").GetComponentRange(0)
    leaves.RescaleTransferFunction(leaf_range[0], max(leaf_range[1], leaf_range[0] + 1))
    mesh_display, plane_display = show_only(view, [(detector, 0), (detector, 1)],
                                            color_by=("CELLS", "SymmetryRegion"))
    plane_display.ColorArrayName = [None, ""]
    plane_display.Representation = "Surface"
    plane_display.Opacity = 0.4
    save(view, bounds, os.path.join(args.output_dir, name + "_symmetry.png"))
    # The tree: leaves and fold planes, one colour per node (the FIELD array
    # FoldingNodeIndex holds one value per block).
    show_only(view, [(builder, 0)], color_by=("FIELD", "FoldingNodeIndex"))
    nodes = GetColorTransferFunction("FoldingNodeIndex")
    nodes.ApplyPreset("Rainbow Uniform", True)
    node_range = OutputPort(builder, 0).GetDataInformation().GetFieldDataInformation() \
        .GetArrayInformation("FoldingNodeIndex").GetComponentRange(0)
    nodes.RescaleTransferFunction(node_range[0], max(node_range[1], node_range[0] + 1))
    # Look at the kept half from its own side of the root plane (the plane quads would
    # hide it from the other side).
    tree_bounds = OutputPort(builder, 0).GetDataInformation().GetBounds()
    origin = list(detector.PlaneOrigin)
    side = sum(n * ((tree_bounds[2 * i] + tree_bounds[2 * i + 1]) / 2 - origin[i])
               for i, n in enumerate(normal))
    side = 1.0 if side >= 0 else -1.0
    Render(view)
    centre = [(bounds[2 * i] + bounds[2 * i + 1]) / 2 for i in range(3)]
    size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
    view.CameraFocalPoint = centre
    view.CameraPosition = [c + 2.2 * size * side * n - (0.8 * size if i == 1 else 0.0)
                           for i, (c, n) in enumerate(zip(centre, normal))]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    path = os.path.join(args.output_dir, name + "_tree.png")
    SaveScreenshot(path, view, ImageResolution=[600, 450])
    print("wrote %s" % path)
    show_only(view, [(builder, 1)], color_by=("CELLS", "FoldingLeafId"))
    save(view, bounds, os.path.join(args.output_dir, name + "_segmentation.png"))
    show_only(view, [(unfolder, 0)], color_by=("CELLS", "FoldingLeafId"))
    save(view, bounds, os.path.join(args.output_dir, name + "_unfolded.png"))
    Delete(view)


if __name__ == "__main__":
    main()
