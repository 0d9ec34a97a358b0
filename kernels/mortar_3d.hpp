#pragma once
// Exact segment-based 3D mortar integration of one (slave face, master face) pair, TRI3/QUAD4
// × TRI3/QUAD4 (Puso & Laursen 2004; Popp, Gitterle, Gee & Wall 2010, sec. 3.2; docs/design.md §3):
//
//  1. auxiliary plane through the slave centre x₀ with the unit centre normal n₀, in-plane
//     orthonormal basis (t₁, t₂);
//  2. slave and master nodes projected on the plane along n₀: p_i = ((x_i − x₀)·t₁, (x_i − x₀)·t₂);
//  3. clip polygon = slave ∩ master polygon (clip_polygons, slivers dropped);
//  4. triangulation about the clip polygon's vertex centroid y_c: cells (y_c, v_i, v_{i+1});
//  5. symmetric Gauss rule (GaussTriangle<Degree>) on each cell;
//  6. back-projection of every Gauss point y along n₀: ξ¹ from Σ N¹_i(ξ¹) p¹_i = y, ξ² from
//     Σ N²_l(ξ²) p²_l = y (face_inverse_map_2d: exact for TRI3, Newton for QUAD4);
//  7. D_jj = ∫ Φ_j dA, M_jl = ∫ Φ_j N²_l dA over the slave surface part that projects into the
//     clip polygon.
//
// The integrals are over the slave surface, not the plane: the cell weight w_g |cell| is
// multiplied by dA¹/dA_plane = |g₁ × g₂| / (n₀ · (g₁ × g₂)) at ξ¹ (1 for a flat slave face), so
// that Σ_j D_jj = slave area when the face is fully covered, also for a warped QUAD4.
// D_jj = ∫ Φ_j Σ_k N¹_k dA = Σ_k ∫ Φ_j N¹_k dA is the row sum of D over the pair (the
// off-diagonal parts vanish on full coverage by biorthogonality).
//
// Rule degree: for a TRI3 or parallelogram QUAD4 slave and master the back-projection is
// affine, so Φ_j N²_l is a polynomial of degree ≤ 4 (bilinear × bilinear) on each cell, which
// degree 4 integrates exactly. A general QUAD4 makes ξ(y) an inverse bilinear map (square
// roots, not polynomial): no rule is exact, the error falls with the degree. The default 6
// (12 points) leaves margin for these with a moderate cost; 8 is available.

#include <cmath>
#include <type_traits>

#include "kernels/dual_basis_3d.hpp"
#include "kernels/face_geometry_3d.hpp"
#include "kernels/gauss_triangle.hpp"
#include "kernels/kernel_macros.hpp"
#include "kernels/mortar_types.hpp"
#include "kernels/polygon_clipping.hpp"

namespace grout {

constexpr int mortar_3d_triangle_degree = 6;  ///< default GaussTriangle degree per cell

/// Auxiliary plane of a slave face: centre x₀, unit normal n₀, basis (t₁, t₂), nodes in plane
/// coordinates.
template <class Scalar>
struct AuxiliaryPlane {
  Scalar x0[3], n0[3], t1[3], t2[3];
  Scalar ps[max_face_nodes][2];  ///< projected slave nodes
};

/// \brief Plane coordinates y = ((x − x₀)·t₁, (x − x₀)·t₂) of x projected along n₀.
template <class Scalar>
GROUT_INLINE_FUNCTION void project_on_plane(const AuxiliaryPlane<Scalar>& plane, const Scalar x[3],
                                            Scalar y[2]) {
  Scalar v[3];
  for (int d = 0; d < 3; ++d) v[d] = x[d] - plane.x0[d];
  y[0] = detail3d::dot(v, plane.t1);
  y[1] = detail3d::dot(v, plane.t2);
}

/// \brief Auxiliary plane of a slave face (Popp et al. 2010, sec. 3.2, step 1-2).
/// \return degenerate for a zero-area slave face, else ok.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus auxiliary_plane(int n_slave, const Scalar xs[max_face_nodes][3],
                                                   AuxiliaryPlane<Scalar>& plane) {
  if (face_centre_normal(n_slave, xs, plane.x0, plane.n0) != MortarStatus::ok)
    return MortarStatus::degenerate;
  Scalar e[3];
  for (int d = 0; d < 3; ++d) e[d] = xs[1][d] - xs[0][d];
  plane_basis(plane.n0, e, plane.t1, plane.t2);
  for (int i = 0; i < n_slave; ++i) project_on_plane(plane, xs[i], plane.ps[i]);
  return MortarStatus::ok;
}

