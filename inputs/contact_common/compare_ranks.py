#!/usr/bin/python3
"""Compare a case's results on N ranks with its 1-rank results, every written step and field.

Usage: compare_ranks.py --np N [--tol 1e-10] STEM [STEM ...]

For each STEM, np1/STEM.e against npN/STEM.e (the output folders of grout_case_run): the same
step times, the same nodal, element and global variable names, and every value of every step
within `tol` of the field's scale (max |a − b| / max(|a|, |b|) over the field, step by step).
A field whose scale is at round-off of another field of its kind (a gap or a reaction that should
be 0) is compared against its kind's scale: lengths (displ_*, gaps, slips), contact forces and
pressures (contact_pressure, lm_*, reaction_*), stresses (stress_*), each as a group. Global
counts, timings and the converged residual are not compared. Exits 1 on any
difference, with the stem, field and step named.
"""
import argparse
import re
import sys

import numpy as np

from grout_results import Results


def group(name):
    """The comparison group of a field: fields of one physical kind share one scale."""
    if name.startswith("displ_") or re.search(r"gap|slip", name):
        return "length"
    for prefix in ("velocity_", "accel_", "stress_", "strain_"):
        if name.startswith(prefix):
            return prefix
    if re.match(r"(contact_pressure|lm_|reaction_|contact_force)", name):
        return "force"
    return name


def compare(stem, np_other, tol):
    a, b = Results("np1/%s.e" % stem), Results("np%d/%s.e" % (np_other, stem))
    failures, worst = [], 0.0
    ta, tb = a.times(), b.times()
    if ta.shape != tb.shape or np.abs(ta - tb).max(initial=0.0) > 0.0:
        return ["%s: step times differ (%s vs %s)" % (stem, ta, tb)], np.inf
    for kind, names_a, names_b, read in (
            ("nodal", a.nodal_names, b.nodal_names, lambda r, n, s: r.nodal(n, s)),
            ("element", a.element_names, b.element_names, lambda r, n, s: r.element(n, s)),
            ("global", a.global_names, b.global_names, lambda r, n, s: r.global_var(n, s))):
        if names_a != names_b:
            failures.append("%s: %s variables differ: %s vs %s" % (stem, kind, names_a, names_b))
            continue
        for step in range(len(ta)):
            values = {n: (np.atleast_1d(read(a, n, step)), np.atleast_1d(read(b, n, step)))
                      for n in names_a}
            scale = {}
            for n, (x, y) in values.items():
                s = max(np.abs(x).max(initial=0.0), np.abs(y).max(initial=0.0))
                scale[group(n)] = max(scale.get(group(n), 0.0), s)
            for n, (x, y) in values.items():
                if kind == "global" and re.search(r"iterations|time|wall|residual", n):
                    continue  # counts, timings and the converged residual: not results
                if x.shape != y.shape:
                    failures.append("%s: %s %s has %d vs %d values" % (stem, kind, n, x.size, y.size))
                    continue
                s = scale[group(n)]
                d = np.abs(x - y).max(initial=0.0) / s if s > 0 else 0.0
                worst = max(worst, d)
                if d > tol:
                    failures.append("%s: %s %s step %d: 1 and %d ranks differ by %.2e (tol %.0e)"
                                    % (stem, kind, n, step + 1, np_other, d, tol))
    return failures, worst


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("stems", nargs="+")
    ap.add_argument("--np", type=int, required=True)
    ap.add_argument("--tol", type=float, default=1e-10)
    args = ap.parse_args()
    failures = []
    for stem in args.stems:
        f, worst = compare(stem, args.np, args.tol)
        print("%s: 1 vs %d ranks, worst %.2e over every field and step" % (stem, args.np, worst))
        failures += f
    for f in failures[:20]:
        print("FAIL", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
