"""Double arc (Kratos validation/double_arch; Drouet 2015, Poulios & Renard 2015), plane strain:
the vertical displacement of the centre of the half ring (its lowest outer node, node set
ring_bottom) against the imposed displacement d = 0.4 t of the ring ends.

Usage: check.py [--frictionless STEM] [--frictional STEM] [--ring STEM] [--tol-frictionless 0.03]
                [--tol-frictional 0.10] [--report-only] [--plot PREFIX]
Results are read from np1/STEM.e and np2/STEM.e (run on 1 and 2 ranks). --report-only prints
the errors against the literature curves without failing on them (the CI run: the 3 % target
is not met, docs/verification.md); every other check still fails the run.

Checks:
- frictionless: against frictionless_reference_center_displacement.csv (the literature curve,
  33 points, d = 0.0053 to 0.0748), at every reference point the run reaches (the computed
  curve is interpolated linearly between steps at the reference d). Error measure:
  e = max_i |u(d_i) - u_ref,i| / max_i |u_ref,i| (max |u_ref| = 0.0519 m, the largest
  deflection of the whole path), within --tol-frictionless (3 %);
- frictional (mu = 0.5): against frictional_reference_figure.csv, the literature curve read
  off Kratos' published figure by digitize_figure.py (21 points, reading uncertainty
  4e-5 m); the same measure relative to max |u_ref| = 0.0107 m, within --tol-frictional;
- ring (--ring STEM, a mesh fine enough through the stiff layer): at the first step the
  ring's own deflection d - delta_c (delta_c = -u_y of the centre) against Castigliano's
  clamped half ring (arch_theory.py, layers 0.085-0.09 m E = 1e11 and 0.09-0.095 m E = 1e9,
  nu = 0.3) with the computed end force: delta_ring = F / k_ring, k_ring = 1.566e8 N/m per m,
  within TOL_RING (3 %);
- 1 and 2 ranks: the centre curve and the final displacement field agree to 1e-8 (relative);
- Newton: the order of the last contraction of the residual in each step (active set
  unchanged) has median >= 1.8 and minimum >= 1.3 (contact_check.newton_rates);
Writes PREFIX_<stem>.png (default: the stem) with the curve against the reference.
"""
import argparse
import csv
import math
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
C_QUADRATIC = 10.0


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



def check_ring(stem, failures):
    """The ring's deflection at the first step against Castigliano (arch_theory.py)."""
    from arch_theory import arch_stiffness
    k_ring = arch_stiffness(RING)
    for np_ in (1, 2):
        r = Results("np%d/%s.e" % (np_, stem))
        node = cc.node_set(r, "ring_bottom")[0]
        d = RATE * r.times()[0]
        ring = d + r.nodal("displ_y", step=0)[node]
        force = abs(r.global_var("reaction_ring_ends_nodes_y", step=0))
        pred = force / k_ring
        if np_ == 1:
            print("%s: d = %.4f, end force %.4e N/m, ring deflection %.4e, Castigliano F/k_ring "
                  "%.4e (k_ring = %.4e), ratio %.4f" % (stem, d, force, ring, pred, k_ring,
                                                         ring / pred))
        if not abs(ring / pred - 1) <= TOL_RING:
            failures.append("np%d/%s: ring deflection %.4e, Castigliano %.4e (> %.0f %% apart)"
                            % (np_, stem, ring, pred, 100 * TOL_RING))


