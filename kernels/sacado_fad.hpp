#pragma once
// Sacado's forward-AD scalars (Sacado::Fad::SFad) for the kernels, on the host and as CUDA
// device code.
//
//   default                   <Sacado.hpp>: SACADO_INLINE_FUNCTION = KOKKOS_INLINE_FUNCTION.
//   GROUT_KERNELS_NO_KOKKOS   only the SFad headers; under nvcc, Sacado's function qualifiers
//                             are set to __host__ __device__ before Sacado defines them (it
//                             defines each only where it is not defined yet), since the Debian
//                             Kokkos behind Sacado's own choice has no CUDA backend
//                             (kernel_macros.hpp; unit_tests/cuda_compile).
#if defined(GROUT_KERNELS_NO_KOKKOS)
#define SACADO_DISABLE_FAD_VIEW_SPEC  // no Kokkos::View of Fad here (it would pull in Teuchos/MPI)
#if defined(__CUDACC__)
#define SACADO_FUNCTION __host__ __device__
#define SACADO_INLINE_FUNCTION __host__ __device__ inline
#define SACADO_FORCEINLINE_FUNCTION __host__ __device__ inline
#endif
#include <Sacado_ConfigDefs.h>
#include <Sacado_Fad_Exp_MathFunctions.hpp>
#include <Sacado_Fad_SFad.hpp>
#else
#include <Sacado.hpp>
#endif
