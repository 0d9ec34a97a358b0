"""Thick-walled cylinder: the maximum nodal error of u_r against Lamé's solution decreases
at O(h^2) over three meshes (observed rate > 1.8 on both refinements), the finest mesh is
within 0.5 %, and 1 and 2 ranks agree to 1e-10."""
import math
import sys

import numpy as np

from grout_results import Results, relative_difference
from lame import max_relative_error

failures = []
errors = []
for level in (1, 2, 3):
    e = max_relative_error("np1/lame_%d.e" % level)
    errors.append(e)
    r1 = Results("np1/lame_%d.e" % level)
    r2 = Results("np2/lame_%d.e" % level)
    diff = max(relative_difference(r1.nodal(v), r2.nodal(v)) for v in ("displ_x", "displ_y"))
    print("level %d (h = 1/%d): max relative u_r error %.3e; 1 vs 2 ranks %.1e"
          % (level, 4 * 2 ** (level - 1), e, diff))
    if not diff < 1e-10:
        failures.append("level %d: 1 and 2 ranks differ by %.2e" % (level, diff))
rates = [math.log2(errors[i] / errors[i + 1]) for i in range(2)]
print("observed rates: %.3f, %.3f (expected 2)" % tuple(rates))
if not all(rate > 1.8 for rate in rates):
    failures.append("convergence rate below 1.8: %s" % rates)
if not errors[-1] < 5e-3:
    failures.append("finest error %.3e above 0.5 %%" % errors[-1])
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
