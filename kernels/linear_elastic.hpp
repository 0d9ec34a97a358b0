#pragma once
// Small-strain isotropic linear elasticity on one solid element (tri3, quad4 in 2D; tet4, hex8
// in 3D): internal force, stiffness and the volume-averaged stress.
//
//   eps = sym(grad u),   sigma = lambda tr(eps) I + 2 mu eps,
//   f_int_{a i} = int sigma_ij dN_a/dX_j dV,
//   K_{a i, b k} = int [lambda N_a,i N_b,k + mu (delta_ik N_a,j N_b,j + N_a,k N_b,i)] dV
// (Hughes, The Finite Element Method, §2.7-2.8 and §3.10; written without the B matrix).
// 2D is plane strain with the 3D Lamé constants, or plane stress with lambda replaced by
// lambda* = 2 lambda mu / (lambda + 2 mu) (Zienkiewicz & Taylor, vol. 1, §6.2); unit thickness.

#include "kernels/kernel_macros.hpp"
#include "kernels/quadrature.hpp"
#include "kernels/shape_functions.hpp"
#include "kernels/topology.hpp"

namespace grout {

/// Lamé constants of an isotropic linear-elastic material (lambda already reduced for plane
/// stress).
struct ElasticConstants {
  double lambda;
  double mu;
};

/// \brief Lamé constants from Young's modulus E and Poisson's ratio nu:
///   lambda = E nu / ((1 + nu)(1 - 2 nu)),  mu = E / (2 (1 + nu));
/// in 2D plane stress lambda* = 2 lambda mu / (lambda + 2 mu) = E nu / (1 - nu^2).
/// plane_stress is ignored unless dimension == 2.
/// \pre E > 0, -1 < nu < 1/2 (validated by the input layer).
GROUT_INLINE_FUNCTION ElasticConstants elastic_constants(double youngs_modulus,
                                                         double poissons_ratio, int dimension,
                                                         bool plane_stress) {
  const double E = youngs_modulus, nu = poissons_ratio;
  ElasticConstants c{E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu))};
  if (dimension == 2 && plane_stress) c.lambda = E * nu / (1.0 - nu * nu);
  return c;
}

/// Polynomial degree of the full Gauss rule of a first-order solid element: 1 point on
/// tri3/tet4 (constant strain), 2 per direction on quad4/hex8.
GROUT_INLINE_FUNCTION constexpr int full_integration_degree(Topology t) {
  return (t == Topology::tri3 || t == Topology::tet4) ? 1 : 3;
}