/// \brief Slave-surface area per plane area at ξ¹: |g₁ × g₂| / (n₀ · (g₁ × g₂)); ≤ 0 if the
/// face folds over the plane.
template <class Scalar>
GROUT_INLINE_FUNCTION Scalar slave_area_ratio(int n_slave, const Scalar xs[max_face_nodes][3],
                                              const Scalar n0[3], const Scalar xi[2]) {
  using std::sqrt;
  Scalar g[2][3], c[3];
  face_tangents(n_slave, xs, xi, g);
  detail3d::cross(g[0], g[1], c);
  return sqrt(detail3d::dot(c, c)) / detail3d::dot(c, n0);
}

namespace detail3d {

/// \brief True if the plane map y(ξ) = Σ N_i(ξ) p_i of a face is affine, so that ξ(y) is affine
/// too: always for TRI3; for a QUAD4 whose plane image is a parallelogram
/// (|p₁ − p₂ + p₃ − p₄| ≤ 1e-13 |diagonals|), only with Scalar = double — for a Fad scalar the
/// derivative of ξ(y) with respect to the nodes is not affine in y even then.
template <class Scalar>
GROUT_INLINE_FUNCTION bool affine_in_plane(int n, const Scalar p[max_face_nodes][2]) {
  using std::abs;
  if (n == 3) return true;
  if (!std::is_same<Scalar, double>::value || n != 4) return false;
  const Scalar dx = p[0][0] - p[1][0] + p[2][0] - p[3][0];
  const Scalar dy = p[0][1] - p[1][1] + p[2][1] - p[3][1];
  const Scalar diag = abs(p[2][0] - p[0][0]) + abs(p[2][1] - p[0][1]) + abs(p[3][0] - p[1][0]) +
                      abs(p[3][1] - p[1][1]);
  return abs(dx) + abs(dy) <= 1e-13 * diag;
}

}  // namespace detail3d

namespace detail3d {

/// Cell loop of for_each_mortar_point_3d with a GaussTriangle<Degree> rule per cell.
template <int Degree, class Scalar, class PointFunctor>
GROUT_INLINE_FUNCTION MortarStatus integrate_cells(
    int n_slave, const Scalar xs[max_face_nodes][3], int n_master,
    const AuxiliaryPlane<Scalar>& plane, const Scalar pm[max_face_nodes][2], int nv,
    const Scalar poly[max_clip_vertices][2], const Scalar yc[2], bool slave_affine,
    bool master_affine, const Scalar xi_vs[max_clip_vertices + 1][2],
    const Scalar xi_vm[max_clip_vertices + 1][2], const Scalar& slave_ratio, PointFunctor& f) {
  for (int i = 0; i < nv; ++i) {
    const int i2 = i + 1 == nv ? 0 : i + 1;
    const Scalar* v1 = poly[i];
    const Scalar* v2 = poly[i2];
    const Scalar cell_area =
        0.5 * ((v1[0] - yc[0]) * (v2[1] - yc[1]) - (v2[0] - yc[0]) * (v1[1] - yc[1]));
    for (int g = 0; g < GaussTriangle<Degree>::num_points; ++g) {
      double a, b, wg;
      GaussTriangle<Degree>::point(g, a, b, wg);
      const double c = 1.0 - a - b;
      const Scalar y[2] = {c * yc[0] + a * v1[0] + b * v2[0], c * yc[1] + a * v1[1] + b * v2[1]};
      Scalar xi_s[2], xi_m[2];
      if (slave_affine) {
        for (int k = 0; k < 2; ++k) xi_s[k] = c * xi_vs[nv][k] + a * xi_vs[i][k] + b * xi_vs[i2][k];
      } else if (face_inverse_map_2d(n_slave, plane.ps, y, xi_s) != MortarStatus::ok) {
        return MortarStatus::projection_failed;
      }
      if (master_affine) {
        for (int k = 0; k < 2; ++k) xi_m[k] = c * xi_vm[nv][k] + a * xi_vm[i][k] + b * xi_vm[i2][k];
      } else if (face_inverse_map_2d(n_master, pm, y, xi_m) != MortarStatus::ok) {
        return MortarStatus::projection_failed;
      }
      Scalar ratio = slave_ratio;
      if (!slave_affine) {
        ratio = slave_area_ratio(n_slave, xs, plane.n0, xi_s);
        if (!(ratio > 0.0)) return MortarStatus::degenerate;
      }
      const Scalar w = wg * cell_area * ratio;
      f(xi_s, xi_m, w);
    }
  }
  return MortarStatus::ok;
}

}  // namespace detail3d

