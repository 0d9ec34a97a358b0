"""Shared helpers of the frictional case checks (friction_patch, dong_friction,
hertz_frictional): the uniform-stress frictional patch solution and its check, the
Cattaneo-Mindlin line-contact solution, nodal normals of a 2D slave arc, the stick-zone
estimator, multi-step histories, and a multi-step fake results writer for the self-tests.

Import from a check.py with
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
    import friction_check as fc

Conventions (docs/design.md §2, nonlinear/mechanics_problem.hpp): lm = the slave multiplier
vector lambda_j; the traction on the slave is -lambda; lambda_n = n.lambda >= 0 in
compression (n = outward slave normal) is `contact_pressure`; contact_status 0 open,
1 stick, 2 slip; slip_* = accumulated slip of the slave relative to the master, sum over
steps of (tau . (D dx_slave - M dx_master)/D) tau (a length); reaction_* = force of the
support on the body at prescribed dofs (f_int - f_ext + f_c there).

Run `python3 friction_check.py` to self-test the formulas.
"""
import math
import os
import shutil

import numpy as np

import contact_check as cc
from grout_results import Results, relative_difference

OPEN, STICK, SLIP = 0, 1, 2


# --- uniform-stress frictional patch (friction_patch) ---------------------------------------


def shear_stress(dim, p, tau):
    """3x3 stress of uniform compression p normal to the interface (y in 2D, z in 3D) plus the
    interface shear `tau` (length dim - 1: sigma_xy in 2D; sigma_xz, sigma_yz in 3D). 2D is
    plane strain: sigma_zz = nu (sigma_xx + sigma_yy) is added by the caller's nu."""
    s = np.zeros((3, 3))
    a = dim - 1
    s[a, a] = -p
    for k in range(dim - 1):
        s[k, a] = s[a, k] = tau[k]
    return s


def fixed_base_gradient(sigma, E, nu, dim):
    """Displacement gradient G (dim x dim) of the uniform stress `sigma` (3x3; for 2D, plane
    strain: sigma_zz is set to nu (sigma_xx + sigma_yy) here) with the rotation chosen so the
    base plane (y = 0 in 2D, z = 0 in 3D) moves in its own plane only: G[a, k] = 0 for the
    normal axis a and k != a, i.e. u(base) = (eps_xx x, 0) / (eps_xx x, eps_yy y, 0) when
    eps_xy = 0. Then G[k, a] = 2 eps_ka (the engineering shear strain)."""
    sigma = np.array(sigma, dtype=float)
    if dim == 2:
        sigma[2, 2] = nu * (sigma[0, 0] + sigma[1, 1])
    eps = cc.strain_3d(sigma, E, nu)[:dim, :dim]
    a = dim - 1
    G = eps.copy()
    for k in range(a):
        G[k, a] = 2 * eps[k, a]
        G[a, k] = 0.0
    return G


def shear_modulus(E, nu):
    return E / (2 * (1 + nu))


def coulomb_status(ratio, mu):
    """The Coulomb prediction for a uniform interface with tangential/normal load ratio
    `ratio` (the ratio a no-slip state would need): stick iff ratio < mu (mu = 0: slip)."""
    return STICK if ratio < mu else SLIP


def tangential_part(lm, normal):
    """lm: (dim, n) multiplier vectors, normal: (dim,) or (dim, n) unit normals ->
    (lambda_n (n,), tangential vectors (dim, n))."""
    lm = np.asarray(lm, dtype=float)
    normal = np.asarray(normal, dtype=float)
    if normal.ndim == 1:
        normal = np.repeat(normal[:, None], lm.shape[1], axis=1)
    lam_n = np.sum(lm * normal, axis=0)
    return lam_n, lm - lam_n * normal


