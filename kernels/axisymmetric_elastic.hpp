#pragma once
// Small-strain isotropic linear elasticity on one axisymmetric solid element (tri3, quad4 in
// the (r, z) = (x, y) half plane r >= 0; torsionless, u = (u_r, u_z) independent of theta):
//
//   eps_rr = u_r,r,  eps_zz = u_z,z,  2 eps_rz = u_r,z + u_z,r,  eps_tt = u_r / r  (hoop),
//   sigma = lambda tr(eps) I + 2 mu eps   (3D Lamé constants, tr eps = eps_rr + eps_zz + eps_tt),
//   f_int_{a i} = int (sigma_ij N_a,j + delta_i0 sigma_tt N_a / r) dV,   dV = 2 pi r dA,
//   K_{a i, b k} = int [lambda (N_a,i + delta_i0 h_a)(N_b,k + delta_k0 h_b)
//                       + mu (delta_ik N_a,j N_b,j + N_a,k N_b,i) + 2 mu delta_i0 delta_k0 h_a h_b]
//                       dV,
//   h_a = N_a / r
// (Zienkiewicz & Taylor, The Finite Element Method, vol. 1, 6th ed., ch. 5; Hughes, The Finite
// Element Method, §2.12). The 2 pi is kept: forces and energies are totals over the full
// circle (docs/input.md, "Axisymmetric models"). Quadrature: 2 x 2 Gauss on quad4, the
// 3-point degree-2 rule on tri3 (the 1-point rule of the plane element would leave the r-weighted
// stiffness of a triangle rank-deficient); no point lies on the axis, so 1/r stays finite.
// For a displacement linear in (r, z) the stress is constant and every integrand of f_int
// is a polynomial the rule integrates exactly (r N_a,j, N_a), so such a field is reproduced
// to round-off (unit_tests/test_kernels_axisymmetric.cpp, inputs/axisymmetric).

#include "kernels/kernel_macros.hpp"
#include "kernels/linear_elastic.hpp"
#include "kernels/quadrature.hpp"
#include "kernels/shape_functions.hpp"
#include "kernels/topology.hpp"

namespace grout {

constexpr double axisymmetric_two_pi = 6.283185307179586476925286766559;

/// Degree of the rule of an axisymmetric element: 2 on tri3 (3 points), 3 per direction on
/// quad4 (2 x 2).
GROUT_INLINE_FUNCTION constexpr int axisymmetric_integration_degree(Topology t) {
  return t == Topology::tri3 ? 2 : 3;
}

/// \brief Radius r = sum_a N_a X_a,r at a point from the shape values N.
GROUT_INLINE_FUNCTION double axisymmetric_radius(int nodes, const double* X, const double* N) {
  double r = 0.0;
  for (int a = 0; a < nodes; ++a) r += N[a] * X[a * 2];
  return r;
}

/// One quadrature point q of an axisymmetric element: shape values N, gradients G, the radius,
/// h_a = N_a / r and dV = 2 pi r w det J.
struct AxisymmetricPoint {
  double N[max_element_nodes], G[max_element_nodes * 3], h[max_element_nodes];
  double radius = 0.0, dV = 0.0;
};

/// \brief Fills `p` at point q of the element's rule (axisymmetric_integration_degree).
/// \return the status of shape_gradients; inverted if r <= 0 there.
GROUT_INLINE_FUNCTION ElementStatus axisymmetric_point(Topology topology, const double* X, int q,
                                                       AxisymmetricPoint& p) {
  const int nodes = topology_num_nodes(topology);
  const QuadraturePoint point =
      quadrature_point(topology, axisymmetric_integration_degree(topology), q);
  double det_J = 0.0;
  const ElementStatus status = shape_gradients(topology, 2, X, point.xi, p.N, p.G, det_J);
  if (status != ElementStatus::ok) return status;
  p.radius = axisymmetric_radius(nodes, X, p.N);
  if (!(p.radius > 0.0)) return ElementStatus::inverted;
  p.dV = axisymmetric_two_pi * p.radius * point.weight * det_J;
  for (int a = 0; a < nodes; ++a) p.h[a] = p.N[a] / p.radius;
  return ElementStatus::ok;
}

/// \brief H_ij = u_i,j and the hoop strain u_r / r at point p.
template <class Scalar>
GROUT_INLINE_FUNCTION void axisymmetric_strains(int nodes, const Scalar* u,
                                                const AxisymmetricPoint& p, Scalar (&H)[2][2],
                                                Scalar& hoop) {
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      H[i][j] = 0.0;
      for (int a = 0; a < nodes; ++a) H[i][j] += u[a * 2 + i] * p.G[a * 2 + j];
    }
  hoop = 0.0;
  for (int a = 0; a < nodes; ++a) hoop += u[a * 2] * p.h[a];
}

