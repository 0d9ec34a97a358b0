"""Shared helpers of the contact case checks (contact_patch, taylor_patch, collocation_study,
hertz_cylinders, hertz_plane, mesh_tying): mesh sets from the Exodus results, uniform-stress
elasticity, the Hertz line-contact solution, and the 1-vs-2-rank comparison.

Import from a check.py with
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
    import contact_check as cc

Run `python3 contact_check.py` to self-test the formulas on known numbers.
"""
import csv
import math

import netCDF4
import numpy as np

from grout_results import Results, relative_difference


def _names(ds, var):
    if var not in ds.variables:
        return []
    return [str(s).strip() for s in netCDF4.chartostring(ds.variables[var][:])]


def node_set(results, name):
    """0-based node indices of the Exodus node set `name` (the results file carries the mesh's
    sets)."""
    names = _names(results.ds, "ns_names")
    if name not in names and name + "_nodes" in names:
        # grout_mesh names the node set of side set X `X_nodes` (since 33bff00; it was X
        # before): scripts written against the old name, such as
        # ../shared/anchors/getfem/summarize.py, still find it.
        name = name + "_nodes"
    if name not in names:
        raise KeyError("%s: no node set '%s' (has %s)" % (results.path, name, names))
    return np.array(results.ds.variables["node_ns%d" % (names.index(name) + 1)][:]) - 1


def side_set_nodes(results, side_set):
    """0-based node indices of side set `side_set`: grout_mesh writes them as the node set
    `<side_set>_nodes`."""
    return node_set(results, side_set + "_nodes")


def block_names(results):
    return _names(results.ds, "eb_names")


def element_block_slices(results):
    """{block name: slice into Results.element(...) arrays} (blocks concatenated in order)."""
    out, start = {}, 0
    for b, name in enumerate(block_names(results), start=1):
        n = results.connectivity(b).shape[0]
        out[name] = slice(start, start + n)
        start += n
    return out


def block_nodes(results, name):
    """Sorted 0-based node indices of element block `name`."""
    b = block_names(results).index(name) + 1
    return np.unique(results.connectivity(b))


# --- linear elasticity with uniform stress --------------------------------------------------


def strain_3d(sigma, E, nu):
    """Small strain of a 3x3 stress: eps = (1+nu)/E sigma - nu/E tr(sigma) I."""
    sigma = np.asarray(sigma, dtype=float)
    return (1 + nu) / E * sigma - nu / E * np.trace(sigma) * np.eye(3)


def plane_strain_stress(sxx, syy, sxy, nu):
    """3x3 stress of a plane-strain state (sigma_zz = nu (sigma_xx + sigma_yy), eps_zz = 0)."""
    return np.array([[sxx, sxy, 0.0], [sxy, syy, 0.0], [0.0, 0.0, nu * (sxx + syy)]])


def stress_of_gradient(grad, E, nu, dim):
    """Stress of a (dim x dim) displacement gradient, by output name (plane strain in 2D)."""
    g = np.zeros((3, 3))
    g[:dim, :dim] = grad
    eps = 0.5 * (g + g.T)
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    s = lam * np.trace(eps) * np.eye(3) + 2 * mu * eps
    return stress_names(s, dim)


def stress_names(s, dim):
    if dim == 2:
        return {"stress_xx": s[0, 0], "stress_yy": s[1, 1], "stress_xy": s[0, 1], "stress_zz": s[2, 2]}
    return {"stress_xx": s[0, 0], "stress_yy": s[1, 1], "stress_zz": s[2, 2],
            "stress_xy": s[0, 1], "stress_yz": s[1, 2], "stress_zx": s[0, 2]}


# --- Hertz line contact ------------------------------------------------------------------------


def hertz_line_contact(P, R1, R2, E1, nu1, E2, nu2):
    """Hertz contact of two parallel cylinders (plane strain), load P per unit length.

    Johnson, Contact Mechanics (1985), §4.2, eqs. (4.43)-(4.45): with the effective curvature
    1/R* = 1/R1 + 1/R2 (R2 = inf for a plane) and modulus 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2,
        b = sqrt(4 P R* / (pi E*)),   p(x) = (2P/(pi b^2)) sqrt(b^2 - x^2),   p0 = 2P/(pi b).
    Returns (b, p0)."""
    inv_r = 1.0 / R1 + (0.0 if math.isinf(R2) else 1.0 / R2)
    e_star = 1.0 / ((1 - nu1**2) / E1 + ((1 - nu2**2) / E2 if E2 else 0.0))
    b = math.sqrt(4 * P / (inv_r * math.pi * e_star))
    return b, 2 * P / (math.pi * b)


