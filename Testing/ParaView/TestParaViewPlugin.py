"""pvbatch loads SubD's ParaView plugin and runs every filter it adds on ParaView sources.

Run: pvbatch TestParaViewPlugin.py PLUGIN.so  (the ctest "paraview.plugin" does this).
Each check compares with a closed form or with another filter's independent code path,
never with a value this plugin produced before. Exits non-zero on the first failure.
"""
import math
import sys
# Python's own all, max and min, by their full names: a Programmable Filter's script runs in
# this script's namespace in pvbatch and imports numpy-based functions of the same names.
import builtins

import paraview.simple as pvs
from paraview import servermanager

PLUGIN = sys.argv[1]
pvs.LoadPlugin(PLUGIN, remote=False)  # adds the filters to paraview.simple

failures = []


def check(condition, message):
    print(("ok   " if condition else "FAIL ") + message)
    if not condition:
        failures.append(message)


def fetch(proxy, port=0):
    proxy.UpdatePipeline()
    return servermanager.Fetch(proxy, idx=port)


def polys(data):
    return data.GetNumberOfPolys()


def points_of(data):
    return [data.GetPoint(i) for i in range(data.GetNumberOfPoints())]


def nearest(point, candidates):
    return builtins.min(math.dist(point, c) for c in candidates)


# Inputs: a closed triangle mesh and an open quad grid (ParaView's own sources; both share
# their points between faces).
sphere = pvs.Sphere(ThetaResolution=12, PhiResolution=8, Radius=1.0)
sphere_data = fetch(sphere)
T = polys(sphere_data)
V = sphere_data.GetNumberOfPoints()
E = 3 * T // 2  # closed triangle mesh
check(V - E + T == 2, "the sphere source is a closed genus-0 triangle mesh (V - E + F = 2)")

grid = pvs.Plane(XResolution=5, YResolution=4)
grid_data = fetch(grid)
check(polys(grid_data) == 20, "the plane source is a 5 x 4 quad grid")

# Every filter of the plugin is in the Filters menu's proxy group.
names = ["SubDCatmullClark", "SubDLoop", "SubDDooSabin", "SubDMidpoint", "SubDSqrt3",
         "SubDModifiedButterfly", "SubDLinear", "SubDCurve", "SubDLimitSurface", "SubDInterpolatingCage",
         "SubDInterpolatingCurve", "SubDBSplineSurface"]
pxm = servermanager.ProxyManager()
for name in names:
    check(pxm.GetPrototypeProxy("filters", name) is not None, "proxy filters/%s is defined" % name)

# Face counts per level (closed forms).
for levels in (1, 2):
    out = fetch(pvs.SubDCatmullClark(Input=grid, NumberOfSubdivisions=levels))
    n = 2 ** levels
    check(polys(out) == 20 * 4 ** levels and out.GetNumberOfPoints() == (5 * n + 1) * (4 * n + 1),
          "Catmull-Clark L%d on the grid: 20*4^L quads, (5*2^L+1)(4*2^L+1) points" % levels)
    check(polys(fetch(pvs.SubDLoop(Input=sphere, NumberOfSubdivisions=levels))) == T * 4 ** levels,
          "Loop L%d on the sphere: T*4^L triangles" % levels)
    check(polys(fetch(pvs.SubDSqrt3(Input=sphere, NumberOfSubdivisions=levels))) == T * 3 ** levels,
          "sqrt(3) L%d on the sphere: T*3^L triangles" % levels)
check(polys(fetch(pvs.SubDDooSabin(Input=sphere, NumberOfSubdivisions=1))) == T + E + V,
      "Doo-Sabin L1 on a closed mesh: a face per face, edge and vertex")
check(polys(fetch(pvs.SubDMidpoint(Input=sphere, NumberOfSubdivisions=1))) == T + V,
      "midpoint L1 on a closed mesh: a face per face and vertex")

# Interpolating schemes keep the input points; approximating ones shrink a convex surface.
inputs = points_of(sphere_data)
butterfly = points_of(fetch(pvs.SubDModifiedButterfly(Input=sphere, NumberOfSubdivisions=2, Tension=0.03)))
check(builtins.all(nearest(p, butterfly) < 1e-6 for p in inputs), "the butterfly keeps every input point")
loop = points_of(fetch(pvs.SubDLoop(Input=sphere, NumberOfSubdivisions=2)))
check(builtins.max(math.dist(p, (0, 0, 0)) for p in loop) < 1.0, "Loop's points move inside the sphere")
linear = fetch(pvs.SubDLinear(Input=grid, NumberOfSubdivisions=2, Split=1))
check(polys(linear) == 20 * 16 and builtins.all(abs(p[2]) < 1e-12 for p in points_of(linear)),
      "linear L2 with the quad split: 16 quads per quad, all on the plane")

