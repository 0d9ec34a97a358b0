#!/usr/bin/python3
"""Mesh of the self-contact patch test (inputs/self_contact/README.md): one body, one element
block, whose surface folds back onto itself along a closed slit.

Usage: slit_strip.py OUTPUT.exo [--dim 2|3] [--nx-lower N] [--nx-upper N] [--layers N]

The body is the rectangle [0, L] x [0, 2] (L = 2) cut by an L-shaped slit: a horizontal cut
along y = 1 from x = a (a = 0.5) to the right edge x = L, and a vertical cut along x = a from
y = 1 up to the tip (a, 1.5). Nodes on the slit are doubled except at the tip, so the part
below the horizontal cut (the lower arm with the left column) and the part above it (the
upper arm) are joined only round the tip, through the top of the left column: a strip folded
back onto itself. The two flanks of the horizontal cut touch with zero gap and face each other;
they are one side set, `fold`, the self-contact surface. (The vertical cut is not in it: under
the test's load it carries no traction, and the corner node would get a normal averaged over
both cuts.) The lower arm has --nx-lower elements along the cut, the upper arm --nx-upper:
non-matching flanks. The left column is [0, a] x [0, 2] with 2 elements across. Interior nodes
of each of the three patches are shifted by a fixed pattern (distorted quads).

Sets: side sets `fold` (both flanks), `fold_lower` and `fold_upper` (each flank alone), `top`
(y = 2), `bottom` (y = 0), `left` (x = 0), `right` (x = L, both arms), `slit_column` and
`slit_arm` (the vertical cut's flanks on the left column and on the upper arm, for the
frictional test's shear tractions); node sets of each (<name>_nodes), and `lower_flank_nodes`,
`upper_flank_nodes` (the two flanks).
--dim 3 sweeps the mesh along z over [0, 0.5] in --layers layers (node sets z0_nodes,
zt_nodes).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from exodus_mesh import Mesh, extrude, write_exodus  # noqa: E402

L, A, Y_TIP = 2.0, 0.5, 1.5


def build(nx_lower, nx_upper):
    coords, index = [], {}

    def node(x, y, tag):
        key = (round(x, 12), round(y, 12), tag)
        if key not in index:
            index[key] = len(coords)
            coords.append((x, y))
        return index[key]

    elements = []

    def patch(xs, ys, tag_of, distort):
        """Quads of the tensor grid xs x ys; tag_of(x, y) splits doubled slit nodes."""
        ids = {}
        for i, x in enumerate(xs):
            for j, y in enumerate(ys):
                px, py = x, y
                if distort and 0 < i < len(xs) - 1 and 0 < j < len(ys) - 1:
                    hx, hy = xs[i + 1] - xs[i], ys[j + 1] - ys[j]
                    px += 0.15 * hx * ((-1) ** (i + j))
                    py += 0.1 * hy * ((-1) ** i)
                ids[i, j] = node(px, py, tag_of(x, y))
        for i in range(len(xs) - 1):
            for j in range(len(ys) - 1):
                elements.append((ids[i, j], ids[i + 1, j], ids[i + 1, j + 1], ids[i, j + 1]))

    y_low = np.linspace(0.0, 1.0, 4)
    y_up = np.linspace(1.0, 2.0, 5)  # 1, 1.25, 1.5 (tip), 1.75, 2
    below = lambda x, y: 0  # noqa: E731
    # The upper arm's copies of the slit nodes (all but the tip) get tag 1.
    upper = lambda x, y: 1 if (abs(y - 1.0) < 1e-12 or (abs(x - A) < 1e-12 and y < Y_TIP - 1e-12)) else 0  # noqa: E731,E501
    patch(np.linspace(0.0, A, 3), np.concatenate([y_low, y_up[1:]]), below, True)  # left column
    patch(np.linspace(A, L, nx_lower + 1), y_low, below, True)  # lower arm
    patch(np.linspace(A, L, nx_upper + 1), y_up, upper, True)  # upper arm
    mesh = Mesh(np.array(coords))
    mesh.add_block("strip", "QUAD4", np.array(elements))
    x = mesh.coords
    faces = mesh.boundary_faces()
    lower_flank = set(index[k] for k in index if k[2] == 0 and abs(k[1] - 1.0) < 1e-12 and k[0] >= A - 1e-12)
    upper_flank = set(index[k] for k in index if k[2] == 1 and abs(k[1] - 1.0) < 1e-12)
    sets = {"fold": [], "top": [], "bottom": [], "left": [], "right": [], "slit_column": [],
            "slit_arm": [], "fold_lower": [], "fold_upper": []}
    for key, (e, side) in faces.items():
        a, b = sorted(key)
        if {a, b} <= lower_flank or {a, b} <= upper_flank:
            sets["fold"].append((e, side))
            sets["fold_lower" if {a, b} <= lower_flank else "fold_upper"].append((e, side))
        elif abs(x[a, 1] - 2.0) < 1e-12 and abs(x[b, 1] - 2.0) < 1e-12:
            sets["top"].append((e, side))
        elif abs(x[a, 1]) < 1e-12 and abs(x[b, 1]) < 1e-12:
            sets["bottom"].append((e, side))
        elif abs(x[a, 0]) < 1e-12 and abs(x[b, 0]) < 1e-12:
            sets["left"].append((e, side))
        elif abs(x[a, 0] - L) < 1e-12 and abs(x[b, 0] - L) < 1e-12:
            sets["right"].append((e, side))
        elif abs(x[a, 0] - A) < 1e-12 and abs(x[b, 0] - A) < 1e-12:  # the vertical cut
            column = x[list(elements[e]), 0].mean() < A
            sets["slit_column" if column else "slit_arm"].append((e, side))
    for name, sides in sets.items():
        mesh.side_sets[name] = sorted(sides)
    mesh.add_side_set_node_sets()
    mesh.node_sets["lower_flank_nodes"] = np.array(sorted(lower_flank))
    mesh.node_sets["upper_flank_nodes"] = np.array(sorted(upper_flank))
    assert len(sets["fold"]) == nx_lower + nx_upper, sets["fold"]
    return mesh


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("output")
    p.add_argument("--dim", type=int, choices=(2, 3), default=2)
    p.add_argument("--nx-lower", type=int, default=5)
    p.add_argument("--nx-upper", type=int, default=7)
    p.add_argument("--layers", type=int, default=2)
    args = p.parse_args()
    mesh = build(args.nx_lower, args.nx_upper)
    if args.dim == 3:
        mesh = extrude(mesh, 0.5, args.layers)
    write_exodus(mesh, args.output, title="self-contact slit strip")


if __name__ == "__main__":
    main()
