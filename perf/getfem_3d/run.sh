#!/bin/bash
# Grout vs GetFEM 5.4.2 on Grout's 3D Hertz case (inputs/gmsh_hertz: two TET4 hemispheres,
# quarter model), same Exodus meshes, sizes in increasing order; per size and repetition:
# Grout 1 rank, GetFEM, Grout 2 ranks (each under /usr/bin/time -v), then summarize.py.
# Usage (from the project root, or GROUT_ROOT=<checkout>):
#   bash perf/getfem_3d/run.sh [WORKDIR]      (default build/getfem_3d)
# Environment: SIZES (contact sizes, default "0.03 0.02 0.015 0.0115" = 1.3k, 3.0k, 5.7k,
#   11.0k nodes), REPS (default 1), GF_ARGS (getfem_hertz_3d.py options), MAX_SECONDS (default
#   300: no larger size is started once a run of a size took longer), GROUT_INPUT (Grout's
#   input file, default inputs/gmsh_hertz/hemispheres.yaml; its mesh must be hemispheres.exo).
# Needs: apt-get install -y python3-getfem python3-netcdf4 python3-gmsh python3-numpy time
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
WORK=${1:-build/getfem_3d}
ROOT=$(cd "${GROUT_ROOT:-.}" && pwd)   # the project checkout with build/bin (default: cwd)
export GROUT_ROOT="$ROOT"
BIN=$ROOT/build/bin
CASE=$ROOT/inputs/gmsh_hertz
PY=/usr/bin/python3            # Debian python (python3-getfem, python3-netcdf4, python3-gmsh)
REPS=${REPS:-1}
SIZES=${SIZES:-"0.03 0.02 0.015 0.0115"}
MAX_SECONDS=${MAX_SECONDS:-300}
GROUT_INPUT=$(realpath "${GROUT_INPUT:-$CASE/hemispheres.yaml}")
# GetFEM settings: large sliding raytracing brick, version 1 ("more symmetric"), from u = 0
# (version 0 stalls from u = 0, see README.md), Newton max_res 1e-10 (Grout's default
# relative_tolerance), 25 iterations, MUMPS; r = E/h, release distance 0.25 (script defaults).
GF_ARGS=${GF_ARGS:-"--version 1 --tol 1e-10 --max-iter 25 --lsolver mumps"}
# single-threaded BLAS/OpenMP in both codes (GetFEM's MUMPS uses OpenBLAS, so does Grout's)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
rm -rf "$WORK"; mkdir -p "$WORK"
{ echo "date: $(date -u)"; echo "uptime before: $(uptime)"; echo "nproc --all: $(nproc --all)"
  echo "grout: $(ls -l --time-style=+%FT%T%z "$BIN/grout" | awk '{print $6, $7}'), checkout HEAD now: $(git -C "$ROOT" log -1 --format='%h %cd' 2>/dev/null || echo '?')"
  echo "GROUT_INPUT: $GROUT_INPUT"; echo "GF_ARGS: $GF_ARGS"; } > "$WORK/env.txt"
$PY -c "import getfem, numpy, netCDF4, gmsh; print('numpy', numpy.__version__, 'netCDF4', netCDF4.__version__, 'gmsh', gmsh.__version__)" >> "$WORK/env.txt"
dpkg -l python3-getfem libgetfem5 | tail -2 >> "$WORK/env.txt"
secs() { awk '/Elapsed/ {n = split($NF, a, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + a[i]; print s}' "$1" 2>/dev/null || echo 0; }
for H in $SIZES; do
  S="$WORK/h$H"; mkdir -p "$S"
  $PY "$CASE/hemispheres.py" "$S/hemispheres.exo" --contact-size "$H" | tee "$S/mesh.txt"
  longest=0
  for r in $(seq 1 "$REPS"); do
    D="$S/rep$r"
    for k in grout_np1 getfem grout_np2; do
      mkdir -p "$D/$k"; cp "$S/hemispheres.exo" "$D/$k/"; cp "$GROUT_INPUT" "$D/$k/hemispheres.yaml"
    done
    echo "h$H rep$r: $(uptime)" >> "$WORK/env.txt"
    (cd "$D/grout_np1" && /usr/bin/time -v -o time.txt $BIN/grout hemispheres.yaml --timers > out.txt 2>&1) || true
    (cd "$D/getfem" && /usr/bin/time -v -o time.txt $PY "$HERE/getfem_hertz_3d.py" hemispheres.exo --out gf $GF_ARGS > out.txt 2> err.txt) || true
    (cd "$D/grout_np2" && /usr/bin/time -v -o time.txt mpirun --oversubscribe -np 2 $BIN/grout hemispheres.yaml --timers > out.txt 2>&1) || true
    t1=$(secs "$D/grout_np1/time.txt"); tg=$(secs "$D/getfem/time.txt"); t2=$(secs "$D/grout_np2/time.txt")
    echo "h$H rep$r: grout1 ${t1}s  getfem ${tg}s  grout2 ${t2}s"
    longest=$(printf '%s\n' "$longest" "$t1" "$tg" "$t2" | sort -g | tail -1)
  done
  if awk -v t="$longest" -v m="$MAX_SECONDS" 'BEGIN {exit !(t > m)}'; then
    echo "h$H: a run took ${longest}s > ${MAX_SECONDS}s: no larger size" | tee -a "$WORK/env.txt"
    break
  fi
done
echo "uptime after: $(uptime)" >> "$WORK/env.txt"
cat "$WORK/env.txt"
$PY "$HERE/summarize.py" "$WORK" | tee "$WORK/summary.md"
