"""Hertz contact of a sphere on a plane, 3D (docs/verification.md #11; Kratos validation/hertz),
on three meshes: the surface displacement of the sphere against Hertz within 1e-2 on the finest
mesh, the contact radius a and the peak pressure P_max converging with refinement; the load's
resultant; 1 and 2 ranks.

Usage: check.py [STEM ...] [--ranks STEM ...] [--tol 0.01]
  STEMs: np1/STEM.e from coarse to fine (default sphere_plane_1 _2 _3);
  --ranks: the STEMs also run on 2 ranks (np2/STEM.e), compared with 1 rank to 1e-10.

Reference: Johnson, Contact Mechanics (Cambridge 1985), section 4.2, eqs. (4.22)-(4.23), and
section 3.4, eqs. (3.41b), (3.42b): a sphere R = D/2 = 6.1237, E1 = 1e8, on a plane E2 = 2.1e11,
nu = 0.29 (k_i = (1 - nu^2)/E_i, 1/E* = k1 + k2), pressed by F = p pi R^2 = 5.8904e7 (p = 5e5
on its flat top):
    a = (3 F R / (4 E*))^(1/3) = 1.35340,   P_max = 3 F / (2 pi a^2) = 1.53546e7,
    p(r) = P_max sqrt(1 - r^2 / a^2);
the sphere's surface displacement (normal to the plane, into the sphere) is
    w1(r) = k1 pi P_max (2 a^2 - r^2) / (4 a)                                    r <= a,
    w1(r) = k1 P_max / (2 a) [(2 a^2 - r^2) asin(a / r) + a sqrt(r^2 - a^2)]     r >= a,
and the profile checked is the displacement relative to the contact centre,
    Delta(r) = w1(0) - w1(r)    (= k1 / (k1 + k2) r^2 / (2R) inside the contact).
The block's share of the compliance is k2 / (k1 + k2) = 4.8e-4, so its finite size
(1.5 R x 1.5 R x R, README.md) changes Delta by less than that.

Computed:
- Delta_FE(r) = u_z(apex) - u_z(r) over the sphere's contact-face nodes with r <= 2a
  (r = sqrt(x^2 + y^2) of the reference position); the error is
  max |Delta_FE - Delta| / Delta(2a), the profile's depth over that range;
- a and P_max: the least-squares fit of p^2 = P_max^2 (1 - r^2/a^2) to the slave nodes (the
  plane's top face) with p > 0 (nodal contact_pressure). The largest nodal pressure and the
  RMS of p - p_Hertz(r) over the slave nodes with r <= 1.2 a (relative to P_max) are printed.

Checks:
- the load: 4 x reaction_plane_bottom_nodes_z = F within 1e-3 (the flat top is a polygon
  of chords 0.2 long, whose area is (0.2/R)^2/6 = 1.8e-4 short of pi R^2 / 4);
- the finest mesh: the displacement error within --tol (1e-2, #11);
- the pressure converging (#11): for a and for P_max, the error against Hertz decreases from
  each mesh to the next, or else the computed values converge over the last three meshes,
  |q3 - q2| < |q2 - q1| (as ../sphere_sphere/check.py);
- 1 and 2 ranks: displacements and contact pressures agree to 1e-10 (--ranks).
Writes sphere_plane_profile.png (p and Delta against r on every mesh, with Hertz).
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402
from grout_results import Results  # noqa: E402

R, E1, E2, NU, P = 6.1237, 1.0e8, 2.1e11, 0.29, 5.0e5
F = P * math.pi * R ** 2
K1, K2 = (1 - NU ** 2) / E1, (1 - NU ** 2) / E2
E_STAR = 1.0 / (K1 + K2)
A_H = (3 * F * R / (4 * E_STAR)) ** (1.0 / 3.0)
P_H = 3 * F / (2 * math.pi * A_H ** 2)
SLAVE = "plane_top_nodes"
SPHERE = "sphere_contact_nodes"
REACTION = "reaction_plane_bottom_nodes_z"


def w1(r):
    """The sphere's surface displacement under the Hertz pressure (Johnson (3.41b), (3.42b))."""
    r = np.asarray(r, dtype=float)
    out = np.empty_like(r)
    inside = r <= A_H
    out[inside] = K1 * math.pi * P_H * (2 * A_H ** 2 - r[inside] ** 2) / (4 * A_H)
    ro = r[~inside]
    out[~inside] = K1 * P_H / (2 * A_H) * ((2 * A_H ** 2 - ro ** 2) * np.arcsin(A_H / ro)
                                           + A_H * np.sqrt(ro ** 2 - A_H ** 2))
    return out


def delta_hertz(r):
    return w1(np.zeros(1))[0] - w1(r)


