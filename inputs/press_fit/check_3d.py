"""Press fit 3D (docs/verification.md #18): Kratos' 3D mesh (press_fit_3d.mdpa: the 2D section
extruded 0.25 in z, 363 nodes, 172 HEX8), the 2D case's materials, contact and path.

Usage: check_3d.py [--held STEM] [--kratos STEM] [--two-d STEM] [--plane-stress STEM]
                   [--ranks 1 2] [--figure]

Runs (np<r>/STEM.csv; reactions per metre of thickness / 1000 = the 2D figure's N per mm):
- --held (default press_fit_3d_plane_strain_ci): every block node held in z as well, i.e. plane
  strain in 3D. Checked (#18): the plateau (mean after figure step 137) within 3 % of the 2D
  plane-strain run (--two-d, default press_fit_ci, press_fit_ci.yaml) and of the closed-form
  strip (check.py's strip_plateaus); the peak within 3 % of the 2D run's; every step converged;
  the runs on the --ranks agree to 1e-8 (relative to the peak).
- --kratos (default press_fit_3d_ci, 1 rank): Kratos' own 3D supports (block held in z on its
  top only: its faces z = 0 and 0.25 are free, so the block is neither plane strain nor plane
  stress). Printed beside the 2D plane-strain and plane-stress runs (--plane-stress, default
  press_fit_plane_stress_ci), with every step converged; not held to the plane-strain targets.
- --figure: also check the --kratos run against solution_3d.png (Kratos' base reaction in N,
  read off the figure: peak 3.81e4 at t = 0.92, just below the 4e4 grid line; no plateau: the
  curve falls from the peak to 0.51e4 at t = 1.4; at t = 1.3, about 1.2e4) -- peak and the value at
  t = 1.3 within 10 % (#18). Not in CI: the figure is 150 times below Grout's base reaction
  and of another shape (docs/verification.md #18), so this check fails.
"""
import argparse
import csv
import importlib.util
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
THICKNESS = 0.25
TOL_2D = 0.03  # #18: the plateau against the 2D plane-strain run and the strip
TOL_FIGURE = 0.10  # #18: against solution_3d.png
FIGURE_PEAK, FIGURE_AT_1_3 = 3.81e4, 1.2e4  # N, read off solution_3d.png (docstring)

ap = argparse.ArgumentParser()
ap.add_argument("--held", default="press_fit_3d_plane_strain_ci")
ap.add_argument("--kratos", default="press_fit_3d_ci")
ap.add_argument("--two-d", default="press_fit_ci")
ap.add_argument("--plane-stress", default="press_fit_plane_stress_ci")
ap.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
ap.add_argument("--figure", action="store_true")
a = ap.parse_args()

spec = importlib.util.spec_from_file_location("press_fit_check", os.path.join(HERE, "check.py"))
press_fit_check = importlib.util.module_from_spec(spec)
spec.loader.exec_module(press_fit_check)  # strip_plateaus (its main() runs only as a script)


def curve(stem, np_, node_set, per_metre):
    """(figure steps, |R_x| of node_set in N/mm of thickness, or N if not per_metre)."""
    rows = list(csv.DictReader(open("np%d/%s.csv" % (np_, stem))))
    t = np.array([float(r["time"]) for r in rows])
    rx = np.abs([float(r["reaction_%s_x" % node_set]) for r in rows])
    return t, t * 150 / 1.3, (rx / THICKNESS / 1e3 if per_metre else rx)


def summary(s, rx):
    k = int(np.argmax(rx))
    return rx[k], s[k], rx[s > 137].mean()


failures = []
_, strip = press_fit_check.strip_plateaus()
t2, s2, r2 = curve(a.two_d, 1, "displacement_displacement_auto3", False)
r2 = r2 / 1e3
peak2, _, plateau2 = summary(s2, r2)
print("2D plane strain (%s): peak %.4g, plateau %.4g N/mm; closed-form strip %.4g"
      % (a.two_d, peak2, plateau2, strip))

held = {}
for np_ in a.ranks:
    t, s, rx = curve(a.held, np_, "displacement_displacement_auto4", True)
    held[np_] = rx
    peak, peak_step, plateau = summary(s, rx)
    print("3D held in z, np%d (%s): peak %.4g at step %.0f (%+.2f %% of 2D), plateau %.4g "
          "(%+.2f %% of 2D, %+.2f %% of the strip)"
          % (np_, a.held, peak, peak_step, 100 * (peak / peak2 - 1), plateau,
             100 * (plateau / plateau2 - 1), 100 * (plateau / strip - 1)))
    if abs(t[-1] - 1.3) > 1e-9:
        failures.append("%s np%d stopped at t = %g" % (a.held, np_, t[-1]))
    for what, value, ref in (("plateau", plateau, plateau2), ("plateau", plateau, strip),
                             ("peak", peak, peak2)):
        if not abs(value / ref - 1) <= TOL_2D:
            failures.append("%s np%d: %s %.4g vs %.4g (%+.1f %%, #18: 3 %%)"
                            % (a.held, np_, what, value, ref, 100 * (value / ref - 1)))
if len(held) > 1:
    first = held[a.ranks[0]]
    for np_ in a.ranks[1:]:
        diff = (np.abs(held[np_] - first).max() / first.max()
                if len(held[np_]) == len(first) else np.inf)
        print("3D held in z: np%d vs np%d: %.2e" % (a.ranks[0], np_, diff))
        if not diff <= 1e-8:
            failures.append("%s: np%d and np%d differ by %.2e" % (a.held, a.ranks[0], np_, diff))

if a.kratos:
    t, s, rx = curve(a.kratos, 1, "displacement_displacement_auto4", True)
    peak, peak_step, plateau = summary(s, rx)
    _, s_ps, r_ps = curve(a.plane_stress, 1, "displacement_displacement_auto3", False)
    peak_ps, _, plateau_ps = summary(s_ps, r_ps / 1e3)
    print("3D Kratos' supports (%s): peak %.4g (2D plane strain %+.1f %%, plane stress %+.1f %%), "
          "plateau %.4g (plane strain %+.1f %%, plane stress %+.1f %%) N/mm"
          % (a.kratos, peak, 100 * (peak / peak2 - 1), 100 * (peak / peak_ps - 1), plateau,
             100 * (plateau / plateau2 - 1), 100 * (plateau / plateau_ps - 1)))
    if abs(t[-1] - 1.3) > 1e-9:
        failures.append("%s stopped at t = %g" % (a.kratos, t[-1]))
    _, _, base = curve(a.kratos, 1, "displacement_displacement_auto2", False)
    print("3D Kratos' supports, base reaction: peak %.4g N at t = %.3f, %.4g N at t = 1.3; "
          "solution_3d.png: peak %.3g N, %.3g N at t = 1.3"
          % (base.max(), t[int(np.argmax(base))], base[-1], FIGURE_PEAK, FIGURE_AT_1_3))
    if a.figure:
        for what, value, ref in (("peak", base.max(), FIGURE_PEAK), ("t = 1.3", base[-1],
                                                                       FIGURE_AT_1_3)):
            if not abs(value / ref - 1) <= TOL_FIGURE:
                failures.append("%s: base reaction %s %.4g N vs solution_3d.png %.3g N (%+.0f %%, "
                                "#18: 10 %%)" % (a.kratos, what, value, ref,
                                                 100 * (value / ref - 1)))

if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("press_fit 3D: all checks passed")