def hertz_pressure(x, b, p0):
    x = np.asarray(x, dtype=float)
    return p0 * np.sqrt(np.clip(1 - (x / b) ** 2, 0.0, None))


def half_width_one_side(x, p):
    """Edge of the contact zone on one side from nodal pressures at |x| increasing.

    x: distances from the centre (ascending, >= 0), p: pressures (> 0 active, 0 inactive).
    Between the last active node (x_a) and the first inactive one (x_i) the Hertz profile
    behaves like sqrt(b - x): p^2 is linear in x there, so the zero of the straight line
    through (x^2, p^2) at the last two active nodes is taken, clamped to [x_a, x_i]."""
    active = np.nonzero(p > 0)[0]
    if active.size == 0:
        return 0.0
    a = active.max()
    if a + 1 >= len(x):
        raise ValueError("contact zone reaches the end of the slave surface")
    xa, xi = x[a], x[a + 1]
    if a == 0:
        return xa
    x1, x2 = x[a - 1], xa
    q1, q2 = p[a - 1] ** 2, p[a] ** 2
    if q1 <= q2:  # not decreasing: no extrapolation
        return xa
    b2 = x2**2 + q2 * (x2**2 - x1**2) / (q1 - q2)  # zero of q(x^2) linear
    return float(np.clip(math.sqrt(b2), xa, xi))


def half_width(x, p):
    """Mean of the left and right contact edges (see half_width_one_side)."""
    x, p = np.asarray(x, dtype=float), np.asarray(p, dtype=float)
    right, left = x >= 0, x <= 0
    xr, pr = x[right], p[right]
    o = np.argsort(xr)
    br = half_width_one_side(xr[o], pr[o])
    xl, pl = -x[left], p[left]
    o = np.argsort(xl)
    bl = half_width_one_side(xl[o], pl[o])
    return 0.5 * (br + bl)


# --- rank comparison -----------------------------------------------------------------------


def compare_ranks(path_np1, path_np2, fields, tol=1e-10):
    """Max relative difference of nodal `fields` between the 1- and 2-rank results; returns
    (difference, failure message or None)."""
    r1, r2 = Results(path_np1), Results(path_np2)
    worst = 0.0
    for f in fields:
        worst = max(worst, relative_difference(r1.nodal(f), r2.nodal(f)))
    msg = None if worst < tol else "%s: 1 and 2 ranks differ by %.2e" % (path_np1, worst)
    return worst, msg


# --- uniform-stress contact cases (contact_patch, taylor_patch, collocation_study) -----------


def body_state(sigma, E, nu, dim, origin=None, offset=None):
    """A body under the uniform stress `sigma` (3x3): {stress, grad, offset}, with displacement
    u(X) = grad (X - origin) + offset."""
    eps = strain_3d(sigma, E, nu)
    grad = eps[:dim, :dim]
    origin = np.zeros(dim) if origin is None else np.asarray(origin, dtype=float)
    offset = np.zeros(dim) if offset is None else np.asarray(offset, dtype=float)
    return {"stress": np.asarray(sigma, dtype=float), "grad": grad,
            "offset": offset - grad @ origin}


def check_uniform(path, bodies, slave, pressure, tol=1e-8):
    """Compare one results file with a uniform-stress solution.

    bodies: {block name: body_state(...)}; slave: slave node set; pressure: the exact
    contact_pressure at every slave node. Checks, relative to the scale of each field:
    displacements at every node, every element stress, contact_pressure = pressure and
    contact_status = 2 (active, frictionless) at every slave node, |normal_gap| <= tol
    (relative to the displacement scale) there and contact_pressure = 0 elsewhere.
    Returns (dict of errors, list of failure messages)."""
    r = Results(path)
    if r.times().size == 0:
        return {}, ["%s: no converged step in the results" % path]
    xyz = r.coordinates()
    dim = xyz.shape[0]
    u = np.array([r.nodal("displ_" + "xyz"[d]) for d in range(dim)])
    u_exact = np.full_like(u, np.nan)
    for name, body in bodies.items():
        nodes = block_nodes(r, name)
        u_exact[:, nodes] = body["grad"] @ xyz[:, nodes] + body["offset"][:, None]
    if np.isnan(u_exact).any():
        raise ValueError("%s: nodes outside the listed blocks" % path)
    u_scale = np.abs(u_exact).max()
    err = {"displacement": np.abs(u - u_exact).max() / u_scale}
    slices = element_block_slices(r)
    s_scale = max(np.abs(b["stress"]).max() for b in bodies.values())
    err["stress"] = 0.0
    for name, body in bodies.items():
        for key, value in stress_names(body["stress"], dim).items():
            err["stress"] = max(err["stress"], np.abs(r.element(key)[slices[name]] - value).max() / s_scale)
    s_nodes = side_set_nodes(r, slave)
    cp = r.nodal("contact_pressure")
    err["contact_pressure"] = np.abs(cp[s_nodes] - pressure).max() / abs(pressure)
    others = np.setdiff1d(np.arange(cp.size), s_nodes)
    err["pressure_elsewhere"] = np.abs(cp[others]).max(initial=0.0) / abs(pressure)
    err["normal_gap"] = np.abs(r.nodal("normal_gap")[s_nodes]).max() / u_scale
    status = r.nodal("contact_status")[s_nodes]
    failures = ["%s: %s error %.2e > %g" % (path, k, v, tol) for k, v in err.items() if not v <= tol]
    if not np.all(status == 2):
        failures.append("%s: %d of %d slave nodes not active (contact_status != 2)"
                        % (path, int(np.sum(status != 2)), status.size))
    print("%-28s " % path + ", ".join("%s %.2e" % kv for kv in err.items()))
    return err, failures


