#!/usr/bin/python3
"""Two half discs touching at one point, meshed by gmsh (all quads), written as Exodus.

Usage: half_discs.py OUTPUT.exo [--contact-size H] [--msh OUTPUT.msh]

Lower half disc: centre (0, 0), R = 8, flat edge y = 0 ("lower_bottom"), arc "lower_contact".
Upper half disc: centre (0, 16), R = 8, flat edge y = 16 ("upper_top"), arc "upper_contact".
Both arcs pass through (0, 8), a node of each body (the bodies touch at that one point).
Element size H within distance 1 (about 1.5 b) of (0, 8) (default 0.057 = b/12 for the load of
gmsh_hertz/*.yaml, b = 0.6808), growing linearly with the distance to R/8 = 1 at distance 4 (gmsh meshes with twice these
sizes, then the subdivision into quads, Mesh.SubdivisionAlgorithm = 1, halves them: all
quads). Blocks "lower", "upper".
"""
import argparse
import os
import sys

import gmsh

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from exodus_mesh import MeshError, write_exodus  # noqa: E402
from gmsh_to_exodus import generate_all_quads, model_to_mesh  # noqa: E402

R = 8.0


def half_disc(cx, cy, up):
    """Half disc of centre (cx, cy): the arc bulges up (up=True) or down. Returns (surface,
    flat edge, arc curves, apex point)."""
    g = gmsh.model.geo
    s = 1.0 if up else -1.0
    c = g.addPoint(cx, cy, 0)
    right = g.addPoint(cx + R, cy, 0)
    apex = g.addPoint(cx, cy + s * R, 0)
    left = g.addPoint(cx - R, cy, 0)
    flat = g.addLine(left, right)
    a1 = g.addCircleArc(right, c, apex)
    a2 = g.addCircleArc(apex, c, left)
    loop = g.addCurveLoop([flat, a1, a2] if up else [-a2, -a1, -flat])
    surface = g.addPlaneSurface([loop])
    return surface, flat, [a1, a2], apex


def build(h_contact):
    lower, lower_flat, lower_arc, lower_apex = half_disc(0.0, 0.0, True)
    upper, upper_flat, upper_arc, upper_apex = half_disc(0.0, 2 * R, False)
    gmsh.model.geo.synchronize()
    for dim, tags, name in [(2, [lower], "lower"), (2, [upper], "upper"),
                            (1, [lower_flat], "lower_bottom"), (1, [upper_flat], "upper_top"),
                            (1, lower_arc, "lower_contact"), (1, upper_arc, "upper_contact")]:
        gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), name)
    f = gmsh.model.mesh.field
    dist = f.add("Distance")
    f.setNumbers(dist, "NodesList", [lower_apex, upper_apex])
    thr = f.add("Threshold")
    f.setNumber(thr, "InField", dist)
    f.setNumber(thr, "SizeMin", 2 * h_contact)  # halved by the subdivision into quads
    f.setNumber(thr, "SizeMax", R / 4)
    f.setNumber(thr, "DistMin", 1.0)
    f.setNumber(thr, "DistMax", R / 2)
    f.setAsBackgroundMesh(thr)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    generate_all_quads()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output")
    ap.add_argument("--contact-size", type=float, default=0.057)
    ap.add_argument("--msh")
    a = ap.parse_args()
    if not a.contact_size > 0:
        print("half_discs.py: error: --contact-size must be > 0", file=sys.stderr)
        return 2
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("half_discs")
        build(a.contact_size)
        if a.msh:
            gmsh.write(a.msh)
        mesh = model_to_mesh("half_discs")
    except MeshError as e:
        print("half_discs.py: error: %s" % e, file=sys.stderr)
        return 2
    finally:
        gmsh.finalize()
    write_exodus(mesh, a.output, title="gmsh half discs, contact size %g" % a.contact_size)
    n_quads = sum(len(c) for _, t, c in mesh.blocks if t == "QUAD4")
    print("half_discs.py: %s: %d nodes, %d quads" % (a.output, len(mesh.coords), n_quads))
    return 0


if __name__ == "__main__":
    sys.exit(main())
