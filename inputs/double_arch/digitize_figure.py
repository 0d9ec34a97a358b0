#!/usr/bin/python3
"""Reads the literature curve ("Reference", blue circles) off Kratos' published figure of the
frictional double arc, double_arch/figures/solution_frictional.png (1796 x 1612 px), and
writes it as CSV. How the figure is read:

- Axes, from the dashed grid lines (columns/rows of grey pixels inside the plot box):
  imposed displacement 0, 2, 4, 6 (x 1e-2 m) at columns 538, 843, 1148, 1453 (305 px per
  0.02 m); centre displacement -0.5, 0, 0.5, 1 (x 1e-2 m) at rows 1165, 925, 685, 445
  (240 px per 0.005 m). One pixel is 6.6e-5 m along x and 2.1e-5 m along y.
- Markers: the blue pixels (B > 0.7, R and G < 0.35) of the plot box outside the legend,
  correlated with a ring of radius 8 to 25 px; the best radius (16 px) gives one peak per
  circle (local maxima above 0.6 of the best). The circle at 0.0005 m that overlaps the
  one at 0 is merged with it.
- Reading uncertainty: +-2 px, i.e. +-1.3e-4 m in the imposed and +-4e-5 m in the centre
  displacement.

Usage: digitize_figure.py FIGURE.png OUTPUT.csv
(FIGURE: ../shared/reference/kratos_examples/double_arch/figures/solution_frictional.png;
the output is committed as frictional_reference_figure.csv.)
"""
import sys

import matplotlib.image as mpimg
import numpy as np
from scipy.ndimage import maximum_filter
from scipy.signal import fftconvolve

X0, PX_X = 538.0, 305.0 / 0.02  # column of imposed displacement 0, pixels per metre
Y0, PX_Y = 925.0, 240.0 / 0.005  # row of centre displacement 0, pixels per metre
PLOT_BOX = (250, 1290, 440, 1700)  # rows, columns inside the axes
LEGEND = (270, 720, 460, 1330)


def markers(path):
    rgb = mpimg.imread(path)[..., :3]
    if rgb.shape[:2] != (1612, 1796):
        raise SystemExit("digitize_figure.py: error: %s is %s px, expected 1612 x 1796 (the "
                         "calibration is for that figure)" % (path, rgb.shape[:2]))
    blue = ((rgb[..., 2] > 0.7) & (rgb[..., 0] < 0.35) & (rgb[..., 1] < 0.35)).astype(float)
    r0, r1, c0, c1 = PLOT_BOX
    mask = np.zeros_like(blue)
    mask[r0:r1, c0:c1] = 1
    blue *= mask
    l0, l1, k0, k1 = LEGEND
    blue[l0:l1, k0:k1] = 0
    best = None
    for radius in range(8, 26):
        yy, xx = np.mgrid[-radius - 3:radius + 4, -radius - 3:radius + 4]
        ring = (abs(np.hypot(yy, xx) - radius) < 1.5).astype(float)
        score = fftconvolve(blue, ring / ring.sum(), mode="same")
        if best is None or score.max() > best[0]:
            best = (score.max(), radius, score)
    top, radius, score = best
    peaks = (score == maximum_filter(score, size=2 * radius)) & (score > 0.6 * top)
    rows, cols = np.where(peaks)
    pts = sorted(((c - X0) / PX_X, (Y0 - r) / PX_Y) for r, c in zip(rows, cols))
    return radius, pts


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip().splitlines()[-3], file=sys.stderr)
        return 2
    radius, pts = markers(argv[1])
    with open(argv[2], "w") as f:
        f.write("# Literature reference of the frictional double arc (mu = 0.5), read off Kratos'\n"
                "# figure solution_frictional.png by digitize_figure.py (marker radius %d px);\n"
                "# uncertainty +-1.3e-4 m (imposed), +-4e-5 m (centre)\n" % radius)
        f.write("imposed_displacement[m],center_vertical_displacement[m]\n")
        for d, u in pts:
            f.write("%.5f,%.5f\n" % (d, u))
    print("digitize_figure.py: %d markers -> %s" % (len(pts), argv[2]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