/// \brief Internal force and, if K != nullptr, the stiffness of one axisymmetric element
/// (formulas in the file comment).
/// \pre X, u: [nodes * 2] node-major (u0r u0z u1r ...); f_int: [n], K: [n * n] row-major.
/// Scalar = double or a Sacado Fad (then d f_int / d u = K); K is always double.
/// \return unsupported unless topology is tri3 or quad4; inverted if det J <= 0 or r <= 0 at a
/// quadrature point (outputs then undefined).
template <class Scalar>
GROUT_INLINE_FUNCTION ElementStatus axisymmetric_elastic_element(Topology topology, const double* X,
                                                                 const Scalar* u,
                                                                 ElasticConstants c, Scalar* f_int,
                                                                 double* K) {
  if (topology != Topology::tri3 && topology != Topology::quad4) return ElementStatus::unsupported;
  const int nodes = topology_num_nodes(topology);
  const int n = nodes * 2;
  for (int r = 0; r < n; ++r) f_int[r] = 0.0;
  if (K)
    for (int r = 0; r < n * n; ++r) K[r] = 0.0;

  const int num_points = quadrature_num_points(topology, axisymmetric_integration_degree(topology));
  for (int q = 0; q < num_points; ++q) {
    AxisymmetricPoint pt{};  // zeroed: GCC cannot see that shape_gradients fills it
    const ElementStatus status = axisymmetric_point(topology, X, q, pt);
    if (status != ElementStatus::ok) return status;
    const double* G = pt.G;
    const double* h = pt.h;
    const double dV = pt.dV;
    Scalar H[2][2], hoop;  // H_ij = u_i,j; hoop = u_r / r
    axisymmetric_strains(nodes, u, pt, H, hoop);
    const Scalar trace = H[0][0] + H[1][1] + hoop;
    Scalar sigma[2][2];
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) sigma[i][j] = c.mu * (H[i][j] + H[j][i]);
    for (int i = 0; i < 2; ++i) sigma[i][i] += c.lambda * trace;
    const Scalar sigma_tt = 2.0 * c.mu * hoop + c.lambda * trace;

    for (int a = 0; a < nodes; ++a)
      for (int i = 0; i < 2; ++i) {
        Scalar f = sigma[i][0] * G[a * 2] + sigma[i][1] * G[a * 2 + 1];
        if (i == 0) f += sigma_tt * h[a];
        f_int[a * 2 + i] += f * dV;
      }

    if (!K) continue;
    for (int a = 0; a < nodes; ++a)
      for (int b = 0; b < nodes; ++b) {
        const double ga_gb = G[a * 2] * G[b * 2] + G[a * 2 + 1] * G[b * 2 + 1];
        for (int i = 0; i < 2; ++i)
          for (int k = 0; k < 2; ++k) {
            const double va = G[a * 2 + i] + (i == 0 ? h[a] : 0.0);
            const double vb = G[b * 2 + k] + (k == 0 ? h[b] : 0.0);
            const double Kaibk = c.lambda * va * vb +
                                 c.mu * ((i == k ? ga_gb : 0.0) + G[a * 2 + k] * G[b * 2 + i]) +
                                 (i == 0 && k == 0 ? 2.0 * c.mu * h[a] * h[b] : 0.0);
            K[(a * 2 + i) * n + b * 2 + k] += Kaibk * dV;
          }
      }
  }
  return ElementStatus::ok;
}

/// \brief Stress averaged over the element's volume of revolution,
/// sigma_avg = int sigma 2 pi r dA / int 2 pi r dA, in the 2D Voigt order of
/// linear_elastic_stress: rr, zz, rz, tt (= xx, yy, xy and the out-of-plane "zz" slot, which
/// holds the hoop stress); stress[4], stress[5] = 0.
/// \pre X, u: [nodes * 2] node-major; stress: room for 6.
/// \return as axisymmetric_elastic_element (stress undefined unless ok).
GROUT_INLINE_FUNCTION ElementStatus axisymmetric_elastic_stress(Topology topology, const double* X,
                                                                const double* u, ElasticConstants c,
                                                                double* stress) {
  if (topology != Topology::tri3 && topology != Topology::quad4) return ElementStatus::unsupported;
  const int nodes = topology_num_nodes(topology);
  double s[4] = {0.0, 0.0, 0.0, 0.0}, volume = 0.0;
  const int num_points = quadrature_num_points(topology, axisymmetric_integration_degree(topology));
  for (int q = 0; q < num_points; ++q) {
    AxisymmetricPoint pt{};  // zeroed: GCC cannot see that shape_gradients fills it
    const ElementStatus status = axisymmetric_point(topology, X, q, pt);
    if (status != ElementStatus::ok) return status;
    const double dV = pt.dV;
    double H[2][2], hoop;
    axisymmetric_strains(nodes, u, pt, H, hoop);
    const double trace = H[0][0] + H[1][1] + hoop;
    s[0] += (2.0 * c.mu * H[0][0] + c.lambda * trace) * dV;
    s[1] += (2.0 * c.mu * H[1][1] + c.lambda * trace) * dV;
    s[2] += c.mu * (H[0][1] + H[1][0]) * dV;
    s[3] += (2.0 * c.mu * hoop + c.lambda * trace) * dV;
    volume += dV;
  }
  for (int k = 0; k < 4; ++k) stress[k] = s[k] / volume;
  stress[4] = stress[5] = 0.0;
  return ElementStatus::ok;
}

}  // namespace grout
