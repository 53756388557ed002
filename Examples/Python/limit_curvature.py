"""Example: the exact limit surface and its curvature from Python.

1. A triangulated sphere refined twice by Loop, projected to the limit, with the limit
   normals and curvature: its mean curvature is positive everywhere.
2. The limit surface at chosen (face, u, v) locations: points, normals and curvature exactly
   there.
Writes <prefix>-loop.vtp.
    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/limit_curvature.py out
"""
import sys

import numpy as np
import subd
from vtkmodules.vtkFiltersSources import vtkSphereSource


def main(prefix="out"):
    source = vtkSphereSource()
    source.SetThetaResolution(10)
    source.SetPhiResolution(8)
    source.Update()
    sphere = subd.to_arrays(source.GetOutput())  # numpy arrays from here on
    cage = (sphere.points, sphere.faces)

    loop = subd.subdivide(cage, scheme="loop", levels=2, limit=True, normals=True, curvature=True)
    subd.write(loop, prefix + "-loop.vtp")
    mean = loop.point_data["Mean_Curvature"]
    print("Loop limit of a sphere: mean curvature in [%.3f, %.3f]" % (mean.min(), mean.max()))

    # Three locations on face 0: its corners' barycentre and two points near its edges.
    uv = np.array([(1 / 3, 1 / 3), (0.1, 0.05), (0.45, 0.45)])
    at = subd.limit_surface(cage, scheme="loop", samples=([0, 0, 0], uv), curvature=True)
    gauss = at.point_data["Gauss_Curvature"]
    for (u, v), point, k in zip(uv, at.points, gauss):
        print("  face 0 at (%.2f, %.2f): point (%.3f, %.3f, %.3f), Gaussian curvature %.3f"
              % ((u, v) + tuple(point) + (k,)))
    ok = mean.min() > 0 and len(at.points) == 3 and np.all(gauss > 0)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:2]))
