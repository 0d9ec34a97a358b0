#pragma once
// Energy-momentum internal force of the total-Lagrangian element over a time step
// (`dynamics: {scheme: energy_momentum}`), after Simo & Tarnow, ZAMP 43 (1992) 757, and
// Gonzalez, CMAME 190 (2000) 1763 (the discrete gradient for any hyperelastic law):
//
//   f_algo_{a i} = int_{Omega_0} (F_mid S_algo)_{iJ} N_a,J dV,     F_mid = (F_n + F_{n+1})/2,
//   S_algo = S(C_mid) + 2 [W(C_{n+1}) - W(C_n) - S(C_mid) : dC / 2] dC / (dC : dC),
//   C_mid = (C_n + C_{n+1})/2,  dC = C_{n+1} - C_n,
//
// S(C) = 2 dW/dC and W(C) from second_piola_kirchhoff (kernels/hyperelastic_material.hpp).
// Properties (per element, exact up to round-off):
//   energy:            f_algo . (u_{n+1} - u_n) = int W(C_{n+1}) - W(C_n) dV, because
//                      dC = F_mid^T dF + dF^T F_mid exactly and S_algo : dC / 2 = dW;
//   angular momentum:  sum_a x_mid,a x f_algo,a = 0 (x_mid = X + u_mid), because
//                      sum_a f_algo,a (x) x_mid,a = int F_mid S_algo F_mid^T dV is symmetric;
//   consistency:       f_algo(u, u) = f_int(u) (S_algo = S(C), F_mid = F).
// With the midpoint kinematics of Newmark's average acceleration, u_{n+1} - u_n =
// dt/2 (v_n + v_{n+1}), the step M (v_{n+1} - v_n)/dt + f_algo = f_ext conserves the total
// energy and the angular momentum of a free hyperelastic body (Simo & Tarnow, §3).
// For St. Venant-Kirchhoff W is quadratic in C and the bracket vanishes: S_algo = S(C_mid),
// Simo & Tarnow's algorithmic stress. Round-off: the bracket is O(mu |dC|^3), but W carries an
// absolute error of eps mu (tr C - 3 of a C near I; mu the shear modulus), which the division
// by |dC|^2 turns into eps mu / |dC| in S_algo: 54 Pa in the steel ring of
// inputs/ring_pendulum at |dC| = 1e-6, enough to stall Newton at |F| ~ 0.1 N. So the bracket
// is weighted by w = s^2 / (1 + s^2), s = |dC|^2 / tol^2, tol = 1e-4: smooth in u (Newton keeps
// its quadratic rate), 1 for |dC| >> tol, where the round-off is below 3 eps mu / tol, and
// |dC|^4 / tol^4 below, where the bracket left out, O(mu |dC|^3) per unit volume and step, is
// the energy error. The angular momentum is kept exactly either way (S_algo stays symmetric).
//
// The element returns f = 2 f_algo - f_int(u_n): with the start of the step's internal force
// f_int(u_n) it averages to f_algo, as the generalised-alpha rows of DynamicProblem average
// (f_{n+1} + f_n)/2 with alpha_f = 1/2. Its tangent is d f / d u_{n+1} by Sacado forward AD.

#include <Kokkos_Core.hpp>
#include <type_traits>

#include "kernels/element_tangent_ad.hpp"
#include "kernels/hyperelastic_material.hpp"
#include "kernels/linear_elastic.hpp"
#include "kernels/total_lagrangian.hpp"

