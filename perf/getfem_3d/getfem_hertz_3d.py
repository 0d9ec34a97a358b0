#!/usr/bin/python3
"""GetFEM 5.4.2 (Debian python3-getfem) version of Grout's inputs/gmsh_hertz/hemispheres.yaml,
on Grout's own Exodus mesh (inputs/gmsh_hertz/hemispheres.py, TET4).

Same problem as hemispheres.yaml: quarter model of two hemispheres R = 1 touching at (0, 0, 1);
block 'lower' (centre (0,0,0), z >= 0) and block 'upper' (centre (0,0,2), z <= 2); linear
elastic, small strain, E = 200, nu = 0.3 (both); nodal Dirichlet conditions as Grout's
(exact, one row per constrained dof, add_constraint_with_multipliers):
  upper_top_nodes  u_z = -0.05        (u_x, u_y free)
  lower_bottom_nodes  u = 0
  x0_nodes  u_x = 0,   y0_nodes  u_y = 0   (symmetry planes)
P1 displacements (FEM_PK(3,1)) on GT_PK(3,1) tets (Exodus TETRA4 n1..n4 = GetFEM's vertex
order), one GetFEM mesh per block; side sets -> face regions (Exodus TET4 side s is the face
opposite the local vertex 2, 0, 1, 3 for s = 1, 2, 3, 4 = GetFEM face number; checked against
the side sets' node sets).

Contact, frictionless, slave = upper_contact, master = lower_contact:
add_integral_large_sliding_contact_brick_raytracing (augmented Lagrangian, current
configuration, the brick the 2D anchor uses: the 2D 'nonmatching' brick gave non-physical
pressures there), vector P1 multiplier filtered on upper_contact; pressure at a slave node =
-lambda.n with n the outward normal of the upper sphere (centre (0,0,2)) at the node.
r = E/h, h = mean edge length of the slave faces within 0.25 of the apex (the mesh's uniform
'contact size' zone), the scale of Grout's default c_n = E/h. Release distance 0.25 (--release;
the gap at r = 0.5 from the axis is 0.27, the contact radius ~0.17).

Newton: md.solve('max_res', 1e-10, 'max_iter', 25, 'lsolver', 'mumps'), from u = 0 unless
--init-dz (the upper body is held by its top face, so it is not free at u = 0 as in 2D).
The script recomputes |residual| after the solve and reports it relative to the top reaction.

Output: one JSON line (prefix 'RESULT ') with nodes, dofs, iterations, timings (mesh read +
model set-up, solve(), whole script), F = 4 x the upper_top z reaction, residuals; and
<out>_pressure.csv (x, y, z, p) for the slave nodes (a and p0 are extracted by summarize.py,
the same way for Grout and GetFEM).
"""
import argparse
import json
import math
import os
import time

T_START = time.perf_counter()

import numpy as np  # noqa: E402
import netCDF4  # noqa: E402
import getfem as gf  # noqa: E402

gf.util_trace_level(0)

R, E, NU, DZ = 1.0, 200.0, 0.3, -0.05
UPPER_CENTRE = np.array([0.0, 0.0, 2.0])
# Exodus TETRA4 side s (1-based) -> local vertex NOT on that side (= GetFEM's face number:
# face f of a GT_PK(3,1) simplex is opposite vertex f). Sides: 1 = (1,2,4), 2 = (2,3,4),
# 3 = (1,4,3), 4 = (1,3,2).
EXO_SIDE_TO_GF_FACE = {1: 2, 2: 0, 3: 1, 4: 3}
EXO_SIDE_NODES = {1: (0, 1, 3), 2: (1, 2, 3), 3: (0, 3, 2), 4: (0, 2, 1)}


def names(ds, var):
    return [str(s).strip() for s in netCDF4.chartostring(ds.variables[var][:])]


