"""The linear solvers give the same answer: for every case, every nodal and element variable
of every (solver, ranks) run equals the first solver's 1-rank run to 1e-8 at every output
time the two runs share (the final time must be shared), relative to the largest magnitude
of the variable's kind over the reference run's output times (lengths: displacements, gaps,
slips; forces: reactions; stresses: stresses, multipliers, contact pressure; contact_status
must be equal). The scale is taken over the run, not per time: at the first step of a
load path the reactions can be nearly self-balanced (1e-8 of the final ones in
hertz_frictional_1), and round-off of the internal forces, which are not small, would then
read as a large relative difference. Newton converges to
round-off in every run, so the answers differ by the linear solves' errors only.

Usage: check.py hertz_1=mumps,amesos2,belos straight_3d=mumps,amesos2 ...
(run in the case folder: results np<ranks>/<case>_<solver>.e, ranks 1 and 2).
"""
import argparse
import sys

import numpy as np

from grout_results import Results

TOLERANCE = 1e-8


def kind(name):
    if name.startswith(("displ_", "slip_")) or name == "normal_gap":
        return "length"
    if name.startswith("reaction_"):
        return "force"
    if name == "contact_status":
        return "status"
    return "stress"  # stress_*, lm_*, contact_pressure


def fields(results, step):
    out = {n: results.nodal(n, step) for n in results.nodal_names}
    out.update({n: results.element(n, step) for n in results.element_names})
    return out


def scales(values):
    """Largest magnitude per kind; the length scale is the largest displacement."""
    s = {"length": 0.0, "force": 0.0, "stress": 0.0}
    for name, v in values.items():
        k = kind(name)
        if k in s and (k != "length" or name.startswith("displ_")):
            s[k] = max(s[k], float(np.abs(v).max(initial=0.0)))
    return {k: max(v, 1e-300) for k, v in s.items()}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("cases", nargs="+", help="case=solver,solver,...")
    args = parser.parse_args()
    failures, worst = [], 0.0
    for spec in args.cases:
        case, solvers = spec.split("=")
        solvers = solvers.split(",")
        ref_path = "np1/%s_%s.e" % (case, solvers[0])
        ref = Results(ref_path)
        ref_times = list(ref.times())
        scale = {"length": 1e-300, "force": 1e-300, "stress": 1e-300}
        for i in range(len(ref_times)):
            for k, v in scales(fields(ref, i)).items():
                scale[k] = max(scale[k], v)
        for solver in solvers:
            for np_ in (1, 2):
                path = "np%d/%s_%s.e" % (np_, case, solver)
                other = Results(path)
                times = list(other.times())
                if not times or times[-1] != ref_times[-1]:
                    failures.append("%s: final time %s, %s has %s" % (path, times[-1:], ref_path,
                                                                     ref_times[-1]))
                    continue
                for i, t in enumerate(ref_times):
                    if t not in times:
                        continue  # a run that cut a step back has other intermediate times
                    a, b = fields(ref, i), fields(other, times.index(t))
                    for name, va in a.items():
                        vb = b.get(name)
                        if vb is None or vb.shape != va.shape:
                            failures.append("%s: %s missing or of another shape" % (path, name))
                            continue
                        if kind(name) == "status":
                            if not np.array_equal(va, vb):
                                failures.append("%s t=%g: contact_status differs" % (path, t))
                            continue
                        d = float(np.abs(va - vb).max(initial=0.0)) / scale[kind(name)]
                        worst = max(worst, d)
                        if not d <= TOLERANCE:
                            failures.append("%s t=%g: %s differs from %s by %.2e (> %g)"
                                            % (path, t, name, ref_path, d, TOLERANCE))
        print("%-20s %s x 1, 2 ranks compared" % (case, ", ".join(solvers)))
    print("largest relative difference: %.2e" % worst)
    for f in failures:
        print("FAIL " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
