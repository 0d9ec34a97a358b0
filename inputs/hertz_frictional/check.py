"""Hertz contact of two cylinders with Coulomb friction, Cattaneo-Mindlin (docs/verification.md #9),
on three nested meshes: the stick-zone half-width c and the tangential traction profile
against the analytic solution, errors decreasing with refinement, the finest within 5 %;
the normal traction against Hertz (finest within 5 %); the local Coulomb law at slip nodes;
equilibrium (the pin and roller carry no force); 1 and 2 ranks agree to 1e-10. Writes
hertz_frictional_profile.csv (finest mesh), hertz_frictional_convergence.csv and
hertz_frictional_profile.png (normal and tangential traction, all levels, vs analytic).

Reference. Johnson, Contact Mechanics (1985), §4.2 (Hertz, two cylinders) and §7.1
(Cattaneo 1938, Mindlin 1949: tangential loading of a line contact below the limit of
friction); the same formulas are thesis eqs. (4.86), (4.87) (Mataix Ferrandiz 2020,
§4.5.4.1.2.2). Two cylinders R1 = R2 = R = 8, E = 200, nu = 0.3 (elastically identical, so
the normal and tangential problems uncouple), normal load P = 2Rp = 10 per unit length
(p = 0.625 on a diameter), then a monotonically increasing tangential load Q = 2Rq with
q = 0.05851, i.e. Q = 0.93616 < mu P = 2 (mu = 0.2): the benchmark's q is a traction on the same
face as p, so Q/(mu P) = q/(mu p) = 0.46808 either way.
    b = sqrt(4 P R*/(pi E*)) = 0.6808,  p0 = 2P/(pi b) = 9.351   (R* = R/2, E* = E/(2(1-nu^2)))
    p_n(x) = p0 sqrt(1 - x^2/b^2)
    c = b sqrt(1 - Q/(mu P)) = 0.4965
    p_t(x) = mu p0/b (sqrt(b^2 - x^2) - sqrt(c^2 - x^2))   |x| <= c   (stick)
           = mu p0/b  sqrt(b^2 - x^2)                      c < |x| <= b (slip: p_t = mu p_n)
It integrates to Q. The runs use `geometry: current`: the analytic solution refers to the
deformed contact interface, which is flat (y = 0) for identical bodies; with reference
(undeformed) normals the Coulomb cone at a node is tilted by x/R (up to b/R = 0.085 rad at
the contact edge, i.e. ~0.4 mu), an O(b/(mu R)) modelling error that does not vanish with
refinement (about 10 % RMS in p_t here).

Computed quantities (final step), slave nodes sorted by x:
  - normal traction: contact_pressure; b from the Hertz edge behaviour
    (contact_check.half_width), p_max = its largest value;
  - tangential traction: the shear on the (flat, y = 0) interface = the x component of the
    traction. The traction on the slave is -lambda (docs/design.md §2) and Q pushes the slave
    (upper) body in +x, so friction acts on it in -x: -lm_x < 0, i.e. p_t = +lm_x. The
    profile is compared sign-robustly (p_t = s lm_x with s the sign of the sum of lm_x over
    the contact), and s = +1 is checked separately, so a sign-convention change shows up as
    one explicit failure instead of a wrong-profile failure;
  - stick zone: contact_status = 1 (stick) nodes must form one interval around x = 0 with
    slip (2) nodes between it and the open (0) nodes; c is located between the last stick
    and the first slip node on each side with the Mindlin edge behaviour
    defect = mu lambda_n - |lambda_tau| ~ sqrt(c - |x|) (friction_check.stick_half_width),
    lambda_tau along the nodal tangent of the deformed slave surface (the solver's frame for
    geometry: current), where at slip nodes |lambda_tau| = mu lambda_n is checked to 1e-8 p0;
  - errors: |c_h - c|/c, RMS over |x| <= b of (p_t - p_t,analytic)/(mu p0), |b_h - b|/b,
    |p_max - p0|/p0.
Pass: finest err_c <= 5 %, RMS p_t <= 5 %, err_b and err_p <= 5 %; err_c and the RMS of the
finest below the coarsest (or both <= 1 %); pin/roller reactions <= 1e-2 Q (the loads are
self-equilibrated; the remainder is the small-strain-solid / current-geometry-contact
mismatch).
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402
import friction_check as fc  # noqa: E402

R, E, NU, LOAD, Q_LOAD, MU = 8.0, 200.0, 0.3, 0.625, 0.05851, 0.2
P, Q = 2 * R * LOAD, 2 * R * Q_LOAD
B, P0 = cc.hertz_line_contact(P, R, R, E, NU, E, NU)
C = fc.mindlin_stick_half_width(B, Q, MU, P)
STEMS = ["hertz_frictional_1", "hertz_frictional_2", "hertz_frictional_3"]
SLAVE = "upper_contact"
TOL, FLOOR = 0.05, 0.01
SUPPORTS = ["reaction_lower_bottom_centre_x", "reaction_lower_bottom_centre_y", "reaction_lower_bottom_end_y"]


def level_data(path):
    from grout_results import Results
    r = Results(path)
    s = cc.side_set_nodes(r, SLAVE)
    xyz = r.coordinates()
    o = np.argsort(xyz[0, s])
    s = s[o]
    x, y = xyz[0, s], xyz[1, s]
    u = np.array([r.nodal("displ_x")[s], r.nodal("displ_y")[s]])
    lm = np.array([r.nodal("lm_x")[s], r.nodal("lm_y")[s]])
    return {"x": x, "y": y, "u": u, "lm": lm, "cp": r.nodal("contact_pressure")[s],
            "status": r.nodal("contact_status")[s].astype(int),
            "supports": {g: r.global_var(g) for g in SUPPORTS if g in r.global_names}}


def analyse(d, b=B, p0=P0, c=C, mu=MU):
    """Errors and failures of one level (dict of level_data)."""
    failures = []
    x, lm, cp, st = d["x"], d["lm"], d["cp"], d["status"]
    n = fc.arc_normals(x + d["u"][0], d["y"] + d["u"][1], -1.0)  # deformed surface (current)
    lam_n = np.sum(lm * n, axis=0)
    tau = np.array([-n[1], n[0]])
    lam_tau = np.sum(lm * tau, axis=0)
    active = st > 0
    out = {"lam_n_vs_cp": float(np.abs(lam_n[active] - cp[active]).max(initial=0.0) / p0)}
    if out["lam_n_vs_cp"] > 1e-6:
        failures.append("n.lm differs from contact_pressure by %.2e p0 (normals or conventions differ)"
                        % out["lam_n_vs_cp"])
    slip = st == fc.SLIP
    out["coulomb"] = float(np.abs(np.abs(lam_tau[slip]) - mu * cp[slip]).max(initial=0.0) / p0)
    if out["coulomb"] > 1e-8:
        failures.append("slip nodes: | |lambda_tau| - mu lambda_n | = %.2e p0 > 1e-8" % out["coulomb"])
    # Sign-robust tangential traction, plus the convention check.
    sign = 1.0 if np.sum(lm[0][active]) >= 0 else -1.0
    out["sign"] = sign
    if sign < 0:
        failures.append("lm_x < 0 over the contact: the traction on the slave (-lambda) does not oppose Q "
                        "(docs/design.md §2 convention)")
    pt = sign * lm[0]
    # Stick zone: one interval around 0, slip between stick and open.
    stick_x = x[st == fc.STICK]
    if stick_x.size == 0:
        failures.append("no stick node")
        return out, failures, pt
    inside = (x >= stick_x.min()) & (x <= stick_x.max())
    if not np.all(st[inside] == fc.STICK) or not (stick_x.min() < 0 < stick_x.max()):
        failures.append("stick nodes do not form one interval around x = 0: %s" % st[np.abs(x) < 1.2 * b].tolist())
    act_x = x[active]
    between = active & ~inside
    if not np.all(st[between] == fc.SLIP) or not np.all(st[(x > act_x.min()) & (x < act_x.max())] > 0):
        failures.append("slip nodes are not between the stick zone and the open nodes")
    out["c"] = fc.stick_half_width(x, st, mu * cp - np.abs(lam_tau))
    out["err_c"] = abs(out["c"] - c) / c
    near = np.abs(x) <= b
    out["rms_t"] = float(np.sqrt(np.mean((pt[near] - fc.mindlin_traction(x[near], b, c, mu, p0)) ** 2)) / (mu * p0))
    out["b"] = cc.half_width(x, cp)
    out["err_b"] = abs(out["b"] - b) / b
    out["p_max"] = float(cp.max())
    out["err_p"] = abs(out["p_max"] - p0) / p0
    out["Q_nodal"] = float(np.trapz(pt, x))  # nodal-quadrature estimate of Q (reported only)
    for g, v in d["supports"].items():
        if abs(v) > 1e-2 * Q:
            failures.append("support %s = %.3g carries force (> 1e-2 Q)" % (g, v))
    return out, failures, pt


def assess(levels, tol=TOL, floor=FLOOR):
    failures = []
    fine, coarse = levels[-1], levels[0]
    for key in ("err_c", "rms_t", "err_b", "err_p"):
        if not fine.get(key, 1.0) <= tol:
            failures.append("finest mesh: %s = %.2f %% > %.0f %%" % (key, 100 * fine.get(key, 1.0), 100 * tol))
    for key in ("err_c", "rms_t"):
        if key in fine and key in coarse and not (fine[key] < coarse[key] or max(fine[key], coarse[key]) <= floor):
            failures.append("%s does not decrease with refinement: %s" % (key, [lv.get(key) for lv in levels]))
    return failures


def write_outputs(levels, profiles, prefix="hertz_frictional"):
    d, pt = profiles[-1]
    with open(prefix + "_profile.csv", "w") as f:
        f.write("x,status,p_n,p_n_hertz,p_t,p_t_mindlin\n")
        for xi, si, pn, ti in zip(d["x"], d["status"], d["cp"], pt):
            f.write("%.10g,%d,%.10g,%.10g,%.10g,%.10g\n" % (xi, si, pn, cc.hertz_pressure(xi, B, P0), ti,
                                                             fc.mindlin_traction(xi, B, C, MU, P0)))
    with open(prefix + "_convergence.csv", "w") as f:
        f.write("level,b,err_b,p_max,err_p,c,err_c,rms_t\n")
        for i, lv in enumerate(levels, start=1):
            f.write("%d,%.8g,%.4e,%.8g,%.4e,%.8g,%.4e,%.4e\n" % (i, lv.get("b", np.nan), lv.get("err_b", np.nan),
                                                                lv.get("p_max", np.nan), lv.get("err_p", np.nan),
                                                                lv.get("c", np.nan), lv.get("err_c", np.nan),
                                                                lv.get("rms_t", np.nan)))
    print("wrote %s_profile.csv, %s_convergence.csv" % (prefix, prefix))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(7, 8), sharex=True)
    xs = np.linspace(-1.4 * B, 1.4 * B, 801)
    a1.plot(xs, cc.hertz_pressure(xs, B, P0), "k-", lw=1.5, label="Hertz")
    a2.plot(xs, fc.mindlin_traction(xs, B, C, MU, P0), "k-", lw=1.5, label="Cattaneo-Mindlin")
    a2.plot(xs, MU * cc.hertz_pressure(xs, B, P0), "k:", lw=1, label="mu p_n (Coulomb limit)")
    for i, ((d, pt), lv) in enumerate(zip(profiles, levels), start=1):
        keep = np.abs(d["x"]) <= 1.4 * B
        a1.plot(d["x"][keep], d["cp"][keep], "o-", ms=3, lw=0.8,
                label="level %d (b err %.1f %%)" % (i, 100 * lv.get("err_b", np.nan)))
        a2.plot(d["x"][keep], pt[keep], "o-", ms=3, lw=0.8,
                label="level %d (c err %.1f %%, RMS %.1f %%)" % (i, 100 * lv.get("err_c", np.nan),
                                                              100 * lv.get("rms_t", np.nan)))
    for a in (a1, a2):
        for v in (-C, C):
            a.axvline(v, color="grey", ls="--", lw=0.6)
        a.legend(fontsize=7)
    a1.set_ylabel("normal traction p_n")
    a2.set_ylabel("tangential traction p_t")
    a2.set_xlabel("x   (dashed: stick-zone edges +-c)")
    a1.set_title("Frictional Hertz (Cattaneo-Mindlin), Q/(mu P) = %.4f: c = %.4f, b = %.4f" % (Q / (MU * P), C, B),
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(prefix + "_profile.png", dpi=120)
    plt.close(fig)
    print("wrote", prefix + "_profile.png")


def synthetic_level(level, n=81, width=1.2):
    """Analytic tractions on nodes of spacing ~ b/(6 2^(level-1)) with errors that shrink."""
    h = B / 6 / 2 ** (level - 1)
    x = np.arange(-width // h, width // h + 1) * h
    th = np.arcsin(np.clip(x / R, -1, 1))
    y = R - R * np.cos(th)
    bb, cc_ = B * (1 + 0.04 / 2 ** level), C * (1 - 0.05 / 2 ** level)
    cp = cc.hertz_pressure(x, bb, P0)
    pt = fc.mindlin_traction(x, bb, cc_, MU, P0)
    st = np.where(cp <= 0, 0, np.where(np.abs(x) < cc_, 1, 2))
    u = np.zeros((2, x.size))
    u[1] = np.where(np.abs(x) <= bb, -y, -y + (x * x - bb * bb) / (2 * R))  # deformed: flat contact
    nrm = fc.arc_normals(x + u[0], y + u[1], -1.0)
    tau = np.array([-nrm[1], nrm[0]])
    lm = cp * nrm + pt * tau
    return {"x": x, "y": y, "u": u, "lm": lm, "cp": cp, "status": st, "supports": {}}


def self_test():
    assert abs(P - 10) < 1e-14 and abs(Q - 0.93616) < 1e-12
    assert abs(B - 0.6808) < 5e-5 and abs(P0 - 9.351) < 5e-4
    assert abs(C - 0.49651) < 1e-4 and abs(Q / (MU * P) - Q_LOAD / (MU * LOAD)) < 1e-15
    # Moment balance of the tangential load in the YAMLs: the vertical traction k x on the
    # face |x| <= R with k = 0.375 q = 3q/R has moment 2R^3/3 k = 2 R^2 q = Q R.
    assert abs(2 * R**3 / 3 * 0.375 * Q_LOAD - Q * R) < 1e-12 and abs(0.375 - 3 / R) < 1e-15
    # The analysis recovers synthetic profiles and judges convergence.
    levels = []
    for level in (1, 2, 3):
        out, f, _ = analyse(synthetic_level(level))
        assert not f, f
        levels.append(out)
    assert not assess(levels), assess(levels)
    assert levels[-1]["err_c"] < levels[0]["err_c"]
    # A flipped sign is one explicit failure; an excessive error fails the tolerance.
    d = synthetic_level(3)
    d["lm"] = d["lm"] * np.array([[-1.0], [1.0]])
    f = analyse(d)[1]
    assert any("oppose" in m for m in f), f
    bad = dict(levels[-1], rms_t=0.08)
    assert any("rms_t" in m for m in assess(levels[:2] + [bad]))
    print("hertz_frictional self-test: ok (b = %.5f, p0 = %.4f, c = %.5f, Q = %.5f, mu P = %g)" % (B, P0, C, Q, MU * P))


if __name__ == "__main__":
    if "--self-test" in sys.argv:
        self_test()
        sys.exit(0)
    failures, levels, profiles = [], [], []
    print("Cattaneo-Mindlin: b = %.5f, p0 = %.5f, c = %.5f (c/b = %.4f), Q = %.5f, mu P = %g"
          % (B, P0, C, C / B, Q, MU * P))
    for stem in STEMS:
        d = level_data("np1/%s.e" % stem)
        out, f, pt = analyse(d)
        failures += ["%s: %s" % (stem, m) for m in f]
        levels.append(out)
        profiles.append((d, pt))
        diff, msg = cc.compare_ranks("np1/%s.e" % stem, "np2/%s.e" % stem,
                                     ["displ_x", "displ_y", "lm_x", "lm_y", "contact_status"])
        if msg:
            failures.append(msg)
        print("%-20s c = %.5f (err %.2f %%), p_t RMS %.2f %%, b = %.5f (err %.2f %%), p_max = %.5g (err %.2f %%), "
              "Q(nodal) = %.4f, |n.lm - cp| %.1e, Coulomb %.1e, 1 vs 2 ranks %.1e, Newton %s"
              % (stem, out.get("c", np.nan), 100 * out.get("err_c", np.nan), 100 * out.get("rms_t", np.nan),
                 out.get("b", np.nan), 100 * out.get("err_b", np.nan), out.get("p_max", np.nan),
                 100 * out.get("err_p", np.nan), out.get("Q_nodal", np.nan), out["lam_n_vs_cp"], out["coulomb"],
                 diff, fc.newton_per_step("np1/%s.e" % stem)))
    failures += assess(levels)
    write_outputs(levels, profiles)
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)
