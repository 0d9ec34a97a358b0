"""Double arc (docs/verification.md #14; Kratos validation/double_arch; Drouet 2015, Poulios &
Renard 2015), plane strain: the vertical displacement u of the centre of the half ring (its
lowest outer node, node set ring_bottom) against the imposed displacement d = 0.4 t of the ring
ends.

Usage: check.py [--frictionless STEM] [--frictional STEM] [--ranks STEM ...] [--ring STEM]
                [--plot PREFIX]

Row 14's pass. No published curve is converged (Kratos' figure and CSV differ by 34 % of
max|u| through the snap), so the curves of the whole path (d up to 0.075, np1/STEM.e) must
show the literature's features, inside the row's bands:
- --frictionless STEM: the dip (the smallest u, at d_dip) 2.4 to 6 mm deep, at d_dip between
  0.015 and 0.021; then a snap-through: the end force |F| falls as d grows (a limit point of
  the displacement-controlled path, by more than DROP_MIN of its peak) and the centre jumps
  up through u = +0.02 m (the middle of the jump from about 0 to 0.04 m, where
  getfem_compare.py measures it too) at d between 0.046 and 0.057;
- --frictional STEM (mu = 0.5): the dip inside the same bands, and no snap-through: |F|
  never falls by more than DROP_MIN of its peak (the centre then rises gradually);
- the third part of the row, Grout within 1 % of GetFEM on the same mesh and law over the
  path, is getfem_compare.py --full (its own ctest).
d_dip is the d of the smallest u over the steps (0.5 mm of d apart in the whole paths), as
getfem_compare.py measures it; the curve is flat there (u changes by 3 um over +-0.5 mm on
Kratos' mesh), so d_dip is known to about a step.
A run that stops before d = 0.057 fails (the snap band is not reached). The largest error
against the literature curves (frictionless_reference_center_displacement.csv, and
frictional_reference_figure.csv read off Kratos' figure by digitize_figure.py), relative to
their largest |u|, is printed as information, not checked: #14 says why.

Other checks:
- --ranks STEM ... (short runs on np1/ and np2/): the centre curve and the final
  displacement field of 1 and 2 ranks agree to 1e-8 (relative); Newton: the order of the last
  contraction of the residual in each step (active set unchanged) has median >= 1.8
  (contact_check.newton_rates), in at least 3 steps;
- --ring STEM (a mesh fine enough through the stiff layer): at the first step the ring's own
  deflection d - delta_c (delta_c = -u_y of the centre) against Castigliano's clamped half ring
  (arch_theory.py, layers 0.085-0.09 m E = 1e11 and 0.09-0.095 m E = 1e9, nu = 0.3) with the
  computed end force: delta_ring = F / k_ring, k_ring = 1.566e8 N/m per m, within TOL_RING (3 %),
  on 1 and 2 ranks.
Writes PREFIX_<stem>.png (default: <stem>.png) for each whole path, with the bands.
"""
import argparse
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contact_check as cc  # noqa: E402
from grout_results import Results, relative_difference  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
RATE = 0.4  # imposed displacement d = 0.4 t (Kratos: "-t*0.4")
TOL_RING = 0.03
RING = [(0.085, 0.09, 1e11, 0.3), (0.09, 0.095, 1e9, 0.3)]  # (r_in, r_out, E, nu)
FORCE = "reaction_ring_ends_nodes_y"
# docs/verification.md #14's bands (m).
DIP_DEPTH = (0.0024, 0.006)
DIP_AT = (0.015, 0.021)
SNAP_AT = (0.046, 0.057)
SNAP_U = 0.02  # m: the middle of the snap-through jump (u goes from about 0 to 0.04)
DROP_MIN = 0.01  # a fall of |F| by more than 1 % of its peak: a limit point (snap-through)
REFERENCES = {"frictionless": "frictionless_reference_center_displacement.csv",
              "frictional": "frictional_reference_figure.csv"}


def read_reference(name):
    rows = [r for r in csv.reader(open(os.path.join(HERE, name))) if r and not r[0].startswith("#")]
    data = np.array([[float(v) for v in r[:2]] for r in rows[1:]])
    return data[:, 0], data[:, 1]


def centre_curve(path, force=None):
    """(d, u_centre) from a Grout Exodus file, the undeformed state first; with `force` (a
    global variable's name) also that variable, 0 first."""
    r = Results(path)
    node = cc.node_set(r, "ring_bottom")
    if len(node) != 1:
        raise SystemExit("%s: node set ring_bottom has %d nodes, expected 1" % (path, len(node)))
    t = r.times()
    u = np.array([r.nodal("displ_y", step=k)[node[0]] for k in range(len(t))])
    d, u = np.concatenate([[0.0], RATE * t]), np.concatenate([[0.0], u])
    if force is None:
        return d, u
    f = np.array([r.global_var(force, step=k) for k in range(len(t))])
    return d, u, np.concatenate([[0.0], f])


