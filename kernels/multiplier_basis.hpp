#pragma once
// The Lagrange multiplier basis on a slave face, as coefficients of the slave shape functions:
//
//   Φ_j = Σ_k A_jk N¹_k
//   dual      A_e = D_e M_e⁻¹, D_e = diag(∫_e N_j dA), M_e = [∫_e N_j N_k dA]   (biorthogonal:
//             ∫_e Φ_j N_k dA = δ_jk ∫_e N_j dA; Wohlmuth 2000; Popp et al. 2010, eq. 26);
//             LINE2 closed form A = [[2, −1], [−1, 2]] (dual_basis.hpp)
//   standard  A = I, Φ_j = N¹_j (the classical mortar multiplier; Puso & Laursen 2004): then
//             D_jk = ∫ N¹_j N¹_k dA is a full (consistent-mass-like) slave × slave matrix.
//
// Either way Σ_j Φ_j = 1, so Σ_k D_jk = Σ_l M_jl on every pair (Σ_k N¹_k = Σ_l N²_l = 1) and
// Σ_jk D_jk is the integrated area. A free function on plain data: the pair kernels take A.

#include "kernels/dual_basis.hpp"
#include "kernels/dual_basis_3d.hpp"
#include "kernels/kernel_macros.hpp"
#include "kernels/mortar_types.hpp"

namespace grout {

/// \brief Coefficients A (Φ_j = Σ_k A_jk N¹_k) of the multiplier basis `basis` on a slave face
/// of n nodes (dim 2: LINE2, x[k][0..1]; dim 3: TRI3/QUAD4). Unused entries are zero.
/// \return degenerate for a zero-length/area face or a wrong node count, else ok.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus multiplier_basis_coefficients(
    MultiplierBasis basis, int dim, int n, const Scalar x[max_face_nodes][3],
    Scalar A[max_face_nodes][max_face_nodes]) {
  for (int j = 0; j < max_face_nodes; ++j)
    for (int k = 0; k < max_face_nodes; ++k) A[j][k] = 0.0;
  if (dim == 2) {
    if (n != 2) return MortarStatus::degenerate;
    const Scalar dx = x[1][0] - x[0][0], dy = x[1][1] - x[0][1];
    if (!(dx * dx + dy * dy > 0.0)) return MortarStatus::degenerate;
    const bool dual = basis == MultiplierBasis::dual;
    A[0][0] = A[1][1] = dual ? 2.0 : 1.0;  // line2_dual_shape: Φ₁ = 2N₁ − N₂, Φ₂ = 2N₂ − N₁
    A[0][1] = A[1][0] = dual ? -1.0 : 0.0;
    return MortarStatus::ok;
  }
  if (dim != 3 || (n != 3 && n != 4)) return MortarStatus::degenerate;
  if (basis == MultiplierBasis::dual) return dual_basis_coefficients_3d(n, x, A);
  for (int j = 0; j < n; ++j) A[j][j] = 1.0;
  Scalar xi[2];
  face_reference_centre(n, xi);
  return face_area_element(n, x, xi) > 0.0 ? MortarStatus::ok : MortarStatus::degenerate;
}

/// \brief Φ_j(ξ) = Σ_k A_jk N_k for j < n, from the shape values N (n nodes).
template <class Scalar>
GROUT_INLINE_FUNCTION void multiplier_shape_functions(
    int n, const Scalar A[max_face_nodes][max_face_nodes], const Scalar N[max_face_nodes],
    Scalar Phi[max_face_nodes]) {
  for (int j = 0; j < max_face_nodes; ++j) {
    Phi[j] = 0.0;
    for (int k = 0; k < n; ++k) Phi[j] += A[j][k] * N[k];
  }
}

}  // namespace grout
