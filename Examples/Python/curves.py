"""Example: subdivision curves from Python (Chaikin, cubic B-spline, 4-point).

A closed star-shaped control polygon with one sharp tip is refined by the three curve schemes;
each result carries unit tangents of its limit curve and is written to <prefix>-<scheme>.vtp.

Run with Debian's python3 and the build's package on the path:
    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/curves.py star
"""
import math
import sys

import numpy as np
import subd


def star(tips=5):
    angles = math.pi / 2 + np.arange(2 * tips) * math.pi / tips
    radius = np.where(np.arange(2 * tips) % 2 == 1, 0.45, 1.0)
    return np.column_stack([radius * np.cos(angles), radius * np.sin(angles), np.zeros(2 * tips)])


def main(prefix="star", levels=4):
    points = star()
    status = 0
    for scheme in ("chaikin", "bspline", "four-point"):
        # Repeating the first point closes the polyline; corner sharpness 10 keeps the top tip.
        curve = subd.refine_curve((points, [list(range(len(points))) + [0]]), scheme=scheme, levels=levels,
                                  corners={0: 10}, tangents=True)
        refined = curve.points
        subd.write(curve, "%s-%s.vtp" % (prefix, scheme))
        print("%s: %d control points -> %d points, tangents %s" % (
            scheme, len(points), len(refined), curve.point_data["Tangents"].shape))
        # The corner opens the closed polygon: 11 points from tip to tip, 10 spans. Each level
        # doubles the spans (Chaikin's clamped ends have one span less to double: 9); the tip
        # (point 0, at the top) is kept exactly and listed once.
        spans = 9 if scheme == "chaikin" else 10
        expected = spans * 2 ** levels + (1 if scheme == "chaikin" else 0)
        tip = np.min(np.linalg.norm(refined - points[0], axis=1))
        if len(refined) != expected or tip != 0.0:
            status = 1
    return status


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:2]))
