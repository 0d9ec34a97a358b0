"""Frictional self-contact (friction_*.yaml; docs/verification.md, self-contact patch test):
the slit strip of check.py, folded onto itself along the cut y = 1, under the boundary data of
the uniform stress sigma = -p e_y e_y + tau (e_x e_y + e_y e_x), p = 1e8, tau = 0.5 p.

- Stick (mu = 1 > tau/p; friction_stick_2d, friction_stick_3d): the uniform field is the exact
  solution, with the displacement u = G X, G = [[eps_xx, tau/G_s], [0, eps_yy]] (plus eps_zz z
  in 3D; the bottom is held at u = (eps_xx x, 0), which fixes the rotation), continuous across
  the cut. The slave flank (the lower one: docs/input.md "Self-contact") carries
  lm = -(sigma e_y) = (-tau, p), contact_pressure = p, contact_status = 1 (stick) and no slip.
  Checked to 1e-8 relative: displacements, element stresses, contact_pressure, lm_x, lm_y,
  slip; every slave node sticks.
- Slip (mu = 0.2 < tau/p; friction_slip_2d): the flanks cannot carry tau, so the upper arm
  slides on the lower one and bends (no closed form). Coulomb's law is the reference: every
  active slave node slips (contact_status 2), with |lm_x| = mu lm_n to 1e-8 and the friction
  force against the slip (lm_x and slip_x of the same sign: the slave's friction traction -lm
  opposes its slip), and the contact's shear is mu times its normal force, less than tau's.
- 1 and 2 ranks agree to 1e-10 (stick) and 1e-8 (slip).
E = 2.069e11, nu = 0.29.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402
from grout_results import Results  # noqa: E402

P, TAU, E, NU = 1.0e8, 0.5e8, 2.069e11, 0.29
G_S = E / (2.0 * (1.0 + NU))  # shear modulus


def exact(dim):
    """(stress 3x3, displacement gradient dim x dim) of the uniform state."""
    sigma = np.zeros((3, 3))
    sigma[1, 1] = -P
    sigma[0, 1] = sigma[1, 0] = TAU
    if dim == 2:
        sigma[2, 2] = -NU * P  # plane strain
    eps = cc.strain_3d(sigma, E, NU)
    grad = np.diag(np.diag(eps)[:dim])
    grad[0, 1] = TAU / G_S  # u_y independent of x (the bottom is held in y)
    return sigma, grad


def check_stick(path, dim, tol=1e-8):
    r = Results(path)
    if r.times().size == 0:
        return ["%s: no converged step" % path]
    sigma, grad = exact(dim)
    x = r.coordinates()
    u = np.array([r.nodal("displ_" + "xyz"[d]) for d in range(dim)])
    u_exact = grad @ x
    u_scale = np.abs(u_exact).max()
    err = {"displacement": np.abs(u - u_exact).max() / u_scale, "stress": 0.0}
    for key, value in cc.stress_names(sigma, dim).items():
        err["stress"] = max(err["stress"], np.abs(r.element(key) - value).max() / P)
    slave = cc.node_set(r, "lower_flank_nodes")
    err["contact_pressure"] = np.abs(r.nodal("contact_pressure")[slave] - P).max() / P
    err["lm_x"] = np.abs(r.nodal("lm_x")[slave] + TAU).max() / P
    err["lm_y"] = np.abs(r.nodal("lm_y")[slave] - P).max() / P
    slip = max(np.abs(r.nodal("slip_" + "xyz"[d])[slave]).max() for d in range(dim))
    err["slip"] = slip / u_scale
    others = np.setdiff1d(np.arange(x.shape[1]), slave)
    err["pressure_elsewhere"] = np.abs(r.nodal("contact_pressure")[others]).max() / P
    status = r.nodal("contact_status")[slave]
    failures = ["%s: %s error %.2e > %g" % (path, k, v, tol)
                for k, v in err.items() if not v <= tol]
    if not np.all(status == 1):
        failures.append("%s: %d of %d slave nodes do not stick (contact_status != 1)"
                        % (path, int(np.sum(status != 1)), status.size))
    print("%-30s stick: " % path + ", ".join("%s %.2e" % kv for kv in err.items()))
    return failures


def check_slip(path, mu, tol=1e-8):
    r = Results(path)
    if r.times().size == 0 or abs(r.times()[-1] - 1.0) > 1e-12:
        return ["%s: did not reach t = 1" % path]
    slave = cc.node_set(r, "lower_flank_nodes")
    status = r.nodal("contact_status")[slave]
    lm_x, lm_n = r.nodal("lm_x")[slave], r.nodal("contact_pressure")[slave]
    slip_x = r.nodal("slip_x")[slave]
    active = status > 0
    failures = []
    if not np.all(status[active] == 2) or active.sum() == 0:
        failures.append("%s: %d active slave nodes, %d of them not slipping"
                        % (path, int(active.sum()), int(np.sum(status[active] != 2))))
    coulomb = np.abs(np.abs(lm_x) - mu * lm_n)[active].max() / P
    against = bool(np.all(lm_x[active] * slip_x[active] > 0.0))
    if not coulomb <= tol:
        failures.append("%s: |lm_x| - mu lm_n up to %.2e p (> %g)" % (path, coulomb, tol))
    if not against:
        failures.append("%s: friction not against the slip at some node" % path)
    ratio = np.abs(lm_x[active]).sum() / lm_n[active].sum()
    print("%-30s slip: %d active nodes, all slipping; ||lm_t| - mu lm_n| <= %.2e p, "
          "shear/normal %.6f (mu = %g, tau/p = %g), max slip_x %.3e"
          % (path, int(active.sum()), coulomb, ratio, mu, TAU / P, np.abs(slip_x).max()))
    return failures


if __name__ == "__main__":
    failures = []
    for np_ in (1, 2):
        failures += check_stick("np%d/friction_stick_2d.e" % np_, 2)
        failures += check_stick("np%d/friction_stick_3d.e" % np_, 3)
        failures += check_slip("np%d/friction_slip_2d.e" % np_, 0.2)
    for stem, dim, tol in (("friction_stick_2d", 2, 1e-10), ("friction_stick_3d", 3, 1e-10),
                           ("friction_slip_2d", 2, 1e-8)):
        fields = ["displ_" + "xyz"[d] for d in range(dim)] + ["contact_pressure"]
        diff, msg = cc.compare_ranks("np1/%s.e" % stem, "np2/%s.e" % stem, fields, tol)
        print("%-30s 1 vs 2 ranks: %.2e" % (stem, diff))
        failures += [msg] if msg else []
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)