def dip(d, u):
    """(depth -min u, the d of the smallest u)."""
    k = int(np.argmin(u))
    return -u[k], d[k]


def snap(d, u, f):
    """(d where u first reaches SNAP_U after the dip, linear interpolation (nan if never),
    the largest fall of |F| as d grows, relative to max |F|, and the d where it starts)."""
    k = int(np.argmin(u))
    at = float("nan")
    for i in range(k, len(d) - 1):
        if u[i] < SNAP_U <= u[i + 1]:
            at = d[i] + (SNAP_U - u[i]) * (d[i + 1] - d[i]) / (u[i + 1] - u[i])
            break
    mag = np.abs(f)
    peak_so_far = np.maximum.accumulate(mag)
    fall = (peak_so_far - mag) / mag.max()
    j = int(np.argmax(fall))
    start = int(np.argmax(mag[:j + 1])) if fall[j] > 0 else j
    return at, float(fall[j]), d[start]


def inside(value, band):
    """value in the closed band, to round-off in d = 0.4 t (1e-12 m)."""
    return band[0] - 1e-12 <= value <= band[1] + 1e-12


def check_path(stem, kind, prefix, failures):
    """Row 14's bands on the whole path of np1/STEM.e; kind: frictionless or frictional."""
    d, u, f = centre_curve("np1/%s.e" % stem, force=FORCE)
    depth, d_dip = dip(d, u)
    at, fall, fall_from = snap(d, u, f)
    print("%s (%s): d up to %.4f m in %d steps; dip %.2f mm at d = %.4f (#14: %.1f to %.1f mm "
          "at d = %.3f to %.3f); u = +%.2f m at d = %.4f; largest fall of |F| %.1f %% of max |F| "
          "= %.3e N/m (from d = %.4f)"
          % (stem, kind, d[-1], len(d) - 1, 1e3 * depth, d_dip, 1e3 * DIP_DEPTH[0],
             1e3 * DIP_DEPTH[1], DIP_AT[0], DIP_AT[1], SNAP_U, at, 100 * fall, np.abs(f).max(),
             fall_from))
    if d[-1] < SNAP_AT[1] - 1e-12:
        failures.append("%s: the run stops at d = %.4f, before the end of the snap-through band "
                        "(%.3f)" % (stem, d[-1], SNAP_AT[1]))
        return
    if not inside(depth, DIP_DEPTH):
        failures.append("%s: dip %.2f mm, outside %.1f-%.1f mm" % (stem, 1e3 * depth,
                                                                    1e3 * DIP_DEPTH[0],
                                                                    1e3 * DIP_DEPTH[1]))
    if not inside(d_dip, DIP_AT):
        failures.append("%s: dip at d = %.4f, outside %.3f-%.3f" % (stem, d_dip, *DIP_AT))
    if kind == "frictionless":
        if not fall > DROP_MIN:
            failures.append("%s: no snap-through: |F| falls by %.2f %% of its peak at most"
                            % (stem, 100 * fall))
        if not inside(at, SNAP_AT):
            failures.append("%s: snap-through (u = +%.2f m) at d = %.4f, outside %.3f-%.3f"
                            % (stem, SNAP_U, at, *SNAP_AT))
    elif fall > DROP_MIN:
        failures.append("%s: snap-through with mu = 0.5: |F| falls by %.1f %% of its peak from "
                        "d = %.4f" % (stem, 100 * fall, fall_from))
    d_ref, u_ref = read_reference(REFERENCES[kind])
    within = d_ref <= d[-1] + 1e-12
    err = np.abs(np.interp(d_ref[within], d, u) - u_ref[within]) / np.abs(u_ref).max()
    print("   information: against %s (not converged, #14), max %.1f %% of its max|u| "
          "= %.4f m; its dip %.2f mm" % (REFERENCES[kind], 100 * err.max(), np.abs(u_ref).max(),
                                         -1e3 * u_ref.min()))
    plot(stem, kind, d, u, d_ref, u_ref, prefix)


