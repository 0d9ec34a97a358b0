#!/usr/bin/python3
"""Structured QUAD4 meshes of the 2D press fit (the geometry of Kratos' press_fit.mdpa), with
Kratos' entity names, so press_fit.yaml runs on them unchanged: a refinement study beyond
Kratos' own meshes.

Usage: press_fit_mesh.py OUTPUT.exo [--level K]

Channel "parts_solid_auto1": [0, 1.9] x [0, y_top(x)], y_top = 0.25 (x <= 0.8), rising
linearly to 0.3 at x = 1.0, 0.3 up to 1.9; 8K x 3K elements on [0, 0.8], 2K on the ramp, 9K
on [1.0, 1.9] (columns), 3K rows (each column split evenly). Block "parts_solid_auto2":
[0, 0.45] x [0.25, 0.45], 5K x 3K elements (K = 1: Kratos' coarse mesh counts for the block).
Node sets: displacement_displacement_auto1 (block top), _auto2 (channel bottom), _auto3
(block left); side sets contact_contact_slave_auto1 (block bottom), contact_contact_master_auto1
(channel top) with their node sets.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from exodus_mesh import Mesh, write_exodus  # noqa: E402


def y_top(x):
    return np.interp(x, [0.0, 0.8, 1.0, 1.9], [0.25, 0.25, 0.3, 0.3])


def grid(xs, ys_of_x, offset):
    """Nodes and QUAD4 connectivity (counter-clockwise) of a mapped grid: columns xs, rows
    ys_of_x(x) (arrays of equal length)."""
    nodes = np.array([[x, y] for x in xs for y in ys_of_x(x)])
    ny = len(ys_of_x(xs[0]))
    conn = [[offset + i * ny + j, offset + (i + 1) * ny + j, offset + (i + 1) * ny + j + 1,
             offset + i * ny + j + 1] for i in range(len(xs) - 1) for j in range(ny - 1)]
    return nodes, np.array(conn)


def build(k):
    xc = np.concatenate([np.linspace(0, 0.8, 8 * k + 1), np.linspace(0.8, 1.0, 2 * k + 1)[1:],
                         np.linspace(1.0, 1.9, 9 * k + 1)[1:]])
    cn, cc = grid(xc, lambda x: np.linspace(0, y_top(x), 3 * k + 1), 0)
    bn, bc = grid(np.linspace(0, 0.45, 5 * k + 1), lambda x: np.linspace(0.25, 0.45, 3 * k + 1), len(cn))
    mesh = Mesh(np.vstack([cn, bn]))
    mesh.add_block("parts_solid_auto1", "QUAD4", cc)
    mesh.add_block("parts_solid_auto2", "QUAD4", bc)
    X = mesh.coords
    n_c = len(cc)
    ny_c, ny_b = 3 * k, 3 * k
    # sides: QUAD4 side 1 = nodes (0, 1) (bottom, as built), side 3 = (2, 3) (top)
    mesh.side_sets["contact_contact_master_auto1"] = [(i * ny_c + ny_c - 1, 3) for i in range(len(xc) - 1)]
    mesh.side_sets["contact_contact_slave_auto1"] = [(n_c + i * ny_b, 1) for i in range(5 * k)]
    tol = 1e-12
    cnodes = np.arange(len(cn))
    bnodes = np.arange(len(cn), len(X))
    mesh.node_sets["displacement_displacement_auto1"] = bnodes[np.abs(X[bnodes, 1] - 0.45) < tol]
    mesh.node_sets["displacement_displacement_auto2"] = cnodes[np.abs(X[cnodes, 1]) < tol]
    mesh.node_sets["displacement_displacement_auto3"] = bnodes[np.abs(X[bnodes, 0]) < tol]
    mesh.add_side_set_node_sets()
    return mesh


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output")
    ap.add_argument("--level", type=int, default=1)
    a = ap.parse_args()
    if a.level < 1:
        print("press_fit_mesh.py: error: --level must be >= 1", file=sys.stderr)
        return 2
    mesh = build(a.level)
    write_exodus(mesh, a.output, title="press fit 2D, structured, level %d" % a.level)
    print("press_fit_mesh.py: %s: %d nodes, %d elements" % (a.output, len(mesh.coords),
                                                            sum(len(b[2]) for b in mesh.blocks)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
