#pragma once
// Dual (biorthogonal) Lagrange-multiplier basis on a slave element (Wohlmuth, SINUM 38 (2000);
// Popp et al. 2010, eqs. 24-26; docs/design.md §2):
//
//   Φ_j = Σ_k a_jk N_k,   A_e = D_e M_e⁻¹,   D_e = diag(∫_e N_j dA),   M_e = [∫_e N_j N_k dA],
//
// so that ∫_e Φ_j N_k dA = δ_jk ∫_e N_j dA. LINE2 has the closed form Φ₁ = 2N₁ − N₂,
// Φ₂ = 2N₂ − N₁ (its Jacobian is constant). This header also holds the generic small dense
// inverse (on small_dense_lu.hpp) and A_e = D_e M_e⁻¹ that the TRI3/QUAD4 code
// (dual_basis_3d.hpp) reuses.

#include <cmath>

#include "kernels/gauss_line.hpp"
#include "kernels/kernel_macros.hpp"
#include "kernels/mortar_types.hpp"
#include "kernels/small_dense_lu.hpp"

namespace grout {

/// \brief LINE2 shape functions N₁ = (1 − ξ)/2, N₂ = (1 + ξ)/2 on ξ ∈ [−1, 1].
template <class Scalar>
GROUT_INLINE_FUNCTION void line2_shape(const Scalar& xi, Scalar N[2]) {
  N[0] = 0.5 * (1.0 - xi);
  N[1] = 0.5 * (1.0 + xi);
}

/// \brief LINE2 dual shape functions, closed form Φ₁ = 2N₁ − N₂ = (1 − 3ξ)/2,
/// Φ₂ = 2N₂ − N₁ = (1 + 3ξ)/2 (Wohlmuth 2000; docs/design.md §2).
template <class Scalar>
GROUT_INLINE_FUNCTION void line2_dual_shape(const Scalar& xi, Scalar Phi[2]) {
  Phi[0] = 0.5 * (1.0 - 3.0 * xi);
  Phi[1] = 0.5 * (1.0 + 3.0 * xi);
}

/// \brief Ainv = A⁻¹ for a small dense N×N matrix by the small dense LU with partial pivoting
/// (kernels/small_dense_lu.hpp; pivots chosen on the value part, so it is valid for Sacado
/// scalars).
/// \return degenerate if a pivot is below 1e-14 · max|A_ij| (singular to working precision).
template <class Scalar, int N>
GROUT_INLINE_FUNCTION MortarStatus invert_small_matrix(const Scalar A[N][N], Scalar Ainv[N][N]) {
  static_assert(N >= 1 && N <= 8, "grout::invert_small_matrix: N must be in [1, 8]");
  using std::abs;
  Scalar a[N][N];
  Scalar scale = 0.0;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      a[i][j] = A[i][j];
      if (abs(A[i][j]) > scale) scale = abs(A[i][j]);
    }
  if (!(scale > 0.0)) return MortarStatus::degenerate;
  const Scalar singular_at = 1e-14 * scale;
  int pivot[N];
  return small_lu_invert(N, &a[0][0], N, pivot, &Ainv[0][0], N, singular_at)
             ? MortarStatus::ok
             : MortarStatus::degenerate;
}

/// \brief Dual-basis coefficients A_e = D_e M_e⁻¹ (Popp et al. 2010, eq. 26) from
/// De[j] = ∫_e N_j dA and Me[j][k] = ∫_e N_j N_k dA (any quadrature exact for N_j N_k det J).
template <class Scalar, int N>
GROUT_INLINE_FUNCTION MortarStatus dual_basis_coefficients(const Scalar De[N],
                                                           const Scalar Me[N][N], Scalar A[N][N]) {
  Scalar Minv[N][N];
  const MortarStatus s = invert_small_matrix<Scalar, N>(Me, Minv);
  if (s != MortarStatus::ok) return s;
  for (int j = 0; j < N; ++j)
    for (int k = 0; k < N; ++k) A[j][k] = De[j] * Minv[j][k];
  return MortarStatus::ok;
}

/// \brief Φ_j = Σ_k a_jk N_k at one point, from the coefficients and the standard shape values.
template <class Scalar, int N>
GROUT_INLINE_FUNCTION void dual_shape_from_coefficients(const Scalar A[N][N], const Scalar Nv[N],
                                                        Scalar Phi[N]) {
  for (int j = 0; j < N; ++j) {
    Phi[j] = A[j][0] * Nv[0];
    for (int k = 1; k < N; ++k) Phi[j] += A[j][k] * Nv[k];
  }
}

/// \brief A_e = D_e M_e⁻¹ for a LINE2 slave element x (2D coordinates), D_e and M_e integrated
/// with the 2-point Gauss rule (exact: N_j N_k is quadratic, det J = L/2 constant). Equals
/// [[2, −1], [−1, 2]] for any non-degenerate element (the closed form of line2_dual_shape).
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus dual_basis_coefficients_line2(const Scalar x[2][2],
                                                                 Scalar A[2][2]) {
  using std::sqrt;
  const Scalar dx = x[1][0] - x[0][0], dy = x[1][1] - x[0][1];
  const Scalar ll = dx * dx + dy * dy;
  if (!(ll > 0.0)) return MortarStatus::degenerate;
  const Scalar det_j = 0.5 * sqrt(ll);
  Scalar De[2] = {0.0, 0.0};
  Scalar Me[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
  for (int g = 0; g < 2; ++g) {
    double xi, w;
    gauss_line_point(2, g, xi, w);
    Scalar Nv[2];
    line2_shape(Scalar(xi), Nv);
    for (int j = 0; j < 2; ++j) {
      De[j] += w * det_j * Nv[j];
      for (int k = 0; k < 2; ++k) Me[j][k] += w * det_j * Nv[j] * Nv[k];
    }
  }
  return dual_basis_coefficients<Scalar, 2>(De, Me, A);
}

}  // namespace grout
