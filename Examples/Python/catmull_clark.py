"""Example: Catmull-Clark subdivision from Python.

Run with Debian's python3 and the build's package on the path:
    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/catmull_clark.py
"""
import sys

import subd
from vtkmodules.vtkFiltersCore import vtkCleanPolyData
from vtkmodules.vtkFiltersSources import vtkCubeSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter


def main(output="cube-smooth-python.vtp", levels=3):
    cube = vtkCubeSource()
    merge = vtkCleanPolyData()  # weld the cube's per-face points into one closed surface
    merge.SetInputConnection(cube.GetOutputPort())

    smooth = subd.vtkSubDCatmullClarkFilter()
    smooth.SetInputConnection(merge.GetOutputPort())
    smooth.SetNumberOfSubdivisions(levels)
    smooth.SetBoundaryRuleToEdgeAndCorner()

    writer = vtkXMLPolyDataWriter()
    writer.SetInputConnection(smooth.GetOutputPort())
    writer.SetFileName(output)
    writer.Write()

    result = smooth.GetOutput()
    print("wrote %s: %d quads, %d points" % (output, result.GetNumberOfPolys(), result.GetNumberOfPoints()))
    return 0 if result.GetNumberOfPolys() == 6 * 4 ** levels else 1


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:2]))
