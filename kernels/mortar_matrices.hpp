#pragma once
// Pair kernels with the full slave matrix D, for any multiplier basis Φ_j = Σ_k A_jk N¹_k
// (multiplier_basis.hpp; docs/design.md §2; Popp et al. 2010, eqs. 9-10; Puso & Laursen 2004):
//
//   D_jk = ∫ Φ_j N¹_k dA,   M_jl = ∫ Φ_j (N²_l ∘ χ) dA     over the pair's overlap.
//
// The integration points are those of the dual kernels, from the same functions: 2D
// mortar_integration_points_2d / for_each_collocation_point_2d (mortar_2d.hpp), 3D
// for_each_mortar_point_3d / for_each_collocation_point_3d (mortar_3d.hpp); only the
// accumulation differs (Φ_j from A instead of the dual closed forms, and D_jk per slave node k
// instead of its row sum). The rules are as exact as for the dual basis: with A = I the
// integrands N¹_j N¹_k and N¹_j N²_l have the degrees of Φ_j N¹_k and Φ_j N²_l.
// Every output is fully written (zeros unless ok).

#include "kernels/face_geometry_3d.hpp"
#include "kernels/kernel_macros.hpp"
#include "kernels/mortar_2d.hpp"
#include "kernels/mortar_3d.hpp"
#include "kernels/mortar_types.hpp"
#include "kernels/multiplier_basis.hpp"

