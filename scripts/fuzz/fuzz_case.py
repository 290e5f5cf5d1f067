"""Fuzz harness: build a small mesh, fold, unfold (optionally through a compact file: "compact": BITS,
0 automatic), check. Usage: fuzz_case.py '<json case>' -> prints RESULT {json}."""
import sys, json, math, os, tempfile
import numpy as np
from vtkmodules.vtkCommonCore import vtkPoints, vtkObject
from vtkmodules.vtkCommonDataModel import vtkPolyData, vtkCellArray
from vtkmodules.vtkFiltersSources import vtkSphereSource, vtkCylinderSource, vtkPlatonicSolidSource
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
from vtkmodules.vtkIOGeometry import vtkOBJReader
from vtkmodules.vtkIOPLY import vtkPLYReader
from foldingmeshes import (vtkFoldingTreeBuilder, vtkFoldingTreeCompactReader, vtkFoldingTreeCompactWriter,
                           vtkFoldingTreeUnfolder, vtkOFFReader)

vtkObject.GlobalWarningDisplayOff()

DOUBLE_POINTS = False  # case key "double": true -> double coordinates (default: VTK's float)

def poly(pts, tris):
    p = vtkPoints()
    if DOUBLE_POINTS:
        p.SetDataTypeToDouble()
    for x in pts:
        p.InsertNextPoint(*map(float, x))
    ca = vtkCellArray()
    for t in tris:
        ca.InsertNextCell(len(t))
        for i in t:
            ca.InsertCellPoint(int(i))
    pd = vtkPolyData(); pd.SetPoints(p); pd.SetPolys(ca)
    return pd

def tri_filter(alg):
    tf = vtkTriangleFilter(); tf.SetInputConnection(alg.GetOutputPort()); tf.Update()
    out = vtkPolyData(); out.DeepCopy(tf.GetOutput()); return out

def box(c=(0,0,0), s=(1,1,1)):
    pts = [(c[0]+s[0]*x, c[1]+s[1]*y, c[2]+s[2]*z) for x in (0,1) for y in (0,1) for z in (0,1)]
    # index = 4x+2y+z
    quads = [(0,1,3,2),(4,6,7,5),(0,4,5,1),(2,3,7,6),(0,2,6,4),(1,5,7,3)]
    tris = []
    for a,b,c_,d in quads:
        tris += [(a,b,c_),(a,c_,d)]
    return pts, tris

