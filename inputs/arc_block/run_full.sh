#!/usr/bin/env bash
# The full arc-on-block paths (d = 1, 1 and 1.775; the finer block of arc_block.exo) on 1 and
# 2 ranks, then check.py (docs/verification.md has the results).
# Usage: inputs/arc_block/run_full.sh [BUILD_DIR]   (default build/; about 4 min per case and
# rank count on one core). Work folder: BUILD_DIR/inputs/arc_block/full.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
work=$build/inputs/arc_block/full
mkdir -p "$work"
cd "$work"
/usr/bin/python3 "$root/inputs/double_arch/arch_on_block.py" arc_block.exo --center 3 6 \
  --radii 2.8 3.0 --layer-names arc --block 0 9 0 --n-around 180 --n-layer 4 \
  --block-nx 90 --block-ny 30
for case in rigid_block deformable_block rigid_arc; do
  cp "$here/$case.yaml" .
  "$build/bin/grout" "$case.yaml" --output-dir np1 > "np1_$case.log"
  OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "$root/tools/local_mpi_env" \
    mpirun --oversubscribe -np 2 "$build/bin/grout" "$case.yaml" --output-dir np2 > "np2_$case.log"
done
PYTHONPATH=$root/tools MPLBACKEND=Agg /usr/bin/python3 "$here/check.py"