def check_uniform_case(stem, bodies, slave, pressure, tol=1e-8, fields=None):
    """check_uniform on np1/<stem>.e and np2/<stem>.e, plus the 1-vs-2-rank comparison."""
    failures = []
    for np_ in (1, 2):
        failures += check_uniform("np%d/%s.e" % (np_, stem), bodies, slave, pressure, tol)[1]
    if failures and any("no converged step" in f for f in failures):
        return failures
    dim = Results("np1/%s.e" % stem).coordinates().shape[0]
    fields = fields or ["displ_" + "xyz"[d] for d in range(dim)] + ["contact_pressure"]
    diff, msg = compare_ranks("np1/%s.e" % stem, "np2/%s.e" % stem, fields)
    print("%-28s 1 vs 2 ranks: %.2e" % (stem, diff))
    return failures + ([msg] if msg else [])


# --- Hertz refinement studies (hertz_cylinders, hertz_plane) ---------------------------------


def hertz_level(path, slave, b, p0):
    """Computed half-width and peak pressure of one results file, their relative errors and
    the RMS profile error (over slave nodes with |x| <= 1.2 b, relative to p0)."""
    r = Results(path)
    s = side_set_nodes(r, slave)
    x = r.coordinates()[0, s]
    p = r.nodal("contact_pressure")[s]
    o = np.argsort(x)
    x, p = x[o], p[o]
    bh, ph = half_width(x, p), float(p.max())
    near = np.abs(x) <= 1.2 * b
    rms = float(np.sqrt(np.mean((p[near] - hertz_pressure(x[near], b, p0)) ** 2)) / p0)
    return {"x": x, "p": p, "b": bh, "p_max": ph, "err_b": abs(bh - b) / b,
            "err_p": abs(ph - p0) / p0, "err_rms": rms}


def hertz_study(stems, slave, b, p0, P, reaction, title, prefix, tol=0.03):
    """Refinement study over `stems` (coarse to fine): prints and checks the errors, the
    equilibrium |reaction| = P (global `reaction`), 1-vs-2-rank agreement; writes
    <prefix>_profile.csv (finest: x, p computed, p analytic), <prefix>_convergence.csv and
    <prefix>_profile.png. Returns the failure messages."""
    failures, levels = [], []
    for stem in stems:
        lv = hertz_level("np1/%s.e" % stem, slave, b, p0)
        levels.append(lv)
        diff, msg = compare_ranks("np1/%s.e" % stem, "np2/%s.e" % stem,
                                  ["displ_x", "displ_y", "contact_pressure"])
        if msg:
            failures.append(msg)
        force = abs(Results("np1/%s.e" % stem).global_var(reaction))
        print("%-10s b = %.5f (err %.2f %%), p_max = %.5g (err %.2f %%), profile RMS %.2f %%, "
              "|%s| = %.6g, 1 vs 2 ranks %.1e" % (stem, lv["b"], 100 * lv["err_b"], lv["p_max"],
                                                   100 * lv["err_p"], 100 * lv["err_rms"], reaction,
                                                   force, diff))
        if not abs(force - P) <= 1e-6 * P:
            failures.append("%s: |%s| = %.8g, expected P = %.8g (equilibrium)" % (stem, reaction, force, P))
    print("Hertz: b = %.5f, p_max = %.5g" % (b, p0))
    failures += assess_convergence(levels, tol)
    fine = levels[-1]
    with open(prefix + "_profile.csv", "w") as f:
        f.write("x,p_computed,p_analytic\n")
        for xi, pi in zip(fine["x"], fine["p"]):
            f.write("%.10g,%.10g,%.10g\n" % (xi, pi, hertz_pressure(xi, b, p0)))
    with open(prefix + "_convergence.csv", "w") as f:
        f.write("level,b,err_b,p_max,err_p,err_rms\n")
        for i, lv in enumerate(levels, start=1):
            f.write("%d,%.8g,%.4e,%.8g,%.4e,%.4e\n" % (i, lv["b"], lv["err_b"], lv["p_max"], lv["err_p"], lv["err_rms"]))
    plot_profiles(levels, b, p0, title, prefix + "_profile.png")
    return failures


