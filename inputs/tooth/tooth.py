#!/usr/bin/python3
"""The layered tooth pressed by a punch (Kratos use_cases/tooth_model, thesis Fig. 4.61), 2D,
meshed by gmsh (all quads), written as Exodus (inputs/tooth/README.md).

Usage: tooth.py OUTPUT.exo [--dentine] [--level N] [--contact-size H] [--far-size H]
                [--fine-within D0] [--grade-to D1] [--msh OUTPUT.msh]

Lengths in mm (README.md says why). The tooth is a layered block of width 8, x in [-4, 4],
its top y = 0:
- composite 1.5 thick (y in [-1.5, 0]), block "composite";
- with --dentine, dentine 0.5 thick below it (y in [-2, -1.5]), block "dentine";
- enamel 2.5 thick below that, block "enamel";
the layer names of Kratos' files (composite15+enamel25, composite15+dentine05+enamel25) read
as thicknesses in tenths of a mm. The layers share their nodes (bonded, one body). The punch
is the lower half of a disc of radius 2 centred at (0, 2): its arc touches the tooth at the
origin, where both bodies have a node; block "punch", flat top y = 2 "punch_top", arc
"punch_arc" (the master). Side sets: "composite_contact", the tooth's top for |x| <= 0.5
(the slave: flat, and inside the arc's span over the whole load); "tooth_bottom" (clamped).

Mesh: element size H (default 0.005) within D0 (default 0.05) of the contact point, growing
linearly with the distance to the far size (default 0.4) at D1 (default 2); gmsh meshes with
twice these sizes and subdivides into quads. --level N refines that mesh N - 1 times more
(gmsh's refine: every quad split into four, new boundary nodes on the curves), so the levels
are nested and h halves from level to level, as a refinement study needs.
"""
import argparse
import os
import sys

import gmsh

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from exodus_mesh import MeshError, write_exodus  # noqa: E402
from gmsh_to_exodus import generate_all_quads, model_to_mesh  # noqa: E402

HALF_WIDTH = 4.0  # the tooth's half width (mm)
COMPOSITE, DENTINE, ENAMEL = 1.5, 0.5, 2.5  # layer thicknesses (mm), top to bottom
RADIUS = 2.0  # the punch's radius (mm)
SLAVE_HALF = 0.5  # the slave side set covers |x| <= SLAVE_HALF on the tooth's top


def layer(g, top, bottom):
    """A layer between the (already made) top line chain and a new bottom line: returns
    (surface, bottom line, bottom left point, bottom right point)."""
    top_lines, top_left, top_right, y = top
    left = g.addPoint(-HALF_WIDTH, y - bottom, 0)
    right = g.addPoint(HALF_WIDTH, y - bottom, 0)
    base = g.addLine(left, right)
    side_r = g.addLine(right, top_right)
    side_l = g.addLine(top_left, left)
    # top_lines run left to right; the loop goes bottom (left to right), right side up,
    # top right to left, left side down.
    loop = g.addCurveLoop([base, side_r] + [-c for c in reversed(top_lines)] + [side_l])
    return g.addPlaneSurface([loop]), ([base], left, right, y - bottom)


def build(dentine, h_contact, h_far, d_fine, d_grade):
    g = gmsh.model.geo
    # The tooth's top, split at x = -0.5, 0, 0.5 (the slave and the contact point).
    xs = [-HALF_WIDTH, -SLAVE_HALF, 0.0, SLAVE_HALF, HALF_WIDTH]
    pts = [g.addPoint(x, 0.0, 0) for x in xs]
    apex_tooth = pts[2]
    top_lines = [g.addLine(a, b) for a, b in zip(pts[:-1], pts[1:])]
    chain = (top_lines, pts[0], pts[-1], 0.0)
    composite, chain = layer(g, chain, COMPOSITE)
    dentine_s = None
    if dentine:
        dentine_s, chain = layer(g, chain, DENTINE)
    enamel, chain = layer(g, chain, ENAMEL)
    bottom = chain[0]
    # The punch: lower half disc, centre (0, R); its own node at the origin.
    c = g.addPoint(0.0, RADIUS, 0)
    left = g.addPoint(-RADIUS, RADIUS, 0)
    right = g.addPoint(RADIUS, RADIUS, 0)
    apex_punch = g.addPoint(0.0, 0.0, 0)
    flat = g.addLine(right, left)
    a1 = g.addCircleArc(left, c, apex_punch)
    a2 = g.addCircleArc(apex_punch, c, right)
    punch = g.addPlaneSurface([g.addCurveLoop([a1, a2, flat])])
    g.synchronize()
    groups = [(2, [composite], "composite"), (2, [enamel], "enamel"), (2, [punch], "punch"),
              (1, top_lines[1:3], "composite_contact"), (1, bottom, "tooth_bottom"),
              (1, [flat], "punch_top"), (1, [a1, a2], "punch_arc")]
    if dentine:
        groups.insert(1, (2, [dentine_s], "dentine"))
    for dim, tags, name in groups:
        gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), name)
    f = gmsh.model.mesh.field
    dist = f.add("Distance")
    f.setNumbers(dist, "NodesList", [apex_tooth, apex_punch])
    thr = f.add("Threshold")
    f.setNumber(thr, "InField", dist)
    f.setNumber(thr, "SizeMin", 2 * h_contact)  # halved by the subdivision into quads
    f.setNumber(thr, "SizeMax", 2 * h_far)
    f.setNumber(thr, "DistMin", d_fine)
    f.setNumber(thr, "DistMax", d_grade)
    f.setAsBackgroundMesh(thr)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    generate_all_quads()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output")
    ap.add_argument("--dentine", action="store_true")
    ap.add_argument("--level", type=int, default=1)
    ap.add_argument("--contact-size", type=float, default=0.005)
    ap.add_argument("--far-size", type=float, default=0.4)
    ap.add_argument("--fine-within", type=float, default=0.05)
    ap.add_argument("--grade-to", type=float, default=2.0)
    ap.add_argument("--msh")
    a = ap.parse_args()
    if not (a.level >= 1 and 0 < a.contact_size <= a.far_size
            and 0 < a.fine_within < a.grade_to):
        print("tooth.py: error: need --level >= 1, 0 < --contact-size <= --far-size, "
              "0 < --fine-within < --grade-to", file=sys.stderr)
        return 2
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("tooth")
        build(a.dentine, a.contact_size, a.far_size, a.fine_within, a.grade_to)
        for _ in range(a.level - 1):
            gmsh.model.mesh.refine()
        if a.msh:
            gmsh.write(a.msh)
        mesh = model_to_mesh("tooth")
    except MeshError as e:
        print("tooth.py: error: %s" % e, file=sys.stderr)
        return 2
    finally:
        gmsh.finalize()
    kind = "enamel-dentine-composite" if a.dentine else "enamel-composite"
    write_exodus(mesh, a.output, title="gmsh tooth, %s, level %d" % (kind, a.level))
    n_quads = sum(len(c) for _, t, c in mesh.blocks if t == "QUAD4")
    print("tooth.py: %s: %d nodes, %d quads" % (a.output, len(mesh.coords), n_quads))
    return 0


if __name__ == "__main__":
    sys.exit(main())
