"""Shallow ironing on Kratos' own 3D mesh (docs/verification.md #19, kratos3d_frictionless.yaml)
solved independently with GetFEM 5.4 (Poulios & Renard's code and large-sliding contact), to judge
whether Grout's 3D F_y plateau (about 5 % above the published curve) comes from the model or
from Grout (docs/verification.md, "Shallow ironing", "The reference's own 3D model").

What: the same 3D frictionless problem as kratos3d_frictionless.yaml, on the same Exodus mesh
(kratos3d.exo: Kratos' shallow_ironing3D.mdpa converted by tools/mdpa_to_exodus.py; or, with
--layout slab, an ironing_mesh.py --layers mesh, as slab_ci_frictionless.yaml), read by
../contact_common/getfem_model.py (shared with the 2D checks, as are its Newton, load stepping
and CSV writer):
- two bodies, each its own GetFEM mesh: the die (block parts_parts_auto1, E = 6.896e9) and the
  block (parts_parts_auto2, E = 6.896e8), nu = 0.32 both; trilinear QK(3,1) with 2x2x2 Gauss,
  as Grout's HEX8 (GetFEM's vertex order is lexicographic, (0,0,0), (1,0,0), (0,1,0), (1,1,0),
  (0,0,1), ...: Exodus 1, 2, 4, 3, 5, 6, 8, 7; every element's Jacobian is checked > 0 at its
  corners);
- Grout's compressible Neo-Hookean in GWFL, W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2,
  in full 3D;
- supports as the yaml's (nodal, as Grout's dirichlet): the block bottom
  (displacement_displacement_auto1) clamped by simplification; the die top
  (displacement_displacement_auto2) u = (0, -0.8 t, 0) for t <= 1, then (10 (t - 1), -0.8, 0),
  by simplification; u_z = 0 on z = 0 of both bodies (displacement_displacement_auto3; none
  with --layout slab_full, the slab's full model mirrored about its mid-plane) with a
  scalar multiplier per z = 0 node that is not already clamped (a QK(3,1) field restricted to
  those nodes, coupled to u_z on the z = 0 faces: u_z = 0 at exactly those nodes, u_x, u_y
  free; GetFEM's generalized Dirichlet condition with multipliers would also constrain the
  clamped nodes twice, and it has no simplification version);
- contact: the integral large sliding contact brick (augmented Lagrangian, raytracing on the
  current geometry), frictionless or Coulomb --mu (the slip measured from the start of the
  step, as the 2D checks), slave = the die's arc (side set
  contact_contact_auto1_auto1), master = the block top (contact_contact_auto1_auto2),
  multiplier on the slave's nodes (QK(3,1) trace), augmentation --r (Pa/m, default
  --r-factor x E_block / h, h the mean edge of the die's arc faces), release distance
  --release (default 0.2);
- checked at every converged step: the die top follows the prescription, |u_z| on z = 0
  (and max |u_x|, |u_y| there, which must not vanish), det F > 0 at every Gauss point, and the
  die's equilibrium in x, y (contact resultant + support force = 0);
- load path: the times of --times (a Grout summary CSV: its column "time", i.e. the steps
  Grout took) and of --add-times, or --steps equal steps to --t-end; Newton from the previous
  state, a step that does not converge is halved (up to 6 times: getfem_model.advance_step);
- output (--csv), one row per step: time, F_x, F_y (N, the force the die's top support puts
  on the die, with the signs of check.py: F_x = reaction_displacement_displacement_auto2_x,
  F_y = -reaction_displacement_displacement_auto2_y), F_z, the contact multiplier's resultant
  on the die (x, y, z), Newton iterations, CPU seconds of the step. The support force is the
  die's internal force summed over the die-top nodes (asm of P : Grad_Test_u over the die; the
  z = 0 multiplier acts along z only, the contact on the arc only).
Measured (2 cores, shared, nice 5), at Grout's 39 steps + t = 1.0: 40 steps, 376 Newton
iterations, 19 min CPU (15 to 25 s a step; 1 or 2 cut-backs on the sliding steps of 0.0425 up
to t = 1.23, and at t = 1.68); F_y within 0.2 % of Grout's at each of Grout's steps from t =
0.255 on (-0.6 % and -0.4 % at the first two), plateau 1.3 <= t <= 1.7 3.541e8 N (Grout
3.538e8, +0.09 %; published 3.376e8). --r-factor 10 (to t = 1.38) moves F_y by at most 0.35 %
(first steps), 0.04 % while sliding, and needs 2 to 4 cut-backs per sliding step.

How to run (from build/ironing_kratos3d, which holds kratos3d.exo and Grout's
np1/kratos3d_frictionless.csv; 3 x 15 876 displacement dofs; about 20 min):
  nice -n 5 /usr/bin/python3 ../../inputs/shallow_ironing/getfem_ironing_3d.py \
      --mesh kratos3d.exo --times np1/kratos3d_frictionless.csv --add-times 1.0 \
      --csv getfem_kratos3d_frictionless.csv
(--t-end 0.34 with --times stops there: a sanity check.) The CI check (ctest
shallow_ironing/getfem_3d, 9 s), on the CI mesh extruded in one layer (1 064 nodes):
  getfem_ironing_3d.py --layout slab --mesh slab_ci.exo --times np1/slab_ci_frictionless.csv \
      --t-end 1.2 --compare np1/slab_ci_frictionless.csv np2/slab_ci_frictionless.csv
With --mu 0.3 on that one-layer mesh GetFEM stops at t = 0.69 while pressing (the
z-friction of the slave nodes on z = 0, held in z on both sides, acts on the supports only;
Grout writes e_z.lambda = 0 in that tangent's row, docs/input.md "Friction on a plane of
symmetry"). Its full model, mirrored about z = 0 with nothing held there, runs through: the
frictional CI check (ctest shallow_ironing/getfem_3d_frictional, 18 s CPU) is
  getfem_ironing_3d.py --layout slab_full --mesh slab_ci_full.exo --mu 0.3 \
      --times np1/slab_ci_full_frictional.csv --t-end 1.2 \
      --compare np1/slab_ci_full_frictional.csv
on ironing_mesh.py slab_ci_full.exo --nx-block 48 --ny-block 8 --n-die 12 --thickness 2
--layers 2 (slab_ci_full_frictional.yaml): 240 Newton iterations, 5 cut-backs (t = 1.08 to
1.2); F_y within 0.20 %, F_x within 0.31 % of Grout's largest F_y; F_z at round-off.
--compare: F_x and F_y against Grout's at every step, max difference over the path relative
to Grout's largest F_y within --tol (0.5 %; frictionless one-layer slab: measured 0.24 % and
0.33 %), and the Grout runs against each other to 1e-10; --nu 0.34 (GetFEM only) gives 0.71 %
and fails. Needs python3-getfem (Debian), numpy, netCDF4. Exit code 77
when GetFEM is missing, 1 when a step does not converge or a comparison fails.
"""
import argparse
import csv
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "contact_common"))
from getfem_model import (Body, add_large_sliding_contact, add_stepping_arguments,  # noqa: E402
                          advance_step, equilibrium_rows, import_getfem, lame, read_exodus,
                          neo_hookean_piola, write_csv)

