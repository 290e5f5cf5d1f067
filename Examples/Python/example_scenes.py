"""Reading meshes and rendering FoldingMeshes results off screen (used by the examples).

Plain vtkmodules; nothing here is specific to one example. Rendering needs a display
(run under ``xvfb-run -a`` on a headless machine).
"""

import math
import os

# The OpenGL back-end registers the render window factories; import it before rendering.
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkmodules.vtkCommonCore import vtkLookupTable, vtkVariant
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkDataObjectTreeIterator, vtkPolyData
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOLegacy import vtkPolyDataReader
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)

# vtkExpatSafeXMLPolyDataReader: vtkXMLPolyDataReader that also reads appended-mode files
# with Debian 12's current libexpat1 (VTK issue 19258).
from foldingmeshes import vtkExpatSafeXMLPolyDataReader, vtkOFFReader

READERS = {
    ".off": vtkOFFReader,
    ".obj": vtkOBJReader,
    ".ply": vtkPLYReader,
    ".stl": vtkSTLReader,
    ".vtp": vtkExpatSafeXMLPolyDataReader,
    ".vtk": vtkPolyDataReader,
}

# Qualitative palette (ColorBrewer Set1/Set2-like) for leaves; cycled when there are more.
PALETTE = [
    (0.89, 0.10, 0.11), (0.22, 0.49, 0.72), (0.30, 0.69, 0.29), (0.60, 0.31, 0.64),
    (1.00, 0.50, 0.00), (0.90, 0.80, 0.20), (0.65, 0.34, 0.16), (0.97, 0.51, 0.75),
    (0.40, 0.76, 0.65), (0.55, 0.63, 0.80), (0.65, 0.85, 0.33), (0.99, 0.55, 0.38),
]
GREY = (0.75, 0.75, 0.76)
PLANE_BLUE = (0.25, 0.45, 0.90)


def read_mesh(path):
    """A reader (algorithm) for a .off .obj .ply .stl .vtp or .vtk surface mesh."""
    extension = os.path.splitext(path)[1].lower()
    if extension not in READERS:
        raise ValueError("cannot read %s: use one of %s" % (path, " ".join(sorted(READERS))))
    if not os.path.isfile(path):
        raise FileNotFoundError(path)
    reader = READERS[extension]()
    reader.SetFileName(path)
    return reader


def region_lookup_table():
    """SymmetryRegion colours as in the paper's Figures 1-2: outside, support, symmetric."""
    table = vtkLookupTable()
    table.SetNumberOfTableValues(3)
    table.SetTableRange(0, 2)
    table.SetTableValue(0, *GREY, 1.0)
    table.SetTableValue(1, 0.95, 0.85, 0.25, 1.0)
    table.SetTableValue(2, 0.30, 0.72, 0.35, 1.0)
    table.Build()
    return table


def leaf_lookup_table(leaf_ids):
    """One palette colour per leaf node index (categorical); anything else is grey."""
    table = vtkLookupTable()
    table.IndexedLookupOn()
    ids = sorted(set(int(i) for i in leaf_ids))
    table.SetNumberOfTableValues(max(1, len(ids)))
    for rank, leaf_id in enumerate(ids):
        table.SetAnnotation(vtkVariant(leaf_id), "leaf %d" % leaf_id)
        table.SetTableValue(rank, *PALETTE[rank % len(PALETTE)], 1.0)
    table.SetNanColor(*GREY, 1.0)
    return table


def mesh_actor(mesh, cell_array=None, lookup_table=None, color=GREY, opacity=1.0):
    """An actor for a polydata, coloured by an integer cell array or a plain colour."""
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(mesh)
    if cell_array and mesh.GetCellData().GetArray(cell_array) is not None:
        mapper.SetScalarModeToUseCellFieldData()
        mapper.SelectColorArray(cell_array)
        mapper.SetLookupTable(lookup_table)
        mapper.UseLookupTableScalarRangeOn()
        mapper.ScalarVisibilityOn()
    else:
        mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    actor.GetProperty().SetOpacity(opacity)
    return actor


def plane_actor(glyph):
    """A translucent blue quad for a plane glyph: the detector's quad, or the rectangle a
    folding tree's "Plane" outline (a closed polyline of its 4 corners) goes round."""
    if glyph.GetNumberOfPolys() == 0 and glyph.GetNumberOfPoints() == 4:
        quad = vtkCellArray()
        quad.InsertNextCell(4)
        for i in range(4):
            quad.InsertCellPoint(i)
        filled = vtkPolyData()
        filled.SetPoints(glyph.GetPoints())
        filled.SetPolys(quad)
        glyph = filled
    return mesh_actor(glyph, color=PLANE_BLUE, opacity=0.35)


