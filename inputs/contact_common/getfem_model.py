"""Pieces shared by the independent GetFEM 5.4 checks (python3-getfem; Poulios & Renard's code):
inputs/double_arch/getfem_double_arch.py, inputs/press_fit/getfem_press_fit.py and
inputs/shallow_ironing/getfem_shallow_ironing.py.

- import_getfem: the module, or None when python3-getfem is missing (the checks skip: 77);
- read_mesh: read_exodus with the element blocks a check needs;

- read_exodus: Grout's QUAD4 Exodus mesh (nodes, blocks, node and side sets) with netCDF4;
- Body: one GetFEM mesh from some Exodus blocks (a volume region per block), face regions from
  Exodus nodes; two touching bodies are two meshes, so their coincident nodes stay apart;
- lame, neo_hookean_piola: Grout's compressible Neo-Hookean (docs/input.md) in GWFL,
  W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2, P = mu (F - F^-T) + lambda ln J F^-T, plane
  strain (F the in-plane 2x2 block, F33 = 1);
- add_neo_hookean: that term on a body, with element-wise (P0) Lame constants per block;
- newton: a plain full Newton on GetFEM's tangent (GetFEM's md.solve() line search weighs
  Dirichlet rows in m against forces in N/m and stalls).
- advance: one load increment with cut-backs, the friction's start-of-step copies set first;
- add_large_sliding_contact: Poulios & Renard's integral large-sliding contact brick;
- write_csv: a check's curve as CSV.
"""
import numpy as np


def lame(e, nu):
    """(lambda, mu) from E and nu."""
    return e * nu / ((1 + nu) * (1 - 2 * nu)), e / (2 * (1 + nu))


def names(var):
    """Exodus names: each ends at its first NUL (the bytes after it are not defined)."""
    out = []
    for row in np.array(var[:], dtype="S1"):
        chars = list(row)
        end = chars.index(b"") if b"" in chars else len(chars)
        out.append(b"".join(chars[:end]).decode("utf-8", "replace").strip())
    return out


def read_exodus(path, dim=2):
    """Nodes (n x dim), blocks {name: connectivity (0-based; QUAD4 counter-clockwise in 2D,
    HEX8 in 3D)}, node sets, side sets {name: [(element, 0-based in block order, side)]}, and
    all blocks' connectivity."""
    import netCDF4
    d = netCDF4.Dataset(path)
    d.set_auto_mask(False)
    x = np.stack([d.variables["coord" + c][:] for c in "xyz"[:dim]], axis=1)
    blocks = {}
    for i, n in enumerate(names(d.variables["eb_names"])):
        conn = np.asarray(d.variables["connect%d" % (i + 1)][:]) - 1
        if conn.shape[1] != (4 if dim == 2 else 8):
            raise SystemExit("%s: block %s is not %s" % (path, n, "QUAD4" if dim == 2 else "HEX8"))
        blocks[n] = conn
    nsets = {n: np.asarray(d.variables["node_ns%d" % (i + 1)][:]) - 1
             for i, n in enumerate(names(d.variables["ns_names"]))}
    ssets = {n: list(zip(np.asarray(d.variables["elem_ss%d" % (i + 1)][:]) - 1,
                         np.asarray(d.variables["side_ss%d" % (i + 1)][:])))
             for i, n in enumerate(names(d.variables["ss_names"]))}
    conn_all = np.concatenate([blocks[n] for n in blocks])
    return x, blocks, nsets, ssets, conn_all


def side_nodes(ssets, conn_all, name):
    """Exodus nodes of side set `name` (QUAD4 side s joins nodes s and s + 1, mod 4)."""
    out = set()
    for el, side in ssets[name]:
        c = conn_all[el]
        out.update((c[side - 1], c[side % 4]))
    return np.array(sorted(out))


class Body:
    """One GetFEM mesh built from some Exodus blocks, a volume region per block."""

    def __init__(self, gf, x, blocks, block_names, region_base):
        self.mesh = gf.Mesh("empty", 2)
        gt = gf.GeoTrans("GT_QK(2,1)")
        self.regions = {}
        for k, name in enumerate(block_names):
            conn = blocks[name]
            # GetFEM's QK(2,1) vertex order is (0,0), (1,0), (0,1), (1,1): Exodus 1, 2, 4, 3.
            pts = np.transpose(x[conn[:, [0, 1, 3, 2]]], (2, 1, 0))
            cvs = self.mesh.add_convex(gt, pts)
            rid = region_base + k
            self.mesh.set_region(rid, np.atleast_2d(cvs))
            self.regions[name] = rid

    def pids(self, nodes, x):
        """GetFEM point ids of Exodus nodes (-1: not in this body)."""
        return np.asarray(self.mesh.pid_from_coords(x[nodes].T, 1e-9), dtype=int)

    def face_region(self, rid, nodes, x):
        """The faces of this mesh whose vertices are all among the Exodus nodes `nodes`."""
        p = self.pids(nodes, x)
        p = p[p >= 0]
        faces = self.mesh.faces_from_pid(p)
        outer = self.mesh.outer_faces()
        keep = set(map(tuple, outer.T))
        faces = np.array([f for f in faces.T if tuple(f) in keep]).T
        self.mesh.set_region(rid, faces)
        return faces.shape[1] if faces.size else 0


