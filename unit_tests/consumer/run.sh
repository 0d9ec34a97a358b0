#!/usr/bin/env bash
# Install the build tree to a scratch prefix, build the consumer against it, run it.
set -euo pipefail
build=$1
source_dir=$(cd "$(dirname "$0")" && pwd)
prefix=$build/consumer-test/install
rm -rf "$build/consumer-test"
cmake --install "$build" --prefix "$prefix" > /dev/null
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$source_dir" -B "$build/consumer-test/build" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" \
  "${launcher[@]}" > /dev/null
cmake --build "$build/consumer-test/build" > /dev/null
"$build/consumer-test/build/consumer"
"$build/consumer-test/build/consumer_kernels"