def check_case(stem, reference, tol, label, prefix, failures, report_only=False):
    d_ref, u_ref = read_reference(reference)
    scale = np.abs(u_ref).max()
    d1, u1 = centre_curve("np1/%s.e" % stem)
    d2, u2 = centre_curve("np2/%s.e" % stem)
    if len(d1) != len(d2) or relative_difference(u1, u2) > 1e-8:
        failures.append("%s: the centre curves of 1 and 2 ranks differ (%d / %d steps)"
                        % (stem, len(d1), len(d2)))
    r1, r2 = Results("np1/%s.e" % stem), Results("np2/%s.e" % stem)
    diff = max(relative_difference(r1.nodal("displ_" + c), r2.nodal("displ_" + c)) for c in "xy")
    if not diff < 1e-8:
        failures.append("%s: 1 and 2 ranks differ by %.2e" % (stem, diff))
    inside = (d_ref >= d1[0]) & (d_ref <= d1[-1] + 1e-12)
    if inside.sum() < 3:
        failures.append("%s: the run (d up to %.4f) reaches fewer than 3 reference points"
                        % (stem, d1[-1]))
        return
    u_at = np.interp(d_ref[inside], d1, u1)
    err = np.abs(u_at - u_ref[inside]) / scale
    worst = int(np.argmax(err))
    print("%s: d up to %.4f m, %d steps, %d reference points; error max %.2f %% (at d = %.4f: "
          "%.5f against %.5f), rms %.2f %% of max|u_ref| = %.4f; 1 vs 2 ranks %.1e"
          % (stem, d1[-1], len(d1) - 1, inside.sum(), 100 * err.max(), d_ref[inside][worst],
             u_at[worst], u_ref[inside][worst], 100 * math.sqrt((err ** 2).mean()), scale, diff))
    for d, uc, ur, e in zip(d_ref[inside], u_at, u_ref[inside], err):
        print("   d = %.4f  u = %+.5f  reference %+.5f  error %5.2f %%" % (d, uc, ur, 100 * e))
    if not err.max() <= tol:
        msg = "%s: error %.2f %% > %.1f %% of max|u_ref|" % (stem, 100 * err.max(), 100 * tol)
        if report_only:
            print("KNOWN GAP (not failing, --report-only): " + msg)
        else:
            failures.append(msg)
    orders = cc.newton_rates("np1/%s_newton.csv" % stem, failures, 1.8)
    cc.newton_rates("np2/%s_newton.csv" % stem, failures, 1.8)
    print("%s: Newton order of the last contraction in %d steps: min %.2f, median %.2f, "
          "%.0f %% of the steps >= 1.8" % (stem, len(orders), min(orders or [0]),
                                             np.median(orders or [0]),
                                             100 * np.mean(np.array(orders) >= 1.8)))
    if len(orders) < 3:
        failures.append("%s: fewer than 3 steps in the quadratic range" % stem)
    try:
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 4.5))
        ax.plot(d_ref, u_ref, "o", mfc="none", label="reference (%s)" % label)
        ax.fill_between(d_ref, u_ref - tol * scale, u_ref + tol * scale, color="C0", alpha=0.15,
                        label="reference +- %.0f %% of max|u|" % (100 * tol))
        if label == "frictionless":  # Kratos' own 3D solution (2017), for comparison
            name = os.path.join(HERE, "frictionless_kratos2017_center_displacement.csv")
            rows = list(csv.reader(open(name)))
            kr = np.array([[float(v) for v in r[1:3]] for r in rows[1:]])
            kr = kr[kr[:, 0] <= d1[-1] + 1e-12]
            ax.plot(kr[:, 0], kr[:, 1], "--", color="gray", lw=1, label="Kratos 2017 (3D hexa)")
        ax.plot(d1, u1, "-", color="C3", label="Grout, plane strain (%d steps)" % (len(d1) - 1))
        ax.set_xlabel("imposed displacement (m)")
        ax.set_ylabel("vertical displacement of the centre (m)")
        ax.set_title("Double arc, %s" % label)
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
        fig.tight_layout()
        out = "%s_%s.png" % (prefix, stem) if prefix else "%s.png" % stem
        fig.savefig(out, dpi=100)
        print("wrote %s" % out)
    except ImportError:
        print("matplotlib not available: no figure")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--frictionless")
    ap.add_argument("--frictional")
    ap.add_argument("--tol-frictionless", type=float, default=0.03)
    ap.add_argument("--tol-frictional", type=float, default=0.10)
    ap.add_argument("--ring")
    ap.add_argument("--report-only", action="store_true")
    ap.add_argument("--plot", default="")
    a = ap.parse_args()
    failures = []
    if a.frictionless:
        check_case(a.frictionless, "frictionless_reference_center_displacement.csv",
                   a.tol_frictionless, "frictionless", a.plot, failures, a.report_only)
    if a.frictional:
        check_case(a.frictional, "frictional_reference_figure.csv", a.tol_frictional,
                   "mu = 0.5", a.plot, failures, a.report_only)
    if a.ring:
        check_ring(a.ring, failures)
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        return 1
    print("double_arch: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
