"""Hertz contact of a sphere on a rigid plane, axisymmetric, frictionless (docs/verification.md
#10, sphere part), on three nested meshes (hertz_sphere_1..3):

- contact radius a (from the nodal pressures, contact_check.half_width_one_side) and peak
  pressure p0 against Hertz, the finest mesh within 2 %, each error below the previous
  level's (docs/verification.md #10: "errors shrinking"; computed values that merely converge
  do not pass);
- the sphere's surface displacement relative to the contact point, u_z(r) - u_z(0) on the
  sphere's contact side set for r <= 2a, against Hertz's w(r) - w(0): max error relative to
  |w(2a) - w(0)| within 2 % on the finest mesh and below the previous level's on each level;
- equilibrium: |reaction_plane_y| = F (reactions are totals over the full circle);
- 1 and 2 ranks agree to 1e-10.
The plane is the slave (contact_pressure on plane_top), the sphere the master.
Writes hertz_sphere_profile.csv (pressure), hertz_sphere_displacement.csv,
hertz_sphere_convergence.csv and hertz_sphere.png.

Reference: Johnson, Contact Mechanics (1985), §3.4 and §4.2 (eqs. 3.41-3.42, 4.22-4.24), a
rigid flat second body: E* = E/(1 - nu^2), F = 5e5 pi R^2 (the benchmark's pressure 5e5 on the
hemisphere's flat face, R = 6.1237, E = 1e8, nu = 0.29):
    a^3 = 3 F R / (4 E*) -> a = 1.35318,   p0 = 3 F / (2 pi a^2) = 1.53594e7,
    w(r) = pi p0 (2a^2 - r^2) / (4 a E*)                                   (r <= a),
    w(r) = p0 [(2a^2 - r^2) asin(a/r) + a sqrt(r^2 - a^2)] / (2 a E*)     (r > a),
so that w(r) - w(0) = -r^2/(2R) inside the contact (the curve of the Kratos benchmark). The
benchmark's script puts (1 - nu^2) twice into a (a = 1.31413); the textbook value is used.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402
from grout_results import Results  # noqa: E402

R, E, NU, LOAD = 6.1237, 1.0e8, 0.29, 5.0e5
F = LOAD * math.pi * R**2
E_STAR = E / (1 - NU**2)
A_H = (3 * F * R / (4 * E_STAR)) ** (1.0 / 3.0)
P0_H = 3 * F / (2 * math.pi * A_H**2)
TOL = 0.02
STEMS = ["hertz_sphere_1", "hertz_sphere_2", "hertz_sphere_3"]


def hertz_w(r):
    """Hertz surface displacement w(r) (positive into the sphere)."""
    r = np.asarray(r, dtype=float)
    inside = math.pi * P0_H * (2 * A_H**2 - r**2) / (4 * A_H * E_STAR)
    ro = np.maximum(r, A_H)
    outside = P0_H * ((2 * A_H**2 - ro**2) * np.arcsin(A_H / ro)
                      + A_H * np.sqrt(ro**2 - A_H**2)) / (2 * A_H * E_STAR)
    return np.where(r <= A_H, inside, outside)


def level(stem):
    r = Results("np1/%s.e" % stem)
    s = cc.side_set_nodes(r, "plane_top")  # the slave: contact_pressure lives here
    xp = r.coordinates()[0, s]
    o = np.argsort(xp)
    xp, p = xp[o], r.nodal("contact_pressure")[s][o]
    s = cc.side_set_nodes(r, "sphere_contact")
    x = r.coordinates()[0, s]
    o = np.argsort(x)
    x, uz = x[o], r.nodal("displ_y")[s][o]
    a = cc.half_width_one_side(xp, p)
    near = xp <= 1.2 * A_H
    rms = float(np.sqrt(np.mean((p[near] - cc.hertz_pressure(xp[near], A_H, P0_H)) ** 2)) / P0_H)
    du = uz - uz[0]  # x[0] = 0: the node on the axis
    dw = hertz_w(x) - hertz_w(0.0)
    band = x <= 2 * A_H
    err_w = float(np.abs(du[band] - dw[band]).max() / abs(hertz_w(2 * A_H) - hertz_w(0.0)))
    return {"x": x, "du": du, "xp": xp, "p": p, "b": a, "p_max": float(p.max()),
            "err_b": abs(a - A_H) / A_H, "err_p": abs(p.max() - P0_H) / P0_H, "err_rms": rms,
            "err_w": err_w, "x0": min(x[0], xp[0])}


def plot(levels, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    rs = np.linspace(0.0, 2 * A_H, 400)
    ax1.plot(rs, cc.hertz_pressure(rs, A_H, P0_H), "k-", lw=1.5, label="Hertz")
    ax2.plot(rs, hertz_w(rs) - hertz_w(0.0), "k-", lw=1.5, label="Hertz")
    for i, lv in enumerate(levels, start=1):
        keep, keep_p = lv["x"] <= 2 * A_H, lv["xp"] <= 2 * A_H
        ax1.plot(lv["xp"][keep_p], lv["p"][keep_p], "o-", ms=3, lw=0.8,
                 label="level %d (a err %.1f %%, p0 err %.1f %%)"
                 % (i, 100 * lv["err_b"], 100 * lv["err_p"]))
        ax2.plot(lv["x"][keep], lv["du"][keep], "o-", ms=3, lw=0.8,
                 label="level %d (err %.2f %%)" % (i, 100 * lv["err_w"]))
    ax1.set_xlabel("r")
    ax1.set_ylabel("contact pressure")
    ax2.set_xlabel("r")
    ax2.set_ylabel("u_z(r) - u_z(0) on the sphere")
    fig.suptitle("Hertz sphere on a rigid plane, axisymmetric (R = 6.1237, F = 5.89e7)")
    for ax in (ax1, ax2):
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    print("wrote", path)


def main():
    failures, levels = [], []
    for stem in STEMS:
        lv = level(stem)
        levels.append(lv)
        if lv["x0"] != 0.0:
            failures.append("%s: the first contact node is not on the axis (r = %g)" % (stem, lv["x0"]))
        diff, msg = cc.compare_ranks("np1/%s.e" % stem, "np2/%s.e" % stem,
                                     ["displ_x", "displ_y", "contact_pressure"])
        if msg:
            failures.append(msg)
        force = abs(Results("np1/%s.e" % stem).global_var("reaction_plane_y"))
        print("%s: a = %.5f (err %.2f %%), p0 = %.5g (err %.2f %%), profile RMS %.2f %%, "
              "surface displacement err %.2f %%, |reaction_plane_y| = %.6g, 1 vs 2 ranks %.1e"
              % (stem, lv["b"], 100 * lv["err_b"], lv["p_max"], 100 * lv["err_p"],
                 100 * lv["err_rms"], 100 * lv["err_w"], force, diff))
        if not abs(force - F) <= 1e-6 * F:
            failures.append("%s: |reaction_plane_y| = %.8g, expected F = %.8g" % (stem, force, F))
    print("Hertz: a = %.5f, p0 = %.6g, F = %.6g" % (A_H, P0_H, F))
    failures += cc.assess_convergence(levels, TOL, self_convergence=())
    w = [lv["err_w"] for lv in levels]
    if not w[-1] <= TOL:
        failures.append("finest mesh: surface displacement error %.2f %% > 2 %%" % (100 * w[-1]))
    for key, name in (("err_b", "contact radius"), ("err_p", "peak pressure"),
                      ("err_w", "surface displacement")):
        e = [lv[key] for lv in levels]
        if not all(fine < coarse for coarse, fine in zip(e, e[1:])):
            failures.append("%s error does not shrink from level to level: %s"
                            % (name, ", ".join("%.2f %%" % (100 * v) for v in e)))
    fine = levels[-1]
    with open("hertz_sphere_profile.csv", "w") as f:
        f.write("r_plane,p_computed,p_hertz\n")
        for xi, pi in zip(fine["xp"], fine["p"]):
            f.write("%.10g,%.10g,%.10g\n" % (xi, pi, cc.hertz_pressure(xi, A_H, P0_H)))
    with open("hertz_sphere_displacement.csv", "w") as f:
        f.write("r_sphere,duz_computed,duz_hertz\n")
        for xi, di in zip(fine["x"], fine["du"]):
            f.write("%.10g,%.10g,%.10g\n" % (xi, di, hertz_w(xi) - hertz_w(0.0)))
    with open("hertz_sphere_convergence.csv", "w") as f:
        f.write("level,a,err_a,p0,err_p0,err_rms,err_surface_displacement\n")
        for i, lv in enumerate(levels, start=1):
            f.write("%d,%.8g,%.4e,%.8g,%.4e,%.4e,%.4e\n" % (i, lv["b"], lv["err_b"], lv["p_max"],
                                                           lv["err_p"], lv["err_rms"], lv["err_w"]))
    plot(levels, "hertz_sphere.png")
    return failures


if __name__ == "__main__":
    fails = main()
    for f in fails:
        print("FAIL:", f)
    sys.exit(1 if fails else 0)
