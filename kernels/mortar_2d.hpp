#pragma once
// Segment-based mortar integration of one (slave LINE2, master LINE2) pair in 2D
// (docs/design.md §3; Yang, Laursen, Meng, IJNME 62 (2005) §3; Popp et al., IJNME 79 (2009) §3.1).
//
// Slave:  x¹(ξ) = N₁(ξ) x¹₁ + N₂(ξ) x¹₂,  interpolated normal n¹(ξ) = N₁ n₁ + N₂ n₂, ξ ∈ [−1, 1].
// Master: x²(η) = N₁(η) x²₁ + N₂(η) x²₂.
// 1. Each master node y is projected onto the slave along the interpolated slave normal:
//    (x¹(ξ) − y) × n¹(ξ) = 0, a quadratic in ξ (closed form below).
// 2. The overlap is [ξ_a, ξ_b] = [−1, 1] ∩ [min ξ(y_l), max ξ(y_l)]; an end point that is ±1 is a
//    slave node, whose projection along its nodal normal n_j lands inside the master
//    (project_along_normal_to_master_2d gives that master parameter).
// 3. Gauss points on [ξ_a, ξ_b]; each is mapped to the master by projection along n¹(ξ_g):
//    (x²(η) − x¹(ξ_g)) × n¹(ξ_g) = 0, linear in η.
// 4. D_jj = ∫ Φ_j dA (row sum of D_jk = ∫ Φ_j N_k, diagonal by biorthogonality on a fully
//    covered element), M_jl = ∫ Φ_j N²_l(η(ξ)) dA, with the LINE2 dual basis Φ (dual_basis.hpp).
// Every output is fully written (zeros when the pair does not overlap), so degenerate pairs
// never produce NaN. Templated on the scalar: double or Sacado::Fad::SFad.
//
// Cost: what depends on the slave segment only (MortarSlave2D: x¹(ξ) = a + ξ b,
// n¹(ξ) = c + ξ d, b × d, b × c, L/2) is computed once per slave element and shared by its
// candidate pairs. Per pair, the master projection of step 3 is the rational function
//   η(ξ) = −((x̄² − x¹(ξ)) × n¹(ξ)) / (b² × n¹(ξ))
//        = −(e×c + ξ (e×d − b×c) − ξ² b×d) / (b²×c + ξ b²×d),  e = x̄² − a
// (its four pair coefficients once, then 8 flops and a division per Gauss point), and each
// master-node projection of step 1 takes one square root and one division.

#include <cmath>

#include "kernels/dual_basis.hpp"
#include "kernels/gauss_line.hpp"
#include "kernels/kernel_macros.hpp"
#include "kernels/mortar_types.hpp"

namespace grout {

constexpr int mortar_2d_gauss_points = 5;        ///< default Gauss points on a 2D overlap segment
constexpr double mortar_2d_overlap_tol = 1e-12;  ///< overlaps shorter than this (in ξ) are empty

/// 2D cross product u × v = u_x v_y − u_y v_x.
template <class Scalar>
GROUT_INLINE_FUNCTION Scalar cross_2d(const Scalar u[2], const Scalar v[2]) {
  return u[0] * v[1] - u[1] * v[0];
}

/// \brief Slave point x¹(ξ) and (non-normalised) interpolated normal n¹(ξ) = Σ N_j n_j.
template <class Scalar>
GROUT_INLINE_FUNCTION void slave_point_2d(const Scalar xs[2][2], const Scalar ns[2][2],
                                          const Scalar& xi, Scalar x[2], Scalar n[2]) {
  Scalar N[2];
  line2_shape(xi, N);
  for (int d = 0; d < 2; ++d) {
    x[d] = N[0] * xs[0][d] + N[1] * xs[1][d];
    n[d] = N[0] * ns[0][d] + N[1] * ns[1][d];
  }
}

/// \brief Slave-segment quantities shared by all pairs of one slave element: mid point a, half
/// edge b (x¹(ξ) = a + ξ b), mean c and half difference d of the nodal normals
/// (n¹(ξ) = c + ξ d), A = b × d, b × c, |n¹|² = nn0 + ξ (nn1 + ξ nn2), det J = L/2.
template <class Scalar>
struct MortarSlave2D {
  Scalar a[2], b[2], c[2], d[2];
  Scalar A, bxc, nn0, nn1, nn2, det_j;
};

/// \brief Fills the MortarSlave2D of the slave segment (xs, ns).
/// \return degenerate if the segment has zero length, ok otherwise.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus mortar_slave_2d(const Scalar xs[2][2], const Scalar ns[2][2],
                                                   MortarSlave2D<Scalar>& s) {
  using std::sqrt;
  for (int k = 0; k < 2; ++k) {
    s.a[k] = 0.5 * (xs[0][k] + xs[1][k]);
    s.b[k] = 0.5 * (xs[1][k] - xs[0][k]);
    s.c[k] = 0.5 * (ns[0][k] + ns[1][k]);
    s.d[k] = 0.5 * (ns[1][k] - ns[0][k]);
  }
  s.A = cross_2d(s.b, s.d);
  s.bxc = cross_2d(s.b, s.c);
  s.nn0 = s.c[0] * s.c[0] + s.c[1] * s.c[1];
  s.nn1 = 2.0 * (s.c[0] * s.d[0] + s.c[1] * s.d[1]);
  s.nn2 = s.d[0] * s.d[0] + s.d[1] * s.d[1];
  const Scalar bb = s.b[0] * s.b[0] + s.b[1] * s.b[1];
  s.det_j = 0.0;
  if (!(bb > 0.0)) return MortarStatus::degenerate;
  s.det_j = sqrt(bb);
  return MortarStatus::ok;
}

