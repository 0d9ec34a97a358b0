#pragma once
// Isotropic hyperelastic laws at one material point: the strain energy density W(F) and the
// first Piola-Kirchhoff stress P = dW/dF from the deformation gradient F.
//
// Compressible Neo-Hookean (Bonet & Wood, Nonlinear Continuum Mechanics for Finite Element
// Analysis, 2nd ed., §6.4.3, eqs. 6.27-6.28; the law of deal.II step-44 and MFEM's
// NeoHookeanModel in this form):
//   W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2,   I1 = tr(F^T F),  J = det F,
//   P = mu (F - F^-T) + lambda ln J F^-T.
// St. Venant-Kirchhoff (Bonet & Wood §6.4.2; Holzapfel, Nonlinear Solid Mechanics, §6.5):
//   E = (F^T F - I)/2,   W = lambda/2 (tr E)^2 + mu E:E,
//   S = lambda tr(E) I + 2 mu E,   P = F S.
// Both reduce to small-strain linear elasticity with the same Lamé constants for |F - I| -> 0.
// F is always 3 x 3: plane strain is F = [[F11, F12, 0], [F21, F22, 0], [0, 0, 1]], and the
// out-of-plane P_33 is what the Cauchy stress sigma_zz needs. Plane stress (the *_plane_stress
// laws): the law reads the in-plane F (or C) only and sets F_33 (C_33) itself so that S_33 = 0
// (kernels/plane_stress_material.hpp), then evaluates the 3D law at the completed F (or C);
// P_33 = S_33 = 0 to round-off and W is the sheet's energy density per unit reference volume.
// Templated on the scalar (double or a Sacado Fad): the tangent dP/dF comes from AD.

#include <Kokkos_Core.hpp>
#include <cmath>

#include "kernels/linear_elastic.hpp"
#include "kernels/plane_stress_material.hpp"

namespace grout {

/// Hyperelastic law of a finite-strain solid (the `linear_elastic` input law under
/// `strain: finite` is St. Venant-Kirchhoff); the *_plane_stress laws are the same laws in a 2D
/// model with `plane: stress` (F_33 from S_33 = 0; file comment).
enum class HyperelasticLaw : int {
  saint_venant_kirchhoff = 0,
  neo_hookean = 1,
  saint_venant_kirchhoff_plane_stress = 2,
  neo_hookean_plane_stress = 3
};

/// True for the laws that find F_33 from S_33 = 0.
KOKKOS_INLINE_FUNCTION constexpr bool is_plane_stress(HyperelasticLaw law) {
  return law == HyperelasticLaw::saint_venant_kirchhoff_plane_stress ||
         law == HyperelasticLaw::neo_hookean_plane_stress;
}

/// The 3D law behind a plane-stress law (the law itself otherwise).
KOKKOS_INLINE_FUNCTION constexpr HyperelasticLaw three_dimensional_law(HyperelasticLaw law) {
  return law == HyperelasticLaw::saint_venant_kirchhoff_plane_stress
             ? HyperelasticLaw::saint_venant_kirchhoff
         : law == HyperelasticLaw::neo_hookean_plane_stress ? HyperelasticLaw::neo_hookean
                                                            : law;
}

/// Outcome of a material evaluation.
enum class MaterialStatus : int { ok = 0, collapsed = 1 };  ///< collapsed: det F <= 0

/// det A of a 3 x 3 matrix and, if A_inv_T is non-null, the transposed inverse A^-T
/// (cofactor matrix / det). Only the value of det is compared by the caller.
template <class Scalar>
KOKKOS_INLINE_FUNCTION Scalar determinant_and_inverse_transpose(const Scalar A[3][3],
                                                                Scalar A_inv_T[3][3]) {
  Scalar C[3][3];  // cofactors C_ij = (-1)^(i+j) minor_ij, so that A^-T = C / det A
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      C[i][j] = A[i1][j1] * A[i2][j2] - A[i1][j2] * A[i2][j1];
    }
  }
  const Scalar det = A[0][0] * C[0][0] + A[0][1] * C[0][1] + A[0][2] * C[0][2];
  if (A_inv_T)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) A_inv_T[i][j] = C[i][j] / det;
  return det;
}

