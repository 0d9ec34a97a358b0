"""Press fit 2D, mu = 0.1 (docs/verification.md #18) solved independently with GetFEM 5.4 (Poulios &
Renard's code and large-sliding contact), to judge Grout's curve against the published figure
(docs/verification.md, "Press fit 2D, μ = 0.1", "Independent check with GetFEM").

What: the same plane-strain problem as press_fit.yaml, on the same Exodus mesh (Kratos'
press_fit.mdpa converted by tools/mdpa_to_exodus.py), read with netCDF4
(../contact_common/getfem_model.py, shared with the double arc's GetFEM check):
- two bodies, each its own GetFEM mesh: the channel (block parts_solid_auto1, E = 2.1e10,
  nu = 0.3) and the block (parts_solid_auto2, E = 1e9, nu = 0.47);
- Grout's compressible Neo-Hookean in GWFL (W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2,
  F33 = 1); bilinear QK(2,1) with 2x2 Gauss, as Grout's QUAD4;
- supports, nodal as Grout's dirichlet: the channel bottom (node set
  displacement_displacement_auto2) clamped (by simplification); the block top
  (displacement_displacement_auto1) u_y = -0.1 t for t <= 0.01, then -0.001, x free; the block's
  left face (displacement_displacement_auto3) u_x = 0 for t <= 0.01, then t - 0.01 (pointwise
  constraints with multipliers: one per node and component);
- contact: the integral large sliding contact brick (augmented Lagrangian, raytracing on the
  current geometry), Coulomb friction --mu (default 0.1; the slip measured from the
  displacement at the start of the step), slave = the block bottom
  (contact_contact_slave_auto1), master = the channel top (contact_contact_master_auto1),
  multiplier on the slave's nodes (QK(2,1) trace), augmentation --r (Pa/m, default
  E_block / h, h the mean length of the slave's sides: 1e9 / 0.09 on Kratos' mesh; GetFEM's
  curve holds for r = 1 ... 10 E_block / h; with E/(3h) or 100 E/h the block loses contact
  while it crosses the ramp, R_x drops 4x in a step: docs/verification.md), release distance
  --release (default 10 mm; 20 mm gives the same curve);
- load path: t = 1.3 k / --steps, k = 1 ... --steps (default 150, Grout's full run and the
  figure's steps); Newton from the previous state, a step that does not converge is halved (up
  to 6 times);
- output (--csv), one row per step: time, the figure step 150 t / 1.3, the push u_x, the
  horizontal reaction on the left face and the vertical one on the block top (N per m of
  thickness: the multipliers of the pointwise constraints, i.e. the force the supports put on
  the block, with the sign of Grout's reaction_*), Newton iterations.

How to run (from a folder holding press_fit.exo; the ctest writes
build/inputs/press_fit/press_fit.exo):
  /usr/bin/python3 inputs/press_fit/getfem_press_fit.py --mesh press_fit.exo \
      --csv getfem_press_fit.csv
and inputs/press_fit/getfem_compare.py for the numbers and the figure (run_getfem.sh does
both). Needs python3-getfem (Debian), numpy, netCDF4. Exit code 77 (ctest: skipped) when
GetFEM is missing (message), 1 when a step does not converge.
"""
import argparse
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "contact_common"))
from getfem_model import (Body, add_large_sliding_contact, add_neo_hookean,  # noqa: E402
                          advance_step, import_getfem, read_mesh, side_nodes, write_csv)

MODULI = {"parts_solid_auto1": (2.1e10, 0.3), "parts_solid_auto2": (1.0e9, 0.47)}
T_END, T_PRESS = 1.3, 0.01


def top_uy(t):
    return -0.1 * t if t <= T_PRESS else -0.001