def interface_jump(r, slave, master, u, dim):
    """Displacement of every slave node minus the master surface's displacement at the same
    (reference) in-plane position; 2D: piecewise-linear interpolation along x on the master
    node set (exact for any nodal field on a flat interface), 3D: least-squares affine fit of
    the master nodes (exact for the linear fields of a patch test; the fit residual is
    returned too). Returns (jump (dim, n_slave), fit residual)."""
    xyz = r.coordinates()
    s, m = cc.side_set_nodes(r, slave), cc.side_set_nodes(r, master)
    if dim == 2:
        o = np.argsort(xyz[0, m])
        jump = np.array([u[d][s] - np.interp(xyz[0, s], xyz[0, m][o], u[d][m][o]) for d in range(2)])
        return jump, 0.0
    A = np.column_stack([np.ones(m.size), xyz[0, m], xyz[1, m]])
    As = np.column_stack([np.ones(s.size), xyz[0, s], xyz[1, s]])
    jump, resid = [], 0.0
    for d in range(3):
        coef = np.linalg.lstsq(A, u[d][m], rcond=None)[0]
        resid = max(resid, float(np.abs(A @ coef - u[d][m]).max()))
        jump.append(u[d][s] - As @ coef)
    return np.array(jump), resid


def patch_case(dim, E, nu, p, tau, mu, status, shift=None, heights=(1.0, 1.0), width=1.0,
               drive=None):
    """The exact solution of one frictional patch run at t = 1 (everything scales with t).

    tau: interface shear vector (sigma_xy / sigma_xz, sigma_yz) = the tangential part of
    lambda; shift: rigid tangential offset of the upper block (slip), None for stick;
    drive: for displacement-controlled runs, the prescribed tangential displacement d of the
    top (beyond eps_xx x), from which the no-slip load ratio is derived.
    Returns a dict used by check_patch."""
    sigma = shear_stress(dim, p, tau)
    G = fixed_base_gradient(sigma, E, nu, dim)
    sig = sigma.copy()
    if dim == 2:
        sig[2, 2] = nu * (sig[0, 0] + sig[1, 1])
    shift = np.zeros(dim - 1) if shift is None else np.asarray(shift, dtype=float)
    if drive is None:  # traction controlled: the applied ratio
        ratio = float(np.linalg.norm(tau)) / p
    else:  # displacement controlled: the shear a no-slip column would need for `drive`
        ratio = shear_modulus(E, nu) * float(np.linalg.norm(drive)) / sum(heights) / p
    lam = np.zeros(dim)
    lam[:dim - 1] = tau
    lam[dim - 1] = -p
    area = width ** (dim - 1)
    return {"dim": dim, "E": E, "nu": nu, "p": p, "tau": np.asarray(tau, dtype=float), "mu": mu,
            "status": status, "predicted": coulomb_status(ratio, mu), "ratio": ratio,
            "sigma": sig, "G": G, "shift": shift, "lm": lam, "area": area,
            "normal_force": p * area, "tangential_force": float(np.linalg.norm(tau)) * area}


def exact_displacement(case, xyz, upper_nodes, t=1.0):
    """u = t (G X) in both bodies, plus t * shift (tangential) in the upper one."""
    dim = case["dim"]
    u = t * (case["G"] @ xyz)
    for k in range(dim - 1):
        u[k, upper_nodes] += t * case["shift"][k]
    return u


