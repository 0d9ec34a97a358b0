#!/usr/bin/env bash
# The tooth model's full-size study (README.md): three nested meshes of each variant at the
# default sizes of tooth.py (contact size 0.005, 0.0025, 0.00125 mm), each run on 1 rank
# (and on 2 ranks with --ranks 2), then check.py on them. The wall and CPU times of every run are printed.
# Usage: inputs/tooth/full.sh BUILD_DIR OUT_DIR [--ranks 2]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "$1" && pwd)
mkdir -p "$2"
out=$(cd "$2" && pwd)
two=0
[ "${3:-}" = "--ranks" ] && [ "${4:-}" = "2" ] && two=1
cd "$out"
mkdir -p np1 np2
stems=()
for variant in ec edc; do
  dentine=""
  [ "$variant" = edc ] && dentine=--dentine
  for level in 1 2 3; do
    stem=tooth_${variant}_${level}
    stems+=("$stem")
    /usr/bin/python3 "$here/tooth.py" "$stem.exo" $dentine --level "$level"
    cp "$here/$stem.yaml" .
    TIMEFORMAT="$stem: 1 rank: %R s wall, %U s user, %S s sys (all processes)"
    time "$build/bin/grout" "$stem.yaml" --output-dir np1 > "np1/$stem.log" 2>&1
    if [ $two = 1 ]; then
      TIMEFORMAT="$stem: 2 ranks: %R s wall, %U s user, %S s sys (all processes)"
      time "$here/../../tools/local_mpi_env" mpirun --oversubscribe --allow-run-as-root -np 2 \
        "$build/bin/grout" "$stem.yaml" --output-dir np2 > "np2/$stem.log" 2>&1
    fi
  done
done
ranks=()
[ $two = 1 ] && ranks=(--ranks "${stems[@]}")
PYTHONPATH="$here/../../tools" MPLBACKEND=Agg /usr/bin/python3 "$here/check.py" "${ranks[@]}"
