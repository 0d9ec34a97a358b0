#!/usr/bin/env bash
# Install the build tree to a scratch prefix, build the consumer against it, run it.
set -euo pipefail
build=$1
source_dir=$(cd "$(dirname "$0")" && pwd)
"$source_dir/../../tools/build_against_install" "$build" "$source_dir" "$build/consumer-test"
"$build/consumer-test/build/consumer"
"$build/consumer-test/build/consumer_kernels"
