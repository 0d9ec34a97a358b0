"""Free flight (inputs/dynamics_free_flight): momentum and energy against their exact values.

Exact: no external force, so the momentum stays (m v_x, m v_y) = (2, 1) at every step for any
scheme of the generalised-alpha family (Sum of M a is the sum of the self-equilibrated internal
forces, zero); the average-acceleration Newmark rule conserves the total energy of a linear
system exactly (Hughes, The Finite Element Method, section 9.3), and a dissipative scheme
(rho_infinity < 1) never increases it. The initial kinetic energy is
1/2 m |v_c|^2 + 1/2 I omega^2 + 1/2 m s^2/12 with I = m (1 + 1)/12 for the unit square and
s the stretch rate (the three parts of the velocity field are orthogonal in the mass inner
product; the consistent mass integrates these linear fields exactly).
Finite strain (finite_*.yaml: Neo-Hookean, lumped mass, spun at omega = 2 rad/s, about 230
degrees over the run): the energy-momentum scheme keeps the total energy and the angular
momentum about the centre of mass, L = sum_a m_a (x_a - x_c) x v_a, exactly (Simo & Tarnow,
ZAMP 43 (1992) 757; Gonzalez, CMAME 190 (2000) 1763): both to 1e-9, the Newton tolerance.
The average-acceleration rule keeps neither under finite strain: its run must miss both by
more than 1e-5 (so that the check can tell the two apart), and both keep the momentum.
Also: 1 and 2 ranks agree to 1e-10.
"""
import csv
import sys

import numpy as np

from grout_results import Results, relative_difference

m, vc, omega = 2.0, np.array([1.0, 0.5]), 0.2
stretch = 0.05  # v_x += stretch (x - 1/2): a symmetric stretch, no momentum
E0 = 0.5 * m * vc @ vc + 0.5 * (m * 2.0 / 12.0) * omega**2 + 0.5 * m * stretch**2 / 12.0
# Row-sum lumped masses on the 4 x 4 grid (h = 1/4): rho h^2 inside, half on edges, a quarter
# at corners; their rotational inertia about the centre is not the continuum one.
g = np.linspace(0.0, 1.0, 5)
w = np.where((g == 0) | (g == 1), 0.5, 1.0)
X, Y = np.meshgrid(g, g)
M_lumped = m / 16.0 * np.outer(w, w)
I_lumped = (M_lumped * ((X - 0.5) ** 2 + (Y - 0.5) ** 2)).sum()
E0_lumped = (0.5 * m * vc @ vc + 0.5 * I_lumped * omega**2
             + 0.5 * (M_lumped * (stretch * (X - 0.5)) ** 2).sum())
failures = []


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


for case in ("newmark", "generalized_alpha", "lumped_hht"):
    s = read("np1/%s.csv" % case)
    p_err = max(np.abs(s["momentum_x"] - m * vc[0]).max(), np.abs(s["momentum_y"] - m * vc[1]).max())
    E = s["total_energy"]
    E_start = E0_lumped if case == "lumped_hht" else E0
    drift = (E - E_start) / E_start
    print("%-18s steps %d  momentum error %.2e  energy drift: final %.2e, max %.2e, max gain %.2e"
          % (case, len(E), p_err, drift[-1], np.abs(drift).max(), drift.max()))
    if p_err > 1e-9:
        failures.append("%s: momentum changed by %.3e" % (case, p_err))
    if case == "newmark" and np.abs(drift).max() > 1e-8:
        failures.append("newmark: total energy drifts by %.3e (exact: 0)" % np.abs(drift).max())
    if case != "newmark" and (drift.max() > 1e-9 or drift.min() < -0.01):
        failures.append("%s: energy gain %.3e or loss %.3e (expected no gain, loss < 1 %%)"
                        % (case, drift.max(), -drift.min()))
    if s["strain_energy"].max() <= 0.0:
        failures.append("%s: no strain energy at all (the spin should stretch the body)" % case)
    r1, r2 = Results("np1/%s.e" % case), Results("np2/%s.e" % case)
    for name in ("displ_x", "displ_y", "velocity_x", "velocity_y", "acceleration_x"):
        d = relative_difference(r1.nodal(name), r2.nodal(name))
        if d > 1e-10:
            failures.append("%s: %s differs between 1 and 2 ranks by %.3e" % (case, name, d))


def angular_momentum(results):
    """L(t) = sum_a m_a (x_a - x_c) x v_a with the row-sum lumped masses of the 4 x 4 grid, and
    the angle through which node 0 has turned about the centre of mass (degrees)."""
    X = results.coordinates()
    edge = lambda c: np.where(np.isclose(c, 0.0) | np.isclose(c, 1.0), 0.5, 1.0)
    mass = m / 16.0 * edge(X[0]) * edge(X[1])
    L, angle = [], []
    for k in range(len(results.times())):
        x, y = X[0] + results.nodal("displ_x", k), X[1] + results.nodal("displ_y", k)
        vx, vy = results.nodal("velocity_x", k), results.nodal("velocity_y", k)
        xc, yc = (mass * x).sum() / m, (mass * y).sum() / m
        L.append((mass * ((x - xc) * vy - (y - yc) * vx)).sum())
        angle.append(np.arctan2(y[0] - yc, x[0] - xc))
    turned = np.degrees(np.unwrap(angle))
    return np.array(L), turned[-1] - turned[0]


for case in ("finite_energy_momentum", "finite_newmark"):
    s = read("np1/%s.csv" % case)
    r1 = Results("np1/%s.e" % case)
    E = s["total_energy"]
    drift = np.abs(E - E[0]).max() / E[0]
    L, turned = angular_momentum(r1)
    L_err = np.abs(L - L[0]).max() / abs(L[0])
    p_err = max(np.abs(s["momentum_x"] - m * vc[0]).max(), np.abs(s["momentum_y"] - m * vc[1]).max())
    print("%-22s steps %d  momentum error %.2e  energy drift max %.2e  angular momentum %.6f, "
          "change max %.2e (turned by %.0f deg)" % (case, len(E), p_err, drift, L[0], L_err, turned))
    if p_err > 1e-9:
        failures.append("%s: momentum changed by %.3e" % (case, p_err))
    if case == "finite_energy_momentum" and (drift > 1e-9 or L_err > 1e-9):
        failures.append("%s: energy drift %.3e, angular momentum change %.3e (exact: 0)"
                        % (case, drift, L_err))
    if case == "finite_newmark" and (drift < 1e-5 or L_err < 1e-5):
        failures.append("%s: energy drift %.3e, angular momentum change %.3e: no longer tells the "
                        "schemes apart" % (case, drift, L_err))
    r2 = Results("np2/%s.e" % case)
    for name in ("displ_x", "displ_y", "velocity_x", "velocity_y"):
        d = relative_difference(r1.nodal(name), r2.nodal(name))
        if d > 1e-10:
            failures.append("%s: %s differs between 1 and 2 ranks by %.3e" % (case, name, d))
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
