#!/usr/bin/env python3
"""Finite-strain dynamics with a stiff body (ring_finite_fall.yaml), against the free fall.

Until the first contact (t = 0.09 s) the cylinder falls freely: every node moves by
u_y = -1/2 g t^2 (a uniform acceleration, which Newmark's average-acceleration scheme
integrates exactly, and which strains nothing), u_x = 0; the ring, held on its outer surface
and carrying only its own weight, moves by less than its static sag (g rho R^2 / E ~ 3e-7 m
for the 0.1 m thick steel ring). Checked at every output step, on 1 and 2 ranks, and
1 = 2 ranks to round-off.
Usage: check_finite_fall.py [stem]   (reads np1/<stem>.e and np2/<stem>.e)
"""
import sys

import numpy as np

from grout_results import Results

G = 9.81
stem = sys.argv[1] if len(sys.argv) > 1 else "ring_finite_fall"
failures = []
runs = {}
for np_ in (1, 2):
    res = Results("np%d/%s.e" % (np_, stem))
    runs[np_] = res
    x, y = res.coordinates()[:2]
    blocks = [np.unique(res.connectivity(b)) for b in range(1, res.num_blocks + 1)]
    # The cylinder is the block whose nodes lie within 0.25 of their centroid.
    def radius(nodes):
        return np.hypot(x[nodes] - x[nodes].mean(), y[nodes] - y[nodes].mean()).max()
    cylinder = min(blocks, key=radius)
    ring = max(blocks, key=radius)
    times = res.times()
    if len(times) < 1 or times[-1] < 0.05 - 1e-12:
        failures.append("np%d: the run stopped at t = %g (expected 0.05)" % (np_, times[-1]))
    worst_fall = worst_ring = 0.0
    for k, t in enumerate(times):
        ux, uy = res.nodal("displ_x", k), res.nodal("displ_y", k)
        fall = 0.5 * G * t * t
        if fall > 0:
            err = max(np.abs(uy[cylinder] + fall).max(), np.abs(ux[cylinder]).max()) / fall
            worst_fall = max(worst_fall, err)
        worst_ring = max(worst_ring, np.hypot(ux[ring], uy[ring]).max())
    print("np%d: cylinder against -1/2 g t^2: max relative error %.2e at %d steps (limit 1e-6);"
          " ring displacement max %.2e m (limit 1e-6 m)" % (np_, worst_fall, len(times), worst_ring))
    if not worst_fall < 1e-6:
        failures.append("np%d: the cylinder does not fall freely (%.2e)" % (np_, worst_fall))
    if not worst_ring < 1e-6:
        failures.append("np%d: the ring moves by %.2e m" % (np_, worst_ring))
d = max(np.abs(runs[1].nodal(n) - runs[2].nodal(n)).max() for n in ("displ_x", "displ_y"))
print("1 vs 2 ranks: max displacement difference %.2e m (limit 1e-12)" % d)
if not d < 1e-12:
    failures.append("1 and 2 ranks differ by %.2e m" % d)
for f in failures:
    print("FAIL:", f)
print("ring_finite_fall: " + ("FAILED" if failures else "all checks passed"))
sys.exit(1 if failures else 0)
