"""Finite-strain sliding: a Neo-Hookean die pressed into a longer Neo-Hookean block, then
dragged by 1.0 (four block elements) on the current geometry.

Usage: check.py [CASE [MU]]   (default: drag_mu0 0; the frictional run: drag_mu03 0.3)

Checks (on 1 and 2 ranks; the two agree to 1e-8):
- the die stays in contact: every slave node active in every step;
- the slave nodes travel across four master elements (x moves by >= 4 h = 1.0; with
  friction by >= 0.9: the die's bottom lags its top by the die's shear);
- frictionless (MU = 0): |R_x| <= 5e-3 R_y on the die's top in every sliding step (only the
  asymmetry of the finite block tilts the contact, Coulomb with mu = 0 transmits no shear);
- Coulomb (MU > 0), in every sliding step in which every slave node slips (contact_status 2):
  |lambda_t| = MU lambda_n at every slave node (to 1e-8; normals and weights D_jj recomputed
  from the deformed die bottom), so the friction resultant in the interface frame is MU
  (to 1e-8); R_x / R_y of the die's top equals the contact resultant's x/y (to 1e-6: the die's
  equilibrium) and MU within 3 %: the dragged block's surface tilts by about 0.01 rad under
  the die, and R_x / R_y = (MU - tan a) / (1 + MU tan a) for a mean tilt a;
- the indentation force grows linearly to first order while pressing (R_y(t) / t within
  15 % of its first value: the Neo-Hookean stiffening at 2.5 % strain is small);
- Newton converges quadratically once the active set (open/stick/slip) has settled:
  |F_k+1| <= 10 |F_k|^2 / |F_0| for every iterate between 1e-1 |F_0| and the round-off
  level whose active set did not change.
Writes CASE.png (R_x, R_y against t).
"""
import csv
import math
import sys

import numpy as np

from grout_results import Results, relative_difference

case = sys.argv[1] if len(sys.argv) > 1 else "drag_mu0"
mu = float(sys.argv[2]) if len(sys.argv) > 2 else 0.0
C_QUADRATIC = 10.0


def coulomb_resultants(results, step_indices):
    """At the given output steps (0-based): the slave (die bottom) nodes' Coulomb law from the
    multipliers and the nodal normals of the deformed die bottom, n_j = normalise(sum of the
    adjacent faces' unit normals) as in Grout, weights D_jj = half the adjacent face lengths
    (dual mortar, fully projected LINE2 faces). Returns the largest | |lambda_t| / lambda_n -
    mu | over the nodes, the largest |sum D lambda_t / sum D lambda_n / mu - 1| (the friction
    resultant in the interface frame), |sum D lambda_x / sum D lambda_y| per step (the contact
    resultant's direction, which the die's top reaction must match) and the mean x-component
    of the normals (the tilt of the interface)."""
    X, Y = results.coordinates()[:2]
    node_err, frame_err, xy, tilt = 0.0, 0.0, [], []
    for k in step_indices:
        status = results.nodal("contact_status", step=k)
        nodes = np.nonzero(status > 0)[0]
        nodes = nodes[np.argsort(X[nodes])]
        x = X[nodes] + results.nodal("displ_x", step=k)[nodes]
        y = Y[nodes] + results.nodal("displ_y", step=k)[nodes]
        lam = np.column_stack([results.nodal("lm_x", step=k)[nodes],
                               results.nodal("lm_y", step=k)[nodes]])
        w, n = np.zeros(len(nodes)), np.zeros((len(nodes), 2))
        for i in range(len(nodes) - 1):
            d = np.array([x[i + 1] - x[i], y[i + 1] - y[i]])
            length = np.hypot(*d)
            face_normal = np.array([d[1], -d[0]]) / length  # outward: down, out of the die
            for j in (i, i + 1):
                w[j] += 0.5 * length
                n[j] += face_normal
        n /= np.linalg.norm(n, axis=1)[:, None]
        lam_n = (lam * n).sum(axis=1)
        lam_t = lam[:, 0] * (-n[:, 1]) + lam[:, 1] * n[:, 0]
        node_err = max(node_err, np.abs(np.abs(lam_t) / lam_n - mu).max())
        frame_err = max(frame_err, abs(abs((w * lam_t).sum()) / (w * lam_n).sum() / mu - 1))
        xy.append(abs((w * lam[:, 0]).sum() / (w * lam[:, 1]).sum()))
        tilt.append(n[:, 0].mean())
    return {"node": node_err, "frame": frame_err, "xy": np.array(xy), "tilt": np.mean(tilt)}