/// \brief The full F of a plane-stress law: F_out = F with F_33 = sqrt(C_33) from S_33 = 0
/// (plane_stress_thickness_C33; C_2 = F_2^T F_2 of the in-plane F_2) and F_13 = F_23 = F_31 =
/// F_32 = 0; any other law: F_out = F.
/// \return collapsed if det F_2 <= 0 or no C_33 > 0 with S_33 = 0 exists (F_out then
/// undefined).
template <class Scalar>
KOKKOS_INLINE_FUNCTION MaterialStatus complete_deformation_gradient(HyperelasticLaw law,
                                                                    ElasticConstants c,
                                                                    const Scalar F[3][3],
                                                                    Scalar F_out[3][3]) {
  using std::sqrt;
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J) F_out[i][J] = F[i][J];
  if (!is_plane_stress(law)) return MaterialStatus::ok;
  if (!(F[0][0] * F[1][1] - F[0][1] * F[1][0] > 0.0)) return MaterialStatus::collapsed;
  Scalar C[3][3];
  for (int I = 0; I < 2; ++I)
    for (int K = 0; K < 2; ++K) C[I][K] = F[0][I] * F[0][K] + F[1][I] * F[1][K];
  Scalar C33;
  if (!plane_stress_thickness_C33(law == HyperelasticLaw::neo_hookean_plane_stress, c, C, C33))
    return MaterialStatus::collapsed;
  for (int k = 0; k < 2; ++k) F_out[k][2] = F_out[2][k] = 0.0;
  F_out[2][2] = sqrt(C33);
  return MaterialStatus::ok;
}

/// \brief The full C of a plane-stress law: C_out = C with C_33 from S_33 = 0
/// (plane_stress_thickness_C33) and C_13 = C_23 = 0; any other law: C_out = C.
/// \return collapsed if det C_2 <= 0 or no C_33 > 0 exists (C_out then undefined).
template <class Scalar>
KOKKOS_INLINE_FUNCTION MaterialStatus complete_right_cauchy_green(HyperelasticLaw law,
                                                                  ElasticConstants c,
                                                                  const Scalar C[3][3],
                                                                  Scalar C_out[3][3]) {
  for (int I = 0; I < 3; ++I)
    for (int K = 0; K < 3; ++K) C_out[I][K] = C[I][K];
  if (!is_plane_stress(law)) return MaterialStatus::ok;
  for (int k = 0; k < 2; ++k) C_out[k][2] = C_out[2][k] = 0.0;
  if (!plane_stress_thickness_C33(law == HyperelasticLaw::neo_hookean_plane_stress, c, C,
                                  C_out[2][2]))
    return MaterialStatus::collapsed;
  return MaterialStatus::ok;
}

/// Which tensor a plane-stress law completes: the deformation gradient or C = FᵀF.
enum class PlaneStressTensor { F, C };

/// \brief For a plane-stress law: A (F or C, only its in-plane part read) completed into A_full
/// (complete_deformation_gradient, complete_right_cauchy_green), A pointed at A_full and law
/// replaced by its three-dimensional form, so that the caller evaluates the 3D law. Any other
/// law: nothing changes. \return collapsed if the completion fails.
template <PlaneStressTensor T, class Scalar>
KOKKOS_INLINE_FUNCTION MaterialStatus use_three_dimensional_law(HyperelasticLaw& law,
                                                                ElasticConstants c,
                                                                const Scalar (*&A)[3],
                                                                Scalar A_full[3][3]) {
  if (!is_plane_stress(law)) return MaterialStatus::ok;
  const MaterialStatus s = T == PlaneStressTensor::F
                               ? complete_deformation_gradient(law, c, A, A_full)
                               : complete_right_cauchy_green(law, c, A, A_full);
  if (s != MaterialStatus::ok) return MaterialStatus::collapsed;
  A = A_full;
  law = three_dimensional_law(law);
  return MaterialStatus::ok;
}

