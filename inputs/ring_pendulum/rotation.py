"""The cylinder's rotation and the moments that drive it, from Grout's Exodus results (2D).

Used by check.py (cylinder in a ring). Per output step k (records 0..n-1, steps 1..n; the
state before step 1 is the release: x = X, v = 0, a = g):

- rotation: the best-fit rigid rotation of the cylinder about its centre of mass,
  theta = atan2(sum m R x d, sum m R . d), R = X - X_c, d = x - x_c (m the lumped nodal masses);
- angular momentum about the centre of mass, H = sum m (x - x_c) x (v - v_c);
- the contact forces on the slave (cylinder) nodes, f_j = -D_jj lam_j, with the dual-mortar
  D_jj = int N_j ds = half the lengths of the two current slave edges at j (LINE2), and the
  slave nodal normals n_j = (n_e1 + n_e2)/|n_e1 + n_e2| (unweighted mean of the unit normals
  of the adjacent edges, current coordinates; Popp et al. 2010 eq. 4, as Grout's
  kernels/surface_normals.hpp);
- the angular momentum balance of the step. Newmark's average-acceleration rule
  (beta = 1/4, gamma = 1/2) has u_{n+1} - u_n = dt/2 (v_n + v_{n+1}), hence exactly
      H_{n+1} - H_n = sum (x_mid - x_c,mid) x m (v_{n+1} - v_n),
  and the stabilised contact treatment has m (v_{n+1} - v_n) = dt/2 (m a*_n + m a*_{n+1} + f_c),
  a* the acceleration carried into the next step (the output `acceleration_*`, which leaves the
  step's contact force out; m a* = m g - f_int). The velocity update adds a rigid translation
  of the body, which has no angular momentum about the centre of mass. So
      dH = dt/2 sum r_mid x (m a*_n + m a*_{n+1})   [elastic forces; gravity has no moment]
         + dt/2 sum r_mid x f_c                     [contact]
  to round-off: the multipliers are the forces the dynamics feels, and nothing else
  (no tangential impulse from the velocity update) turns the cylinder.
- the lean of the contact force: the angle between the line of action of the resultant
  contact force and the line through the centre of mass, alpha = (moment / |F_c|) / r.
"""
import numpy as np


# Corners of the reference element in Exodus order: QUAD4 (2D), HEX8 (3D).
CORNERS = {2: np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]], dtype=float),
           3: np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
                        [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]], dtype=float)}


def lumped_weights(xy, conn):
    """Integral of each bilinear (QUAD4) or trilinear (HEX8) shape function over the block
    (2^dim Gauss points): the row sums of the consistent mass matrix / rho, i.e. the lumped
    nodal masses / rho. N_a = prod_k (1 + c_ak xi_k) / 2^dim, c_a the corners."""
    dim = xy.shape[0]
    c = CORNERS[dim]
    w = np.zeros(xy.shape[1])
    p = xy[:, conn]  # [d, e, a]
    for gp in c / np.sqrt(3.0):
        n = np.prod(1 + c * gp, axis=1) / 2 ** dim
        dn = np.empty((dim, len(c)))  # dN_a / dxi_k
        for k in range(dim):
            other = [j for j in range(dim) if j != k]
            dn[k] = c[:, k] * np.prod(1 + c[:, other] * gp[other], axis=1) / 2 ** dim
        jac = np.einsum("dea,ka->edk", p, dn)  # [e, d, k]
        np.add.at(w, conn, np.linalg.det(jac)[:, None] * n[None, :])
    return w


def boundary_edges(xy, conn):
    """The block's boundary edges (used once), oriented with the outward normal on the left
    of (b - a) rotated by -90 degrees: n = (t_y, -t_x)."""
    count = {}
    for e in conn:
        for a in range(conn.shape[1]):
            edge = (e[a], e[(a + 1) % conn.shape[1]])
            key = tuple(sorted(edge))
            count.setdefault(key, []).append(edge)
    edges = np.array([v[0] for v in count.values() if len(v) == 1])
    centre = xy[:, np.unique(conn)].mean(axis=1)
    t = xy[:, edges[:, 1]] - xy[:, edges[:, 0]]
    mid = 0.5 * (xy[:, edges[:, 0]] + xy[:, edges[:, 1]]) - centre[:, None]
    inward = (t[1] * mid[0] - t[0] * mid[1]) < 0
    edges[inward] = edges[inward][:, ::-1]
    return edges


