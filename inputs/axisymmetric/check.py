"""Axisymmetric solids and contact (model/plane: axisymmetric, x = r, y = z), against closed
forms, on 1 and 2 ranks (which must agree to 1e-10):

- solid sphere under external pressure p: u = -p (1 - 2 nu)/E (r, z) (Timoshenko & Goodier,
  Theory of Elasticity, §137 with no cavity), a linear field: every nodal displacement to
  1e-10 relative and every element stress (rr, zz, tt in the "zz" slot) = -p to 1e-10;
- the same sphere under a dead pressure, finite strain, Neo-Hookean: the homogeneous stretch
  F = s I, mu (s - 1/s) + lambda 3 ln(s)/s = -p (Bonet & Wood eq. 6.28), u = (s - 1)(r, z) at
  every node and the Cauchy stress -p/s^2 in every element, to 1e-8 (Newton's tolerance);
- thick-walled cylinder, held in z at both ends (plane strain along the axis), internal
  pressure: Lamé's u_r = (1 + nu) p a^2 / (E (b^2 - a^2)) [(1 - 2 nu) r + b^2 / r], u_z = 0
  (Timoshenko & Goodier §28), not in the element space: the maximum nodal error of u_r
  decreases at O(h^2) (observed rates > 1.8) and is below 0.5 % on the finest mesh;
- flat punch on a cylinder end (contact patch test, non-matching distorted meshes, two
  materials): sigma_zz = -p, u_r = nu p r / E, u_z = -p z / E in each body, contact_pressure = p
  at every slave node, to 1e-8 (contact_common/contact_check.py, check_uniform);
- the same punch under finite strain (Neo-Hookean, both bodies alike, dead pressure p):
  F = diag(l_r, l_z, l_r) with P_rr = P_tt = 0, P_zz = -p, u = ((l_r - 1) r, (l_z - 1) z) and
  contact_pressure = p / l_r^2 (Cauchy, current area) at every slave node, to 1e-8.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402
from grout_results import Results, relative_difference  # noqa: E402

failures = []


def rank_difference(stem, fields):
    r1, r2 = Results("np1/%s.e" % stem), Results("np2/%s.e" % stem)
    diff = max(relative_difference(r1.nodal(f), r2.nodal(f)) for f in fields)
    if not diff < 1e-10:
        failures.append("%s: 1 and 2 ranks differ by %.2e" % (stem, diff))
    return diff


# Solid sphere under pressure.
P_S, E_S, NU_S = 1.0e6, 2.0e9, 0.3
for np_ in (1, 2):
    r = Results("np%d/sphere_pressure.e" % np_)
    x, y = r.coordinates()[:2]
    c = -P_S * (1 - 2 * NU_S) / E_S
    u = np.array([r.nodal("displ_x"), r.nodal("displ_y")])
    err_u = np.abs(u - c * np.array([x, y])).max() / (abs(c) * np.hypot(x, y).max())
    err_s = max(np.abs(r.element(k) + P_S).max() for k in ("stress_xx", "stress_yy", "stress_zz")) / P_S
    err_s = max(err_s, np.abs(r.element("stress_xy")).max() / P_S)
    print("sphere_pressure np%d: max nodal displacement error %.2e, stress error %.2e"
          % (np_, err_u, err_s))
    if not (err_u < 1e-10 and err_s < 1e-10):
        failures.append("sphere_pressure np%d: errors %.2e, %.2e above 1e-10" % (np_, err_u, err_s))
print("sphere_pressure 1 vs 2 ranks: %.1e" % rank_difference("sphere_pressure", ["displ_x", "displ_y"]))

# The same sphere, finite strain (Neo-Hookean, dead pressure).
P_F = 2.0e8
LAM = E_S * NU_S / ((1 + NU_S) * (1 - 2 * NU_S))
MU = E_S / (2 * (1 + NU_S))
s = 1.0
for _ in range(50):  # Newton on mu (s - 1/s) + 3 lambda ln(s)/s + p = 0
    s -= ((MU * (s - 1 / s) + 3 * LAM * math.log(s) / s + P_F)
          / (MU * (1 + 1 / s**2) + 3 * LAM * (1 - math.log(s)) / s**2))
for np_ in (1, 2):
    r = Results("np%d/sphere_pressure_finite.e" % np_)
    x, y = r.coordinates()[:2]
    u = np.array([r.nodal("displ_x"), r.nodal("displ_y")])
    err_u = np.abs(u - (s - 1) * np.array([x, y])).max() / (abs(s - 1) * np.hypot(x, y).max())
    sig = -P_F / s**2
    err_s = max(np.abs(r.element(k) - sig).max() for k in ("stress_xx", "stress_yy", "stress_zz"))
    err_s = max(err_s, np.abs(r.element("stress_xy")).max()) / abs(sig)
    print("sphere_pressure_finite np%d (s = %.6f): max nodal displacement error %.2e, Cauchy "
          "stress error %.2e" % (np_, s, err_u, err_s))
    if not (err_u < 1e-8 and err_s < 1e-8):
        failures.append("sphere_pressure_finite np%d: errors %.2e, %.2e above 1e-8"
                        % (np_, err_u, err_s))
print("sphere_pressure_finite 1 vs 2 ranks: %.1e"
      % rank_difference("sphere_pressure_finite", ["displ_x", "displ_y"]))

# Lamé cylinder, O(h^2).
A, B, P_L, E_L, NU_L = 1.0, 2.0, 10.0, 1000.0, 0.3


def lame_u(r):
    return (1 + NU_L) * P_L * A**2 / (E_L * (B**2 - A**2)) * ((1 - 2 * NU_L) * r + B**2 / r)


errors = []
for level in (1, 2, 3):
    stem = "lame_axisymmetric_%d" % level
    r = Results("np1/%s.e" % stem)
    x = r.coordinates()[0]
    exact = lame_u(x)
    e = np.abs(r.nodal("displ_x") - exact).max() / np.abs(exact).max()
    uz = np.abs(r.nodal("displ_y")).max() / np.abs(exact).max()
    errors.append(e)
    diff = rank_difference(stem, ["displ_x", "displ_y"])
    print("%s (h = 1/%d): max relative u_r error %.3e, max |u_z| %.1e; 1 vs 2 ranks %.1e"
          % (stem, 4 * 2 ** (level - 1), e, uz, diff))
    if not uz < 1e-10:
        failures.append("%s: u_z = %.2e, expected 0" % (stem, uz))
rates = [math.log2(errors[i] / errors[i + 1]) for i in range(2)]
print("Lame observed rates: %.3f, %.3f (expected 2)" % tuple(rates))
if not all(rate > 1.8 for rate in rates):
    failures.append("Lame convergence rate below 1.8: %s" % rates)
if not errors[-1] < 5e-3:
    failures.append("Lame finest error %.3e above 0.5 %%" % errors[-1])

# Flat punch on a cylinder end.
P_C = 1.0e8
sigma = np.zeros((3, 3))
sigma[1, 1] = -P_C  # sigma_zz; the hoop slot sigma[2, 2] = sigma_tt = 0
lower = cc.body_state(sigma, 1.0e11, 0.35, 2)
upper = cc.body_state(sigma, 2.069e11, 0.29, 2, origin=[0.0, 1.0],
                      offset=lower["grad"] @ [0.0, 1.0] + lower["offset"])
failures += cc.check_uniform_case("punch_patch", {"lower": lower, "upper": upper}, "upper_bottom",
                                  P_C, tol=1e-8)

# The punch under finite strain: solve P_rr(l_r, l_z) = 0, P_zz(l_r, l_z) = -p by Newton.
P_N, E_N, NU_N = 2.0e10, 2.069e11, 0.29
LAM_N = E_N * NU_N / ((1 + NU_N) * (1 - 2 * NU_N))
MU_N = E_N / (2 * (1 + NU_N))


def nominal_stress(lr, lz):
    log_j = math.log(lr * lr * lz)
    return np.array([MU_N * (lr - 1 / lr) + LAM_N * log_j / lr,
                     MU_N * (lz - 1 / lz) + LAM_N * log_j / lz + P_N])


st = np.array([1.0, 1.0])
for _ in range(30):
    f0 = nominal_stress(*st)
    jac = np.zeros((2, 2))
    for k in range(2):
        d = np.zeros(2)
        d[k] = 1e-7
        jac[:, k] = (nominal_stress(*(st + d)) - f0) / 1e-7
    st -= np.linalg.solve(jac, f0)
LR, LZ = st
for np_ in (1, 2):
    r = Results("np%d/punch_patch_finite.e" % np_)
    x, y = r.coordinates()[:2]
    err_u = max(np.abs(r.nodal("displ_x") - (LR - 1) * x).max(),
                np.abs(r.nodal("displ_y") - (LZ - 1) * y).max()) / (abs(LZ - 1) * np.abs(y).max())
    s_nodes = cc.side_set_nodes(r, "upper_bottom")
    cp = r.nodal("contact_pressure")[s_nodes]
    err_p = np.abs(cp - P_N / LR**2).max() / (P_N / LR**2)
    err_s = np.abs(r.element("stress_yy") + P_N / LR**2).max() / (P_N / LR**2)
    print("punch_patch_finite np%d (l_r = %.6f, l_z = %.6f): displacement %.2e, contact_pressure "
          "%.2e, sigma_zz %.2e" % (np_, LR, LZ, err_u, err_p, err_s))
    if not (err_u < 1e-8 and err_p < 1e-8 and err_s < 1e-8):
        failures.append("punch_patch_finite np%d: errors %.2e, %.2e, %.2e above 1e-8"
                        % (np_, err_u, err_p, err_s))
print("punch_patch_finite 1 vs 2 ranks: %.1e"
      % rank_difference("punch_patch_finite", ["displ_x", "displ_y", "contact_pressure"]))

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