/// \brief Exact segmentation of a pair: calls f(ξ¹, ξ², w) for every integration point, with
/// ξ¹/ξ² the slave/master parameters and w the slave-surface weight (Σ w = overlap area).
/// \return ok; no_overlap (nothing called); degenerate (slave face);
/// projection_failed (a back-projection did not converge); capacity_exceeded.
template <int Degree = mortar_3d_triangle_degree, class Scalar, class PointFunctor>
GROUT_INLINE_FUNCTION MortarStatus for_each_mortar_point_3d(int n_slave,
                                                            const Scalar xs[max_face_nodes][3],
                                                            int n_master,
                                                            const Scalar xm[max_face_nodes][3],
                                                            PointFunctor& f) {
  if ((n_slave != 3 && n_slave != 4) || (n_master != 3 && n_master != 4))
    return MortarStatus::degenerate;
  AuxiliaryPlane<Scalar> plane;
  if (auxiliary_plane(n_slave, xs, plane) != MortarStatus::ok) return MortarStatus::degenerate;
  Scalar pm[max_face_nodes][2];
  for (int l = 0; l < n_master; ++l) project_on_plane(plane, xm[l], pm[l]);

  Scalar poly[max_clip_vertices][2];
  int nv = 0;
  const MortarStatus clipped = clip_polygons(n_slave, plane.ps, n_master, pm, poly, nv);
  if (clipped == MortarStatus::degenerate) return MortarStatus::no_overlap;  // edge-on master
  if (clipped != MortarStatus::ok) return clipped;

  Scalar yc[2] = {0.0, 0.0};
  for (int i = 0; i < nv; ++i) yc[0] += poly[i][0] / nv, yc[1] += poly[i][1] / nv;

  // An affine side (detail3d::affine_in_plane) has parameters affine in y: those of a Gauss
  // point are the barycentric combination of those of its cell's vertices (mapped once per
  // polygon vertex, not per point), and for an affine slave the area ratio is constant.
  const bool slave_affine = detail3d::affine_in_plane(n_slave, plane.ps);
  const bool master_affine = detail3d::affine_in_plane(n_master, pm);
  Scalar xi_vs[max_clip_vertices + 1][2] = {};  // slave parameters; [nv]: centroid
  Scalar xi_vm[max_clip_vertices + 1][2] = {};  // master parameters; [nv]: centroid
  for (int i = 0; i <= nv; ++i) {
    const Scalar* y = i < nv ? poly[i] : yc;
    if ((slave_affine && face_inverse_map_2d(n_slave, plane.ps, y, xi_vs[i]) != MortarStatus::ok) ||
        (master_affine && face_inverse_map_2d(n_master, pm, y, xi_vm[i]) != MortarStatus::ok))
      return MortarStatus::projection_failed;
  }
  Scalar slave_ratio = 1.0;
  if (slave_affine) {
    slave_ratio = slave_area_ratio(n_slave, xs, plane.n0, xi_vs[nv]);
    if (!(slave_ratio > 0.0)) return MortarStatus::degenerate;
  }

  // Both sides affine: Φ_j N²_l is a polynomial of degree ≤ 4 on each cell (file comment), so
  // the degree-4 rule is exact and replaces a higher requested degree.
  if (slave_affine && master_affine && Degree > 4)
    return detail3d::integrate_cells<4>(n_slave, xs, n_master, plane, pm, nv, poly, yc,
                                        slave_affine, master_affine, xi_vs, xi_vm, slave_ratio, f);
  return detail3d::integrate_cells<Degree>(n_slave, xs, n_master, plane, pm, nv, poly, yc,
                                           slave_affine, master_affine, xi_vs, xi_vm, slave_ratio,
                                           f);
}