def tree_parts(tree):
    """The leaves and plane glyphs of a folding tree (vtkFoldingTreeBuilder output 0).

    Nodes are told apart by the field array FoldingNodeKind (0 leaf, 1 folding-node plane,
    2 segmentation-node marker); returns (leaves, planes) as lists of vtkPolyData.
    """
    leaves, planes = [], []
    iterator = vtkDataObjectTreeIterator()
    iterator.SetDataSet(tree)
    iterator.VisitOnlyLeavesOn()
    iterator.InitTraversal()
    while not iterator.IsDoneWithTraversal():
        block = iterator.GetCurrentDataObject()
        kind = block.GetFieldData().GetArray("FoldingNodeKind") if block else None
        if isinstance(block, vtkPolyData) and kind is not None:
            if int(kind.GetTuple1(0)) == 0:
                leaves.append(block)
            elif int(kind.GetTuple1(0)) == 1:
                planes.append(block)
        iterator.GoToNextItem()
    return leaves, planes


def oblique_camera(renderer, bounds, normal, up=None, flip=False, zoom=1.15):
    """Look at `bounds` obliquely across a plane with `normal`, from the side it points to.

    Up is `up` when given, else the longest axis of the box among those lying in the plane.
    The camera sits mostly along up x normal (or its opposite with `flip`).
    """
    n = list(normal)
    centre = [0.5 * (bounds[2 * k] + bounds[2 * k + 1]) for k in range(3)]
    if up is None:
        scores = [(bounds[2 * k + 1] - bounds[2 * k]) * (1.0 - abs(n[k])) for k in range(3)]
        up = [0.0, 0.0, 0.0]
        up[scores.index(max(scores))] = 1.0
    side = [up[1] * n[2] - up[2] * n[1], up[2] * n[0] - up[0] * n[2], up[0] * n[1] - up[1] * n[0]]
    length = (math.sqrt(sum(s * s for s in side)) or 1.0) * (-1.0 if flip else 1.0)
    direction = [side[k] / length + 0.6 * n[k] + 0.35 * up[k] for k in range(3)]
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(*centre)
    camera.SetPosition(*[centre[k] + direction[k] for k in range(3)])
    camera.SetViewUp(*up)
    renderer.ResetCamera(bounds)
    camera.Zoom(zoom)
    return camera


def render_panels(panels, width, height, path, bounds, normal, up=None, flip=False):
    """Render side-by-side panels (lists of actors) with one shared camera into a PNG.

    `bounds`, `normal`, `up` and `flip` place the camera (see oblique_camera). Returns the PNG path.
    """
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(width, height)
    camera = None
    for i, actors in enumerate(panels):
        renderer = vtkRenderer()
        renderer.SetBackground(1.0, 1.0, 1.0)
        renderer.SetViewport(i / len(panels), 0.0, (i + 1) / len(panels), 1.0)
        for actor in actors:
            renderer.AddActor(actor)
        if camera is None:
            camera = oblique_camera(renderer, bounds, normal, up, flip)
        else:
            renderer.SetActiveCamera(camera)
        window.AddRenderer(renderer)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(path)
    writer.Write()
    window.Finalize()
    return path


def leaf_color(table, leaf_id):
    """The colour leaf_lookup_table gives to leaf node index `leaf_id`."""
    index = table.GetAnnotatedValueIndex(vtkVariant(int(leaf_id)))
    return table.GetTableValue(index)[:3] if index >= 0 else GREY


def leaf_actors(leaves, table):
    """One actor per tree leaf, in the colour of its node index (FoldingNodeIndex)."""
    actors = []
    for leaf in leaves:
        actor = mesh_actor(leaf)
        index = leaf.GetFieldData().GetArray("FoldingNodeIndex").GetTuple1(0)
        actor.GetProperty().SetColor(*leaf_color(table, index))
        actors.append(actor)
    return actors


def root_plane_normal(planes, default=(1.0, 0.0, 0.0)):
    """The normal of the shallowest folding plane of a tree (tree_parts' planes)."""
    if not planes:
        return default
    root = min(planes, key=lambda p: p.GetFieldData().GetArray("FoldingNodeDepth").GetTuple1(0))
    return root.GetFieldData().GetArray("FoldingPlaneNormal").GetTuple3(0)
