"""Rendering from Python with no display: the offscreen window takes EGL (libGL, not
libOSMesa, is this process's OpenGL) and gives the same pixels as the C++ OSMesa test's
baseline for the same scene."""
import os
import sys

os.environ.pop("DISPLAY", None)

import subd  # noqa: E402
from vtkmodules.vtkTestingRendering import vtkTesting  # noqa: E402
from vtkmodules.vtkCommonCore import vtkFloatArray  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData  # noqa: E402
from vtkmodules.vtkCommonCore import vtkPoints  # noqa: E402

baseline_dir, temp_dir = sys.argv[1], sys.argv[2]

# The built-in creased cube of `subd` (Apps/subd/SubDBuiltinCages.cxx), rebuilt here.
points = vtkPoints()
for p in [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]:
    points.InsertNextPoint(p)
polys = vtkCellArray()
for face in [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]:
    polys.InsertNextCell(4, face)
lines = vtkCellArray()
lines.InsertNextCell(5, (4, 5, 6, 7, 4))
cage = vtkPolyData()
cage.SetPoints(points)
cage.SetPolys(polys)
cage.SetLines(lines)
sharpness = vtkFloatArray()
sharpness.SetName("Sharpness")
sharpness.SetNumberOfTuples(cage.GetNumberOfCells())
sharpness.Fill(0.0)
sharpness.SetValue(0, 2.5)
cage.GetCellData().AddArray(sharpness)
corners = vtkFloatArray()
corners.SetName("CornerSharpness")
corners.SetNumberOfTuples(8)
corners.Fill(0.0)
corners.SetValue(0, 10.0)
cage.GetPointData().AddArray(corners)

cc = subd.vtkSubDCatmullClarkFilter()
cc.SetInputData(cage)
cc.SetNumberOfSubdivisions(3)
cc.Update()

scene = subd.vtkSubDScene()
scene.SetViewSize(240, 240)
scene.AddView(cc.GetOutput(), cage, "catmull-clark L3")
assert scene.Render(), "rendering failed"
window = scene.GetRenderWindow()
assert window.GetBackendInUse() == "egl", window.GetBackendInUse()
assert not subd.vtkSubDOffscreenRenderWindow.ProcessUsesOSMesa()

testing = vtkTesting()
for argument in ("-V", os.path.join(baseline_dir, "catmull-clark_creased-cube_L3.png"), "-T", temp_dir):
    testing.AddArgument(argument)
testing.SetRenderWindow(window)
result = testing.RegressionTest(0.1)
assert result == vtkTesting.PASSED, "image differs from the baseline; see " + temp_dir

out = os.path.join(temp_dir, "python-scene.png")
assert scene.WritePNG(out) and os.path.getsize(out) > 1000
print("rendered with", window.GetBackendInUse())
