"""Finite-strain solids (total Lagrangian) against closed-form references.

1. Homogeneous finite deformation patch tests (stretch_quad4: Neo-Hookean, plane strain;
   shear_hex8: St. Venant-Kirchhoff, 3D): u = (F - I) X on the boundary, so the exact
   solution is u = (F - I) X everywhere with the Cauchy stress of the law at F; displacement
   and element stresses to 1e-10 relative. Plane stress (plane: stress, strain: finite):
   stretch_quad4_plane_stress, a Neo-Hookean sheet in uniaxial stretch, against the closed form
   l(s) = s^-2 exp(mu (1 - s^2) / lambda), sigma_xx = mu (l^2 - s^2) / (l s^2) at every step;
   shear_quad4_plane_stress, St. Venant-Kirchhoff under a general in-plane F, against
   E_33 = -lambda (E_11 + E_22) / (lambda + 2 mu), sigma = F S F^T / J.
2. Large-deflection cantilever (Neo-Hookean, nu = 0, L/h = 20, P L^2 / EI = 2 at t = 1) on
   three nested meshes against the elastica (elastica.py; Mattiasson 1981, Table I:
   u/L = 0.16064, w/L = 0.49346): the tip errors fall by at least 3x per refinement, the finest
   mesh is within 1 % and the Richardson extrapolation (order 2) within 0.5 % of the elastica
   (what remains is shear deformation, about (E/kG)(h/L)^2/4 = 0.15 %, and the stretch of the
   axis, both absent from the elastica). Writes cantilever.png.
3. Quadratic Newton convergence (consistent AD tangent): in every step of every run, on the
   iterations with 0.1 |F_0| > |F_k|, |F_{k+1}| > 10 x the round-off level (the step's last
   residual), |F_{k+1}| <= C |F_k|^2 / |F_0| with C = 10.
4. 1 and 2 ranks agree to 1e-10.
"""
import csv
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from elastica import tip_displacement  # noqa: E402
from grout_results import Results, relative_difference  # noqa: E402

E, NU = 1000.0, 0.3
LAM, MU = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
failures = []
C_QUADRATIC = 10.0


def neo_hookean_cauchy(F):
    J = np.linalg.det(F)
    return MU / J * (F @ F.T - np.eye(3)) + LAM * math.log(J) / J * np.eye(3)


def svk_cauchy(F):
    Eg = 0.5 * (F.T @ F - np.eye(3))
    S = LAM * np.trace(Eg) * np.eye(3) + 2 * MU * Eg
    return F @ S @ F.T / np.linalg.det(F)


def check_patch(name, F, sigma):
    dim = 2 if "quad4" in name else 3
    names = (["stress_xx", "stress_yy", "stress_xy", "stress_zz"] if dim == 2 else
             ["stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_yz", "stress_zx"])
    index = {"xx": (0, 0), "yy": (1, 1), "zz": (2, 2), "xy": (0, 1), "yz": (1, 2), "zx": (0, 2)}
    runs = {}
    for np_ in (1, 2):
        r = Results("np%d/%s.e" % (np_, name))
        X = r.coordinates()
        u_exact = (F[:dim, :dim] - np.eye(dim)) @ X
        u = np.array([r.nodal("displ_" + "xyz"[d]) for d in range(dim)])
        err_u = np.abs(u - u_exact).max() / np.abs(u_exact).max()
        scale = np.abs(sigma).max()
        err_s = max(np.abs(r.element(n) - sigma[index[n[-2:]]]).max() for n in names) / scale
        print("%-14s np%d: max rel. error displacement %.2e, Cauchy stress %.2e"
              % (name, np_, err_u, err_s))
        if not (err_u < 1e-10 and err_s < 1e-10):
            failures.append("%s np%d: error above 1e-10" % (name, np_))
        runs[np_] = u.ravel()
    diff = relative_difference(runs[1], runs[2])
    print("%-14s 1 vs 2 ranks: %.2e" % (name, diff))
    if not diff < 1e-10:
        failures.append("%s: 1 and 2 ranks differ by %.2e" % (name, diff))


