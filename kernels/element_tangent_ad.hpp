#pragma once
// An element's force vector and its tangent K = d f / d u by Sacado forward AD, with a
// derivative array sized to the element's dofs (6, 8, 12 or 24: tri3 and quad4 in 2D, tet4
// and hex8 in 3D), for the element kernels templated on the scalar (total_lagrangian.hpp,
// energy_momentum.hpp). K is exact to round-off: the derivative of the same function.

#include <Kokkos_Core.hpp>
#include <Sacado.hpp>
#include <type_traits>

#include "kernels/shape_functions.hpp"

namespace grout {

namespace detail {

/// evaluate(u_ad, f_ad) on SFad<double, N> scalars seeded with the N dofs of u.
template <int N, class Evaluate>
KOKKOS_INLINE_FUNCTION ElementStatus force_and_tangent_fad(const double* u,
                                                           const Evaluate& evaluate, double* f,
                                                           double* K) {
  using Fad = Sacado::Fad::SFad<double, N>;
  Fad u_ad[N], f_ad[N];
  for (int k = 0; k < N; ++k) u_ad[k] = Fad(N, k, u[k]);
  const ElementStatus status = evaluate(static_cast<const Fad*>(u_ad), static_cast<Fad*>(f_ad));
  if (status != ElementStatus::ok) return status;
  for (int r = 0; r < N; ++r) {
    f[r] = f_ad[r].val();
    for (int k = 0; k < N; ++k) K[r * N + k] = f_ad[r].dx(k);
  }
  return ElementStatus::ok;
}

}  // namespace detail

/// \brief f = evaluate(u) and K = d f / d u (row-major [n * n]).
/// \pre evaluate(const Fad* u, Fad* f) -> ElementStatus, generic in the scalar Fad, writes the
/// n entries of f; u: [n]; f: [n]; K: room for n * n.
/// \return unsupported unless n is 6, 8, 12 or 24; otherwise what evaluate returns.
template <class Evaluate>
KOKKOS_INLINE_FUNCTION ElementStatus force_and_tangent_by_ad(int n, const double* u,
                                                             const Evaluate& evaluate, double* f,
                                                             double* K) {
  switch (n) {
    case 6:
      return detail::force_and_tangent_fad<6>(u, evaluate, f, K);
    case 8:
      return detail::force_and_tangent_fad<8>(u, evaluate, f, K);
    case 12:
      return detail::force_and_tangent_fad<12>(u, evaluate, f, K);
    case 24:
      return detail::force_and_tangent_fad<24>(u, evaluate, f, K);
    default:
      return ElementStatus::unsupported;
  }
}

}  // namespace grout
