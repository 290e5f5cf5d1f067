"""Fold every mesh of a folder with the FoldingMeshes ParaView plugin; write a CSV summary.

    pvbatch fold_folder.py FOLDER [--plugin FoldingMeshes.so] [--csv summary.csv]
                           [--tolerance 0.02]

Reads every .off, .obj, .ply, .stl and .vtp file of FOLDER (sorted by name), runs Symmetry
Plane Detector, Folding Tree Builder and Folding Tree Unfolder on it and writes one CSV row
per mesh (columns: see COLUMNS). A mesh that fails is reported in the "error" column and the
run goes on. "hausdorff" is the unfolder's HausdorffToOriginal when the unfolder takes the
original mesh (its optional "Original" input), else empty. Without --plugin the plugin must
already be loaded (PV_PLUGIN_PATH=<its folder>). Exit status: 0 when every mesh was folded.
"""

import argparse
import csv
import glob
import os
import sys
import time

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403

EXTENSIONS = (".off", ".obj", ".ply", ".stl", ".vtp")
COLUMNS = ["file", "faces", "plane_found", "normal_x", "normal_y", "normal_z",
           "symmetric_area_fraction", "stored_faces", "compression", "tree_height",
           "unfolded_faces", "open_edges", "hausdorff", "detect_seconds", "build_seconds",
           "unfold_seconds", "error"]


def timed_update(proxy):
    start = time.perf_counter()
    proxy.UpdatePipeline()
    return time.perf_counter() - start


def as_surface(reader):
    """The reader's output as one vtkPolyData (readers of some formats give other types)."""
    source = reader
    info = reader.GetDataInformation()
    if info.IsCompositeDataSet():
        source = MergeBlocks(Input=source)
    if info.GetDataSetTypeAsString() != "vtkPolyData" or info.IsCompositeDataSet():
        source = ExtractSurface(Input=source)
    return source


def takes_original(unfolder):
    """Whether the server-side unfolder has the optional second input port."""
    return unfolder.GetClientSideObject().GetNumberOfInputPorts() >= 2


def fold_one(path, tolerance):
    row = {"file": os.path.basename(path)}
    created = []
    try:
        reader = OpenDataFile(path)
        if reader is None:
            raise RuntimeError("no ParaView reader for this file")
        created.append(reader)
        reader.UpdatePipeline()
        surface = as_surface(reader)
        if surface is not reader:
            created.append(surface)
        detector = SymmetryPlaneDetector(Input=surface, Tolerance=tolerance)
        builder = FoldingTreeBuilder(Input=OutputPort(detector, 0), Tolerance=tolerance)
        unfolder = FoldingTreeUnfolder(Input=OutputPort(builder, 0))
        created += [unfolder, builder, detector]
        if takes_original(unfolder):
            unfolder.Original = surface
        row["detect_seconds"] = "%.3f" % timed_update(detector)
        row["build_seconds"] = "%.3f" % timed_update(builder)
        row["unfold_seconds"] = "%.3f" % timed_update(unfolder)
        for proxy in (detector, builder, unfolder):
            proxy.UpdatePropertyInformation()
        normal = list(detector.PlaneNormal)
        row.update({
            "faces": builder.OriginalFaces,
            "plane_found": detector.SymmetryFound,
            "normal_x": "%.6f" % normal[0], "normal_y": "%.6f" % normal[1],
            "normal_z": "%.6f" % normal[2],
            "symmetric_area_fraction": "%.4f" % detector.SymmetricAreaFraction,
            "stored_faces": builder.StoredFaces,
            "compression": "%.4f" % builder.Compression,
            "tree_height": builder.TreeHeight,
            "open_edges": unfolder.OpenEdges,
        })
        unfolded = servermanager.Fetch(unfolder)
        row["unfolded_faces"] = unfolded.GetNumberOfCells()
        hausdorff = unfolded.GetFieldData().GetArray("HausdorffToOriginal")
        row["hausdorff"] = "%.6g" % hausdorff.GetTuple1(0) if hausdorff is not None else ""
        if builder.OriginalFaces == 0:
            raise RuntimeError("the pipeline failed (see the messages above)")
    except Exception as error:  # report the mesh (no partial values) and go on
        row = {"file": row["file"], "error": str(error).replace("\n", " ")}
    for proxy in created:
        Delete(proxy)
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", help="folder of meshes")
    parser.add_argument("--plugin", help="path of FoldingMeshes.so (default: already loaded)")
    parser.add_argument("--csv", default="folding_summary.csv", help="CSV file to write")
    parser.add_argument("--tolerance", type=float, default=0.02,
                        help="relative tolerance of detection and folding (default 0.02)")
    args = parser.parse_args()

    if args.plugin:
        LoadPlugin(args.plugin, remote=False, ns=globals())
    if "FoldingTreeBuilder" not in globals():
        sys.exit("The FoldingMeshes plugin is not loaded: pass --plugin or set PV_PLUGIN_PATH.")
    meshes = sorted(p for p in glob.glob(os.path.join(args.folder, "*"))
                    if p.lower().endswith(EXTENSIONS))
    if not meshes:
        sys.exit("No mesh (%s) in %s" % (" ".join(EXTENSIONS), args.folder))

    rows = []
    for path in meshes:
        row = fold_one(path, args.tolerance)
        rows.append(row)
        print("%-32s faces %6s  plane %s  stored %6s  compression %6s  height %2s  %s"
              % (row["file"], row.get("faces", ""), row.get("plane_found", ""),
                 row.get("stored_faces", ""), row.get("compression", ""),
                 row.get("tree_height", ""), row.get("error", "")))
    with open(args.csv, "w", newline="") as stream:
        writer = csv.DictWriter(stream, fieldnames=COLUMNS, restval="")
        writer.writeheader()
        writer.writerows(rows)
    print("wrote %s (%d meshes)" % (args.csv, len(rows)))
    return 1 if any(row.get("error") for row in rows) else 0


if __name__ == "__main__":
    sys.exit(main())