/// \brief First Piola-Kirchhoff stress P(F) and strain energy density W(F) of `law` with Lamé
/// constants c (formulas in the file comment).
/// \pre F: the full 3 x 3 deformation gradient (plane strain: F33 = 1, F13 = F23 = F31 = F32 = 0;
/// plane stress: only the in-plane F is read).
/// \return collapsed if det F <= 0 (P and W then undefined); the check applies to both laws:
/// St. Venant-Kirchhoff has a finite energy there, but the configuration is not admissible.
template <class Scalar>
KOKKOS_INLINE_FUNCTION MaterialStatus first_piola_kirchhoff(HyperelasticLaw law, ElasticConstants c,
                                                            const Scalar F[3][3], Scalar P[3][3],
                                                            Scalar& W) {
  using std::log;
  Scalar F_plane_stress[3][3];
  if (use_three_dimensional_law<PlaneStressTensor::F>(law, c, F, F_plane_stress) !=
      MaterialStatus::ok)
    return MaterialStatus::collapsed;
  Scalar F_inv_T[3][3];
  const Scalar J = determinant_and_inverse_transpose(F, F_inv_T);
  if (!(J > 0.0)) return MaterialStatus::collapsed;
  if (law == HyperelasticLaw::neo_hookean) {
    const Scalar ln_J = log(J);
    Scalar I1 = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        I1 += F[i][j] * F[i][j];
        P[i][j] = c.mu * (F[i][j] - F_inv_T[i][j]) + c.lambda * ln_J * F_inv_T[i][j];
      }
    W = 0.5 * c.mu * (I1 - 3.0) - c.mu * ln_J + 0.5 * c.lambda * ln_J * ln_J;
    return MaterialStatus::ok;
  }
  // St. Venant-Kirchhoff.
  Scalar E[3][3];
  for (int I = 0; I < 3; ++I)
    for (int K = 0; K < 3; ++K) {
      E[I][K] = 0.0;
      for (int i = 0; i < 3; ++i) E[I][K] += F[i][I] * F[i][K];
      E[I][K] *= 0.5;
      if (I == K) E[I][K] -= 0.5;
    }
  const Scalar tr_E = E[0][0] + E[1][1] + E[2][2];
  Scalar S[3][3], E_E = 0.0;
  for (int I = 0; I < 3; ++I)
    for (int K = 0; K < 3; ++K) {
      E_E += E[I][K] * E[I][K];
      S[I][K] = 2.0 * c.mu * E[I][K];
      if (I == K) S[I][K] += c.lambda * tr_E;
    }
  for (int i = 0; i < 3; ++i)
    for (int K = 0; K < 3; ++K) {
      P[i][K] = 0.0;
      for (int I = 0; I < 3; ++I) P[i][K] += F[i][I] * S[I][K];
    }
  W = 0.5 * c.lambda * tr_E * tr_E + c.mu * E_E;
  return MaterialStatus::ok;
}

namespace detail {

/// W(C) of `law` given det C > 0 (the formulas of second_piola_kirchhoff).
template <class Scalar>
KOKKOS_INLINE_FUNCTION Scalar strain_energy_of_C(HyperelasticLaw law, ElasticConstants c,
                                                 const Scalar C[3][3], const Scalar& det_C) {
  using std::log;
  const Scalar tr_C = C[0][0] + C[1][1] + C[2][2];
  if (law == HyperelasticLaw::neo_hookean) {
    const Scalar ln_J = 0.5 * log(det_C);
    return 0.5 * c.mu * (tr_C - 3.0) - c.mu * ln_J + 0.5 * c.lambda * ln_J * ln_J;
  }
  const Scalar tr_E = 0.5 * (tr_C - 3.0);
  Scalar E_E = 0.0;
  for (int I = 0; I < 3; ++I)
    for (int K = 0; K < 3; ++K) {
      const Scalar E = 0.5 * (C[I][K] - (I == K ? 1.0 : 0.0));
      E_E += E * E;
    }
  return 0.5 * c.lambda * tr_E * tr_E + c.mu * E_E;
}

}  // namespace detail