def check_patch(path, case, slave="upper_bottom", master="lower_top", tol=1e-8,
                tangential_reaction="reaction_upper_top_nodes", normal_reaction="reaction_lower_bottom_nodes"):
    """Check every step of one frictional patch run against the exact solution scaled by t.

    Per step: displacements (relative to the displacement scale), every element stress
    (relative to p), contact_pressure = p at the slave nodes (0 elsewhere), lm = lambda,
    contact_status = the expected status = the Coulomb prediction, the local Coulomb law
    (slip: |lambda_t| = mu lambda_n; stick: |lambda_t| < mu lambda_n), slip_* = the shift
    (0 in stick), the tangential displacement jump across the interface = the shift (0 in
    stick), in slip lambda_t . slip > 0 (the friction on the slave, -lambda_t, opposes its
    slip), and the reactions: normal = p A; tangential = mu x normal (slip, driven top) or
    = |tau| A (stick, at the base). Returns (errors dict, failures)."""
    r = Results(path)
    times = r.times()
    if times.size == 0:
        return {}, ["%s: no converged step in the results" % path]
    dim = case["dim"]
    failures = []
    if case["predicted"] != case["status"]:
        failures.append("%s: case set up wrongly: Coulomb predicts status %d (ratio %.4g, mu %g), "
                        "expected %d" % (path, case["predicted"], case["ratio"], case["mu"], case["status"]))
    xyz = r.coordinates()
    s = cc.side_set_nodes(r, slave)
    upper = cc.block_nodes(r, "upper")
    slices = cc.element_block_slices(r)
    normal = np.zeros(dim)
    normal[dim - 1] = -1.0  # outward normal of the upper block's bottom
    err = {k: 0.0 for k in ("displacement", "stress", "contact_pressure", "pressure_elsewhere", "lm",
                            "coulomb", "slip", "jump", "reaction_n", "reaction_t")}
    p, mu = case["p"], case["mu"]
    for step, t in enumerate(times):
        u = np.array([r.nodal("displ_" + "xyz"[d], step) for d in range(dim)])
        ue = exact_displacement(case, xyz, upper, t)
        u_scale = max(np.abs(ue).max(), 1e-300)
        err["displacement"] = max(err["displacement"], np.abs(u - ue).max() / u_scale)
        for key, value in cc.stress_names(t * case["sigma"], dim).items():
            for name in ("lower", "upper"):
                err["stress"] = max(err["stress"], np.abs(r.element(key, step)[slices[name]] - value).max() / (p * t))
        cp = r.nodal("contact_pressure", step)
        err["contact_pressure"] = max(err["contact_pressure"], np.abs(cp[s] - p * t).max() / (p * t))
        others = np.setdiff1d(np.arange(cp.size), s)
        err["pressure_elsewhere"] = max(err["pressure_elsewhere"], np.abs(cp[others]).max(initial=0.0) / (p * t))
        lm = np.array([r.nodal("lm_" + "xyz"[d], step)[s] for d in range(dim)])
        err["lm"] = max(err["lm"], np.abs(lm - t * case["lm"][:, None]).max() / (p * t))
        lam_n, lam_t = tangential_part(lm, normal)
        lam_t_norm = np.linalg.norm(lam_t, axis=0)
        status = r.nodal("contact_status", step)[s]
        bad = int(np.sum(status != case["status"]))
        if bad:
            failures.append("%s t=%g: %d of %d slave nodes have contact_status != %d (got %s)"
                            % (path, t, bad, status.size, case["status"], sorted(set(status.tolist()))))
        slipping = status == SLIP
        if slipping.any():
            err["coulomb"] = max(err["coulomb"], np.abs(lam_t_norm[slipping] - mu * lam_n[slipping]).max() / (p * t))
        sticking = status == STICK
        if sticking.any() and not np.all(lam_t_norm[sticking] < mu * lam_n[sticking]):
            failures.append("%s t=%g: stick node with |lambda_t| >= mu lambda_n" % (path, t))
        slip = np.array([r.nodal("slip_" + "xyz"[d], step)[s] for d in range(dim)])
        shift = np.zeros(dim)
        shift[:dim - 1] = t * case["shift"]
        jump, fit = interface_jump(r, slave, master, u, dim)
        err["slip"] = max(err["slip"], np.abs(slip - shift[:, None]).max() / u_scale)
        err["jump"] = max(err["jump"], (np.abs(jump[:dim - 1] - shift[:dim - 1, None]).max() + fit) / u_scale)
        if case["status"] == SLIP and mu > 0:
            if not np.all(np.sum(lam_t * slip, axis=0) > 0):
                failures.append("%s t=%g: lambda_t . slip <= 0 at a slipping node (friction does not "
                                "oppose the slip)" % (path, t))
        # Reactions (support forces): normal at the base; tangential at the driven top (slip)
        # or at the base (stick).
        rn = abs(r.global_var("%s_%s" % (normal_reaction, "xyz"[dim - 1]), step))
        err["reaction_n"] = max(err["reaction_n"], abs(rn - t * case["normal_force"]) / (t * case["normal_force"]))
        where = tangential_reaction if case["status"] == SLIP else normal_reaction
        rt = np.array([r.global_var("%s_%s" % (where, "xyz"[k]), step) for k in range(dim - 1)])
        expected_t = mu * rn if case["status"] == SLIP else t * case["tangential_force"]
        scale = expected_t if expected_t > 0 else rn
        err["reaction_t"] = max(err["reaction_t"], abs(np.linalg.norm(rt) - expected_t) / scale)
        if case["status"] == SLIP and mu > 0 and dim == 3:
            d = case["tau"] / np.linalg.norm(case["tau"])
            err["reaction_t"] = max(err["reaction_t"], abs(abs(np.dot(rt, d)) - np.linalg.norm(rt)) / scale)
    failures += ["%s: %s error %.2e > %g" % (path, k, v, tol) for k, v in err.items() if not v <= tol]
    print("%-24s mu = %-6g ratio %.4g -> %s; " % (path, mu, case["ratio"], "stick" if case["status"] == STICK else "slip")
          + ", ".join("%s %.1e" % kv for kv in err.items()))
    return err, failures