def push_ux(t):
    return 0.0 if t <= T_PRESS else t - T_PRESS


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--mesh", default="press_fit.exo")
    ap.add_argument("--steps", type=int, default=150)
    ap.add_argument("--t-end", type=float, default=T_END, help="stop at this time (steps of "
                    "1.3/--steps)")
    ap.add_argument("--mu", type=float, default=0.1, help="Coulomb friction coefficient")
    ap.add_argument("--r", type=float, default=None,
                    help="augmentation (Pa/m; default E_block / h)")
    ap.add_argument("--r-factor", type=float, default=1.0, help="multiplies the default --r")
    ap.add_argument("--release", type=float, default=0.01, help="release distance (m)")
    ap.add_argument("--max-res", type=float, default=1e-3,
                    help="Newton: max |residual| (N/m) on the equilibrium rows")
    ap.add_argument("--csv", default="")
    ap.add_argument("--noisy", action="store_true")
    a = ap.parse_args()
    gf = import_getfem("getfem_press_fit.py")
    if gf is None:
        return 77
    t0 = time.process_time()
    x, blocks, nsets, ssets, conn_all = read_mesh(a.mesh, MODULI)
    chan = Body(gf, x, blocks, ["parts_solid_auto1"], 10)
    blk = Body(gf, x, blocks, ["parts_solid_auto2"], 20)
    BOTTOM, MASTER, SLAVE = 1, 2, 3
    counts = (chan.face_region(BOTTOM, nsets["displacement_displacement_auto2"], x),
              chan.face_region(MASTER, side_nodes(ssets, conn_all,
                                                  "contact_contact_master_auto1"), x),
              blk.face_region(SLAVE, side_nodes(ssets, conn_all, "contact_contact_slave_auto1"),
                              x))
    expect = (len(nsets["displacement_displacement_auto2"]) - 1,
              len(ssets["contact_contact_master_auto1"]), len(ssets["contact_contact_slave_auto1"]))
    if counts != expect:
        raise SystemExit("%s: faces found %s, expected %s" % (a.mesh, counts, expect))
    top, left = nsets["displacement_displacement_auto1"], nsets["displacement_displacement_auto3"]
    if min(blk.pids(top, x).min(), blk.pids(left, x).min()) < 0:
        raise SystemExit("%s: a supported node of the block is not in the block" % a.mesh)
    print("mesh %s: channel %d nodes %d quads, block %d nodes %d quads; %d top, %d left nodes"
          % (a.mesh, chan.mesh.nbpts(), chan.mesh.nbcvs(), blk.mesh.nbpts(), blk.mesh.nbcvs(),
             len(top), len(left)))

    im = "IM_GAUSS_PARALLELEPIPED(2,3)"  # 2x2 Gauss
    mfc, mfb = gf.MeshFem(chan.mesh, 2), gf.MeshFem(blk.mesh, 2)
    for mf in (mfc, mfb):
        mf.set_fem(gf.Fem("FEM_QK(2,1)"))
    mimc, mimb = gf.MeshIm(chan.mesh, gf.Integ(im)), gf.MeshIm(blk.mesh, gf.Integ(im))
    md = gf.Model("real")
    md.add_fem_variable("uc", mfc)
    md.add_fem_variable("ub", mfb)
    add_neo_hookean(gf, md, chan, "uc", mimc, "ch", MODULI)
    add_neo_hookean(gf, md, blk, "ub", mimb, "b", MODULI)
    md.add_initialized_data("zero", [0.0, 0.0])
    md.add_Dirichlet_condition_with_simplification("uc", BOTTOM, "zero")
    # Block supports: one pointwise constraint per node and component (x, y interleaved).
    pts = np.concatenate([x[top], x[left]])
    dirs = np.concatenate([np.tile([0.0, 1.0], (len(top), 1)), np.tile([1.0, 0.0], (len(left), 1))])
    md.add_initialized_data("sup_pts", pts.ravel())
    md.add_initialized_data("sup_dirs", dirs.ravel())
    md.add_initialized_data("sup_vals", np.zeros(len(pts)))
    md.add_pointwise_constraints_with_multipliers("ub", "sup_pts", "sup_dirs", "sup_vals")
    mult = "mult_on_ub"  # GetFEM's name of the multipliers (getfem_model.cc: "mult_on_" + u)
    if md.interval_of_variable(mult)[1] != len(pts):
        raise SystemExit("getfem_press_fit.py: %s is not the support multipliers" % mult)

    slave = side_nodes(ssets, conn_all, "contact_contact_slave_auto1")
    h = np.ptp(x[slave, 0]) / len(ssets["contact_contact_slave_auto1"])
    r = a.r if a.r is not None else a.r_factor * MODULI["parts_solid_auto2"][0] / h
    print("contact: r = %.4g Pa/m (h = %.4g m), release distance %.3g m, mu = %g"
          % (r, h, a.release, a.mu))
    ind, w = add_large_sliding_contact(gf, md, r, a.release, a.mu,
                                       ("ub", mfb, blk.mesh, mimb, SLAVE),
                                       ("uc", mfc, mimc, MASTER))

    # Equilibrium rows: all of ub (the supports act through the multipliers) and uc but its
    # clamped dofs.
    free = []
    for var, fixed in (("ub", []), ("uc", mfc.basic_dof_on_region(BOTTOM))):
        i0, n = md.interval_of_variable(var)
        keep = np.ones(n, bool)
        keep[np.asarray(fixed, int)] = False
        free.append(i0 + np.nonzero(keep)[0])
    free = np.concatenate(free)
    ntop = len(top)

    def values(t):
        return np.r_[np.full(ntop, top_uy(t)), np.full(len(left), push_ux(t))]

    def reactions():
        # The support's force on the block is minus the multiplier (the top pushes the
        # block down: R_y < 0, as Grout's reaction_displacement_displacement_auto1_y).
        m = np.asarray(md.variable(mult)).ravel()
        return -m[ntop:].sum(), -m[:ntop].sum()

    rows = []
    dt0 = T_END / a.steps
    t_prev = 0.0
    nsteps = int(round(a.t_end / dt0))
    for step in range(1, nsteps + 1):
        t_target = step * dt0
        total_it, cuts, conv = advance_step(
            gf, md, free, lambda t: md.set_variable("sup_vals", values(t)), step, t_prev, t_target,
            w, a.max_res, a.noisy, failed=lambda: write(a.csv, rows))
        if not conv:
            return 1
        ub = np.asarray(md.variable("ub"))
        err = np.abs(sup_displacements(mfb, ub, pts, dirs) - values(t_target)).max()
        if err > 1e-9:
            raise SystemExit("step %d: the supports are off by %.2e m" % (step, err))
        rx, ry = reactions()
        rows.append((t_target, t_target * 150 / T_END, push_ux(t_target), rx, ry, total_it))
        print("step %3d  t = %.5f  push %.5f  R_x = %+.5e  R_y(top) = %+.5e N/m  newton %d%s"
              % (step, t_target, push_ux(t_target), rx, ry, total_it,
                 "  (%d cut-backs)" % cuts if cuts else ""), flush=True)
        t_prev = t_target
    write(a.csv, rows)
    print("getfem_press_fit.py: %d steps, %.1f s CPU" % (len(rows), time.process_time() - t0))
    return 0


def sup_displacements(mf, u, pts, dirs):
    """u . direction at the supported points (the nodes: their dofs, to 1e-9 m)."""
    dn = mf.basic_dof_nodes()
    out = []
    for p, d in zip(pts, dirs):
        k = int(np.argmax(d))
        i = [j for j in range(k, mf.nbdof(), 2) if np.hypot(*(dn[:, j] - p)) < 1e-9]
        out.append(u[i[0]])
    return np.array(out)


def write(path, rows):
    write_csv(path, "time,figure_step,push_x[m],reaction_x[N/m],reaction_top_y[N/m],newton",
              "%.10g,%.6g,%.10g,%.10g,%.10g,%d", rows)


if __name__ == "__main__":
    sys.exit(main())