F2 = np.array([[1.5, 0.4, 0.0], [-0.1, 0.8, 0.0], [0.0, 0.0, 1.0]])
check_patch("stretch_quad4", F2, neo_hookean_cauchy(F2))
F3 = np.eye(3) + np.array([[0.3, 0.2, 0.0], [0.0, -0.1, 0.25], [0.1, 0.0, 0.2]])
check_patch("shear_hex8", F3, svk_cauchy(F3))

# 1b. Plane stress (model: {plane: stress, strain: finite}).
# Neo-Hookean sheet in uniaxial stretch, F = diag(l, s, s): P_22 = P_33 = 0 give
# mu (s^2 - 1) + lambda ln(l s^2) = 0, so l(s) = s^-2 exp(mu (1 - s^2) / lambda), and
# sigma_xx = mu (l^2 - s^2) / (l s^2) (derivation: unit_tests/test_kernels_plane_stress.cpp).
# At t = 1 the prescribed l_1 = l(0.9); at every step the measured lateral stretch s must give
# back the prescribed l(t) through l(s), and the stresses their closed forms.
L1 = math.exp(0.19 / 1.5) / 0.81


def stretch_of(s):
    return math.exp(MU * (1.0 - s * s) / LAM) / (s * s)


S1 = 0.9
F_ps = np.diag([stretch_of(S1), S1, S1])
sigma_ps = np.diag([MU * (F_ps[0, 0] ** 2 - S1 ** 2) / (F_ps[0, 0] * S1 ** 2), 0.0, 0.0])
check_patch("stretch_quad4_plane_stress", F_ps, sigma_ps)
for np_ in (1, 2):
    r = Results("np%d/stretch_quad4_plane_stress.e" % np_)
    x, y = r.coordinates()
    top = y > 0.5
    worst = 0.0
    for step, t in enumerate(r.times()):
        if t == 0.0:
            continue
        s = 1.0 + np.mean(r.nodal("displ_y", step)[top] / y[top])
        l_prescribed = 1.0 + t * (L1 - 1.0)
        sxx = MU * (l_prescribed ** 2 - s * s) / (l_prescribed * s * s)
        err = max(abs(stretch_of(s) / l_prescribed - 1.0),
                  np.abs(r.element("stress_xx", step) - sxx).max() / sxx,
                  max(np.abs(r.element(n, step)).max() for n in ("stress_yy", "stress_xy",
                                                                 "stress_zz")) / sxx)
        worst = max(worst, err)
    print("stretch_quad4_plane_stress np%d: every step, l(s) and sigma against the closed form: "
          "max rel. error %.2e" % (np_, worst))
    if not worst < 1e-10:
        failures.append("stretch_quad4_plane_stress np%d: closed form missed by %.2e" % (np_, worst))


def svk_plane_stress_cauchy(F):
    """St. Venant-Kirchhoff sheet: E_33 = -lambda (E_11 + E_22) / (lambda + 2 mu), S_33 = 0."""
    F = F.copy()
    E2 = 0.5 * (F[:2, :2].T @ F[:2, :2] - np.eye(2))
    E33 = -LAM * np.trace(E2) / (LAM + 2 * MU)
    F[2, 2] = math.sqrt(1.0 + 2.0 * E33)
    return svk_cauchy(F)


F_svk = np.array([[1.3, 0.3, 0.0], [-0.2, 0.9, 0.0], [0.0, 0.0, 1.0]])
check_patch("shear_quad4_plane_stress", F_svk, svk_plane_stress_cauchy(F_svk))

