#!/usr/bin/python3
"""Plane-strain ironing meshes (gmsh, all quads), written as Exodus.

Usage: ironing_mesh.py OUTPUT.exo [--die shallow|circular] [--nx-block N] [--ny-block N]
                       [--n-die N] [--msh OUTPUT.msh]

The x-y section of the Kratos examples shallow_ironing_3D and ironing_with_die_3D
(../shared/reference/kratos_examples/CASES.md):
  block "block": [0, 12] x [0, 4], a structured nx x ny grid graded towards the top (a
    geometric progression whose top layer is as thick as an element is wide, 12 / nx, or
    uniform when 4 / ny is thinner); side sets block_top (y = 4), block_bottom (y = 0);
  die "die", touching the block at one point (the Kratos meshes leave 6.7e-5 and 3.4e-4):
    shallow:  [0.2, 1.4] x [4, 5.2] whose bottom is the arc of radius 0.75 about (0.8, 4.75),
              from (0.2, 4.3) to (1.4, 4.3) through (0.8, 4); a structured grid, n-die
              elements along the arc and the top, n-die / 2 across;
    circular: the half disc of radius 1 about (2, 5) below the rectangle [1, 3] x [5, 6];
              gmsh quads, 2 n-die faces along the arc;
  side sets die_bottom (the arc) and die_top (y = 5.2 or 6).
Each side set X comes with the node set X_nodes.
--thickness T --layers N (shallow die only): the 3D slab of the Kratos example instead, both
bodies extruded by T in z with N HEX8 layers; the side sets become the extruded faces, plus
the side sets block_z0 and die_z0 (the bodies' faces at z = 0).
"""
import argparse
import math
import os
import sys

import gmsh

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from exodus_mesh import MeshError, write_exodus  # noqa: E402
from gmsh_to_exodus import model_to_mesh  # noqa: E402


def grading(nx, ny):
    """Ratio r of the layer thicknesses (bottom to top): the top layer of the ny layers over
    the height 4 is 4 r^(ny-1) (1 - r) / (1 - r^ny) = 12 / nx (bisection; 1 = uniform)."""
    target = 12.0 / nx
    top = lambda r: 4.0 / ny if r == 1.0 else 4.0 * r ** (ny - 1) * (1 - r) / (1 - r ** ny)
    if top(1.0) <= target:
        return 1.0
    lo, hi = 0.3, 1.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if top(mid) < target else (lo, mid)
    return 0.5 * (lo + hi)


def extrude(surface, thickness, layers):
    """Extrudes a 2D surface by `thickness` in z (HEX8): (volume, lateral surfaces in the order
    of the surface's boundary curves)."""
    out = gmsh.model.geo.extrude([(2, surface)], 0, 0, thickness, numElements=[layers],
                                 recombine=True)
    return out[1][1], [tag for _, tag in out[2:]]


def block(nx, ny):
    g = gmsh.model.geo
    p = [g.addPoint(x, y, 0) for x, y in ((0, 0), (12, 0), (12, 4), (0, 4))]
    bottom, right = g.addLine(p[0], p[1]), g.addLine(p[1], p[2])
    top, left = g.addLine(p[2], p[3]), g.addLine(p[3], p[0])
    surface = g.addPlaneSurface([g.addCurveLoop([bottom, right, top, left])])
    g.mesh.setTransfiniteCurve(bottom, nx + 1)
    g.mesh.setTransfiniteCurve(top, nx + 1)
    # Progression r from the bottom up on the right edge, from the top down on the left one.
    r = grading(nx, ny)
    g.mesh.setTransfiniteCurve(right, ny + 1, "Progression", r)
    g.mesh.setTransfiniteCurve(left, ny + 1, "Progression", 1 / r)
    g.mesh.setTransfiniteSurface(surface)
    g.mesh.setRecombine(2, surface)
    return surface, top, bottom, [bottom, right, top, left]