def neo_hookean_piola(u, sfx, dim=2):
    """GWFL: first Piola stress of variable u (dim = 2: plane strain, F33 = 1; 3: full 3D)
    with Lame data lam_<sfx>, mu_<sfx>."""
    f = "(Id(%d)+Grad_%s)" % (dim, u)
    return "(mu_%s*(%s-Inv(%s)')+lam_%s*log(Det(%s))*Inv(%s)')" % (sfx, f, f, sfx, f, f)


def equilibrium_rows(md, supports):
    """The model's rows where equilibrium holds: every dof of the variables in `supports`
    [(variable, MeshFem, supported region)] but those on their supported region. Returns them
    and, per variable, its supported dofs (numbered within the variable)."""
    free, supported = [], {}
    for var, mf, region in supports:
        i0, n = md.interval_of_variable(var)
        keep = np.ones(n, bool)
        supported[var] = np.asarray(mf.basic_dof_on_region(region), int)
        keep[supported[var]] = False
        free.append(i0 + np.nonzero(keep)[0])
    return np.concatenate(free), supported


def add_stepping_arguments(ap, steps, t_end, release, max_res):
    """The command-line options shared by the ironing checks: the load path (--times, --steps,
    --t-end), the contact brick (--r, --r-factor, --release), Newton (--max-res), --csv,
    --noisy."""
    ap.add_argument("--times", default="", help="take the steps of this Grout summary CSV")
    ap.add_argument("--steps", type=int, default=steps, help="equal steps (without --times)")
    ap.add_argument("--t-end", type=float, default=t_end, help="last time")
    ap.add_argument("--r", type=float, default=None, help="augmentation (Pa/m)")
    ap.add_argument("--r-factor", type=float, default=1.0, help="multiplies E_block / h")
    ap.add_argument("--release", type=float, default=release, help="release distance")
    ap.add_argument("--max-res", type=float, default=max_res,
                    help="Newton: max |residual| (N) on the equilibrium rows")
    ap.add_argument("--csv", default="")
    ap.add_argument("--noisy", action="store_true")


def add_neo_hookean(gf, md, body, u, mim, sfx, moduli):
    """The Neo-Hookean internal virtual work of variable u on body; moduli {block name:
    (E, nu)}; the Lame constants are element-wise (P0) data lam_<sfx>, mu_<sfx>."""
    mf0 = gf.MeshFem(body.mesh, 1)
    mf0.set_fem(gf.Fem("FEM_QK(2,0)"))
    lam_v, mu_v = np.zeros(mf0.nbdof()), np.zeros(mf0.nbdof())
    for name, rid in body.regions.items():
        dofs = mf0.basic_dof_on_region(rid)
        lam_v[dofs], mu_v[dofs] = lame(*moduli[name])
    md.add_initialized_fem_data("lam_" + sfx, mf0, lam_v)
    md.add_initialized_fem_data("mu_" + sfx, mf0, mu_v)
    md.add_nonlinear_term(mim, neo_hookean_piola(u, sfx) + ":Grad_Test_" + u)


def newton(gf, md, free, max_res, noisy=False, max_dx=1e-12, max_it=40):
    """Full Newton on the whole model (GetFEM assembles the tangent and the residual; Dirichlet
    rows by simplification hold the distance to the imposed value). Converged when
    max |R| over the rows `free` (the equilibrium rows, N/m) <= max_res and max |dx| over them
    <= max_dx (m). Returns (iterations, converged); noisy prints the residuals."""
    for it in range(1, max_it + 1):
        md.assembly("build_all")
        rhs = md.rhs()
        res = np.abs(rhs[free]).max()
        if not np.isfinite(res):
            return it, False
        dx = np.asarray(gf.linsolve_mumps(md.tangent_matrix(), rhs)).ravel()
        step = np.abs(dx[free]).max()
        if noisy:
            print("     newton %2d  |R_free| = %.3e  |dx| = %.3e" % (it, res, step))
        if not np.all(np.isfinite(dx)):
            return it, False
        if res <= max_res and step <= max_dx:
            return it, True
        md.to_variables(md.from_variables() + dx)
    return max_it, False


