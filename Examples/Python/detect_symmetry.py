#!/usr/bin/env python3
"""Find the dominant mirror plane of a mesh and its symmetric region (paper, section 3).

    PYTHONPATH=<build>/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \
        detect_symmetry.py MESH [--outdir DIR] [--tolerance F]

Writes, in DIR: STEM_symmetry.vtp (the mesh with cell array SymmetryRegion: 2 symmetric,
1 support only, 0 outside), STEM_plane.vtp (a quad on the plane) and STEM_symmetry.png
(green: symmetric region, yellow: support only, grey: outside, blue: the plane). Prints the
plane; exits with 0 when a symmetry was found, 2 when not (or the mesh cannot be read).
"""

import argparse
import os
import sys

from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

from example_scenes import mesh_actor, plane_actor, read_mesh, region_lookup_table, render_panels
from foldingmeshes import vtkSymmetryPlaneDetector


def write_polydata(data, path):
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(data)
    writer.SetFileName(path)
    # Inline binary data: Debian 12's ParaView 5.11 (VTK 9.2) cannot read the writers'
    # default appended mode with a current libexpat1 (VTK issue 19258).
    writer.SetDataModeToBinary()
    if not writer.Write():
        raise OSError("cannot write " + path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("mesh")
    parser.add_argument("--outdir", default=".")
    parser.add_argument("--tolerance", type=float, default=0.02,
                        help="epsilon as a fraction of the bounding-box diagonal (default 0.02)")
    args = parser.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    stem = os.path.join(args.outdir, os.path.splitext(os.path.basename(args.mesh))[0])

    reader = read_mesh(args.mesh)  # keep a reference: the pipeline does not own it
    detector = vtkSymmetryPlaneDetector()
    detector.SetInputConnection(reader.GetOutputPort())
    detector.SetTolerance(args.tolerance)
    if not detector.GetExecutive().Update():
        print("symmetry detection failed on %s" % args.mesh, file=sys.stderr)
        return 2
    mesh, glyph = detector.GetOutput(0), detector.GetOutput(1)

    origin, normal = detector.GetPlaneOrigin(), detector.GetPlaneNormal()
    print("plane origin %.4f %.4f %.4f normal %.4f %.4f %.4f" % (origin + normal))
    print("symmetric area %.1f%%, symmetry found: %s, iterations %d coarse + %d fine"
          % (100.0 * detector.GetSymmetricAreaFraction(),
             "yes" if detector.GetSymmetryFound() else "no",
             detector.GetCoarseIterations(), detector.GetFineIterations()))

    write_polydata(mesh, stem + "_symmetry.vtp")
    write_polydata(glyph, stem + "_plane.vtp")
    panels = [[mesh_actor(mesh, "SymmetryRegion", region_lookup_table()), plane_actor(glyph)]]
    render_panels(panels, 600, 500, stem + "_symmetry.png", mesh.GetBounds(), normal)
    print("wrote %s_symmetry.vtp, %s_plane.vtp, %s_symmetry.png" % (stem, stem, stem))
    return 0 if detector.GetSymmetryFound() else 2


if __name__ == "__main__":
    sys.exit(main())
