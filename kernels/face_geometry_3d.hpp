#pragma once
// Geometry of a TRI3 / QUAD4 surface face in 3D: shape functions, position, covariant
// tangents, area element, centre normal, and the inverse map along a fixed direction.
//
// Reference elements (Exodus/Kratos conventions):
//   TRI3  N = (1 - ξ - η, ξ, η),           (ξ, η) ∈ {ξ, η ≥ 0, ξ + η ≤ 1}
//   QUAD4 N_i = ¼ (1 + ξ ξ_i)(1 + η η_i),  (ξ_i, η_i) = (-1,-1), (1,-1), (1,1), (-1,1)
// x(ξ) = Σ N_i(ξ) x_i, g_a = ∂x/∂ξ_a, dA = |g_1 × g_2| dξ dη, unit normal n = g_1 × g_2 / |.|
// (right-hand rule on the node order).
//
// Every function is templated on the scalar (double or Sacado::Fad::SFad): comparisons act on
// values only, and no branch depends on a derivative part.

#include <cmath>
#include <type_traits>

#include "kernels/kernel_macros.hpp"
#include "kernels/mortar_types.hpp"
#include "kernels/scalar_value.hpp"

namespace grout {

constexpr int face_inverse_map_max_iterations = 25;   ///< Newton cap (QUAD4)
constexpr double face_inverse_map_tolerance = 1e-14;  ///< on the parameter update |Δξ|

namespace detail3d {

template <class Scalar>
GROUT_INLINE_FUNCTION Scalar dot(const Scalar a[3], const Scalar b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <class Scalar>
GROUT_INLINE_FUNCTION void cross(const Scalar a[3], const Scalar b[3], Scalar c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

}  // namespace detail3d

/// \brief Parametric centre of the reference face: TRI3 (1/3, 1/3), QUAD4 (0, 0).
template <class Scalar>
GROUT_INLINE_FUNCTION void face_reference_centre(int n, Scalar xi[2]) {
  xi[0] = n == 3 ? Scalar(1.0 / 3.0) : Scalar(0.0);
  xi[1] = xi[0];
}

/// \brief Shape functions N_i(ξ, η) of a TRI3 (n = 3) or QUAD4 (n = 4) face.
template <class Scalar>
GROUT_INLINE_FUNCTION void face_shape_functions(int n, const Scalar xi[2],
                                                Scalar N[max_face_nodes]) {
  if (n == 3) {
    N[0] = 1.0 - xi[0] - xi[1];
    N[1] = xi[0];
    N[2] = xi[1];
    N[3] = 0.0;
  } else {
    N[0] = 0.25 * (1.0 - xi[0]) * (1.0 - xi[1]);
    N[1] = 0.25 * (1.0 + xi[0]) * (1.0 - xi[1]);
    N[2] = 0.25 * (1.0 + xi[0]) * (1.0 + xi[1]);
    N[3] = 0.25 * (1.0 - xi[0]) * (1.0 + xi[1]);
  }
}

/// \brief Shape-function derivatives dN[i][a] = ∂N_i/∂ξ_a.
template <class Scalar>
GROUT_INLINE_FUNCTION void face_shape_derivatives(int n, const Scalar xi[2],
                                                  Scalar dN[max_face_nodes][2]) {
  if (n == 3) {
    dN[0][0] = -1.0, dN[0][1] = -1.0;
    dN[1][0] = 1.0, dN[1][1] = 0.0;
    dN[2][0] = 0.0, dN[2][1] = 1.0;
    dN[3][0] = 0.0, dN[3][1] = 0.0;
  } else {
    dN[0][0] = -0.25 * (1.0 - xi[1]), dN[0][1] = -0.25 * (1.0 - xi[0]);
    dN[1][0] = 0.25 * (1.0 - xi[1]), dN[1][1] = -0.25 * (1.0 + xi[0]);
    dN[2][0] = 0.25 * (1.0 + xi[1]), dN[2][1] = 0.25 * (1.0 + xi[0]);
    dN[3][0] = -0.25 * (1.0 + xi[1]), dN[3][1] = 0.25 * (1.0 - xi[0]);
  }
}

/// \brief Position x(ξ) = Σ_i N_i(ξ) x_i.
template <class Scalar>
GROUT_INLINE_FUNCTION void face_position(int n, const Scalar x[max_face_nodes][3],
                                         const Scalar xi[2], Scalar p[3]) {
  Scalar N[max_face_nodes];
  face_shape_functions(n, xi, N);
  for (int d = 0; d < 3; ++d) {
    p[d] = 0.0;
    for (int i = 0; i < n; ++i) p[d] += N[i] * x[i][d];
  }
}

/// \brief Covariant tangents g_a = Σ_i ∂N_i/∂ξ_a x_i.
template <class Scalar>
GROUT_INLINE_FUNCTION void face_tangents(int n, const Scalar x[max_face_nodes][3],
                                         const Scalar xi[2], Scalar g[2][3]) {
  Scalar dN[max_face_nodes][2];
  face_shape_derivatives(n, xi, dN);
  for (int a = 0; a < 2; ++a)
    for (int d = 0; d < 3; ++d) {
      g[a][d] = 0.0;
      for (int i = 0; i < n; ++i) g[a][d] += dN[i][a] * x[i][d];
    }
}

/// \brief Area element j(ξ) = |g_1 × g_2| (dA = j dξ dη).
template <class Scalar>
GROUT_INLINE_FUNCTION Scalar face_area_element(int n, const Scalar x[max_face_nodes][3],
                                               const Scalar xi[2]) {
  using std::sqrt;
  Scalar g[2][3], c[3];
  face_tangents(n, x, xi, g);
  detail3d::cross(g[0], g[1], c);
  return sqrt(detail3d::dot(c, c));
}

/// \brief Centre x₀ = x(ξ_c) and unit centre normal n₀ = g_1 × g_2 / |g_1 × g_2| at ξ_c
/// (the auxiliary-plane data of Popp et al. 2010, sec. 3.2).
/// \return degenerate if |g_1 × g_2| ≤ 1e-14 (edge length)², else ok.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus face_centre_normal(int n, const Scalar x[max_face_nodes][3],
                                                      Scalar centre[3], Scalar normal[3]) {
  using std::sqrt;
  Scalar xi[2], g[2][3];
  face_reference_centre(n, xi);
  face_position(n, x, xi, centre);
  face_tangents(n, x, xi, g);
  detail3d::cross(g[0], g[1], normal);
  const Scalar len2 = detail3d::dot(normal, normal);
  const Scalar scale2 = detail3d::dot(g[0], g[0]) + detail3d::dot(g[1], g[1]);
  if (!(len2 > 1e-28 * scale2 * scale2) || !(scale2 > 0.0)) return MortarStatus::degenerate;
  const Scalar len = sqrt(len2);
  for (int d = 0; d < 3; ++d) normal[d] /= len;
  return MortarStatus::ok;
}

/// \brief Orthonormal in-plane basis (t₁, t₂) of the plane with unit normal n₀:
/// t₁ = (e − (e·n₀) n₀)/|.|, t₂ = n₀ × t₁, with e a given in-plane-ish direction
/// (e.g. the first edge of the face). Right-handed: t₁ × t₂ = n₀.
template <class Scalar>
GROUT_INLINE_FUNCTION void plane_basis(const Scalar normal[3], const Scalar e[3], Scalar t1[3],
                                       Scalar t2[3]) {
  using std::sqrt;
  const Scalar en = detail3d::dot(e, normal);
  for (int d = 0; d < 3; ++d) t1[d] = e[d] - en * normal[d];
  const Scalar len = sqrt(detail3d::dot(t1, t1));
  for (int d = 0; d < 3; ++d) t1[d] /= len;
  detail3d::cross(normal, t1, t2);
}

namespace detail3d {
/// One Newton step ξ ← ξ − J⁻¹ (Σ N_i(ξ) p_i − y) of face_inverse_map_2d; Δξ in d.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus inverse_map_step(int n, const Scalar p[max_face_nodes][2],
                                                    const Scalar y[2], Scalar xi[2], Scalar d[2]) {
  using std::abs;
  Scalar N[max_face_nodes], dN[max_face_nodes][2], r[2] = {-y[0], -y[1]};
  Scalar J[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
  face_shape_functions(n, xi, N);
  face_shape_derivatives(n, xi, dN);
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < 2; ++a) {
      r[a] += N[i] * p[i][a];
      for (int b = 0; b < 2; ++b) J[a][b] += p[i][a] * dN[i][b];
    }
  const Scalar det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
  const Scalar jscale = abs(J[0][0]) + abs(J[1][1]) + abs(J[0][1]) + abs(J[1][0]);
  if (!(abs(det) > 1e-14 * jscale * jscale)) return MortarStatus::projection_failed;
  d[0] = (J[1][1] * r[0] - J[0][1] * r[1]) / det;
  d[1] = (J[0][0] * r[1] - J[1][0] * r[0]) / det;
  xi[0] -= d[0];
  xi[1] -= d[1];
  return MortarStatus::ok;
}
}  // namespace detail3d

/// \brief Inverse of the planar map y(ξ) = Σ_i N_i(ξ) p_i (p_i: nodes in 2D plane
/// coordinates): Newton from the centre, J_ab = Σ_i p_i,a ∂N_i/∂ξ_b, ξ ← ξ − J⁻¹(y(ξ) − y).
/// TRI3 is affine: one step is exact, values and derivatives alike. QUAD4: iterate until
/// |Δξ| < face_inverse_map_tolerance. With a derivative-carrying scalar (Sacado Fad) the QUAD4
/// iterations run on the values only, and one final Newton step is taken in the scalar from the
/// converged ξ* (held constant): its derivative is −J⁻¹ ∂r/∂(p, y) + O(|r(ξ*)|), the
/// implicit-function derivative of the root (exact to the tolerance, like iterating in Fad,
/// for a fraction of the cost).
/// \return projection_failed (singular J or no convergence within the cap), else ok.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus face_inverse_map_2d(int n, const Scalar p[max_face_nodes][2],
                                                       const Scalar y[2], Scalar xi[2]) {
  using std::abs;
  if constexpr (!std::is_same<Scalar, double>::value) {
    if (n == 4) {  // converge on the values, then one step with derivatives (see above)
      double pv[max_face_nodes][2], yv[2] = {value_of(y[0]), value_of(y[1])};
      double xv[2];
      for (int i = 0; i < n; ++i)
        for (int a = 0; a < 2; ++a) pv[i][a] = value_of(p[i][a]);
      const MortarStatus s = face_inverse_map_2d(n, pv, yv, xv);
      if (s != MortarStatus::ok) return s;
      xi[0] = xv[0];
      xi[1] = xv[1];
      Scalar d[2];
      return detail3d::inverse_map_step(n, p, y, xi, d);
    }
  }
  face_reference_centre(n, xi);
  const int max_it = n == 3 ? 1 : face_inverse_map_max_iterations;
  for (int it = 0; it < max_it; ++it) {
    Scalar d[2];
    if (detail3d::inverse_map_step(n, p, y, xi, d) != MortarStatus::ok)
      return MortarStatus::projection_failed;
    if (n == 3) return MortarStatus::ok;
    if (abs(d[0]) + abs(d[1]) < double(face_inverse_map_tolerance)) return MortarStatus::ok;
    if (!(abs(xi[0]) + abs(xi[1]) < 1e6)) return MortarStatus::projection_failed;  // diverged
  }
  return MortarStatus::projection_failed;
}

