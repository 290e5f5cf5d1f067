# Repro 13: queen: H > eps
# Run: PYTHONPATH=/work/main/build/lib/python3/dist-packages timeout 60 /usr/bin/python3 scripts/fuzz/repro_13.py
import numpy as np
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData, vtkCellArray
from foldingmeshes import vtkFoldingTreeBuilder, vtkFoldingTreeUnfolder
from vtkmodules.vtkIOGeometry import vtkOBJReader as R
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
r = R(); r.SetFileName('/work/shared/data/meshes/queen_chess_quaddamage.obj')
tf = vtkTriangleFilter(); tf.SetInputConnection(r.GetOutputPort()); tf.Update()
mesh = tf.GetOutput()

def area(pd):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    P = vtk_to_numpy(pd.GetPoints().GetData()).astype(float)
    c = pd.GetPolys(); off = vtk_to_numpy(c.GetOffsetsArray()); con = vtk_to_numpy(c.GetConnectivityArray())
    A = 0.0
    for i in range(len(off) - 1):
        v = con[off[i]:off[i+1]]
        for k in range(1, len(v) - 1):
            A += 0.5 * np.linalg.norm(np.cross(P[v[k]] - P[v[0]], P[v[k+1]] - P[v[0]]))
    return A

b = vtkFoldingTreeBuilder()
b.SetInputData(mesh)
b.SetUseMinimumFaces(False)
b.SetUseMinimumAreaFraction(False)
b.Update()
u = vtkFoldingTreeUnfolder()
u.SetInputData(b.GetOutputDataObject(0))
u.SetOriginalData(mesh)
u.Update()
out = u.GetOutput()
fd = out.GetFieldData()
g = lambda n: fd.GetArray(n).GetTuple1(0) if fd.GetArray(n) else None
eps = g("RootEpsilon")
print("faces in/out", mesh.GetNumberOfCells(), out.GetNumberOfCells())
print("area ratio out/in %.4f" % (area(out) / area(mesh)))
print("HausdorffToOriginal %.6g  HausdorffToOriginalBound %.6g  RootEpsilon %.6g  bound/eps %.3f" % (g("HausdorffToOriginal"), g("HausdorffToOriginalBound"), eps, g("HausdorffToOriginalBound") / eps))
print("OpenEdges", g("OpenEdges"), "NonManifoldEdges", g("NonManifoldEdges"), "MisorientedEdges", g("MisorientedEdges"), "RepairDroppedFaces", g("RepairDroppedFaces"))
