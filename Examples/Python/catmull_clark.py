"""Example: Catmull-Clark subdivision from Python, numpy in and numpy out.

Run with Debian's python3 and the build's package on the path:
    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/catmull_clark.py
"""
import sys

import numpy as np
import subd

CUBE_POINTS = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]])
CUBE_FACES = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]


def main(output="cube-smooth-python.vtp", levels=3):
    mesh = subd.subdivide((CUBE_POINTS, CUBE_FACES), scheme="catmull-clark", levels=levels, normals=True)
    subd.write(mesh, output)
    print("wrote %s: %d quads, %d points, normals %s" % (
        output, len(mesh.faces), len(mesh.points), mesh.point_data["Normals"].shape))
    return 0 if mesh.faces.shape == (6 * 4 ** levels, 4) else 1


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:2]))
