#!/usr/bin/env python3
"""TestSymmetryPlaneDetectorPython: the Python-wrapped vtkSymmetryPlaneDetector.

A procedural mesh with exactly one mirror plane (an ellipsoid with bumps placed in
mirror pairs about x = 0, plus one bump on the +x side only) is moved by a known
rotation + translation. The test checks that

- the detected plane normal is within 1 degree of the rotated x axis and the
  plane passes through the moved origin, SymmetricAreaFraction > 0.9;
- the output arrays (SymmetryRegion, SymmetryDistance, SymmetryWeight) and the
  field data arrays exist with the right sizes, on both output ports;
- with DetectRotation, a twisted 5-fold vase (no mirror plane) moved by the same motion
  gives order 5 about the moved z axis, the rotation arrays and field data, and a
  line glyph on the axis (output 2); without it output 2 is empty and no Rotation
  array is added;
- bad input (an empty vtkPolyData, a polydata with only lines) makes the update
  fail with an error, without crashing;
- the rendering of the region colouring and the plane glyph matches the
  baseline TestSymmetryPlaneDetectorPython.png.

Run with /usr/bin/python3 and PYTHONPATH=<build>/lib/python3/dist-packages:
    TestSymmetryPlaneDetectorPython.py -B <baseline dir> -T <temp dir>
"""

import math

# Rendering back-end and interactor style factories must be loaded before any
# render window is created.
import vtkmodules.vtkInteractionStyle  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.test import Testing
from vtkmodules.vtkCommonCore import vtkLookupTable, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource
from rotation_shapes import make_twisted_vase
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
)

from foldingmeshes import vtkSymmetryPlaneDetector

# Bumps (direction of the centre, height, width^2): mirror pairs about x = 0 and
# one on the plane keep the mirror symmetry and break every other one; the last
# bump, on the +x side only, makes a small asymmetric region.
SYMMETRIC_BUMPS = [
    ((0.55, 0.45, 0.35), 0.6, 0.04),
    ((-0.55, 0.45, 0.35), 0.6, 0.04),
    ((0.0, -0.6, 0.5), 0.35, 0.04),
    ((0.3, -0.2, -0.7), 0.4, 0.04),
    ((-0.3, -0.2, -0.7), 0.4, 0.04),
]
ASYMMETRIC_BUMP = ((0.6, -0.55, 0.1), 0.3, 0.02)
SEMI_AXES = (1.0, 0.8, 0.6)


def make_symmetric_mesh(with_asymmetry=True):
    """A bumpy ellipsoid, mirror-symmetric about x = 0 (plus an optional bump).

    vtkSphereSource with an even theta resolution starts at theta = 0 on the x
    axis, so its tessellation itself is mirror-symmetric about x = 0.
    """
    sphere = vtkSphereSource()
    sphere.SetRadius(1.0)
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(32)
    sphere.Update()
    mesh = vtkPolyData()
    mesh.DeepCopy(sphere.GetOutput())
    mesh.GetPointData().Initialize()  # drop the sphere's normals: they no longer fit
    bumps = SYMMETRIC_BUMPS + ([ASYMMETRIC_BUMP] if with_asymmetry else [])
    points = vtkPoints()
    points.SetDataTypeToDouble()
    source = mesh.GetPoints()
    for i in range(source.GetNumberOfPoints()):
        p = source.GetPoint(i)
        radius = 1.0
        for direction, height, width2 in bumps:
            length = math.sqrt(sum(c * c for c in direction))
            d2 = sum((p[k] - direction[k] / length) ** 2 for k in range(3))
            radius += height * math.exp(-d2 / width2)
        points.InsertNextPoint(*(p[k] * radius * SEMI_AXES[k] for k in range(3)))
    mesh.SetPoints(points)
    return mesh


def make_transform():
    """The known rigid motion applied to the mesh (true plane: its image of x = 0)."""
    transform = vtkTransform()
    transform.Translate(0.3, -0.2, 0.5)
    transform.RotateWXYZ(35.0, 1.0, 2.0, 3.0)
    return transform


class ErrorObserver:
    """Records the error messages of a VTK object (and keeps them off stderr)."""

    def __init__(self):
        self.messages = []
        self.CallDataType = "string0"  # VTK passes the message (call data) as a str

    def __call__(self, caller, event, message=None):
        self.messages.append(message)

    def attach(self, vtk_object):
        vtk_object.AddObserver("ErrorEvent", self)
        return self


def angle_between_lines_deg(a, b):
    """Angle between two directions, ignoring orientation (a plane normal's sign is free)."""
    na = math.sqrt(sum(x * x for x in a))
    nb = math.sqrt(sum(x * x for x in b))
    c = abs(sum(x * y for x, y in zip(a, b))) / (na * nb)
    return math.degrees(math.acos(min(1.0, c)))


