"""Example: the exact limit surface and its curvature from Python.

1. A Loop surface refined twice with ProjectToLimit, ComputeLimitNormals and ComputeCurvature:
   a triangulated sphere's limit surface, whose mean curvature is positive everywhere.
2. vtkSubDLimitFilter at chosen locations: (face, u, v) triples as point data "FaceId" and
   "FaceUV" of a second input give the limit points, normals and curvature exactly there.
Writes <prefix>-loop.vtp.
    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/limit_curvature.py out
"""
import sys

import subd
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter


def main(prefix="out"):
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(10)
    sphere.SetPhiResolution(8)

    loop = subd.vtkSubDLoopFilter()
    loop.SetInputConnection(sphere.GetOutputPort())
    loop.SetNumberOfSubdivisions(2)
    loop.ProjectToLimitOn()
    loop.ComputeLimitNormalsOn()
    loop.ComputeCurvatureOn()
    writer = vtkXMLPolyDataWriter()
    writer.SetInputConnection(loop.GetOutputPort())
    writer.SetFileName(prefix + "-loop.vtp")
    writer.Write()
    mean = loop.GetOutput().GetPointData().GetArray("Mean_Curvature").GetRange()
    print("Loop limit of a sphere: mean curvature in [%.3f, %.3f]" % mean)

    # Three locations on face 0: its corners' barycentre and two points near its edges.
    locations = vtkPolyData()
    points = vtkPoints()
    face_id = vtkDoubleArray()
    face_id.SetName("FaceId")
    face_uv = vtkDoubleArray()
    face_uv.SetName("FaceUV")
    face_uv.SetNumberOfComponents(2)
    for u, v in ((1 / 3, 1 / 3), (0.1, 0.05), (0.45, 0.45)):
        points.InsertNextPoint(0, 0, 0)  # replaced by the limit points
        face_id.InsertNextValue(0)
        face_uv.InsertNextTuple2(u, v)
    locations.SetPoints(points)
    locations.GetPointData().AddArray(face_id)
    locations.GetPointData().AddArray(face_uv)

    limit = subd.vtkSubDLimitFilter()
    limit.SetInputConnection(sphere.GetOutputPort())
    limit.SetSchemeToLoop()
    limit.SetInputDataObject(1, locations)  # the second input: where to evaluate
    limit.ComputeCurvatureOn()
    limit.Update()
    at = limit.GetOutput()
    gauss = at.GetPointData().GetArray("Gauss_Curvature")
    for i in range(at.GetNumberOfPoints()):
        print("  face 0 at (%.2f, %.2f): point (%.3f, %.3f, %.3f), Gaussian curvature %.3f"
              % (face_uv.GetTuple2(i) + at.GetPoint(i) + (gauss.GetValue(i),)))
    ok = mean[0] > 0 and at.GetNumberOfPoints() == 3 and all(gauss.GetValue(i) > 0 for i in range(3))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:2]))
