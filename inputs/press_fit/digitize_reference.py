#!/usr/bin/python3
"""Reads the reference curve ("Reference", solid blue: Fischer & Wriggers 2006) off Kratos'
published figure press_fit/figures/solution_2d.png (833 x 814 px) and writes it as CSV.

Usage: digitize_reference.py [FIGURE.png] [OUTPUT.csv]
(defaults: ../shared/reference/kratos_examples/press_fit/figures/solution_2d.png from the
repository's parent folder, and reference_solution_2d.csv next to this script)

How:
1. Axes calibration from the dashed grid lines, which sit at the tick values: pixel columns
   whose light-gray pixels (RGB 185..200) are many mark the x grid (steps 0, 50, 100, 150),
   rows the y grid (0, 1, 2, 3, 4 x 1e4); the centroid of each run gives its pixel position
   (sub-pixel); of these, the equally spaced ones are the grid (the legend box's edge is
   gray too), and a least-squares line maps pixels to values.
2. The curve: "blue" pixels (B > 150, R < 120, G < 120: the anti-aliased solid blue line),
   outside the legend box; in each pixel column the centroid of their rows, weighted by the
   blueness, is one point. Columns where the red dashed line hides the blue one have no point.
3. Pixels -> (step, reaction in the figure's unit, N/mm per unit thickness).
The scale is read to about +-0.5 px: +-0.15 steps and +-45 (0.1 % of the peak) in y.
"""
import os
import sys

import numpy as np


def runs(mask_counts, threshold):
    """Centroids of the runs of indices whose count exceeds threshold."""
    idx = np.nonzero(mask_counts > threshold)[0]
    groups, cur = [], [idx[0]]
    for i in idx[1:]:
        if i == cur[-1] + 1:
            cur.append(i)
        else:
            groups.append(cur)
            cur = [i]
    groups.append(cur)
    return [float(np.average(g, weights=mask_counts[g])) for g in groups]


def equally_spaced(candidates, n):
    """The n candidates (sorted) closest to an equally spaced set spanning the widest range:
    the grid lines, without the legend box's edges."""
    import itertools

    best, best_err = None, None
    for sub in itertools.combinations(sorted(candidates), n):
        step = (sub[-1] - sub[0]) / (n - 1)
        err = max(abs(v - (sub[0] + k * step)) for k, v in enumerate(sub))
        if err < 2.0 and (best is None or sub[-1] - sub[0] > best[-1] - best[0]):
            best, best_err = sub, err
    if best is None:
        raise RuntimeError("no %d equally spaced grid lines among %s" % (n, candidates))
    return list(best)


def digitize(path, x_ticks=(0.0, 50.0, 100.0, 150.0), y_ticks=(0.0, 1e4, 2e4, 3e4, 4e4),
             legend=(480, 265)):
    """(points (x, y) of the blue curve, (x grid columns, y grid rows, x map, y map)); the
    grid lines sit at x_ticks and y_ticks; legend = (right column, bottom row) of a legend box
    in the upper left whose blue pixels are skipped ((0, 0): none)."""
    import matplotlib.image as mpimg

    rgb = (mpimg.imread(path)[:, :, :3] * 255).round()
    gray = (rgb.max(axis=2) - rgb.min(axis=2) <= 2) & (rgb[:, :, 0] >= 185) & (rgb[:, :, 0] <= 200)
    xs = equally_spaced(runs(gray.sum(axis=0), 100), len(x_ticks))  # left to right
    ys = equally_spaced(runs(gray.sum(axis=1), 100), len(y_ticks))[::-1]  # bottom up
    ax = np.polyfit(xs, list(x_ticks), 1)
    ay = np.polyfit(ys, list(y_ticks), 1)
    for name, a, px, v in (("x", ax, xs, list(x_ticks)), ("y", ay, ys, list(y_ticks))):
        if np.abs(np.polyval(a, px) - v).max() > 0.01 * (v[-1] - v[0]):
            raise RuntimeError("%s: %s grid lines %s are not equally spaced" % (path, name, px))
    b = rgb[:, :, 2] - np.maximum(rgb[:, :, 0], rgb[:, :, 1])
    blue = (rgb[:, :, 2] > 150) & (rgb[:, :, 0] < 120) & (rgb[:, :, 1] < 120)
    rows = np.arange(rgb.shape[0])
    legend_right, legend_bottom = legend  # legend box (upper left)
    points = []
    for col in range(rgb.shape[1]):
        sel = blue[:, col] & ~((col < legend_right) & (rows < legend_bottom))
        if not sel.any():
            continue
        r = float(np.average(rows[sel], weights=b[sel, col]))
        points.append((np.polyval(ax, col), np.polyval(ay, r)))
    return np.array(points), (xs, ys, ax, ay)


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    fig = argv[1] if len(argv) > 1 else os.path.join(
        here, "..", "..", "..", "shared", "reference", "kratos_examples", "press_fit", "figures",
        "solution_2d.png")
    out = argv[2] if len(argv) > 2 else os.path.join(here, "reference_solution_2d.csv")
    pts, (xs, ys, ax, ay) = digitize(fig)
    with open(out, "w") as f:
        f.write("# digitised from press_fit/figures/solution_2d.png by digitize_reference.py\n")
        f.write("# x grid columns %s, y grid rows %s (pixels)\n" %
                (", ".join("%.2f" % v for v in xs), ", ".join("%.2f" % v for v in ys)))
        f.write("step,reaction\n")
        for s, v in pts:
            f.write("%.3f,%.1f\n" % (s, v))
    k = int(np.argmax(pts[:, 1]))
    late = pts[pts[:, 0] > 137, 1]
    print("digitize_reference: %d points; peak %.4g at step %.1f; mean after step 137 %.4g; "
          "grid x %s, y %s" % (len(pts), pts[k, 1], pts[k, 0], late.mean(), xs, ys))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