/// \brief Slave parameter ξ of the point y projected along the interpolated slave normal:
/// (a − y + ξ b) × (c + ξ d) = 0, i.e. A ξ² + B ξ + C = 0, A = b×d, B = (a−y)×d + b×c,
/// C = (a−y)×c. Stable roots q/A, C/q with q = −(B + sgn(B)√(B² − 4AC))/2; the root nearest the
/// element (smallest |ξ|: |q/A| < |C/q| ⇔ q² < |A C|) is returned. ξ may lie outside [−1, 1].
/// \return projection_failed if no real root exists.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus project_to_slave_2d(const MortarSlave2D<Scalar>& s,
                                                       const Scalar y[2], Scalar& xi) {
  using std::abs;
  using std::sqrt;
  const Scalar am[2] = {s.a[0] - y[0], s.a[1] - y[1]};
  const Scalar& A = s.A;
  const Scalar B = cross_2d(am, s.d) + s.bxc;
  const Scalar C = cross_2d(am, s.c);
  xi = 0.0;
  if (abs(A) <= 1e-14 * abs(B)) {  // parallel nodal normals: linear equation
    if (!(abs(B) > 0.0)) return MortarStatus::projection_failed;
    xi = -C / B;
    return MortarStatus::ok;
  }
  const Scalar disc = B * B - 4.0 * A * C;
  if (disc < 0.0) return MortarStatus::projection_failed;
  const Scalar q = B >= 0.0 ? Scalar(-0.5 * (B + sqrt(disc))) : Scalar(-0.5 * (B - sqrt(disc)));
  if (!(abs(q) > 0.0)) return MortarStatus::ok;  // B = C = 0: double root ξ = 0
  xi = q * q < abs(A * C) ? Scalar(q / A) : Scalar(C / q);
  return MortarStatus::ok;
}

/// \brief Master parameter η of the point x projected along the direction n onto the master
/// line: (x²(η) − x) × n = 0 ⇒ η = −((x̄² − x) × n) / (b² × n), x̄², b² the master mid point and
/// half edge. η may lie outside [−1, 1]. Used for Gauss points (n = n¹(ξ_g)) and for slave nodes
/// (n = n_j). \return projection_failed if n is parallel to the master edge.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus project_along_normal_to_master_2d(const Scalar xm[2][2],
                                                                     const Scalar x[2],
                                                                     const Scalar n[2],
                                                                     Scalar& eta) {
  Scalar am[2], b[2];
  for (int k = 0; k < 2; ++k) {
    am[k] = 0.5 * (xm[0][k] + xm[1][k]) - x[k];
    b[k] = 0.5 * (xm[1][k] - xm[0][k]);
  }
  const Scalar den = cross_2d(b, n);
  eta = 0.0;
  // |b × n| > 1e-14 |b| |n|, squared (no square root per Gauss point).
  const Scalar scale2 = (b[0] * b[0] + b[1] * b[1]) * (n[0] * n[0] + n[1] * n[1]);
  if (!(den * den > 1e-28 * scale2)) return MortarStatus::projection_failed;
  eta = -cross_2d(am, n) / den;
  return MortarStatus::ok;
}

