#pragma once
// The smallest Jacobian determinant of an element over the points of its quadrature rule:
// the check that a mesh's elements are usable before anything is assembled on them.

#include <Kokkos_Core.hpp>

#include "kernels/quadrature.hpp"
#include "kernels/shape_functions.hpp"
#include "kernels/topology.hpp"

namespace grout {

/// \brief det_min = min_q det J(ξ_q) with J_ij = Σ_a X_a,i ∂N_a/∂ξ_j (Hughes §3.2) over the
/// points ξ_q of the rule exact to `degree` on topology t: an element is usable where every
/// det J > 0 (the integrals of the solid use exactly these points).
/// \pre X[a * dim + i], a < topology_num_nodes(t).
/// \return false (det_min untouched) when a coordinate is not finite or topology_dimension(t)
/// != dim.
KOKKOS_INLINE_FUNCTION bool min_jacobian_determinant(Topology t, int dim, const double* X,
                                                     int degree, double& det_min) {
  if (topology_dimension(t) != dim) return false;
  for (int r = 0; r < topology_num_nodes(t) * dim; ++r)
    if (!(X[r] - X[r] == 0.0)) return false;  // NaN or ±inf
  const int num_points = quadrature_num_points(t, degree);
  for (int q = 0; q < num_points; ++q) {
    const QuadraturePoint p = quadrature_point(t, degree, q);
    double G[max_element_nodes * 3], det_J = 0.0;
    shape_gradients(t, dim, X, p.xi, nullptr, G, det_J);  // det_J is set also when <= 0
    det_min = q == 0 || det_J < det_min ? det_J : det_min;
  }
  return num_points > 0;
}

}  // namespace grout