# The exact limit: Catmull-Clark with ProjectToLimit and the limit filter are two code paths
# (stencil masks vs patch evaluation); at a vertex they must agree.
limit_cc = fetch(pvs.SubDCatmullClark(Input=sphere, NumberOfSubdivisions=1, ProjectToLimit=1,
                                  ComputeLimitNormals=1, ComputeCurvature=1,
                                  OutputPointsPrecision=1))
tessellation = fetch(pvs.SubDLimitSurface(Input=sphere, Scheme=0, Resolution=2, ComputeCurvature=1))
check(polys(tessellation) == T * 3 * 1, "limit tessellation: 3 quads per triangle at resolution 2")
tess_points = points_of(tessellation)
check(builtins.all(nearest(p, tess_points) < 1e-9 for p in points_of(limit_cc)),
      "projected Catmull-Clark vertices lie on the exact limit tessellation")
normals = limit_cc.GetPointData().GetArray("Normals")
check(normals is not None and builtins.all(abs(math.hypot(*normals.GetTuple3(i)) - 1) < 1e-6
                                  for i in range(normals.GetNumberOfTuples())),
      "limit normals are unit vectors")
# The adaptive tessellation: crack-free (every edge in two triangles) on the closed sphere,
# fewer triangles at a looser tolerance; the selective one with every face at level 1 is the
# uniform tessellation at resolution 2, point for point.
def open_edges(mesh):
    count = {}
    for c in range(mesh.GetNumberOfCells()):
        ids = mesh.GetCell(c).GetPointIds()
        n = ids.GetNumberOfIds()
        for k in range(n):
            edge = tuple(sorted((ids.GetId(k), ids.GetId((k + 1) % n))))
            count[edge] = count.get(edge, 0) + 1
    return builtins.sum(1 for v in count.values() if v != 2)
fine = fetch(pvs.SubDLimitSurface(Input=sphere, Scheme=1, Tessellation=1, Tolerance=1e-3))
coarse = fetch(pvs.SubDLimitSurface(Input=sphere, Scheme=1, Tessellation=1, Tolerance=1e-2))
check(open_edges(fine) == 0 and polys(coarse) < polys(fine),
      "adaptive limit tessellation: watertight, %d triangles at 1e-3, %d at 1e-2" % (polys(fine), polys(coarse)))
levels = pvs.ProgrammableFilter(Input=sphere)
levels.Script = """
import vtk
out = self.GetOutput()
out.ShallowCopy(self.GetInput())
a = vtk.vtkIntArray()
a.SetName("RefineLevel")
a.SetNumberOfTuples(out.GetNumberOfCells())
a.Fill(1)
out.GetCellData().AddArray(a)
"""
selective = points_of(fetch(pvs.SubDLimitSurface(Input=levels, Scheme=1, Tessellation=2)))
uniform = points_of(fetch(pvs.SubDLimitSurface(Input=sphere, Scheme=1, Resolution=2)))
check(len(selective) == len(uniform) and builtins.all(nearest(p, uniform) < 1e-12 for p in selective),
      "selective limit tessellation at level 1 = the uniform one at resolution 2")
# A cube's Catmull-Clark limit is convex (its extraordinary vertices have valence 3; the
# sphere's poles, of valence 12, are not: high valences pucker Catmull-Clark's limit).
cube = pvs.Clean(Input=pvs.Box())
rounded = fetch(pvs.SubDCatmullClark(Input=cube, NumberOfSubdivisions=2, ComputeCurvature=1))
mean = rounded.GetPointData().GetArray("Mean_Curvature")
smallest = builtins.min(mean.GetValue(i) for i in range(mean.GetNumberOfTuples())) if mean else None
check(polys(rounded) == 96 and smallest is not None and smallest > 0,
      "the cube's limit: 96 quads at L2, mean curvature positive everywhere (smallest %s)"
      % smallest)

# Interpolation: the limit surface of the solved cage passes through the input points.
bumpy = pvs.ProgrammableFilter(Input=grid)
bumpy.Script = """
out = self.GetOutput()
out.DeepCopy(self.GetInput())  # a shallow copy would move the plane source's points too
pts = out.GetPoints()
import math
for i in range(pts.GetNumberOfPoints()):
    x, y, z = pts.GetPoint(i)
    pts.SetPoint(i, x, y, 0.3 * math.sin(4 * x) * math.cos(3 * y))
"""
targets = points_of(fetch(bumpy))
cage = pvs.SubDInterpolatingCage(Input=bumpy, Scheme=0, InterpolationArrayName="(all points)")
at_limit = points_of(fetch(pvs.SubDCatmullClark(Input=cage, NumberOfSubdivisions=0, ProjectToLimit=1)))
check(builtins.max(math.dist(a, b) for a, b in zip(at_limit, targets)) < 1e-9,
      "SubD Interpolating Cage: the Catmull-Clark limit passes through every input point")