def check_patch_case(stem, case, **kw):
    """check_patch on np1 and np2, and the 1-vs-2-rank comparison (1e-10)."""
    failures = []
    for n in (1, 2):
        failures += check_patch("np%d/%s.e" % (n, stem), case, **kw)[1]
    if any("no converged step" in f for f in failures):
        return failures
    dim = case["dim"]
    fields = ["displ_" + "xyz"[d] for d in range(dim)] + ["lm_" + "xyz"[d] for d in range(dim)]
    diff, msg = cc.compare_ranks("np1/%s.e" % stem, "np2/%s.e" % stem, fields)
    print("%-24s 1 vs 2 ranks: %.1e; Newton iterations per step: %s" % (stem, diff, newton_per_step("np1/%s.e" % stem)))
    return failures + ([msg] if msg else [])


def newton_per_step(path):
    r = Results(path)
    return [int(r.global_var("newton_iterations", k)) for k in range(r.times().size)]


# --- Cattaneo-Mindlin (hertz_frictional) ------------------------------------------------------


def mindlin_stick_half_width(b, Q, mu, P):
    """Cattaneo-Mindlin, line contact (Johnson, Contact Mechanics §7.1, eq. (7.8)):
    c/b = sqrt(1 - Q/(mu P)), for 0 <= Q < mu P."""
    if not 0 <= Q < mu * P:
        raise ValueError("Cattaneo-Mindlin needs 0 <= Q < mu P (Q = %g, mu P = %g)" % (Q, mu * P))
    return b * math.sqrt(1 - Q / (mu * P))


def mindlin_traction(x, b, c, mu, p0):
    """Tangential traction magnitude of the Cattaneo-Mindlin line contact (Johnson §7.1,
    eq. (7.7)/(7.9)): q(x) = mu p0/b (sqrt(b^2 - x^2) - sqrt(c^2 - x^2)) for |x| <= c,
    mu p0/b sqrt(b^2 - x^2) for c < |x| <= b, 0 outside; p0 = 2P/(pi b) (= 4Rp/(pi b) for
    the load p on a diameter 2R)."""
    x = np.asarray(x, dtype=float)
    outer = np.sqrt(np.clip(b * b - x * x, 0.0, None))
    inner = np.sqrt(np.clip(c * c - x * x, 0.0, None))
    return mu * p0 / b * (outer - inner)


