"""Contact patch tests, frictionless (docs/verification.md #1 and #2): the computed fields equal the
analytic uniform-stress solution to 1e-8 (relative), on 1 and 2 ranks, and the runs agree to
1e-10.

Reference (small-strain linear elasticity, exact for any mesh that passes the patch test):
every body carries a uniform stress, so its displacement is linear, u = eps X + c, with
eps = (1 + nu)/E sigma - nu/E tr(sigma) I (plane strain: sigma_zz = nu (sigma_xx + sigma_yy)),
and the frictionless interface transmits the normal traction only:
  straight (2D/3D): sigma = -p e_y e_y (2D) / -p e_z e_z (3D); contact_pressure = p;
  sloped 2D: sigma = -p I (in plane; a uniaxial state would shear the sloped interface);
    contact_pressure = p; with different strains eps_l, eps_u (nu = 0 in one body) the upper
    body moves rigidly by c_y = -(eps_u - eps_l) d / n_y, d = X.n on the interface line,
    which keeps the gap closed while the bodies slide (Taylor & Papadopoulos 1991 style
    patch test for contact; Popp et al. 2010, §5).
p = 1e8, E = 2.069e11 (p/E ~ 5e-4, small strain).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402

P, E, NU = 1.0e8, 2.069e11, 0.29
Y_LEFT, Y_RIGHT, WIDTH = 0.9, 1.1, 1.0


def straight(dim, nu_lower):
    axis = dim - 1
    sigma = np.zeros((3, 3))
    sigma[axis, axis] = -P
    if dim == 2:
        s_l = cc.plane_strain_stress(0.0, -P, 0.0, nu_lower)
        s_u = cc.plane_strain_stress(0.0, -P, 0.0, NU)
    else:
        s_l = s_u = sigma
    lower = cc.body_state(s_l, E, nu_lower, dim)
    top_of_lower = np.zeros(dim)
    top_of_lower[axis] = 1.0
    upper = cc.body_state(s_u, E, NU, dim, origin=top_of_lower,
                          offset=lower["grad"] @ top_of_lower + lower["offset"])
    return {"lower": lower, "upper": upper}


def sloped(nu_lower):
    lower = cc.body_state(cc.plane_strain_stress(-P, -P, 0.0, nu_lower), E, nu_lower, 2)
    upper = cc.body_state(cc.plane_strain_stress(-P, -P, 0.0, NU), E, NU, 2)
    eps_l, eps_u = lower["grad"][0, 0], upper["grad"][0, 0]
    length = np.hypot(WIDTH, Y_RIGHT - Y_LEFT)
    n = np.array([-(Y_RIGHT - Y_LEFT), WIDTH]) / length
    d = np.dot([0.0, Y_LEFT], n)
    upper["offset"] = np.array([0.0, -(eps_u - eps_l) * d / n[1]])
    return {"lower": lower, "upper": upper}


def self_test():
    # Straight 2D: u_y at the top = -(1 - nu^2) p 2/E; nu = 0 below: -p/E - (1 - nu^2) p/E.
    b = straight(2, NU)
    top = b["upper"]["grad"] @ [0.0, 2.0] + b["upper"]["offset"]
    assert abs(top[1] + 2 * (1 - NU**2) * P / E) < 1e-12 * P / E
    b = straight(2, 0.0)
    top = b["upper"]["grad"] @ [0.0, 2.0] + b["upper"]["offset"]
    assert abs(top[1] + P / E + (1 - NU**2) * P / E) < 1e-12 * P / E
    assert b["lower"]["grad"][0, 0] == 0.0
    # Sloped, nu = 0 below: the normal gap stays closed at both ends of the interface line.
    b = sloped(0.0)
    n = np.array([-0.2, 1.0]) / np.hypot(0.2, 1.0)
    for x in ([0.0, Y_LEFT], [WIDTH, Y_RIGHT]):
        jump = (b["upper"]["grad"] @ x + b["upper"]["offset"]) - (b["lower"]["grad"] @ x + b["lower"]["offset"])
        assert abs(np.dot(jump, n)) < 1e-12 * P / E, jump
    # 3D: eps_zz = -p/E, eps_xx = nu p/E.
    b = straight(3, NU)
    assert abs(b["lower"]["grad"][2, 2] + P / E) < 1e-25 and abs(b["lower"]["grad"][0, 0] - NU * P / E) < 1e-25
    print("contact_patch self-test: ok")


if __name__ == "__main__":
    if "--self-test" in sys.argv:
        self_test()
        sys.exit(0)
    failures = []
    failures += cc.check_uniform_case("straight_2d", straight(2, NU), "upper_bottom", P)
    failures += cc.check_uniform_case("straight_2d_nu0", straight(2, 0.0), "lower_top", P)
    failures += cc.check_uniform_case("straight_3d", straight(3, NU), "upper_bottom", P)
    failures += cc.check_uniform_case("sloped_2d", sloped(NU), "upper_bottom", P)
    failures += cc.check_uniform_case("sloped_2d_nu0", sloped(0.0), "upper_bottom", P)
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)
