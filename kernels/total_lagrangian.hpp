#pragma once
// Total-Lagrangian finite-strain solid element (tri3, quad4 in plane strain or plane stress;
// tet4, hex8 in 3D): internal force, its tangent by forward AD, the stored energy and the Cauchy
// stress.
//
//   F = I + grad_X u,  F_iJ = delta_iJ + sum_a u_ai dN_a/dX_J,
//   f_int_{a i} = int_{Omega_0} P_iJ(F) dN_a/dX_J dV,      Pi_int = int_{Omega_0} W(F) dV
// (Bonet & Wood, Nonlinear Continuum Mechanics for Finite Element Analysis, 2nd ed., §8.3,
// eq. 8.13; Belytschko, Liu & Moran, Nonlinear Finite Elements, §4.4). f_int = dPi_int/du.
// P and W come from first_piola_kirchhoff (kernels/hyperelastic_material.hpp); the element
// knows nothing of the law. Plane strain: F33 = 1, unit thickness; plane stress (the
// *_plane_stress laws): the law sets F33 itself, unit reference thickness, so that f_int and
// Pi_int are per unit reference thickness. Full Gauss integration as
// the small-strain element. Axisymmetric (axisymmetric = true, 2D tri3/quad4, x = R, y = Z):
// F_tt = 1 + u_r / R (hoop stretch), the 3D law, dV = 2 pi R dA and
// f_int_{a r} += int P_tt N_a / R dV (Bonet & Wood §8.3 with the hoop term of the
// axisymmetric element, kernels/axisymmetric_elastic.hpp; its quadrature). The tangent K = d f_int
// / d u is the Jacobian of the same function evaluated with Sacado forward-AD scalars (exact to
// round-off).

#include <Kokkos_Core.hpp>
#include <Sacado.hpp>
#include <type_traits>

#include "kernels/axisymmetric_elastic.hpp"
#include "kernels/element_tangent_ad.hpp"
#include "kernels/hyperelastic_material.hpp"
#include "kernels/linear_elastic.hpp"

