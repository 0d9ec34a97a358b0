"""Hertz contact of two spheres (hemispheres.py, quarter model, TET4), displacement-controlled:
the run converges, and the contact radius a and peak pressure p0 agree with Hertz for the
computed total force F (4 x the quarter's reaction) within 15 %; 1 and 2 ranks agree to 1e-10.

Reference: Johnson, Contact Mechanics (Cambridge 1985), §4.2 (eqs. 4.22-4.23), two spheres of
radius R1 = R2 = 1 (1/R* = 1/R1 + 1/R2, R* = 0.5), E = 200, nu = 0.3
(1/E* = 2 (1 - nu^2)/E, E* = 109.89), pressed by a total force F:
    a = (3 F R*/(4 E*))^(1/3),    p0 = 3 F/(2 pi a^2),    p(r) = p0 sqrt(1 - r^2/a^2).
F is not compared with Hertz' F(delta): the prescribed 0.05 is the approach of the flat faces,
which adds the hemispheres' bulk compression to Hertz' local approach delta.
Computed a and p0: least-squares fit of p^2 = p0^2 (1 - r^2/a^2) to the slave nodes with
p > 0 (nodal contact_pressure, r = sqrt(x^2 + y^2) of the reference position). The mesh has
a/h = 5.4 (h = 0.03 near the contact point) and TET4 faces, hence the 15 % tolerance (the 2D
cases, with b/h = 12, hold 5 %); the finer mesh (h = 0.015, a/h = 11) is checked at 5 %
(usage: check_3d.py [STEM [TOL]]). On both, the largest nodal pressure is within 10 % of p0.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402
from grout_results import Results  # noqa: E402

R, E, NU = 1.0, 200.0, 0.3
R_STAR = 1.0 / (1.0 / R + 1.0 / R)
E_STAR = 1.0 / (2 * (1 - NU ** 2) / E)
TOL = 0.15       # a and p0 on the default mesh (a/h = 5.4); the finer mesh passes its own
PEAK_TOL = 0.10  # largest nodal pressure against p0


def hertz_sphere(F):
    a = (3 * F * R_STAR / (4 * E_STAR)) ** (1.0 / 3.0)
    return a, 3 * F / (2 * math.pi * a * a)


def fit(r, p):
    """a, p0 of p^2 = p0^2 (1 - r^2/a^2) fitted to the nodes with p > 0."""
    on = p > 0
    A = np.vstack([np.ones(on.sum()), r[on] ** 2]).T
    c, _, _, _ = np.linalg.lstsq(A, p[on] ** 2, rcond=None)
    return math.sqrt(-c[0] / c[1]), math.sqrt(c[0])


def main(stem, tol):
    failures = []
    res = Results("np1/%s.e" % stem)
    s = cc.node_set(res, "upper_contact_nodes")
    xyz = res.coordinates()
    r = np.hypot(xyz[0, s], xyz[1, s])
    p = res.nodal("contact_pressure")[s]
    F = 4 * abs(res.global_var("reaction_lower_bottom_nodes_z"))
    a_h, p0_h = hertz_sphere(F)
    a, p0 = fit(r, p)
    diff, msg = cc.compare_ranks("np1/%s.e" % stem, "np2/%s.e" % stem,
                                 ["displ_x", "displ_y", "displ_z", "contact_pressure"])
    if msg:
        failures.append(msg)
    ea, ep = abs(a - a_h) / a_h, abs(p0 - p0_h) / p0_h
    p_max = float(p.max())
    em = abs(p_max - p0_h) / p0_h
    print("%s: F = %.5g, a = %.5f (Hertz %.5f, err %.1f %%), p0 = %.5g (Hertz %.5g, err %.1f %%), "
          "largest nodal pressure %.5g (err %.1f %%), %d nodes in contact, 1 vs 2 ranks %.1e"
          % (stem, F, a, a_h, 100 * ea, p0, p0_h, 100 * ep, p_max, 100 * em, int((p > 0).sum()),
             diff))
    if not F > 0:
        failures.append("no contact force")
    if not ea <= tol:
        failures.append("contact radius error %.1f %% > %.0f %%" % (100 * ea, 100 * tol))
    if not ep <= tol:
        failures.append("peak pressure error %.1f %% > %.0f %%" % (100 * ep, 100 * tol))
    # No pressure spikes (faces left unpaired at the edge of the contact zone gave nodal
    # pressures of 12-26 x p0 on finer meshes).
    if not em <= PEAK_TOL:
        failures.append("largest nodal pressure %.5g is %.1f %% off Hertz' p0 (> %.0f %%)"
                        % (p_max, 100 * em, 100 * PEAK_TOL))
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "hemispheres",
                  float(sys.argv[2]) if len(sys.argv) > 2 else TOL))
