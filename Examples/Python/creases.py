"""Example: creases from Python - automatic ones from a feature angle, and semi-sharp ones.

A box is subdivided by Catmull-Clark three times, projected to the limit:
1. plain: it rounds into a blob;
2. with a feature angle of 60 degrees: its 12 edges are infinitely sharp, it stays a box;
3. with the three edges at one corner given as creases of sharpness 1, 2 and 3: they round
   off less and less.
Each result goes to <prefix>-*.vtp; the program prints how far each one's corner point is
from the box's corner.
    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/creases.py box
"""
import sys

import numpy as np
import subd

UNIT_CUBE = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]])
BOX_POINTS = 2.0 * UNIT_CUBE - 1
BOX_FACES = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
CORNER = 6  # the point (1, 1, 1), and its three edges:
CORNER_EDGES = [(6, 5), (6, 7), (6, 2)]


def smooth(path, **options):
    mesh = subd.subdivide((BOX_POINTS, BOX_FACES), levels=3, limit=True, **options)
    subd.write(mesh, path)
    return np.min(np.linalg.norm(mesh.points - BOX_POINTS[CORNER], axis=1))


def main(prefix="box"):
    plain = smooth(prefix + "-plain.vtp")
    sharp = smooth(prefix + "-feature-angle.vtp", feature_angle=60.0)
    semi = [smooth("%s-semi-%d.vtp" % (prefix, s), creases=[(a, b, s) for a, b in CORNER_EDGES]) for s in (1, 2, 3)]
    print("distance from the box corner: plain %.3f, sharpness 1/2/3: %.3f / %.3f / %.3f, feature angle %.3g"
          % (plain, semi[0], semi[1], semi[2], sharp))
    # Sharper creases keep the corner closer; infinitely sharp ones keep it exactly.
    ok = plain > semi[0] > semi[1] > semi[2] > sharp and sharp < 1e-12
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:2]))
