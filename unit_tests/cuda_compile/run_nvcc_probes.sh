#!/usr/bin/env bash
# The nvcc half of the kernel probes (see kernel_probes.hpp). Two modes, two ctest entries:
#
#   run_nvcc_probes.sh device    NVCC SOURCE_DIR WORK_DIR HOST_EXE TRILINOS_INCLUDE TEUCHOS_LIB
#       compiles kernel_probes.cu with nvcc (device code for sm_80 + host code, no Kokkos; Sacado
#       from TRILINOS_INCLUDE, its one Teuchos static from TEUCHOS_LIB) into
#       WORK_DIR/kernel_probes_nvcc and checks that the PTX has a __global__ entry for every
#       probe HOST_EXE --list names. Fails on any nvcc error or warning.
#   run_nvcc_probes.sh agreement NVCC SOURCE_DIR WORK_DIR HOST_EXE
#       runs WORK_DIR/kernel_probes_nvcc (the probes on the host, as compiled by nvcc) and
#       compares its results with the host build's (HOST_EXE --compare).
#
# Exits 77 (ctest: skipped) when NVCC is empty or not executable: no GPU is needed, but nvcc is.
set -euo pipefail
mode=$1
nvcc=$2
source_dir=$3
work=$4
host_exe=$5
trilinos_include=${6:-/usr/include/trilinos}
teuchos_lib=${7:-}

if [[ -z "$nvcc" || ! -x "$nvcc" ]]; then
  echo "SKIP: nvcc not found (GROUT_NVCC='$nvcc'); configure with -DGROUT_NVCC=/path/to/nvcc"
  exit 77
fi
exe=$work/kernel_probes_nvcc

case $mode in
  device)
    "$nvcc" --version | tail -n 2
    rm -rf "$work/keep" "$exe"
    mkdir -p "$work/keep"
    flags=(-x cu -std=c++17 --expt-relaxed-constexpr -arch=sm_80 -O2 -Werror all-warnings
      -Xptxas -v -DGROUT_KERNELS_NO_KOKKOS -I"$source_dir" -I"$source_dir/unit_tests/cuda_compile"
      -isystem "$trilinos_include" --keep --keep-dir "$work/keep")
    echo "$nvcc ${flags[*]} $source_dir/unit_tests/cuda_compile/kernel_probes.cu -o $exe"
    start=$(date +%s%N)
    "$nvcc" "${flags[@]}" "$source_dir/unit_tests/cuda_compile/kernel_probes.cu" -o "$exe" \
      ${teuchos_lib:+-Xlinker "$teuchos_lib"}
    end=$(date +%s%N)
    ms=$(((end - start) / 1000000))
    printf "nvcc took %d.%03d s\n" $((ms / 1000)) $((ms % 1000))
    ptx=$(ls "$work"/keep/*.ptx)
    missing=0
    for name in $("$host_exe" --list); do
      symbol=probe_${name}_kernel
      # Itanium mangling of `void probe_<name>_kernel(double*, int*)`.
      if grep -q "^\.visible \.entry _Z${#symbol}${symbol}PdPi(" "$ptx"; then
        echo "device entry: $symbol"
      else
        echo "MISSING device entry for probe $name ($symbol) in $ptx"
        missing=1
      fi
    done
    exit $missing
    ;;
  agreement)
    if [[ ! -x "$exe" ]]; then
      echo "$exe is missing: run the kernels_nvcc_device_compile test first"
      exit 1
    fi
    "$exe" > "$work/nvcc_results.txt"
    "$host_exe" --compare "$work/nvcc_results.txt"
    ;;
  *)
    echo "unknown mode $mode (device | agreement)"
    exit 2
    ;;
esac
