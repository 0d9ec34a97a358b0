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
- --figure: also check the run --figure-run (default press_fit_3d_kratos_time: Kratos' 3D
  supports on Kratos' time axis, dt = 0.005 to t = 1.4, np1/STEM.e) against solution_3d.png,
  digitised into reference_solution_3d.csv (digitize_solution_3d.py). The figure is not the total
  base reaction (150-350 times smaller, another shape): the Examples' README calls it "the
  reaction in the base support most western points", i.e. the horizontal reaction of the base
  nodes at x = 0 (y = 0; three nodes, z = 0, 0.125, 0.25), summed here. Checked (#18, 10 %):
  the spike after the interference (largest value for t <= 0.05), the decay (t = 0.1 and 0.2),
  the dip (smallest value for 0.2 < t < 0.5), the peak (largest value after t = 0.5) and the
  values at t = 1.3 and 1.4, signed (the figure's values are all positive). Not in CI: measured,
  the first phase (block over the left end) matches within 8 %, but after the block reaches the
  ramp Grout's westernmost reaction changes sign and peaks at 1.35e4 at t = 1.0 while the figure
  rises to 3.81e4 at t = 0.92, so this check fails (docs/verification.md #18).
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

ap = argparse.ArgumentParser()
ap.add_argument("--held", default="press_fit_3d_plane_strain_ci")
ap.add_argument("--kratos", default="press_fit_3d_ci")
ap.add_argument("--two-d", default="press_fit_ci")
ap.add_argument("--plane-stress", default="press_fit_plane_stress_ci")
ap.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
ap.add_argument("--figure", action="store_true")
ap.add_argument("--figure-run", default="press_fit_3d_kratos_time")
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


def westernmost_reaction(stem):
    """(times, summed reaction_x of the base nodes at x = 0, y = 0) of np1/STEM.e."""
    from grout_results import Results

    r = Results("np1/%s.e" % stem)
    x = np.asarray(r.coordinates())
    x = x.T if x.shape[0] == 3 else x
    west = np.nonzero((np.abs(x[:, 0]) < 1e-9) & (np.abs(x[:, 1]) < 1e-9))[0]
    if len(west) != 3:
        raise SystemExit("np1/%s.e: %d base nodes at x = 0, expected 3" % (stem, len(west)))
    t = np.asarray(r.times())
    return t, np.array([r.nodal("reaction_x", k)[west].sum() for k in range(len(t))])


def figure_check(stem):
    """solution_3d.png (reference_solution_3d.csv) against the westernmost base reaction of
    np1/STEM.e (docstring, --figure); returns the failures."""
    ref = np.loadtxt(os.path.join(HERE, "reference_solution_3d.csv"), delimiter=",", comments="#",
                     skiprows=3)
    tf, rf = ref[:, 0], ref[:, 1]
    t, rg = westernmost_reaction(stem)
    out = []

    def extreme(tt, r, lo, hi, pick):
        sel = np.nonzero((tt > lo) & (tt <= hi))[0]
        k = sel[pick(r[sel])]
        return r[k], tt[k]

    rows = [("spike, t <= 0.05", extreme(t, rg, 0, 0.05, np.argmax),
             extreme(tf, rf, 0, 0.05, np.argmax))]
    for tq in (0.1, 0.2):
        rows.append(("t = %g" % tq, (np.interp(tq, t, rg), tq), (np.interp(tq, tf, rf), tq)))
    rows.append(("dip, 0.2 < t < 0.5", extreme(t, rg, 0.2, 0.5, np.argmin),
                 extreme(tf, rf, 0.2, 0.5, np.argmin)))
    rows.append(("peak, t > 0.5", extreme(t, rg, 0.5, 2, np.argmax),
                 extreme(tf, rf, 0.5, 2, np.argmax)))
    for tq in (1.3, 1.4):
        rows.append(("t = %g" % tq, (np.interp(tq, t, rg), tq), (np.interp(tq, tf, rf), tq)))
    print("solution_3d.png against the westernmost base reaction (x = 0, y = 0, 3 nodes) of "
          "np1/%s.e (N):" % stem)
    for what, (g, tg), (f, tfig) in rows:
        err = g / f - 1
        print("  %-20s Grout %10.4g at t = %.3f   figure %10.4g at t = %.3f   %+7.1f %%"
              % (what, g, tg, f, tfig, 100 * err))
        if not abs(err) <= TOL_FIGURE:
            out.append("%s: westernmost base reaction, %s: %.4g N vs solution_3d.png %.4g N "
                       "(%+.0f %%, #18: 10 %%)" % (stem, what, g, f, 100 * err))
    return out


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
    print("3D Kratos' supports, total base reaction: peak %.4g N at t = %.3f, %.4g N at t = 1.3 "
          "(solution_3d.png peaks at 3.81e4 N: it is not this sum)"
          % (base.max(), t[int(np.argmax(base))], base[-1]))

if a.figure:
    failures += figure_check(a.figure_run)
if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("press_fit 3D: all checks passed")
