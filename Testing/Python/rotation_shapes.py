"""Procedural shapes with exact rotational symmetry for the Python tests
(TestSymmetryPlaneDetectorPython, TestRotationNodesPython)."""

import math

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData


def make_twisted_vase(k, segments_per_lobe=10, rings=24, amplitude=0.15):
    """A closed vase along z in [0, 2] with k twisted lobes: r = R(z) (1 + a cos(k t + 0.9 z)).

    The only symmetries are the turns by multiples of 360/k about the z axis: the lobes
    twist (no mirror plane) and R is uneven (no half turn across the axis).
    """
    n = k * segments_per_lobe
    points, polys = vtkPoints(), vtkCellArray()
    for j in range(rings):
        z = 2.0 * (j + 0.5) / rings
        profile = 0.55 + 0.22 * math.sin(1.7 * z + 0.4) + 0.08 * z
        for i in range(n):
            t = 2.0 * math.pi * i / n
            r = profile * (1.0 + amplitude * math.cos(k * t + 0.9 * z))
            points.InsertNextPoint(r * math.cos(t), r * math.sin(t), z)
    bottom = points.InsertNextPoint(0.0, 0.0, 0.0)
    top = points.InsertNextPoint(0.0, 0.0, 2.0)

    def triangle(a, b, c):
        polys.InsertNextCell(3)
        for v in (a, b, c):
            polys.InsertCellPoint(v)

    for j in range(rings - 1):
        for i in range(n):
            a, b = j * n + i, j * n + (i + 1) % n
            c, d = b + n, a + n
            triangle(a, b, c)
            triangle(a, c, d)
    for i in range(n):
        triangle(bottom, (i + 1) % n, i)
        triangle(top, (rings - 1) * n + i, (rings - 1) * n + (i + 1) % n)
    vase = vtkPolyData()
    vase.SetPoints(points)
    vase.SetPolys(polys)
    return vase