def read_exodus(path):
    ds = netCDF4.Dataset(path, "r")
    ds.set_auto_mask(False)
    X = np.stack([np.asarray(ds.variables[c][:], dtype=float) for c in ("coordx", "coordy", "coordz")])
    blocks, elem_block = {}, []
    for i, bn in enumerate(names(ds, "eb_names"), start=1):
        v = ds.variables["connect%d" % i]
        assert v.getncattr("elem_type").upper().startswith("TET"), "TETRA4 only"
        conn = np.asarray(v[:], dtype=np.int64) - 1
        assert conn.shape[1] == 4, "TETRA4 only"
        blocks[bn] = conn
        elem_block += [(bn, k) for k in range(conn.shape[0])]
    side_sets = {}
    for i, sn in enumerate(names(ds, "ss_names"), start=1):
        el = np.asarray(ds.variables["elem_ss%d" % i][:]) - 1
        sd = np.asarray(ds.variables["side_ss%d" % i][:])
        side_sets[sn] = [(elem_block[e][0], elem_block[e][1], int(s)) for e, s in zip(el, sd)]
    node_sets = {}
    for i, nn in enumerate(names(ds, "ns_names"), start=1):
        node_sets[nn] = np.asarray(ds.variables["node_ns%d" % i][:], dtype=np.int64) - 1
    ds.close()
    return X, blocks, side_sets, node_sets


class Body:
    """GetFEM mesh of one block; pid[n] = GetFEM point id of Exodus node n (or -1)."""


def build_body(X, conn):
    b = Body()
    b.conn = conn
    b.mesh = gf.Mesh("empty", 3)
    gt = gf.GeoTrans("GT_PK(3,1)")
    pts = X[:, conn.T]  # (3, 4, ncv)
    b.cv = np.asarray(b.mesh.add_convex(gt, pts), dtype=np.int64).ravel()
    assert len(b.cv) == conn.shape[0]
    nodes = np.unique(conn)
    b.pid = -np.ones(X.shape[1], dtype=np.int64)
    b.pid[nodes] = np.asarray(b.mesh.pid_from_coords(X[:, nodes]), dtype=np.int64).ravel()
    assert np.all(b.pid[nodes] >= 0)
    assert b.mesh.nbpts() == len(nodes), (b.mesh.nbpts(), len(nodes))
    # vertex order kept: GetFEM's points of each convex = the Exodus connectivity
    pid_cv, idx = b.mesh.pid_from_cvid(b.cv)
    pid_cv = np.asarray(pid_cv, dtype=np.int64).reshape(-1, 4)
    assert np.array_equal(pid_cv, b.pid[conn]), "GetFEM reordered the tet vertices"
    return b