failures = []
rows = {np_: list(csv.DictReader(open("np%d/%s.csv" % (np_, case)))) for np_ in (1, 2)}
for np_ in (1, 2):
    t = np.array([float(r["time"]) for r in rows[np_]])
    rx = np.array([float(r["reaction_die_top_nodes_x"]) for r in rows[np_]])
    ry = -np.array([float(r["reaction_die_top_nodes_y"]) for r in rows[np_]])
    active = np.array([int(r["active_nodes"]) for r in rows[np_]])
    n_slave = len({r["node"] for r in csv.DictReader(open("np%d/%s_contact.csv" % (np_, case)))})
    if not (active == n_slave).all():
        failures.append("np%d: slave nodes left contact: %s" % (np_, active))
    sliding = t > 1.0 + 1e-9
    ratio = np.abs(rx[sliding]) / ry[sliding]
    if mu == 0.0:
        print("np%d: %d sliding steps, max |R_x|/R_y = %.2e, R_y from %.3f to %.3f"
              % (np_, sliding.sum(), ratio.max(), ry[sliding].max(), ry[sliding].min()))
        if not (sliding.sum() >= 5 and ratio.max() < 5e-3):
            failures.append("np%d: frictionless R_x/R_y %.2e not below 5e-3" % (np_, ratio.max()))
    else:
        # Steps in which every slave node slips (the die's contact csv, per step).
        status = {}
        for r in csv.DictReader(open("np%d/%s_contact.csv" % (np_, case))):
            status.setdefault(int(r["step"]), []).append(float(r["contact_status"]))
        steps = np.array([int(r["step"]) for r in rows[np_]])
        all_slip = np.array([min(status[s]) == 2.0 for s in steps])
        sel = all_slip & sliding
        coulomb = coulomb_resultants(Results("np%d/%s.e" % (np_, case)), np.nonzero(sel)[0])
        ratio_all = np.abs(rx) / ry
        print("np%d: %d steps with every slave node slipping: R_x/R_y / mu from %.4f to %.4f;"
              " largest | |lambda_t|/lambda_n - mu | at a node %.1e; Coulomb resultant in the"
              " interface frame / mu - 1 up to %.1e; R_x/R_y against the resultant's x/y %.1e;"
              " mean normal tilt %.4f rad" % (
                  np_, sel.sum(), (ratio_all[sel] / mu).min(), (ratio_all[sel] / mu).max(),
                  coulomb["node"], coulomb["frame"], np.abs(coulomb["xy"] - ratio_all[sel]).max(),
                  coulomb["tilt"]))
        if sel.sum() < 5:
            failures.append("np%d: only %d steps in full slip" % (np_, sel.sum()))
        elif not (coulomb["node"] <= 1e-8 * mu and coulomb["frame"] <= 1e-8):
            failures.append("np%d: slipping nodes violate |lambda_t| = mu lambda_n" % np_)
        elif not np.abs(coulomb["xy"] - ratio_all[sel]).max() <= 1e-6 * mu:
            failures.append("np%d: R_x/R_y is not the contact resultant's" % np_)
        elif not np.abs(ratio_all[sel] / mu - 1).max() <= 0.03:
            failures.append("np%d: R_x/R_y differs from mu by more than 3 %%" % np_)
    pressing = t <= 1.0 + 1e-9
    k = ry[pressing] / t[pressing]
    if not np.abs(k / k[0] - 1).max() < 0.15:
        failures.append("np%d: indentation force not ~linear: %s" % (np_, k))
    if np_ == 1:
        try:
            import matplotlib.pyplot as plt
            fig, ax = plt.subplots(figsize=(6, 4))
            ax.plot(t, ry, "o-", label="R_y (die top)")
            ax.plot(t, rx, "s-", label="R_x (die top)")
            if mu > 0:
                ax.plot(t[sliding], mu * ry[sliding], "k--", label="mu R_y (Coulomb, full slip)")
            ax.axvline(1.0, color="gray", lw=0.5)
            ax.set_xlabel("t (press to t = 1, then drag 0.5 per unit t)")
            ax.set_ylabel("reaction")
            ax.set_title("Neo-Hookean die dragged over a block, mu = %g" % mu)
            ax.legend()
            fig.tight_layout()
            fig.savefig("%s.png" % case, dpi=100)
        except ImportError:
            pass

# Quadratic convergence where the active set is settled.
checked = 0
for np_ in (1, 2):
    newton = list(csv.DictReader(open("np%d/%s_newton.csv" % (np_, case))))
    for s in sorted({(int(r["step"]), float(r["time"])) for r in newton}):
        its = [r for r in newton if (int(r["step"]), float(r["time"])) == s]
        f = [float(r["residual"]) for r in its]
        changes = [int(r["active_changes"]) for r in its]
        floor = 10 * f[-1]
        for k in range(1, len(f) - 1):
            if changes[k] == 0 and changes[k + 1] == 0 and 1e-1 * f[0] > f[k] > floor and \
                    f[k + 1] > floor:
                checked += 1
                if np_ == 1:
                    print("step %d: |F|/|F0| %.2e -> %.2e (order %.2f)" % (
                        s[0], f[k] / f[0], f[k + 1] / f[0],
                        math.log(f[k + 1] / f[0]) / math.log(f[k] / f[0])))
                if not f[k + 1] <= C_QUADRATIC * f[k] ** 2 / f[0]:
                    failures.append("np%d step %d: |F| %.3e -> %.3e is not quadratic"
                                    % (np_, s[0], f[k], f[k + 1]))
print("quadratic convergence checked on %d iterations" % checked)
if checked < 5:
    failures.append("fewer than 5 iterations in the quadratic range")

r1, r2 = Results("np1/%s.e" % case), Results("np2/%s.e" % case)
x0 = r1.coordinates()[0]
ux = r1.nodal("displ_x")
die_bottom = (np.abs(r1.coordinates()[1] - 5.0) < 1e-12) & (x0 >= 4.0 - 1e-12) & (x0 <= 6.0 + 1e-12)
# the die's bottom nodes and the block's top nodes share y = 5: the die's moved by ~1
moved = ux[die_bottom].max()
# With friction the die's bottom lags its top by the die's shear (mu p h / G ~ 0.04).
least = 0.99 if mu == 0.0 else 0.9
print("largest x-travel of an interface node: %.3f (block element size 0.25)" % moved)
if not moved > least:
    failures.append("interface nodes travelled %.3f < %.2f" % (moved, least))
diff = max(relative_difference(r1.nodal("displ_" + c), r2.nodal("displ_" + c)) for c in "xy")
print("1 vs 2 ranks: %.2e" % diff)
if not diff < 1e-8:
    failures.append("1 and 2 ranks differ by %.2e" % diff)
if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("finite_sliding %s: all checks passed" % case)
