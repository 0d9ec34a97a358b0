#pragma once
// The frame of each slave node (unit averaged normal and tangents) with its exact derivatives
// with respect to the coordinates of the faces around the node:
//
//   N_j = Σ_{f∋j} n_f,   n_j = N_j / |N_j|,   τ_j = tangent_2d(n_j) | tangents_3d(n_j)
//   ∂n_j/∂x_{f,a} = (∂n_j/∂N_j) (∂n_f/∂x_{f,a}),  likewise τ_j      (chain rule over N_j)
//
// (docs/design.md, "Mortar terms"; Popp et al. 2010, eq. 4: the unweighted average of the unit
// element normals n_f, face_normal.hpp). Both factors are Sacado forward AD of the same
// functions that compute the values: ∂n_f/∂x over the face's own ≤ 4 nodes (SFad<double, 4·Dim>),
// ∂n_j/∂N_j over Dim components (SFad<double, Dim>), so no derivative is written by hand and no
// scalar carries a variable-length patch. A node whose face normals cancel (N_j = 0) keeps
// n_j = N_j, as normalize_vector does. The launch over the slave nodes is in slave_frames.hpp.

#include "kernels/face_normal.hpp"
#include "kernels/kernel_macros.hpp"
#include "kernels/mortar_types.hpp"
#include "kernels/sacado_fad.hpp"

namespace grout {

/// Layout of one node's frame: rows 0..Dim−1 are n_d, then τ_{k,d} at Dim + k·Dim + d (k < Dim−1):
/// Dim·Dim rows. A derivative block has one column per face coordinate x_{a,c}: a·Dim + c
/// (a < max_face_nodes).
template <int Dim>
struct SlaveFrameLayout {
  static constexpr int rows = Dim * Dim;
  static constexpr int columns = max_face_nodes * Dim;
  GROUT_INLINE_FUNCTION static constexpr int normal(int d) { return d; }
  GROUT_INLINE_FUNCTION static constexpr int tangent(int k, int d) { return Dim + k * Dim + d; }
};

/// \brief Unit normal n_f of a face (face_normal) and ∂n_f/∂x_{a,c} (columns a·Dim + c).
/// \return face_normal's status (degenerate: zero length or area).
template <int Dim>
GROUT_INLINE_FUNCTION MortarStatus
face_normal_gradient(int n_nodes, const double x[max_face_nodes][3], double n[3],
                     double dn[3][SlaveFrameLayout<Dim>::columns]) {
  constexpr int vars = SlaveFrameLayout<Dim>::columns;
  using Fad = Sacado::Fad::SFad<double, vars>;
  Fad xf[max_face_nodes][3], nf[3];
  for (int a = 0; a < max_face_nodes; ++a)
    for (int c = 0; c < 3; ++c)
      xf[a][c] = a < n_nodes && c < Dim ? Fad(vars, a * Dim + c, x[a][c]) : Fad(x[a][c]);
  const MortarStatus status = face_normal(Dim, n_nodes, xf, nf);
  for (int d = 0; d < 3; ++d) {
    n[d] = nf[d].val();
    for (int v = 0; v < vars; ++v) dn[d][v] = nf[d].fastAccessDx(v);
  }
  return status;
}

/// \brief The frame (n_j, τ_j) from the summed normal N_j, and J = ∂frame/∂N_j (rows of
/// SlaveFrameLayout<Dim>, Dim columns).
template <int Dim>
GROUT_INLINE_FUNCTION void frame_of_normal_sum(const double N[3],
                                               double frame[SlaveFrameLayout<Dim>::rows],
                                               double J[SlaveFrameLayout<Dim>::rows][Dim]) {
  using L = SlaveFrameLayout<Dim>;
  using Fad = Sacado::Fad::SFad<double, Dim>;
  Fad n[3], t[2][3];
  for (int d = 0; d < 3; ++d) n[d] = d < Dim ? Fad(Dim, d, N[d]) : Fad(0.0);
  normalize_vector<Dim>(n);
  if constexpr (Dim == 2) {
    tangent_2d(n, t[0]);
  } else {
    tangents_3d(n, t[0], t[1]);
  }
  for (int d = 0; d < Dim; ++d) {
    frame[L::normal(d)] = n[d].val();
    for (int e = 0; e < Dim; ++e) J[L::normal(d)][e] = n[d].fastAccessDx(e);
    for (int k = 0; k < Dim - 1; ++k) {
      frame[L::tangent(k, d)] = t[k][d].val();
      for (int e = 0; e < Dim; ++e) J[L::tangent(k, d)][e] = t[k][d].fastAccessDx(e);
    }
  }
}

/// \brief The chain rule of one face around a node: out[r][v] = Σ_e J[r][e] dn_f[e][v], the
/// derivative of frame row r with respect to the face coordinate v, from J = ∂frame/∂N
/// (frame_of_normal_sum) and dn_f = ∂n_f/∂x (face_normal_gradient).
template <int Dim>
GROUT_INLINE_FUNCTION void chain_frame_gradient(
    const double J[SlaveFrameLayout<Dim>::rows][Dim],
    const double dn_f[3][SlaveFrameLayout<Dim>::columns],
    double out[SlaveFrameLayout<Dim>::rows][SlaveFrameLayout<Dim>::columns]) {
  using L = SlaveFrameLayout<Dim>;
  for (int r = 0; r < L::rows; ++r)
    for (int v = 0; v < L::columns; ++v) {
      double sum = 0.0;
      for (int e = 0; e < Dim; ++e) sum += J[r][e] * dn_f[e][v];
      out[r][v] = sum;
    }
}

}  // namespace grout