/// \brief Overlap [ξ_a, ξ_b] ⊂ [−1, 1] of the slave segment with the master segment projected
/// along the interpolated slave normal (step 2 above).
/// \return no_overlap if ξ_b − ξ_a ≤ mortar_2d_overlap_tol, projection_failed if a master node
/// has no projection, ok otherwise.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus mortar_overlap_2d(const MortarSlave2D<Scalar>& slave,
                                                     const Scalar xm[2][2], Scalar& xi_a,
                                                     Scalar& xi_b) {
  xi_a = 0.0;
  xi_b = 0.0;
  Scalar xi_m[2];
  for (int l = 0; l < 2; ++l) {
    const MortarStatus s = project_to_slave_2d(slave, xm[l], xi_m[l]);
    if (s != MortarStatus::ok) return s;
  }
  const Scalar lo = xi_m[0] < xi_m[1] ? xi_m[0] : xi_m[1];
  const Scalar hi = xi_m[0] < xi_m[1] ? xi_m[1] : xi_m[0];
  xi_a = lo > -1.0 ? lo : Scalar(-1.0);  // end point: master node projection or slave node 1
  xi_b = hi < 1.0 ? hi : Scalar(1.0);    // end point: master node projection or slave node 2
  if (!(xi_b - xi_a > double(mortar_2d_overlap_tol))) {
    xi_a = xi_b = 0.0;
    return MortarStatus::no_overlap;
  }
  return MortarStatus::ok;
}

/// \brief Gauss points of an n_gauss-point rule on the overlap: slave parameters ξ_g, master
/// parameters η_g (by projection along n¹(ξ_g), the rational η(ξ) of the file comment) and
/// physical weights w_g = ŵ_g (ξ_b − ξ_a)/2 · L/2 (Σ w_g = overlap length).
/// \pre 1 ≤ n_gauss ≤ max_gauss_line_points.
/// \return the overlap status; capacity_exceeded for an unsupported n_gauss, projection_failed
/// if n¹(ξ_g) is parallel to the master edge (|b² × n¹| ≤ 1e-14 |b²| |n¹|).
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus mortar_integration_points_2d(const MortarSlave2D<Scalar>& slave,
                                                                const Scalar xm[2][2], int n_gauss,
                                                                Scalar xi_s[max_gauss_line_points],
                                                                Scalar eta_m[max_gauss_line_points],
                                                                Scalar w[max_gauss_line_points]) {
  for (int g = 0; g < max_gauss_line_points; ++g) xi_s[g] = eta_m[g] = w[g] = 0.0;
  if (n_gauss < 1 || n_gauss > max_gauss_line_points) return MortarStatus::capacity_exceeded;
  if (!(slave.det_j > 0.0)) return MortarStatus::degenerate;
  Scalar xi_a, xi_b;
  const MortarStatus s = mortar_overlap_2d(slave, xm, xi_a, xi_b);
  if (s != MortarStatus::ok) return s;
  // η(ξ) = −(n0 + ξ (n1 − ξ A)) / (den0 + ξ den1) (file comment).
  Scalar e[2], bm[2];
  for (int k = 0; k < 2; ++k) {
    e[k] = 0.5 * (xm[0][k] + xm[1][k]) - slave.a[k];
    bm[k] = 0.5 * (xm[1][k] - xm[0][k]);
  }
  const Scalar n0 = cross_2d(e, slave.c), n1 = cross_2d(e, slave.d) - slave.bxc;
  const Scalar den0 = cross_2d(bm, slave.c), den1 = cross_2d(bm, slave.d);
  const Scalar bb_tol = 1e-28 * (bm[0] * bm[0] + bm[1] * bm[1]);
  const Scalar half = 0.5 * (xi_b - xi_a), mid = 0.5 * (xi_a + xi_b);
  bool parallel = false;
  for (int g = 0; g < n_gauss; ++g) {
    double t, wr;
    gauss_line_point(n_gauss, g, t, wr);
    const Scalar xi = mid + half * t;
    const Scalar den = den0 + xi * den1;
    // |b² × n¹| > 1e-14 |b²| |n¹|, squared (no square root per Gauss point).
    parallel = parallel || !(den * den > bb_tol * (slave.nn0 + xi * (slave.nn1 + xi * slave.nn2)));
    xi_s[g] = xi;
    w[g] = wr * half * slave.det_j;
    eta_m[g] = -(n0 + xi * (n1 - xi * slave.A)) / den;
  }
  if (parallel) {
    for (int g = 0; g < n_gauss; ++g) eta_m[g] = 0.0;
    return MortarStatus::projection_failed;
  }
  return MortarStatus::ok;
}