namespace detail3d {

/// Accumulates overlap, D_jj = Σ w Φ_j and M_jl = Σ w Φ_j N²_l.
template <class Scalar>
struct AccumulateMortarPair {
  const Scalar (*A)[max_face_nodes];
  MortarPairResult<Scalar>* out;
  GROUT_INLINE_FUNCTION void operator()(const Scalar xi_s[2], const Scalar xi_m[2],
                                        const Scalar& w) const {
    Scalar Phi[max_face_nodes], Nm[max_face_nodes];
    dual_shape_functions_3d(out->n_slave, A, xi_s, Phi);
    face_shape_functions(out->n_master, xi_m, Nm);
    out->overlap += w;
    for (int j = 0; j < out->n_slave; ++j) {
      const Scalar wphi = w * Phi[j];
      out->D[j] += wphi;
      for (int l = 0; l < out->n_master; ++l) out->M[j][l] += wphi * Nm[l];
    }
  }
};

template <class Scalar>
GROUT_INLINE_FUNCTION void reset_pair_result(int n_slave, int n_master,
                                             MortarPairResult<Scalar>& out) {
  out.n_slave = n_slave;
  out.n_master = n_master;
  out.overlap = 0.0;
  for (int j = 0; j < max_face_nodes; ++j) {
    out.D[j] = 0.0;
    for (int l = 0; l < max_face_nodes; ++l) out.M[j][l] = 0.0;
  }
}

}  // namespace detail3d

/// \brief D_jj = ∫ Φ_j dA and M_jl = ∫ Φ_j (N²_l ∘ χ) dA of one pair, exact segment-based
/// integration (see the file comment), with precomputed dual coefficients A (Φ_j = Σ_k A_jk
/// N¹_k, dual_basis_coefficients_3d). On any status but ok, `out` holds zeros.
template <int Degree = mortar_3d_triangle_degree, class Scalar>
GROUT_INLINE_FUNCTION MortarStatus integrate_mortar_3d_dual(
    int n_slave, const Scalar xs[max_face_nodes][3], const Scalar A[max_face_nodes][max_face_nodes],
    int n_master, const Scalar xm[max_face_nodes][3], MortarPairResult<Scalar>& out) {
  detail3d::reset_pair_result(n_slave, n_master, out);
  detail3d::AccumulateMortarPair<Scalar> acc{A, &out};
  const MortarStatus status = for_each_mortar_point_3d<Degree>(n_slave, xs, n_master, xm, acc);
  if (status != MortarStatus::ok) detail3d::reset_pair_result(n_slave, n_master, out);
  return status;
}

/// \brief D_jj, M_jl of a (slave face, master face) pair by exact segment-based integration
/// (Popp et al. 2010, dual basis, sec. 3.2 segmentation).
/// \pre n_slave, n_master ∈ {3, 4}; node order gives the slave normal (right-hand rule).
/// `ns` (slave nodal normals) is not needed by the auxiliary-plane projection (n₀ is used).
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus integrate_mortar_3d(
    int n_slave, const Scalar xs[max_face_nodes][3], const Scalar ns[max_face_nodes][3],
    int n_master, const Scalar xm[max_face_nodes][3], MortarPairResult<Scalar>& out) {
  (void)ns;
  detail3d::reset_pair_result(n_slave, n_master, out);
  if ((n_slave != 3 && n_slave != 4) || (n_master != 3 && n_master != 4))
    return MortarStatus::degenerate;
  Scalar A[max_face_nodes][max_face_nodes];
  if (dual_basis_coefficients_3d(n_slave, xs, A) != MortarStatus::ok)
    return MortarStatus::degenerate;
  return integrate_mortar_3d_dual(n_slave, xs, A, n_master, xm, out);
}

