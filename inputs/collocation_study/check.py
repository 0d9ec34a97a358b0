"""Exact vs collocation mortar integration (docs/verification.md #6) on the 2D Taylor patch test.

Reference: the Taylor patch test's exact contact pressure is p = 10 at every slave node
(see taylor_patch/check.py: uniform sigma_yy = -10 solves the problem for any mesh). With
exact segment-based integration (docs/design.md §3) the mortar integrals of the piecewise-linear
master field are exact, so the discrete solution reproduces p to round-off. Collocation
integrates Phi_j N_l over a slave element with a fixed rule that ignores the kinks of the
master interpolation at the projected master nodes (here at an arbitrary point of a slave
element), so it is never exact; its error shrinks with the number of points (Popp et al.
2010 §3.3 and Farah, Popp & Wall, "Segment-based vs element-based integration for mortar
methods in computational contact mechanics", Comput. Mech. 55, 2015).

Writes collocation_study.csv (points, integration, max relative pressure error on 1 and on 2
ranks) and asserts: exact < 1e-8; every collocation error > 1e-10 (never round-off);
errors decrease with the number of points (each below the previous: docs/verification.md #6,
"decreasing"); 1- and 2-rank runs agree to 1e-10.
"""
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402
from grout_results import Results  # noqa: E402

P = 10.0
POINTS = [10, 20, 50, 100, 200]


def pressure_error(path):
    r = Results(path)
    s = cc.side_set_nodes(r, "die_bottom")
    return float(np.abs(r.nodal("contact_pressure")[s] - P).max() / P)


def assess(exact, colloc):
    """Failure messages for the exact error and the {points: error} collocation errors."""
    failures = []
    if not exact < 1e-8:
        failures.append("exact integration: pressure error %.2e not at round-off (< 1e-8)" % exact)
    pts = sorted(colloc)
    for n in pts:
        if not colloc[n] > 1e-10:
            failures.append("collocation %d: error %.2e at round-off (> 1e-10 expected)" % (n, colloc[n]))
    for a, b in zip(pts, pts[1:]):
        if not colloc[b] < colloc[a]:
            failures.append("collocation error does not decrease from %d (%.2e) to %d points (%.2e)"
                            % (a, colloc[a], b, colloc[b]))
    return failures


def self_test():
    assert not assess(1e-14, {10: 1e-3, 20: 3e-4, 50: 5e-5, 100: 1e-5, 200: 3e-6})
    assert len(assess(1e-5, {10: 1e-3, 20: 3e-4, 50: 5e-5, 100: 1e-5, 200: 3e-6})) == 1
    assert len(assess(1e-14, {10: 1e-3, 20: 3e-4, 50: 1e-16, 100: 1e-5, 200: 3e-6})) >= 1
    assert len(assess(1e-14, {10: 1e-3, 20: 3e-3, 50: 5e-5, 100: 1e-5, 200: 3e-6})) == 1
    # An error that does not decrease (here 1.5x the previous) fails.
    assert len(assess(1e-14, {10: 1e-3, 20: 3e-4, 50: 4.5e-4, 100: 1e-5, 200: 3e-6})) == 1
    print("collocation_study self-test: ok")


if __name__ == "__main__":
    if "--self-test" in sys.argv:
        self_test()
        sys.exit(0)
    failures = []
    rows = []
    errors = {}
    for stem, points in [("exact", None)] + [("collocation_%d" % n, n) for n in POINTS]:
        e = [pressure_error("np%d/%s.e" % (np_, stem)) for np_ in (1, 2)]
        errors[stem] = e[0]
        diff, msg = cc.compare_ranks("np1/%s.e" % stem, "np2/%s.e" % stem,
                                     ["displ_x", "displ_y", "contact_pressure"])
        if msg:
            failures.append(msg)
        rows.append(["exact" if points is None else points, "exact" if points is None else "collocation",
                     "%.6e" % e[0], "%.6e" % e[1]])
        print("%-16s max |p - 10|/10: np1 %.3e, np2 %.3e; 1 vs 2 ranks %.2e" % (stem, e[0], e[1], diff))
    with open("collocation_study.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["points", "integration", "max_pressure_error_np1", "max_pressure_error_np2"])
        w.writerows(rows)
    print("wrote collocation_study.csv")
    failures += assess(errors["exact"], {n: errors["collocation_%d" % n] for n in POINTS})
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)
