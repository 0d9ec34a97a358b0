#!/usr/bin/env bash
# The double arc solved by GetFEM 5.4 and by Grout on the same meshes (frictionless, and
# mu = 0.5), against the literature (docs/verification.md, "Double arc", "Independent check
# with GetFEM").
# Usage: inputs/double_arch/run_getfem.sh [BUILD_DIR]   (default build/). Work folder:
# BUILD_DIR/inputs/double_arch/full (shared with run_full.sh). Runs, on 1 rank:
#   Grout  double_arch.yaml on Kratos' mesh and on a mesh twice as fine,
#   GetFEM QK(2,1) on both meshes (same elements as Grout), QK(2,2) on Kratos' mesh, and
#          QK(2,1) with the base's E halved (a diagnostic),
#   and both codes with mu = 0.5 on Kratos' mesh (GetFEM with slave = base, as Grout, and with
#   slave = ring, the one whose frictional curve converges in its steps),
# then getfem_compare.py: numbers, getfem_double_arch.png and getfem_double_arch_mu05.png. About
# 3.7 min CPU in all (Grout 11 + 35-90 + 9 s, GetFEM 11 + 50 + 61 + 11 + 13 + 13 s). Needs
# python3-getfem.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
work=$build/inputs/double_arch/full
py=/usr/bin/python3
mkdir -p "$work"
cd "$work"
$py "$here/arch_on_block.py" double_arch.exo --center 0.125 0.145 \
  --radii 0.085 0.09 0.095 --layer-names ring_inner ring_outer --block 0 0.25 0 \
  --n-around 60 --n-layer 2 2 --block-nx 50 --block-ny 7
$py "$here/arch_on_block.py" double_arch_fine.exo --center 0.125 0.145 \
  --radii 0.085 0.09 0.095 --layer-names ring_inner ring_outer --block 0 0.25 0 \
  --n-around 120 --n-layer 4 4 --block-nx 100 --block-ny 14
cp "$here/double_arch.yaml" "$here/double_arch_mu05.yaml" .
sed -e 's/double_arch\.exo/double_arch_fine.exo/' -e 's/double_arch\.e,/double_arch_fine.e,/' \
    -e 's/double_arch\.csv/double_arch_fine.csv/' double_arch.yaml > double_arch_fine.yaml
for input in double_arch double_arch_fine double_arch_mu05; do
  "$build/bin/grout" $input.yaml --output-dir np1 > "np1_$input.log"
done
g="$py $here/getfem_double_arch.py"
$g --mesh double_arch.exo --csv getfem_q1.csv > getfem_q1.log
$g --mesh double_arch_fine.exo --csv getfem_fine_q1.csv > getfem_fine_q1.log
$g --mesh double_arch.exo --order 2 --csv getfem_q2.csv > getfem_q2.log
$g --mesh double_arch.exo --moduli 1.5e8 1e11 1e9 --csv getfem_base_half.csv > getfem_base_half.log
$g --mesh double_arch.exo --mu 0.5 --csv getfem_mu05_q1.csv > getfem_mu05_q1.log
$g --mesh double_arch.exo --mu 0.5 --slave ring --csv getfem_mu05_q1_ring.csv > getfem_mu05_q1_ring.log
$g --mesh double_arch_fine.exo --d-max 0.001 --steps 1 --ring-check | grep "ring check"
$g --mesh double_arch_fine.exo --order 2 --d-max 0.001 --steps 1 --ring-check | grep "ring check"
PYTHONPATH=$root/tools MPLBACKEND=Agg $py "$here/getfem_compare.py" \
  --grout "double_arch:QUAD4, Kratos' mesh" "double_arch_fine:QUAD4, mesh 2x finer" \
  --getfem "getfem_q1.csv:QK(2,1), Kratos' mesh:double_arch" \
           "getfem_fine_q1.csv:QK(2,1), mesh 2x finer:double_arch_fine" \
           "getfem_q2.csv:QK(2,2), Kratos' mesh" \
           "getfem_base_half.csv:QK(2,1), base E halved (diagnostic)" \
  --plot getfem_double_arch.png
PYTHONPATH=$root/tools MPLBACKEND=Agg $py "$here/getfem_compare.py" --frictional \
  --grout "double_arch_mu05:QUAD4, Kratos' mesh, mu = 0.5" \
  --getfem "getfem_mu05_q1.csv:QK(2,1), Kratos' mesh, mu = 0.5:double_arch_mu05" \
           "getfem_mu05_q1_ring.csv:QK(2,1), Kratos' mesh, mu = 0.5, slave ring:double_arch_mu05" \
  --plot getfem_double_arch_mu05.png
