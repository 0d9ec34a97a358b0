"""A run killed with SIGKILL in the middle of a multi-step case leaves a readable Exodus file
that holds every step its log reported, at the reported times, and at most one step more, each
still the right solution (Lamé's thick cylinder, u_r = t * u_r^Lamé(r) under the pressure 10 t,
within the mesh error). The driver writes and flushes a step before it prints the step's line
(drivers/grout.cpp, write_step), so that no reported step can be missing from the file; a kill
between the two leaves the one step written and not yet reported (seen once in CI on a loaded
machine: 3 steps in the file, 2 in the log).

usage: kill_run.py <ranks> <input.yaml> <driver> [mpiexec and its options]

The results file is found through the name the log reports ("grout: results file ..."); the
driver's ranks are killed after the second reported step; every line the run printed before
it died counts as reported."""
import os
import re
import signal
import subprocess
import sys
import time

import numpy as np

from grout_results import Results
from lame import nodal_radial

KILL_AFTER_STEPS = 2
MESH_TOLERANCE = 0.01  # max relative u_r error of this mesh (3.3e-3 measured; 8 x 16 QUAD4)


def descendants(pid):
    """Process ids below `pid` (the ranks under mpiexec), from /proc."""
    children = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % entry) as f:
                parent = int(f.read().rsplit(")", 1)[1].split()[1])
        except (OSError, IndexError, ValueError):
            continue
        children.setdefault(parent, []).append(int(entry))
    found, todo = [], [pid]
    while todo:
        for child in children.get(todo.pop(), []):
            found.append(child)
            todo.append(child)
    return found


def main():
    ranks, input_file, driver = int(sys.argv[1]), sys.argv[2], sys.argv[3]
    launcher = sys.argv[4:]
    out_dir = "killed_np%d" % ranks
    command = [driver, input_file, "--output-dir", out_dir]
    if ranks > 1:
        command = launcher + ["-np", str(ranks)] + command
    run = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    results_file, lines, steps_seen, killed = None, [], 0, False
    for line in run.stdout:
        lines.append(line.rstrip("\n"))
        match = re.match(r"grout: results file (.+)$", lines[-1])
        if match:
            results_file = match.group(1)
        if re.match(r"step \d+ ", lines[-1]):
            steps_seen += 1
            if steps_seen == KILL_AFTER_STEPS and not killed:
                # The driver itself: the process on 1 rank, every rank under mpiexec.
                victims = [run.pid] if ranks == 1 else descendants(run.pid)
                for pid in victims:
                    try:
                        os.kill(pid, signal.SIGKILL)
                    except ProcessLookupError:
                        pass
                killed = True
                print("killed %s after step %d was reported" % (victims, steps_seen))
    try:
        run.wait(timeout=120)
    except subprocess.TimeoutExpired:
        run.kill()
        run.wait()
    print("\n".join("  | " + l for l in lines))

    failures = []
    if not killed:
        failures.append("the run ended before %d steps were reported" % KILL_AFTER_STEPS)
    if any(l.startswith("grout: wrote") for l in lines):
        failures.append("the run finished before it was killed: make the case longer")
    if results_file is None:
        failures.append("the log does not name the results file")
    reported = [float(m.group(1)) for m in
                (re.match(r"step \d+\s+t = (\S+)", l) for l in lines) if m]
    if results_file is not None and not failures:
        results = Results(results_file)
        times = results.times()
        print("log: %d steps %s; %s: %d steps %s" % (len(reported), reported, results_file,
                                                     len(times), list(times)))
        if not len(reported) <= len(times) <= len(reported) + 1:
            failures.append("the file holds %d steps, the log reported %d (expected those, and "
                            "at most the one being reported)" % (len(times), len(reported)))
        elif not np.allclose(times[:len(reported)], reported, rtol=1e-5, atol=0):
            failures.append("step times differ: file %s, log %s" % (list(times), reported))
        for step, t in enumerate(times):
            r, ur, exact = nodal_radial(results_file, step=step)
            error = np.abs(ur - t * exact).max() / np.abs(t * exact).max()
            print("step %d (t = %g): max relative u_r error %.2e" % (step + 1, t, error))
            if not np.all(np.isfinite(ur)) or not error < MESH_TOLERANCE:
                failures.append("step %d: u_r error %.2e (tolerance %g)"
                                % (step + 1, error, MESH_TOLERANCE))
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
