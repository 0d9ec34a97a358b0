"""Patch tests: the computed fields equal the exact linear displacement and constant stress
to 1e-10 (relative), on 1 and 2 ranks, and the two runs agree to 1e-10."""
import sys

import numpy as np

from grout_results import Results, relative_difference

E, NU = 1000.0, 0.3
LAM, MU = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))

A2 = np.array([[0.001, 0.002], [-0.0005, 0.0015]])
A3 = np.array([[0.001, 0.002, -0.001], [-0.0005, 0.0015, 0.0007], [0.0003, -0.0004, 0.0012]])


def stress_3d(grad):
    eps = 0.5 * (grad + grad.T)
    return LAM * np.trace(eps) * np.eye(3) + 2 * MU * eps


def exact_patch(dim):
    """Displacement gradient, and stress components by output name."""
    if dim == 2:
        g = np.zeros((3, 3))
        g[:2, :2] = A2
        s = stress_3d(g)  # plane strain: eps_zz = 0
        return A2, {"stress_xx": s[0, 0], "stress_yy": s[1, 1], "stress_xy": s[0, 1], "stress_zz": s[2, 2]}
    s = stress_3d(A3)
    return A3, {"stress_xx": s[0, 0], "stress_yy": s[1, 1], "stress_zz": s[2, 2],
                "stress_xy": s[0, 1], "stress_yz": s[1, 2], "stress_zx": s[0, 2]}


def exact_tension():
    sigma = 10.0
    grad = np.diag([(1 - NU**2) * sigma / E, -NU * (1 + NU) * sigma / E])
    return grad, {"stress_xx": sigma, "stress_yy": 0.0, "stress_xy": 0.0, "stress_zz": NU * sigma}


def check(name, exact, tol=1e-10):
    failures = []
    runs = {}
    for np_ in (1, 2):
        r = Results("np%d/%s.e" % (np_, name))
        xyz = r.coordinates()
        dim = xyz.shape[0]
        grad, stress = exact
        u_exact = grad @ xyz
        scale = np.abs(u_exact).max()
        err_u = max(np.abs(r.nodal("displ_" + "xyz"[d]) - u_exact[d]).max() for d in range(dim)) / scale
        s_scale = max(abs(v) for v in stress.values())
        err_s = max(np.abs(r.element(k) - v).max() for k, v in stress.items()) / s_scale
        print("%-14s np%d: max rel. error displacement %.2e, stress %.2e" % (name, np_, err_u, err_s))
        if not (err_u < tol and err_s < tol):
            failures.append("%s np%d exceeds %g" % (name, np_, tol))
        runs[np_] = np.concatenate([r.nodal("displ_" + "xyz"[d]) for d in range(dim)])
    diff = relative_difference(runs[1], runs[2])
    print("%-14s 1 vs 2 ranks: %.2e" % (name, diff))
    if not diff < 1e-10:
        failures.append("%s: 1 and 2 ranks differ by %.2e" % (name, diff))
    return failures


failures = []
failures += check("patch_quad4", exact_patch(2))
failures += check("patch_tri3", exact_patch(2))
failures += check("patch_hex8", exact_patch(3))
failures += check("patch_tet4", exact_patch(3))
failures += check("tension_quad4", exact_tension())
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
