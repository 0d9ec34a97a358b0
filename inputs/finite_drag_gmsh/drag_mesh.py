#!/usr/bin/python3
"""A die over a longer block, meshed by gmsh (all quads), written as Exodus: the two-body
finite-strain drag of inputs/finite_drag_gmsh.

Usage: drag_mesh.py OUTPUT.exo [--size H] [--gap G] [--radius R] [--msh OUTPUT.msh]
                    [--thickness T [--layers N]]

Block [0, 8] x [0, 5] (block "block", side sets "block_top", "block_bottom"). Die of width 2
and height 2 centred on x = 4 (block "die", side sets "die_bottom", "die_top"):
- flat bottom at y = 5 + G (default G = 0: the bodies touch along the whole die bottom);
- --radius R: the bottom is a circular arc of radius R with its lowest point (a node) at
  (4, 5 + G); with G = 0 the bodies touch at that single node.
The mesh is made with G = 0 and the die's nodes are then moved up by G, so meshes that differ
in G only differ by that translation of the die.
Element size H (default 0.125) on the block top within 1.5 of x in [3, 6] and on the die
bottom, growing to 4 H away from the contact; gmsh meshes with twice these sizes and
subdivides into quads (Mesh.SubdivisionAlgorithm = 1, all quads). The two meshes do not
match (the die is meshed 0.8 times finer).
--thickness T: the 2D mesh swept along z over [0, T] in N HEX8 layers (default 1;
exodus_mesh.extrude): the same names, the side sets become faces, node set "z0_nodes" holds the
nodes on z = 0, "zt_nodes" those on z = T, and "z_faces" both (with one layer, every node).
"""
import argparse
import math
import os
import sys

import gmsh
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from exodus_mesh import MeshError, extrude, write_exodus  # noqa: E402
from gmsh_to_exodus import generate_all_quads, model_to_mesh  # noqa: E402

L, HB = 8.0, 5.0  # block
W, HD, XC = 2.0, 2.0, 4.0  # die width, height, centre


def build(h, radius):
    g = gmsh.model.geo
    y0 = HB
    # block, counter-clockwise from the lower left corner; extra points on the top edge bound
    # the refined contact strip
    bp = [g.addPoint(0, 0, 0), g.addPoint(L, 0, 0), g.addPoint(L, HB, 0),
          g.addPoint(XC + 2.0 + 1.0, HB, 0), g.addPoint(XC - 1.0 - 1.5, HB, 0), g.addPoint(0, HB, 0)]
    bl = [g.addLine(bp[k], bp[(k + 1) % 6]) for k in range(6)]
    block = g.addPlaneSurface([g.addCurveLoop(bl)])
    # die
    sag = 0.0 if radius is None else radius - math.sqrt(radius * radius - (W / 2) ** 2)
    p_bl, p_br = g.addPoint(XC - W / 2, y0 + sag, 0), g.addPoint(XC + W / 2, y0 + sag, 0)
    p_tr, p_tl = g.addPoint(XC + W / 2, y0 + HD, 0), g.addPoint(XC - W / 2, y0 + HD, 0)
    if radius is None:
        bottom = [g.addLine(p_bl, p_br)]
    else:
        apex = g.addPoint(XC, y0, 0)
        centre = g.addPoint(XC, y0 + radius, 0)
        bottom = [g.addCircleArc(p_bl, centre, apex), g.addCircleArc(apex, centre, p_br)]
    right, top, left = g.addLine(p_br, p_tr), g.addLine(p_tr, p_tl), g.addLine(p_tl, p_bl)
    die = g.addPlaneSurface([g.addCurveLoop(bottom + [right, top, left])])
    g.synchronize()
    for dim, tags, name in [(2, [block], "block"), (2, [die], "die"),
                            (1, bl[2:5], "block_top"), (1, [bl[0]], "block_bottom"),
                            (1, bottom, "die_bottom"), (1, [top], "die_top")]:
        gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), name)
    # sizes (doubled: the subdivision halves them): fine on the contact strip of the block
    # top and on the die bottom, coarser away from them
    f = gmsh.model.mesh.field
    d_block = f.add("Distance")
    f.setNumbers(d_block, "CurvesList", [bl[3]])
    f.setNumber(d_block, "NumPointsPerCurve", 200)
    t_block = f.add("Threshold")
    f.setNumber(t_block, "InField", d_block)
    f.setNumber(t_block, "SizeMin", 2 * h)
    f.setNumber(t_block, "SizeMax", 8 * h)
    f.setNumber(t_block, "DistMin", 0.25)
    f.setNumber(t_block, "DistMax", 3.0)
    d_die = f.add("Distance")
    f.setNumbers(d_die, "CurvesList", bottom)
    f.setNumber(d_die, "NumPointsPerCurve", 200)
    t_die = f.add("Threshold")
    f.setNumber(t_die, "InField", d_die)
    f.setNumber(t_die, "SizeMin", 1.6 * h)
    f.setNumber(t_die, "SizeMax", 6 * h)
    f.setNumber(t_die, "DistMin", 0.25)
    f.setNumber(t_die, "DistMax", 2.0)
    both = f.add("Min")
    f.setNumbers(both, "FieldsList", [t_block, t_die])
    f.setAsBackgroundMesh(both)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    generate_all_quads()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output")
    ap.add_argument("--size", type=float, default=0.125)
    ap.add_argument("--gap", type=float, default=0.0)
    ap.add_argument("--radius", type=float)
    ap.add_argument("--msh")
    ap.add_argument("--thickness", type=float, help="sweep along z: a 3D HEX8 mesh")
    ap.add_argument("--layers", type=int, default=1, help="HEX8 layers through --thickness")
    a = ap.parse_args()
    if not (a.size > 0 and a.gap >= 0 and (a.radius is None or a.radius > W / 2)):
        print("drag_mesh.py: error: need --size > 0, --gap >= 0, --radius > %g" % (W / 2),
              file=sys.stderr)
        return 2
    if a.thickness is not None and not (a.thickness > 0 and a.layers >= 1):
        print("drag_mesh.py: error: need --thickness > 0 and --layers >= 1", file=sys.stderr)
        return 2
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("drag")
        build(a.size, a.radius)
        if a.msh:
            gmsh.write(a.msh)
        mesh = model_to_mesh("drag_mesh")
        die = next(conn for name, _, conn in mesh.blocks if name == "die")
        mesh.coords[np.unique(die), 1] += a.gap
        if a.thickness is not None:
            mesh = extrude(mesh, a.thickness, a.layers)
    except MeshError as e:
        print("drag_mesh.py: error: %s" % e, file=sys.stderr)
        return 2
    finally:
        gmsh.finalize()
    write_exodus(mesh, a.output, title="gmsh die over block, size %g, gap %g, radius %s" %
                 (a.size, a.gap, a.radius))
    print("drag_mesh.py: %s: %d nodes, blocks %s" % (a.output, len(mesh.coords),
                                                      [(b[0], len(b[2])) for b in mesh.blocks]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
