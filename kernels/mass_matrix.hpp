#pragma once
// Mass matrix of one solid element (tri3, quad4 in 2D with unit thickness; tet4, hex8 in 3D):
//
//   consistent  M_ab = ρ ∫ N_a N_b dV          (Hughes, The Finite Element Method, eq. 7.2.3)
//   lumped      M_ab = δ_ab ρ ∫ N_a dV         (row-sum lumping, Hughes §7.3.2)
//
// per node pair (a, b); the dof matrix is M_ab δ_ij (the same for every component i). The
// Gauss rule integrates N_a N_b det J exactly: degree 2 on tri3/tet4 (det J constant), 3 per
// direction on quad4 (N_a N_b of degree 2, det J of degree 1), 4 per direction on hex8
// (det J of degree 2). Row sums of either matrix are ρ ∫ N_a dV, and Σ_ab M_ab = ρ V.

#include <Kokkos_Core.hpp>

#include "kernels/quadrature.hpp"
#include "kernels/shape_functions.hpp"
#include "kernels/topology.hpp"

namespace grout {

/// Degree of the Gauss rule that makes element_mass exact (file comment).
KOKKOS_INLINE_FUNCTION constexpr int mass_integration_degree(Topology t) {
  return (t == Topology::tri3 || t == Topology::tet4) ? 2 : t == Topology::hex8 ? 4 : 3;
}

/// \brief Element mass per node pair, consistent or row-sum lumped (file comment).
/// \pre X: [nodes * dimension] node-major reference coordinates; M: [nodes * nodes] row-major,
/// overwritten; density ≥ 0.
/// \return unsupported unless topology_dimension(topology) == dimension in {2, 3}; inverted if
/// det J ≤ 0 at a quadrature point (M then undefined).
KOKKOS_INLINE_FUNCTION ElementStatus element_mass(Topology topology, int dimension, const double* X,
                                                  double density, bool lumped, double* M) {
  const int dim = dimension;
  if (dim < 2 || dim > 3 || topology_dimension(topology) != dim) return ElementStatus::unsupported;
  const int nodes = topology_num_nodes(topology);
  for (int k = 0; k < nodes * nodes; ++k) M[k] = 0.0;
  const int degree = mass_integration_degree(topology);
  const int num_points = quadrature_num_points(topology, degree);
  for (int q = 0; q < num_points; ++q) {
    const QuadraturePoint p = quadrature_point(topology, degree, q);
    double N[max_element_nodes], G[max_element_nodes * 3], det_J = 0.0;
    const ElementStatus status = shape_gradients(topology, dim, X, p.xi, N, G, det_J);
    if (status != ElementStatus::ok) return status;
    const double dm = density * p.weight * det_J;
    for (int a = 0; a < nodes; ++a) {
      if (lumped) {
        M[a * nodes + a] += N[a] * dm;
      } else {
        for (int b = 0; b < nodes; ++b) M[a * nodes + b] += N[a] * N[b] * dm;
      }
    }
  }
  return ElementStatus::ok;
}

}  // namespace grout
