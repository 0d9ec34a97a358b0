"""Taylor patch test, frictionless, non-matching meshes (docs/verification.md #4 and #5): contact
pressure = 10 at every slave node and the uniform stress state to 1e-8 (relative), u_y (u_z
in 3D) continuous across the interface, on 1 and 2 ranks; the runs agree to 1e-10.

Reference (Taylor & Papadopoulos, "On a patch test for contact problems in two dimensions",
1991; Popp, Gitterle, Gee & Wall, IJNME 83, 2010, §6.1; Kratos taylor_patch_test): the die
and the uncovered foundation top carry the same pressure p = 10, so the uniaxial state
sigma = -p e_v e_v (e_v = vertical axis) satisfies equilibrium in both bodies, the traction
boundary conditions and frictionless contact; it is the exact small-strain solution for any
E, nu per body. Plane strain adds sigma_zz = nu (sigma_xx + sigma_yy) = -4 (nu = 0.4).
Displacements: eps = (1 + nu)/E sigma - nu/E tr(sigma) I, u = eps X for the foundation
(anchored at the origin) and u = eps_die (X - X_anchor) + (0, eps_vv,block h) for the die
(h = foundation height 5 in 2D, 4 in 3D), e.g. u_y(y=5) = -(1 - nu^2) p 5/E = -0.042 for
E = 1000 (Kratos' stated exact value). The frictionless interface lets the die slide when its
lateral strain differs (E = 3000), so only the vertical displacement is continuous.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402
from grout_results import Results  # noqa: E402

P, NU = 10.0, 0.4


def bodies(dim, e_block, e_die):
    v = dim - 1
    if dim == 2:
        sigma = cc.plane_strain_stress(0.0, -P, 0.0, NU)
        anchor, h = np.array([4.0, 5.0]), 5.0
    else:
        sigma = np.zeros((3, 3))
        sigma[2, 2] = -P
        anchor, h = np.array([4.0, 4.0, 4.0]), 4.0
    block = cc.body_state(sigma, e_block, NU, dim)
    offset = np.zeros(dim)
    offset[v] = block["grad"][v, v] * h
    die = cc.body_state(sigma, e_die, NU, dim, origin=anchor, offset=offset)
    return {"block": block, "die": die}


def interface_jump(path, dim):
    """Max |vertical displacement jump| across the interface, relative to its magnitude: 2D by
    interpolating the master (block top) u_y at the slave nodes' x; 3D, where the exact u_z is
    constant on the interface, as the spread of u_z over both sides."""
    r = Results(path)
    xyz = r.coordinates()
    uv = r.nodal("displ_" + "xyz"[dim - 1])
    s, m = cc.side_set_nodes(r, "die_bottom"), cc.side_set_nodes(r, "block_top")
    m = m[(xyz[0, m] >= 4.0) & (xyz[0, m] <= 6.0)]
    if dim == 3:
        m = m[(xyz[1, m] >= 4.0) & (xyz[1, m] <= 6.0)]
        both = uv[np.concatenate([s, m])]
        return (both.max() - both.min()) / np.abs(both).max()
    o = np.argsort(xyz[0, m])
    master = np.interp(xyz[0, s], xyz[0, m][o], uv[m][o])
    return np.abs(uv[s] - master).max() / np.abs(master).max()


def self_test():
    b = bodies(2, 1000.0, 1000.0)
    assert abs(b["block"]["grad"][1, 1] * 5 + 0.042) < 1e-15
    assert abs(b["block"]["grad"][0, 0] - 0.0056) < 1e-15
    # Die bottom at the foundation top, anchor (4, 7) fixed in x.
    u = b["die"]["grad"] @ np.array([4.0, 7.0]) + b["die"]["offset"]
    assert abs(u[0]) < 1e-15
    u = b["die"]["grad"] @ np.array([5.0, 5.0]) + b["die"]["offset"]
    assert abs(u[1] + 0.042) < 1e-15
    b = bodies(3, 1000.0, 3000.0)
    assert abs(b["block"]["grad"][2, 2] * 4 + 0.04) < 1e-15  # eps_zz = -p/E
    u = b["die"]["grad"] @ np.array([6.0, 4.0, 6.0]) + b["die"]["offset"]
    assert abs(u[1]) < 1e-15 and abs(u[0] - 0.4 * 10 / 3000 * 2) < 1e-15
    print("taylor_patch self-test: ok")


if __name__ == "__main__":
    if "--self-test" in sys.argv:
        self_test()
        sys.exit(0)
    failures = []
    cases = [("taylor_2d", 2, 1000.0, 1000.0), ("taylor_2d_bimaterial", 2, 1000.0, 3000.0),
             ("taylor_3d_hex", 3, 1000.0, 1000.0), ("taylor_3d_hex_bimaterial", 3, 1000.0, 3000.0),
             ("taylor_3d_tet", 3, 1000.0, 1000.0)]
    for stem, dim, e_block, e_die in cases:
        failures += cc.check_uniform_case(stem, bodies(dim, e_block, e_die), "die_bottom", P)
        for np_ in (1, 2):
            if Results("np%d/%s.e" % (np_, stem)).times().size == 0:
                continue  # no converged step: already reported
            jump = interface_jump("np%d/%s.e" % (np_, stem), dim)
            print("%-28s np%d: vertical displacement jump across the interface %.2e" % (stem, np_, jump))
            if not jump < 1e-8:
                failures.append("%s np%d: interface jump %.2e" % (stem, np_, jump))
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)
