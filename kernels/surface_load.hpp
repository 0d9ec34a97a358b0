#pragma once
// Consistent nodal forces of a pressure/traction load on one element side, reference
// configuration (dead load):
//
//   f_a = int_side N_a (-p n + t) dA,   p = sum_b N_b p_b,  t = sum_b N_b t_b,
//
// with n dA = a dxi, a the side's area vector (shape_functions.hpp: 2D a = (T_y, -T_x),
// 3D a = T_1 x T_2), so f_a = sum_q w_q N_a (-p a + t |a|) (Hughes, The Finite Element
// Method, §3.8; Zienkiewicz & Taylor vol. 1, §6.7). p > 0 pushes into the body when the side's
// node order gives the outward normal (topology.hpp). Axisymmetric (2D, x = r): dA = 2 pi r ds,
// r = sum_b N_b X_b,r, so the forces are totals over the full circle; on a straight side the
// integrand N_a p r is cubic and the 2-point rule stays exact.

#include <Kokkos_Core.hpp>

#include "kernels/quadrature.hpp"
#include "kernels/shape_functions.hpp"
#include "kernels/topology.hpp"

namespace grout {

/// \brief Consistent nodal forces f_a = int N_a (-p n + t) dA on one side (line2 in 2D, tri3 or
/// quad4 in 3D), reference configuration. Quadrature: 2 Gauss points (line2), the 3-point
/// degree-2 rule (tri3), 2x2 Gauss (quad4) — exact for the pressure part and, on straight/planar
/// sides, for the traction part.
/// \pre X: [side_nodes * dimension]; p_nodal: [side_nodes] or null (no pressure); t_nodal:
/// [side_nodes * dimension] or null (no traction); f: [side_nodes * dimension], overwritten.
/// \return unsupported for any other (side_topology, dimension); ok otherwise (a degenerate side
/// of zero area gets zero forces).
KOKKOS_INLINE_FUNCTION ElementStatus surface_load(Topology side_topology, int dimension,
                                                  const double* X, const double* p_nodal,
                                                  const double* t_nodal, double* f,
                                                  bool axisymmetric = false) {
  const int dim = dimension;
  const bool supported =
      (dim == 2 && side_topology == Topology::line2) ||
      (dim == 3 && (side_topology == Topology::tri3 || side_topology == Topology::quad4));
  if (!supported) return ElementStatus::unsupported;
  const int nodes = topology_num_nodes(side_topology);
  for (int r = 0; r < nodes * dim; ++r) f[r] = 0.0;

  const int degree = side_topology == Topology::tri3 ? 2 : 3;
  const int num_points = quadrature_num_points(side_topology, degree);
  for (int q = 0; q < num_points; ++q) {
    const QuadraturePoint point = quadrature_point(side_topology, degree, q);
    double N[max_element_nodes] = {}, a[3] = {0.0, 0.0, 0.0};
    side_area_vector(side_topology, dim, X, point.xi, N, a);
    const double area = Kokkos::Experimental::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);

    // Load per unit reference parameter area: -p a + t |a|.
    double load[3] = {0.0, 0.0, 0.0};
    if (p_nodal) {
      double p = 0.0;
      for (int b = 0; b < nodes; ++b) p += N[b] * p_nodal[b];
      for (int i = 0; i < dim; ++i) load[i] -= p * a[i];
    }
    if (t_nodal)
      for (int i = 0; i < dim; ++i) {
        double t = 0.0;
        for (int b = 0; b < nodes; ++b) t += N[b] * t_nodal[b * dim + i];
        load[i] += t * area;
      }
    if (axisymmetric && dim == 2) {
      double r = 0.0;
      for (int b = 0; b < nodes; ++b) r += N[b] * X[b * 2];
      for (int i = 0; i < 2; ++i) load[i] *= 6.283185307179586476925286766559 * r;
    }
    for (int b = 0; b < nodes; ++b)
      for (int i = 0; i < dim; ++i) f[b * dim + i] += point.weight * N[b] * load[i];
  }
  return ElementStatus::ok;
}

}  // namespace grout
