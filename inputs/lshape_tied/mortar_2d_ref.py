"""An independent Python transcription of Grout's 2D segment-based dual mortar integrals D and M
(kernels/mortar_2d.hpp, surface_normals.hpp, dual_basis.hpp; Yang, Laursen, Meng, IJNME 62
(2005) §3; Popp et al., IJNME 79 (2009) §3.1), on given coordinates:

  nodal normal   n_j = Σ_e n_e / |Σ_e n_e|, n_e = (y_b − y_a, x_a − x_b)/L of face (a, b);
  slave segment  x¹(ξ) = a + ξ b, interpolated normal n¹(ξ) = c + ξ d;
  overlap        master nodes projected on the slave along n¹(ξ): (x¹(ξ) − y) × n¹(ξ) = 0,
                 clipped to [−1, 1];
  quadrature     5 Gauss points on the overlap, each projected on the master along n¹(ξ_g);
  D_jj += w Φ_j(ξ),  M_jl += w Φ_j(ξ) N_l(η),  Φ_1,2 = (1 ∓ 3ξ)/2 (LINE2 dual basis).

Used by check.py to test the tying constraint D_jj u_s,j = Σ_l M_jl u_m,l on the results.
"""
import numpy as np

GAUSS5 = [(-0.90617984593866399, 0.23692688505618909), (-0.53846931010568309, 0.47862867049936647),
          (0.0, 0.56888888888888889), (0.53846931010568309, 0.47862867049936647),
          (0.90617984593866399, 0.23692688505618909)]
SIDES = {4: [(0, 1), (1, 2), (2, 3), (3, 0)], 3: [(0, 1), (1, 2), (2, 0)]}


def cross(u, v):
    return u[0] * v[1] - u[1] * v[0]


def side_set_faces(results, name):
    """(n_faces, 2) 0-based node pairs of Exodus side set `name`, in the element's side order
    (counter-clockwise elements: the outward normal is (y_b − y_a, x_a − x_b))."""
    import netCDF4
    ds = results.ds
    names = [str(s).strip() for s in netCDF4.chartostring(ds.variables["ss_names"][:])]
    if name not in names:
        raise KeyError("%s: no side set '%s' (has %s)" % (results.path, name, names))
    k = names.index(name) + 1
    elems = np.array(ds.variables["elem_ss%d" % k][:]) - 1
    sides = np.array(ds.variables["side_ss%d" % k][:]) - 1
    conn = [results.connectivity(b) for b in range(1, results.num_blocks + 1)]
    rows = [row for c in conn for row in c]
    return np.array([[rows[e][SIDES[len(rows[e])][s][0]], rows[e][SIDES[len(rows[e])][s][1]]]
                     for e, s in zip(elems, sides)], dtype=int)


def nodal_normals(faces, X):
    n = {}
    for a, b in faces:
        ne = np.array([X[b, 1] - X[a, 1], X[a, 0] - X[b, 0]])
        ne /= np.hypot(*ne)
        for j in (a, b):
            n[j] = n.get(j, 0.0) + ne
    return {j: v / np.hypot(*v) for j, v in n.items()}


def project_to_slave(a, b, c, d, y):
    A, bxc = cross(b, d), cross(b, c)
    am = a - y
    B = cross(am, d) + bxc
    C = cross(am, c)
    if abs(A) <= 1e-14 * abs(B):
        return -C / B
    disc = B * B - 4 * A * C
    if disc < 0:
        return None
    q = -0.5 * (B + np.sqrt(disc)) if B >= 0 else -0.5 * (B - np.sqrt(disc))
    if q == 0:
        return 0.0
    return q / A if q * q < abs(A * C) else C / q


