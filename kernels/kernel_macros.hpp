#pragma once
// Function qualifier and math of the pure-math kernels, so that they compile both in the
// normal build (Kokkos present) and as CUDA device code by nvcc without a CUDA-enabled Kokkos
// (the Debian Kokkos has the Serial backend only; unit_tests/cuda_compile compiles the kernels
// with nvcc this way).
//
//   default                   GROUT_INLINE_FUNCTION = KOKKOS_INLINE_FUNCTION (unchanged
//                             semantics: `inline` for Serial, `__host__ __device__ inline`
//                             with a CUDA-enabled Kokkos); includes <Kokkos_Core.hpp>.
//   GROUT_KERNELS_NO_KOKKOS   no Kokkos header; under nvcc (__CUDACC__)
//                             GROUT_INLINE_FUNCTION = __host__ __device__ inline, else inline.
//
// Headers using these macros must not need anything else from Kokkos: Views, launches and
// atomics stay in the headers that do the launches (surface_normals.hpp, weighted_gap.hpp,
// mortar_integrate.hpp, coarse_search.hpp). Math that Kokkos would provide goes through
// grout::kmath below.

#if defined(GROUT_KERNELS_NO_KOKKOS)
#include <cmath>
#if defined(__CUDACC__)
#define GROUT_INLINE_FUNCTION __host__ __device__ inline
#else
#define GROUT_INLINE_FUNCTION inline
#endif
#else
#include <Kokkos_Core.hpp>
#define GROUT_INLINE_FUNCTION KOKKOS_INLINE_FUNCTION
#endif

namespace grout {
namespace kmath {

/// Square root of a double on host and device: Kokkos::Experimental::sqrt with Kokkos,
/// otherwise std::sqrt (which nvcc provides in device code).
GROUT_INLINE_FUNCTION double sqrt(double x) {
#if defined(GROUT_KERNELS_NO_KOKKOS)
  return std::sqrt(x);
#else
  return Kokkos::Experimental::sqrt(x);
#endif
}

}  // namespace kmath
}  // namespace grout
