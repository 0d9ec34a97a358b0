#!/usr/bin/python3
"""A half ring (U-shaped, open side up) of one or more conforming layers resting on a
rectangular block, touching it at one point: structured QUAD4 mesh by gmsh (transfinite),
written as Exodus. Used by inputs/double_arch (Kratos' double arch) and inputs/arc_block.

Usage: arch_on_block.py OUTPUT.exo --center CX CY --radii R0 R1 [R2 ...] --layer-names A [B ...]
           --block X0 X1 Y0 --n-around N --n-layer K [K ...] --block-nx NX --block-ny NY

The ring: centre (CX, CY), layers between consecutive radii (R0 < R1 < ..., layer k between
R_k and R_k+1, element block layer-names[k], K_k elements through its thickness), the lower
half (angles pi to 2 pi), N elements around (N even: a node at the lowest point x = CX).
Its outer surface (radius R_last) touches the block top y = CY - R_last at x = CX.
The block: [X0, X1] x [Y0, CY - R_last], NX elements along x (split at x = CX in proportion,
so a block-top node lies at x = CX), NY through its height; element block "base".
Side sets (each with a node set <name>_nodes): base_top, base_bottom, ring_contact (the
outer arc), ring_ends (the two end edges of all layers, y = CY). Node sets: ring_bottom
(the lowest node of the outer arc), ring_bottom_inner (of the inner arc), base_center (the
block-top node at x = CX).
"""
import argparse
import os
import sys

import gmsh

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from exodus_mesh import MeshError, write_exodus  # noqa: E402
from gmsh_to_exodus import model_to_mesh  # noqa: E402


def build(a):
    g = gmsh.model.geo
    cx, cy = a.center
    radii = a.radii
    centre = g.addPoint(cx, cy, 0)
    # Per radius: left end (angle pi), bottom (3 pi / 2), right end (2 pi).
    pts = [(g.addPoint(cx - r, cy, 0), g.addPoint(cx, cy - r, 0), g.addPoint(cx + r, cy, 0))
           for r in radii]
    arcs = [(g.addCircleArc(p[0], centre, p[1]), g.addCircleArc(p[1], centre, p[2])) for p in pts]
    ring_surfaces, ends = [], []
    half = a.n_around // 2
    for k in range(len(radii) - 1):
        left = g.addLine(pts[k][0], pts[k + 1][0])
        mid = g.addLine(pts[k][1], pts[k + 1][1])
        right = g.addLine(pts[k][2], pts[k + 1][2])
        ends += [left, right]
        s1 = g.addPlaneSurface([g.addCurveLoop([left, arcs[k + 1][0], -mid, -arcs[k][0]])])
        s2 = g.addPlaneSurface([g.addCurveLoop([mid, arcs[k + 1][1], -right, -arcs[k][1]])])
        for c in (left, mid, right):
            g.mesh.setTransfiniteCurve(c, a.n_layer[k] + 1)
        ring_surfaces.append([s1, s2])
    for pair in arcs:
        for c in pair:
            g.mesh.setTransfiniteCurve(c, half + 1)
    # Block, split at x = cx.
    x0, x1, y0 = a.block
    y1 = cy - radii[-1]
    nl = max(1, round(a.block_nx * (cx - x0) / (x1 - x0)))
    nr = max(1, a.block_nx - nl)
    b = [g.addPoint(x0, y0, 0), g.addPoint(cx, y0, 0), g.addPoint(x1, y0, 0),
         g.addPoint(x1, y1, 0), g.addPoint(cx, y1, 0), g.addPoint(x0, y1, 0)]
    bottom = [g.addLine(b[0], b[1]), g.addLine(b[1], b[2])]
    right_side = g.addLine(b[2], b[3])
    top = [g.addLine(b[3], b[4]), g.addLine(b[4], b[5])]
    left_side = g.addLine(b[5], b[0])
    middle = g.addLine(b[1], b[4])
    base = [g.addPlaneSurface([g.addCurveLoop([bottom[0], middle, top[1], left_side])]),
            g.addPlaneSurface([g.addCurveLoop([bottom[1], right_side, top[0], -middle])])]
    for c, n in [(bottom[0], nl), (top[1], nl), (bottom[1], nr), (top[0], nr)]:
        g.mesh.setTransfiniteCurve(c, n + 1)
    for c in (left_side, right_side, middle):
        g.mesh.setTransfiniteCurve(c, a.block_ny + 1)
    g.synchronize()
    for s in base + [s for pair in ring_surfaces for s in pair]:
        gmsh.model.mesh.setTransfiniteSurface(s)
        gmsh.model.mesh.setRecombine(2, s)
    groups = [(2, base, "base"), (1, top, "base_top"), (1, bottom, "base_bottom"),
              (1, list(arcs[-1]), "ring_contact"), (1, ends, "ring_ends"),
              (0, [pts[-1][1]], "ring_bottom"), (0, [pts[0][1]], "ring_bottom_inner"),
              (0, [b[4]], "base_center")]
    # layer-names[k]: the layer between R_k and R_k+1 (R0 innermost).
    for k, pair in enumerate(ring_surfaces):
        groups.append((2, pair, a.layer_names[k]))
    for dim, tags, name in groups:
        gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), name)
    gmsh.model.mesh.generate(2)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output")
    ap.add_argument("--center", type=float, nargs=2, required=True)
    ap.add_argument("--radii", type=float, nargs="+", required=True)
    ap.add_argument("--layer-names", nargs="+", required=True)
    ap.add_argument("--block", type=float, nargs=3, required=True)
    ap.add_argument("--n-around", type=int, required=True)
    ap.add_argument("--n-layer", type=int, nargs="+", required=True)
    ap.add_argument("--block-nx", type=int, required=True)
    ap.add_argument("--block-ny", type=int, required=True)
    a = ap.parse_args()
    problems = []
    if len(a.radii) < 2 or any(r1 <= r0 for r0, r1 in zip(a.radii, a.radii[1:])) or a.radii[0] <= 0:
        problems.append("--radii must be two or more increasing positive radii")
    if len(a.layer_names) != len(a.radii) - 1 or len(a.n_layer) != len(a.radii) - 1:
        problems.append("--layer-names and --n-layer need one entry per layer (%d)"
                        % (len(a.radii) - 1))
    if a.n_around < 2 or a.n_around % 2 or min(a.n_layer) < 1 or a.block_nx < 2 or a.block_ny < 1:
        problems.append("element counts: --n-around even >= 2, --n-layer >= 1, --block-nx >= 2, "
                        "--block-ny >= 1")
    x0, x1, y0 = a.block
    if not (x0 < a.center[0] < x1 and y0 < a.center[1] - a.radii[-1]):
        problems.append("--block must contain x = CX and lie below the ring")
    if problems:
        print("arch_on_block.py: error: " + "; ".join(problems), file=sys.stderr)
        return 2
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("arch_on_block")
        build(a)
        mesh = model_to_mesh("arch_on_block")
    except MeshError as e:
        print("arch_on_block.py: error: %s" % e, file=sys.stderr)
        return 2
    finally:
        gmsh.finalize()
    write_exodus(mesh, a.output, title="gmsh half ring on a block")
    print("arch_on_block.py: %s: %d nodes, %d quads" %
          (a.output, len(mesh.coords), sum(len(c) for _, _, c in mesh.blocks)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
