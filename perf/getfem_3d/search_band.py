#!/usr/bin/python3
"""Diagnostic for Grout's 3D Hertz case in reference geometry (strain: small): which slave faces
of upper_contact get a coarse-search candidate at zero displacement?

Grout evaluates D, M and the normals once, on the reference positions
(nonlinear/mechanics_problem.cpp, `!current_geometry`), with the coarse search of
kernels/coarse_search.hpp: face bounding boxes grown by search_factor (0.5,
assembly/contact_mortar.hpp) x the box's largest extent. On the hemispheres the reference gap
at distance r from the axis is about r^2, so only slave faces with r^2 below about one face
size have a master candidate. This script repeats that box test (numpy, brute force) and prints
the largest r of a slave node on a face with a candidate, to compare with the Hertz contact
radius (~0.165 for the 0.05 approach).

Usage: search_band.py MESH.exo [...] [--factor 0.5]
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from getfem_hertz_3d import EXO_SIDE_NODES, read_exodus  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("meshes", nargs="+")
    ap.add_argument("--factor", type=float, default=0.5)
    a = ap.parse_args()
    for path in a.meshes:
        X, blocks, ss, _ = read_exodus(path)

        def faces(name):
            return np.array([blocks[bn][k][list(EXO_SIDE_NODES[s])] for bn, k, s in ss[name]])

        def boxes(F):
            P = X[:, F]  # (3, n_faces, 3)
            lo, hi = P.min(axis=2), P.max(axis=2)
            ext = (hi - lo).max(axis=0)
            return lo - a.factor * ext, hi + a.factor * ext

        S, M = faces("upper_contact"), faces("lower_contact")
        slo, shi = boxes(S)
        mlo, mhi = boxes(M)
        has = np.zeros(len(S), dtype=bool)
        for i in range(0, len(S), 256):  # chunks: (3, 256, n_master) booleans
            j = slice(i, i + 256)
            has[j] = np.all((slo[:, j, None] <= mhi[:, None, :]) & (mlo[:, None, :] <= shi[:, j, None]),
                            axis=0).any(axis=1)
        r = np.hypot(X[0], X[1])
        paired = np.unique(S[has])
        unpaired = np.setdiff1d(np.unique(S), paired)
        print("%s: %d of %d slave faces have a candidate; slave nodes on them up to r = %.4f; "
              "nearest slave node on no such face at r = %.4f"
              % (path, has.sum(), len(S), r[paired].max(), r[unpaired].min()))


if __name__ == "__main__":
    main()