E_DIE, E_BLOCK, NU = 6.896e9, 6.896e8, 0.32
# The mesh's names (--layout): element blocks die, block; node sets of the block's bottom
# (clamped), the die's top (prescribed) and z = 0 (u_z = 0); side sets of the die's arc
# (slave) and the block's top (master).
LAYOUTS = {
    # Kratos' shallow_ironing3D.mdpa through tools/mdpa_to_exodus.py
    "kratos": dict(die="parts_parts_auto1", block="parts_parts_auto2",
                   bottom="displacement_displacement_auto1",
                   top="displacement_displacement_auto2",
                   z0=("displacement_displacement_auto3",),
                   slave="contact_contact_auto1_auto1", master="contact_contact_auto1_auto2"),
    # ironing_mesh.py --thickness T --layers N (the slab3d_*.yaml meshes)
    "slab": dict(die="die", block="block", bottom="block_bottom_nodes", top="die_top_nodes",
                 z0=("block_z0_nodes", "die_z0_nodes"), slave="die_bottom", master="block_top"),
    # the same names, the full model (the slab mirrored about its mid-plane, as
    # slab_ci_full_frictional.yaml): nothing held on z = 0
    "slab_full": dict(die="die", block="block", bottom="block_bottom_nodes",
                      top="die_top_nodes", z0=(), slave="die_bottom", master="block_top"),
}
# Exodus HEX8 sides (1-based nodes); GetFEM QK(3,1) vertex k is Exodus node EXO_OF_GF[k] + 1.
HEX_SIDES = ((1, 2, 6, 5), (2, 3, 7, 6), (3, 4, 8, 7), (1, 5, 8, 4), (1, 4, 3, 2), (5, 6, 7, 8))
EXO_OF_GF = [0, 1, 3, 2, 4, 5, 7, 6]


