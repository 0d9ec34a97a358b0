#!/usr/bin/python3
"""Cylinder in a ring (benchmark #13, plane strain), meshed by gmsh (all quads), as Exodus.

Usage: ring.py OUTPUT.exo [--size H] [--interior H2] [--thickness T [--layers N]]

Ring: annulus about the origin, inner radius 0.9, outer radius 1.0 (block "ring"; outer
circle "ring_outer", inner circle "ring_inner"). Cylinder: disc of radius 0.2 centred at
(0.699, 0) (block "cylinder", circle "cylinder_surface"), 0.001 from the ring's inner
surface: released there, it swings as a pendulum of length 0.7 about the ring centre.
Element size H (default 0.025) on the ring and the cylinder surface; with --interior H2 > H
the elements grow from H on the contact surfaces (the ring's inner circle and the cylinder's
circle) to H2 at 0.1 from them (a fine contact surface at a small cost: refinement studies).
With --thickness T the quads are swept along z over [0, T] in N layers (default 1) of HEX8
(exodus_mesh.extrude): the 3D version with the issue's dimensions, the side sets now faces, and
node set "z_faces" the nodes on z = 0 and z = T.
"""
import argparse
import os
import sys

import gmsh

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from exodus_mesh import MeshError, extrude, write_exodus  # noqa: E402
from gmsh_to_exodus import generate_all_quads, model_to_mesh  # noqa: E402


def circle(g, cx, cy, r):
    """Four arcs of the circle of centre (cx, cy) and radius r (counter-clockwise)."""
    c = g.addPoint(cx, cy, 0)
    p = [g.addPoint(cx + r, cy, 0), g.addPoint(cx, cy + r, 0), g.addPoint(cx - r, cy, 0),
         g.addPoint(cx, cy - r, 0)]
    return [g.addCircleArc(p[k], c, p[(k + 1) % 4]) for k in range(4)]


def build(h, interior):
    g = gmsh.model.geo
    outer, inner = circle(g, 0.0, 0.0, 1.0), circle(g, 0.0, 0.0, 0.9)
    disc = circle(g, 0.699, 0.0, 0.2)
    ring = g.addPlaneSurface([g.addCurveLoop(outer), g.addCurveLoop(inner)])
    cylinder = g.addPlaneSurface([g.addCurveLoop(disc)])
    g.synchronize()
    for dim, tags, name in [(2, [ring], "ring"), (2, [cylinder], "cylinder"),
                            (1, outer, "ring_outer"), (1, inner, "ring_inner"),
                            (1, disc, "cylinder_surface")]:
        gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), name)
    gmsh.option.setNumber("Mesh.MeshSizeMax", 2 * h)  # halved by the subdivision into quads
    if interior > h:  # graded: h on the contact surfaces, growing to `interior` 0.1 inside
        f = gmsh.model.mesh.field
        distance = f.add("Distance")
        f.setNumbers(distance, "CurvesList", inner + disc)
        f.setNumber(distance, "NumPointsPerCurve", 2000)
        threshold = f.add("Threshold")
        f.setNumber(threshold, "InField", distance)
        f.setNumber(threshold, "SizeMin", 2 * h)
        f.setNumber(threshold, "SizeMax", 2 * interior)
        f.setNumber(threshold, "DistMin", 0.0)
        f.setNumber(threshold, "DistMax", 0.1)
        f.setAsBackgroundMesh(threshold)
        gmsh.option.setNumber("Mesh.MeshSizeMax", 2 * interior)
        gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
        gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    generate_all_quads()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output")
    ap.add_argument("--size", type=float, default=0.025)
    ap.add_argument("--interior", type=float, default=None,
                    help="element size 0.1 away from the contact surfaces (default: --size)")
    ap.add_argument("--thickness", type=float, default=None,
                    help="sweep along z over this thickness: a 3D HEX8 mesh")
    ap.add_argument("--layers", type=int, default=1, help="HEX8 layers through --thickness")
    a = ap.parse_args()
    if not a.size > 0:
        print("ring.py: error: --size must be > 0", file=sys.stderr)
        return 2
    if a.thickness is not None and not (a.thickness > 0 and a.layers >= 1):
        print("ring.py: error: --thickness must be > 0 and --layers >= 1", file=sys.stderr)
        return 2
    interior = a.size if a.interior is None else a.interior
    if interior < a.size:
        print("ring.py: error: --interior must be >= --size", file=sys.stderr)
        return 2
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        build(a.size, interior)
        mesh = model_to_mesh("ring.py")
        if a.thickness is not None:
            mesh = extrude(mesh, a.thickness, a.layers)
        write_exodus(mesh, a.output)
    except MeshError as e:
        print("ring.py: error: %s" % e, file=sys.stderr)
        return 2
    finally:
        gmsh.finalize()
    return 0


if __name__ == "__main__":
    sys.exit(main())