/// mortar_integration_points_2d from the slave nodes and nodal normals.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus mortar_integration_points_2d(const Scalar xs[2][2],
                                                                const Scalar ns[2][2],
                                                                const Scalar xm[2][2], int n_gauss,
                                                                Scalar xi_s[max_gauss_line_points],
                                                                Scalar eta_m[max_gauss_line_points],
                                                                Scalar w[max_gauss_line_points]) {
  MortarSlave2D<Scalar> s;
  mortar_slave_2d(xs, ns, s);
  return mortar_integration_points_2d(s, xm, n_gauss, xi_s, eta_m, w);
}

template <class Scalar>
GROUT_INLINE_FUNCTION void zero_pair_result_2d(MortarPairResult<Scalar>& out) {
  out.n_slave = 2;
  out.n_master = 2;
  out.overlap = 0.0;
  for (int j = 0; j < max_face_nodes; ++j) {
    out.D[j] = 0.0;
    for (int l = 0; l < max_face_nodes; ++l) out.M[j][l] = 0.0;
  }
}

/// Adds one integration point (slave ξ, master η, weight w) to D_jj += w Φ_j, M_jl += w Φ_j N²_l.
template <class Scalar>
GROUT_INLINE_FUNCTION void add_mortar_point_2d(const Scalar& xi, const Scalar& eta, const Scalar& w,
                                               MortarPairResult<Scalar>& out) {
  Scalar Phi[2], Nm[2];
  line2_dual_shape(xi, Phi);
  line2_shape(eta, Nm);
  out.overlap += w;
  for (int j = 0; j < 2; ++j) {
    out.D[j] += w * Phi[j];
    for (int l = 0; l < 2; ++l) out.M[j][l] += w * Phi[j] * Nm[l];
  }
}

/// D_jj, M_jl and the overlap of one LINE2/LINE2 pair, summed in local variables over the
/// integration points and stored once.
template <class Scalar>
struct Line2PairSums {
  Scalar overlap = 0.0, D[2] = {0.0, 0.0}, M[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
  /// One point of weight w (the measure included): overlap += w, D_j += w Φ_j,
  /// M_jl += w Φ_j N²_l.
  GROUT_INLINE_FUNCTION void add(const Scalar& w, const Scalar Phi[2], const Scalar Nm[2]) {
    overlap += w;
    for (int j = 0; j < 2; ++j) {
      const Scalar wp = w * Phi[j];
      D[j] += wp;
      for (int l = 0; l < 2; ++l) M[j][l] += wp * Nm[l];
    }
  }
  GROUT_INLINE_FUNCTION void store(MortarPairResult<Scalar>& out) const {
    out.overlap = overlap;
    for (int j = 0; j < 2; ++j) {
      out.D[j] = D[j];
      for (int l = 0; l < 2; ++l) out.M[j][l] = M[j][l];
    }
  }
};

/// \brief Exact (segment-based) D_jj and M_jl of one LINE2/LINE2 pair with an n_gauss-point rule
/// on the overlap (steps 1-4 above), the slave given by its MortarSlave2D. D, M and the overlap
/// are summed in local variables and stored once.
/// \return ok, no_overlap (out zero), degenerate, projection_failed or capacity_exceeded.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus integrate_mortar_2d(const MortarSlave2D<Scalar>& slave,
                                                       const Scalar xm[2][2], int n_gauss,
                                                       MortarPairResult<Scalar>& out) {
  zero_pair_result_2d(out);
  Scalar xi[max_gauss_line_points], eta[max_gauss_line_points], w[max_gauss_line_points];
  const MortarStatus s = mortar_integration_points_2d(slave, xm, n_gauss, xi, eta, w);
  if (s != MortarStatus::ok) return s;
  // Φ_1,2 = (1 ∓ 3ξ)/2, N²_1,2 = (1 ∓ η)/2 (dual_basis.hpp).
  Line2PairSums<Scalar> sums;
  for (int g = 0; g < n_gauss; ++g) {
    Scalar Phi[2], Nm[2];
    line2_dual_shape(xi[g], Phi);
    line2_shape(eta[g], Nm);
    sums.add(w[g], Phi, Nm);
  }
  sums.store(out);
  return MortarStatus::ok;
}

