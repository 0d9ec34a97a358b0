#!/usr/bin/python3
"""Reads Kratos' 3D press fit curve off its published figure press_fit/figures/solution_3d.png
(855 x 807 px; "3D Press fit (base reaction)", horizontal reaction in N against time; the
Examples' README calls it "the reaction in the base support most western points") and writes
it as CSV, with digitize_reference.py's method (docstring there): the axes from the dashed grid
lines at time 0, 0.5, 1, 1.5 and reaction 0 ... 4e4 N, the curve from the blue pixels' centroid
per pixel column (the figure has no legend). One pixel is 2.6e-3 in time and 82 N; where the
curve is steep (t < 0.02) a column's centroid lies inside the vertical stroke (there the
stroke spans 2.2e4 to 3.37e4 N).

Usage: digitize_solution_3d.py [FIGURE.png] [OUTPUT.csv]
(FIGURE: solution_3d.png of the Kratos Examples' press_fit case, default as for
digitize_reference.py; OUTPUT: reference_solution_3d.csv next to this script)
"""
import os
import sys

import numpy as np

from digitize_reference import digitize


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    fig = argv[1] if len(argv) > 1 else os.path.join(
        here, "..", "..", "..", "shared", "reference", "kratos_examples", "press_fit", "figures",
        "solution_3d.png")
    out = argv[2] if len(argv) > 2 else os.path.join(here, "reference_solution_3d.csv")
    pts, (xs, ys, _, _) = digitize(fig, (0.0, 0.5, 1.0, 1.5), (0.0, 1e4, 2e4, 3e4, 4e4), (0, 0))
    with open(out, "w") as f:
        f.write("# digitised from press_fit/figures/solution_3d.png by digitize_solution_3d.py\n")
        f.write("# x grid columns %s, y grid rows %s (pixels)\n" %
                (", ".join("%.2f" % v for v in xs), ", ".join("%.2f" % v for v in ys)))
        f.write("time,reaction\n")
        for t, v in pts:
            f.write("%.5f,%.1f\n" % (t, v))
    k = int(np.argmax(pts[:, 1]))
    dip = pts[(pts[:, 0] > 0.2) & (pts[:, 0] < 0.5)]
    j = int(np.argmin(dip[:, 1]))
    print("digitize_solution_3d: %d points; peak %.4g at t = %.3f; dip %.4g at t = %.3f; "
          "last %.4g at t = %.3f; grid x %s, y %s" % (len(pts), pts[k, 1], pts[k, 0], dip[j, 1],
                                                      dip[j, 0], pts[-1, 1], pts[-1, 0], xs, ys))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
