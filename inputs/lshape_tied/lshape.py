#!/usr/bin/python3
"""L-shape with a circular region at its inner corner (docs/verification.md #21), meshed by gmsh
(all quads), written as Exodus.

Usage: lshape.py OUTPUT.exo [--size H] [--conforming] [--msh OUTPUT.msh]

L = [0, 2] x [0, 1] U [0, 1] x [0, 4]; inner (re-entrant) corner (1, 1). The disc of radius
0.5 about (1, 1), cut by the L (a three-quarter disc), is a body of its own.
- default (tied): two blocks meshed independently, "outer" (L minus the disc, element size H)
  and "disc" (size 0.6 H), so their nodes on the 270-degree arc do not match; side sets
  "outer_arc" and "disc_arc" on the two sides of the interface.
- --conforming: the same geometry meshed as one body (the arc is a shared curve, size 0.6 H
  on it), one block "body": the reference without the tied interface.
Both: side sets "top" (y = 4) and "right" (x = 2) with node sets "top_nodes", "right_nodes".
gmsh meshes with twice these sizes, then subdivides into quads (Mesh.SubdivisionAlgorithm =
1, all quads).
"""
import argparse
import os
import sys

import gmsh

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from exodus_mesh import MeshError, write_exodus  # noqa: E402
from gmsh_to_exodus import generate_all_quads, model_to_mesh  # noqa: E402

R = 0.5
CORNER = (1.0, 1.0)


def l_shape():
    occ = gmsh.model.occ
    a = occ.addRectangle(0, 0, 0, 2, 1)
    b = occ.addRectangle(0, 0, 0, 1, 4)
    out, _ = occ.fuse([(2, a)], [(2, b)])
    return out


def disc():
    return [(2, gmsh.model.occ.addDisk(CORNER[0], CORNER[1], 0, R, R))]


def curves_where(surfaces, test):
    """Boundary curves of the surfaces whose bounding box satisfies test(xmin, ymin, xmax, ymax)."""
    found = []
    for s in surfaces:
        for d, c in gmsh.model.getBoundary([(2, s)], oriented=False):
            box = gmsh.model.getBoundingBox(d, abs(c))
            if test(box[0], box[1], box[3], box[4]):
                found.append(abs(c))
    return sorted(set(found))


def is_arc(x0, y0, x1, y1):
    return x0 < CORNER[0] - 0.1 and y0 < CORNER[1] - 0.1 and x1 > CORNER[0] + 0.1


def build(h, conforming):
    occ = gmsh.model.occ
    if conforming:
        frags, _ = occ.fragment(l_shape(), disc())
        occ.synchronize()
        # the fragment of the disc outside the L (the quarter in the inner corner) is removed
        keep = []
        for d, s in frags:
            x, y, _ = occ.getCenterOfMass(d, s)
            if x > CORNER[0] and y > CORNER[1]:
                occ.remove([(d, s)], recursive=True)
            else:
                keep.append(s)
        occ.synchronize()
        blocks = [("body", keep)]
        outer = keep
        arc_curves = []
    else:
        outer_s = occ.cut(l_shape(), disc())[0]
        inner_s = occ.intersect(l_shape(), disc())[0]
        occ.synchronize()
        outer = [s for _, s in outer_s]
        inner = [s for _, s in inner_s]
        blocks = [("outer", outer), ("disc", inner)]
        arc_curves = [("outer_arc", curves_where(outer, is_arc)), ("disc_arc", curves_where(inner, is_arc))]
    all_surfaces = [s for _, ss in blocks for s in ss]
    top = curves_where(all_surfaces, lambda x0, y0, x1, y1: y0 > 4 - 1e-6)
    right = curves_where(all_surfaces, lambda x0, y0, x1, y1: x0 > 2 - 1e-6)
    for name, ss in blocks:
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, ss), name)
    for name, cs in arc_curves + [("top", top), ("right", right)]:
        if not cs:
            raise MeshError("lshape.py: no curve found for side set '%s'" % name)
        gmsh.model.setPhysicalName(1, gmsh.model.addPhysicalGroup(1, cs), name)
    # sizes (doubled: the subdivision into quads halves them)
    gmsh.model.mesh.setSize(gmsh.model.getEntities(0), 2 * h)
    arc_size = 0.6 * h
    if conforming:
        arcs = curves_where(outer, is_arc)
        pts = gmsh.model.getBoundary([(1, c) for c in arcs], combined=False, oriented=False)
        gmsh.model.mesh.setSize(pts, 2 * arc_size)
    else:
        pts = gmsh.model.getBoundary([(2, s) for s in inner], combined=False, oriented=False,
                                     recursive=True)
        gmsh.model.mesh.setSize(pts, 2 * arc_size)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 1)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    generate_all_quads()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output")
    ap.add_argument("--size", type=float, default=0.2)
    ap.add_argument("--conforming", action="store_true")
    ap.add_argument("--msh")
    a = ap.parse_args()
    if not a.size > 0:
        print("lshape.py: error: --size must be > 0", file=sys.stderr)
        return 2
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("lshape")
        build(a.size, a.conforming)
        if a.msh:
            gmsh.write(a.msh)
        mesh = model_to_mesh("lshape")
    except MeshError as e:
        print("lshape.py: error: %s" % e, file=sys.stderr)
        return 2
    finally:
        gmsh.finalize()
    write_exodus(mesh, a.output, title="gmsh L-shape, size %g%s" % (a.size, ", conforming" if a.conforming else ""))
    print("lshape.py: %s: %d nodes, blocks %s" % (a.output, len(mesh.coords),
                                                   [(b[0], len(b[2])) for b in mesh.blocks]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
