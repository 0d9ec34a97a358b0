"""Coulomb friction across a plane of symmetry: a half model (u_z = 0 on z = 0 on both bodies)
against its full model (twice as thick, no constraint on its mid-plane). A half-model node at z
maps to the full model's node at z + the half thickness. Defaults: the drag
(drag_sym_half_mu03.yaml, drag_sym_full_mu03.yaml, half thickness 0.25); the options set up
another pair (inputs/shallow_ironing: the one-layer ironing slab, slab_ci_frictional.yaml).

References and checks:
- Both runs take their steps (--steps equal steps to --t-end) with no cut-back. (Before the
  rule for held tangents, docs/input.md "Friction on a plane of symmetry", the drag's half
  model's first step did not converge: the z-stick rows of the plane's slave nodes pinned free
  master dofs through their small share of M, with updates of 1e12. Under the rule's former
  limits, 0.01 rad and 0.01 of D, the ironing slab's half model stopped at t = 0.72.)
- The full model is symmetric: the die's R_z and the z-multipliers of its mid-plane slave
  nodes vanish (limit 1e-10 of R_y and of max |lambda|; round-off).
- The half model is the full model's half: the die's R_x and R_y are half the full model's,
  and the displacements equal the full model's at the mapped nodes. Not to round-off: the
  half model's nodal normals on z = 0 average the faces of one side only, and tilt off the
  plane as the bodies bulge, where the full model's are exactly in it. Drag: the tilt is up to
  ~1e-3 rad; limits 1e-5 of R_y and of max |u| (measured 8.2e-7 and 2.7e-6, the tilt times the
  plane nodes' share of the contact). Limits of the sliding phase (t >= --sliding-from) apart:
  --sliding-force-limit.
- The half model's plane: lambda_z = 0 at every slave node there (the rule writes e_z.lambda =
  0, as the full model's symmetry gives; limit 1e-12 of max |lambda|).
- Coulomb while sliding (t >= --sliding-from): the half model's R_x / R_y is mu within
  --ratio-limit (3 %, as in check_mu03.py; 0: not checked).
- 1 and 2 ranks (the half model): displacements within --ranks-limit (default 1e-8).
"""
import argparse
import csv
import sys

import numpy as np

from drag_summary import summary
from grout_results import Results, relative_difference

ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
ap.add_argument("--half", default="drag_sym_half_mu03", help="the half model's output stem")
ap.add_argument("--full", default="drag_sym_full_mu03", help="the full model's output stem")
ap.add_argument("--offset", type=float, default=0.25, help="z of the full model's mid-plane")
ap.add_argument("--steps", type=int, default=8)
ap.add_argument("--t-end", type=float, default=2.0)
ap.add_argument("--mu", type=float, default=0.3)
ap.add_argument("--sliding-from", type=float, default=1.25)
ap.add_argument("--ratio-limit", type=float, default=0.03)
ap.add_argument("--force-limit", type=float, default=1e-5)
ap.add_argument("--sliding-force-limit", type=float, default=1e-5)
ap.add_argument("--u-limit", type=float, default=1e-5)
ap.add_argument("--lz-limit", type=float, default=1e-12)
ap.add_argument("--ranks-limit", type=float, default=1e-8,
                help="1 against 2 ranks, the half model's displacements (relative)")
a = ap.parse_args()
MU, STEPS, T_HALF = a.mu, a.steps, a.offset
failures = []


def check(ok, message):
    if not ok:
        failures.append(message)


def summary_z(stem):
    rows = list(csv.DictReader(open("np1/%s.csv" % stem)))
    return np.array([float(r["reaction_die_top_nodes_z"]) for r in rows])


half, full = summary(a.half, 1), summary(a.full, 1)
for stem, (t, _, _, _) in (("half", half), ("full", full)):
    print("%s model: %d steps to t = %g" % (stem, len(t), t[-1]))
    check(len(t) == STEPS and abs(t[-1] - a.t_end) < 1e-12,
          "%s model: %d steps to t = %g (expected %d equal steps to %g: no cut-back)"
          % (stem, len(t), t[-1], STEPS, a.t_end))