def die_top(t):
    """Prescribed displacement of the die's top (the yaml's push_y, drag_x, top_z)."""
    return np.array([0.0 if t <= 1 else 10 * (t - 1), -0.8 * t if t <= 1 else -0.8, 0.0])


def read_exodus_3d(path, names_of):
    """getfem_model.read_exodus in 3D (HEX8), refusing a mesh without the layout's names."""
    x, blocks, nsets, ssets, conn_all = read_exodus(path, dim=3)
    for need in (names_of["die"], names_of["block"], names_of["bottom"], names_of["top"],
                 *names_of["z0"], names_of["slave"], names_of["master"]):
        if need not in blocks and need not in nsets and need not in ssets:
            raise SystemExit("%s: %s missing (--layout?)" % (path, need))
    return x, blocks, nsets, ssets, conn_all


def side_faces(ssets, conn_all, name):
    """The faces of side set `name`, each its 4 Exodus nodes (in the side's cyclic order)."""
    return np.array([conn_all[el][np.array(HEX_SIDES[side - 1]) - 1]
                     for el, side in ssets[name]])


def min_corner_jacobian(p):
    """Smallest corner Jacobian determinant of trilinear hexes, p: (elements, 8, 3) in GetFEM's
    lexicographic vertex order (vertex i + 2 j + 4 k at (i, j, k))."""
    worst = np.inf
    for i in (0, 1):
        for j in (0, 1):
            for k in (0, 1):
                def v(a, b, c):
                    return p[:, a + 2 * b + 4 * c]
                ex = v(1, j, k) - v(0, j, k)
                ey = v(i, 1, k) - v(i, 0, k)
                ez = v(i, j, 1) - v(i, j, 0)
                worst = min(worst, np.einsum("ij,ij->i", ex, np.cross(ey, ez)).min())
    return worst