def shallow_die(n):
    g = gmsh.model.geo
    c = g.addPoint(0.8, 4.75, 0)
    a, b = g.addPoint(0.2, 4.3, 0), g.addPoint(1.4, 4.3, 0)
    tr, tl = g.addPoint(1.4, 5.2, 0), g.addPoint(0.2, 5.2, 0)
    arc = g.addCircleArc(a, c, b)
    right, top, left = g.addLine(b, tr), g.addLine(tr, tl), g.addLine(tl, a)
    surface = g.addPlaneSurface([g.addCurveLoop([arc, right, top, left])])
    g.mesh.setTransfiniteCurve(arc, n + 1)
    g.mesh.setTransfiniteCurve(top, n + 1)
    g.mesh.setTransfiniteCurve(right, max(n // 2, 2) + 1)
    g.mesh.setTransfiniteCurve(left, max(n // 2, 2) + 1)
    g.mesh.setTransfiniteSurface(surface)
    g.mesh.setRecombine(2, surface)
    return surface, top, [arc], [arc, right, top, left]


def circular_die(n):
    g = gmsh.model.geo
    c = g.addPoint(2, 5, 0)
    left, bottom, right = g.addPoint(1, 5, 0), g.addPoint(2, 4, 0), g.addPoint(3, 5, 0)
    tr, tl = g.addPoint(3, 6, 0), g.addPoint(1, 6, 0)
    arcs = [g.addCircleArc(left, c, bottom), g.addCircleArc(bottom, c, right)]
    lines = [g.addLine(right, tr), g.addLine(tr, tl), g.addLine(tl, left)]
    surface = g.addPlaneSurface([g.addCurveLoop(arcs + lines)])
    h = math.pi / n
    for arc in arcs:
        g.mesh.setTransfiniteCurve(arc, n // 2 + 1)
    for p in (left, bottom, right, tr, tl):
        g.mesh.setSize([(0, p)], 2 * h)  # halved by the subdivision into quads
    return surface, lines[1], arcs, arcs + lines


def build(die, nx, ny, n_die, thickness=0.0, layers=0):
    b_surface, b_top, b_bottom, b_loop = block(nx, ny)
    d_surface, d_top, d_bottom, d_loop = (shallow_die(n_die) if die == "shallow" else
                                          circular_die(n_die))
    if layers > 0:  # 3D: the extruded volumes and faces
        b_volume, b_sides = extrude(b_surface, thickness, layers)
        d_volume, d_sides = extrude(d_surface, thickness, layers)
        face = lambda sides, loop, curves: [sides[loop.index(c)] for c in curves]
        groups = [(3, [b_volume], "block"), (3, [d_volume], "die"),
                  (2, face(b_sides, b_loop, [b_top]), "block_top"),
                  (2, face(b_sides, b_loop, [b_bottom]), "block_bottom"),
                  (2, face(d_sides, d_loop, d_bottom), "die_bottom"),
                  (2, face(d_sides, d_loop, [d_top]), "die_top"),
                  (2, [b_surface], "block_z0"), (2, [d_surface], "die_z0")]
    else:
        groups = [(2, [b_surface], "block"), (2, [d_surface], "die"),
                  (1, [b_top], "block_top"), (1, [b_bottom], "block_bottom"),
                  (1, d_bottom, "die_bottom"), (1, [d_top], "die_top")]
    gmsh.model.geo.synchronize()
    for dim, tags, name in groups:
        gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), name)
    gmsh.option.setNumber("Mesh.RecombineAll", 1)
    if die == "circular":
        # Unstructured quads in the die: triangles recombined, then subdivided (all quads);
        # the subdivision would split the structured block too, so its counts are halved.
        gmsh.option.setNumber("Mesh.SubdivisionAlgorithm", 1)
        gmsh.option.setNumber("Mesh.Algorithm", 6)
    gmsh.model.mesh.generate(3 if layers > 0 else 2)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output")
    ap.add_argument("--die", choices=["shallow", "circular"], default="shallow")
    ap.add_argument("--nx-block", type=int, default=120)
    ap.add_argument("--ny-block", type=int, default=20)
    ap.add_argument("--n-die", type=int, default=24)
    ap.add_argument("--thickness", type=float, default=1.0)
    ap.add_argument("--layers", type=int, default=0)
    ap.add_argument("--msh")
    a = ap.parse_args()
    if a.layers < 0 or (a.layers > 0 and (a.die != "shallow" or not a.thickness > 0)):
        print("ironing_mesh.py: error: --layers needs the shallow die and --thickness > 0",
              file=sys.stderr)
        return 2
    for key in ("nx_block", "ny_block", "n_die"):
        if getattr(a, key) < 2 or (a.die == "circular" and getattr(a, key) % 2):
            print("ironing_mesh.py: error: --%s must be >= 2 (even for the circular die)" %
                  key.replace("_", "-"), file=sys.stderr)
            return 2
    nx, ny, n_die = a.nx_block, a.ny_block, a.n_die
    if a.die == "circular":  # the subdivision into quads doubles every structured count
        nx, ny = nx // 2, ny // 2
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("ironing")
        build(a.die, nx, ny, n_die, a.thickness, a.layers)
        if a.msh:
            gmsh.write(a.msh)
        mesh = model_to_mesh("ironing")
    except MeshError as e:
        print("ironing_mesh.py: error: %s" % e, file=sys.stderr)
        return 2
    finally:
        gmsh.finalize()
    write_exodus(mesh, a.output, title="plane-strain ironing, %s die" % a.die)
    n_cells = sum(len(c) for _, t, c in mesh.blocks if t in ("QUAD4", "HEX8"))
    print("ironing_mesh.py: %s: %d nodes, %d %s" % (a.output, len(mesh.coords), n_cells,
                                                   "hexahedra" if a.layers else "quads"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