/// \brief Internal force f_int = int B^T sigma(u) dV and, if K != nullptr, the stiffness
/// K = int B^T C B dV (formulas in the file comment), full Gauss integration.
/// \pre X, u: [nodes * dimension] node-major (u0x u0y [u0z] u1x ...); f_int: [n], K: [n * n]
/// row-major, n = nodes * dimension <= max_element_dofs. Both outputs are overwritten.
/// Scalar = double or a Sacado Fad (then d f_int / d u = K); K is always double.
/// \return unsupported unless topology_dimension(topology) == dimension in {2, 3}; inverted if
/// det J <= 0 at a quadrature point (outputs then undefined).
template <class Scalar>
GROUT_INLINE_FUNCTION ElementStatus linear_elastic_element(Topology topology, int dimension,
                                                           const double* X, const Scalar* u,
                                                           ElasticConstants c, Scalar* f_int,
                                                           double* K) {
  const int dim = dimension;
  if (dim < 2 || dim > 3 || topology_dimension(topology) != dim) return ElementStatus::unsupported;
  const int nodes = topology_num_nodes(topology);
  const int n = nodes * dim;
  for (int r = 0; r < n; ++r) f_int[r] = 0.0;
  if (K)
    for (int r = 0; r < n * n; ++r) K[r] = 0.0;

  const int degree = full_integration_degree(topology);
  const int num_points = quadrature_num_points(topology, degree);
  for (int q = 0; q < num_points; ++q) {
    const QuadraturePoint p = quadrature_point(topology, degree, q);
    double G[max_element_nodes * 3], det_J = 0.0;  // G[a * dim + j] = dN_a/dX_j
    const ElementStatus status = shape_gradients(topology, dim, X, p.xi, nullptr, G, det_J);
    if (status != ElementStatus::ok) return status;
    const double dV = p.weight * det_J;

    // sigma = lambda tr(eps) I + 2 mu eps, eps_ij = (u_i,j + u_j,i) / 2, u_i,j = sum_a u_ai G_aj.
    Scalar H[3][3];
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j) {
        H[i][j] = 0.0;
        for (int a = 0; a < nodes; ++a) H[i][j] += u[a * dim + i] * G[a * dim + j];
      }
    Scalar trace = 0.0;
    for (int i = 0; i < dim; ++i) trace += H[i][i];
    Scalar sigma[3][3];
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j) sigma[i][j] = c.mu * (H[i][j] + H[j][i]);
    for (int i = 0; i < dim; ++i) sigma[i][i] += c.lambda * trace;

    for (int a = 0; a < nodes; ++a)
      for (int i = 0; i < dim; ++i) {
        Scalar f = 0.0;
        for (int j = 0; j < dim; ++j) f += sigma[i][j] * G[a * dim + j];
        f_int[a * dim + i] += f * dV;
      }

    if (!K) continue;
    for (int a = 0; a < nodes; ++a)
      for (int b = 0; b < nodes; ++b) {
        double ga_gb = 0.0;
        for (int j = 0; j < dim; ++j) ga_gb += G[a * dim + j] * G[b * dim + j];
        for (int i = 0; i < dim; ++i)
          for (int k = 0; k < dim; ++k) {
            const double Kaibk = c.lambda * G[a * dim + i] * G[b * dim + k] +
                                 c.mu * ((i == k ? ga_gb : 0.0) + G[a * dim + k] * G[b * dim + i]);
            K[(a * dim + i) * n + b * dim + k] += Kaibk * dV;
          }
      }
  }
  return ElementStatus::ok;
}

/// \brief Volume-averaged stress sigma_avg = (1/V) int sigma(u) dV, Voigt order
///   2D: xx, yy, xy, zz   (stress[4], stress[5] set to 0)
///   3D: xx, yy, zz, xy, yz, xz.
/// sigma_zz in 2D: plane strain (plane_strain = true, c from elastic_constants with
/// plane_stress = false) sigma_zz = lambda (eps_xx + eps_yy) = nu (sigma_xx + sigma_yy);
/// plane stress sigma_zz = 0. poissons_ratio is used only for plane strain.
/// \pre X, u: [nodes * dimension] node-major; stress: room for 6.
/// \return as linear_elastic_element (stress undefined unless ok).
GROUT_INLINE_FUNCTION ElementStatus linear_elastic_stress(Topology topology, int dimension,
                                                          const double* X, const double* u,
                                                          ElasticConstants c, bool plane_strain,
                                                          double poissons_ratio, double* stress) {
  const int dim = dimension;
  if (dim < 2 || dim > 3 || topology_dimension(topology) != dim) return ElementStatus::unsupported;
  const int nodes = topology_num_nodes(topology);
  double sigma_int[3][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
  double volume = 0.0;

  const int degree = full_integration_degree(topology);
  const int num_points = quadrature_num_points(topology, degree);
  for (int q = 0; q < num_points; ++q) {
    const QuadraturePoint p = quadrature_point(topology, degree, q);
    double G[max_element_nodes * 3], det_J = 0.0;
    const ElementStatus status = shape_gradients(topology, dim, X, p.xi, nullptr, G, det_J);
    if (status != ElementStatus::ok) return status;
    const double dV = p.weight * det_J;
    double H[3][3];
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j) {
        H[i][j] = 0.0;
        for (int a = 0; a < nodes; ++a) H[i][j] += u[a * dim + i] * G[a * dim + j];
      }
    double trace = 0.0;
    for (int i = 0; i < dim; ++i) trace += H[i][i];
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j)
        sigma_int[i][j] += (c.mu * (H[i][j] + H[j][i]) + (i == j ? c.lambda * trace : 0.0)) * dV;
    volume += dV;
  }

  double s[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s[i][j] = sigma_int[i][j] / volume;
  if (dim == 2) {
    stress[0] = s[0][0];
    stress[1] = s[1][1];
    stress[2] = s[0][1];
    stress[3] = plane_strain ? poissons_ratio * (s[0][0] + s[1][1]) : 0.0;
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
