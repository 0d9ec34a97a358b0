// The kernel probes compiled by nvcc, without Kokkos (-DGROUT_KERNELS_NO_KOKKOS):
//   - device code: one __global__ wrapper per probe, so every kernel the probes call is
//     compiled for the GPU (run_nvcc_probes.sh checks that each wrapper is in the PTX);
//   - host code: main() runs the same __host__ __device__ probes on the host (no GPU needed)
//     and prints their results for comparison with the g++/Kokkos build.
// Command and flags: run_nvcc_probes.sh.
#if !defined(__CUDACC__) || !defined(GROUT_KERNELS_NO_KOKKOS)
#error "kernel_probes.cu is compiled by nvcc with -DGROUT_KERNELS_NO_KOKKOS"
#endif

#include "probe_results.hpp"

/// probe_<name>_kernel(values, count): one thread evaluates the probe into values[0..count).
#define GROUT_PROBE_KERNEL(name)                                      \
  __global__ void probe_##name##_kernel(double* values, int* count) { \
    grout::probes::ProbeOutput out{values};                           \
    grout::probes::probe_##name(out);                                 \
    *count = out.n;                                                   \
  }
GROUT_KERNEL_PROBES(GROUT_PROBE_KERNEL)
#undef GROUT_PROBE_KERNEL

int main() {
  grout::probes::write_probe_results(stdout, grout::probes::run_probes());
  return 0;
}
