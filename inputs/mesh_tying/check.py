"""Mesh tying patch tests (docs/verification.md #21, patches): the linear field u = A X is
reproduced to 1e-10 (relative) at every node of both bodies and the constant stress sigma(A)
in every element, across a tied non-matching interface (QUAD4/TRI3 in 2D, HEX8/TET4 in 3D),
on 1 and 2 ranks; the two runs agree to 1e-10.

Reference: a linear displacement field with the same material on both sides has constant
stress, so it satisfies equilibrium in each body, traction continuity across the interface
and the tying condition u1 = u2; it is the exact solution of the boundary value problem
(Dirichlet u = A X on the outer boundary of the lower body and the top of the upper one,
traction sigma(A) n on the upper body's sides). Dual mortar tying D u1 = M u2 with exactly
integrated D and M reproduces linear fields on a flat non-matching interface (the mortar
patch test: Puso, IJNME 59 (2004); Popp et al., IJNME 83 (2010) §3), and linear elements
reproduce a linear field exactly, hence round-off.
A as in inputs/patch_test; E = 1000, nu = 0.3, plane strain in 2D.

The tied interface reports its normal traction too: the slave (upper) body's outward normal
on the interface is n = -e_y (2D) or -e_z (3D), the slave traction sigma n = -lambda, so
contact_pressure = n . lambda = -sigma_yy (-sigma_zz in 3D) at every slave node (negative:
the interface is in tension), to 1e-10 relative.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402
from grout_results import Results  # noqa: E402

E, NU = 1000.0, 0.3
A2 = np.array([[0.001, 0.002], [-0.0005, 0.0015]])
A3 = np.array([[0.001, 0.002, -0.001], [-0.0005, 0.0015, 0.0007], [0.0003, -0.0004, 0.0012]])


def check(stem, grad, tol=1e-10):
    dim = grad.shape[0]
    stress = cc.stress_of_gradient(grad, E, NU, dim)
    failures = []
    for np_ in (1, 2):
        path = "np%d/%s.e" % (np_, stem)
        r = Results(path)
        xyz = r.coordinates()
        u_exact = grad @ xyz
        u = np.array([r.nodal("displ_" + "xyz"[d]) for d in range(dim)])
        err_u = np.abs(u - u_exact).max() / np.abs(u_exact).max()
        s_scale = max(abs(v) for v in stress.values())
        err_s = max(np.abs(r.element(k) - v).max() for k, v in stress.items()) / s_scale
        # Normal traction on the tied interface (slave side set upper_bottom).
        normal_stress = stress["stress_yy" if dim == 2 else "stress_zz"]
        slave = cc.side_set_nodes(r, "upper_bottom")
        err_p = np.abs(r.nodal("contact_pressure")[slave] + normal_stress).max() / s_scale
        lm_n = -r.nodal("lm_" + "xyz"[dim - 1])[slave]
        err_p = max(err_p, np.abs(r.nodal("contact_pressure")[slave] - lm_n).max() / s_scale)
        print("%-16s np%d: max rel. error displacement %.2e, stress %.2e, contact_pressure %.2e"
              % (stem, np_, err_u, err_s, err_p))
        if not (err_u < tol and err_s < tol and err_p < tol):
            failures.append("%s np%d exceeds %g" % (stem, np_, tol))
    diff, msg = cc.compare_ranks("np1/%s.e" % stem, "np2/%s.e" % stem, ["displ_" + "xyz"[d] for d in range(dim)])
    print("%-16s 1 vs 2 ranks: %.2e" % (stem, diff))
    return failures + ([msg] if msg else [])


def self_test():
    # The tractions written in the YAML files are sigma(A) n with these exact fractions.
    s2 = cc.stress_of_gradient(A2, E, NU, 2)
    assert abs(s2["stress_xx"] - 115 / 52) < 1e-14 and abs(s2["stress_yy"] - 135 / 52) < 1e-14
    assert abs(s2["stress_xy"] - 15 / 26) < 1e-14
    s3 = cc.stress_of_gradient(A3, E, NU, 3)
    expected = {"stress_xx": 151 / 52, "stress_yy": 171 / 52, "stress_zz": 159 / 52,
                "stress_xy": 15 / 26, "stress_yz": 3 / 26, "stress_zx": -7 / 26}
    assert all(abs(s3[k] - v) < 1e-14 for k, v in expected.items()), s3
    print("mesh_tying self-test: ok")


if __name__ == "__main__":
    if "--self-test" in sys.argv:
        self_test()
        sys.exit(0)
    failures = check("tied_quad_tri", A2) + check("tied_hex_tet", A3)
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)
