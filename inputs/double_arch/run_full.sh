#!/usr/bin/env bash
# The full double arc (imposed displacement to 0.075 m, frictionless and mu = 0.5) on 1 and 2
# ranks, then check.py: docs/verification.md #14's bands (the literature errors printed).
# Usage: inputs/double_arch/run_full.sh [BUILD_DIR]   (default build/; about 2 x 70 s per rank
# count on one core). Work folder: BUILD_DIR/inputs/double_arch/full. Also runs
# double_arch_readme.yaml (the README's materials) on 1 rank for the comparison.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
work=$build/inputs/double_arch/full
mkdir -p "$work"
cd "$work"
/usr/bin/python3 "$here/arch_on_block.py" double_arch.exo --center 0.125 0.145 \
  --radii 0.085 0.09 0.095 --layer-names ring_inner ring_outer --block 0 0.25 0 \
  --n-around 60 --n-layer 2 2 --block-nx 50 --block-ny 7
cp "$here"/double_arch.yaml "$here"/double_arch_mu05.yaml "$here"/double_arch_readme.yaml .
for input in double_arch.yaml double_arch_mu05.yaml; do
  "$build/bin/grout" "$input" --output-dir np1 > "np1_${input%.yaml}.log"
  OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "$root/tools/local_mpi_env" \
    mpirun --oversubscribe -np 2 "$build/bin/grout" "$input" --output-dir np2 \
    > "np2_${input%.yaml}.log"
done
"$build/bin/grout" double_arch_readme.yaml --output-dir readme > readme.log
PYTHONPATH=$root/tools MPLBACKEND=Agg /usr/bin/python3 "$here/check.py" \
  --frictionless double_arch --frictional double_arch_mu05
