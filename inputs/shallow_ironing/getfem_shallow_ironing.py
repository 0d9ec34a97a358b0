"""Shallow ironing, plane strain (docs/verification.md #19) solved independently with GetFEM 5.4
(Poulios & Renard's code and large-sliding contact), to judge whether Grout's F_x/F_y > mu and its
F_y plateau come from the model or from Grout (docs/verification.md, "Shallow ironing, plane
strain", "Independent check with GetFEM").

What: the same plane-strain problem as ci_frictional.yaml / ci_frictionless.yaml, on the same
Exodus mesh (ironing_mesh.py; the ctest writes build/inputs/shallow_ironing/shallow_ci.exo),
read with netCDF4 (../contact_common/getfem_model.py, shared with the double arc's and the
press fit's GetFEM checks):
- two bodies, each its own GetFEM mesh: the die (block "die", E = 6.896e9) and the block
  (block "block", E = 6.896e8), nu = 0.32 both;
- Grout's compressible Neo-Hookean in GWFL (W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2,
  F33 = 1); bilinear QK(2,1) with 2x2 Gauss, as Grout's QUAD4;
- supports, nodal as Grout's dirichlet (by simplification): the block bottom (block_bottom
  nodes) clamped; the die top (die_top_nodes) u = (0, -0.8 t) for t <= 1, then
  (10 (t - 1), -0.8);
- contact: the integral large sliding contact brick (augmented Lagrangian, raytracing on the
  current geometry), frictionless or Coulomb --mu (the slip measured from the displacement at
  the start of the step), slave = the die bottom (side set die_bottom), master = the block top
  (block_top), multiplier on the slave's nodes (QK(2,1) trace), augmentation --r (Pa/m,
  default --r-factor x E_block / h, h the mean length of the die's bottom faces), release
  distance --release (default 0.2: with 0.1 the frictionless run stops at t = 0.7);
- load path: the times of --times (a Grout summary CSV: its column "time", i.e. the steps
  Grout took) or --steps equal steps to --t-end; Newton from the previous state, a step that
  does not converge is halved (up to 6 times: getfem_model.advance_step);
- output (--csv), one row per step: time, F_x, F_y (N per unit thickness, the force the die's
  top support puts on the die, with the signs of check.py: F_x = reaction_die_top_nodes_x,
  F_y = -reaction_die_top_nodes_y), the contact resultants on the die from the multiplier
  (normal and tangential parts along the die's current normal), Newton iterations.
  The support force is the die's internal force summed over the die-top nodes (asm of
  P : Grad_Test_u over the die; no other load acts on those nodes).

How to run (from a folder holding shallow_ci.exo and Grout's np1/ci_frictional.csv):
  /usr/bin/python3 inputs/shallow_ironing/getfem_shallow_ironing.py --mesh shallow_ci.exo \
      --mu 0.3 --times np1/ci_frictional.csv --csv getfem_ci_frictional.csv
and getfem_compare.py for the numbers and the figure. Needs python3-getfem (Debian), numpy,
netCDF4. Exit code 77 (ctest: skipped) when GetFEM is missing, 1 when a step does not
converge.
"""
import argparse
import csv
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "contact_common"))
from getfem_model import (Body, add_large_sliding_contact, add_neo_hookean,  # noqa: E402
                          add_stepping_arguments, advance_step, equilibrium_rows,
                          neo_hookean_piola, import_getfem, read_mesh, side_nodes, write_csv)

MODULI = {"die": (6.896e9, 0.32), "block": (6.896e8, 0.32)}


