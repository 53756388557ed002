"""Example: surfaces and curves through given points, from Python.

1. A coarse triangulated sphere: subd.interpolate finds the Loop cage whose limit surface
   passes through the sphere's vertices except the poles; subd.subdivide then refines it.
2. Scattered samples of a height field with a hole in the middle: vtkSubDBSplineSurfaceFilter
   fits a bicubic B-spline (least squares, with shape equations so the hole stays solvable).
3. An open zigzag: vtkSubDCurveInterpolateFilter gives the Chaikin curve through its points.

Each result is written to <prefix>-*.vtp. Run with Debian's python3 and the build's package:
    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/interpolation.py out
"""
import math
import sys

import numpy as np
import subd
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter


def write(data, path):
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(data)
    writer.SetFileName(path)
    return writer.Write() == 1


def loop_through_sphere(prefix):
    source = vtkSphereSource()
    source.SetThetaResolution(8)
    source.SetPhiResolution(6)
    source.Update()
    sphere = subd.to_arrays(source.GetOutput())
    targets = np.flatnonzero(np.abs(sphere.points[:, 2]) <= 0.49)  # not the poles
    cage = subd.interpolate((sphere.points, sphere.faces), scheme="loop", targets=targets)
    # The limit points of the solved cage: Loop at level 0, projected to the limit.
    limit = subd.subdivide((cage.points, cage.faces), scheme="loop", levels=0, limit=True)
    worst = np.max(np.linalg.norm(limit.points[targets] - sphere.points[targets], axis=1))
    print("Loop cage through %d of %d sphere points: largest miss %.2g" % (len(targets), len(sphere.points), worst))
    surface = subd.subdivide((cage.points, cage.faces), scheme="loop", levels=3)
    subd.write(surface, prefix + "-loop.vtp")
    return worst < 1e-9


def fit_height_field(prefix):
    points = vtkPoints()
    uv = vtkDoubleArray()
    uv.SetName("UV")
    uv.SetNumberOfComponents(2)
    n = 60
    for a in range(n):
        for b in range(n):
            u, v = a / (n - 1), b / (n - 1)
            if (u - 0.5) ** 2 + (v - 0.5) ** 2 < 0.25 ** 2:
                continue  # no measurements in the middle
            points.InsertNextPoint(4 * u, 4 * v, math.sin(3 * u) * math.cos(2 * v))
            uv.InsertNextTuple2(u, v)
    samples = vtkPolyData()
    samples.SetPoints(points)
    samples.GetPointData().AddArray(uv)

    fit = subd.vtkSubDBSplineSurfaceFilter()
    fit.SetInputData(samples)
    fit.SetModeToApproximateScattered()
    fit.SetNumberOfControlPoints(16, 16)
    fit.SetShapeWeight(0.01)
    fit.Update()
    print("B-spline fit of %d samples with a hole: %d control points, rms error %.2g, max %.2g" % (
        samples.GetNumberOfPoints(), fit.GetControlNet().GetNumberOfPoints(), fit.GetRmsError(),
        fit.GetMaxError()))
    return (write(fit.GetSurface(), prefix + "-fit.vtp") and write(fit.GetControlNet(), prefix + "-fit-net.vtp")
            and fit.GetRmsError() < 1e-2)


def chaikin_through_zigzag(prefix):
    points = vtkPoints()
    line = vtkCellArray()
    line.InsertNextCell(7)
    for k in range(7):
        points.InsertNextPoint(k, 1.0 if k % 2 else 0.0, 0.0)
        line.InsertCellPoint(k)
    zigzag = vtkPolyData()
    zigzag.SetPoints(points)
    zigzag.SetLines(line)
    curve = subd.vtkSubDCurveInterpolateFilter()
    curve.SetInputData(zigzag)
    curve.SetSchemeToChaikin()
    curve.OutputRefinedCurveOn()
    curve.SetNumberOfSubdivisions(6)
    curve.Update()
    result = curve.GetOutput()
    # The refined curve runs within a hair of every zigzag point (6 levels: ~1e-3).
    worst = max(min(math.dist(zigzag.GetPoint(k), result.GetPoint(i)) for i in range(result.GetNumberOfPoints()))
                for k in range(7))
    print("Chaikin curve through a 7-point zigzag: %d points, farthest zigzag point %.2g away" % (
        result.GetNumberOfPoints(), worst))
    return write(result, prefix + "-chaikin.vtp") and worst < 0.02


def main(prefix="interpolation"):
    ok = loop_through_sphere(prefix)
    ok = fit_height_field(prefix) and ok
    ok = chaikin_through_zigzag(prefix) and ok
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:2]))
