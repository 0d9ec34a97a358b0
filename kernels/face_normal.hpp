#pragma once
// Unit element normal and tangent basis of one contact face (LINE2 in 2D, TRI3/QUAD4 in 3D),
// from its current coordinates:
//
//   element normal   LINE2: n_e = (dy, −dx) / |x₂ − x₁|           (topology.hpp convention)
//                    TRI3:  n_e = (x₂ − x₁) × (x₃ − x₁) / |…|
//                    QUAD4: n_e = (x₃ − x₁) × (x₄ − x₂) / |…|      (normal at the centre)
//   tangents         2D: τ = e_z × n = (−n_y, n_x);  3D: τ₁ ⊥ n from the coordinate axis least
//                    aligned with n, τ₂ = n × τ₁ (right-handed (τ₁, τ₂, n)).
// Templated on the scalar (double or Sacado::Fad::SFad). The averaged nodal normals over a
// surface (the launches) are in surface_normals.hpp.

#include <cmath>

#include "kernels/kernel_macros.hpp"
#include "kernels/mortar_types.hpp"

namespace grout {

/// \brief n ← n/|n| for a Dim-vector. \return false if |n| = 0 (n left unchanged).
template <int Dim, class Scalar>
GROUT_INLINE_FUNCTION bool normalize_vector(Scalar n[Dim]) {
  using std::sqrt;
  Scalar nn = n[0] * n[0];
  for (int d = 1; d < Dim; ++d) nn += n[d] * n[d];
  if (!(nn > 0.0)) return false;
  const Scalar len = sqrt(nn);
  for (int d = 0; d < Dim; ++d) n[d] /= len;
  return true;
}

/// \brief Unit normal of a LINE2 face x₁→x₂: n = (dy, −dx)/L. \pre x in any length unit.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus line2_normal(const Scalar x[2][2], Scalar n[2]) {
  n[0] = x[1][1] - x[0][1];
  n[1] = x[0][0] - x[1][0];
  return normalize_vector<2>(n) ? MortarStatus::ok : MortarStatus::degenerate;
}

template <class Scalar>
GROUT_INLINE_FUNCTION void cross_product(const Scalar a[3], const Scalar b[3], Scalar c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

/// \brief Unit normal of a TRI3 face: (x₂ − x₁) × (x₃ − x₁) normalised.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus tri3_normal(const Scalar x[][3], Scalar n[3]) {
  Scalar a[3], b[3];
  for (int d = 0; d < 3; ++d) {
    a[d] = x[1][d] - x[0][d];
    b[d] = x[2][d] - x[0][d];
  }
  cross_product(a, b, n);
  return normalize_vector<3>(n) ? MortarStatus::ok : MortarStatus::degenerate;
}

/// \brief Unit normal at the centre of a bilinear QUAD4 face: (x₃ − x₁) × (x₄ − x₂) normalised
/// (∂x/∂ξ × ∂x/∂η at ξ = η = 0 is a quarter of this product).
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus quad4_normal(const Scalar x[][3], Scalar n[3]) {
  Scalar a[3], b[3];
  for (int d = 0; d < 3; ++d) {
    a[d] = x[2][d] - x[0][d];
    b[d] = x[3][d] - x[1][d];
  }
  cross_product(a, b, n);
  return normalize_vector<3>(n) ? MortarStatus::ok : MortarStatus::degenerate;
}

/// \brief Unit element normal of a face with `n_nodes` nodes in dimension `dim`
/// (2: LINE2 using x[k][0..1]; 3: TRI3 or QUAD4). Unused components of n are set to zero.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus face_normal(int dim, int n_nodes,
                                               const Scalar x[max_face_nodes][3], Scalar n[3]) {
  n[0] = n[1] = n[2] = 0.0;
  if (dim == 2 && n_nodes == 2) {
    const Scalar x2[2][2] = {{x[0][0], x[0][1]}, {x[1][0], x[1][1]}};
    return line2_normal(x2, n);
  }
  if (dim == 3 && n_nodes == 3) return tri3_normal(x, n);
  if (dim == 3 && n_nodes == 4) return quad4_normal(x, n);
  return MortarStatus::degenerate;
}

/// \brief 2D tangent τ = e_z × n = (−n_y, n_x): for a LINE2 element normal it points x₁→x₂.
template <class Scalar>
GROUT_INLINE_FUNCTION void tangent_2d(const Scalar n[2], Scalar t[2]) {
  t[0] = -n[1];
  t[1] = n[0];
}

/// \brief 3D tangents: τ₁ = normalised projection of the axis e_a with the smallest |n_a| onto
/// the plane ⊥ n, τ₂ = n × τ₁. \pre |n| = 1.
template <class Scalar>
GROUT_INLINE_FUNCTION void tangents_3d(const Scalar n[3], Scalar t1[3], Scalar t2[3]) {
  using std::abs;
  int a = 0;
  if (abs(n[1]) < abs(n[a])) a = 1;
  if (abs(n[2]) < abs(n[a])) a = 2;
  for (int d = 0; d < 3; ++d) t1[d] = (d == a ? 1.0 : 0.0) - n[a] * n[d];
  normalize_vector<3>(t1);
  cross_product(n, t1, t2);
}

}  // namespace grout
