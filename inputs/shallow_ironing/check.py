"""Shallow ironing (docs/verification.md #19), plane strain or 3D: the die's reaction against the
published curves of the Kratos example (Poulios & Renard 2015), digitised into reference_*.csv
by digitize_reference.py.

Usage: check.py CASE MU [--plateau T0 T1] [--fy-tolerance TOL] [--fx-tolerance TOL]
                [--ratio-range LO HI] [--plane-strain | --plane-stress] [--ranks 1 2]
                [--force-set NAME]
                [--label TEXT]

The defaults are #19's pass, which is for the reference's own model, 3D on Kratos' mesh
(kratos3d_*.yaml, run_kratos3d.sh): the F_y plateau within 7 % of the published one, and
F_x/F_y in [1.00, 1.06] mu while sliding. --plane-strain: the 2D plane-strain model (the CI
runs ci_*.yaml), which #19 reports beside 3D and does not hold to the 3D figure (the
published curve is not plane strain: +18 % on F_y measured, docs/verification.md): its F_y
and F_x/F_y are printed against the reference, not checked. What such a run checks is what
holds for any model: Coulomb's law at the nodes, frictionless F_x = 0, 1 = 2 ranks; its
forces are checked against GetFEM's plane-strain solution by getfem_compare.py (ctest
shallow_ironing/getfem). --plane-stress: the same for the 2D plane-stress model
(ci_plane_stress_*.yaml, full_plane_stress_*.yaml: the ironing hypothesis, #19).

Reads np<r>/CASE.csv: F_x = reaction_NAME_x (the drag force, > 0 along the sliding
direction), F_y = -reaction_NAME_y (the pressing force, > 0): the signs of the reference
figure. NAME is the node set of the die's top (default die_top_nodes; on Kratos' 3D mesh
converted by tools/mdpa_to_exodus.py, displacement_displacement_auto2). Checks, on each rank
count:
- MU = 0: |F_x| <= FX_TOL F_y (default 2e-2) at every step of the sliding plateau
  (T0 <= t <= T1);
- MU > 0: at every step of the plateau in which every active slave node slips (at least half
  of the plateau's steps; the nodes from CASE_contact.csv, or from CASE.e in 3D), Coulomb's
  law at each slave node, |lambda_t| = sqrt(|lambda|^2 - lambda_n^2) = MU lambda_n (to 1e-6
  lambda_n; lambda with its z component in 3D; to 1e-4 at the 3D slave nodes on z = 0, the
  plane held in z on both bodies, where Grout writes lambda_z = 0 for the tangent along z and
  Coulomb's law for the other: the plane's nodal normal tilts off it by some 1e-3 rad, and
  |lambda_t| then exceeds MU lambda_n by the square of that tilt, docs/input.md "Friction on a
  plane of symmetry"), and F_x / F_y at each of those steps within [LO, HI] MU (default
  [1.00, 1.06], #19). F_x / F_y is not MU exactly: a curved die gives (MU + s)/(1 - MU s),
  s the pressure-weighted slope of the die's normals: the block presses on the front of the
  die's arc (ploughing; measured +8 % in plane strain, +4 % on the 3D slab and on Kratos'
  mesh; the 3D reference has +1 %), see docs/verification.md;
- the mean F_y over the plateau against the reference's (3.37e8 N for both cases, read off
  the figures) within FY_TOL (default 0.07, #19);
- 1 and 2 ranks: the reactions agree to 1e-10 relative.
Writes CASE.png: F_y, F_x against t with the reference curves.
"""
import argparse
import csv
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))

ap = argparse.ArgumentParser()
ap.add_argument("case")
ap.add_argument("mu", type=float)
ap.add_argument("--plateau", type=float, nargs=2, default=[1.3, 1.7])
ap.add_argument("--fy-tolerance", type=float, default=0.07)
ap.add_argument("--fx-tolerance", type=float, default=2e-2)
ap.add_argument("--ratio-range", type=float, nargs=2, default=[1.00, 1.06])
ap.add_argument("--plane-strain", action="store_true",
                help="2D plane strain: F_y and F_x/F_y printed against the 3D reference, "
                     "not checked (#19)")
ap.add_argument("--plane-stress", action="store_true",
                help="2D plane stress: printed, not checked, as --plane-strain")
