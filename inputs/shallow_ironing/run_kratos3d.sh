#!/usr/bin/env bash
# Shallow ironing on the reference's own 3D model (docs/verification.md #19): Kratos' mesh
# shallow_ironing3D.mdpa (KratosMultiphysics/Examples, commit 9eacc7b3,
# contact_structural_mechanics/validation/shallow_ironing_3D/source; not in this repository),
# frictionless and mu = 0.3 (kratos3d_*.yaml), then check.py with #19's targets, its defaults:
# the F_y plateau (1.3 <= t <= 1.7) within 7 % of the published one, and F_x/F_y in
# [1.00, 1.06] mu at every step of the plateau in full slip. Exits 1 when a target fails.
# Usage: inputs/shallow_ironing/run_kratos3d.sh MDPA [BUILD_DIR] [RANKS]
#   BUILD_DIR default build/; RANKS 1 (default) or "1 2" (also on 2 ranks, compared with 1).
#   Work folder: BUILD_DIR/ironing_kratos3d. About 20 and 28 min on 1 rank (15 876 nodes).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
mdpa=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
build=$(cd "${2:-$root/build}" && pwd)
ranks=${3:-1}
work=$build/ironing_kratos3d
mkdir -p "$work"
cd "$work"
/usr/bin/python3 "$root/tools/mdpa_to_exodus.py" "$mdpa" kratos3d.exo
cp "$here"/kratos3d_frictionless.yaml "$here"/kratos3d_frictional.yaml .
for input in kratos3d_frictionless kratos3d_frictional; do
  for np in $ranks; do
    if [ "$np" = 1 ]; then
      "$build/bin/grout" $input.yaml --output-dir np1 > np1_$input.log
    else
      OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "$root/tools/local_mpi_env" \
        mpirun --oversubscribe -np "$np" "$build/bin/grout" $input.yaml --output-dir np$np \
        > np${np}_$input.log
    fi
  done
done
status=0
for case in "kratos3d_frictionless 0" "kratos3d_frictional 0.3"; do
  PYTHONPATH=$root/tools MPLBACKEND=Agg /usr/bin/python3 "$here/check.py" $case --ranks $ranks \
    --force-set displacement_displacement_auto2 --label "3D, Kratos' mesh" || status=1
done
exit $status
