"""Example: subdivision curves from Python (Chaikin, cubic B-spline, 4-point).

A closed star-shaped control polygon with one sharp tip is refined by the three curve schemes;
each result carries unit tangents of its limit curve and is written to <prefix>-<scheme>.vtp.

Run with Debian's python3 and the build's package on the path:
    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/curves.py star
"""
import math
import sys

import subd
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter


def star(tips=5):
    points = vtkPoints()
    for k in range(2 * tips):
        angle = math.pi / 2 + k * math.pi / tips
        radius = 0.45 if k % 2 else 1.0
        points.InsertNextPoint(radius * math.cos(angle), radius * math.sin(angle), 0.0)
    line = vtkCellArray()
    line.InsertNextCell(2 * tips + 1)
    for k in list(range(2 * tips)) + [0]:  # repeating the first point closes the polyline
        line.InsertCellPoint(k)
    corner = vtkFloatArray()
    corner.SetName("CornerSharpness")  # >= 10: the top tip stays a sharp corner
    for k in range(2 * tips):
        corner.InsertNextValue(10.0 if k == 0 else 0.0)
    polygon = vtkPolyData()
    polygon.SetPoints(points)
    polygon.SetLines(line)
    polygon.GetPointData().AddArray(corner)
    return polygon


def main(prefix="star", levels=4):
    polygon = star()
    schemes = {"chaikin": subd.vtkSubDCurveFilter.SCHEME_CHAIKIN,
               "bspline": subd.vtkSubDCurveFilter.SCHEME_CUBIC_BSPLINE,
               "four-point": subd.vtkSubDCurveFilter.SCHEME_FOUR_POINT}
    status = 0
    for name, scheme in schemes.items():
        curve = subd.vtkSubDCurveFilter()
        curve.SetInputData(polygon)
        curve.SetScheme(scheme)
        curve.SetNumberOfSubdivisions(levels)
        curve.ComputeTangentsOn()
        writer = vtkXMLPolyDataWriter()
        writer.SetInputConnection(curve.GetOutputPort())
        writer.SetFileName("%s-%s.vtp" % (prefix, name))
        writer.Write()
        result = curve.GetOutput()
        tangents = result.GetPointData().GetTangents()
        print("%s: %d control points -> %d points, tangents: %s" % (
            name, polygon.GetNumberOfPoints(), result.GetNumberOfPoints(), tangents.GetName()))
        # The corner opens the closed polygon: 11 points from tip to tip, 10 spans. Each level
        # doubles the spans (Chaikin's clamped ends have one span less to double: 9); the tip
        # (point 0, at the top) is kept exactly and listed once.
        spans = 9 if name == "chaikin" else 10
        expected = spans * 2 ** levels + (1 if name == "chaikin" else 0)
        tip = min(math.dist(result.GetPoint(i), polygon.GetPoint(0)) for i in range(result.GetNumberOfPoints()))
        if result.GetNumberOfPoints() != expected or tip != 0.0:
            status = 1
    return status


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:2]))
