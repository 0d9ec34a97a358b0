#pragma once
// The Jacobian determinant of a solid element at its corners, where a bilinear or trilinear
// element folds first: det J at the Gauss points can stay positive while a corner has turned
// inside out.

#include <Kokkos_Core.hpp>

#include "kernels/shape_functions.hpp"
#include "kernels/topology.hpp"

namespace grout {

/// \brief det F at the corners of one element, from its reference coordinates X and current
/// coordinates x = X + u: det F(ξ_c) = det J_x(ξ_c) / det J_X(ξ_c) (F = ∂x/∂X = J_x J_X⁻¹,
/// Hughes §3.2 for J), at the corners ξ_c ∈ {−1, 1}^dim of quad4/hex8. On tri3/tet4 F is
/// constant and the centroid stands for every point. Corners where det J_X ≤ 0 are skipped
/// (the reference element is checked at its Gauss points when the mesh is read).
/// \pre X and x: [nodes * dim], node-major.
/// \return the smallest det F over the corners (1 when none applies); `corner` gets its local
/// node (the corner a of ξ_a), or -1.
KOKKOS_INLINE_FUNCTION double min_corner_det_F(Topology t, int dim, const double* X,
                                               const double* x, int& corner) {
  corner = -1;
  double det_F_min = 1.0;
  if (topology_dimension(t) != dim) return det_F_min;
  const bool linear = t == Topology::tri3 || t == Topology::tet4;
  const int nodes = topology_num_nodes(t), points = linear ? 1 : nodes;
  for (int c = 0; c < points; ++c) {
    double xi[3] = {0.25, 0.25, 0.25};
    if (!linear) {
      xi[0] = (c == 1 || c == 2 || c == 5 || c == 6) ? 1.0 : -1.0;  // shape_functions' order
      xi[1] = (c == 2 || c == 3 || c == 6 || c == 7) ? 1.0 : -1.0;
      xi[2] = c >= 4 ? 1.0 : -1.0;
    } else if (t == Topology::tri3) {
      xi[0] = xi[1] = 1.0 / 3.0;
    }
    double G[max_element_nodes * 3], det_X = 0.0, det_x = 0.0;
    shape_gradients(t, dim, X, xi, nullptr, G, det_X);  // det_J is set also when <= 0
    shape_gradients(t, dim, x, xi, nullptr, G, det_x);
    if (!(det_X > 0.0)) continue;
    const double det_F = det_x / det_X;
    if (corner < 0 || det_F < det_F_min) det_F_min = det_F, corner = c;
  }
  return det_F_min;
}

}  // namespace grout
