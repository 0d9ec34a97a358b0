#!/usr/bin/python3
"""Reads the reference curves off the published shallow-ironing figures (Poulios & Renard's
F_y and F_x, as redrawn in the Kratos example) into CSV files.

Usage: digitize_reference.py [FIGURE_DIR] [OUT_DIR]
  FIGURE_DIR: ../shared/reference/kratos_examples/shallow_ironing_3D/figures (default)
  writes OUT_DIR/reference_frictionless.csv and reference_frictional.csv (time, F_y, F_x in N)

How the figure is read: the axes are calibrated on the dashed grid lines, found as the pixel
columns and rows that are mostly grey (t = 0, 0.5, ..., 2 at columns 207.5 + 133.25 k;
F = 0, 1e8, 2e8, 3e8 at rows 579.5 - 122 k in the frictionless figure, 604.5 - 129.67 k in
the frictional one). The "ref." curves are the blue (F_y) and red (F_x) lines with hollow
circle markers; in each pixel column the curve is the middle of the column's blue (red)
pixels, which is the line itself between markers and the marker centre on a marker (the ring
is symmetric). The legend box is left out. Resolution: one pixel is 0.0038 s and 8e5 N.
"""
import os
import sys

import numpy as np
from matplotlib import image

HERE = os.path.dirname(os.path.abspath(__file__))
FIGURES = os.path.join(HERE, "..", "..", "..", "shared", "reference", "kratos_examples",
                       "shallow_ironing_3D", "figures")
# figure: (row of F = 0, rows per 1e8 N); t = (column - 207.5) / 266.5
CALIBRATION = {"frictionless": (579.5, 122.0), "frictional": (604.5, 129.67)}
LEGEND = (slice(130, 360), slice(165, 400))  # rows, columns of the legend box


def curve(mask, y0, dy):
    t, f = [], []
    for col in range(208, 742):
        rows = np.nonzero(mask[125:645, col])[0] + 125
        if len(rows) == 0:
            continue
        t.append((col - 207.5) / 266.5)
        f.append((y0 - 0.5 * (rows.min() + rows.max())) / dy * 1e8)
    return np.array(t), np.array(f)


def main():
    fig_dir = sys.argv[1] if len(sys.argv) > 1 else FIGURES
    out_dir = sys.argv[2] if len(sys.argv) > 2 else HERE
    for case, (y0, dy) in CALIBRATION.items():
        rgb = image.imread(os.path.join(fig_dir, "solution_%s.png" % case))[:, :, :3]
        rgb[LEGEND] = 1.0
        blue = (rgb[:, :, 2] > 0.7) & (rgb[:, :, 0] < 0.3) & (rgb[:, :, 1] < 0.3)
        red = (rgb[:, :, 0] > 0.7) & (rgb[:, :, 1] < 0.3) & (rgb[:, :, 2] < 0.3)
        t_y, f_y = curve(blue, y0, dy)
        t_x, f_x = curve(red, y0, dy)
        t = np.intersect1d(t_y, t_x)
        rows = np.column_stack([t, np.interp(t, t_y, f_y), np.interp(t, t_x, f_x)])
        path = os.path.join(out_dir, "reference_%s.csv" % case)
        np.savetxt(path, rows, delimiter=",", fmt="%.5g", header="time,F_y,F_x", comments="")
        plateau = (t >= 1.3) & (t <= 1.7)
        print("%s: %d points; plateau t in [1.3, 1.7]: F_y = %.4g, F_x = %.4g" %
              (path, len(t), rows[plateau, 1].mean(), rows[plateau, 2].mean()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
