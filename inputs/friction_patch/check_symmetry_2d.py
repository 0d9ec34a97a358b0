"""Coulomb friction across a plane of symmetry, 2D small strain: the half model
(symmetry_half_2d.yaml, u_x = 0 on x = 0 for both blocks) against the full model
(symmetry_full_2d.yaml, twice as wide, symmetric about x = 1). A half-model node (x, y) of a
block maps to the full model's node (1 + x, y) of the same block.

References and checks (every step):
- The full model is symmetric about x = 1: u_x(1 + s, y) = -u_x(1 - s, y), u_y equal
  (limit 1e-12 of max |u|).
- The half model is the full model's half, to round-off: the geometry of the contact is the
  reference one (normals, D and M do not move) and the meshes match at the interface, so the
  slave node on the symmetry line, held in x on both sides (its tangential multiplier 0, as
  the full model's symmetry gives), is the only difference in the equations. Displacements
  and multipliers within 1e-12 of their maxima; the supports' R_y of the half is half the
  full model's (1e-12 of it); the contact status of every slave node the same.
- The case exercises both branches: at the last step the half model has sticking and slipping
  slave nodes, and the one on the symmetry line sticks.
- 1 and 2 ranks (the half model): displacements within 1e-12.
"""
import csv
import sys

import numpy as np

from grout_results import Results, relative_difference

STEPS = 4
failures = []


def check(ok, message):
    if not ok:
        failures.append(message)


half, full = Results("np1/symmetry_half_2d.e"), Results("np1/symmetry_full_2d.e")
xh, bh = half.coordinates().T, half.node_blocks()
mapped = half.node_map(full, lambda p: p + [1.0, 0.0])
mirror = full.node_map(full, lambda p: [2.0 - p[0], p[1]])
check(len(half.times()) == STEPS and len(full.times()) == STEPS,
      "steps: half %d, full %d (expected %d)" % (len(half.times()), len(full.times()), STEPS))

d_sym = d_u = d_lm = 0.0
status_differs = 0
for step in range(min(len(half.times()), len(full.times()))):
    ux, uy = full.nodal("displ_x", step), full.nodal("displ_y", step)
    scale = max(np.abs(ux).max(), np.abs(uy).max())
    d_sym = max(d_sym, max(np.abs(ux + ux[mirror]).max(), np.abs(uy - uy[mirror]).max()) / scale)
    uh = np.stack([half.nodal("displ_" + c, step) for c in "xy"], 1)
    uf = np.stack([full.nodal("displ_" + c, step) for c in "xy"], 1)[mapped]
    lh = np.stack([half.nodal("lm_" + c, step) for c in "xy"], 1)
    lf = np.stack([full.nodal("lm_" + c, step) for c in "xy"], 1)[mapped]
    d_u = max(d_u, np.abs(uh - uf).max() / np.abs(uf).max())
    d_lm = max(d_lm, np.abs(lh - lf).max() / np.abs(lf).max())
    status_differs += int(np.any(half.nodal("contact_status", step)
                                 != full.nodal("contact_status", step)[mapped]))
print("full model symmetric about x = 1: %.2e of max |u| (limit 1e-12)" % d_sym)
print("half - full at mapped nodes: displacements %.2e, multipliers %.2e (limit 1e-12)"
      % (d_u, d_lm))
check(d_sym <= 1e-12, "full model not symmetric: %.2e" % d_sym)
check(d_u <= 1e-12, "half and full displacements differ by %.2e" % d_u)
check(d_lm <= 1e-12, "half and full multipliers differ by %.2e" % d_lm)
check(status_differs == 0, "contact status differs in %d steps" % status_differs)

rows = {m: list(csv.DictReader(open("np1/symmetry_%s_2d.csv" % m))) for m in ("half", "full")}
ry = {m: np.array([float(r["reaction_lower_bottom_nodes_y"]) for r in rows[m]]) for m in rows}
d_r = np.abs(ry["full"] - 2 * ry["half"]).max() / np.abs(ry["full"]).max()
print("supports' R_y: full - 2 x half %.2e of R_y (limit 1e-12)" % d_r)
check(d_r <= 1e-12, "R_y of the full model differs from twice the half's by %.2e" % d_r)

status = half.nodal("contact_status", -1)
slave = (bh == 2) & (np.abs(xh[:, 1] - 1.0) < 1e-12)  # upper block's bottom: the slave side
on_line = slave & (np.abs(xh[:, 0]) < 1e-12)
print("half model, last step: %d sticking, %d slipping slave nodes; on the line: %s"
      % ((status[slave] == 1).sum(), (status[slave] == 2).sum(), status[on_line]))
check((status[slave] == 1).any() and (status[slave] == 2).any(),
      "the last step has not both sticking and slipping slave nodes")
check(on_line.sum() == 1 and status[on_line][0] == 1, "the slave node on the line does not stick")

for name in ("displ_x", "displ_y"):
    d = relative_difference(half.nodal(name), Results("np2/symmetry_half_2d.e").nodal(name))
    check(d <= 1e-12, "half model: %s differs between 1 and 2 ranks by %.3e" % (name, d))

for f in failures:
    print("FAIL:", f)
print("check_symmetry_2d: %s"
      % ("all checks passed" if not failures else "%d failure(s)" % len(failures)))
sys.exit(1 if failures else 0)