class Body3D(Body):
    """One GetFEM mesh (GT_QK(3,1)) built from one Exodus HEX8 block (pids, face_region: Body's)."""

    def __init__(self, gf, x, conn, name):
        self.mesh = gf.Mesh("empty", 3)
        pts = x[conn[:, EXO_OF_GF]]                      # (elements, 8, 3)
        jmin = min_corner_jacobian(pts)
        if not jmin > 0:
            raise SystemExit("block %s: corner Jacobian %.3g <= 0 (node order?)" % (name, jmin))
        self.jmin = jmin
        self.mesh.add_convex(gf.GeoTrans("GT_QK(3,1)"), np.transpose(pts, (2, 1, 0)))
        self.name = name


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--mesh", default="kratos3d.exo")
    ap.add_argument("--layout", default="kratos", choices=sorted(LAYOUTS),
                    help="the mesh's block and set names")
    add_stepping_arguments(ap, steps=34, t_end=1.7, release=0.2, max_res=1.0)
    ap.add_argument("--add-times", type=float, nargs="*", default=[],
                    help="extra step times (merged with --times / --steps)")
    ap.add_argument("--mu", type=float, default=0.0, help="Coulomb coefficient (0: frictionless)")
    ap.add_argument("--nu", type=float, default=NU, help="Poisson's ratio of both bodies")
    ap.add_argument("--compare", nargs="*", default=[], metavar="GROUT_CSV",
                    help="Grout summary CSVs of the same run, compared step by step")
    ap.add_argument("--tol", type=float, default=5e-3,
                    help="--compare: max |F difference| / Grout's max F_y, over the path")
    a = ap.parse_args()
    gf = import_getfem("getfem_ironing_3d.py")
    if gf is None:
        return 77
    # The raytracing warns "Inverted element" on Newton iterates of the large sliding steps
    # (those iterates are not kept; each converged state is checked: J > 0 at every Gauss
    # point); --noisy shows them.
    gf.util_warning_level(1 if a.noisy else 0)
    t0 = time.process_time()
    n = LAYOUTS[a.layout]
    x, blocks, nsets, ssets, conn_all = read_exodus_3d(a.mesh, n)
    die, blk = Body3D(gf, x, blocks[n["die"]], "die"), Body3D(gf, x, blocks[n["block"]], "block")
    slave_faces = side_faces(ssets, conn_all, n["slave"])
    master_faces = side_faces(ssets, conn_all, n["master"])
    top_nodes, bottom_nodes = nsets[n["top"]], nsets[n["bottom"]]
    has_z0 = len(n["z0"]) > 0  # slab_full: no z = 0 sets, no regions Z0D, Z0B, no multiplier
    z0 = np.unique(np.concatenate([nsets[name] for name in n["z0"]])) if has_z0 else None
    TOP, BOTTOM, SLAVE, MASTER, Z0D, Z0B = 1, 2, 3, 4, 5, 6
    counts = (die.face_region(TOP, top_nodes, x),
              blk.face_region(BOTTOM, bottom_nodes, x),
              die.face_region(SLAVE, np.unique(slave_faces), x),
              blk.face_region(MASTER, np.unique(master_faces), x))
    if has_z0:
        counts += (die.face_region(Z0D, z0, x), blk.face_region(Z0B, z0, x))

    def exodus_faces(conn, nodes):
        """Element sides (Exodus HEX8 sides) of `conn` with all 4 nodes among `nodes`."""
        inside = np.isin(conn, nodes)
        return sum(int(inside[:, np.array(sd) - 1].all(axis=1).sum()) for sd in HEX_SIDES)
    expect = (exodus_faces(blocks[n["die"]], top_nodes),
              exodus_faces(blocks[n["block"]], bottom_nodes), len(slave_faces),
              len(master_faces))
    z0_ok = True
    if has_z0:
        z0_in = (die.pids(z0, x) >= 0).sum() + (blk.pids(z0, x) >= 0).sum()
        expect += (exodus_faces(blocks[n["die"]], z0), exodus_faces(blocks[n["block"]], z0))
        z0_ok = z0_in == len(z0) and not np.abs(x[z0, 2]).max() > 0
    print("mesh %s: die %d nodes %d hexes, block %d nodes %d hexes; smallest corner Jacobians "
          "%.3g, %.3g" % (a.mesh, die.mesh.nbpts(), die.mesh.nbcvs(), blk.mesh.nbpts(),
                          blk.mesh.nbcvs(), die.jmin, blk.jmin))
    print(("faces: die top %d, block bottom %d, die arc %d, block top %d"
           + (", z = 0: die %d, block %d" if has_z0 else " (nothing held on z = 0)")) % counts)
    if counts != expect or not z0_ok:
        raise SystemExit("%s: faces found %s, expected %s" % (a.mesh, counts, expect))

    im = gf.Integ("IM_GAUSS_PARALLELEPIPED(3,3)")  # 2x2x2 Gauss
    mfd, mfb = gf.MeshFem(die.mesh, 3), gf.MeshFem(blk.mesh, 3)
    for mf in (mfd, mfb):
        mf.set_fem(gf.Fem("FEM_QK(3,1)"))
    mimd, mimb = gf.MeshIm(die.mesh, im), gf.MeshIm(blk.mesh, im)
    md = gf.Model("real")
    md.add_fem_variable("ud", mfd)
    md.add_fem_variable("ub", mfb)
    for var, body, mim, sfx in (("ud", die, mimd, "d"), ("ub", blk, mimb, "b")):
        lam, mu = lame(E_DIE if body.name == "die" else E_BLOCK, a.nu)
        md.add_initialized_data("lam_" + sfx, [lam])
        md.add_initialized_data("mu_" + sfx, [mu])
        md.add_nonlinear_term(mim, neo_hookean_piola(var, sfx, 3) + ":Grad_Test_" + var)
    md.add_initialized_data("zero", [0.0, 0.0, 0.0])
    md.add_initialized_data("top", [0.0, 0.0, 0.0])
    md.add_Dirichlet_condition_with_simplification("ub", BOTTOM, "zero")
    md.add_Dirichlet_condition_with_simplification("ud", TOP, "top")
    md.add_initialized_data("ez", [0.0, 0.0, 1.0])

    # u_z = 0 on z = 0: a multiplier z_<var> per z = 0 node not already clamped (a partial
    # QK(3,1) field), int_{z = 0} (z_v u_z + u_z* z_v) da: the face mass matrix restricted to
    # those nodes is regular, so u_z = 0 at each of them. None without z = 0 sets (slab_full).
    held = (("ud", mfd, mimd, Z0D, TOP), ("ub", mfb, mimb, Z0B, BOTTOM)) if has_z0 else ()
    zdofs, keep_alive = {}, []  # (the partial MeshFem needs its parent alive)
    for var, mf, mim, z0r, fixed in held:
        mfs = gf.MeshFem(mf.linked_mesh(), 1)
        mfs.set_fem(gf.Fem("FEM_QK(3,1)"))
        if not np.allclose(mfs.basic_dof_nodes(), mf.basic_dof_nodes()[:, ::3]):
            raise SystemExit("%s: scalar and vector dofs are not interleaved" % var)
        keep = np.setdiff1d(mfs.basic_dof_on_region(z0r), mfs.basic_dof_on_region(fixed))
        mfz = gf.MeshFem("partial", mfs, keep)
        keep_alive.append((mfs, mfz))
        md.add_fem_variable("z_" + var, mfz)
        md.add_linear_term(mim, "z_%s*(Test_%s.ez) + (%s.ez)*Test_z_%s" % (var, var, var, var), z0r)
        zdofs[var] = np.asarray(mfs.basic_dof_on_region(z0r), int)
        print("u_z = 0: %s, %d nodes on z = 0 (%d by the multiplier, %d clamped)"
              % (var, len(zdofs[var]), len(keep), len(zdofs[var]) - len(keep)))

    h = np.linalg.norm(x[np.roll(slave_faces, -1, axis=1)] - x[slave_faces], axis=2).mean()
    r = a.r if a.r is not None else a.r_factor * E_BLOCK / h
    print("contact: r = %.4g Pa/m (h = %.4g), release distance %.3g, mu = %g"
          % (r, h, a.release, a.mu))
    _, w = add_large_sliding_contact(gf, md, r, a.release, a.mu,
                                       ("ud", mfd, die.mesh, mimd, SLAVE),
                                       ("ub", mfb, mimb, MASTER), dim=3)

    # Equilibrium rows: all displacement dofs but the supported ones (the z = 0 rows hold the
    # multiplier's reaction, so they are in); the die top's dofs (x, y, z interleaved).
    free, supported = equilibrium_rows(md, (("ud", mfd, TOP), ("ub", mfb, BOTTOM)))
    top_dofs = supported["ud"]
    print("dofs: %d in all, %d equilibrium rows" % (md.nbdof(), len(free)))
    i0d = md.interval_of_variable("ud")[0]
    if len(top_dofs) != 3 * len(top_nodes):
        raise SystemExit("die top: %d dofs for %d nodes" % (len(top_dofs), len(top_nodes)))
    top_c = [top_dofs[top_dofs % 3 == c] for c in range(3)]
    internal = "(%s):Grad_Test_ud" % neo_hookean_piola("ud", "d", 3)
    gauss = [(var, gf.MeshImData(mim, -1, [])) for var, mim in (("ud", mimd), ("ub", mimb))]

    def min_jacobian():
        """Smallest det F over the Gauss points of both bodies."""
        return min(np.min(md.interpolation("Det(Id(3)+Grad_%s)" % var, g)) for var, g in gauss)

    def support_force():
        """The die-top support's force on the die: the die's internal force there."""
        f = np.asarray(gf.asm_generic(mimd, 1, internal, -1, md)).ravel()
        f = f[i0d:i0d + mfd.nbdof()]
        return [f[d].sum() for d in top_c]

    def contact_force():
        """Resultant of the multiplier lam_c on the die's arc (GetFEM's multiplier: the nominal
        traction the block puts on the slave, integrated on the reference boundary)."""
        return [float(np.asarray(gf.asm_generic(mimd, 0, "lam_c(%d)" % c, SLAVE, md)).ravel()[0])
                for c in (1, 2, 3)]

    if a.times:
        tt = np.array([float(rw["time"]) for rw in csv.DictReader(open(a.times))])
    else:
        tt = a.t_end * np.arange(1, a.steps + 1) / a.steps
    tt = np.unique(np.round(np.concatenate([tt, a.add_times]), 12))
    tt = tt[(tt > 0) & (tt <= a.t_end + 1e-12)]
    rows = []
    t_prev = 0.0
    for step, t_target in enumerate(tt, 1):
        c0 = time.process_time()
        total_it, cuts, conv = advance_step(
            gf, md, free, lambda t: md.set_variable("top", die_top(t)), step, t_prev, t_target,
            w, a.max_res, a.noisy, failed=lambda: write(a.csv, rows))
        if not conv:
            return 1
        ud, ub = np.asarray(md.variable("ud")), np.asarray(md.variable("ub"))
        err = max(np.abs(ud[top_c[c]] - die_top(t_target)[c]).max() for c in range(3))
        if err > 1e-9:
            raise SystemExit("step %d: the die's top is off by %.2e" % (step, err))
        z0_note = ""
        if has_z0:
            uz = max(np.abs(ud[3 * zdofs["ud"] + 2]).max(),
                     np.abs(ub[3 * zdofs["ub"] + 2]).max())
            uxy = np.abs(ub[np.concatenate([3 * zdofs["ub"], 3 * zdofs["ub"] + 1])]).max()
            if uz > 1e-10:
                raise SystemExit("step %d: |u_z| = %.2e on z = 0" % (step, uz))
            z0_note = "; z = 0: |u_z| %.1e, max |u_x|, |u_y| %.3g" % (uz, uxy)
        jmin = min_jacobian()
        if not jmin > 0:
            raise SystemExit("step %d: det F = %.3g at a Gauss point" % (step, jmin))
        fx, fy, fz = support_force()
        lx, ly, lz = contact_force()
        cpu = time.process_time() - c0
        rows.append((t_target, fx, -fy, fz, lx, ly, lz, total_it, cpu))
        print("step %3d  t = %.5f  F_x = %+.5e  F_y = %+.5e  F_z = %+.3e  newton %d%s  "
              "(|contact + support|_xy %.1e N%s; min det F %.3f)  %.0f s"
              % (step, t_target, fx, -fy, fz, total_it, " (%d cut-backs)" % cuts if cuts else "",
                 np.hypot(lx + fx, ly + fy), z0_note, jmin, cpu), flush=True)
        t_prev = t_target
    write(a.csv, rows)
    print("getfem_ironing_3d.py: %d steps, %.1f s CPU" % (len(rows), time.process_time() - t0))
    return compare(rows, a.compare, n["top"], a.tol)


