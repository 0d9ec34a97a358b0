"""Frictional patch tests (docs/verification.md #3), 2D and 3D, mu = 0, 0.001, 0.01, 1, 10: every
step of every run equals the exact uniform-stress solution to 1e-8 (relative), on 1 and 2
ranks, and the two agree to 1e-10.

Reference (analytic, small-strain linear elasticity + Coulomb's law). Two stacked unit
blocks (2D: unit squares, plane strain; 3D: unit cubes), same material E = 2.069e11,
nu = 0.29, interface y = 1 (z = 1), slave = the upper block's bottom (outward normal -e_y).
The boundary data are those of a uniform stress
    sigma = -p e_n e_n + tau (e_t e_n + e_n e_t),     p = 1e8
(e_n the interface normal, tau the interface shear vector): the top carries (tau, -p) (or
the pressure p with a prescribed tangential displacement), the side faces carry the shear
traction (0, +-tau) of that stress, and the base is held at the exact displacement
u(base) = (eps_xx x, 0) [(eps_xx x, eps_yy y, 0) in 3D]. Then the exact solution is
    u = t (G X)             in the lower block,
    u = t (G X + c)         in the upper block (c tangential: the slip),
with G = eps + a rotation that keeps the base in its plane (friction_check.fixed_base_gradient):
    2D: G = [[nu (1 + nu) p/E, tau/G_s], [0, -(1 - nu^2) p/E]]      (G_s = E/(2 (1 + nu)))
    3D: G = [[nu p/E, 0, tau_x/G_s], [0, nu p/E, tau_y/G_s], [0, 0, -p/E]].
At every slave node lambda = (tau, -p) (the traction on the slave is -lambda),
contact_pressure = p, and Coulomb's law decides the status from the load ratio:
  STICK (traction controlled, tau = q, |q|/p = 0.5 < mu = 1, 10): c = 0, contact_status = 1,
    slip = 0, no tangential displacement jump across the interface; the base carries the
    tangential reaction |q| A.
  SLIP (displacement controlled: the top is moved by d = 1e-3 along e_s beyond eps_xx x, since
    a traction q > mu p has no static equilibrium): the no-slip state would need the shear
    G_s d/(h_lower + h_upper) = 0.401 p > mu p (mu = 0, 0.001, 0.01), so every node slips,
    tau = mu p e_s, c = (d - 2 mu p/G_s) e_s, contact_status = 2, slip_* = c, the tangential
    displacement jump = c, lambda_t . slip > 0 (friction opposes the slip), and the
    tangential reaction of the driven top = mu x the normal reaction (= p A) to 1e-8.
Literature: Mataix Ferrandiz, PhD thesis UPC 2020, §4.5.1.2 (Kratos
hyper_simple_*_patch_test family: no friction mu = 0, threshold slip 0.001, slip 0.01, stick
1.0, perfect stick 10); Hueber, Stadler & Wohlmuth, SIAM J. Sci. Comput. 30 (2008).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import friction_check as fc  # noqa: E402

E, NU, P = 2.069e11, 0.29, 1.0e8
Q_RATIO = 0.5  # stick runs: |q| = 0.5 p
DRIVE = 1.0e-3  # slip runs: tangential displacement of the top at t = 1
GS = fc.shear_modulus(E, NU)
DIR3 = np.array([0.6, 0.8])  # 3D load/slip direction (both tangent directions)


def stick(dim, mu):
    tau = Q_RATIO * P * (np.array([1.0]) if dim == 2 else DIR3)
    return fc.patch_case(dim, E, NU, P, tau, mu, fc.STICK)


def slip(dim, mu):
    e = np.array([1.0]) if dim == 2 else DIR3
    return fc.patch_case(dim, E, NU, P, mu * P * e, mu, fc.SLIP, shift=(DRIVE - 2 * mu * P / GS) * e,
                         drive=DRIVE * e)


RUNS = [("stick_mu1_2d", stick(2, 1.0)), ("stick_mu10_2d", stick(2, 10.0)),
        ("slip_mu0_2d", slip(2, 0.0)), ("slip_mu0001_2d", slip(2, 0.001)),
        ("slip_mu001_2d", slip(2, 0.01)),
        ("stick_mu1_3d", stick(3, 1.0)), ("slip_mu001_3d", slip(3, 0.01))]


def self_test():
    # Every run is set up so that the Coulomb prediction equals its intended status.
    for stem, case in RUNS:
        assert case["predicted"] == case["status"], stem
    # Stick: ratio 0.5; slip: G_s d/2/p = 0.401 > mu.
    assert abs(stick(2, 1.0)["ratio"] - 0.5) < 1e-15
    assert abs(slip(2, 0.01)["ratio"] - GS * DRIVE / 2 / P) < 1e-15 and slip(2, 0.01)["ratio"] > 0.4
    # Slip shift: d - 2 mu p/G_s = 1e-3 - 2.494e-5 for mu = 0.01; = d for mu = 0.
    assert abs(slip(2, 0.01)["shift"][0] - 9.7506e-4) < 1e-8, slip(2, 0.01)["shift"]
    assert slip(2, 0.0)["shift"][0] == DRIVE
    # The upper block's top moves by eps_xx x + d (the prescribed value of the YAML):
    # G [x, 2] + c = eps_xx x + 2 G_xy + c with 2 G_xy + c = d.
    c = slip(2, 0.01)
    assert abs(2 * c["G"][0, 1] + c["shift"][0] - DRIVE) < 1e-15
    c3 = slip(3, 0.01)
    assert np.abs(2 * c3["G"][:2, 2] + c3["shift"] - DRIVE * DIR3).max() < 1e-15
    # The base value of the YAML: eps_xx = 1.29*0.29*1e8/2.069e11 (2D), 0.29*1e8/2.069e11 (3D).
    assert abs(c["G"][0, 0] - 1.29 * 0.29 * 1.0e8 / 2.069e11) < 1e-19
    assert abs(c3["G"][0, 0] - 0.29 * 1.0e8 / 2.069e11) < 1e-19
    # lambda = (tau, -p): stick (5e7, -1e8); 3D slip (0.6e6, 0.8e6, -1e8).
    assert np.allclose(stick(2, 1.0)["lm"], [5e7, -1e8]) and np.allclose(c3["lm"], [6e5, 8e5, -1e8])
    print("friction_patch self-test: ok")


if __name__ == "__main__":
    if "--self-test" in sys.argv:
        self_test()
        sys.exit(0)
    only = [a for a in sys.argv[1:] if not a.startswith("-")]
    failures = []
    for stem, case in RUNS:
        if only and stem not in only:
            continue
        failures += fc.check_patch_case(stem, case)
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)
