#!/usr/bin/python3
"""Run one input on the distributed and on the replicated mesh and compare the results.

Usage: compare_paths.py [--tol TOL | --dynamic-tol TOL] [--answers-only] INPUT NP GROUT
                        [LAUNCHER ...]

Runs GROUT on INPUT on NP ranks twice, from the working directory: as it chooses (drivers/mesh_choice.hpp says which runs
read the distributed mesh) with
--timers into paths/<input>/distributed_np<NP>, and with GROUT_MESH=replicated into
paths/<input>/replicated_np<NP>. The first must say that it read the distributed mesh, with one
holdings line per rank, each rank holding less than the whole mesh when NP > 1; the second that
it read the replicated one. Then tools/compare_results --geometry: the same Exodus mesh, value
for value, and the same results and CSV summary to 1e-11 of each quantity's scale (round-off:
the two paths partition the mesh differently, so the direct solver sums in another order).
--tol TOL: an input on the iterative solver. The distributed run must have set up MueLu (the
timer "grout: linear solve: MueLu set-up"), and the answers agree to TOL of each quantity's
scale (tools/compare_results --answers-only: the Krylov iteration counts differ with the
partition, which changes the rank-local smoothers and aggregates). TOL = 2 κ(K) τ: each path
stops at ‖r‖ ≤ τ‖b‖ (Belos's `Convergence Tolerance`, 1e-12 by default), so the two answers
differ by K⁻¹(r_a − r_b), at most 2 κ(K) τ of ‖u‖; κ(K) of the free dofs from
condition_number.py.
--dynamic-tol TOL: a dynamic run with contact, whose round-off grows over its steps as the
contact opens and closes (the replicated path's own answers on 2 and 3 ranks differ by up to
1.1e-9 of the scale on the 3D ring pendulum): the answers agree to TOL (1e-8 relative, the
agreement asked of two rank counts, to which a partition is one more), no MueLu asked for.
LAUNCHER: the MPI launcher and its options, used when NP > 1. --answers-only: the converged
answers alone (compare_results --answers-only), for a case whose Newton iterates carry the
solve's round-off times a large condition number, so that their residuals differ by more than
1e-11 between any two partitions, the replicated path's own on 1 and 2 ranks included.
"""
import os
import pathlib
import re
import subprocess
import sys

TOOLS = pathlib.Path(__file__).resolve().parents[2] / "tools"


def run(command, env, label):
    result = subprocess.run(command, env=env, capture_output=True, text=True, timeout=600)
    if result.returncode != 0:
        sys.exit(f"{label}: exit {result.returncode}\n{result.stdout}\n{result.stderr}")
    return result.stdout


def main():
    args = sys.argv[1:]
    tol, iterative = None, False
    if args[:1] in (["--tol"], ["--dynamic-tol"]) and len(args) > 1:
        iterative = args[0] == "--tol"
        tol, args = args[1], args[2:]
    answers_only = bool(args) and args[0] == "--answers-only"
    if answers_only:
        args = args[1:]
    if len(args) < 3:
        sys.exit(__doc__)
    input_file, np, grout, launcher = args[0], int(args[1]), args[2], args[3:]
    stem = pathlib.Path(input_file).stem
    out = pathlib.Path("paths") / stem
    prefix = launcher + ["-np", str(np)] if np > 1 else []
    env = {k: v for k, v in os.environ.items() if k != "GROUT_MESH"}
    distributed_dir, replicated_dir = out / f"distributed_np{np}", out / f"replicated_np{np}"
    log = run(prefix + [grout, input_file, "--output-dir", str(distributed_dir), "--timers"], env,
              "distributed run")
    if "grout: mesh: distributed" not in log:
        sys.exit(f"{input_file} on {np} rank(s) did not read the distributed mesh:\n{log}")
    if iterative and "grout: linear solve: MueLu set-up" not in log:
        sys.exit(f"{input_file} on {np} rank(s) did not take the iterative path:\n{log}")
    held = re.findall(r"^mesh on rank (\d+): nodes (\d+) owned .*\(([\d.]+) % of (\d+)\), "
                      r"elements (\d+) owned .*\(([\d.]+) % of (\d+)\)", log, re.MULTILINE)
    if len(held) != np:
        sys.exit(f"expected {np} holdings lines, got {len(held)}:\n{log}")
    for rank, _, nodes, _, _, elements, _ in held:
        print(f"rank {rank}: {nodes} % of the nodes, {elements} % of the elements")
        if np > 1 and (float(nodes) >= 100.0 or float(elements) >= 100.0):
            sys.exit(f"rank {rank} holds the whole mesh on {np} ranks")
    for what, owned, total in (("nodes", 1, 3), ("elements", 4, 6)):
        if sum(int(h[owned]) for h in held) != int(held[0][total]):
            sys.exit(f"the ranks' owned {what} do not add up to the mesh's {held[0][total]}")
    env["GROUT_MESH"] = "replicated"
    log = run(prefix + [grout, input_file, "--output-dir", str(replicated_dir), "--timers"], env,
              "replicated run")
    if "grout: mesh: replicated" not in log:
        sys.exit(f"GROUT_MESH=replicated did not read the replicated mesh:\n{log}")
    compare = [sys.executable, str(TOOLS / "compare_results"), str(replicated_dir),
               str(distributed_dir), "--geometry"]
    if tol is not None:
        compare += ["--tol", tol]
    if tol is not None or answers_only:
        compare += ["--answers-only"]
    result = subprocess.run(compare, capture_output=True, text=True)
    print(result.stdout, end="")
    return result.returncode


if __name__ == "__main__":
    sys.exit(main())