/// \brief integrate_mortar_2d from the slave nodes and nodal normals.
/// \pre ns: unit (or at least non-zero) slave nodal normals.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus integrate_mortar_2d(const Scalar xs[2][2], const Scalar ns[2][2],
                                                       const Scalar xm[2][2], int n_gauss,
                                                       MortarPairResult<Scalar>& out) {
  MortarSlave2D<Scalar> s;
  mortar_slave_2d(xs, ns, s);
  return integrate_mortar_2d(s, xm, n_gauss, out);
}

/// \brief Axisymmetric LINE2 dual basis Φ_j = Σ_k A_jk N_k (x = r, dA = 2π r ds): the
/// biorthogonality ∫_e Φ_j N_k r ds = δ_jk ∫_e N_j r ds in the r-weighted inner product, so that D
/// stays diagonal. A = D_e M_e⁻¹ (dual_basis.hpp) with r = r₁N₁ + r₂N₂ and the exact integrals
/// (∫N₁³ = 1/4, ∫N₁²N₂ = 1/12 of the length): 12 M_e/L = [[3r₁+r₂, r₁+r₂], [r₁+r₂, r₁+3r₂]],
/// 12 D_e/L = diag(4r₁+2r₂, 2r₁+4r₂), det(12 M_e/L) = 2(r₁² + 4r₁r₂ + r₂²); r₁ = r₂ gives the
/// closed form of line2_dual_shape, and Σ_j A_jk = 1 for any r₁, r₂ (Σ_j Φ_j = 1).
/// \return degenerate unless r₁, r₂ ≥ 0 and r₁ + r₂ > 0 (a segment on the axis has no area).
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus line2_dual_coefficients_axisymmetric(const Scalar& r1,
                                                                        const Scalar& r2,
                                                                        Scalar A[2][2]) {
  A[0][0] = A[0][1] = A[1][0] = A[1][1] = 0.0;
  if (r1 < 0.0 || r2 < 0.0 || !(r1 + r2 > 0.0)) return MortarStatus::degenerate;
  const Scalar det = 2.0 * (r1 * r1 + 4.0 * r1 * r2 + r2 * r2);
  const Scalar d1 = (4.0 * r1 + 2.0 * r2) / det, d2 = (2.0 * r1 + 4.0 * r2) / det;
  A[0][0] = d1 * (r1 + 3.0 * r2);
  A[0][1] = -d1 * (r1 + r2);
  A[1][0] = -d2 * (r1 + r2);
  A[1][1] = d2 * (3.0 * r1 + r2);
  return MortarStatus::ok;
}

/// \brief Axisymmetric variant of integrate_mortar_2d (x = r ≥ 0, y the axis): every integral
/// weighted by 2π r(ξ), r the slave point's radius, with the weighted dual basis
/// (line2_dual_coefficients_axisymmetric):
///   D_jj = ∫ Φ_j 2π r ds,  M_jl = ∫ Φ_j N²_l(η(ξ)) 2π r ds,  overlap = ∫ 2π r ds,
/// so that D_jj λ_j is the force on the full circle and λ_j the traction. The exact segmentation
/// is that of integrate_mortar_2d; the extra linear factor r(ξ) needs one more Gauss point than
/// the plane kernel for the same exactness (the caller passes it).
/// \return as integrate_mortar_2d; degenerate for a slave segment on the axis or at r < 0.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus
integrate_mortar_2d_axisymmetric(const MortarSlave2D<Scalar>& slave, const Scalar xm[2][2],
                                 int n_gauss, MortarPairResult<Scalar>& out) {
  zero_pair_result_2d(out);
  Scalar A[2][2];
  const Scalar r1 = slave.a[0] - slave.b[0], r2 = slave.a[0] + slave.b[0];
  if (line2_dual_coefficients_axisymmetric(r1, r2, A) != MortarStatus::ok)
    return MortarStatus::degenerate;
  Scalar xi[max_gauss_line_points], eta[max_gauss_line_points], w[max_gauss_line_points];
  const MortarStatus s = mortar_integration_points_2d(slave, xm, n_gauss, xi, eta, w);
  if (s != MortarStatus::ok) return s;
  constexpr double two_pi = 6.283185307179586476925286766559;
  Line2PairSums<Scalar> sums;
  for (int g = 0; g < n_gauss; ++g) {
    Scalar Ns[2], Nm[2];
    line2_shape(xi[g], Ns);
    line2_shape(eta[g], Nm);
    const Scalar wr = two_pi * (slave.a[0] + xi[g] * slave.b[0]) * w[g];
    const Scalar Phi[2] = {A[0][0] * Ns[0] + A[0][1] * Ns[1], A[1][0] * Ns[0] + A[1][1] * Ns[1]};
    sums.add(wr, Phi, Nm);
  }
  sums.store(out);
  return MortarStatus::ok;
}