if not failures:
    th, rxh, ryh, _ = half
    tf, rxf, ryf, _ = full
    rz = summary_z(a.full)
    sliding = th >= a.sliding_from - 1e-12
    d_rz = np.abs(rz / ryf).max()
    d_force = np.maximum(np.abs(rxf - 2 * rxh), np.abs(ryf - 2 * ryh)) / np.abs(ryf).max()
    print("full model: die R_z / R_y max %.2e (limit 1e-10)" % d_rz)
    check(d_rz <= 1e-10, "full model: die R_z / R_y = %.2e (limit 1e-10)" % d_rz)
    for phase, steps, limit in (("t < %g" % a.sliding_from, ~sliding, a.force_limit),
                                ("t >= %g" % a.sliding_from, sliding, a.sliding_force_limit)):
        worst = d_force[steps].max(initial=0.0)
        print("full R_x, R_y - 2 x half, %s: %.2e of max R_y (limit %g)" % (phase, worst, limit))
        check(worst <= limit, "full R_x, R_y differ from twice the half's by %.2e of R_y, %s"
              % (worst, phase))
    if a.ratio_limit > 0:
        ratio = rxh[sliding] / ryh[sliding]
        print("half model: R_x/R_y while sliding %.4f ... %.4f (mu = %g)"
              % (ratio.min(), ratio.max(), MU))
        check(np.abs(ratio / MU - 1).max() <= a.ratio_limit,
              "half model: R_x/R_y while sliding off mu by %.2f %% (limit %g %%)"
              % (100 * np.abs(ratio / MU - 1).max(), 100 * a.ratio_limit))

    rh, rf = Results("np1/%s.e" % a.half), Results("np1/%s.e" % a.full)
    xh = rh.coordinates().T
    mapped = rh.node_map(rf, lambda x: x + [0.0, 0.0, T_HALF])
    plane = np.abs(xh[:, 2]) < 1e-12
    d_u = d_lz = d_lz_full = 0.0
    for step in range(STEPS):
        uh = np.stack([rh.nodal("displ_" + c, step) for c in "xyz"], 1)
        uf = np.stack([rf.nodal("displ_" + c, step) for c in "xyz"], 1)[mapped]
        lh = np.stack([rh.nodal("lm_" + c, step) for c in "xyz"], 1)
        lf = np.stack([rf.nodal("lm_" + c, step) for c in "xyz"], 1)[mapped]
        d_u = max(d_u, np.abs(uh - uf).max() / np.abs(uf).max())
        d_lz = max(d_lz, np.abs(lh[plane, 2]).max() / np.abs(lh).max())
        d_lz_full = max(d_lz_full, np.abs(lf[plane, 2]).max() / np.abs(lf).max())
    print("full model: mid-plane |lambda_z| / max |lambda| %.2e (limit 1e-10)" % d_lz_full)
    print("half model: plane |lambda_z| / max |lambda| %.2e (limit %g)" % (d_lz, a.lz_limit))
    print("displacements, half - full at the mapped nodes: %.2e of max |u| (limit %g)"
          % (d_u, a.u_limit))
    check(d_lz_full <= 1e-10, "full model: mid-plane lambda_z %.2e of max |lambda|" % d_lz_full)
    check(d_lz <= a.lz_limit, "half model: plane lambda_z %.2e of max |lambda| (limit %g)"
          % (d_lz, a.lz_limit))
    check(d_u <= a.u_limit, "half and full displacements differ by %.2e of max |u|" % d_u)

    r1, r2 = rh, Results("np2/%s.e" % a.half)
    for name in ("displ_x", "displ_y", "displ_z"):
        d = relative_difference(r1.nodal(name), r2.nodal(name))
        print("half model: %s, 1 vs 2 ranks %.2e (limit %g)" % (name, d, a.ranks_limit))
        check(d <= a.ranks_limit, "half model: %s differs between 1 and 2 ranks by %.3e (limit %g)"
              % (name, d, a.ranks_limit))

for f in failures:
    print("FAIL:", f)
print("check_symmetry: %s"
      % ("all checks passed" if not failures else "%d failure(s)" % len(failures)))
sys.exit(1 if failures else 0)