def assess_convergence(levels, tol, floor=0.01, self_convergence=("b", "p_max")):
    """Finest level within tol for b and p_max, and convergence:
    - the errors of b, p_max and the profile RMS on the finest level below those of the
      coarsest (node-sampled values need not be monotone level by level), an error already
      below `floor` on both counting as converged;
    - for the quantities in `self_convergence` the error against Hertz may instead stall at
      the model error (finite bodies vs Hertz' half-spaces), as long as the computed values
      converge: |q3 - q2| < |q2 - q1|."""
    failures = []
    fine, coarse = levels[-1], levels[0]
    for key in ("err_b", "err_p"):
        if not fine[key] <= tol:
            failures.append("finest mesh: %s = %.2f %% > %.0f %%" % (key, 100 * fine[key], 100 * tol))
    for q, key in (("b", "err_b"), ("p_max", "err_p"), (None, "err_rms")):
        if fine[key] < coarse[key] or max(fine[key], coarse[key]) <= floor:
            continue
        if q in self_convergence and len(levels) >= 3:
            v = [lv[q] for lv in levels[-3:]]
            if abs(v[2] - v[1]) < abs(v[1] - v[0]):
                continue
        failures.append("%s does not decrease with refinement: %s" % (key, [lv[key] for lv in levels]))
    return failures


def plot_profiles(levels, b, p0, title, path, labels=None):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    xs = np.linspace(-1.5 * b, 1.5 * b, 601)
    ax.plot(xs, hertz_pressure(xs, b, p0), "k-", lw=1.5, label="Hertz")
    for i, lv in enumerate(levels, start=1):
        keep = np.abs(lv["x"]) <= 1.5 * b
        ax.plot(lv["x"][keep], lv["p"][keep], "o-", ms=3, lw=0.8,
                label="%s (b err %.1f %%, p_max err %.1f %%)"
                % (labels[i - 1] if labels else "level %d" % i, 100 * lv["err_b"], 100 * lv["err_p"]))
    ax.set_xlabel("x")
    ax.set_ylabel("contact pressure")
    ax.set_title(title)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    print("wrote", path)


def newton_rates(path, failures, median_min):
    """Convergence order of Newton's last judged contraction in every step of a
    `<stem>_newton.csv`, p = log(|F_k+1| / |F_0|) / log(|F_k| / |F_0|) (2 = quadratic), over
    Newton steps k -> k+1 that keep the active set of iterate k (no change at k+1; a change
    at k itself is the set the step was computed with) and are taken in full (`step_length`
    1 at k+1: a line search's damped update is not a Newton contraction), with |F_k| between
    0.1 |F_0| and 10x the step's final (round-off) residual and |F_k+1| above the latter.
    Required: median p >= median_min and every p >= 1.3 (superlinear:
    where the contact pairs, i.e. the segments, change between iterates the current-geometry
    linearisation is exact only piecewise). Appends to `failures`; returns the orders."""
    rows = list(csv.DictReader(open(path)))
    attempts = {}
    for r in rows:
        attempts.setdefault((int(r["step"]), r["time"]), []).append(r)
    orders = []
    for (step, t), hist in attempts.items():
        f = [float(r["residual"]) for r in hist]
        changes = [int(r["active_changes"]) for r in hist]
        full = [float(r.get("step_length") or 1.0) == 1.0 for r in hist]
        f0, floor = f[0], 10 * f[-1]
        pairs = [k for k in range(1, len(f) - 1) if changes[k + 1] == 0 and full[k + 1]
                 and 0.1 * f0 > f[k] > floor and f[k + 1] > floor]
        if pairs:
            k = pairs[-1]
            orders.append(math.log(f[k + 1] / f0) / math.log(f[k] / f0))
            if orders[-1] < 1.3:
                failures.append("%s step %d (t = %s): |F| %.3e -> %.3e, order %.2f < 1.3"
                                % (path, step, t, f[k], f[k + 1], orders[-1]))
    if orders and np.median(orders) < median_min:
        failures.append("%s: median Newton order %.2f < %.1f"
                        % (path, np.median(orders), median_min))
    return orders


