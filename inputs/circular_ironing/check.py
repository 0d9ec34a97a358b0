"""Circular ironing, plane strain (docs/verification.md #20): the half-disc die of Kratos'
ironing_with_die_3D against the shallow die under the same loading (pressed 1, then slid),
frictionless.

Usage: check.py SIZE [--plateau T0 T1] [--ranks 1 2]     (SIZE: ci or full)

Reads np<r>/circular_SIZE.csv and np<r>/shallow_SIZE.csv: (R_x, R_y) = -(reaction_die_top_nodes_x,
reaction_die_top_nodes_y), the force of the block on the die, as in Kratos' comparison.png
(R_Y > 0; R_X < 0 while pressing the shallow die, > 0 near the block's end). Reference (qualitative, Kratos' comparison.png of the 3D
cases: R_y of the circular die 1.28e8 against 1.21e8 of the shallow one, +6 %, both R_X near
0 while sliding):
- the circular die's mean R_y over the plateau T0 <= t <= T1 is above the shallow die's by
  0 to 15 % ("slightly above");
- |R_x| <= 1e-2 R_y for the circular die at every step of the plateau (frictionless);
- 1 and 2 ranks: the same steps and reactions to 1e-10 relative.
Writes ironing_SIZE.png (R_y and R_x of both dies against t).
"""
import argparse
import csv
import sys

import numpy as np

ap = argparse.ArgumentParser()
ap.add_argument("size")
ap.add_argument("--plateau", type=float, nargs=2, default=[4.0, 5.0])
ap.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
a = ap.parse_args()


def read(np_, die):
    rows = list(csv.DictReader(open("np%d/%s_%s.csv" % (np_, die, a.size))))
    t = np.array([float(r["time"]) for r in rows])
    rx = -np.array([float(r["reaction_die_top_nodes_x"]) for r in rows])
    ry = -np.array([float(r["reaction_die_top_nodes_y"]) for r in rows])
    return t, rx, ry


failures = []
data = {(np_, die): read(np_, die) for np_ in a.ranks for die in ("circular", "shallow")}
for np_ in a.ranks:
    mean = {}
    for die in ("circular", "shallow"):
        t, rx, ry = data[(np_, die)]
        plateau = (t >= a.plateau[0] - 1e-12) & (t <= a.plateau[1] + 1e-12)
        if plateau.sum() < 3:
            failures.append("np%d %s: only %d steps in the plateau" % (np_, die, plateau.sum()))
            mean[die] = np.nan
            continue
        mean[die] = ry[plateau].mean()
        print("np%d %s: %d steps, %d on t = [%g, %g]: mean R_y = %.4g, max |R_x|/R_y = %.2e"
              % (np_, die, len(t), plateau.sum(), a.plateau[0], a.plateau[1], mean[die],
                 (np.abs(rx) / ry)[plateau].max()))
        if die == "circular" and not (np.abs(rx) / ry)[plateau].max() <= 1e-2:
            failures.append("np%d: circular |R_x|/R_y above 1e-2 on the plateau" % np_)
    ratio = mean["circular"] / mean["shallow"]
    print("np%d: R_y circular / shallow = %.4f (Kratos 3D: 1.28e8 / 1.21e8 = 1.06)" % (np_, ratio))
    if not 1.0 < ratio <= 1.15:
        failures.append("np%d: R_y circular / shallow = %.4f not in (1, 1.15]" % (np_, ratio))

if 1 in a.ranks and 2 in a.ranks:
    for die in ("circular", "shallow"):
        (t1, rx1, ry1), (t2, rx2, ry2) = data[(1, die)], data[(2, die)]
        if len(t1) != len(t2) or np.abs(t1 - t2).max() > 1e-12:
            failures.append("%s: 1 and 2 ranks took different steps" % die)
            continue
        diff = max(np.abs(rx1 - rx2).max(), np.abs(ry1 - ry2).max()) / np.abs(ry1).max()
        print("%s: 1 vs 2 ranks %.2e" % (die, diff))
        if not diff < 1e-10:
            failures.append("%s: 1 and 2 ranks differ by %.2e" % (die, diff))

try:
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for die, color in (("circular", "tab:red"), ("shallow", "tab:blue")):
        t, rx, ry = data[(a.ranks[0], die)]
        ax.plot(t, ry, "-", color=color, label="R_y %s die" % die)
        ax.plot(t, rx, "--", color=color, label="R_x %s die" % die)
    ax.axvspan(a.plateau[0], a.plateau[1], color="gray", alpha=0.1)
    ax.set_xlabel("t (press 1 for t <= 1, then slide x = t - 1)")
    ax.set_ylabel("reaction on the die's top (N per unit thickness)")
    ax.set_title("Circular against shallow ironing, frictionless (plane strain)")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig("ironing_%s.png" % a.size, dpi=100)
except ImportError:
    pass

if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("circular_ironing %s: all checks passed" % a.size)