/// \brief Collocation points of a pair: n_points_per_direction = k uniformly spread points on
/// the slave face (QUAD4: midpoints of a k × k grid of [-1,1]², weight (2/k)² j(ξ); TRI3:
/// centroids of the k² congruent sub-triangles, weight j/(2k²)); each point x¹(ξ) is projected
/// on the master along n₀ and f(ξ¹, ξ², w) is called for those that land inside the master.
/// \pre n_slave, n_master ∈ {3, 4}, k ≥ 1. \return degenerate (slave face), else ok.
template <class Scalar, class PointFunctor>
GROUT_INLINE_FUNCTION MortarStatus for_each_collocation_point_3d(int n_slave,
                                                                 const Scalar xs[max_face_nodes][3],
                                                                 int n_master,
                                                                 const Scalar xm[max_face_nodes][3],
                                                                 int k, PointFunctor& f) {
  AuxiliaryPlane<Scalar> plane;
  if (auxiliary_plane(n_slave, xs, plane) != MortarStatus::ok) return MortarStatus::degenerate;
  Scalar pm[max_face_nodes][2];
  for (int l = 0; l < n_master; ++l) project_on_plane(plane, xm[l], pm[l]);
  const double h = n_slave == 3 ? 1.0 / k : 2.0 / k;
  const double w_ref = n_slave == 3 ? 0.5 / (double(k) * k) : h * h;
  for (int c = 0; c < k * k; ++c) {  // k² points for both shapes
    double r[2];
    if (n_slave == 4) {
      r[0] = -1.0 + h * (c % k + 0.5), r[1] = -1.0 + h * (c / k + 0.5);
    } else if (c < k * (k + 1) / 2) {  // upward sub-triangles (i, j), i + j ≤ k − 1
      int i = c, j = 0;
      while (i >= k - j) i -= k - j, ++j;
      r[0] = h * (i + 1.0 / 3.0), r[1] = h * (j + 1.0 / 3.0);
    } else {  // downward sub-triangles (i, j), i + j ≤ k − 2
      int i = c - k * (k + 1) / 2, j = 0;
      while (i >= k - 1 - j) i -= k - 1 - j, ++j;
      r[0] = h * (i + 2.0 / 3.0), r[1] = h * (j + 2.0 / 3.0);
    }
    const Scalar xi_s[2] = {Scalar(r[0]), Scalar(r[1])};
    Scalar x[3], y[2], xi_m[2];
    face_position(n_slave, xs, xi_s, x);
    project_on_plane(plane, x, y);
    if (face_inverse_map_2d(n_master, pm, y, xi_m) != MortarStatus::ok) continue;  // missed
    if (!face_contains(n_master, xi_m)) continue;
    f(xi_s, xi_m, Scalar(w_ref * face_area_element(n_slave, xs, xi_s)));
  }
  return MortarStatus::ok;
}

/// \brief Collocation (element-based) variant of integrate_mortar_3d_dual, with the multiplier
/// coefficients A (Φ_j = Σ_k A_jk N¹_k): the points of for_each_collocation_point_3d.
/// Converges to the exact integration as k grows (O(1/k): the overlap boundary cuts cells).
/// \return ok; no_overlap (no point hits, out zero); degenerate (slave face or k < 1).
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus integrate_mortar_3d_collocation_dual(
    int n_slave, const Scalar xs[max_face_nodes][3], const Scalar A[max_face_nodes][max_face_nodes],
    int n_master, const Scalar xm[max_face_nodes][3], int n_points_per_direction,
    MortarPairResult<Scalar>& out) {
  detail3d::reset_pair_result(n_slave, n_master, out);
  const int k = n_points_per_direction;
  if ((n_slave != 3 && n_slave != 4) || (n_master != 3 && n_master != 4) || k < 1)
    return MortarStatus::degenerate;
  detail3d::AccumulateMortarPair<Scalar> acc{A, &out};
  if (for_each_collocation_point_3d(n_slave, xs, n_master, xm, k, acc) != MortarStatus::ok)
    return MortarStatus::degenerate;
  return out.overlap > 0.0 ? MortarStatus::ok : MortarStatus::no_overlap;
}

/// \brief Collocation (element-based) variant: integrate_mortar_3d_collocation_dual with the
/// dual coefficients of the slave face (dual_basis_coefficients_3d).
/// \return ok; no_overlap (no point hits, out zero); degenerate (slave face or k < 1).
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus integrate_mortar_3d_collocation(
    int n_slave, const Scalar xs[max_face_nodes][3], const Scalar ns[max_face_nodes][3],
    int n_master, const Scalar xm[max_face_nodes][3], int n_points_per_direction,
    MortarPairResult<Scalar>& out) {
  (void)ns;
  detail3d::reset_pair_result(n_slave, n_master, out);
  const int k = n_points_per_direction;
  if ((n_slave != 3 && n_slave != 4) || (n_master != 3 && n_master != 4) || k < 1)
    return MortarStatus::degenerate;
  Scalar A[max_face_nodes][max_face_nodes];
  if (dual_basis_coefficients_3d(n_slave, xs, A) != MortarStatus::ok)
    return MortarStatus::degenerate;
  return integrate_mortar_3d_collocation_dual(n_slave, xs, A, n_master, xm, k, out);
}

}  // namespace grout