def cross(r, f):
    return r[0] * f[1] - r[1] * f[0]


def analyse(res, block, rho, g):
    """Per step: rotation, angular momentum, the two parts of the balance, contact resultant,
    lean, and the frictionless residual |lam x n| / |lam| at the active slave nodes."""
    xyz = res.coordinates()
    conn = res.connectivity(block)
    nodes = np.unique(conn)
    X_all = xyz[:2]
    m = rho * lumped_weights(X_all, conn)[nodes]
    edges = boundary_edges(X_all, conn)
    X = X_all[:, nodes]
    Xc = (X * m).sum(axis=1) / m.sum()
    R = X - Xc[:, None]
    times = res.times()
    n = len(times)
    out = {k: np.zeros(n) for k in ("rotation", "H", "dH", "dH_elastic", "dH_contact",
                                    "force", "lean", "tangential")}
    x_prev, ma_prev = X.copy(), m * np.array(g)[:, None]  # the release: a_0 = g
    H_prev = 0.0
    for k in range(n):
        u = np.array([res.nodal("displ_x", k), res.nodal("displ_y", k)])
        lam = np.array([res.nodal("lm_x", k), res.nodal("lm_y", k)])
        x_all = X_all + u
        x = x_all[:, nodes]
        v = np.array([res.nodal("velocity_x", k)[nodes], res.nodal("velocity_y", k)[nodes]])
        ma = m * np.array([res.nodal("acceleration_x", k)[nodes],
                           res.nodal("acceleration_y", k)[nodes]])
        t = x_all[:, edges[:, 1]] - x_all[:, edges[:, 0]]
        length = np.hypot(*t)
        D = np.zeros(x_all.shape[1])
        np.add.at(D, edges[:, 0], 0.5 * length)
        np.add.at(D, edges[:, 1], 0.5 * length)
        ne = np.array([t[1], -t[0]]) / length
        normal = np.zeros_like(x_all)
        for d in range(2):
            np.add.at(normal[d], edges[:, 0], ne[d])
            np.add.at(normal[d], edges[:, 1], ne[d])
        f_c = -(D * lam)[:, nodes]
        active = np.nonzero(np.hypot(*lam[:, nodes]) > 0)[0]
        if len(active):
            lj, nj = lam[:, nodes][:, active], normal[:, nodes][:, active]
            out["tangential"][k] = np.max(np.abs(cross(lj, nj)) / np.hypot(*lj) / np.hypot(*nj))
        xc = (x * m).sum(axis=1) / m.sum()
        vc = (v * m).sum(axis=1) / m.sum()
        d = x - xc[:, None]
        out["rotation"][k] = np.arctan2((m * cross(R, d)).sum(), (m * (R * d).sum(axis=0)).sum())
        H = (m * cross(d, v - vc[:, None])).sum()
        out["H"][k], out["dH"][k] = H, H - H_prev
        dt = times[k] - (times[k - 1] if k else 0.0)
        x_mid = 0.5 * (x + x_prev)
        r_mid = x_mid - ((x_mid * m).sum(axis=1) / m.sum())[:, None]
        out["dH_elastic"][k] = 0.5 * dt * cross(r_mid, ma_prev + ma).sum()
        out["dH_contact"][k] = 0.5 * dt * cross(r_mid, f_c).sum()
        F = np.hypot(*f_c.sum(axis=1))
        out["force"][k] = F
        if F > 0:
            radius = np.hypot(*R).max()
            out["lean"][k] = cross(r_mid, f_c).sum() / F / radius
        x_prev, ma_prev, H_prev = x, ma, H
    out["time"] = times
    out["inertia"] = (m * (R ** 2).sum(axis=0)).sum()
    out["radius"] = np.hypot(*R).max()
    return out