cage.UpdatePropertyInformation()
check(cage.GetProperty("NumberOfTaggedPoints").GetElement(0) == len(targets)
      and cage.GetProperty("Residual").GetElement(0) < 1e-9
      and cage.GetProperty("ConditionEstimate").GetElement(0) >= 1,
      "the cage reports its solve: every point tagged, residual, condition estimate >= 1")

line = pvs.PolyLineSource(Points=[0, 0, 0, 1, 1, 0, 2, 0, 0, 3, 1, 0, 4, 0, 0], Closed=0)
curve_cage = pvs.SubDInterpolatingCurve(Input=line, Scheme=1, InterpolationArrayName="(all points)")
on_curve = points_of(fetch(pvs.SubDCurve(Input=curve_cage, Scheme=1, NumberOfSubdivisions=0,
                                     ProjectToLimit=1)))
line_points = points_of(fetch(line))
check(len(on_curve) == len(line_points) and builtins.all(nearest(p, on_curve) < 1e-9 for p in line_points),
      "SubD Interpolating Curve: the cubic B-spline limit passes through every input point")
curve_cage.UpdatePropertyInformation()
check(curve_cage.GetProperty("NumberOfTaggedPoints").GetElement(0) == len(line_points)
      and curve_cage.GetProperty("Solver") is not None and curve_cage.GetProperty("Tolerance") is not None,
      "the curve's solve has the cage's solver options and report (every point tagged)")
four_point = fetch(pvs.SubDCurve(Input=line, Scheme=2, NumberOfSubdivisions=3))
check(four_point.GetNumberOfPoints() == 8 * 4 + 1 and
      builtins.all(nearest(p, points_of(four_point)) < 1e-12 for p in line_points),
      "4-point curve L3: 2^L segments per segment, through the input points")

# B-spline surface through the grid: a flat grid gives a flat surface, net (P+2) x (Q+2).
bspline = pvs.SubDBSplineSurface(Input=grid, SamplesPerSpan=4)
net = fetch(bspline, 0)
surface = fetch(bspline, 1)
check(net.GetNumberOfPoints() == 8 * 7, "B-spline control net of a 6 x 5 point grid is 8 x 7")
check(polys(surface) == 20 * 16 and builtins.all(abs(p[2]) < 1e-12 for p in points_of(surface)),
      "B-spline surface: 4 x 4 samples per span, flat for a flat grid")

# Array selection: any cell array can mark holes; an unrelated array is never picked by
# default.
tagged = pvs.ProgrammableFilter(Input=grid)
tagged.Script = """
out = self.GetOutput()
out.ShallowCopy(self.GetInput())
from vtkmodules.vtkCommonCore import vtkIntArray
for name, marked in (("Cut", 7), ("Material", 3)):
    a = vtkIntArray()
    a.SetName(name)
    a.SetNumberOfTuples(out.GetNumberOfCells())
    a.Fill(0)
    a.SetValue(marked, 1)
    out.GetCellData().AddArray(a)
"""
cc = pvs.SubDCatmullClark(Input=tagged, NumberOfSubdivisions=1)
check(cc.HoleArrayName in ("Hole", "(none)"),
      "HoleArrayName is not set to an unrelated array by default (%s)" % cc.HoleArrayName)
check(polys(fetch(cc)) == 80, "no hole without a Hole array")
domain = cc.GetProperty("HoleArrayName").FindDomain("vtkSMArrayListDomain")
listed = [domain.GetString(i) for i in range(domain.GetNumberOfStrings())]
check("Cut" in listed and "Material" in listed, "the hole selection lists the input's cell arrays")
cc.HoleArrayName = "Cut"
check(polys(fetch(cc)) == 76, "HoleArrayName=Cut: the marked face's 4 children are not output")

# Progress: ParaView's progress bar shows the filter's progress events; in pvbatch the filter
# is in this process, so they can be watched directly.
busy = pvs.SubDLoop(Input=sphere, NumberOfSubdivisions=4)
progress = []
busy.GetClientSideObject().AddObserver("ProgressEvent", lambda o, e: progress.append(o.GetProgress()))
busy.UpdatePipeline()
check(len(progress) > 3 and progress[-1] == 1.0 and progress == sorted(progress),
      "progress is reported while subdividing, increasing to 1 (%d events)" % len(progress))

# Defaults the VTK object chooses are not overridden by the XML.
curve = pvs.SubDCurve(Input=line)
curve.UpdatePropertyInformation()
check(curve.GetProperty("MaximumMemoryInfo").GetElement(0) > 100,
      "the curve filter's Maximum Memory comes from the filter too")
memory = cc.GetProperty("MaximumMemoryInfo")
cc.UpdatePropertyInformation()
check(memory is not None and memory.GetElement(0) > 100,
      "Maximum Memory comes from the filter (half the physical memory: %s MiB)"
      % (memory.GetElement(0) if memory else None))

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("all checks passed")