def pair(xs, ns, xm):
    """D (2,) and M (2, 2) of one slave/master segment pair (zeros without overlap)."""
    a, b = 0.5 * (xs[0] + xs[1]), 0.5 * (xs[1] - xs[0])
    c, d = 0.5 * (ns[0] + ns[1]), 0.5 * (ns[1] - ns[0])
    D, M = np.zeros(2), np.zeros((2, 2))
    xi_m = [project_to_slave(a, b, c, d, y) for y in xm]
    if None in xi_m:
        return D, M
    xa, xb = max(min(xi_m), -1.0), min(max(xi_m), 1.0)
    if not xb - xa > 1e-12:
        return D, M
    A, bxc = cross(b, d), cross(b, c)
    e, bm = 0.5 * (xm[0] + xm[1]) - a, 0.5 * (xm[1] - xm[0])
    n0, n1 = cross(e, c), cross(e, d) - bxc
    den0, den1 = cross(bm, c), cross(bm, d)
    half, mid, det_j = 0.5 * (xb - xa), 0.5 * (xa + xb), np.hypot(*b)
    for t, wr in GAUSS5:
        xi = mid + half * t
        w = wr * half * det_j
        eta = -(n0 + xi * (n1 - xi * A)) / (den0 + xi * den1)
        phi = np.array([0.5 * (1 - 3 * xi), 0.5 * (1 + 3 * xi)])
        N = np.array([0.5 * (1 - eta), 0.5 * (1 + eta)])
        D += w * phi
        M += w * np.outer(phi, N)
    return D, M


def mortar_matrices(slave_faces, master_faces, X):
    """{slave node: D_jj}, {(slave node, master node): M_jl} on coordinates X (n, 2). Pairs:
    master segments within (L_s + L_m) of the slave segment's mid point (a coarse search: the
    projection of a segment on the far side of a curved interface is not a neighbour)."""
    normals = nodal_normals(slave_faces, X)
    D, M = {}, {}
    for s in slave_faces:
        xs, ns = X[s], np.array([normals[s[0]], normals[s[1]]])
        ls = np.hypot(*(xs[1] - xs[0]))
        for m in master_faces:
            xm = X[m]
            lm = np.hypot(*(xm[1] - xm[0]))
            if np.hypot(*(0.5 * (xs[0] + xs[1] - xm[0] - xm[1]))) > ls + lm:
                continue
            Dp, Mp = pair(xs, ns, xm)
            for j in range(2):
                D[s[j]] = D.get(s[j], 0.0) + Dp[j]
                for l in range(2):
                    M[(s[j], m[l])] = M.get((s[j], m[l]), 0.0) + Mp[j, l]
    return D, M


def _self_test():
    # Matching straight segments: D = M = L/2 per node (biorthogonality: ∫Φ_j N_k = δ_jk ∫N_j).
    X = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [0.0, 0.0]])
    D, M = mortar_matrices(np.array([[1, 0]]), np.array([[3, 2]]), X)  # facing segments
    assert abs(D[0] - 0.5) < 1e-14 and abs(D[1] - 0.5) < 1e-14, D
    assert abs(M[(0, 3)] - 0.5) < 1e-14 and abs(M[(0, 2)]) < 1e-14, M
    # Non-matching flat interface, linear field: D u_s = M u_m exactly for u = linear in x.
    Xs = np.array([[0.0, 0.0], [0.3, 0.0], [0.7, 0.0], [1.0, 0.0]])
    Xm = np.array([[0.0, 0.0], [0.55, 0.0], [1.0, 0.0]])
    X = np.vstack([Xs, Xm])
    sf = np.array([[1, 0], [2, 1], [3, 2]])  # slave body above: outward normal -y
    mf = np.array([[4, 5], [5, 6]])
    D, M = mortar_matrices(sf, mf, X)
    u = 2.0 + 3.0 * X[:, 0]
    for j in range(4):
        r = D[j] * u[j] - sum(v * u[l] for (jj, l), v in M.items() if jj == j)
        assert abs(r) < 1e-14, (j, r)
    print("mortar_2d_ref self-test: ok")


if __name__ == "__main__":
    _self_test()
