"""Finite-strain two-body drag on gmsh meshes (issue 12, "done when"): a Neo-Hookean die
pressed into a longer Neo-Hookean block (t <= 1), then dragged along it by 1.0 (t <= 3),
frictionless, contact on the current geometry, three starts (drag_mesh.py):

- drag_touch: flat die bottom on the block top (zero gap);
- drag_gap: the same mesh with the die moved up by G = 0.02 (0.16 contact elements), pushed
  down by G more. Reference: drag_touch. The two problems are the same up to the translation
  of the die (an elastic, frictionless problem has one solution whatever the path), so at
  every common time t >= 1 the displacements (die: minus the translation) and the reactions
  agree to 1e-6;
- drag_point: the die's bottom is an arc of radius R = 4 touching the block at one node.
  Reference: Hertz for a cylinder on a half-plane (Johnson 1985, eq. 4.43; both bodies
  E = 1000, nu = 0.3): b = sqrt(4 P R / (pi E*)) for the computed load P at the end of
  pressing; b within 10 % (b spans 4-5 contact elements on this mesh).

Every variant (1 and 2 ranks, agreeing to 1e-8): converges every step, keeps the die in
contact while sliding, travels across >= 4 block elements, and |R_x| <= 5e-3 R_y in every
sliding step (frictionless: no shear; only the asymmetry of the finite block tilts the
contact). Writes drag_gmsh.png (R_x, R_y against t; drag_point's pressure against Hertz).
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402
from grout_results import Results, relative_difference  # noqa: E402
from drag_summary import summary  # noqa: E402

E, NU, R, GAP = 1000.0, 0.3, 4.0, 0.02
VARIANTS = ("drag_touch", "drag_gap", "drag_point")


def common_checks(stem, failures):
    for np_ in (1, 2):
        t, rx, ry, active = summary(stem, np_)
        if abs(t[-1] - 3.0) > 1e-12:
            failures.append("%s np%d: stopped at t = %g" % (stem, np_, t[-1]))
        sliding = t > 1.0 + 1e-9
        ratio = np.abs(rx[sliding]) / ry[sliding]
        print("%-10s np%d: %d steps (%d sliding), max |R_x|/R_y while sliding %.2e, R_y at t=1 "
              "%.4f, active slave nodes %d..%d" % (stem, np_, len(t), sliding.sum(), ratio.max(),
                                                   ry[np.argmin(abs(t - 1))], active[sliding].min(),
                                                   active[sliding].max()))
        if not (sliding.sum() >= 5 and ratio.max() < 5e-3):
            failures.append("%s np%d: frictionless R_x/R_y %.2e not below 5e-3" % (stem, np_, ratio.max()))
        if not active[sliding].min() > 0:
            failures.append("%s np%d: the die left contact while sliding" % (stem, np_))
    r1, r2 = Results("np1/%s.e" % stem), Results("np2/%s.e" % stem)
    diff = max(relative_difference(r1.nodal("displ_" + c), r2.nodal("displ_" + c)) for c in "xy")
    print("%-10s 1 vs 2 ranks: %.2e" % (stem, diff))
    if not diff < 1e-8:
        failures.append("%s: 1 and 2 ranks differ by %.2e" % (stem, diff))
    ux = r1.nodal("displ_x")
    die = cc.side_set_nodes(r1, "die_bottom")
    if not ux[die].min() > 0.99:
        failures.append("%s: die bottom travelled %.3f < 4 block elements" % (stem, ux[die].min()))


def gap_against_touch(failures):
    a, b = Results("np1/drag_touch.e"), Results("np1/drag_gap.e")
    ta, tb = np.round(a.times(), 9), np.round(b.times(), 9)
    common = [t for t in ta if t >= 1.0 - 1e-9 and t in set(tb)]
    die = cc.block_nodes(b, "die")
    worst = 0.0
    for t in common:
        ia, ib = int(np.nonzero(ta == t)[0][0]), int(np.nonzero(tb == t)[0][0])
        ua = np.array([a.nodal("displ_x", ia), a.nodal("displ_y", ia)])
        ub = np.array([b.nodal("displ_x", ib), b.nodal("displ_y", ib)])
        ub[1, die] += GAP  # the gap mesh's die starts GAP higher and moves GAP further down
        worst = max(worst, np.abs(ua - ub).max() / np.abs(ua).max())
    _, _, rya, _ = summary("drag_touch", 1)
    tsa, _, _, _ = summary("drag_touch", 1)
    tsb, _, ryb, _ = summary("drag_gap", 1)
    rmap = dict(zip(np.round(tsb, 9), ryb))
    rdiff = max(abs(rya[k] - rmap[round(t, 9)]) / abs(rya[k]) for k, t in enumerate(tsa)
                if round(t, 9) in rmap and t >= 1.0 - 1e-9)
    print("gap start against the touching start: %d common times t >= 1, max displacement "
          "difference %.2e, R_y %.2e (relative)" % (len(common), worst, rdiff))
    if not (len(common) >= 3 and worst < 1e-6 and rdiff < 1e-6):
        failures.append("drag_gap differs from drag_touch by %.2e (displacement), %.2e (R_y) "
                        "on %d common times" % (worst, rdiff, len(common)))


def hertz_point(failures):
    r = Results("np1/drag_point.e")
    t = np.round(r.times(), 9)
    k = int(np.nonzero(t == 1.0)[0][0])
    s = cc.side_set_nodes(r, "die_bottom")
    x = r.coordinates()[0, s] + r.nodal("displ_x", k)[s]
    p = r.nodal("contact_pressure", k)[s]
    ts, _, ry, _ = summary("drag_point", 1)
    P = ry[int(np.argmin(abs(ts - 1.0)))]
    xc = np.average(x, weights=np.clip(p, 0, None))
    b_fe = cc.half_width(x - xc, p)
    b_h, p0 = cc.hertz_line_contact(P, R, math.inf, E, NU, E, NU)
    err = abs(b_fe - b_h) / b_h
    print("drag_point at t = 1: P = %.4f, contact half-width %.4f, Hertz %.4f (error %.1f %%); "
          "peak pressure %.2f, Hertz p0 %.2f" % (P, b_fe, b_h, 100 * err, p.max(), p0))
    if not err < 0.10:
        failures.append("drag_point: half-width %.4f vs Hertz %.4f (%.1f %%)" % (b_fe, b_h, 100 * err))
    near = np.abs(x - xc) < 1.5 * b_h
    return x[near] - xc, p[near], b_h, p0


def plot(profile):
    try:
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.5))
    for k, stem in enumerate(VARIANTS):
        t, rx, ry, _ = summary(stem, 1)
        ax.plot(t, ry, "o-", color="C%d" % k, ms=3, label="R_y, " + stem)
        ax.plot(t, rx, "s--", color="C%d" % k, ms=3, label="R_x, " + stem)
    ax.axvline(1.0, color="gray", lw=0.5)
    ax.set_xlabel("t (press to t = 1, then drag 0.5 per unit t)")
    ax.set_ylabel("reaction on the die top")
    ax.set_title("frictionless: R_x = 0 while sliding; gap start = touching start", fontsize=9)
    ax.legend(fontsize=7)
    x, p, b_h, p0 = profile
    xs = np.linspace(-1.2 * b_h, 1.2 * b_h, 200)
    bx.plot(xs, cc.hertz_pressure(xs, b_h, p0), "b-", label="Hertz, computed load")
    bx.plot(x, p, "ro", ms=4, label="drag_point, t = 1")
    bx.set_xlabel("x - contact centre")
    bx.set_ylabel("contact pressure")
    bx.set_title("one-node start (arc die, R = 4) against Hertz", fontsize=9)
    bx.legend(fontsize=8)
    fig.suptitle("Neo-Hookean die pressed into and dragged over a block (gmsh meshes)")
    fig.tight_layout()
    fig.savefig("drag_gmsh.png", dpi=100)


def main():
    failures = []
    for stem in VARIANTS:
        common_checks(stem, failures)
    gap_against_touch(failures)
    profile = hertz_point(failures)
    plot(profile)
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        return 1
    print("finite_drag_gmsh: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
