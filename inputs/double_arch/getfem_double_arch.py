"""Double arc (docs/verification.md #14) solved independently with GetFEM 5.4 (Poulios & Renard's
own code and contact formulation), to judge Grout's curves (docs/verification.md, "Double arc",
"Independent check with GetFEM").

What: the same plane-strain problem as double_arch.yaml, on the same Exodus mesh
(arch_on_block.py; blocks base / ring_inner / ring_outer, side sets base_bottom, base_top,
ring_contact, ring_ends, node set ring_bottom), read with netCDF4:
- two bodies, each its own GetFEM mesh (the ring's lowest outer node and the base's top centre
  node coincide; one mesh would merge them): base (E = 3e8) and the half ring (inner layer
  r 0.085-0.09 E = 1e11, outer layer 0.09-0.095 E = 1e9), nu = 0.3 everywhere;
- compressible Neo-Hookean written out in GWFL, the same W as Grout (docs/input.md):
  W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2, P = mu (F - F^-T) + lambda ln J F^-T,
  plane strain (F is the in-plane 2x2 block, F33 = 1: I1 = |F|^2 + 1, J = det F),
  lambda = E nu / ((1 + nu)(1 - 2 nu)), mu = E / (2 (1 + nu));
- elements: --order 1 (default) bilinear QK(2,1) with 2x2 Gauss, as Grout's QUAD4; --order 2
  biquadratic QK(2,2), 3x3 Gauss, on the same mesh (the discretisation check);
- supports: base bottom u = 0; ring ends (y = 0.145) u = (0, -d), nodal (Dirichlet by
  simplification, as Grout's dirichlet);
- contact: GetFEM's integral large sliding contact brick (augmented Lagrangian, raytracing on
  the current geometry: Poulios & Renard 2015, the formulation of the literature curve),
  frictionless, or Coulomb with --mu (the slip measured from the displacement at the start of
  the step, times --alpha = 1, as GetFEM's own demo), slave = the base top (as Kratos and Grout;
  --slave ring swaps: with --mu the only choice whose curve converges in --steps,
  docs/verification.md), multiplier on
  the slave's nodes (QK(2,1) trace); augmentation parameter --r (Pa/m, default E_base / h with
  h = 5 mm the base's element size), release distance --release (default 5 mm);
- diagnostics only: --moduli BASE INNER OUTER replaces the json's moduli; --base-support roller
  lets the base bottom slide in x (u_y = 0, u_x = 0 at its middle node); --alpha, GetFEM's
  factor on the slip (>= 20 the Newton fails); --brick-version 1, GetFEM's "more symmetric"
  brick; --contact-integration nodal, the contact terms on the element nodes;
- load path: d = 0 ... --d-max in --steps equal steps (Newton from the previous state; a step
  that does not converge is halved, up to 6 times);
- output: --csv, one row per step: imposed d, the centre's (ring_bottom, the lowest outer node)
  vertical displacement, the ring-end reaction (N per m of thickness: the y internal force of
  the ring on the end nodes), Newton iterations, and the vertical displacement of the ring's
  lowest inner node (ring_bottom_inner; a diagnostic);
- --ring-check: after the first step, the ring's own deflection d - delta_c against
  Castigliano's clamped composite half ring (arch_theory.py, k_ring = 1.566e8 N/m per m) with
  the computed end force, as check.py --ring does for Grout; prints the ratio.

How to run (from a folder holding the mesh; the ctest writes
build/inputs/double_arch/double_arch.exo, run_full.sh build/inputs/double_arch/full/):
  /usr/bin/python3 inputs/double_arch/getfem_double_arch.py --mesh double_arch.exo \
      --d-max 0.075 --steps 150 --csv getfem_double_arch.csv
  /usr/bin/python3 inputs/double_arch/getfem_double_arch.py --mesh double_arch_fine.exo \
      --d-max 0.001 --steps 1 --ring-check
Runtime (CPU, one core of the shared 2-core machine; printed at the end), d to 0.075 in 150
steps: Kratos' mesh QK(2,1) 11 s, QK(2,2) 61 s; the mesh twice as fine QK(2,1) 50 s, QK(2,2)
276 s. The CI portion (d <= 0.024, 8 steps, Kratos' mesh): 0.7 s.

Needs python3-getfem (Debian), numpy, netCDF4. Exit code 77 (ctest: skipped) when GetFEM is
missing (message), 1 when a step does not converge.
"""
import argparse
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "contact_common"))
from getfem_model import (Body, add_large_sliding_contact, add_neo_hookean,  # noqa: E402
                          advance_step, neo_hookean_piola, import_getfem, read_mesh, side_nodes,
                          write_csv)
