#pragma once
// The integral of a face's shape function N_a over the face, w_a = ∫_e N_a dA: the share of the
// face's area that slave node a would carry with a fully covered face. With dual multipliers
// Σ_faces ∫_cov Φ_j dA = D_jj equals Σ_faces w_a exactly when the node's faces are fully
// covered (Φ_j is biorthogonal to the N_k on each face and Σ_k N_k = 1; Popp, Gitterle, Gee &
// Wall 2010, eq. 30), so D_jj / w_j measures the coverage (docs/embedding.md, "Partly covered
// rows"; the driver's partly covered node rule, contact_mortar.hpp).
//
//   LINE2: L/2;   TRI3: A/3;   QUAD4: Σ_g w_g N_a(ξ_g) |x_ξ × x_η| on a 3 × 3 Gauss rule
//   (exact for parallelograms).

#include <cmath>

#include "kernels/face_normal.hpp"
#include "kernels/kernel_macros.hpp"

namespace grout {

namespace detail {
GROUT_INLINE_FUNCTION double vector_length(const double v[3]) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}
}  // namespace detail

/// \brief w_a = ∫_e N_a dA over one face (dim 2: LINE2; 3: TRI3 or QUAD4), x: its nodes.
/// `axisymmetric` (LINE2, x = r): dA = 2π r ds, w_a = 2π L (2 r_a + r_b) / 6, the weight of
/// the r-weighted dual basis (mortar_2d.hpp, line2_dual_coefficients_axisymmetric).
/// \pre 0 ≤ a < n; unused components of x are ignored.
GROUT_INLINE_FUNCTION double face_node_weight(int dim, int n, const double x[][3], int a,
                                              bool axisymmetric = false) {
  if (dim == 2) {
    const double d[3] = {x[1][0] - x[0][0], x[1][1] - x[0][1], 0.0};
    const double L = detail::vector_length(d);
    if (axisymmetric) return 2.0 * 3.141592653589793 * L * (2.0 * x[a][0] + x[1 - a][0]) / 6.0;
    return 0.5 * L;
  }
  if (n == 3) {
    double u[3], v[3], c[3];
    for (int d = 0; d < 3; ++d) u[d] = x[1][d] - x[0][d], v[d] = x[2][d] - x[0][d];
    cross_product(u, v, c);
    return detail::vector_length(c) / 6.0;
  }
  const double xi_node[4] = {-1.0, 1.0, 1.0, -1.0}, eta_node[4] = {-1.0, -1.0, 1.0, 1.0};
  const double g[3] = {-0.7745966692414834, 0.0, 0.7745966692414834},  // ±√0.6
      wg[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  double w = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      double t1[3] = {0.0, 0.0, 0.0}, t2[3] = {0.0, 0.0, 0.0}, c[3];
      for (int b = 0; b < 4; ++b)
        for (int d = 0; d < 3; ++d) {
          t1[d] += 0.25 * xi_node[b] * (1.0 + eta_node[b] * g[k]) * x[b][d];
          t2[d] += 0.25 * eta_node[b] * (1.0 + xi_node[b] * g[i]) * x[b][d];
        }
      cross_product(t1, t2, c);
      const double N = 0.25 * (1.0 + xi_node[a] * g[i]) * (1.0 + eta_node[a] * g[k]);
      w += wg[i] * wg[k] * N * detail::vector_length(c);
    }
  return w;
}

}  // namespace grout