def make(name):
    if name == 'square':
        return poly([(0,0,0),(1,0,0),(1,1,0),(0,1,0)], [(0,1,2),(0,2,3)])
    if name == 'square_diag2':
        return poly([(0,0,0),(1,0,0),(1,1,0),(0,1,0)], [(0,1,3),(1,2,3)])
    if name == 'rect':
        return poly([(0,0,0),(2,0,0),(2,1,0),(0,1,0)], [(0,1,2),(0,2,3)])
    if name == 'triangle':
        return poly([(0,0,0),(1,0,0),(0.5,math.sqrt(3)/2,0)], [(0,1,2)])
    if name == 'right_triangle':
        return poly([(0,0,0),(1,0,0),(0,1,0)], [(0,1,2)])
    if name == 'isosceles':
        return poly([(0,0,0),(2,0,0),(1,0.5,0)], [(0,1,2)])
    if name.startswith('fan'):  # fanN: regular polygon as fan around center
        n = int(name[3:])
        pts = [(0,0,0)] + [(math.cos(2*math.pi*k/n), math.sin(2*math.pi*k/n), 0) for k in range(n)]
        return poly(pts, [(0,1+k,1+(k+1)%n) for k in range(n)])
    if name.startswith('polyfan'):  # polygon fan from vertex 0 (no centre)
        n = int(name[7:])
        pts = [(math.cos(2*math.pi*k/n), math.sin(2*math.pi*k/n), 0) for k in range(n)]
        return poly(pts, [(0,k,k+1) for k in range(1,n-1)])
    if name.startswith('grid'):  # gridN: NxN flat grid
        n = int(name[4:])
        pts = [(i/n, j/n, 0) for j in range(n+1) for i in range(n+1)]
        tris = []
        for j in range(n):
            for i in range(n):
                a = j*(n+1)+i; b=a+1; c=a+n+2; d=a+n+1
                tris += [(a,b,c),(a,c,d)]
        return poly(pts, tris)
    if name == 'cube':
        return poly(*box())
    if name == 'boxlong':
        return poly(*box(s=(3,1,0.5)))
    if name == 'twocubes':
        p1,t1 = box(); p2,t2 = box(c=(3,0,0))
        return poly(p1+p2, t1+[(a+8,b+8,c+8) for a,b,c in t2])
    if name == 'twocubes_asym':
        p1,t1 = box(); p2,t2 = box(c=(3,0.3,0), s=(0.5,0.7,1.2))
        return poly(p1+p2, t1+[(a+8,b+8,c+8) for a,b,c in t2])
    if name in ('tetra','octa','icosa','dodeca','hexa'):
        s = vtkPlatonicSolidSource()
        s.SetSolidType({'tetra':0,'hexa':1,'octa':2,'icosa':3,'dodeca':4}[name])
        return tri_filter(s)
    if name.startswith('sphere'):  # sphereT_P
        t, p = map(int, name[6:].split('_'))
        s = vtkSphereSource(); s.SetThetaResolution(t); s.SetPhiResolution(p)
        return tri_filter(s)
    if name.startswith('cyl') and not name.startswith('cylraw'):
        r = int(name[3:])
        s = vtkCylinderSource(); s.SetResolution(r)
        return weld(tri_filter(s))
    if name.startswith('cylraw'):
        r = int(name[6:])
        s = vtkCylinderSource(); s.SetResolution(r)
        return tri_filter(s)
    if name == 'bumpbox':
        # box top face subdivided with a bump at the middle
        n = 6
        pts = []; tris = []
        # top grid of (n+1)^2 at z=1 with bump
        for j in range(n+1):
            for i in range(n+1):
                x, y = i/n, j/n
                z = 1 + (0.3 if (i, j) == (n//2, n//2) else 0)
                pts.append((x, y, z))
        for j in range(n):
            for i in range(n):
                a = j*(n+1)+i; b=a+1; c=a+n+2; d=a+n+1
                tris += [(a,b,c),(a,c,d)]
        # bottom grid z=0 reversed
        off = len(pts)
        for j in range(n+1):
            for i in range(n+1):
                pts.append((i/n, j/n, 0))
        for j in range(n):
            for i in range(n):
                a = off+j*(n+1)+i; b=a+1; c=a+n+2; d=a+n+1
                tris += [(a,c,b),(a,d,c)]
        # sides: connect boundary rings
        def top(i,j): return j*(n+1)+i
        def bot(i,j): return off+j*(n+1)+i
        ring = [(i,0) for i in range(n)] + [(n,j) for j in range(n)] + [(i,n) for i in range(n,0,-1)] + [(0,j) for j in range(n,0,-1)]
        for k in range(len(ring)):
            p0 = ring[k]; p1 = ring[(k+1)%len(ring)]
            tris += [(bot(*p0), bot(*p1), top(*p1)), (bot(*p0), top(*p1), top(*p0))]
        return poly(pts, tris)
    if name == 'Lprism':
        # L-shaped polygon extruded, triangulated
        L = [(0,0),(2,0),(2,1),(1,1),(1,2),(0,2)]
        # triangulation of L: split into
        ltris = [(0,1,2),(0,2,3),(0,3,4),(0,4,5)]
        pts = [(x,y,0) for x,y in L] + [(x,y,0.5) for x,y in L]
        tris = [(c,b,a) for a,b,c in ltris] + [(a+6,b+6,c+6) for a,b,c in ltris]
        for k in range(6):
            a, b = k, (k+1)%6
            tris += [(a,b,b+6),(a,b+6,a+6)]
        return poly(pts, tris)
    if name.startswith('file:'):
        path = name[5:]
        if path.endswith('.off'):
            r = vtkOFFReader()
        elif path.endswith('.obj'):
            r = vtkOBJReader()
        else:
            r = vtkPLYReader()
        r.SetFileName(path)
        return tri_filter(r)
    raise ValueError(name)

def weld(pd):
    from vtkmodules.vtkFiltersCore import vtkCleanPolyData
    c = vtkCleanPolyData(); c.SetInputData(pd); c.SetTolerance(0.0); c.PointMergingOn(); c.Update()
    out = vtkPolyData(); out.DeepCopy(c.GetOutput()); return out

def rigid(pd, seed):
    if not seed:
        return pd
    rng = np.random.default_rng(seed)
    q = rng.normal(size=4); q /= np.linalg.norm(q)
    a,b,c,d = q
    R = np.array([[a*a+b*b-c*c-d*d, 2*(b*c-a*d), 2*(b*d+a*c)],
                  [2*(b*c+a*d), a*a-b*b+c*c-d*d, 2*(c*d-a*b)],
                  [2*(b*d-a*c), 2*(c*d+a*b), a*a-b*b-c*c+d*d]])
    t = rng.normal(size=3) * 5
    P, T = arrays(pd)
    P2 = P @ R.T + t
    return poly(P2, T)

def arrays(pd):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    P = vtk_to_numpy(pd.GetPoints().GetData()).astype(float)
    tris = []
    polys = pd.GetPolys()
    polys.InitTraversal()
    from vtkmodules.vtkCommonCore import vtkIdList
    ids = vtkIdList()
    while polys.GetNextCell(ids):
        n = ids.GetNumberOfIds()
        v = [ids.GetId(i) for i in range(n)]
        for k in range(1, n-1):
            tris.append((v[0], v[k], v[k+1]))
    return P, np.array(tris, dtype=int).reshape(-1, 3)

def area(P, T):
    if len(T) == 0: return 0.0
    a = P[T[:,1]]-P[T[:,0]]; b = P[T[:,2]]-P[T[:,0]]
    return 0.5*np.linalg.norm(np.cross(a,b),axis=1).sum()

def edge_stats(P, T):
    # weld by exact coords
    _, inv = np.unique(np.round(P, 12), axis=0, return_inverse=True)
    inv = inv.reshape(-1)
    TT = inv[T]
    from collections import Counter
    cnt = Counter()
    for t in TT:
        if len(set(t)) < 3: continue
        for i in range(3):
            a, b = t[i], t[(i+1)%3]
            cnt[(min(a,b), max(a,b))] += 1
    openE = sum(1 for v in cnt.values() if v == 1)
    nm = sum(1 for v in cnt.values() if v > 2)
    return openE, nm

def fd(pd, name):
    a = pd.GetFieldData().GetArray(name)
    if a is None: return None
    if a.GetNumberOfTuples()*a.GetNumberOfComponents() == 1:
        return a.GetTuple1(0)
    return [a.GetValue(i) for i in range(a.GetNumberOfTuples()*a.GetNumberOfComponents())]

def run(case):
    global DOUBLE_POINTS
    DOUBLE_POINTS = bool(case.get('double', False))
    mesh = make(case['mesh'])
    mesh = rigid(mesh, case.get('rigid', 0))
    P0, T0 = arrays(mesh)
    A0 = area(P0, T0)
    open0, nm0 = edge_stats(P0, T0)
    b = vtkFoldingTreeBuilder()
    b.SetInputData(mesh)
    for k, v in case.get('b', {}).items():
        getattr(b, 'Set' + k)(v)
    b.Update()
    tree = b.GetOutputDataObject(0)
    u = vtkFoldingTreeUnfolder()
    if 'compact' in case:  # through a compact file (.fmz) at these bits (0: automatic)
        fd_, path = tempfile.mkstemp(suffix='.fmz')
        os.close(fd_)
        w = vtkFoldingTreeCompactWriter()
        w.SetInputData(tree)
        w.SetFileName(path)
        w.SetQuantizationBits(int(case['compact']))
        w.SetOriginalData(mesh)  # proved against the mesh, more bits where not (as compress)
        w.Write()
        reader = vtkFoldingTreeCompactReader()
        reader.SetFileName(path)
        reader.Update()
        os.remove(path)
        read = reader.GetOutputDataObject(0)
        if read is None or read.GetNumberOfBlocks() == 0:
            raise RuntimeError('the compact file did not read back')
        u.SetInputData(read)
    else:
        u.SetInputData(tree)
    u.SetOriginalData(mesh)
    for k, v in case.get('u', {}).items():
        getattr(u, 'Set' + k)(v)
    u.Update()
    out = u.GetOutput()
    P1, T1 = arrays(out) if out.GetNumberOfPoints() else (np.zeros((0,3)), np.zeros((0,3),int))
    A1 = area(P1, T1)
    treeinfo = tree.GetBlock(1) if tree and tree.GetNumberOfBlocks() > 1 else None
    ti = {}
    if treeinfo is not None:
        for n in ('StoredFaces','TreeHeight','NumberOfLeaves','NumberOfFolds','RootEpsilon','Diagonal'):
            ti[n] = fd(treeinfo, n)
    res = dict(case=case, inFaces=len(T0), inArea=A0, inOpen=open0, inNM=nm0,
               outFaces=len(T1), outArea=A1, areaRatio=(A1/A0 if A0 else None),
               tree=ti)
    for n in ('HausdorffToOriginal','HausdorffToOriginalBound','RootEpsilon','OriginalDiagonal','Diagonal',
              'OpenEdges','NonManifoldEdges','MisorientedEdges','RepairDroppedFaces','OpenLoops','FilledFaces','BorderEdges'):
        res[n] = fd(out, n)
    return res

def check(r):
    fails = []
    eps = r.get('RootEpsilon'); diag = r.get('OriginalDiagonal') or r.get('Diagonal')
    hb = r.get('HausdorffToOriginalBound')
    if eps is None or hb is None:
        fails.append('missing field data')
    else:
        if hb > eps + 1e-4*diag:
            fails.append('bound %.6g > eps %.6g (ratio %.3f)' % (hb, eps, hb/eps))
        h = r.get('HausdorffToOriginal')
        if h is not None and h > eps + 1e-4*diag:
            fails.append('sampled H %.6g > eps %.6g' % (h, eps))
    ar = r.get('areaRatio')
    if ar is None or ar < 0.99:
        fails.append('area drop ratio %s' % ar)
    elif ar > 1.05:
        fails.append('area rise ratio %.4f' % ar)
    u = r['case'].get('u', {})
    default_unf = not u
    if r['inOpen'] == 0 and r['inNM'] == 0 and default_unf:
        if r.get('OpenEdges'):
            fails.append('OpenEdges %s on closed input' % r['OpenEdges'])
        if r.get('NonManifoldEdges'):
            fails.append('NonManifoldEdges %s on manifold input' % r['NonManifoldEdges'])
        if r.get('MisorientedEdges'):
            fails.append('MisorientedEdges %s' % r['MisorientedEdges'])
    return fails

if __name__ == '__main__':
    case = json.loads(sys.argv[1])
    r = run(case)
    r['fails'] = check(r)
    print('RESULT ' + json.dumps(r))