ap.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
ap.add_argument("--force-set", default="die_top_nodes")
ap.add_argument("--label", default="plane strain", help="the model, in the plot's legend")
a = ap.parse_args()
MODEL_2D = "plane stress" if a.plane_stress else "plane strain"
if a.plane_stress and a.label == "plane strain":
    a.label = "plane stress"
a.plane_strain = a.plane_strain or a.plane_stress  # a 2D model: printed, not checked

reference = np.loadtxt(os.path.join(HERE, "reference_%s.csv" % (
    "frictionless" if a.mu == 0 else "frictional")), delimiter=",", skiprows=1)
t_ref, fy_ref, fx_ref = reference.T
# The reference presses for 0.2 <= t <= 1 (after closing a gap of 0.2), the runs for t <= 1:
# its times before 1 map to (t - 0.2) / 0.8.
t_ref = np.where(t_ref < 1.0, (t_ref - 0.2) / 0.8, t_ref)
in_ref = (t_ref >= a.plateau[0]) & (t_ref <= a.plateau[1])
fy_ref_plateau = fy_ref[in_ref].mean()


def slave_nodes(np_, steps):
    """(step, contact_status, contact_pressure, |lambda|^2, on the plane z = 0) of every slave
    node at every step: from np<r>/CASE_contact.csv (2D), else from the Exodus file np<r>/CASE.e
    (3D writes no contact CSV; its Exodus time k is the summary's k-th step)."""
    path = "np%d/%s_contact.csv" % (np_, a.case)
    if os.path.exists(path):
        for r in csv.DictReader(open(path)):
            yield (int(r["step"]), float(r["contact_status"]), float(r["contact_pressure"]),
                   sum(float(r[c]) ** 2 for c in ("lm_x", "lm_y", "lm_z") if c in r), False)
        return
    sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
    from grout_results import Results
    results = Results("np%d/%s.e" % (np_, a.case))
    components = [c for c in ("lm_x", "lm_y", "lm_z") if c in results.nodal_names]
    xyz = results.coordinates()
    on_plane = np.abs(xyz[2]) < 1e-12 if len(xyz) == 3 else np.zeros(len(xyz[0]), bool)
    for index, k in enumerate(steps):
        st = results.nodal("contact_status", index)
        lam_n = results.nodal("contact_pressure", index)
        lam2 = sum(results.nodal(c, index) ** 2 for c in components)
        for node in np.nonzero(st != 0.0)[0]:
            yield (int(k), float(st[node]), float(lam_n[node]), float(lam2[node]),
                   bool(on_plane[node]))


TARGET_FY = (MODEL_2D + ": reported beside 3D, not checked" if a.plane_strain
             else "#19: within %g %%" % (100 * a.fy_tolerance))
TARGET_RATIO = (MODEL_2D + ": reported, not checked" if a.plane_strain
                else "#19: in [%g, %g]" % tuple(a.ratio_range))