/// \brief Parameters ξ of the point of the face hit by the line through `point` with
/// direction `dir` (unit): x(ξ) − point ∥ dir. Nodes and point are projected on the plane
/// ⊥ dir and face_inverse_map_2d solves there.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus face_inverse_map_along(int n, const Scalar x[max_face_nodes][3],
                                                          const Scalar point[3],
                                                          const Scalar dir[3], Scalar xi[2]) {
  Scalar e[3], t1[3], t2[3], p[max_face_nodes][2], y[2] = {0.0, 0.0};
  for (int d = 0; d < 3; ++d) e[d] = x[1][d] - x[0][d];
  plane_basis(dir, e, t1, t2);
  for (int i = 0; i < n; ++i) {
    Scalar v[3];
    for (int d = 0; d < 3; ++d) v[d] = x[i][d] - point[d];
    p[i][0] = detail3d::dot(v, t1);
    p[i][1] = detail3d::dot(v, t2);
  }
  return face_inverse_map_2d(n, p, y, xi);
}

/// \brief True if ξ lies in the reference face, up to `tol` (parameter units).
template <class Scalar>
GROUT_INLINE_FUNCTION bool face_contains(int n, const Scalar xi[2], double tol = 1e-12) {
  if (n == 3) return xi[0] >= -tol && xi[1] >= -tol && xi[0] + xi[1] <= 1.0 + tol;
  return xi[0] >= -1.0 - tol && xi[0] <= 1.0 + tol && xi[1] >= -1.0 - tol && xi[1] <= 1.0 + tol;
}

}  // namespace grout