def _self_test():
    # Row 8: R = 8 both, E = 200, nu = 0.3, p = 0.625 on the diameter -> P = 2 R p = 10.
    b, p0 = hertz_line_contact(10.0, 8.0, 8.0, 200.0, 0.3, 200.0, 0.3)
    assert abs(b - 0.6808) < 5e-5, b
    assert abs(p0 - 9.35) < 5e-3, p0
    # As in docs/verification.md #8: b = 2 sqrt(2 R^2 p (1 - nu^2)/(E pi)), p_max = 4 R p/(pi b).
    R, p, E, nu = 8.0, 0.625, 200.0, 0.3
    assert abs(b - 2 * math.sqrt(2 * R**2 * p * (1 - nu**2) / (E * math.pi))) < 1e-12
    assert abs(p0 - 4 * R * p / (math.pi * b)) < 1e-12
    # Equilibrium: integral of p over [-b, b] = P.
    x = np.linspace(-b, b, 200001)
    assert abs(np.trapz(hertz_pressure(x, b, p0), x) - 10.0) < 1e-4
    # Rigid plane (R2 = inf, E2 = inf) reduces to R* = R1, E* = E1/(1 - nu1^2).
    b2, p2 = hertz_line_contact(1.0, 2.0, math.inf, 1.0, 0.0, math.inf, 0.0)
    assert abs(b2 - math.sqrt(8 / math.pi)) < 1e-14 and abs(p2 - 2 / (math.pi * b2)) < 1e-14
    # The half-width estimator recovers b from an exact sqrt profile sampled at nodes.
    xs = np.linspace(-2.0, 2.0, 41)
    assert abs(half_width(xs, hertz_pressure(xs, 0.6808, 9.35)) - 0.6808) < 1e-12
    # Plane strain uniaxial: eps_xx = nu (1 + nu) p/E, eps_yy = -(1 - nu^2) p/E.
    eps = strain_3d(plane_strain_stress(0.0, -10.0, 0.0, 0.4), 1000.0, 0.4)
    assert abs(eps[0, 0] - 0.0056) < 1e-15 and abs(eps[1, 1] + 0.0084) < 1e-15
    assert abs(eps[2, 2]) < 1e-18
    # Stress of a gradient reproduces the stress that produced its strain.
    s = stress_of_gradient(eps[:2, :2], 1000.0, 0.4, 2)
    assert abs(s["stress_yy"] + 10) < 1e-12 and abs(s["stress_xx"]) < 1e-12
    assert abs(s["stress_zz"] + 4) < 1e-12
    # Convergence verdicts.
    lv = [{"b": 0.60, "p_max": 9.9, "err_b": 0.05, "err_p": 0.04, "err_rms": 0.05},
          {"b": 0.66, "p_max": 9.6, "err_b": 0.02, "err_p": 0.03, "err_rms": 0.03},
          {"b": 0.67, "p_max": 9.5, "err_b": 0.01, "err_p": 0.02, "err_rms": 0.01}]
    assert not assess_convergence(lv, 0.03)
    assert len(assess_convergence(lv[:2] + [dict(lv[2], err_b=0.04)], 0.03)) == 1  # tolerance
    # p_max error grows and the values diverge: tolerance and convergence both fail.
    assert len(assess_convergence(lv[:2] + [dict(lv[2], err_p=0.05, p_max=10.3)], 0.03)) == 2
    assert not assess_convergence([dict(lv[0], err_b=0.002, err_p=0.001, err_rms=0.003)] * 3, 0.03)
    # Stalling error against Hertz but converging values: accepted for b and p_max only.
    st = [{"b": 0.62, "p_max": 5.99, "err_b": 0.05, "err_p": 0.017, "err_rms": 0.05},
          {"b": 0.64, "p_max": 6.01, "err_b": 0.03, "err_p": 0.020, "err_rms": 0.03},
          {"b": 0.65, "p_max": 6.005, "err_b": 0.02, "err_p": 0.019, "err_rms": 0.02}]
    assert not assess_convergence(st, 0.03)
    assert len(assess_convergence(st, 0.03, self_convergence=())) == 1
    assert not assess_convergence([{"err_b": 0.002, "err_p": 0.001, "err_rms": 0.003}] * 3, 0.03)
    print("contact_check self-test: ok (b = %.6f, p0 = %.6f)" % (b, p0))


if __name__ == "__main__":
    _self_test()