def plot(stem, kind, d, u, d_ref, u_ref, prefix):
    try:
        import matplotlib.pyplot as plt
        from matplotlib.patches import Rectangle
    except ImportError:
        print("matplotlib not available: no figure")
        return
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.plot(d_ref, u_ref, "o", mfc="none", ms=4, label="literature (%s)" % kind)
    if kind == "frictionless":  # Kratos' own 3D solution (2017), for comparison
        name = os.path.join(HERE, "frictionless_kratos2017_center_displacement.csv")
        rows = list(csv.reader(open(name)))
        kr = np.array([[float(v) for v in r[1:3]] for r in rows[1:]])
        ax.plot(kr[:, 0], kr[:, 1], "--", color="gray", lw=1, label="Kratos 2017 (3D hexa)")
        ax.axvspan(*SNAP_AT, color="C1", alpha=0.12, label="#14: snap-through band")
    ax.add_patch(Rectangle((DIP_AT[0], -DIP_DEPTH[1]), DIP_AT[1] - DIP_AT[0],
                           DIP_DEPTH[1] - DIP_DEPTH[0], color="C2", alpha=0.3,
                           label="#14: dip band"))
    ax.plot(d, u, "-", color="C3", label="Grout, plane strain (%d steps)" % (len(d) - 1))
    ax.set_xlabel("imposed displacement d (m)")
    ax.set_ylabel("vertical displacement of the centre (m)")
    ax.set_title("Double arc, %s" % ("frictionless" if kind == "frictionless" else "mu = 0.5"))
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    out = "%s_%s.png" % (prefix, stem) if prefix else "%s.png" % stem
    fig.savefig(out, dpi=100)
    print("wrote %s" % out)


def check_ranks(stem, failures):
    """1 vs 2 ranks and Newton's order on the runs np1/STEM and np2/STEM."""
    d1, u1 = centre_curve("np1/%s.e" % stem)
    d2, u2 = centre_curve("np2/%s.e" % stem)
    if len(d1) != len(d2) or relative_difference(u1, u2) > 1e-8:
        failures.append("%s: the centre curves of 1 and 2 ranks differ (%d / %d steps)"
                        % (stem, len(d1), len(d2)))
    r1, r2 = Results("np1/%s.e" % stem), Results("np2/%s.e" % stem)
    diff = max(relative_difference(r1.nodal("displ_" + c), r2.nodal("displ_" + c)) for c in "xy")
    if not diff < 1e-8:
        failures.append("%s: 1 and 2 ranks differ by %.2e" % (stem, diff))
    orders = cc.newton_rates("np1/%s_newton.csv" % stem, failures, 1.8)
    cc.newton_rates("np2/%s_newton.csv" % stem, failures, 1.8)
    print("%s: d up to %.4f m, %d steps, 1 vs 2 ranks %.1e; Newton order of the last contraction "
          "in %d steps: min %.2f, median %.2f" % (stem, d1[-1], len(d1) - 1, diff, len(orders),
                                                  min(orders or [0]), np.median(orders or [0])))
    if len(orders) < 3:
        failures.append("%s: fewer than 3 steps in the quadratic range" % stem)


def check_ring(stem, failures):
    """The ring's deflection at the first step against Castigliano (arch_theory.py)."""
    from arch_theory import arch_stiffness
    k_ring = arch_stiffness(RING)
    for np_ in (1, 2):
        r = Results("np%d/%s.e" % (np_, stem))
        node = cc.node_set(r, "ring_bottom")[0]
        d = RATE * r.times()[0]
        ring = d + r.nodal("displ_y", step=0)[node]
        force = abs(r.global_var(FORCE, step=0))
        pred = force / k_ring
        if np_ == 1:
            print("%s: d = %.4f, end force %.4e N/m, ring deflection %.4e, Castigliano F/k_ring "
                  "%.4e (k_ring = %.4e), ratio %.4f" % (stem, d, force, ring, pred, k_ring,
                                                         ring / pred))
        if not abs(ring / pred - 1) <= TOL_RING:
            failures.append("np%d/%s: ring deflection %.4e, Castigliano %.4e (> %.0f %% apart)"
                            % (np_, stem, ring, pred, 100 * TOL_RING))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--frictionless", help="the whole frictionless path (np1/)")
    ap.add_argument("--frictional", help="the whole mu = 0.5 path (np1/)")
    ap.add_argument("--ranks", nargs="*", default=[], help="runs on np1/ and np2/")
    ap.add_argument("--ring")
    ap.add_argument("--plot", default="")
    a = ap.parse_args()
    failures = []
    if a.frictionless:
        check_path(a.frictionless, "frictionless", a.plot, failures)
    if a.frictional:
        check_path(a.frictional, "frictional", a.plot, failures)
    for stem in a.ranks:
        check_ranks(stem, failures)
    if a.ring:
        check_ring(a.ring, failures)
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        return 1
    print("double_arch: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
