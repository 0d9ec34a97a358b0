#!/usr/bin/env bash
# The press fit solved by GetFEM 5.4 and by Grout on the same meshes, against the published
# figure (docs/verification.md, "Press fit 2D, μ = 0.1", "Independent check with GetFEM").
# Usage: inputs/press_fit/run_getfem.sh [BUILD_DIR]   (default build/). Work folder:
# BUILD_DIR/inputs/press_fit/getfem. Runs, 150 steps, 1 rank:
#   Grout  press_fit.yaml on Kratos' mesh and on the structured meshes of levels 2 and 4
#          (press_fit_mesh.py),
#   GetFEM on Kratos' mesh with the augmentation r = 1, 3, 10 E_block/h, and on levels 2 and 4
#          (r = 1 and 3 E_block/h),
# then getfem_compare.py: the numbers, getfem_press_fit.png (Kratos' mesh) and
# getfem_press_fit_l4.png (level 4). About 4 min CPU. Needs python3-getfem.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
work=$build/inputs/press_fit/getfem
py=/usr/bin/python3
mkdir -p "$work"
cd "$work"
$py "$root/tools/mdpa_to_exodus.py" "$here/press_fit.mdpa" press_fit.exo > /dev/null
cp "$here/press_fit.yaml" .
for k in 2 4; do
  $py "$here/press_fit_mesh.py" press_fit_l$k.exo --level $k
  sed -e "s/press_fit\.exo/press_fit_l$k.exo/" -e "s/press_fit\.e,/press_fit_l$k.e,/" \
      -e "s/press_fit\.csv/press_fit_l$k.csv/" press_fit.yaml > press_fit_l$k.yaml
done
for input in press_fit press_fit_l2 press_fit_l4; do
  "$build/bin/grout" $input.yaml --output-dir np1 > "np1_$input.log"
done
g="$py $here/getfem_press_fit.py"
for f in 1 3 10; do
  $g --mesh press_fit.exo --r-factor $f --csv getfem_r$f.csv > getfem_r$f.log
done
for k in 2 4; do
  for f in 1 3; do
    $g --mesh press_fit_l$k.exo --r-factor $f --csv getfem_l${k}_r$f.csv > getfem_l${k}_r$f.log
  done
done
tail -qn1 getfem_*.log
c="env PYTHONPATH=$root/tools MPLBACKEND=Agg $py $here/getfem_compare.py"
$c --grout "np1/press_fit.csv:Grout, Kratos' mesh" \
   --getfem "getfem_r1.csv:GetFEM, Kratos' mesh, r = E/h" \
            "getfem_r3.csv:GetFEM, Kratos' mesh, r = 3 E/h" \
            "getfem_r10.csv:GetFEM, Kratos' mesh, r = 10 E/h" \
   --plot getfem_press_fit.png
for k in 2 4; do
  $c --grout "np1/press_fit_l$k.csv:Grout, level $k" \
     --getfem "getfem_l${k}_r1.csv:GetFEM, level $k, r = E/h" \
              "getfem_l${k}_r3.csv:GetFEM, level $k, r = 3 E/h" \
     --plot getfem_press_fit_l$k.png
done