namespace grout {

/// tol^2 of the bracket's weight (file comment): |dC| = 1e-4.
constexpr double bracket_tol2 = 1e-8;

/// \brief f = 2 f_algo(u_n, u) - f_int(u_n) of the element (formulas in the file comment).
/// \pre X, u_n, u: [nodes * dimension] node-major; f: [nodes * dimension] (overwritten).
/// \return unsupported unless topology_dimension(topology) == dimension in {2, 3}; inverted if
/// the reference element has det J <= 0; collapsed if det F <= 0 at a quadrature point of u_n
/// or u.
template <class Scalar>
KOKKOS_INLINE_FUNCTION ElementStatus energy_momentum_element(Topology topology, int dimension,
                                                             const double* X, const double* u_n,
                                                             const Scalar* u, HyperelasticLaw law,
                                                             ElasticConstants c, Scalar* f) {
  const int dim = dimension;
  if (dim < 2 || dim > 3 || topology_dimension(topology) != dim) return ElementStatus::unsupported;
  const int nodes = topology_num_nodes(topology);
  for (int r = 0; r < nodes * dim; ++r) f[r] = 0.0;

  const int degree = full_integration_degree(topology);
  const int num_points = quadrature_num_points(topology, degree);
  for (int q = 0; q < num_points; ++q) {
    const QuadraturePoint p = quadrature_point(topology, degree, q);
    double G[max_element_nodes * 3], det_J = 0.0;  // G[a * dim + J] = dN_a/dX_J
    const ElementStatus status = shape_gradients(topology, dim, X, p.xi, nullptr, G, det_J);
    if (status != ElementStatus::ok) return status;
    const double dV = p.weight * det_J;

    double F_n[3][3];
    Scalar F[3][3];
    deformation_gradient(dim, nodes, u_n, G, F_n);
    deformation_gradient(dim, nodes, u, G, F);
    if (!(determinant_and_inverse_transpose<Scalar>(F, nullptr) > 0.0) ||
        !(determinant_and_inverse_transpose<double>(F_n, nullptr) > 0.0))
      return ElementStatus::collapsed;
    double C_n[3][3];
    Scalar C[3][3], C_mid[3][3], dC[3][3];
    for (int I = 0; I < 3; ++I)
      for (int K = 0; K < 3; ++K) {
        C_n[I][K] = 0.0;
        C[I][K] = 0.0;
        for (int i = 0; i < 3; ++i) {
          C_n[I][K] += F_n[i][I] * F_n[i][K];
          C[I][K] += F[i][I] * F[i][K];
        }
        dC[I][K] = C[I][K] - C_n[I][K];
        C_mid[I][K] = 0.5 * (C[I][K] + C_n[I][K]);
      }
    double S_n[3][3], W_n = 0.0;
    Scalar S_mid[3][3], W_mid;
    if (second_piola_kirchhoff<double>(law, c, C_n, S_n, W_n) != MaterialStatus::ok ||
        second_piola_kirchhoff<Scalar>(law, c, C_mid, S_mid, W_mid) != MaterialStatus::ok)
      return ElementStatus::collapsed;
    if (law != HyperelasticLaw::saint_venant_kirchhoff) {  // SVK: the bracket is zero
      // Gonzalez's bracket: the part of dW that S(C_mid) misses, along dC.
      Scalar W;
      if (strain_energy_of_C<Scalar>(law, c, C, W) != MaterialStatus::ok)
        return ElementStatus::collapsed;
      Scalar dC_dC = 0.0, S_dC = 0.0;
      for (int I = 0; I < 3; ++I)
        for (int K = 0; K < 3; ++K) dC_dC += dC[I][K] * dC[I][K], S_dC += S_mid[I][K] * dC[I][K];
      // Weighted by w = s²/(1 + s²), s = |dC|²/tol²: w / |dC|² = s / ((1 + s²) tol²).
      const Scalar s = dC_dC / bracket_tol2;
      const Scalar factor = 2.0 * (W - W_n - 0.5 * S_dC) * s / ((1.0 + s * s) * bracket_tol2);
      for (int I = 0; I < 3; ++I)
        for (int K = 0; K < 3; ++K) S_mid[I][K] += factor * dC[I][K];
    }
    // f += 2 F_mid S_algo grad N - F_n S_n grad N.
    for (int i = 0; i < dim; ++i)
      for (int J = 0; J < dim; ++J) {
        Scalar P_algo = 0.0;
        double P_n = 0.0;
        for (int K = 0; K < 3; ++K) {
          P_algo += (F[i][K] + F_n[i][K]) * S_mid[K][J];  // 2 F_mid S_algo
          P_n += F_n[i][K] * S_n[K][J];
        }
        for (int a = 0; a < nodes; ++a) f[a * dim + i] += (P_algo - P_n) * G[a * dim + J] * dV;
      }
  }
  return ElementStatus::ok;
}

/// \brief f = 2 f_algo(u_n, u) - f_int(u_n) and, if K != nullptr, K = d f / d u (row-major
/// [n * n], n = nodes * dimension) by forward AD (force_and_tangent_by_ad).
/// \pre as energy_momentum_element; K: room for n * n.
/// \return as energy_momentum_element.
KOKKOS_INLINE_FUNCTION ElementStatus energy_momentum_force_and_tangent(
    Topology topology, int dimension, const double* X, const double* u_n, const double* u,
    HyperelasticLaw law, ElasticConstants c, double* f, double* K) {
  if (!K) return energy_momentum_element<double>(topology, dimension, X, u_n, u, law, c, f);
  if (dimension < 2 || dimension > 3 || topology_dimension(topology) != dimension)
    return ElementStatus::unsupported;
  const auto evaluate = [&](const auto* u_ad, auto* f_ad) {
    using Fad = std::remove_pointer_t<decltype(f_ad)>;
    return energy_momentum_element<Fad>(topology, dimension, X, u_n, u_ad, law, c, f_ad);
  };
  return force_and_tangent_by_ad(topology_num_nodes(topology) * dimension, u, evaluate, f, K);
}

}  // namespace grout