NU = 0.3
E = {"base": 3.0e8, "ring_inner": 1.0e11, "ring_outer": 1.0e9}
RING = [(0.085, 0.09, 1e11, 0.3), (0.09, 0.095, 1e9, 0.3)]  # (r_in, r_out, E, nu): arch_theory


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--mesh", default="double_arch.exo")
    ap.add_argument("--d-max", type=float, default=0.075)
    ap.add_argument("--steps", type=int, default=150)
    ap.add_argument("--order", type=int, default=1, choices=(1, 2))
    ap.add_argument("--r", type=float, default=None, help="augmentation parameter (Pa/m)")
    ap.add_argument("--release", type=float, default=0.005, help="release distance (m)")
    ap.add_argument("--slave", default="base", choices=("base", "ring"))
    ap.add_argument("--mu", type=float, default=0.0, help="Coulomb friction coefficient")
    ap.add_argument("--moduli", type=float, nargs=3, metavar=("BASE", "INNER", "OUTER"),
                    help="Young's moduli in place of the input's (diagnostics only)")
    ap.add_argument("--base-support", default="clamped", choices=("clamped", "roller"),
                    help="roller: the base bottom slides in x (diagnostic only)")
    ap.add_argument("--alpha", type=float, default=1.0,
                    help="GetFEM's slip factor (diagnostics; 1: the slip increment of a step)")
    ap.add_argument("--brick-version", type=int, default=0, choices=(0, 1),
                    help="GetFEM's contact brick: 0 non-symmetric, 1 more symmetric")
    ap.add_argument("--contact-integration", default="gauss", choices=("gauss", "nodal"),
                    help="contact terms on the element's Gauss points or its nodes (diagnostic)")
    ap.add_argument("--csv", default="")
    ap.add_argument("--ring-check", action="store_true")
    ap.add_argument("--max-res", type=float, default=1e-4,
                    help="Newton: max |residual| (N/m) on the free rows")
    ap.add_argument("--noisy", action="store_true")
    a = ap.parse_args()
    gf = import_getfem("getfem_double_arch.py")
    if gf is None:
        return 77
    t0 = time.process_time()
    if a.moduli:
        E.update(zip(("base", "ring_inner", "ring_outer"), a.moduli))
    x, blocks, nsets, ssets, conn_all = read_mesh(a.mesh, ("base", "ring_inner", "ring_outer"))
    base = Body(gf, x, blocks, ["base"], 10)
    ring = Body(gf, x, blocks, ["ring_inner", "ring_outer"], 20)
    BOTTOM, TOP, CONTACT, ENDS = 1, 2, 3, 4

    counts = tuple(body.face_region(rid, side_nodes(ssets, conn_all, name), x)
                   for body, rid, name in ((base, BOTTOM, "base_bottom"), (base, TOP, "base_top"),
                                           (ring, CONTACT, "ring_contact"),
                                           (ring, ENDS, "ring_ends")))
    expect = tuple(len(ssets[n]) for n in ("base_bottom", "base_top", "ring_contact",
                                           "ring_ends"))
    if counts != expect:
        raise SystemExit("%s: faces found %s, side sets have %s" % (a.mesh, counts, expect))
    centre = ring.pids(nsets["ring_bottom"], x)
    if len(centre) != 1 or centre[0] < 0:
        raise SystemExit("%s: node set ring_bottom must be one ring node" % a.mesh)
    print("mesh %s: base %d nodes %d quads, ring %d nodes %d quads; centre node at (%.4f, %.4f)"
          % (a.mesh, base.mesh.nbpts(), base.mesh.nbcvs(), ring.mesh.nbpts(), ring.mesh.nbcvs(),
             *x[nsets["ring_bottom"][0]]))

    def fem(body, order):
        mf = gf.MeshFem(body.mesh, 2)
        mf.set_fem(gf.Fem("FEM_QK(2,%d)" % order))
        return mf

    im = "IM_GAUSS_PARALLELEPIPED(2,%d)" % (3 if a.order == 1 else 5)  # 2x2 / 3x3 Gauss
    mfb, mfr = fem(base, a.order), fem(ring, a.order)
    mimb, mimr = gf.MeshIm(base.mesh, gf.Integ(im)), gf.MeshIm(ring.mesh, gf.Integ(im))
    md = gf.Model("real")
    md.add_fem_variable("ub", mfb)
    md.add_fem_variable("ur", mfr)

    moduli = {name: (e, NU) for name, e in E.items()}
    for body, u, mim, sfx in ((base, "ub", mimb, "b"), (ring, "ur", mimr, "r")):
        add_neo_hookean(gf, md, body, u, mim, sfx, moduli)

    md.add_initialized_data("zero", [0.0, 0.0])
    if a.base_support == "clamped":
        md.add_Dirichlet_condition_with_simplification("ub", BOTTOM, "zero")
        base_fixed = mfb.basic_dof_on_region(BOTTOM)
    else:  # diagnostic: u_y = 0 on the bottom (multipliers), u_x = 0 at its middle node only
        md.add_normal_Dirichlet_condition_with_multipliers(mimb, "ub", 1, BOTTOM)
        md.add_initialized_data("pin_pt", [0.125, 0.0])
        md.add_initialized_data("pin_dir", [1.0, 0.0])
        md.add_pointwise_constraints_with_multipliers("ub", "pin_pt", "pin_dir")
        base_fixed = []
    md.add_initialized_data("dend", [0.0, 0.0])
    md.add_Dirichlet_condition_with_simplification("ur", ENDS, "dend")

    h = 0.25 / 50
    r = a.r if a.r is not None else E["base"] / h
    # Coulomb: the slip is measured from the displacement at the start of the step (w).
    def contact_im(body, mim):  # nodal: the vertex (Newton-Cotes) rule, 2 points per side
        if a.contact_integration == "gauss":
            return mim
        return gf.MeshIm(body.mesh, gf.Integ("IM_NC_PARALLELEPIPED(2,1)"))

    bodies = {"base": ("ub", mfb, base.mesh, contact_im(base, mimb), TOP),
              "ring": ("ur", mfr, ring.mesh, contact_im(ring, mimr), CONTACT)}
    other = "ring" if a.slave == "base" else "base"
    ind, w = add_large_sliding_contact(gf, md, r, a.release, a.mu, bodies[a.slave],
                                       bodies[other][:2] + bodies[other][3:], order=a.order,
                                       alpha=a.alpha, version=a.brick_version)

    # The centre's y dof (and the inner bottom node's, when the mesh names it), the ring-end
    # y dofs (for the reaction). A vector MeshFem interleaves the components (x, y per node).
    pts_r = mfr.basic_dof_nodes()

    def y_dof(node_set):
        p = x[nsets[node_set][0]]
        dofs = [i for i in range(1, mfr.nbdof(), 2) if np.hypot(*(pts_r[:, i] - p)) < 1e-9]
        if len(dofs) != 1:
            raise SystemExit("%s: no ring dof at node set %s" % (a.mesh, node_set))
        return dofs[0]

    cy_dof = y_dof("ring_bottom")
    iy_dof = y_dof("ring_bottom_inner") if "ring_bottom_inner" in nsets else cy_dof
    end_dofs = mfr.basic_dof_on_region(ENDS)
    end_y = end_dofs[end_dofs % 2 == 1]

    def end_force():
        fint = gf.asm_generic(mimr, 1, neo_hookean_piola("ur", "r") + ":Grad_Test_ur", -1, md,
                              "select_output", "ur")
        return float(np.sum(fint[end_y]))

    # Rows of the residual that are equilibrium equations (not Dirichlet rows): the force
    # residual the Newton test measures.
    free = []
    for var, mf, fixed in (("ub", mfb, base_fixed),
                           ("ur", mfr, end_dofs)):
        i0, n = md.interval_of_variable(var)
        keep = np.ones(n, bool)
        keep[np.asarray(fixed, int)] = False
        free.append(i0 + np.nonzero(keep)[0])
    free = np.concatenate(free)

    rows = []
    d_prev, d_target = 0.0, 0.0
    dd0 = a.d_max / a.steps
    for step in range(1, a.steps + 1):
        d_target = min(a.d_max, step * dd0)
        total_it, cuts, conv = advance_step(
            gf, md, free, lambda d: md.set_variable("dend", [0.0, -d]), step, d_prev, d_target,
            w, a.max_res, a.noisy, name="d", failed=lambda: write(a.csv, rows))
        if not conv:
            return 1
        u = md.variable("ur")
        fy = end_force()
        rows.append((d_target, u[cy_dof], fy, total_it, u[iy_dof]))
        print("step %3d  d = %.5f  u_centre = %+.6f  end force %+.4e N/m  newton %d%s"
              % (step, d_target, u[cy_dof], fy, total_it, "  (%d cut-backs)" % cuts if cuts
                 else ""), flush=True)
        d_prev = d_target
        if a.ring_check and step == 1:
            sys.path.insert(0, HERE)
            from arch_theory import arch_stiffness
            k = arch_stiffness(RING)
            ring_defl = d_target + u[cy_dof]
            pred = abs(fy) / k
            print("ring check: d = %.4f, end force %.4e N/m, ring deflection d - delta_c = "
                  "%.4e, Castigliano F/k_ring = %.4e (k_ring = %.4e), ratio %.4f"
                  % (d_target, abs(fy), ring_defl, pred, k, ring_defl / pred))
    write(a.csv, rows)
    print("getfem_double_arch.py: %d steps, %.1f s CPU" % (len(rows), time.process_time() - t0))
    return 0


def write(path, rows):
    write_csv(path, "imposed_displacement[m],center_vertical_displacement[m],end_force_y[N/m],"
              "newton,inner_bottom_vertical_displacement[m]", "%.8g,%.10g,%.8g,%d,%.10g", rows)


if __name__ == "__main__":
    sys.exit(main())
