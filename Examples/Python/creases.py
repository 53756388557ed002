"""Example: creases from Python - automatic ones from a feature angle, and semi-sharp ones.

A box from vtkCubeSource (its points merged) is subdivided by Catmull-Clark three times:
1. plain: it rounds into a blob;
2. with AutomaticCreases (FeatureAngle 60): its 12 edges are infinitely sharp, it stays a box;
3. with crease lines given as input cells with a "Sharpness" array: semi-sharp edges of
   sharpness 1, 2 and 3 round off less and less.
Each result goes to <prefix>-*.vtp; the program prints how far each one's corner point is
from the box's corner.
    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/creases.py box
"""
import math
import sys

import subd
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkCleanPolyData
from vtkmodules.vtkFiltersSources import vtkCubeSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter


def box():
    cube = vtkCubeSource()
    cube.SetXLength(2.0)
    cube.SetYLength(2.0)
    cube.SetZLength(2.0)
    merge = vtkCleanPolyData()
    merge.SetInputConnection(cube.GetOutputPort())
    merge.Update()
    mesh = vtkPolyData()
    mesh.DeepCopy(merge.GetOutput())
    mesh.GetPointData().Initialize()  # vtkCubeSource's normals and texture coordinates
    return mesh


def nearest_to_corner(mesh):
    return min(math.dist(mesh.GetPoint(i), (1.0, 1.0, 1.0)) for i in range(mesh.GetNumberOfPoints()))


def smooth(mesh, path, **options):
    cc = subd.vtkSubDCatmullClarkFilter()
    cc.SetInputData(mesh)
    cc.SetNumberOfSubdivisions(3)
    cc.ProjectToLimitOn()
    if options.get("feature_angle"):
        cc.AutomaticCreasesOn()
        cc.SetFeatureAngle(options["feature_angle"])
    writer = vtkXMLPolyDataWriter()
    writer.SetInputConnection(cc.GetOutputPort())
    writer.SetFileName(path)
    writer.Write()
    return cc.GetOutput()


def with_semi_sharp_edges(mesh, sharpness_values):
    """The edges at corner (1, 1, 1) as crease lines, with the given sharpness each."""
    corner = min(range(mesh.GetNumberOfPoints()), key=lambda i: math.dist(mesh.GetPoint(i), (1, 1, 1)))
    lines = vtkCellArray()
    for axis in range(3):
        other = (1.0, 1.0, 1.0)[:axis] + (-1.0,) + (1.0, 1.0, 1.0)[axis + 1:]
        neighbour = min(range(mesh.GetNumberOfPoints()), key=lambda i: math.dist(mesh.GetPoint(i), other))
        lines.InsertNextCell(2)
        lines.InsertCellPoint(corner)
        lines.InsertCellPoint(neighbour)
    creased = vtkPolyData()
    creased.DeepCopy(mesh)
    creased.SetLines(lines)
    sharpness = vtkFloatArray()
    sharpness.SetName("Sharpness")  # lines come first among a polydata's cells
    for value in sharpness_values:
        sharpness.InsertNextValue(value)
    for _ in range(mesh.GetNumberOfPolys()):
        sharpness.InsertNextValue(0.0)
    creased.GetCellData().AddArray(sharpness)
    return creased


def main(prefix="box"):
    mesh = box()
    plain = nearest_to_corner(smooth(mesh, prefix + "-plain.vtp"))
    sharp = nearest_to_corner(smooth(mesh, prefix + "-feature-angle.vtp", feature_angle=60.0))
    semi = [nearest_to_corner(smooth(with_semi_sharp_edges(mesh, [s] * 3), "%s-semi-%d.vtp" % (prefix, s)))
            for s in (1, 2, 3)]
    print("distance from the box corner: plain %.3f, sharpness 1/2/3: %.3f / %.3f / %.3f, feature angle %.3g"
          % (plain, semi[0], semi[1], semi[2], sharp))
    # Sharper creases keep the corner closer; infinitely sharp ones keep it exactly.
    ok = plain > semi[0] > semi[1] > semi[2] > sharp and sharp < 1e-12
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:2]))
