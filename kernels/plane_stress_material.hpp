#pragma once
// Plane stress under finite strain: the thickness stretch of a thin sheet at one material
// point. With the in-plane right Cauchy-Green tensor C_2 (C_IJ, I, J in {1, 2}) given and
// C_13 = C_23 = 0, the out-of-plane C_33 = F_33^2 is the one that makes the 3D law's
// S_33 = 0 (then P_33 = F_33 S_33 = 0 and sigma_33 = 0). The in-plane stress is the 3D law's
// at C = C_2 + C_33 e3 e3, and the sheet's energy density W_ps(C_2) = W(C_2, C_33(C_2)) has
// 2 dW_ps/dC_2 = S_2 there, since dW/dC_33 = S_33 / 2 = 0 (so W_ps is a hyperelastic law of
// C_2, and the energy-momentum element keeps its properties with it).
//
// Compressible Neo-Hookean (kernels/hyperelastic_material.hpp), S = mu (I - C^-1) + lambda ln J
// C^-1 with J^2 = det C = det C_2 C_33:
//   S_33 = 0  <=>  h(y) = mu (e^y - 1) + lambda/2 (ln det C_2 + y) = 0,   y = ln C_33.
// h is convex (h'' = mu e^y > 0) and, for lambda >= 0 (nu >= 0), increasing (h' = mu e^y +
// lambda/2 > 0), so the root is unique. Newton starts at the root of the linearisation,
// y_0 = -lambda ln det C_2 / (2 mu + lambda), where h(y_0) = mu (e^y0 - 1 - y_0) >= 0: from the
// right of the root of a convex increasing function the iterates fall monotonically to it, with
// no overshoot. For nu < 0 (lambda < 0) h has a minimum, and the physical root (the larger one,
// y = 0 at C_2 = I) exists only down to some in-plane compression (nu = -0.5, lambda = -mu/2:
// min h = mu (ln 4 - 3 - ln det C_2) / 4 > 0 for det C_2 < 0.199); Newton then meets h' <= 0
// or does not converge, and the point is reported as collapsed.
// St. Venant-Kirchhoff, S = lambda tr E I + 2 mu E, E = (C - I)/2, is linear in E_33:
//   E_33 = -lambda (E_11 + E_22) / (lambda + 2 mu),   C_33 = 1 + 2 E_33   (closed form).
// Small strain: both reduce to the plane-stress Hooke law, lambda* = 2 lambda mu / (lambda +
// 2 mu) = E nu / (1 - nu^2) (kernels/linear_elastic.hpp, elastic_constants).
//
// Templated on the scalar: with a Sacado Fad the Newton iterates carry derivatives, and one
// more step is taken after convergence, at a point where h = 0 to round-off, so that the
// derivative of C_33 is the implicit one, dC_33/dC_2 = -(dh/dC_2) / (dh/dC_33), to round-off
// (the derivative of a Newton step x - h/h' is -h_p/h' + h (...) / h'^2). The element's AD
// tangent is then the consistent plane-stress tangent.

#include <Kokkos_Core.hpp>
#include <cmath>

#include "kernels/linear_elastic.hpp"

namespace grout {

/// Newton iterations of plane_stress_thickness_C33 (it converges in fewer than 10 for
/// det C_2 in [1e-3, 1e3]; the iterates fall monotonically, see the file comment).
constexpr int plane_stress_max_newton = 50;

/// \brief C_33 of a plane-stress point: S_33(C) = 0 for the Neo-Hookean law (neo_hookean =
/// true) or St. Venant-Kirchhoff (false) with Lamé constants c (formulas in the file comment).
/// Reads C[0][0], C[0][1], C[1][0], C[1][1] only.
/// \pre c: the 3D Lamé constants (elastic_constants with plane_stress = false).
/// \return false if det C_2 <= 0, if C_33 <= 0 (St. Venant-Kirchhoff under a large in-plane
/// stretch) or if Newton has not converged (C33 then undefined).
template <class Scalar>
KOKKOS_INLINE_FUNCTION bool plane_stress_thickness_C33(bool neo_hookean, ElasticConstants c,
                                                       const Scalar C[3][3], Scalar& C33) {
  using std::exp;
  using std::log;
  const Scalar det_C2 = C[0][0] * C[1][1] - C[0][1] * C[1][0];
  if (!(det_C2 > 0.0)) return false;
  if (!neo_hookean) {
    C33 = 1.0 - c.lambda * (C[0][0] + C[1][1] - 2.0) / (c.lambda + 2.0 * c.mu);
    return C33 > 0.0;
  }
  const Scalar ln_det = log(det_C2);
  Scalar y = -c.lambda * ln_det / (2.0 * c.mu + c.lambda);
  // k < max: Newton steps y -= h / h' until |step| < 1e-12; then the extra step at h = 0 (file
  // comment).
  bool converged = false;
  for (int k = 0; k <= plane_stress_max_newton; ++k) {
    const Scalar e = exp(y);
    const Scalar slope = c.mu * e + 0.5 * c.lambda;
    if (!(slope > 0.0)) return false;  // only for lambda < 0 (file comment)
    const Scalar step = (c.mu * (e - 1.0) + 0.5 * c.lambda * (ln_det + y)) / slope;
    y -= step;
    if (converged) break;
    converged = step * step < 1e-24;
  }
  if (!converged) return false;
  C33 = exp(y);
  return true;
}

}  // namespace grout