/// \brief integrate_mortar_2d with mortar_2d_gauss_points points: the 2D pair kernel. The 3D pair
/// kernel (mortar_3d.hpp) has the signature
/// `integrate_mortar_3d(int n_slave, const Scalar xs[4][3], const Scalar ns[4][3], int n_master,
///  const Scalar xm[4][3], MortarPairResult<Scalar>& out)`.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus integrate_mortar_2d(const Scalar xs[2][2], const Scalar ns[2][2],
                                                       const Scalar xm[2][2],
                                                       MortarPairResult<Scalar>& out) {
  return integrate_mortar_2d(xs, ns, xm, mortar_2d_gauss_points, out);
}

/// \brief Collocation points of a pair: n_points uniformly spread slave points
/// ξ_i = −1 + (2i + 1)/n_points with weights (2/n_points)·L/2 (mid-point rule); a point whose
/// projection along n¹(ξ_i) misses the master (|η| > 1) is dropped (Farah, Popp, Wall 2015);
/// f(ξ, η, w) is called for the others. \return capacity_exceeded (n_points < 1), degenerate
/// (zero-length slave), no_overlap if every point was dropped, else ok.
template <class Scalar, class PointFunctor>
GROUT_INLINE_FUNCTION MortarStatus for_each_collocation_point_2d(const Scalar xs[2][2],
                                                                 const Scalar ns[2][2],
                                                                 const Scalar xm[2][2],
                                                                 int n_points, PointFunctor& f) {
  using std::sqrt;
  if (n_points < 1) return MortarStatus::capacity_exceeded;
  const Scalar dx = xs[1][0] - xs[0][0], dy = xs[1][1] - xs[0][1];
  const Scalar ll = dx * dx + dy * dy;
  if (!(ll > 0.0)) return MortarStatus::degenerate;
  const Scalar w = (1.0 / n_points) * sqrt(ll);  // (2/N) · L/2
  bool any = false;
  for (int i = 0; i < n_points; ++i) {
    const Scalar xi = -1.0 + (2.0 * i + 1.0) / n_points;
    Scalar x[2], n[2], eta;
    slave_point_2d(xs, ns, xi, x, n);
    if (project_along_normal_to_master_2d(xm, x, n, eta) != MortarStatus::ok) continue;
    if (eta < -1.0 || eta > 1.0) continue;
    f(xi, eta, w);
    any = true;
  }
  return any ? MortarStatus::ok : MortarStatus::no_overlap;
}

namespace detail2d {
/// add_mortar_point_2d as a point functor.
template <class Scalar>
struct AddMortarPoint2D {
  MortarPairResult<Scalar>* out;
  GROUT_INLINE_FUNCTION void operator()(const Scalar& xi, const Scalar& eta,
                                        const Scalar& w) const {
    add_mortar_point_2d(xi, eta, w, *out);
  }
};
}  // namespace detail2d

/// \brief Collocation (element-based) variant of integrate_mortar_2d: the points of
/// for_each_collocation_point_2d. \return no_overlap if every point was dropped.
template <class Scalar>
GROUT_INLINE_FUNCTION MortarStatus integrate_mortar_2d_collocation(const Scalar xs[2][2],
                                                                   const Scalar ns[2][2],
                                                                   const Scalar xm[2][2],
                                                                   int n_points,
                                                                   MortarPairResult<Scalar>& out) {
  zero_pair_result_2d(out);
  detail2d::AddMortarPoint2D<Scalar> add{&out};
  return for_each_collocation_point_2d(xs, ns, xm, n_points, add);
}

}  // namespace grout
