#pragma once
// Dual (biorthogonal) Lagrange-multiplier basis on a TRI3 / QUAD4 slave face.
//
//   Φ_j = Σ_k a_jk N_k,   A_e = D_e M_e⁻¹,   D_e = diag(∫_e N_j dA),   M_e = [∫_e N_j N_k dA]
//
// so that ∫_e Φ_j N_k dA = δ_jk ∫_e N_j dA (Wohlmuth 2000; Popp et al. 2010;
// docs/design.md §2). Σ_j Φ_j = 1 follows (1ᵀD_e = 1ᵀM_e). On TRI3 the area element is constant
// and A_e = 4I − 11ᵀ for every (distorted) triangle: Φ_i = 3N_i − N_j − N_k = 4N_i − 1
// (Popp et al. 2010: Φ_1 = 3 − 4ξ − 4η, Φ_2 = 4ξ − 1, Φ_3 = 4η − 1). Note: "3N_i − 1"
// is not biorthogonal: ∫(3N_1 − 1)N_2 dA = −A/12. On QUAD4, D_e and
// M_e are integrated on the actual face (distorted, possibly warped) with a 4×4 Gauss rule:
// exact for flat faces (N_j N_k j(ξ) is of degree ≤ 3 per direction), and for warped faces
// (j = |g_1 × g_2| is then not polynomial) accurate to far below the mortar tolerances.

#include "kernels/dual_basis.hpp"
#include "kernels/face_geometry_3d.hpp"
#include "kernels/kernel_macros.hpp"
#include "kernels/mortar_types.hpp"

namespace grout {

/// \brief Element mass data of a TRI3/QUAD4 face: d[j] = ∫_e N_j dA, m[j][k] = ∫_e N_j N_k dA
/// (4×4 Gauss–Legendre on QUAD4, exact on flat faces; closed form on TRI3:
/// d_j = A/3, m_jk = A(1 + δ_jk)/12).
template <class Scalar>
GROUT_INLINE_FUNCTION void face_mass_matrix(int n, const Scalar x[max_face_nodes][3],
                                            Scalar d[max_face_nodes],
                                            Scalar m[max_face_nodes][max_face_nodes]) {
  for (int j = 0; j < max_face_nodes; ++j) {
    d[j] = 0.0;
    for (int k = 0; k < max_face_nodes; ++k) m[j][k] = 0.0;
  }
  if (n == 3) {
    Scalar xi[2];
    face_reference_centre(n, xi);
    const Scalar area = 0.5 * face_area_element(n, x, xi);
    for (int j = 0; j < 3; ++j) {
      d[j] = area / 3.0;
      for (int k = 0; k < 3; ++k) m[j][k] = area * (j == k ? 2.0 : 1.0) / 12.0;
    }
    return;
  }
  // 4-point Gauss–Legendre on [-1, 1]
  static constexpr double gp[4] = {-0.86113631159405257522, -0.33998104358485626480,
                                   0.33998104358485626480, 0.86113631159405257522};
  static constexpr double gw[4] = {0.34785484513745385737, 0.65214515486254614263,
                                   0.65214515486254614263, 0.34785484513745385737};
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      const Scalar xi[2] = {Scalar(gp[a]), Scalar(gp[b])};
      Scalar N[max_face_nodes];
      face_shape_functions(n, xi, N);
      const Scalar w = gw[a] * gw[b] * face_area_element(n, x, xi);
      for (int j = 0; j < 4; ++j) {
        d[j] += w * N[j];
        for (int k = 0; k < 4; ++k) m[j][k] += w * N[j] * N[k];
      }
    }
}

/// \brief Coefficients A[j][k] = a_jk of the dual basis Φ_j = Σ_k a_jk N_k on a TRI3 (n = 3)
/// or QUAD4 (n = 4) face: A_e = D_e M_e⁻¹ (Popp et al. 2010), on QUAD4 by the small dense LU
/// with partial pivoting (dual_basis_coefficients, dual_basis.hpp; kernels/small_dense_lu.hpp).
/// \return degenerate for a zero-area face (singular M_e), else ok.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus dual_basis_coefficients_3d(
    int n, const Scalar x[max_face_nodes][3], Scalar A[max_face_nodes][max_face_nodes]) {
  for (int j = 0; j < max_face_nodes; ++j)
    for (int k = 0; k < max_face_nodes; ++k) A[j][k] = 0.0;
  if (n == 3) {  // closed form Φ_i = 4 N_i − 1 = Σ_k (4 δ_ik − 1) N_k
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) A[j][k] = j == k ? 3.0 : -1.0;
    Scalar xi[2];
    face_reference_centre(n, xi);
    return face_area_element(n, x, xi) > 0.0 ? MortarStatus::ok : MortarStatus::degenerate;
  }
  static_assert(max_face_nodes == 4, "grout::dual_basis_coefficients_3d: QUAD4 fills M_e");
  Scalar d[max_face_nodes], m[max_face_nodes][max_face_nodes];
  face_mass_matrix(n, x, d, m);  // n = 4: M_e is the full 4×4 array
  return dual_basis_coefficients<Scalar, max_face_nodes>(d, m, A);
}

/// \brief Dual shape functions Φ_j(ξ) = Σ_k A[j][k] N_k(ξ).
template <class Scalar>
GROUT_INLINE_FUNCTION void dual_shape_functions_3d(int n,
                                                   const Scalar A[max_face_nodes][max_face_nodes],
                                                   const Scalar xi[2], Scalar Phi[max_face_nodes]) {
  Scalar N[max_face_nodes];
  face_shape_functions(n, xi, N);
  for (int j = 0; j < max_face_nodes; ++j) {
    Phi[j] = 0.0;
    for (int k = 0; k < n; ++k) Phi[j] += A[j][k] * N[k];
  }
}

}  // namespace grout
