#!/usr/bin/env bash
# ctest's embed_mortar_example: install Grout's build tree to a scratch prefix, build this
# example against it, run it on 1 and 2 ranks.
# Usage: run_test.sh <Grout build dir> <mpiexec command ...>
set -euo pipefail
build=$1
shift
source_dir=$(cd "$(dirname "$0")" && pwd)
work=$build/embed-mortar-test
rm -rf "$work"
cmake --install "$build" --prefix "$work/install" > /dev/null
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$source_dir" -B "$work/build" -G Ninja -DCMAKE_PREFIX_PATH="$work/install" \
  "${launcher[@]}" > /dev/null
cmake --build "$work/build" > /dev/null
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
"$@" -np 1 "$work/build/embed_mortar"
"$@" -np 2 "$work/build/embed_mortar"