/// \brief Second Piola-Kirchhoff stress S = 2 dW/dC and strain energy density W as functions of
/// the right Cauchy-Green tensor C = F^T F (the laws of the file comment in C):
///   Neo-Hookean: W = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2, J = sqrt(det C),
///                S = mu (I - C^-1) + lambda ln J C^-1             (Bonet & Wood eq. 6.28);
///   St. Venant-Kirchhoff: E = (C - I)/2, W = lambda/2 (tr E)^2 + mu E:E, S = lambda tr E I + 2 mu
///   E.
/// The energy-momentum element evaluates the law at C_{n+1/2} = (C_n + C_{n+1})/2, which is no
/// F^T F of a configuration (kernels/energy_momentum.hpp).
/// \pre C symmetric; 3 x 3 (plane strain: C33 = 1, C13 = C23 = 0; plane stress: only the
/// in-plane C is read).
/// \return collapsed if det C <= 0 (S and W then undefined).
template <class Scalar>
KOKKOS_INLINE_FUNCTION MaterialStatus second_piola_kirchhoff(HyperelasticLaw law,
                                                             ElasticConstants c,
                                                             const Scalar C[3][3], Scalar S[3][3],
                                                             Scalar& W) {
  using std::log;
  Scalar C_plane_stress[3][3];
  if (use_three_dimensional_law<PlaneStressTensor::C>(law, c, C, C_plane_stress) !=
      MaterialStatus::ok)
    return MaterialStatus::collapsed;
  const bool neo_hookean = law == HyperelasticLaw::neo_hookean;
  Scalar C_inv[3][3];  // C symmetric: C^-T = C^-1 (Neo-Hookean only)
  const Scalar det_C = determinant_and_inverse_transpose(C, neo_hookean ? C_inv : nullptr);
  if (!(det_C > 0.0)) return MaterialStatus::collapsed;
  W = detail::strain_energy_of_C(law, c, C, det_C);
  if (neo_hookean) {
    const Scalar ln_J = 0.5 * log(det_C);
    for (int I = 0; I < 3; ++I)
      for (int K = 0; K < 3; ++K)
        S[I][K] = (c.lambda * ln_J - c.mu) * C_inv[I][K] + (I == K ? c.mu : 0.0);
    return MaterialStatus::ok;
  }
  const Scalar tr_E = 0.5 * (C[0][0] + C[1][1] + C[2][2] - 3.0);
  for (int I = 0; I < 3; ++I)
    for (int K = 0; K < 3; ++K) {
      S[I][K] = c.mu * (C[I][K] - (I == K ? 1.0 : 0.0));  // 2 mu E
      if (I == K) S[I][K] += c.lambda * tr_E;
    }
  return MaterialStatus::ok;
}

/// \brief Strain energy density W(C) alone (second_piola_kirchhoff's W, without S).
/// \pre as second_piola_kirchhoff. \return collapsed if det C <= 0 (W then undefined).
template <class Scalar>
KOKKOS_INLINE_FUNCTION MaterialStatus strain_energy_of_C(HyperelasticLaw law, ElasticConstants c,
                                                         const Scalar C[3][3], Scalar& W) {
  Scalar C_plane_stress[3][3];
  if (use_three_dimensional_law<PlaneStressTensor::C>(law, c, C, C_plane_stress) !=
      MaterialStatus::ok)
    return MaterialStatus::collapsed;
  const Scalar det_C = determinant_and_inverse_transpose<Scalar>(C, nullptr);
  if (!(det_C > 0.0)) return MaterialStatus::collapsed;
  W = detail::strain_energy_of_C(law, c, C, det_C);
  return MaterialStatus::ok;
}

/// \brief Cauchy stress sigma = P F^T / J (Bonet & Wood eq. 5.42) from P and F.
/// \pre det F > 0.
template <class Scalar>
KOKKOS_INLINE_FUNCTION void cauchy_from_first_piola(const Scalar F[3][3], const Scalar P[3][3],
                                                    Scalar sigma[3][3]) {
  const Scalar J = determinant_and_inverse_transpose<Scalar>(F, nullptr);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      sigma[i][j] = 0.0;
      for (int K = 0; K < 3; ++K) sigma[i][j] += P[i][K] * F[j][K];
      sigma[i][j] /= J;
    }
}

}  // namespace grout
