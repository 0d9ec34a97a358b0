#!/usr/bin/env bash
# ctest's embed_mortar_example: install Grout's build tree to a scratch prefix, build this
# example against it (no configure warning: tools/build_against_install), check what the host
# executable links, run it on 1 and 2 ranks.
# Usage: run_test.sh <Grout build dir> <mpiexec command ...>
set -euo pipefail
build=$1
shift
source_dir=$(cd "$(dirname "$0")" && pwd)
work=$build/embed-mortar-test
"$source_dir/../../tools/build_against_install" "$build" "$source_dir" "$work"
# Grout::mortar needs Kokkos, Teuchos and MPI only: none of the other Trilinos packages
# (nor Exodus, MUMPS, muParser) may be among the host's shared libraries.
needed=$(readelf -d "$work/build/embed_mortar" | sed -n 's/.*Shared library: \[\(.*\)\]/\1/p')
heavy=$(echo "$needed" | grep -E 'trilinos_' | grep -vE \
  'trilinos_(kokkoscore|kokkoscontainers|kokkosalgorithms|teuchos(core|parser|parameterlist|comm))\.' || true)
heavy+=$(echo "$needed" | grep -E 'exoII|netcdf|mumps|muparser|hdf5' || true)
if [ -n "$heavy" ]; then
  echo "embed_mortar links libraries Grout::mortar should not need:" $heavy >&2
  exit 1
fi
echo "embed_mortar's Trilinos libraries:" $(echo "$needed" | grep trilinos_)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
"$@" -np 1 "$work/build/embed_mortar"
"$@" -np 2 "$work/build/embed_mortar"