namespace grout {

/// \brief F = I + grad_X u at a point: F_iJ = delta_iJ + sum_a u_ai G_aJ, G_aJ = dN_a/dX_J
/// (3 x 3; plane strain: F33 = 1, F13 = F23 = F31 = F32 = 0).
/// \pre u: [nodes * dim] node-major; G: [nodes * dim] as shape_gradients returns it.
template <class Scalar>
KOKKOS_INLINE_FUNCTION void deformation_gradient(int dim, int nodes, const Scalar* u,
                                                 const double* G, Scalar F[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J) F[i][J] = i == J ? 1.0 : 0.0;
  for (int i = 0; i < dim; ++i)
    for (int J = 0; J < dim; ++J)
      for (int a = 0; a < nodes; ++a) F[i][J] += u[a * dim + i] * G[a * dim + J];
}

/// \brief Internal force f_int_{a i} = int P_iJ N_a,J dV and, if energy != nullptr, the
/// stored energy int W dV (formulas in the file comment).
/// \pre X, u: [nodes * dimension] node-major; f_int: [nodes * dimension] (overwritten).
/// \return unsupported unless topology_dimension(topology) == dimension in {2, 3}; inverted if
/// the reference element has det J <= 0; collapsed if det F <= 0 at a quadrature point.
template <class Scalar>
KOKKOS_INLINE_FUNCTION ElementStatus total_lagrangian_element(
    Topology topology, int dimension, const double* X, const Scalar* u, HyperelasticLaw law,
    ElasticConstants c, Scalar* f_int, Scalar* energy, bool axisymmetric = false) {
  const int dim = dimension;
  if (dim < 2 || dim > 3 || topology_dimension(topology) != dim) return ElementStatus::unsupported;
  if (axisymmetric && dim != 2) return ElementStatus::unsupported;
  const int nodes = topology_num_nodes(topology);
  for (int r = 0; r < nodes * dim; ++r) f_int[r] = 0.0;
  if (energy) *energy = 0.0;

  const int degree =
      axisymmetric ? axisymmetric_integration_degree(topology) : full_integration_degree(topology);
  const int num_points = quadrature_num_points(topology, degree);
  for (int q = 0; q < num_points; ++q) {
    const QuadraturePoint p = quadrature_point(topology, degree, q);
    // Zeroed: GCC cannot see that shape_gradients fills them (-Wmaybe-uninitialized).
    double G[max_element_nodes * 3] = {}, det_J = 0.0;            // G[a * dim + J] = dN_a/dX_J
    double N[max_element_nodes] = {}, h[max_element_nodes] = {};  // axisymmetric: N_a, N_a / R
    const ElementStatus status =
        shape_gradients(topology, dim, X, p.xi, axisymmetric ? N : nullptr, G, det_J);
    if (status != ElementStatus::ok) return status;
    double dV = p.weight * det_J;

    Scalar F[3][3];
    deformation_gradient(dim, nodes, u, G, F);
    if (axisymmetric) {
      const double radius = axisymmetric_radius(nodes, X, N);
      if (!(radius > 0.0)) return ElementStatus::inverted;
      dV *= axisymmetric_two_pi * radius;
      for (int a = 0; a < nodes; ++a) {
        h[a] = N[a] / radius;
        F[2][2] += u[a * 2] * h[a];  // F_tt = 1 + u_r / R
      }
    }
    Scalar P[3][3], W;
    if (first_piola_kirchhoff(law, c, F, P, W) != MaterialStatus::ok)
      return ElementStatus::collapsed;

    for (int a = 0; a < nodes; ++a)
      for (int i = 0; i < dim; ++i) {
        Scalar f = 0.0;
        for (int J = 0; J < dim; ++J) f += P[i][J] * G[a * dim + J];
        if (axisymmetric && i == 0) f += P[2][2] * h[a];
        f_int[a * dim + i] += f * dV;
      }
    if (energy) *energy += W * dV;
  }
  return ElementStatus::ok;
}

/// \brief Internal force and, if K != nullptr, the tangent K = d f_int / d u (row-major
/// [n * n], n = nodes * dimension) by forward AD (force_and_tangent_by_ad: 6, 8, 12 or 24 dofs).
/// \pre as total_lagrangian_element; K: room for n * n.
/// \return as total_lagrangian_element.
KOKKOS_INLINE_FUNCTION ElementStatus total_lagrangian_force_and_tangent(
    Topology topology, int dimension, const double* X, const double* u, HyperelasticLaw law,
    ElasticConstants c, double* f_int, double* K, bool axisymmetric = false) {
  if (!K)
    return total_lagrangian_element<double>(topology, dimension, X, u, law, c, f_int, nullptr,
                                            axisymmetric);
  if (dimension < 2 || dimension > 3 || topology_dimension(topology) != dimension)
    return ElementStatus::unsupported;
  const auto evaluate = [&](const auto* u_ad, auto* f_ad) {
    using Fad = std::remove_pointer_t<decltype(f_ad)>;
    return total_lagrangian_element<Fad>(topology, dimension, X, u_ad, law, c, f_ad, nullptr,
                                         axisymmetric);
  };
  return force_and_tangent_by_ad(topology_num_nodes(topology) * dimension, u, evaluate, f_int, K);
}

/// \brief Volume-averaged Cauchy stress over the deformed element,
///   sigma_avg = int_{Omega} sigma dv / int_{Omega} dv = int_{Omega_0} P F^T dV / int_{Omega_0} J
///   dV,
/// in the Voigt order of linear_elastic_stress (2D: xx, yy, xy, zz; 3D: xx, yy, zz, xy, yz, xz).
/// In plane strain sigma_zz = P_33 / J from the law with F33 = 1; in plane stress F33 and J
/// are the law's (complete_deformation_gradient) and sigma_zz = 0 to round-off.
/// Axisymmetric: F_tt = 1 + u_r / R, volumes of revolution, and the "zz" slot holds sigma_tt.
/// \pre X, u: [nodes * dimension] node-major; stress: room for 6.
/// \return as total_lagrangian_element (stress undefined unless ok).
KOKKOS_INLINE_FUNCTION ElementStatus total_lagrangian_cauchy_stress(
    Topology topology, int dimension, const double* X, const double* u, HyperelasticLaw law,
    ElasticConstants c, double* stress, bool axisymmetric = false) {
  const int dim = dimension;
  if (dim < 2 || dim > 3 || topology_dimension(topology) != dim) return ElementStatus::unsupported;
  if (axisymmetric && dim != 2) return ElementStatus::unsupported;
  const int nodes = topology_num_nodes(topology);
  double tau_int[3][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};  // int P F^T dV
  double volume = 0.0;                                                         // int J dV
  const int degree =
      axisymmetric ? axisymmetric_integration_degree(topology) : full_integration_degree(topology);
  const int num_points = quadrature_num_points(topology, degree);
  for (int q = 0; q < num_points; ++q) {
    const QuadraturePoint p = quadrature_point(topology, degree, q);
    // Zeroed: GCC cannot see that shape_gradients fills them (-Wmaybe-uninitialized).
    double G[max_element_nodes * 3] = {}, det_J = 0.0, N[max_element_nodes] = {};
    const ElementStatus status =
        shape_gradients(topology, dim, X, p.xi, axisymmetric ? N : nullptr, G, det_J);
    if (status != ElementStatus::ok) return status;
    double dV = p.weight * det_J;
    double F_2[3][3], F[3][3];
    deformation_gradient(dim, nodes, u, G, F_2);
    if (axisymmetric) {
      const double radius = axisymmetric_radius(nodes, X, N);
      if (!(radius > 0.0)) return ElementStatus::inverted;
      dV *= axisymmetric_two_pi * radius;
      for (int a = 0; a < nodes; ++a) F_2[2][2] += u[a * 2] * N[a] / radius;
    }
    if (complete_deformation_gradient(law, c, F_2, F) != MaterialStatus::ok)  // plane stress: F33
      return ElementStatus::collapsed;
    double P[3][3], W = 0.0;
    if (first_piola_kirchhoff(law, c, F, P, W) != MaterialStatus::ok)
      return ElementStatus::collapsed;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int K = 0; K < 3; ++K) tau_int[i][j] += P[i][K] * F[j][K] * dV;
    volume += determinant_and_inverse_transpose<double>(F, nullptr) * dV;
  }
  double s[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s[i][j] = tau_int[i][j] / volume;
  if (dim == 2) {
    stress[0] = s[0][0];
    stress[1] = s[1][1];
    stress[2] = s[0][1];
    stress[3] = s[2][2];
    stress[4] = 0.0;
    stress[5] = 0.0;
  } else {
    stress[0] = s[0][0];
    stress[1] = s[1][1];
    stress[2] = s[2][2];
    stress[3] = s[0][1];
    stress[4] = s[1][2];
    stress[5] = s[0][2];
  }
  return ElementStatus::ok;
}

}  // namespace grout