class TestSymmetryPlaneDetectorPython(Testing.vtkTest):
    def setUp(self):
        self.transform = make_transform()
        self.moved = vtkTransformPolyDataFilter()
        self.moved.SetInputData(make_symmetric_mesh())
        self.moved.SetTransform(self.transform)
        self.detector = vtkSymmetryPlaneDetector()
        self.detector.SetInputConnection(self.moved.GetOutputPort())

    def run_detector(self):
        self.assertEqual(self.detector.GetExecutive().Update(), 1)
        return self.detector.GetOutput(0), self.detector.GetOutput(1)

    def testDefaults(self):
        d = vtkSymmetryPlaneDetector()
        self.assertAlmostEqual(d.GetTolerance(), 0.02)
        self.assertEqual(d.GetToleranceMode(), vtkSymmetryPlaneDetector.RELATIVE_TO_DIAGONAL)
        self.assertEqual(d.GetMethod(), vtkSymmetryPlaneDetector.ROBUST)
        self.assertFalse(d.GetUseInitialPlane())
        self.assertEqual(d.GetInitialPlaneOrigin(), (0.0, 0.0, 0.0))
        self.assertEqual(d.GetInitialPlaneNormal(), (1.0, 0.0, 0.0))
        self.assertEqual(d.GetNumberOfCandidates(), 8)
        self.assertEqual(d.GetMaximumIterations(), 50)
        self.assertAlmostEqual(d.GetCompatibilityAngle(), 45.0)
        self.assertTrue(d.GetConnectNearbyParts())
        self.assertAlmostEqual(d.GetMinimumSymmetricAreaFraction(), 0.1)
        self.assertEqual(d.GetRandomSeed(), 1)
        # The setters clamp like the ParaView domains say.
        d.SetNumberOfCandidates(1000)
        self.assertEqual(d.GetNumberOfCandidates(), 64)
        d.SetCompatibilityAngle(0.0)
        self.assertAlmostEqual(d.GetCompatibilityAngle(), 1.0)

    def testDetectsRotatedPlane(self):
        self.run_detector()
        truth = self.transform.TransformVector(1.0, 0.0, 0.0)
        normal = self.detector.GetPlaneNormal()
        origin = self.detector.GetPlaneOrigin()
        error = angle_between_lines_deg(normal, truth)
        self.assertLess(error, 1.0, "normal %s vs truth %s: %.3f deg" % (normal, truth, error))
        # The plane must pass through the image of the origin (which lies on x = 0).
        centre = self.transform.TransformPoint(0.0, 0.0, 0.0)
        offset = abs(sum((c - o) * n for c, o, n in zip(centre, origin, normal)))
        self.assertLess(offset, 0.01)
        self.assertGreater(self.detector.GetSymmetricAreaFraction(), 0.9)
        self.assertLess(self.detector.GetSymmetricAreaFraction(), 1.0)  # the odd bump
        self.assertTrue(self.detector.GetSymmetryFound())

    def testOutputArrays(self):
        mesh, glyph = self.run_detector()
        n_points = self.moved.GetOutput().GetNumberOfPoints()
        n_triangles = self.moved.GetOutput().GetNumberOfPolys()  # already triangles
        self.assertEqual(mesh.GetNumberOfPoints(), n_points)
        self.assertEqual(mesh.GetNumberOfCells(), n_triangles)

        region = mesh.GetCellData().GetArray("SymmetryRegion")
        self.assertIsNotNone(region)
        self.assertEqual(region.GetNumberOfTuples(), n_triangles)
        self.assertEqual(region.GetNumberOfComponents(), 1)
        low, high = region.GetRange()
        self.assertGreaterEqual(low, 0)
        self.assertLessEqual(high, 2)
        self.assertEqual(high, 2)
        self.assertEqual(mesh.GetCellData().GetScalars().GetName(), "SymmetryRegion")
        for name in ("SymmetryDistance", "SymmetryWeight"):
            array = mesh.GetPointData().GetArray(name)
            self.assertIsNotNone(array, name)
            self.assertEqual(array.GetNumberOfTuples(), n_points, name)
            self.assertEqual(array.GetNumberOfComponents(), 1, name)
            self.assertGreaterEqual(array.GetRange()[0], 0.0, name)

        plane_field = {
            "SymmetryPlaneOrigin": 3,
            "SymmetryPlaneNormal": 3,
            "SymmetricAreaFraction": 1,
            "SymmetryFound": 1,
            "SymmetryTolerance": 1,
        }
        mesh_field = dict(plane_field, SymmetryIterations=2)
        for data, expected_field in ((mesh, mesh_field), (glyph, plane_field)):
            field = data.GetFieldData()
            for name, components in expected_field.items():
                array = field.GetArray(name)
                self.assertIsNotNone(array, name)
                self.assertEqual(array.GetNumberOfTuples(), 1, name)
                self.assertEqual(array.GetNumberOfComponents(), components, name)
        history = mesh.GetFieldData().GetArray("SymmetryCostHistory")
        self.assertIsNotNone(history)
        iterations = mesh.GetFieldData().GetArray("SymmetryIterations").GetTuple2(0)
        self.assertEqual(history.GetNumberOfTuples(), int(iterations[0] + iterations[1]))

        # Field data agree with the getters.
        normal = self.detector.GetPlaneNormal()
        field_normal = mesh.GetFieldData().GetArray("SymmetryPlaneNormal").GetTuple3(0)
        self.assertLess(angle_between_lines_deg(normal, field_normal), 1e-9)
        self.assertAlmostEqual(
            mesh.GetFieldData().GetArray("SymmetricAreaFraction").GetValue(0),
            self.detector.GetSymmetricAreaFraction())

        # The plane glyph: one quad lying on the plane.
        self.assertEqual(glyph.GetNumberOfPoints(), 4)
        self.assertEqual(glyph.GetNumberOfPolys(), 1)
        origin = self.detector.GetPlaneOrigin()
        for i in range(4):
            p = glyph.GetPoint(i)
            self.assertLess(abs(sum((a - b) * c for a, b, c in zip(p, origin, normal))), 1e-6)

    def testRotation(self):
        # Without DetectRotation: nothing about rotations.
        mesh, _ = self.run_detector()
        self.assertIsNone(mesh.GetCellData().GetArray("RotationRegion"))
        self.assertIsNone(mesh.GetFieldData().GetArray("RotationOrder"))
        self.assertEqual(self.detector.GetOutput(2).GetNumberOfPoints(), 0)
        self.assertEqual(self.detector.GetRotationOrder(), 0)

        moved = vtkTransformPolyDataFilter()
        moved.SetInputData(make_twisted_vase(5))
        moved.SetTransform(self.transform)
        detector = vtkSymmetryPlaneDetector()
        detector.SetInputConnection(moved.GetOutputPort())
        self.assertFalse(detector.GetDetectRotation())
        self.assertEqual(detector.GetMaximumRotationOrder(), 64)
        detector.DetectRotationOn()
        self.assertEqual(detector.GetExecutive().Update(), 1)
        self.assertEqual(detector.GetRotationOrder(), 5)
        self.assertTrue(detector.GetRotationFound())
        self.assertFalse(detector.GetRotationContinuous())
        self.assertGreater(detector.GetRotationalAreaFraction(), 0.95)
        truth = self.transform.TransformVector(0.0, 0.0, 1.0)
        direction = detector.GetRotationAxisDirection()
        self.assertLess(angle_between_lines_deg(direction, truth), 0.1)
        # The moved origin lies on the found axis.
        centre = self.transform.TransformPoint(0.0, 0.0, 0.0)
        origin = detector.GetRotationAxisOrigin()
        r = [c - o for c, o in zip(centre, origin)]
        along = sum(x * d for x, d in zip(r, direction))
        off = math.sqrt(max(0.0, sum(x * x for x in r) - along * along))
        self.assertLess(off, 1e-3)

        mesh = detector.GetOutput(0)
        region = mesh.GetCellData().GetArray("RotationRegion")
        self.assertIsNotNone(region)
        self.assertEqual(region.GetNumberOfTuples(), mesh.GetNumberOfCells())
        distance = mesh.GetPointData().GetArray("RotationDistance")
        self.assertIsNotNone(distance)
        self.assertEqual(distance.GetNumberOfTuples(), mesh.GetNumberOfPoints())
        # SymmetryRegion stays the active scalars.
        self.assertEqual(mesh.GetCellData().GetScalars().GetName(), "SymmetryRegion")
        axis = detector.GetOutput(2)
        self.assertEqual(axis.GetNumberOfPoints(), 2)
        self.assertEqual(axis.GetNumberOfLines(), 1)
        for data in (mesh, axis):
            field = data.GetFieldData()
            self.assertEqual(field.GetArray("RotationOrder").GetValue(0), 5)
            self.assertEqual(field.GetArray("RotationFound").GetValue(0), 1)
            self.assertEqual(field.GetArray("RotationContinuous").GetValue(0), 0)
            self.assertEqual(field.GetArray("RotationAxisOrigin").GetNumberOfComponents(), 3)
            self.assertLess(angle_between_lines_deg(
                field.GetArray("RotationAxisDirection").GetTuple3(0), direction), 1e-9)
        # Both glyph points lie on the axis, and the line covers the vase (height 2).
        p0, p1 = axis.GetPoint(0), axis.GetPoint(1)
        self.assertGreater(math.dist(p0, p1), 2.0)
        for p in (p0, p1):
            r = [a - o for a, o in zip(p, origin)]
            along = sum(x * d for x, d in zip(r, direction))
            self.assertLess(math.sqrt(max(0.0, sum(x * x for x in r) - along * along)), 1e-6)

    def check_update_fails(self, data):
        detector = vtkSymmetryPlaneDetector()
        detector.SetInputData(data)
        algorithm_errors = ErrorObserver().attach(detector)
        ErrorObserver().attach(detector.GetExecutive())  # "returned failure for request"
        self.assertEqual(detector.GetExecutive().Update(), 0)
        self.assertTrue(algorithm_errors.messages, "no error reported")
        print("expected error:", str(algorithm_errors.messages[0]).strip())
        # The filter must stay usable afterwards.
        detector.SetInputConnection(self.moved.GetOutputPort())
        self.assertEqual(detector.GetExecutive().Update(), 1)

    def testEmptyInputFails(self):
        self.check_update_fails(vtkPolyData())

    def testLinesOnlyInputFails(self):
        points = vtkPoints()
        lines = vtkCellArray()
        for i in range(10):
            points.InsertNextPoint(math.cos(i), math.sin(i), 0.1 * i)
        for i in range(9):
            lines.InsertNextCell(2)
            lines.InsertCellPoint(i)
            lines.InsertCellPoint(i + 1)
        data = vtkPolyData()
        data.SetPoints(points)
        data.SetLines(lines)
        self.check_update_fails(data)

    def testImage(self):
        mesh, glyph = self.run_detector()

        # SymmetryRegion: 0 outside (grey), 1 support only (orange), 2 symmetric (blue).
        lut = vtkLookupTable()
        lut.SetNumberOfTableValues(3)
        lut.SetTableRange(0.0, 2.0)
        lut.SetTableValue(0, 0.70, 0.70, 0.70, 1.0)
        lut.SetTableValue(1, 0.95, 0.55, 0.15, 1.0)
        lut.SetTableValue(2, 0.25, 0.50, 0.85, 1.0)
        lut.Build()
        mesh_mapper = vtkPolyDataMapper()
        mesh_mapper.SetInputData(mesh)
        mesh_mapper.SetScalarModeToUseCellFieldData()
        mesh_mapper.SelectColorArray("SymmetryRegion")
        mesh_mapper.SetLookupTable(lut)
        mesh_mapper.SetScalarRange(0.0, 2.0)
        mesh_mapper.ScalarVisibilityOn()
        mesh_actor = vtkActor()
        mesh_actor.SetMapper(mesh_mapper)

        # The plane glyph: translucent quad plus its opaque outline.
        plane_mapper = vtkPolyDataMapper()
        plane_mapper.SetInputData(glyph)
        plane_mapper.ScalarVisibilityOff()
        plane_actor = vtkActor()
        plane_actor.SetMapper(plane_mapper)
        plane_actor.GetProperty().SetColor(1.0, 1.0, 0.9)
        plane_actor.GetProperty().SetOpacity(0.4)
        outline_actor = vtkActor()
        outline_actor.SetMapper(plane_mapper)
        outline_actor.GetProperty().SetRepresentationToWireframe()
        outline_actor.GetProperty().SetColor(0.1, 0.1, 0.1)
        outline_actor.GetProperty().SetLineWidth(2.0)
        outline_actor.GetProperty().LightingOff()

        renderer = vtkRenderer()
        renderer.SetBackground(1.0, 1.0, 1.0)
        renderer.AddActor(mesh_actor)
        renderer.AddActor(plane_actor)
        renderer.AddActor(outline_actor)
        window = vtkRenderWindow()
        window.SetOffScreenRendering(1)
        window.SetMultiSamples(0)
        window.SetSize(400, 300)
        window.AddRenderer(renderer)

        # Fixed camera, expressed in the mesh's own frame and moved with it: looking
        # obliquely at the mirror plane from the -y side, a little towards +x.
        camera = renderer.GetActiveCamera()
        camera.SetFocalPoint(self.transform.TransformPoint(0.0, 0.0, 0.0))
        camera.SetPosition(self.transform.TransformPoint(1.6, -5.5, 3.0))
        camera.SetViewUp(self.transform.TransformVector(0.0, 0.0, 1.0))
        camera.SetViewAngle(30.0)
        renderer.ResetCameraClippingRange()
        window.Render()

        # Fails (raises) when the image differs from the baseline or the baseline is
        # missing; the test image, baseline and difference go to the -T directory.
        Testing.compareImage(window, Testing.getAbsImagePath("TestSymmetryPlaneDetectorPython.png"))


if __name__ == "__main__":
    Testing.main([(TestSymmetryPlaneDetectorPython, "test")])
