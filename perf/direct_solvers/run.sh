#!/usr/bin/env bash
# MUMPS against KLU2 (amesos2) on the two-block 3D contact case stacked_3d.yaml, whole runs
# of the driver: wall time and peak memory (/usr/bin/time -v), the linear-solve time
# (grout --timers), and the largest relative difference of every nodal and element result.
# Usage (from the project root, after tools/build):
#   perf/direct_solvers/run.sh N [RANKS] [SOLVERS]
#     N: lower block N x N x N/2 elements, upper (N+1) x (N+1) x N/2 (14: 3 848 nodes,
#        20: 10 175 nodes); RANKS default 1; SOLVERS default "mumps amesos2".
# Output in build/direct_solvers/n<N>_np<RANKS>/.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build_dir=${GROUT_BUILD_DIR:-$root/build}
n=$1
np=${2:-1}
solvers=${3:-"mumps amesos2"}
work=$build_dir/direct_solvers/n${n}_np$np
mkdir -p "$work"
cd "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
"$build_dir/bin/grout_mesh" stacked_3d --nx-lower "$n" --ny-lower "$n" --nz-lower $((n / 2)) \
  --nx-upper $((n + 1)) --ny-upper $((n + 1)) --nz-upper $((n / 2)) -o stacked.exo >/dev/null
echo "perf/direct_solvers/run.sh: n = $n, $np rank(s), load before: $(cut -d' ' -f1-3 /proc/loadavg)"
for solver in $solvers; do
  sed -e "s/MESH/stacked.exo/" -e "s/SOLVER/$solver/" -e "s/OUTPUT/$solver/g" \
    "$root/perf/direct_solvers/stacked_3d.yaml" >"$solver.yaml"
  launch=()
  [ "$np" -gt 1 ] && launch=("$root/tools/local_mpi_env" mpirun --oversubscribe -np "$np")
  /usr/bin/time -v -o "$solver.time" "${launch[@]}" "$build_dir/bin/grout" "$solver.yaml" \
    --timers >"$solver.log" 2>&1 || { cat "$solver.log"; exit 1; }
  wall=$(awk -F': ' '/Elapsed/ {print $2}' "$solver.time")
  rss=$(awk -F': ' '/Maximum resident/ {printf "%.0f", $2 / 1024}' "$solver.time")
  cpu=$(awk -F': ' '/User time|System time/ {s += $2} END {printf "%.2f", s}' "$solver.time")
  echo "$solver: wall $wall, CPU ${cpu} s (user + sys, all ranks), peak RSS ${rss} MB (largest" \
    "rank); $(grep -m1 '^step' "$solver.log")"
  grep -E "grout: (linear solve|MUMPS)" "$solver.log" | sed 's/^/  /'
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
set -- $solvers
# Differences relative to the largest magnitude of each kind of field, as
# inputs/solver_agreement/check.py (lengths, forces, stresses; contact_status equal).
PYTHONPATH="$root/tools:$root/inputs/solver_agreement" /usr/bin/python3 - "$@" <<'PY'
import sys
import numpy as np
from check import fields, kind, scales
from grout_results import Results
first = fields(Results(sys.argv[1] + ".e"), -1)
scale = scales(first)
for other_name in sys.argv[2:]:
    other = fields(Results(other_name + ".e"), -1)
    worst = {}
    for name, a in first.items():
        k = kind(name)
        if k == "status":
            print("contact_status %s" % ("equal" if np.array_equal(a, other[name]) else "DIFFERS"))
            continue
        d = float(np.abs(a - other[name]).max()) / scale[k]
        worst[k] = max(worst.get(k, 0.0), d)
    print("largest relative difference %s vs %s: %s" % (other_name, sys.argv[1],
          ", ".join("%s %.2e" % kv for kv in sorted(worst.items()))))
PY