def advance(gf, md, free, apply, s_from, s_to, w, max_res, noisy=False, max_cuts=6):
    """Take the load parameter from s_from to s_to: apply(s) sets the prescribed values for s;
    before each try the friction's reference displacements w (model variable -> its copy)
    are set to the last converged state; a failed Newton is undone and its increment halved,
    at most max_cuts times. Returns (Newton iterations, cut-backs, converged, last s tried)."""
    ds, s_now, total, cuts = s_to - s_from, s_from, 0, 0
    eps = 1e-12 * abs(s_to - s_from)
    s_try = s_to
    while s_now < s_to - eps:
        s_try = min(s_to, s_now + ds)
        apply(s_try)
        saved = md.from_variables()
        for var, wname in w.items():
            md.set_variable(wname, md.variable(var))
        nit, conv = newton(gf, md, free, max_res, noisy)
        total += nit
        if conv:
            s_now = s_try
            continue
        md.to_variables(saved)
        cuts += 1
        ds /= 2
        if cuts > max_cuts:
            return total, cuts, False, s_try
    return total, cuts, True, s_try


def advance_step(gf, md, free, apply, step, s_from, s_to, w, max_res, noisy=False, name="t",
                 failed=None):
    """advance() over load step `step`; when it fails after its cut-backs, says so and calls
    failed() (the scripts write the steps done so far). Returns (Newton iterations, cut-backs,
    converged)."""
    total, cuts, converged, s_try = advance(gf, md, free, apply, s_from, s_to, w, max_res, noisy)
    if not converged:
        print("step %d: no convergence at %s = %.5f after %d cut-backs"
              % (step, name, s_try, cuts - 1))
        if failed:
            failed()
    return total, cuts, converged


def add_large_sliding_contact(gf, md, r, release, mu, slave, master, order=1, dim=2, alpha=1.0,
                              version=0):
    """Poulios & Renard's integral large-sliding contact brick (raytracing): augmentation r,
    release distance `release`, Coulomb mu (0: frictionless). slave = (variable, MeshFem,
    mesh, MeshIm, region), master = (variable, MeshFem, MeshIm, region); the multiplier lam_c
    is QK(dim, order) on the slave's mesh, filtered to its region. With mu > 0 each body's slip is
    measured from its copy w_<variable>, the start-of-step state (`advance` sets it).
    GetFEM's slip is (u_s - u_m(Y) - (w_s - w_m(Y))) * alpha, Y the master point now opposite;
    alpha = 1 (the default, as GetFEM's own demo_large_sliding_contact.py) makes it the slip
    increment of the step; version 1 is GetFEM's "more symmetric" brick (0: the default).
    Returns (brick index, {variable: its copy's name})."""
    md.add_initialized_data("r", [r])
    md.add_initialized_data("f", [mu])
    md.add_initialized_data("alpha", [alpha])
    ind = md.add_integral_large_sliding_contact_brick_raytracing("r", release, "f", "alpha",
                                                                 version)
    s_var, s_mf, s_mesh, s_mim, s_region = slave
    m_var, m_mf, m_mim, m_region = master
    w = {}
    if mu > 0:
        for var, mf in ((s_var, s_mf), (m_var, m_mf)):
            md.add_fem_data("w_" + var, mf)
            w[var] = "w_" + var
    mfl = gf.MeshFem(s_mesh, dim)
    mfl.set_fem(gf.Fem("FEM_QK(%d,%d)" % (dim, order)))
    md.add_filtered_fem_variable("lam_c", mfl, s_region)
    md.add_slave_contact_boundary_to_large_sliding_contact_brick(
        ind, s_mim, s_region, s_var, "lam_c", *([w[s_var]] if w else []))
    md.add_master_contact_boundary_to_large_sliding_contact_brick(
        ind, m_mim, m_region, m_var, *([w[m_var]] if w else []))
    return ind, w


def import_getfem(script):
    """GetFEM's Python module with its trace output off; None, after a message naming
    `script`, when python3-getfem is not installed (the checks then exit 77: skipped)."""
    try:
        import getfem as gf
    except ImportError:
        print("%s: python3-getfem is not installed (Debian package python3-getfem); nothing to "
              "compare" % script)
        return None
    gf.util_trace_level(0)
    return gf


def read_mesh(path, needed_blocks):
    """read_exodus(path), refusing a mesh without one of the element blocks named."""
    x, blocks, nsets, ssets, conn_all = read_exodus(path)
    for need in needed_blocks:
        if need not in blocks:
            raise SystemExit("%s: block %s missing" % (path, need))
    return x, blocks, nsets, ssets, conn_all


def write_csv(path, header, row_format, rows):
    """rows as CSV under `header` (no-op when path is empty), each row % row_format."""
    if not path:
        return
    with open(path, "w") as f:
        f.write(header + "\n")
        for r in rows:
            f.write(row_format % tuple(r) + "\n")
    print("wrote %s" % path)