# 2. Cantilever.
L, H, K_END = 10.0, 0.5, 2.0
ref_u, ref_w = tip_displacement(K_END)
print("elastica k = %g: u/L = %.5f, w/L = %.5f" % (K_END, ref_u, ref_w))
tips, curves = [], []
for level in (1, 2, 3):
    per_rank = {}
    for np_ in (1, 2):
        r = Results("np%d/cantilever_%d.e" % (np_, level))
        x, y = r.coordinates()
        tip = int(np.argmin((x - L) ** 2 + (y - H / 2) ** 2))
        steps = len(r.times())
        per_rank[np_] = np.array([[-r.nodal("displ_x", s)[tip] / L, r.nodal("displ_y", s)[tip] / L]
                                  for s in range(steps)])
        if np_ == 1:
            curves.append((2.0 * r.times(), per_rank[1]))
    diff = relative_difference(per_rank[1], per_rank[2])
    if not diff < 1e-10:
        failures.append("cantilever_%d: 1 and 2 ranks differ by %.2e" % (level, diff))
    u, w = per_rank[1][-1]
    tips.append((u, w))
    print("cantilever_%d: u/L = %.5f (error %+.2e), w/L = %.5f (error %+.2e); 1 vs 2 ranks %.1e"
          % (level, u, u - ref_u, w, w - ref_w, diff))
for c, ref in ((0, ref_u), (1, ref_w)):
    errors = [abs(t[c] - ref) for t in tips]
    what = "uw"[c]
    if not (errors[1] * 3 < errors[0] and errors[2] * 3 < errors[1]):
        failures.append("cantilever %s/L: errors %s do not fall 3x per refinement" % (what, errors))
    if not errors[2] < 1e-2 * ref:
        failures.append("cantilever %s/L: finest error %.2e above 1 %%" % (what, errors[2]))
    extrapolated = tips[2][c] + (tips[2][c] - tips[1][c]) / 3.0
    print("cantilever %s/L: Richardson extrapolation %.5f (%+.2f %% from the elastica)"
          % (what, extrapolated, 100 * (extrapolated / ref - 1)))
    if not abs(extrapolated / ref - 1) < 5e-3:
        failures.append("cantilever %s/L: extrapolation off by more than 0.5 %%" % what)

try:
    import matplotlib.pyplot as plt
    k = np.linspace(0.0, K_END, 21)
    ref = np.array([tip_displacement(v) for v in k])
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(k, ref[:, 1], "k-", label="elastica w/L")
    ax.plot(k, ref[:, 0], "k--", label="elastica u/L")
    for level, (kk, vals) in enumerate(curves, start=1):
        ax.plot(kk, vals[:, 1], "o", ms=4, label="Grout w/L, mesh %d" % level)
        ax.plot(kk, vals[:, 0], "s", ms=4, mfc="none", label="Grout u/L, mesh %d" % level)
    ax.set_xlabel("P L^2 / EI")
    ax.set_ylabel("tip displacement / L")
    ax.set_title("Neo-Hookean cantilever, L/h = 20")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig("cantilever.png", dpi=100)
    print("wrote cantilever.png")
except ImportError:
    print("matplotlib not available: no cantilever.png")

# 3. Quadratic convergence.
checked = 0
for name in ("stretch_quad4", "shear_hex8", "stretch_quad4_plane_stress", "shear_quad4_plane_stress",
             "cantilever_1", "cantilever_2", "cantilever_3"):
    for np_ in (1, 2):
        rows = list(csv.DictReader(open("np%d/%s_newton.csv" % (np_, name))))
        steps = sorted({(int(r["step"]), float(r["time"])) for r in rows})
        for s in steps:
            hist = [float(r["residual"]) for r in rows
                    if (int(r["step"]), float(r["time"])) == s]
            f0, floor = hist[0], 10 * hist[-1]  # the last iterate sits at the round-off level
            for fa, fb in zip(hist, hist[1:]):
                if 1e-1 * f0 > fa > floor and fb > floor:
                    checked += 1
                    order = math.log(fb / f0) / math.log(fa / f0)
                    if np_ == 1:
                        print("%s step %d: |F|/|F0| %.2e -> %.2e (order %.2f)"
                              % (name, s[0], fa / f0, fb / f0, order))
                    if not fb <= C_QUADRATIC * fa * fa / f0:
                        failures.append("%s np%d step %d: |F| %.3e -> %.3e is not quadratic"
                                        % (name, np_, s[0], fa, fb))
print("quadratic convergence checked on %d iterations" % checked)
if checked < 10:
    failures.append("fewer than 10 iterations in the quadratic range")

if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("finite_strain: all checks passed")