def compare(rows, grout_csvs, top, tol):
    """GetFEM's F_x, F_y against each Grout summary CSV at the same times: the largest
    differences over the path relative to Grout's largest F_y, within tol; the Grout CSVs
    (1 and 2 ranks) against each other to 1e-10. Returns the exit code (1: a difference above
    its tolerance, or other times)."""
    failed = False
    t, fx, fy = (np.array([r[i] for r in rows]) for i in (0, 1, 2))
    first = None
    for path in grout_csvs:
        g = list(csv.DictReader(open(path)))
        tg = np.array([float(r["time"]) for r in g])
        if len(tg) != len(t) or np.abs(tg - t).max() > 1e-12:
            print("%s: other times than GetFEM's" % path)
            failed = True
            continue
        gx = np.array([float(r["reaction_%s_x" % top]) for r in g])
        gy = -np.array([float(r["reaction_%s_y" % top]) for r in g])
        dy, dx = np.abs(fy - gy).max() / gy.max(), np.abs(fx - gx).max() / gy.max()
        print("GetFEM - Grout (%s), %d steps, relative to Grout's max F_y %.4g N: max |F_y "
              "difference| %.2e, max |F_x difference| %.2e (tolerance %g)"
              % (path, len(t), gy.max(), dy, dx, tol))
        failed = failed or not (dy <= tol and dx <= tol)
        if first is None:
            first = (path, gx, gy)
        else:  # Grout on another number of ranks: the same answer to round-off
            d = max(np.abs(gx - first[1]).max(), np.abs(gy - first[2]).max()) / gy.max()
            print("Grout %s against %s: %.2e (tolerance 1e-10)" % (path, first[0], d))
            failed = failed or not d <= 1e-10
    if grout_csvs:
        print("getfem_ironing_3d.py: %s" % ("FAILED" if failed else "GetFEM agrees with Grout"))
    return 1 if failed else 0


def write(path, rows):
    if path and os.path.dirname(path):
        os.makedirs(os.path.dirname(path), exist_ok=True)
    write_csv(path, "time,F_x,F_y,F_z,contact_x,contact_y,contact_z,newton,cpu_s",
              "%.16g,%.16g,%.16g,%.16g,%.16g,%.16g,%.16g,%d,%.1f", rows)


if __name__ == "__main__":
    sys.exit(main())
