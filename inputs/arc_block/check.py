"""Arc pressing a block (Kratos use_cases/arc_block), plane strain, three stiffness ratios
E_arc / E_block = 10 ("rigid block"), 1000 ("deformable block"), 10000 ("rigid arc").

Measure: the share of the strain energy each body holds, W_block / (W_arc + W_block), with
W = sum over the elements of a block of the Neo-Hookean energy (plane strain, 2 x 2 Gauss
points) of the computed displacements (strain_energy). Also: the arc's own deflection
delta_arc = d - delta_c, delta_c = -u_y of its lowest outer node (node set ring_bottom), and
the vertical end force F (reaction_ring_ends_nodes_y).

References and checks:
- energy balance: W_arc + W_block = int F dd (frictionless contact does no work), at the last
  step within TOL_BALANCE (the trapezoid rule over the steps);
- the arc at the first step (d <= D_LINEAR): a clamped half ring under a central point load,
  Castigliano (../double_arch/arch_theory.py; bending, axial and shear energy, plane strain,
  R = 2.9, h = 0.2): k_arc = 1.680e7 N/m per m for E = 6.896e9 (x 10 for 6.896e10);
  delta_arc = F / k_arc within TOL_ARC where delta_arc >= 1 % of d;
- the split at the first step: two compliances in series, W_block / W = k_arc / (k_arc +
  k_block), with k_block = F / delta_c of the rigid-arc case (its arc is 1e4 times stiffer,
  so delta_c is the block's indentation), scaled by E_block (Neo-Hookean stress is
  proportional to E at a given deformation); within TOL_SPLIT (absolute);
- over the whole path the softer body holds most of the energy: the arc >= 0.9 of it with
  the rigid block (ratio 10), the block >= 0.9 with the rigid arc (ratio 1e4), the deformable
  block in between (the share increases with the ratio at the last step);
- 1 and 2 ranks agree to 1e-10 (docs/verification.md); the Newton order of the last contraction in each step
  (contact_check.newton_rates) has median >= 1.5 and minimum >= 1.3.
Writes arc_block_split.png (the block's energy share against d, the three cases).

Usage: check.py [--cases STEM:E_ARC:E_BLOCK ...]
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "double_arch"))
import arch_theory  # noqa: E402
import contact_check as cc  # noqa: E402
from grout_results import Results, relative_difference  # noqa: E402

R, H, NU = 2.9, 0.2, 0.32
D_LINEAR = 0.05
TOL_ARC = 0.10
TOL_SPLIT = 0.05
TOL_BALANCE = 0.02
C_QUADRATIC = 10.0
DEFAULT_CASES = ["rigid_block:6.896e9:6.896e8", "deformable_block:6.896e9:6.896e6",
                 "rigid_arc:6.896e10:6.896e6"]


def arch_stiffness(e):
    """P / delta of the arc (a clamped half ring, r in [2.8, 3.0]) under a point load at its
    lowest point: Castigliano, ../double_arch/arch_theory.py."""
    return arch_theory.arch_stiffness([(R - H / 2, R + H / 2, e, NU)])


def strain_energy(r, block, e, nu, step):
    """Neo-Hookean plane-strain energy of element block `block` at `step`:
    sum over QUAD4 elements and 2 x 2 Gauss points of W(F) det(dX/dxi),
    W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2 with I1 = tr(F^T F) + 1 (F33 = 1)."""
    lam, mu = e * nu / ((1 + nu) * (1 - 2 * nu)), e / (2 * (1 + nu))
    b = cc.block_names(r).index(block) + 1
    conn = r.connectivity(b)
    xy = r.coordinates()[:2].T
    u = np.stack([r.nodal("displ_x", step=step), r.nodal("displ_y", step=step)], axis=1)
    X, x = xy[conn], (xy + u)[conn]  # (n_e, 4, 2)
    total = 0.0
    g = 1 / np.sqrt(3)
    for xi, eta in [(-g, -g), (g, -g), (g, g), (-g, g)]:
        dn = 0.25 * np.array([[-(1 - eta), -(1 - xi)], [1 - eta, -(1 + xi)],
                              [1 + eta, 1 + xi], [-(1 + eta), 1 - xi]])  # dN/dxi (4, 2)
        jac0 = np.einsum("eai,aj->eij", X, dn)  # dX/dxi
        jac = np.einsum("eai,aj->eij", x, dn)  # dx/dxi
        f = jac @ np.linalg.inv(jac0)
        det_f = np.linalg.det(f)
        i1 = np.einsum("eij,eij->e", f, f) + 1.0
        w = mu / 2 * (i1 - 3) - mu * np.log(det_f) + lam / 2 * np.log(det_f) ** 2
        total += np.sum(w * np.linalg.det(jac0))
    return total


def read_case(stem, failures, e_arc, e_block):
    out = {}
    for np_ in (1, 2):
        r = Results("np%d/%s.e" % (np_, stem))
        node = cc.node_set(r, "ring_bottom")[0]
        t = r.times()
        dc = np.array([-r.nodal("displ_y", step=k)[node] for k in range(len(t))])
        f = np.array([abs(r.global_var("reaction_ring_ends_nodes_y", step=k))
                      for k in range(len(t))])
        out[np_] = (np.concatenate([[0], t]), np.concatenate([[0], dc]),
                    np.concatenate([[0], f]), r)
    (d, dc, f, r1), (d2, dc2, _, r2) = out[1], out[2]
    diff = max(relative_difference(r1.nodal("displ_" + c), r2.nodal("displ_" + c))
               for c in "xy")
    if len(d) != len(d2) or relative_difference(dc, dc2) > 1e-10 or not diff < 1e-10:
        failures.append("%s: 1 and 2 ranks differ (%.2e)" % (stem, diff))
    work = np.concatenate([[0], np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(d))])
    steps = range(len(d) - 1)
    w_block = np.array([0.0] + [strain_energy(r1, "base", e_block, NU, k) for k in steps])
    w_arc = np.array([0.0] + [strain_energy(r1, "arc", e_arc, NU, k) for k in steps])
    checked = cc.newton_rates("np1/%s_newton.csv" % stem, failures, 1.5)
    cc.newton_rates("np2/%s_newton.csv" % stem, failures, 1.5)
    return dict(d=d, dc=dc, f=f, work=work, w_block=w_block, w_arc=w_arc, diff=diff,
                newton=checked)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", nargs="+", default=DEFAULT_CASES)
    a = ap.parse_args()
    failures = []
    cases = {}
    for spec in a.cases:
        stem, e_arc, e_block = spec.split(":")
        c = read_case(stem, failures, float(e_arc), float(e_block))
        c.update(stem=stem, e_arc=float(e_arc), e_block=float(e_block),
                 k_arc=arch_stiffness(float(e_arc)))
        c["share"] = c["w_block"][1:] / (c["w_arc"][1:] + c["w_block"][1:])
        cases[stem] = c
    # Block indentation stiffness per unit E_block, from the stiffest arc at its first step.
    stiff = max(cases.values(), key=lambda c: c["e_arc"] / c["e_block"])
    kb_per_e = stiff["f"][1] / stiff["dc"][1] / stiff["e_block"]
    print("block indentation stiffness from %s at d = %.4f: k_block / E_block = %.4f"
          % (stiff["stem"], stiff["d"][1], kb_per_e))
    for c in cases.values():
        d, dc, f = c["d"], c["dc"], c["f"]
        ratio = c["e_arc"] / c["e_block"]
        if not d[1] <= D_LINEAR + 1e-12:
            failures.append("%s: first step d = %g > %g" % (c["stem"], d[1], D_LINEAR))
        arc, pred = d[1] - dc[1], f[1] / c["k_arc"]
        split = c["k_arc"] / (c["k_arc"] + kb_per_e * c["e_block"])
        print("%s (E_arc/E_block = %g), first step d = %.4f: F = %.4e, arc deflection %.4e "
              "(Castigliano F/k_arc %.4e, ratio %.3f); block's share of the energy %.4f "
              "(series estimate %.4f)" % (c["stem"], ratio, d[1], f[1], arc, pred, arc / pred,
                                          c["share"][0], split))
        if arc >= 0.01 * d[1] and not abs(arc / pred - 1) <= TOL_ARC:
            failures.append("%s: arc deflection %.4e, Castigliano %.4e (> %.0f %% apart)"
                            % (c["stem"], arc, pred, 100 * TOL_ARC))
        if c is not stiff and not abs(c["share"][0] - split) <= TOL_SPLIT:
            failures.append("%s: block energy share %.4f, series estimate %.4f"
                            % (c["stem"], c["share"][0], split))
        w = c["w_arc"][-1] + c["w_block"][-1]
        balance = w / c["work"][-1] - 1
        print("   path to d = %.4f (%d steps): block's share of the energy from %.4f to %.4f "
              "(min %.4f, max %.4f); W_arc + W_block = %.5e, work of the end force %.5e "
              "(%+.2f %%); 1 vs 2 ranks %.1e; Newton order of the last contraction: %d steps, "
              "min %.2f, median %.2f"
              % (d[-1], len(d) - 1, c["share"][0], c["share"][-1], c["share"].min(),
                 c["share"].max(), w, c["work"][-1], 100 * balance, c["diff"], len(c["newton"]),
                 min(c["newton"] or [0]), np.median(c["newton"] or [0])))
        if not abs(balance) <= TOL_BALANCE:
            failures.append("%s: energy balance off by %.2f %%" % (c["stem"], 100 * balance))
        if len(c["newton"]) < 3:
            failures.append("%s: fewer than 3 steps in the quadratic range" % c["stem"])
        if ratio <= 10 and not (1 - c["share"]).min() >= 0.9:
            failures.append("%s: the arc holds %.3f of the energy, expected >= 0.9"
                            % (c["stem"], (1 - c["share"]).min()))
        if ratio >= 1e4 and not c["share"].min() >= 0.9:
            failures.append("%s: the block holds %.3f of the energy, expected >= 0.9"
                            % (c["stem"], c["share"].min()))
    ordered = sorted(cases.values(), key=lambda c: c["e_arc"] / c["e_block"])
    shares = [c["share"][-1] for c in ordered]
    if not all(s1 < s2 for s1, s2 in zip(shares, shares[1:])):
        failures.append("block's energy share not increasing with E_arc / E_block: %s" % shares)
    try:
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6.5, 4.5))
        for i, c in enumerate(ordered):
            ratio = c["e_arc"] / c["e_block"]
            ax.plot(c["d"][1:], c["share"], "o-", ms=3, color="C%d" % i,
                    label="E_arc/E_block = %g" % ratio)
            split = c["k_arc"] / (c["k_arc"] + kb_per_e * c["e_block"])
            ax.plot([0, c["d"][-1]], [split, split], ":", color="C%d" % i, lw=1)
        ax.set_xlabel("imposed displacement d of the arc ends")
        ax.set_ylabel("W_block / (W_arc + W_block)")
        ax.set_ylim(-0.02, 1.02)
        ax.set_title("Arc pressing a block: the block's share of the strain energy\n"
                     "(dotted: series compliances, Castigliano arc, small d)", fontsize=10)
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
        fig.tight_layout()
        fig.savefig("arc_block_split.png", dpi=100)
        print("wrote arc_block_split.png")
    except ImportError:
        print("matplotlib not available: no figure")
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        return 1
    print("arc_block: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