def die_top(t):
    """Prescribed displacement of the die's top (the yamls' push_y, drag_x)."""
    return np.array([0.0 if t <= 1 else 10 * (t - 1), -0.8 * t if t <= 1 else -0.8])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--mesh", default="shallow_ci.exo")
    ap.add_argument("--mu", type=float, default=0.3, help="Coulomb coefficient (0: frictionless)")
    add_stepping_arguments(ap, steps=56, t_end=1.4, release=0.2, max_res=1.0)
    a = ap.parse_args()
    gf = import_getfem("getfem_shallow_ironing.py")
    if gf is None:
        return 77
    t0 = time.process_time()
    x, blocks, nsets, ssets, conn_all = read_mesh(a.mesh, MODULI)
    die = Body(gf, x, blocks, ["die"], 10)
    blk = Body(gf, x, blocks, ["block"], 20)
    TOP, BOTTOM, SLAVE, MASTER = 1, 2, 3, 4
    counts = (die.face_region(TOP, nsets["die_top_nodes"], x),
              blk.face_region(BOTTOM, nsets["block_bottom_nodes"], x),
              die.face_region(SLAVE, side_nodes(ssets, conn_all, "die_bottom"), x),
              blk.face_region(MASTER, side_nodes(ssets, conn_all, "block_top"), x))
    expect = (len(nsets["die_top_nodes"]) - 1, len(nsets["block_bottom_nodes"]) - 1,
              len(ssets["die_bottom"]), len(ssets["block_top"]))
    if counts != expect:
        raise SystemExit("%s: faces found %s, expected %s" % (a.mesh, counts, expect))
    print("mesh %s: die %d nodes %d quads, block %d nodes %d quads"
          % (a.mesh, die.mesh.nbpts(), die.mesh.nbcvs(), blk.mesh.nbpts(), blk.mesh.nbcvs()))

    im = "IM_GAUSS_PARALLELEPIPED(2,3)"  # 2x2 Gauss
    mfd, mfb = gf.MeshFem(die.mesh, 2), gf.MeshFem(blk.mesh, 2)
    for mf in (mfd, mfb):
        mf.set_fem(gf.Fem("FEM_QK(2,1)"))
    mimd, mimb = gf.MeshIm(die.mesh, gf.Integ(im)), gf.MeshIm(blk.mesh, gf.Integ(im))
    md = gf.Model("real")
    md.add_fem_variable("ud", mfd)
    md.add_fem_variable("ub", mfb)
    add_neo_hookean(gf, md, die, "ud", mimd, "d", MODULI)
    add_neo_hookean(gf, md, blk, "ub", mimb, "b", MODULI)
    md.add_initialized_data("zero", [0.0, 0.0])
    md.add_initialized_data("top", [0.0, 0.0])
    md.add_Dirichlet_condition_with_simplification("ub", BOTTOM, "zero")
    md.add_Dirichlet_condition_with_simplification("ud", TOP, "top")

    slave = side_nodes(ssets, conn_all, "die_bottom")
    seg = np.diff(x[slave[np.argsort(x[slave, 0])]], axis=0)
    h = np.hypot(seg[:, 0], seg[:, 1]).mean()
    r = a.r if a.r is not None else a.r_factor * MODULI["block"][0] / h
    print("contact: r = %.4g Pa/m (h = %.4g), release distance %.3g, mu = %g"
          % (r, h, a.release, a.mu))
    ind, w = add_large_sliding_contact(gf, md, r, a.release, a.mu,
                                       ("ud", mfd, die.mesh, mimd, SLAVE),
                                       ("ub", mfb, mimb, MASTER))

    # Equilibrium rows: all but the supported dofs; the die top's dofs (x, y interleaved).
    free, supported = equilibrium_rows(md, (("ud", mfd, TOP), ("ub", mfb, BOTTOM)))
    top_dofs = supported["ud"]
    i0d = md.interval_of_variable("ud")[0]
    if len(top_dofs) != 2 * len(nsets["die_top_nodes"]):
        raise SystemExit("die top: %d dofs for %d nodes" % (len(top_dofs),
                                                            len(nsets["die_top_nodes"])))
    top_x = top_dofs[np.isin(top_dofs, np.arange(0, mfd.nbdof(), 2))]
    top_y = top_dofs[np.isin(top_dofs, np.arange(1, mfd.nbdof(), 2))]
    internal = "(%s):Grad_Test_ud" % neo_hookean_piola("ud", "d")

    def support_force():
        """The die-top support's force on the die: the die's internal force there."""
        f = np.asarray(gf.asm_generic(mimd, 1, internal, -1, md)).ravel()
        f = f[i0d:i0d + mfd.nbdof()]
        return f[top_x].sum(), f[top_y].sum()

    def contact_force():
        """Resultant of the multiplier lam_c on the die's bottom (GetFEM's multiplier: the
        nominal traction the block puts on the slave, integrated on the reference boundary):
        its part along the die's current normal n = F^-T N / |F^-T N|, (lam . n) n, and the
        whole. The rest is the friction; the die's equilibrium: whole + support = 0."""
        def integral(e):
            return float(np.asarray(gf.asm_generic(mimd, 0, e, SLAVE, md)).ravel()[0])
        nrm = "(Normalized(Inv(Id(2)+Grad_ud)'*Normal))"
        ln = "lam_c.%s" % nrm
        return (integral("%s*%s(1)" % (ln, nrm)), integral("%s*%s(2)" % (ln, nrm)),
                integral("lam_c(1)"), integral("lam_c(2)"))

    if a.times:
        tt = np.array([float(rw["time"]) for rw in csv.DictReader(open(a.times))])
    else:
        tt = a.t_end * np.arange(1, a.steps + 1) / a.steps
    rows = []
    t_prev = 0.0
    for step, t_target in enumerate(tt, 1):
        total_it, cuts, conv = advance_step(
            gf, md, free, lambda t: md.set_variable("top", die_top(t)), step, t_prev, t_target,
            w, a.max_res, a.noisy, failed=lambda: write(a.csv, rows))
        if not conv:
            return 1
        ud = np.asarray(md.variable("ud"))
        err = np.abs(ud[top_x] - die_top(t_target)[0]).max() + \
            np.abs(ud[top_y] - die_top(t_target)[1]).max()
        if err > 1e-9:
            raise SystemExit("step %d: the die's top is off by %.2e" % (step, err))
        rx, ry = support_force()
        nx, ny, lx, ly = contact_force()
        rows.append((t_target, rx, -ry, nx, ny, lx, ly, total_it))
        print("step %3d  t = %.5f  F_x = %+.5e  F_y = %+.5e  F_x/F_y = %+.4f  newton %d%s"
              % (step, t_target, rx, -ry, rx / -ry if ry else 0, total_it,
                 "  (%d cut-backs)" % cuts if cuts else ""), flush=True)
        t_prev = t_target
    write(a.csv, rows)
    print("getfem_shallow_ironing.py: %d steps, %.1f s CPU" % (len(rows),
                                                               time.process_time() - t0))
    return 0


def write(path, rows):
    write_csv(path, "time,F_x,F_y,contact_normal_x,contact_normal_y,contact_x,contact_y,newton",
              "%.16g,%.16g,%.16g,%.16g,%.16g,%.16g,%.16g,%d", rows)


if __name__ == "__main__":
    sys.exit(main())