namespace grout {

/// Zeroes a MortarPairMatrices and sets its node counts.
template <class Scalar>
GROUT_INLINE_FUNCTION void reset_pair_matrices(int n_slave, int n_master,
                                               MortarPairMatrices<Scalar>& out) {
  out.n_slave = n_slave;
  out.n_master = n_master;
  out.overlap = 0.0;
  for (int j = 0; j < max_face_nodes; ++j)
    for (int k = 0; k < max_face_nodes; ++k) out.D[j][k] = out.M[j][k] = 0.0;
}

/// \brief Adds one point with slave shape values Ns, master shape values Nm, weight w:
/// D_jk += w Φ_j Ns_k, M_jl += w Φ_j Nm_l, Φ_j = Σ_k A_jk Ns_k.
template <class Scalar>
GROUT_INLINE_FUNCTION void add_mortar_matrices_point(const Scalar A[max_face_nodes][max_face_nodes],
                                                     const Scalar Ns[max_face_nodes],
                                                     const Scalar Nm[max_face_nodes],
                                                     const Scalar& w,
                                                     MortarPairMatrices<Scalar>& out) {
  Scalar Phi[max_face_nodes];
  multiplier_shape_functions(out.n_slave, A, Ns, Phi);
  out.overlap += w;
  for (int j = 0; j < out.n_slave; ++j) {
    const Scalar wphi = w * Phi[j];
    for (int k = 0; k < out.n_slave; ++k) out.D[j][k] += wphi * Ns[k];
    for (int l = 0; l < out.n_master; ++l) out.M[j][l] += wphi * Nm[l];
  }
}

namespace detail {

/// Point functor of the 2D kernels: LINE2 shape values at (ξ, η).
template <class Scalar>
struct AddMatricesPoint2D {
  const Scalar (*A)[max_face_nodes];
  MortarPairMatrices<Scalar>* out;
  GROUT_INLINE_FUNCTION void operator()(const Scalar& xi, const Scalar& eta,
                                        const Scalar& w) const {
    Scalar Ns[max_face_nodes] = {}, Nm[max_face_nodes] = {};
    line2_shape(xi, Ns);
    line2_shape(eta, Nm);
    add_mortar_matrices_point(A, Ns, Nm, w, *out);
  }
};

/// Point functor of the 3D kernels: TRI3/QUAD4 shape values at (ξ¹, ξ²).
template <class Scalar>
struct AddMatricesPoint3D {
  const Scalar (*A)[max_face_nodes];
  MortarPairMatrices<Scalar>* out;
  GROUT_INLINE_FUNCTION void operator()(const Scalar xi_s[2], const Scalar xi_m[2],
                                        const Scalar& w) const {
    Scalar Ns[max_face_nodes], Nm[max_face_nodes];
    face_shape_functions(out->n_slave, xi_s, Ns);
    face_shape_functions(out->n_master, xi_m, Nm);
    add_mortar_matrices_point(A, Ns, Nm, w, *out);
  }
};

}  // namespace detail

/// \brief Exact (segment-based) D_jk, M_jl of a LINE2/LINE2 pair with an n_gauss-point rule on
/// the overlap (the points of mortar_integration_points_2d), basis coefficients A.
/// \return ok, no_overlap, degenerate, projection_failed or capacity_exceeded (out zero then).
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus integrate_mortar_matrices_2d(
    const MortarSlave2D<Scalar>& slave, const Scalar A[max_face_nodes][max_face_nodes],
    const Scalar xm[2][2], int n_gauss, MortarPairMatrices<Scalar>& out) {
  reset_pair_matrices(2, 2, out);
  Scalar xi[max_gauss_line_points], eta[max_gauss_line_points], w[max_gauss_line_points];
  const MortarStatus s = mortar_integration_points_2d(slave, xm, n_gauss, xi, eta, w);
  if (s != MortarStatus::ok) return s;
  detail::AddMatricesPoint2D<Scalar> add{A, &out};
  for (int g = 0; g < n_gauss; ++g) add(xi[g], eta[g], w[g]);
  return MortarStatus::ok;
}

/// \brief Collocation variant of integrate_mortar_matrices_2d (for_each_collocation_point_2d).
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus integrate_mortar_matrices_2d_collocation(
    const Scalar xs[2][2], const Scalar ns[2][2], const Scalar A[max_face_nodes][max_face_nodes],
    const Scalar xm[2][2], int n_points, MortarPairMatrices<Scalar>& out) {
  reset_pair_matrices(2, 2, out);
  detail::AddMatricesPoint2D<Scalar> add{A, &out};
  const MortarStatus s = for_each_collocation_point_2d(xs, ns, xm, n_points, add);
  if (s != MortarStatus::ok) reset_pair_matrices(2, 2, out);
  return s;
}

/// \brief Exact (segment-based) D_jk, M_jl of a TRI3/QUAD4 pair (the points of
/// for_each_mortar_point_3d), basis coefficients A. \pre n_slave, n_master ∈ {3, 4}.
template <int Degree = mortar_3d_triangle_degree, class Scalar>
GROUT_INLINE_FUNCTION MortarStatus integrate_mortar_matrices_3d(
    int n_slave, const Scalar xs[max_face_nodes][3], const Scalar A[max_face_nodes][max_face_nodes],
    int n_master, const Scalar xm[max_face_nodes][3], MortarPairMatrices<Scalar>& out) {
  reset_pair_matrices(n_slave, n_master, out);
  detail::AddMatricesPoint3D<Scalar> add{A, &out};
  const MortarStatus s = for_each_mortar_point_3d<Degree>(n_slave, xs, n_master, xm, add);
  if (s != MortarStatus::ok) reset_pair_matrices(n_slave, n_master, out);
  return s;
}

/// \brief Collocation variant of integrate_mortar_matrices_3d with k points per direction
/// (for_each_collocation_point_3d). \return no_overlap if no point hits the master.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus integrate_mortar_matrices_3d_collocation(
    int n_slave, const Scalar xs[max_face_nodes][3], const Scalar A[max_face_nodes][max_face_nodes],
    int n_master, const Scalar xm[max_face_nodes][3], int k, MortarPairMatrices<Scalar>& out) {
  reset_pair_matrices(n_slave, n_master, out);
  if ((n_slave != 3 && n_slave != 4) || (n_master != 3 && n_master != 4) || k < 1)
    return MortarStatus::degenerate;
  detail::AddMatricesPoint3D<Scalar> add{A, &out};
  if (for_each_collocation_point_3d(n_slave, xs, n_master, xm, k, add) != MortarStatus::ok) {
    reset_pair_matrices(n_slave, n_master, out);
    return MortarStatus::degenerate;
  }
  return out.overlap > 0.0 ? MortarStatus::ok : MortarStatus::no_overlap;
}

}  // namespace grout
