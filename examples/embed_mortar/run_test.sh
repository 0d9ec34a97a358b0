#!/usr/bin/env bash
# ctest's embed_mortar_example: install Grout's build tree to a scratch prefix, build this
# example against it, run it on 1 and 2 ranks.
# Usage: run_test.sh <Grout build dir> <mpiexec command ...>
set -euo pipefail
build=$1
shift
source_dir=$(cd "$(dirname "$0")" && pwd)
work=$build/embed-mortar-test
"$source_dir/../../tools/build_against_install" "$build" "$source_dir" "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
"$@" -np 1 "$work/build/embed_mortar"
"$@" -np 2 "$work/build/embed_mortar"
