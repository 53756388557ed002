"""Python: Debian's /usr/bin/python3 imports subd next to vtkmodules and runs the filter."""
import math
import sys

import subd
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkFiltersCore import vtkCleanPolyData
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkSphereSource


def main():
    assert "vtkSubDCatmullClarkFilter" in subd.__all__, subd.__all__
    assert "vtkSubDOFFReader" in subd.__all__
    assert "vtkSubDLoopFilter" in subd.__all__
    assert "vtkSubDLinearFilter" in subd.__all__

    source = vtkSphereSource()  # kept alive: a pipeline does not own its upstream algorithm
    for name in ("vtkSubDLoopFilter", "vtkSubDLinearFilter", "vtkSubDDooSabinFilter", "vtkSubDMidpointFilter",
                 "vtkSubDButterflyFilter", "vtkSubDSqrt3Filter"):
        f = getattr(subd, name)()
        f.SetInputConnection(source.GetOutputPort())
        f.Update()
        assert f.GetOutput().GetNumberOfPolys() > 0, name

    sphere = vtkSphereSource()
    sphere.SetThetaResolution(16)
    sphere.SetPhiResolution(10)
    cc = subd.vtkSubDCatmullClarkFilter()
    cc.SetInputConnection(sphere.GetOutputPort())
    cc.SetNumberOfSubdivisions(2)
    cc.SetBoundaryRuleToEdgeAndCorner()
    assert cc.GetBoundaryRuleAsString() == "EdgeAndCorner"
    cc.SetNumberOfSubdivisions(99)  # clamped by the Set macro
    assert cc.GetNumberOfSubdivisions() == 30
    cc.SetNumberOfSubdivisions(2)

    progress = []
    cc.AddObserver(vtkCommand.ProgressEvent, lambda obj, _: progress.append(obj.GetProgress()))
    cc.Update()
    out = cc.GetOutput()
    sphere.Update()
    triangles = sphere.GetOutput().GetNumberOfPolys()
    assert out.GetNumberOfPolys() == triangles * 3 * 4, out.GetNumberOfPolys()
    assert progress and progress[-1] == 1.0, progress
    # Approximating scheme: nothing leaves the input sphere (radius 0.5).
    radius = max(math.sqrt(sum(c * c for c in out.GetPoint(i))) for i in range(out.GetNumberOfPoints()))
    assert radius <= 0.5 + 1e-12, radius
    # The class documentation comes through the wrapping.
    assert "Catmull" in subd.vtkSubDCatmullClarkFilter.__doc__
    # Sharp features: automatic creases on a cube give 12 crease lines, Chaikin selectable.
    source = vtkCubeSource()  # kept referenced: the pipeline does not own it in Python
    cube = vtkCleanPolyData()  # vtkCubeSource's faces share no points
    cube.SetInputConnection(source.GetOutputPort())
    sharp = subd.vtkSubDCatmullClarkFilter()
    sharp.SetInputConnection(cube.GetOutputPort())
    sharp.SetNumberOfSubdivisions(0)
    sharp.AutomaticCreasesOn()
    sharp.SetCreaseMethodToChaikin()
    assert sharp.GetCreaseMethodAsString() == "Chaikin"
    sharp.Update()
    assert sharp.GetOutput().GetNumberOfLines() == 12, sharp.GetOutput().GetNumberOfLines()

    # The limit surface: a tessellation with exact normals and (convex: positive) curvature.
    limit = subd.vtkSubDLimitFilter()
    limit.SetInputConnection(cube.GetOutputPort())
    limit.SetResolution(2)
    limit.ComputeCurvatureOn()
    limit.Update()
    tess = limit.GetOutput()
    assert tess.GetNumberOfPolys() == 6 * 2 * 2, tess.GetNumberOfPolys()  # Resolution 2 per edge
    mean = tess.GetPointData().GetArray("Mean_Curvature")
    assert mean is not None and all(mean.GetValue(i) > 0 for i in range(mean.GetNumberOfTuples()))
    normals = tess.GetPointData().GetNormals()
    assert normals is not None and normals.GetNumberOfTuples() == tess.GetNumberOfPoints()
    print("python: %d faces, %d points" % (out.GetNumberOfPolys(), out.GetNumberOfPoints()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