def arc_normals(x, y, outward_y_sign):
    """Averaged nodal normals of a 2D polyline through the nodes (x, y) sorted by x: the
    normalised sum of the unit normals of the adjacent segments (as the mortar code does),
    oriented so that n_y has the sign `outward_y_sign` (-1 for a body above the interface).
    Returns (2, n)."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    seg = np.array([np.diff(x), np.diff(y)])
    seg_n = np.array([-seg[1], seg[0]]) / np.hypot(seg[0], seg[1])
    seg_n *= np.sign(seg_n[1]) * outward_y_sign
    n = np.zeros((2, x.size))
    n[:, :-1] += seg_n
    n[:, 1:] += seg_n
    return n / np.hypot(n[0], n[1])


def stick_edge_one_side(x, status, defect):
    """Edge of the central stick zone on one side: x >= 0 ascending, status per node,
    defect = mu lambda_n - |lambda_t| (> 0 in stick, 0 in slip). Cattaneo-Mindlin: the
    defect is mu p0/b sqrt(c^2 - x^2), so defect^2 is linear in x^2 near c; the zero of the
    line through the last two stick nodes is taken, clamped between the last stick node and
    the first non-stick node (as contact_check.half_width_one_side does for b)."""
    stick = np.nonzero(status == STICK)[0]
    if stick.size == 0:
        return 0.0
    a = stick.max()
    if a + 1 >= len(x):
        return float(x[a])
    d = np.where(status == STICK, defect, 0.0)
    return cc.half_width_one_side(x, d) if a > 0 else float(x[a])


def stick_half_width(x, status, defect):
    """Mean of the left and right stick-zone edges (see stick_edge_one_side)."""
    x, status, defect = np.asarray(x, float), np.asarray(status), np.asarray(defect, float)
    out = []
    for side in (x >= 0, x <= 0):
        xs = np.abs(x[side])
        o = np.argsort(xs)
        out.append(stick_edge_one_side(xs[o], status[side][o], defect[side][o]))
    return 0.5 * (out[0] + out[1])


# --- histories over the steps (dong_friction) ----------------------------------------------------


def history(path, global_name, nodes=None, nodal_name=None):
    """Per-step values: a global variable, or the mean of a nodal field over `nodes`."""
    r = Results(path)
    n = r.times().size
    if nodal_name is None:
        return np.array([r.global_var(global_name, k) for k in range(n)])
    return np.array([r.nodal(nodal_name, k)[nodes].mean() for k in range(n)])


# --- multi-step fake results (self-tests of the checks) -------------------------------------


def write_results_steps(mesh, path, times, nodal, element=None, globals_=None):
    """Like fake_results.write_results, for several steps: nodal/element/globals map names to
    arrays of shape (n_steps, n) / (n_steps, n_elements) / (n_steps,)."""
    import netCDF4
    from fake_results import _put_names
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    shutil.copyfile(mesh, path)
    ds = netCDF4.Dataset(path, "a")
    length = len(ds.dimensions["len_name"])
    if "time_whole" not in ds.variables:
        ds.createVariable("time_whole", "f8", ("time_step",))
    for k, t in enumerate(times):
        ds.variables["time_whole"][k] = t
    _put_names(ds, "num_nod_var", "name_nod_var", list(nodal), length)
    for i, (name, values) in enumerate(nodal.items(), start=1):
        v = ds.createVariable("vals_nod_var%d" % i, "f8", ("time_step", "num_nodes"))
        v[:, :] = np.asarray(values, dtype=float)
    element = element or {}
    if element:
        _put_names(ds, "num_elem_var", "name_elem_var", list(element), length)
        n_blocks = len(ds.dimensions["num_el_blk"])
        for i, (name, values) in enumerate(element.items(), start=1):
            values = np.asarray(values, dtype=float)
            start = 0
            for b in range(1, n_blocks + 1):
                n = len(ds.dimensions["num_el_in_blk%d" % b])
                v = ds.createVariable("vals_elem_var%deb%d" % (i, b), "f8", ("time_step", "num_el_in_blk%d" % b))
                v[:, :] = values[:, start:start + n]
                start += n
    globals_ = globals_ or {}
    if globals_:
        _put_names(ds, "num_glo_var", "name_glo_var", list(globals_), length)
        v = ds.createVariable("vals_glo_var", "f8", ("time_step", "num_glo_var"))
        v[:, :] = np.array([np.asarray(g, dtype=float) for g in globals_.values()]).T
    ds.close()


def patch_fake_fields(mesh, case, times, slave="upper_bottom", dim=None):
    """Exact nodal/element/global fields of a patch run on `mesh` at `times` (for tests)."""
    r = Results(mesh)
    xyz = r.coordinates()
    dim = xyz.shape[0]
    upper = cc.block_nodes(r, "upper")
    s = cc.side_set_nodes(r, slave)
    n = xyz.shape[1]
    nodal = {k: [] for k in ["displ_" + "xyz"[d] for d in range(dim)] + ["contact_pressure", "normal_gap",
                                                                         "contact_status"]
             + ["lm_" + "xyz"[d] for d in range(dim)] + ["slip_" + "xyz"[d] for d in range(dim)]}
    slices = cc.element_block_slices(r)
    n_el = sum(sl.stop - sl.start for sl in slices.values())
    element = {}
    glob = {"newton_iterations": [], "reaction_lower_bottom_nodes_" + "xyz"[dim - 1]: []}
    for k in range(dim - 1):
        glob["reaction_upper_top_nodes_" + "xyz"[k]] = []
        glob["reaction_lower_bottom_nodes_" + "xyz"[k]] = []
    for t in times:
        u = exact_displacement(case, xyz, upper, t)
        for d in range(dim):
            nodal["displ_" + "xyz"[d]].append(u[d])
            lm = np.zeros(n)
            lm[s] = t * case["lm"][d]
            nodal["lm_" + "xyz"[d]].append(lm)
            sl = np.zeros(n)
            if d < dim - 1:
                sl[s] = t * case["shift"][d]
            nodal["slip_" + "xyz"[d]].append(sl)
        cp = np.zeros(n)
        cp[s] = t * case["p"]
        st = np.zeros(n)
        st[s] = case["status"]
        nodal["contact_pressure"].append(cp)
        nodal["normal_gap"].append(np.zeros(n))
        nodal["contact_status"].append(st)
        for key, value in cc.stress_names(t * case["sigma"], dim).items():
            element.setdefault(key, []).append(np.full(n_el, value))
        glob["newton_iterations"].append(2)
        glob["reaction_lower_bottom_nodes_" + "xyz"[dim - 1]].append(t * case["normal_force"])
        tau_dir = case["tau"] / max(np.linalg.norm(case["tau"]), 1e-300)
        ft = t * (case["mu"] * case["normal_force"] if case["status"] == SLIP else case["tangential_force"])
        for k in range(dim - 1):
            glob["reaction_upper_top_nodes_" + "xyz"[k]].append(ft * tau_dir[k] if case["status"] == SLIP else 0.0)
            glob["reaction_lower_bottom_nodes_" + "xyz"[k]].append(-ft * tau_dir[k])
    return nodal, element, glob


def _self_test():
    # Plane strain patch gradient: eps_xx = nu (1 + nu) p/E, eps_yy = -(1 - nu^2) p/E,
    # G_xy = tau/G (engineering shear), G_yx = 0 (the base moves along itself only).
    E, nu, p, q = 2.069e11, 0.29, 1e8, 5e7
    G = fixed_base_gradient(shear_stress(2, p, [q]), E, nu, 2)
    assert abs(G[0, 0] - nu * (1 + nu) * p / E) < 1e-18
    assert abs(G[1, 1] + (1 - nu**2) * p / E) < 1e-18
    assert abs(G[0, 1] - q / shear_modulus(E, nu)) < 1e-18 and G[1, 0] == 0.0
    # The stress of G (rotation removed) is the stress that produced it.
    st = cc.stress_of_gradient(G, E, nu, 2)
    assert abs(st["stress_xy"] - q) < 1e-6 and abs(st["stress_yy"] + p) < 1e-6 and abs(st["stress_xx"]) < 1e-6
    # 3D: oblique shear.
    G3 = fixed_base_gradient(shear_stress(3, p, [0.6 * q, 0.8 * q]), E, nu, 3)
    st = cc.stress_of_gradient(G3, E, nu, 3)
    assert abs(st["stress_zx"] - 0.6 * q) < 1e-6 and abs(st["stress_yz"] - 0.8 * q) < 1e-6
    assert abs(st["stress_zz"] + p) < 1e-6 and G3[2, 0] == G3[2, 1] == 0.0
    # Coulomb prediction; mu = 0 always slips.
    assert coulomb_status(0.5, 1.0) == STICK and coulomb_status(0.5, 0.01) == SLIP
    assert coulomb_status(0.0, 0.0) == SLIP
    # Displacement-driven ratio: G d/(h_l + h_u)/p = 8.019e10 * 1e-3 / 2 / 1e8 = 0.40.
    c = patch_case(2, E, nu, p, [0.01 * p], 0.01, SLIP, shift=[1e-3], drive=[1e-3])
    assert abs(c["ratio"] - 0.40096) < 1e-4 and c["predicted"] == SLIP
    # Tangential part.
    lam_n, lam_t = tangential_part(np.array([[3.0], [-10.0]]), np.array([0.0, -1.0]))
    assert lam_n[0] == 10.0 and lam_t[0, 0] == 3.0 and lam_t[1, 0] == 0.0
    # Cattaneo-Mindlin, docs/verification.md #9: Q/(mu P) = 2R q/(mu 2R p) = 0.05851/0.125.
    b, p0 = cc.hertz_line_contact(10.0, 8.0, 8.0, 200.0, 0.3, 200.0, 0.3)
    cm = mindlin_stick_half_width(b, 16 * 0.05851, 0.2, 10.0)
    assert abs(cm / b - math.sqrt(1 - 0.05851 / 0.125)) < 1e-14 and abs(cm - 0.49652) < 1e-4, cm
    # The traction integrates to Q: mu P (1 - c^2/b^2) = Q.
    xs = np.linspace(-b, b, 400001)
    Q = np.trapz(mindlin_traction(xs, b, cm, 0.2, p0), xs)
    assert abs(Q - 16 * 0.05851) < 1e-4, Q
    # Continuous at c and full slip (mu p) outside.
    assert abs(mindlin_traction(0.8 * b, b, cm, 0.2, p0) - 0.2 * cc.hertz_pressure(0.8 * b, b, p0)) < 1e-12
    assert abs(mindlin_traction(cm * (1 - 1e-12), b, cm, 0.2, p0) - 0.2 * cc.hertz_pressure(cm, b, p0)) < 1e-5
    assert mindlin_traction(0.0, b, cm, 0.2, p0) < mindlin_traction(0.5 * cm, b, cm, 0.2, p0)
    # Normals of a circle arc are radial.
    th = np.linspace(-0.3, 0.3, 31)
    n = arc_normals(8 * np.sin(th), 8 - 8 * np.cos(th), -1.0)
    # interior nodes (the end nodes have one segment only)
    assert np.abs(n[0] - np.sin(th))[1:-1].max() < 1e-12 and np.abs(n[1] + np.cos(th))[1:-1].max() < 1e-12
    # The stick-zone estimator recovers c from a sampled exact defect.
    xs = np.linspace(-1.5, 1.5, 61)
    defect = 0.2 * p0 / b * np.sqrt(np.clip(cm**2 - xs**2, 0, None))
    status = np.where(np.abs(xs) < cm, STICK, np.where(np.abs(xs) <= b, SLIP, OPEN))
    assert abs(stick_half_width(xs, status, defect) - cm) < 1e-12
    print("friction_check self-test: ok (b = %.6f, c = %.6f, c/b = %.6f)" % (b, cm, cm / b))


if __name__ == "__main__":
    _self_test()
