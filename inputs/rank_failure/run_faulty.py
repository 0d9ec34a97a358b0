"""A failure that one rank alone meets inside the iterative solve ends or continues the whole
job alike on every rank, never a hang (inputs/rank_failure/README.md).

usage: run_faulty.py <stall|first> <input.yaml> <module dir> <driver> <mpiexec and its options>

The run uses the faulty module in <module dir> (GROUT_PLUGIN_DIR) on 2 ranks:
  stall: rank 0's second solve (step 2's first; step 1 converges in one) throws while rank 1
         waits in a collective for it. Passes when the job ends within the stall limit
         (GROUT_STALL_LIMIT = 2 s) plus start-up, with exit code 1, rank 0's message on standard
         error, no library trace, and the results file holding step 1 (t = 0.5) with
         contact_pressure = p/2.
  first: rank 0's first solve throws after every rank solved. Passes when both ranks cut the
         step back together and finish: exit 0, the cut-back in the log, t = 1 reached, and
         contact_pressure = p on the contact surface (the patch test's exact answer, to 1e-6,
         the Krylov tolerance's reach).
On 2 ranks without the agreement of nonlinear/timed_agreement.hpp both hang until the timeout."""
import os
import subprocess
import sys
import time

import numpy as np

from grout_results import Results

P = 1.0e8  # faulty.yaml's pressure
STALL_LIMIT = 2.0
START_UP = 60.0  # reading, set-up and the first solve, with margin for a loaded machine


def check_last_step(results, t, failures):
    """The file's last step is at time t, with contact_pressure = p t on the contact nodes."""
    times = results.times()
    if abs(times[-1] - t) > 1e-12:
        failures.append("last time %g, expected %g" % (times[-1], t))
    pressure = results.nodal("contact_pressure")
    touching = pressure[pressure != 0.0]
    error = np.max(np.abs(touching / (P * t) - 1.0)) if touching.size else np.inf
    print("t = %g: contact nodes %d, max |p/(P t) - 1| = %.2e" % (times[-1], touching.size, error))
    if touching.size == 0 or error > 1e-6:
        failures.append("contact_pressure differs from p t by %.2e (1e-6)" % error)


def main():
    mode, input_path, module_dir, driver = sys.argv[1:5]
    mpiexec = sys.argv[5:]
    out = "out_" + mode
    env = dict(os.environ, GROUT_PLUGIN_DIR=module_dir, GROUT_FAULTY_SOLVE=mode,
               GROUT_STALL_LIMIT=str(STALL_LIMIT), OMP_NUM_THREADS="1")
    command = mpiexec + ["-np", "2", driver, input_path, "--output-dir", out]
    start = time.monotonic()
    try:
        run = subprocess.run(command, env=env, capture_output=True, text=True,
                             timeout=STALL_LIMIT + START_UP)
    except subprocess.TimeoutExpired:
        sys.exit("FAIL: the job did not end within %g s (a hang)" % (STALL_LIMIT + START_UP))
    took = time.monotonic() - start
    print(run.stdout)
    print(run.stderr, file=sys.stderr)
    failures = []
    if mode == "stall":
        if run.returncode != 1:
            failures.append("exit code %d, expected 1" % run.returncode)
        if "injected failure on rank 0 (stall)" not in run.stderr:
            failures.append("rank 0's message is not on standard error")
        if "did not answer within 2 s" not in run.stderr:
            failures.append("no word of the ranks that did not answer")
        for trace in ("Throw number", "terminate called", "what():"):
            if trace in run.stderr:
                failures.append("a library trace on standard error: " + trace)
        check_last_step(Results(os.path.join(out, "faulty.e")), 0.5, failures)
    else:
        if run.returncode != 0:
            failures.append("exit code %d, expected 0" % run.returncode)
        if "cutting the step" not in run.stdout:
            failures.append("no cut-back in the log")
        if run.returncode == 0:
            check_last_step(Results(os.path.join(out, "faulty.e")), 1.0, failures)
    print("%s: %.1f s, exit code %d" % (mode, took, run.returncode))
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("ok")


if __name__ == "__main__":
    main()