failures = []
results = {}
for np_ in a.ranks:
    rows = list(csv.DictReader(open("np%d/%s.csv" % (np_, a.case))))
    t = np.array([float(r["time"]) for r in rows])
    fx = np.array([float(r["reaction_%s_x" % a.force_set]) for r in rows])
    fy = -np.array([float(r["reaction_%s_y" % a.force_set]) for r in rows])
    steps = np.array([int(r["step"]) for r in rows])
    results[np_] = (t, fx, fy)
    plateau = (t >= a.plateau[0] - 1e-12) & (t <= a.plateau[1] + 1e-12)
    if plateau.sum() < 3:
        failures.append("np%d: only %d steps in the plateau" % (np_, plateau.sum()))
        continue
    fy_mean = fy[plateau].mean()
    error = fy_mean / fy_ref_plateau - 1
    print("np%d: %d steps, %d in t = [%g, %g]: mean F_y = %.4g N (reference %.4g N, %+.2f %%; %s),"
          " F_y from %.4g to %.4g" % (np_, len(t), plateau.sum(), a.plateau[0], a.plateau[1],
                                       fy_mean, fy_ref_plateau, 100 * error, TARGET_FY,
                                       fy[plateau].min(), fy[plateau].max()))
    if not a.plane_strain and not abs(error) <= a.fy_tolerance:
        failures.append("np%d: F_y plateau %.4g differs from the reference %.4g by %+.1f %%"
                        % (np_, fy_mean, fy_ref_plateau, 100 * error))
    ratio = fx / fy
    if a.mu == 0:
        print("np%d: max |F_x|/F_y on the plateau = %.2e" % (np_, np.abs(ratio[plateau]).max()))
        if not np.abs(ratio[plateau]).max() <= a.fx_tolerance:
            failures.append("np%d: frictionless |F_x|/F_y %.2e > %g"
                            % (np_, np.abs(ratio[plateau]).max(), a.fx_tolerance))
    else:
        status, coulomb, coulomb_plane = {}, {}, {}
        for k, st, lam_n, lam2, plane_node in slave_nodes(np_, steps):
            if st == 0.0:
                continue
            status.setdefault(k, []).append(st)
            lam_t = np.sqrt(max(lam2 - lam_n ** 2, 0.0))
            if st == 2.0:
                worst_of = coulomb_plane if plane_node else coulomb
                worst_of[k] = max(worst_of.get(k, 0.0), abs(lam_t - a.mu * lam_n) / lam_n)
        full_slip = np.array([s in status and min(status[s]) == 2.0 for s in steps])
        sel = plateau & full_slip
        worst = max(coulomb.get(s, 0.0) for s in steps[sel]) if sel.any() else np.inf
        worst_plane = max(coulomb_plane.get(s, 0.0) for s in steps[sel]) if sel.any() else 0.0
        mean = (ratio[sel] / a.mu).mean() if sel.any() else np.nan
        print("np%d: %d of %d plateau steps in full slip; largest | |lambda_t| - mu lambda_n |"
              " / lambda_n at a node %.1e%s; F_x/F_y / mu from %.4f to %.4f, mean %.4f (%s)"
              % (np_, sel.sum(), plateau.sum(), worst,
                 " (%.1e on the plane z = 0)" % worst_plane if coulomb_plane else "",
                 (ratio[sel] / a.mu).min() if sel.any() else 0,
                 (ratio[sel] / a.mu).max() if sel.any() else 0, mean, TARGET_RATIO))
        if sel.sum() < max(3, plateau.sum() // 2):
            failures.append("np%d: only %d plateau steps in full slip" % (np_, sel.sum()))
        elif not (worst <= 1e-6 and worst_plane <= 1e-4):
            failures.append("np%d: slipping nodes violate |lambda_t| = mu lambda_n (%.1e, on "
                            "the plane z = 0 %.1e)" % (np_, worst, worst_plane))
        elif not a.plane_strain and not (a.ratio_range[0] <= (ratio[sel] / a.mu).min()
                                         and (ratio[sel] / a.mu).max() <= a.ratio_range[1]):
            failures.append("np%d: F_x/F_y from %.4f to %.4f mu, not within [%g, %g] mu"
                            % (np_, (ratio[sel] / a.mu).min(), (ratio[sel] / a.mu).max(),
                               *a.ratio_range))

if 1 in results and 2 in results:
    t1, fx1, fy1 = results[1]
    t2, fx2, fy2 = results[2]
    if len(t1) != len(t2) or np.abs(t1 - t2).max() > 1e-12:
        failures.append("1 and 2 ranks took different steps")
    else:
        scale = np.abs(fy1).max()
        diff = max(np.abs(fx1 - fx2).max(), np.abs(fy1 - fy2).max()) / scale
        print("1 vs 2 ranks: reactions differ by %.2e (relative to max F_y)" % diff)
        if not diff < 1e-10:
            failures.append("1 and 2 ranks differ by %.2e" % diff)

try:
    import matplotlib.pyplot as plt
    t, fx, fy = results[a.ranks[0]]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.plot(t_ref, fy_ref, "-", color="tab:blue", lw=3, alpha=0.4, label="F_y reference")
    ax.plot(t_ref, fx_ref, "-", color="tab:red", lw=3, alpha=0.4, label="F_x reference")
    ax.plot(t, fy, ".", color="tab:blue", ms=3, label="F_y Grout (%s)" % a.label)
    ax.plot(t, fx, ".", color="tab:red", ms=3, label="F_x Grout")
    ax.axvspan(a.plateau[0], a.plateau[1], color="gray", alpha=0.1)
    ax.set_xlabel("t (press 0.8 for t <= 1, slide 10 for 1 <= t <= 2)")
    ax.set_ylabel("force on the block (N per unit thickness)")
    ax.set_title("Shallow ironing, mu = %g" % a.mu)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig("%s.png" % a.case, dpi=100)
except ImportError:
    pass

if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("shallow_ironing %s: all checks passed" % a.case)
