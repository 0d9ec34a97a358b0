#!/usr/bin/python3
"""Mesh of the squeezed flat tube (inputs/self_contact/README.md): the cross-section of a tube
pressed flat, one body, one element block, plane strain.

Usage: flat_tube.py OUTPUT.exo [--width W] [--gap G] [--thickness T] [--flat N] [--end N]
                    [--layers N] [--length L --slices N]

The cavity is a stadium: two flat inner walls y = +-G/2 for |x| <= W/2, joined by half circles
of radius G/2 centred at (+-W/2, 0). The wall, of thickness T, is the band between the cavity
and its offset by T (flat outer walls y = +-(G/2 + T), half circles of radius G/2 + T). An
O-grid of QUAD4: --flat elements along each flat wall, --end along each half circle, --layers
through the thickness.

Sets: side set `inner` (the whole cavity wall: the self-contact surface), `outer`; node sets
`top_nodes` and `bottom_nodes` (the outer flat walls, |x| <= W/2, y > 0 and y < 0),
`inner_nodes`, `outer_nodes`. --length L: the tube itself, the section swept along z over
[0, L] in --slices HEX8 layers (the sets swept with it; node sets z_faces, z0_nodes, zt_nodes).
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from exodus_mesh import Mesh, extrude, write_exodus  # noqa: E402


def cavity(W, G, flat, end):
    """Points and outward (into the wall) unit normals round the cavity, counter-clockwise
    from (-W/2, -G/2): bottom flat, right half circle, top flat, left half circle."""
    r = G / 2
    pts, nrm = [], []
    for i in range(flat):  # bottom wall, left to right; the wall is below: normal (0, -1)
        pts.append((-W / 2 + W * i / flat, -r))
        nrm.append((0.0, -1.0))
    for i in range(end):  # right end, from angle -90 to 90 degrees
        a = -math.pi / 2 + math.pi * i / end
        pts.append((W / 2 + r * math.cos(a), r * math.sin(a)))
        nrm.append((math.cos(a), math.sin(a)))
    for i in range(flat):  # top wall, right to left
        pts.append((W / 2 - W * i / flat, r))
        nrm.append((0.0, 1.0))
    for i in range(end):  # left end, from 90 to 270 degrees
        a = math.pi / 2 + math.pi * i / end
        pts.append((-W / 2 + r * math.cos(a), r * math.sin(a)))
        nrm.append((math.cos(a), math.sin(a)))
    return np.array(pts), np.array(nrm)


def build(W, G, T, flat, end, layers):
    p, n = cavity(W, G, flat, end)
    m = len(p)
    coords = np.vstack([p + (T * j / layers) * n for j in range(layers + 1)])
    conn = []
    for j in range(layers):
        for i in range(m):
            a, b = j * m + i, j * m + (i + 1) % m
            conn.append((a, b, b + m, a + m))
    mesh = Mesh(coords)
    mesh.add_block("tube", "QUAD4", np.array(conn))
    faces = mesh.boundary_faces()
    inner, outer = [], []
    for key, es in faces.items():
        a, b = sorted(key)
        (inner if a < m and b < m else outer).append(es)
    mesh.side_sets["inner"] = sorted(inner)
    mesh.side_sets["outer"] = sorted(outer)
    mesh.add_side_set_node_sets()
    x = mesh.coords
    out = np.arange(layers * m, (layers + 1) * m)
    flat_out = out[np.abs(np.abs(x[out, 1]) - (G / 2 + T)) < 1e-12]
    flat_out = flat_out[np.abs(x[flat_out, 0]) <= W / 2 + 1e-12]
    mesh.node_sets["top_nodes"] = np.sort(flat_out[x[flat_out, 1] > 0])
    mesh.node_sets["bottom_nodes"] = np.sort(flat_out[x[flat_out, 1] < 0])
    return mesh


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("output")
    p.add_argument("--width", type=float, default=2.0)
    p.add_argument("--gap", type=float, default=0.3)
    p.add_argument("--thickness", type=float, default=0.1)
    p.add_argument("--flat", type=int, default=40)
    p.add_argument("--end", type=int, default=12)
    p.add_argument("--layers", type=int, default=2)
    p.add_argument("--length", type=float, default=0.0)
    p.add_argument("--slices", type=int, default=2)
    a = p.parse_args()
    mesh = build(a.width, a.gap, a.thickness, a.flat, a.end, a.layers)
    if a.length > 0:
        mesh = extrude(mesh, a.length, a.slices)
    write_exodus(mesh, a.output, title="squeezed flat tube")


if __name__ == "__main__":
    main()