def level(stem):
    """Fit, errors and the profiles of np1/STEM.e."""
    res = Results("np1/%s.e" % stem)
    xyz = res.coordinates()
    s = cc.node_set(res, SLAVE)
    r = np.hypot(xyz[0, s], xyz[1, s])
    p = res.nodal("contact_pressure")[s]
    on = p > 0
    c = np.linalg.lstsq(np.vstack([np.ones(on.sum()), r[on] ** 2]).T, p[on] ** 2, rcond=None)[0]
    a, p0 = math.sqrt(-c[0] / c[1]), math.sqrt(c[0])
    near = r <= 1.2 * A_H
    hertz = P_H * np.sqrt(np.clip(1 - (r[near] / A_H) ** 2, 0.0, None))
    b = cc.node_set(res, SPHERE)
    rb = np.hypot(xyz[0, b], xyz[1, b])
    uz = res.nodal("displ_z")[b]
    apex = int(np.argmin(rb))
    if rb[apex] > 1e-9:
        raise SystemExit("%s: no sphere node at the contact centre (r = %g)" % (stem, rb[apex]))
    keep = rb <= 2 * A_H
    d_fe = uz[apex] - uz[keep]
    d_h = delta_hertz(rb[keep])
    depth = delta_hertz(np.array([2 * A_H]))[0]
    worst = int(np.argmax(np.abs(d_fe - d_h)))
    return {"stem": stem, "a": a, "p": p0, "err_a": a / A_H - 1, "err_p": p0 / P_H - 1,
            "p_node": float(p.max()), "rms": float(np.sqrt(np.mean((p[near] - hertz) ** 2)) / P_H),
            "force": 4 * abs(res.global_var(REACTION)), "active": int(on.sum()), "r": r,
            "p_nodal": p, "err_u": float(abs(d_fe[worst] - d_h[worst]) / depth),
            "r_u": float(rb[keep][worst]), "rb": rb[keep], "d_fe": d_fe}


def shrinking(levels, q, failures):
    """The error of q falls from each level to the next, or else the values converge over
    the last three levels, |q3 - q2| < |q2 - q1|."""
    err = [abs(lv["err_" + q]) for lv in levels]
    val = [lv[q] for lv in levels]
    errors = ", ".join("%+.2f %%" % (100 * lv["err_" + q]) for lv in levels)
    if all(err[i] < err[i - 1] for i in range(1, len(levels))):
        print("%s: the error against Hertz shrinks (%s)" % (q, errors))
    elif len(levels) >= 3 and abs(val[-1] - val[-2]) < abs(val[-2] - val[-3]):
        print("%s: the error against Hertz does not shrink at every step (%s); the values "
              "converge: |q3 - q2| = %.3g < |q2 - q1| = %.3g"
              % (q, errors, abs(val[-1] - val[-2]), abs(val[-2] - val[-3])))
    else:
        failures.append("%s: neither does the error shrink (%s) nor do the values converge"
                        % (q, errors))


def plot(levels):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.5))
    rs = np.linspace(0, 2 * A_H, 300)
    ax.plot(rs, P_H * np.sqrt(np.clip(1 - (rs / A_H) ** 2, 0, None)), "k-", lw=1.5,
            label="Hertz: a = %.4f, P_max = %.4g" % (A_H, P_H))
    bx.plot(rs, delta_hertz(rs), "k-", lw=1.5, label="Hertz")
    for i, lv in enumerate(levels):
        keep = lv["r"] <= 1.5 * A_H
        ax.plot(lv["r"][keep], lv["p_nodal"][keep], ".", ms=3, color="C%d" % i,
                label="%s: a %+.2f %%, P_max %+.2f %% (fit)" % (lv["stem"], 100 * lv["err_a"],
                                                                 100 * lv["err_p"]))
        bx.plot(lv["rb"], lv["d_fe"], ".", ms=3, color="C%d" % i,
                label="%s: error %.2g" % (lv["stem"], lv["err_u"]))
    ax.set_xlabel("r")
    ax.set_ylabel("contact pressure (slave: the plane)")
    bx.set_xlabel("r")
    bx.set_ylabel("u_z(0) - u_z(r), sphere surface")
    ax.set_title("Hertz, sphere on a plane (D = 12.2474)")
    ax.legend(fontsize=7)
    bx.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig("sphere_plane_profile.png", dpi=110)
    plt.close(fig)
    print("wrote sphere_plane_profile.png")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("stems", nargs="*",
                    default=["sphere_plane_1", "sphere_plane_2", "sphere_plane_3"])
    ap.add_argument("--ranks", nargs="*", default=[])
    ap.add_argument("--tol", type=float, default=0.01)
    a = ap.parse_args()
    failures = []
    print("Hertz: F = %.6g, a = %.5f, P_max = %.6g, Delta(2a) = %.5f"
          % (F, A_H, P_H, delta_hertz(np.array([2 * A_H]))[0]))
    levels = [level(stem) for stem in a.stems]
    for lv in levels:
        print("%s: %d slave nodes in contact; a = %.5f (%+.2f %%), P_max = %.5g (%+.2f %%) "
              "(fit); largest nodal pressure %.5g (%+.2f %%); profile RMS %.2f %% of P_max; "
              "displacement error %.2e (at r = %.3f); load 4 R_z = %.6g (%+.1e)"
              % (lv["stem"], lv["active"], lv["a"], 100 * lv["err_a"], lv["p"], 100 * lv["err_p"],
                 lv["p_node"], 100 * (lv["p_node"] / P_H - 1), 100 * lv["rms"], lv["err_u"],
                 lv["r_u"], lv["force"], lv["force"] / F - 1))
        if not abs(lv["force"] / F - 1) <= 1e-3:
            failures.append("%s: load %.6g, expected F = %.6g within 1e-3"
                            % (lv["stem"], lv["force"], F))
    fine = levels[-1]
    if not fine["err_u"] <= a.tol:
        failures.append("%s: displacement error %.2e > %.0e" % (fine["stem"], fine["err_u"], a.tol))
    for q in ("a", "p"):
        shrinking(levels, q, failures)
    for stem in a.ranks:
        diff, msg = cc.compare_ranks("np1/%s.e" % stem, "np2/%s.e" % stem,
                                     ["displ_x", "displ_y", "displ_z", "contact_pressure"])
        print("%s: 1 vs 2 ranks %.1e" % (stem, diff))
        if msg:
            failures.append(msg)
    plot(levels)
    for f in failures:
        print("FAIL:", f)
    if not failures:
        print("sphere_plane: all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