def face_region(body, X, sides, node_set):
    """Set of GetFEM (cv, face) for the Exodus (element, side) pairs; checked: the points of the
    region are the node set, and each face's three points are the Exodus side's nodes."""
    cvs = body.cv[[k for k, s in sides]]
    fs = np.array([EXO_SIDE_TO_GF_FACE[s] for k, s in sides], dtype=np.int64)
    cvf = np.array([cvs, fs], dtype=np.int64)
    for j in range(0, len(sides), max(1, len(sides) // 50)):  # sample of single faces
        k, s = sides[j]
        got = sorted(int(p) for p in np.asarray(body.mesh.pid_in_faces(cvf[:, j:j + 1])).ravel())
        want = sorted(int(body.pid[body.conn[k][i]]) for i in EXO_SIDE_NODES[s])
        assert got == want, ("face mismatch", k, s, got, want)
    got = set(int(p) for p in np.asarray(body.mesh.pid_in_faces(cvf)).ravel())
    assert got == set(int(p) for p in body.pid[node_set]), "face region != node set"
    return cvf


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exo")
    ap.add_argument("--out", default="gf")
    ap.add_argument("--tol", type=float, default=1e-10)
    ap.add_argument("--max-iter", type=int, default=25)
    ap.add_argument("--release", type=float, default=0.25, help="raytracing release distance")
    ap.add_argument("--integ", type=int, default=5, help="IM_TETRAHEDRON order on the contact faces")
    ap.add_argument("--r", type=float, default=None, help="augmentation parameter (default E/h)")
    ap.add_argument("--init-dz", type=float, default=0.0, help="initial guess u_z of the upper body")
    ap.add_argument("--lsolver", default="mumps")
    ap.add_argument("--lsearch", default=None, help="GetFEM line search (default: GetFEM's)")
    ap.add_argument("--version", type=int, default=0, help="brick version: 0 non-symmetric, 1 more symmetric")
    ap.add_argument("--noisy", action="store_true")
    a = ap.parse_args()

    X, blocks, side_sets, node_sets = read_exodus(a.exo)
    n_nodes = X.shape[1]
    up, lo = build_body(X, blocks["upper"]), build_body(X, blocks["lower"])
    assert up.mesh.nbpts() + lo.mesh.nbpts() == n_nodes

    SLAVE, MASTER, TOP, BOTTOM, UX0, UY0, LX0, LY0 = 1, 2, 3, 4, 5, 6, 7, 8

    def region(body, bname, rid, sname):
        sides = [(k, s) for (bn, k, s) in side_sets[sname] if bn == bname]
        ns = np.intersect1d(node_sets[sname + "_nodes"], np.unique(body.conn))
        body.mesh.set_region(rid, face_region(body, X, sides, ns))

    for (bn, k, s) in side_sets["upper_contact"] + side_sets["upper_top"]:
        assert bn == "upper"
    for (bn, k, s) in side_sets["lower_contact"] + side_sets["lower_bottom"]:
        assert bn == "lower"
    region(up, "upper", SLAVE, "upper_contact")
    region(up, "upper", TOP, "upper_top")
    region(up, "upper", UX0, "x0")
    region(up, "upper", UY0, "y0")
    region(lo, "lower", MASTER, "lower_contact")
    region(lo, "lower", BOTTOM, "lower_bottom")
    region(lo, "lower", LX0, "x0")
    region(lo, "lower", LY0, "y0")

    fem = gf.Fem("FEM_PK(3,1)")
    mfu1, mfu2 = gf.MeshFem(up.mesh, 3), gf.MeshFem(lo.mesh, 3)
    mfu1.set_fem(fem)
    mfu2.set_fem(fem)
    im_vol = gf.Integ("IM_TETRAHEDRON(1)")  # P1: constant strain, exact
    mim1, mim2 = gf.MeshIm(up.mesh, im_vol), gf.MeshIm(lo.mesh, im_vol)
    im_c = gf.Integ("IM_TETRAHEDRON(%d)" % a.integ)  # its face rules on the contact triangles
    mim1c, mim2c = gf.MeshIm(up.mesh, im_c), gf.MeshIm(lo.mesh, im_c)

    lam = E * NU / ((1 + NU) * (1 - 2 * NU))
    mu = E / (2 * (1 + NU))
    md = gf.Model("real")
    md.add_fem_variable("u1", mfu1)
    md.add_fem_variable("u2", mfu2)
    md.add_initialized_data("lambda", [lam])
    md.add_initialized_data("mu", [mu])
    md.add_isotropic_linearized_elasticity_brick(mim1, "u1", "lambda", "mu")
    md.add_isotropic_linearized_elasticity_brick(mim2, "u2", "lambda", "mu")

    # nodal Dirichlet conditions as Grout's: one constraint row per (dof, value), by multipliers
    def constraints(mf, var, mult, items):
        val = {}
        for rid, comps, v in items:
            d = np.asarray(mf.basic_dof_on_region(rid), dtype=np.int64).ravel()
            for c in comps:
                for dof in d[d % 3 == c]:
                    assert val.get(int(dof), v) == v
                    val[int(dof)] = v
        rows = sorted(val)
        n = mf.nbdof()
        B = gf.Spmat("copy", gf.Spmat("identity", n), rows, list(range(n)))
        md.add_variable(mult, len(rows))
        md.add_constraint_with_multipliers(var, mult, B, np.array([val[r] for r in rows]))
        return rows

    top_rows = constraints(mfu1, "u1", "mult1", [(TOP, [2], DZ), (UX0, [0], 0.0), (UY0, [1], 0.0)])
    constraints(mfu2, "u2", "mult2", [(BOTTOM, [0, 1, 2], 0.0), (LX0, [0], 0.0), (LY0, [1], 0.0)])
    top_z = np.asarray(mfu1.basic_dof_on_region(TOP), dtype=np.int64).ravel()
    top_z = top_z[top_z % 3 == 2]

    # contact: h = mean slave edge length near the apex
    sides = [(k, s) for (bn, k, s) in side_sets["upper_contact"]]
    edges = []
    for k, s in sides:
        p = X[:, up.conn[k][list(EXO_SIDE_NODES[s])]]
        if np.linalg.norm(p.mean(axis=1) - np.array([0, 0, 1.0])) <= 0.25:
            edges += [np.linalg.norm(p[:, i] - p[:, (i + 1) % 3]) for i in range(3)]
    h = float(np.mean(edges))
    r = a.r if a.r else E / h
    md.add_initialized_data("r", [r])
    md.add_filtered_fem_variable("lambda1", mfu1, SLAVE)  # vector contact stress on the slave
    md.add_initialized_data("f", [0.0])  # frictionless
    md.add_initialized_data("alpha", [1.0])
    ind = md.add_integral_large_sliding_contact_brick_raytracing("r", a.release, "f", "alpha", a.version)
    md.add_slave_contact_boundary_to_large_sliding_contact_brick(ind, mim1c, SLAVE, "u1", "lambda1")
    md.add_master_contact_boundary_to_large_sliding_contact_brick(ind, mim2c, MASTER, "u2")
    if a.init_dz:
        U1 = md.variable("u1").copy()
        U1[2::3] = a.init_dz
        md.set_variable("u1", U1)
    t_setup = time.perf_counter() - T_START

    t0 = time.perf_counter()
    args = ["max_res", a.tol, "max_iter", a.max_iter]
    if a.noisy:
        args.append("noisy")
    if a.lsolver:
        args += ["lsolver", a.lsolver]
    if a.lsearch:
        args += ["lsearch", a.lsearch]
    err = None
    try:
        nit, conv = md.solve(*args)
    except Exception as ex:  # report GetFEM's error text
        nit, conv, err = -1, 0, str(ex)
    t_solve = time.perf_counter() - t0

    md.assembly("build_rhs")
    res = float(np.linalg.norm(md.rhs()))
    # reaction on upper_top (z): internal force of the upper body on the top z dofs
    expr = "(lambda*Div_u1*Id(3)+mu*(Grad_u1+Grad_u1')):Grad_Test_u1"
    fint = np.asarray(gf.asm_generic(mim1, 1, expr, -1, md))
    if len(fint) == md.nbdof():
        i0, n = md.interval_of_variable("u1")
        fint = fint[i0:i0 + n]
    reac_top_z = float(np.sum(fint[top_z]))  # force the top face exerts on the body, z
    F = 4 * abs(reac_top_z)
    mult1 = np.asarray(md.variable("mult1"))
    reac_mult = float(np.sum(mult1[[i for i, d in enumerate(top_rows) if d % 3 == 2]]))

    # nodal pressure at the slave nodes: -lambda.n, n outward normal of the upper sphere
    sd = np.asarray(mfu1.basic_dof_on_region(SLAVE), dtype=np.int64).ravel()
    assert np.array_equal(sd[0::3] + 1, sd[1::3]) and np.array_equal(sd[0::3] + 2, sd[2::3])
    xyz = np.asarray(mfu1.basic_dof_nodes(sd[0::3]))
    lam_v = np.asarray(md.variable("lambda1")).reshape(-1, 3).T
    assert lam_v.shape == xyz.shape
    nrm = (xyz - UPPER_CENTRE[:, None]) / R
    p = -np.sum(lam_v * nrm, axis=0)
    with open(a.out + "_pressure.csv", "w") as f:
        f.write("x,y,z,p\n")
        for j in range(xyz.shape[1]):
            f.write("%.12g,%.12g,%.12g,%.12g\n" % (xyz[0, j], xyz[1, j], xyz[2, j], p[j]))

    out = {
        "exo": os.path.basename(a.exo), "nodes": int(n_nodes), "ndof": int(md.nbdof()),
        "r": r, "h_contact": h, "release": a.release, "init_dz": a.init_dz, "lsolver": a.lsolver,
        "iterations": int(nit), "converged": int(conv), "error": err,
        "t_setup": t_setup, "t_solve": t_solve, "t_script": time.perf_counter() - T_START,
        "residual": res, "rel_residual": res / max(abs(reac_top_z), 1e-300),
        "F": F, "reaction_top_z": reac_top_z, "reaction_top_z_multipliers": reac_mult,
        "p_max": float(p.max()), "p_min": float(p.min()), "n_pos": int(np.sum(p > 0)),
        "nslave": int(len(p)),
    }
    print("RESULT " + json.dumps(out), flush=True)


if __name__ == "__main__":
    main()
