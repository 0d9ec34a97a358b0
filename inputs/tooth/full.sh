#!/usr/bin/env bash
# The tooth model's full-size study (README.md): three nested meshes of each variant at the
# default sizes of tooth.py (contact size 0.005, 0.0025, 0.00125 mm), each run on 1 rank
# (and on 2 ranks with --ranks 2), then check.py on them. Wall time of every run printed.
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
    start=$(date +%s.%N)
    "$build/bin/grout" "$stem.yaml" --output-dir np1 > "np1/$stem.log" 2>&1
    echo "$stem: 1 rank: $(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN {printf "%.1f", b - a}') s wall"
    if [ $two = 1 ]; then
      start=$(date +%s.%N)
      "$here/../../tools/local_mpi_env" mpirun --oversubscribe --allow-run-as-root -np 2 \
        "$build/bin/grout" "$stem.yaml" --output-dir np2 > "np2/$stem.log" 2>&1
      echo "$stem: 2 ranks: $(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN {printf "%.1f", b - a}') s wall"
    fi
  done
done
ranks=()
[ $two = 1 ] && ranks=(--ranks "${stems[@]}")
PYTHONPATH="$here/../../tools" MPLBACKEND=Agg /usr/bin/python3 "$here/check.py" "${ranks[@]}"
