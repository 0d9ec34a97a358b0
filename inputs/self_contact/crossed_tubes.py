#!/usr/bin/python3
"""Our own mesh of Kratos' crossed tubes (README.md, "Penetration"), for a refinement study of
the tube-on-tube penetration: the same geometry as Kratos' meshes, structured HEX8.

Usage: crossed_tubes.py OUTPUT.exo [--upper-axial N] [--upper-around N] [--lower-axial N]
                        [--lower-around N] [--layers N]

Both tubes: r from 0.0112 to 0.012, length 0.1. The upper tube's axis is along x through
y = 0.024, z = 0.05 (x from -0.05 to 0.05), the lower tube's along z through x = y = 0 (z from
0 to 0.1). Nodes on the exact circles. Around each tube the nodes start at the +y direction,
so the lower tube's crown (x = 0, y = 0.012) is a node. An odd --upper-axial puts the middle of
an upper face at x = 0, over that crown: the lower tube's node there lies under the middle of
an upper tube's face, where the face (a chord along x) is furthest from the lower circle.

Sets (as kratos_mesh.py names Kratos' parts): blocks `upper`, `lower`; side sets `upper_outer`,
`lower_outer`, `inner_lower` and `inner_upper` (the upper tube's inner surface below and above
its axis); node sets `upper_ends` (x = +-0.05), `lower_ends` (z = 0, 0.1).
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from exodus_mesh import SIDES, Mesh, write_exodus  # noqa: E402

R_IN, R_OUT, LENGTH = 0.0112, 0.012, 0.1


def tube(axial, around, layers, offset, frame, s0):
    """Nodes (n, 3) and HEX8 connectivity (positive volume) of a tube: the point at axial
    coordinate s (s0 to s0 + LENGTH), angle a and radius r is offset + s e_axis +
    r (cos a e_1 + sin a e_2), frame = (e_axis, e_1, e_2) right-handed."""
    e_ax, e1, e2 = (np.asarray(v, dtype=float) for v in frame)
    s = s0 + LENGTH * np.arange(axial + 1) / axial
    a = 2 * math.pi * np.arange(around) / around
    r = R_IN + (R_OUT - R_IN) * np.arange(layers + 1) / layers
    S, A, Rr = np.meshgrid(s, a, r, indexing="ij")  # (axial + 1, around, layers + 1)
    x = (np.asarray(offset)[None, None, None, :] + S[..., None] * e_ax
         + Rr[..., None] * (np.cos(A)[..., None] * e1 + np.sin(A)[..., None] * e2))

    def node(i, j, k):
        return (i * around + j % around) * (layers + 1) + k

    conn = []
    for i in range(axial):
        for j in range(around):
            for k in range(layers):
                # Bottom face (i): (j, k), (j, k+1), (j+1, k+1), (j+1, k); top face i + 1.
                bottom = [node(i, j, k), node(i, j, k + 1), node(i, j + 1, k + 1),
                          node(i, j + 1, k)]
                conn.append(bottom + [n + around * (layers + 1) for n in bottom])
    conn = np.array(conn)
    X = x.reshape(-1, 3)
    p = X[conn]
    vol = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 3] - p[:, 0]), p[:, 4] - p[:, 0])
    if np.any(vol < 0):
        conn = conn[:, [0, 3, 2, 1, 4, 7, 6, 5]]
    return X, conn


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("output")
    p.add_argument("--upper-axial", type=int, default=25)
    p.add_argument("--upper-around", type=int, default=48)
    p.add_argument("--lower-axial", type=int, default=32)
    p.add_argument("--lower-around", type=int, default=96)
    p.add_argument("--layers", type=int, default=2)
    a = p.parse_args()
    # Angle 0 along +y (the lower tube's crown, the upper tube's top), growing towards +x / +z.
    Xu, cu = tube(a.upper_axial, a.upper_around, a.layers, (0.0, 0.024, 0.05),
                  ((1, 0, 0), (0, 1, 0), (0, 0, 1)), -LENGTH / 2)
    Xl, cl = tube(a.lower_axial, a.lower_around, a.layers, (0.0, 0.0, 0.0),
                  ((0, 0, 1), (0, 1, 0), (1, 0, 0)), 0.0)
    mesh = Mesh(np.vstack([Xu, Xl]))
    mesh.add_block("upper", "HEX8", cu)
    mesh.add_block("lower", "HEX8", cl + len(Xu))
    n_upper = len(cu)
    X = mesh.coords
    sets = {k: [] for k in ("upper_outer", "lower_outer", "inner_lower", "inner_upper")}
    conn = {e: row for e, _, row in mesh.elements()}
    for _, (e, side) in sorted(mesh.boundary_faces().items(), key=lambda kv: kv[1]):
        c = X[[conn[e][i] for i in SIDES["HEX8"][side - 1]]].mean(axis=0)
        upper = e < n_upper
        radius = math.hypot(c[1] - 0.024, c[2] - 0.05) if upper else math.hypot(c[0], c[1])
        if abs(radius - R_OUT) < 0.1 * (R_OUT - R_IN):
            sets["upper_outer" if upper else "lower_outer"].append((e, side))
        elif upper and abs(radius - R_IN) < 0.1 * (R_OUT - R_IN):
            sets["inner_lower" if c[1] < 0.024 else "inner_upper"].append((e, side))
    mesh.side_sets = sets
    tol = 1e-9
    upper_nodes = np.arange(len(Xu))
    lower_nodes = np.arange(len(Xu), len(X))
    mesh.node_sets["upper_ends"] = upper_nodes[np.abs(np.abs(X[upper_nodes, 0]) - 0.05) < tol]
    mesh.node_sets["lower_ends"] = lower_nodes[(np.abs(X[lower_nodes, 2]) < tol)
                                               | (np.abs(X[lower_nodes, 2] - 0.1) < tol)]
    mesh.add_side_set_node_sets()
    write_exodus(mesh, a.output, "crossed tubes (inputs/self_contact/crossed_tubes.py)")
    print("%s: %d nodes, %d HEX8; upper face along x %.3e, lower node spacing around %.3e; %s"
          % (a.output, len(X), len(cu) + len(cl), LENGTH / a.upper_axial,
             2 * math.pi * R_OUT / a.lower_around,
             ", ".join("%s %d" % (k, len(v)) for k, v in sets.items())))


if __name__ == "__main__":
    main()
