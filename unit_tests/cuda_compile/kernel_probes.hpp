#pragma once
// Probes: the per-pair mortar kernels and the small-strain element kernel evaluated on fixed
// inputs, each probe writing its statuses and results into a flat array of doubles.
//
// The same functions are compiled three ways (unit_tests/cuda_compile/CMakeLists.txt):
//   - by the host compiler with Kokkos (kernel_probes_host.cpp): the reference results;
//   - by nvcc as CUDA device code, one __global__ wrapper per probe (kernel_probes.cu):
//     the device compile shows that the kernels are valid device code;
//   - by nvcc for the host, without Kokkos (GROUT_KERNELS_NO_KOKKOS, kernel_probes.cu's main):
//     its results must agree with the reference (same math whichever macro path is taken).
// GROUT_KERNEL_PROBES lists the probes once for all three.

#include "kernels/contact_law.hpp"
#include "kernels/dual_basis.hpp"
#include "kernels/dual_basis_3d.hpp"
#include "kernels/face_normal.hpp"
#include "kernels/kernel_macros.hpp"
#include "kernels/linear_elastic.hpp"
#include "kernels/mortar_2d.hpp"
#include "kernels/mortar_3d.hpp"
#include "kernels/mortar_matrices.hpp"
#include "kernels/mortar_pair_variables.hpp"
#include "kernels/multiplier_basis.hpp"
#include "kernels/polygon_clipping.hpp"
#include "kernels/slave_frame.hpp"

/// X(name) for every probe grout::probes::probe_<name>.
#define GROUT_KERNEL_PROBES(X) \
  X(dual_basis_2d)             \
  X(mortar_2d)                 \
  X(clip_polygons)             \
  X(dual_basis_3d)             \
  X(mortar_3d)                 \
  X(mortar_matrices)           \
  X(face_normal)               \
  X(slave_frame)               \
  X(mortar_pair_gradient_2d)   \
  X(mortar_pair_gradient_3d)   \
  X(contact_law)               \
  X(linear_elastic_2d)         \
  X(linear_elastic_3d)

namespace grout {
namespace probes {

constexpr int max_probe_values = 1024;  ///< capacity of one probe's output

/// Output of one probe: values in order; `failures` counts statuses other than ok (the probe
/// inputs are chosen so that every kernel succeeds).
struct ProbeOutput {
  double* values;
  int n = 0;
  int failures = 0;
  GROUT_INLINE_FUNCTION void put(double v) {
    if (n < max_probe_values) values[n] = v;
    ++n;
  }
  template <class Status>
  GROUT_INLINE_FUNCTION void put_status(Status s) {
    put(static_cast<int>(s));
    if (static_cast<int>(s) != 0) ++failures;
  }
  GROUT_INLINE_FUNCTION void put_pair(const MortarPairResult<double>& r) {
    put(r.overlap);
    for (int j = 0; j < r.n_slave; ++j) put(r.D[j]);
    for (int j = 0; j < r.n_slave; ++j)
      for (int l = 0; l < r.n_master; ++l) put(r.M[j][l]);
  }
};

/// Slave and master LINE2 of the 2D probes: non-parallel, partly overlapping, master reversed.
GROUT_INLINE_FUNCTION void line_pair_2d(double xs[2][2], double ns[2][2], double xm[2][2]) {
  const double s[2][2] = {{0.0, 0.0}, {2.0, 0.2}}, m[2][2] = {{2.3, -0.5}, {0.4, -0.35}};
  for (int k = 0; k < 2; ++k)
    for (int d = 0; d < 2; ++d) xs[k][d] = s[k][d], xm[k][d] = m[k][d];
  // Nodal normals tilted either way from the element normal (as averaged normals would be).
  ns[0][0] = 0.05, ns[0][1] = -1.0;
  ns[1][0] = 0.2, ns[1][1] = -1.0;
  normalize_vector<2>(ns[0]);
  normalize_vector<2>(ns[1]);
}

/// Warped QUAD4 slave, TRI3 and (non-parallelogram) QUAD4 masters of the 3D probes.
GROUT_INLINE_FUNCTION void faces_3d(double xs[max_face_nodes][3], double xt[max_face_nodes][3],
                                    double xq[max_face_nodes][3]) {
  const double s[4][3] = {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.02}, {1.1, 1.0, -0.01}, {0.0, 0.9, 0.01}};
  const double t[4][3] = {{-0.2, 0.1, 0.05}, {0.4, 1.2, 0.04}, {0.9, -0.1, 0.06}, {0, 0, 0}};
  const double q[4][3] = {{0.3, -0.2, 0.05}, {0.25, 1.1, 0.04}, {1.3, 0.8, 0.07}, {1.2, 0.1, 0.06}};
  for (int k = 0; k < 4; ++k)
    for (int d = 0; d < 3; ++d) xs[k][d] = s[k][d], xt[k][d] = t[k][d], xq[k][d] = q[k][d];
}

/// LINE2 dual basis (closed form and the general A = D M⁻¹ route) and its shape functions.
GROUT_INLINE_FUNCTION void probe_dual_basis_2d(ProbeOutput& out) {
  double xs[2][2], ns[2][2], xm[2][2], A[2][2];
  line_pair_2d(xs, ns, xm);
  out.put_status(dual_basis_coefficients_line2(xs, A));
  for (int j = 0; j < 2; ++j)
    for (int k = 0; k < 2; ++k) out.put(A[j][k]);
  const double De[3] = {0.4, 0.5, 0.3};
  const double Me[3][3] = {{0.2, 0.05, 0.01}, {0.05, 0.3, 0.04}, {0.01, 0.04, 0.15}};
  double A3[3][3];
  out.put_status(dual_basis_coefficients<double, 3>(De, Me, A3));
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) out.put(A3[j][k]);
  double Phi[2], N[2];
  line2_dual_shape(0.3, Phi);
  line2_shape(-0.7, N);
  for (int j = 0; j < 2; ++j) out.put(Phi[j]), out.put(N[j]);
}

/// 2D segment-based mortar integration (default and 3-point Gauss) and the collocation variant.
GROUT_INLINE_FUNCTION void probe_mortar_2d(ProbeOutput& out) {
  double xs[2][2], ns[2][2], xm[2][2];
  line_pair_2d(xs, ns, xm);
  MortarPairResult<double> r;
  out.put_status(integrate_mortar_2d(xs, ns, xm, r));
  out.put_pair(r);
  out.put_status(integrate_mortar_2d(xs, ns, xm, 3, r));
  out.put_pair(r);
  out.put_status(integrate_mortar_2d_collocation(xs, ns, xm, 7, r));
  out.put_pair(r);
}

/// Convex quadrilateral clipped by a triangle, and the area of the intersection.
GROUT_INLINE_FUNCTION void probe_clip_polygons(ProbeOutput& out) {
  const double subject[4][2] = {{0.0, 0.0}, {1.0, 0.1}, {0.9, 1.0}, {-0.1, 0.8}};
  const double clip[3][2] = {{0.5, -0.3}, {1.3, 0.6}, {0.2, 1.2}};
  double result[max_clip_vertices][2];
  int n_result = 0;
  out.put_status(clip_polygons(4, subject, 3, clip, result, n_result));
  out.put(n_result);
  for (int i = 0; i < n_result && i < max_clip_vertices; ++i)
    out.put(result[i][0]), out.put(result[i][1]);
  out.put(polygon_signed_area(n_result, result));
}

/// 3D dual basis on the warped QUAD4 and a TRI3, and Φ at a point.
GROUT_INLINE_FUNCTION void probe_dual_basis_3d(ProbeOutput& out) {
  double xs[max_face_nodes][3], xt[max_face_nodes][3], xq[max_face_nodes][3];
  faces_3d(xs, xt, xq);
  double A[max_face_nodes][max_face_nodes], Phi[max_face_nodes];
  const double xi[2] = {0.2, -0.4};
  out.put_status(dual_basis_coefficients_3d(4, xs, A));
  for (int j = 0; j < 4; ++j)
    for (int k = 0; k < 4; ++k) out.put(A[j][k]);
  dual_shape_functions_3d(4, A, xi, Phi);
  for (int j = 0; j < 4; ++j) out.put(Phi[j]);
  out.put_status(dual_basis_coefficients_3d(3, xt, A));
  const double xt_ref[2] = {0.25, 0.4};
  dual_shape_functions_3d(3, A, xt_ref, Phi);
  for (int j = 0; j < 3; ++j) out.put(Phi[j]);
}

/// 3D exact segment-based mortar integration (clipping, triangulation, back-projection) of the
/// QUAD4 slave with a TRI3 and a QUAD4 master, and the collocation variant.
GROUT_INLINE_FUNCTION void probe_mortar_3d(ProbeOutput& out) {
  double xs[max_face_nodes][3], xt[max_face_nodes][3], xq[max_face_nodes][3];
  faces_3d(xs, xt, xq);
  MortarPairResult<double> r;
  out.put_status(integrate_mortar_3d(4, xs, xs, 3, xt, r));
  out.put_pair(r);
  out.put_status(integrate_mortar_3d(4, xs, xs, 4, xq, r));
  out.put_pair(r);
  out.put_status(integrate_mortar_3d_collocation(4, xs, xs, 4, xq, 5, r));
  out.put_pair(r);
}

/// Full pair matrices (standard and dual bases, multiplier_basis.hpp / mortar_matrices.hpp):
/// the 2D pair exact and by collocation, the warped QUAD4 slave against the QUAD4 master.
GROUT_INLINE_FUNCTION void probe_mortar_matrices(ProbeOutput& out) {
  double xs[max_face_nodes][3], xt[max_face_nodes][3], xq[max_face_nodes][3];
  faces_3d(xs, xt, xq);
  double xs2[2][2], ns2[2][2], xm2[2][2];
  line_pair_2d(xs2, ns2, xm2);
  double xl[max_face_nodes][3] = {{xs2[0][0], xs2[0][1], 0.0}, {xs2[1][0], xs2[1][1], 0.0}};
  MortarPairMatrices<double> r;
  const auto put = [&](MortarStatus s) {
    out.put_status(s);
    out.put(r.overlap);
    for (int j = 0; j < r.n_slave; ++j) {
      for (int k = 0; k < r.n_slave; ++k) out.put(r.D[j][k]);
      for (int l = 0; l < r.n_master; ++l) out.put(r.M[j][l]);
    }
  };
  for (MultiplierBasis basis : {MultiplierBasis::standard, MultiplierBasis::dual}) {
    double A[max_face_nodes][max_face_nodes];
    out.put_status(multiplier_basis_coefficients(basis, 2, 2, xl, A));
    MortarSlave2D<double> slave;
    mortar_slave_2d(xs2, ns2, slave);
    put(integrate_mortar_matrices_2d(slave, A, xm2, 5, r));
    put(integrate_mortar_matrices_2d_collocation(xs2, ns2, A, xm2, 7, r));
    out.put_status(multiplier_basis_coefficients(basis, 3, 4, xs, A));
    put(integrate_mortar_matrices_3d(4, xs, A, 4, xq, r));
    put(integrate_mortar_matrices_3d_collocation(4, xs, A, 4, xq, 5, r));
  }
}

/// Element normals of a LINE2, TRI3 and warped QUAD4 face, and the tangents.
GROUT_INLINE_FUNCTION void probe_face_normal(ProbeOutput& out) {
  double xs[max_face_nodes][3], xt[max_face_nodes][3], xq[max_face_nodes][3];
  faces_3d(xs, xt, xq);
  double n[3], t[2], t1[3], t2[3];
  out.put_status(face_normal(2, 2, xs, n));
  tangent_2d(n, t);
  for (int d = 0; d < 2; ++d) out.put(n[d]), out.put(t[d]);
  out.put_status(face_normal(3, 3, xt, n));
  for (int d = 0; d < 3; ++d) out.put(n[d]);
  out.put_status(face_normal(3, 4, xs, n));
  tangents_3d(n, t1, t2);
  for (int d = 0; d < 3; ++d) out.put(n[d]), out.put(t1[d]), out.put(t2[d]);
}

/// Slave frames in AD (slave_frame.hpp, the body of compute_slave_frames): ∂n_f/∂x of a LINE2
/// and a warped QUAD4, the frame of a summed normal and ∂frame/∂N, and their chain.
GROUT_INLINE_FUNCTION void probe_slave_frame(ProbeOutput& out) {
  double xs[max_face_nodes][3], xt[max_face_nodes][3], xq[max_face_nodes][3];
  faces_3d(xs, xt, xq);
  double n[3], dn2[3][SlaveFrameLayout<2>::columns], dn3[3][SlaveFrameLayout<3>::columns];
  out.put_status(face_normal_gradient<2>(2, xs, n, dn2));
  double frame2[4], J2[4][2], block2[4][SlaveFrameLayout<2>::columns];
  frame_of_normal_sum<2>(n, frame2, J2);
  chain_frame_gradient<2>(J2, dn2, block2);
  for (int r = 0; r < 4; ++r) {
    out.put(frame2[r]);
    for (int v = 0; v < 4; ++v) out.put(block2[r][v]);
  }
  out.put_status(face_normal_gradient<3>(4, xs, n, dn3));
  const double N[3] = {n[0] + 0.1, n[1] - 0.05, n[2] + 0.9};  // a neighbour's normal added
  double frame3[9], J3[9][3], block3[9][SlaveFrameLayout<3>::columns];
  frame_of_normal_sum<3>(N, frame3, J3);
  chain_frame_gradient<3>(J3, dn3, block3);
  for (int r = 0; r < 9; ++r) {
    out.put(frame3[r]);
    for (int v = 0; v < SlaveFrameLayout<3>::columns; ++v) out.put(block3[r][v]);
  }
}

/// The derivative launch's pair work (mortar_pair_gradient.hpp): seed the pair variables,
/// integrate in MortarPairFad<Dim>, store values and derivatives. 2D: the LINE2 pair.
GROUT_INLINE_FUNCTION void probe_mortar_pair_gradient_2d(ProbeOutput& out) {
  using Vars = MortarPairVariables<2>;
  using Fad = MortarPairFad<2>;
  double xs2[2][2], ns2[2][2], xm2[2][2];
  line_pair_2d(xs2, ns2, xm2);
  double xs[max_face_nodes][3] = {}, ns[max_face_nodes][3] = {}, xm[max_face_nodes][3] = {};
  for (int a = 0; a < 2; ++a)
    for (int d = 0; d < 2; ++d) xs[a][d] = xs2[a][d], ns[a][d] = ns2[a][d], xm[a][d] = xm2[a][d];
  Fad fs[max_face_nodes][3], fn[max_face_nodes][3], fm[max_face_nodes][3];
  seed_face(2, xs, fs, Vars::Slave(), Vars::count);
  seed_face(2, ns, fn, Vars::Normal(), Vars::count);
  seed_face(2, xm, fm, Vars::Master(), Vars::count);
  const Fad s[2][2] = {{fs[0][0], fs[0][1]}, {fs[1][0], fs[1][1]}};
  const Fad n2[2][2] = {{fn[0][0], fn[0][1]}, {fn[1][0], fn[1][1]}};
  const Fad m[2][2] = {{fm[0][0], fm[0][1]}, {fm[1][0], fm[1][1]}};
  MortarPairResult<Fad> pair;
  const MortarStatus st = integrate_mortar_2d(s, n2, m, pair);
  MortarPairGradient<2> g;
  store_pair_gradient<2>(st, pair, 2, 2, g);
  out.put_status(st);
  for (int j = 0; j < 2; ++j) {
    out.put(g.D[j]);
    for (int v = 0; v < Vars::count; ++v) out.put(g.dD[j][v]);
    for (int l = 0; l < 2; ++l) {
      out.put(g.M[j][l]);
      for (int v = 0; v < Vars::count; ++v) out.put(g.dM[j][l][v]);
    }
  }
}

/// As probe_mortar_pair_gradient_2d in 3D: the warped QUAD4 slave (dual coefficients in AD)
/// against the TRI3 master, exact clipping.
GROUT_INLINE_FUNCTION void probe_mortar_pair_gradient_3d(ProbeOutput& out) {
  using Vars = MortarPairVariables<3>;
  using Fad = MortarPairFad<3>;
  double xs[max_face_nodes][3], xt[max_face_nodes][3], xq[max_face_nodes][3];
  faces_3d(xs, xt, xq);
  Fad fs[max_face_nodes][3], fm[max_face_nodes][3], A[max_face_nodes][max_face_nodes];
  seed_face(4, xs, fs, Vars::Slave(), Vars::count);
  seed_face(3, xt, fm, Vars::Master(), Vars::count);
  out.put_status(dual_basis_coefficients_3d(4, fs, A));
  MortarPairResult<Fad> pair;
  const MortarStatus st = integrate_mortar_3d_dual(4, fs, A, 3, fm, pair);
  MortarPairGradient<3> g;
  store_pair_gradient<3>(st, pair, 4, 3, g);
  out.put_status(st);
  for (int j = 0; j < 4; ++j) {
    out.put(g.D[j]);
    for (int v = 0; v < Vars::count; ++v) out.put(g.dD[j][v]);
    for (int l = 0; l < 3; ++l) {
      out.put(g.M[j][l]);
      for (int v = 0; v < Vars::count; v += 3) out.put(g.dM[j][l][v]);  // every third: capacity
    }
  }
}

/// One node of the contact law (contact_law.hpp) in AD: status, and per row the value, kind,
/// identity component and ∂C/∂v over the ContactLawLayout.
GROUT_INLINE_FUNCTION void put_contact_law(ProbeOutput& out, const ContactLawParameters& p,
                                           const ContactLawNode& x) {
  ContactLawResult r;
  contact_law(p, x, true, r);
  out.put(r.status);
  for (int row = 0; row < p.dim; ++row) {
    out.put(r.C[row]);
    out.put(r.kind[row]);
    out.put(r.component[row]);
    for (int v = 0; v < ContactLawLayout::count; ++v) out.put(r.dC[row][v]);
  }
}

/// The contact law at a slave node with its derivatives (the work item of evaluate_contact_law,
/// contact_laws.hpp): 2D Coulomb slip; 3D Coulomb slip (both tangents), stick with a held
/// tangent, frictionless; 3D tied with a held component.
GROUT_INLINE_FUNCTION void probe_contact_law(ProbeOutput& out) {
  ContactLawParameters p{2, coulomb_law, 120.0, 40.0, 0.3, 1e-8};
  ContactLawNode x{};
  x.paired = 1;
  x.n[0] = 0.1, x.n[1] = -1.0;
  normalize_vector<2>(x.n);
  tangent_2d(x.n, x.t[0]);
  x.lambda[0] = 0.4, x.lambda[1] = -1.5;  // λ_n ≈ 1.53, λ_τ ≈ 0.25
  x.gap = -1e-3, x.slip[0] = 0.02;        // ξ ≈ 1.05 > μ s ≈ 0.5: slip
  put_contact_law(out, p, x);

  p.dim = 3;
  x = ContactLawNode{};
  x.paired = 1;
  x.n[0] = 0.1, x.n[1] = -0.2, x.n[2] = -1.0;
  normalize_vector<3>(x.n);
  tangents_3d(x.n, x.t[0], x.t[1]);
  x.lambda[0] = 0.3, x.lambda[1] = -0.2, x.lambda[2] = -1.2;
  x.gap = -2e-3, x.slip[0] = 0.01, x.slip[1] = -0.015;
  put_contact_law(out, p, x);  // slip
  x.slip[0] = x.slip[1] = 0.0;
  x.lambda[0] = x.lambda[1] = 0.0;
  x.gap = 0.0;
  x.n[0] = 0.0, x.n[1] = 0.02, x.n[2] = -1.0;  // tangents_3d: τ_0 = e_x
  normalize_vector<3>(x.n);
  tangents_3d(x.n, x.t[0], x.t[1]);
  x.prescribed[0] = 1, x.free_share[0] = 0.05;
  x.slip[1] = 1e-3;
  put_contact_law(out, p, x);  // stick (|ξ_1| ≈ 0.06 < μ s ≈ 0.36), τ_0 held
  p.kind = frictionless_law;
  put_contact_law(out, p, x);
  p.kind = tied_law;
  x.tied[0] = 1e-3, x.tied[1] = -2e-3, x.tied[2] = 5e-4;
  x.prescribed[1] = 1, x.free_share[1] = 0.0;
  put_contact_law(out, p, x);
}

/// Force, stiffness and mean stress of one solid element with a non-trivial displacement.
GROUT_INLINE_FUNCTION void element_probe(ProbeOutput& out, Topology t, int dim, const double* X,
                                         bool plane_stress) {
  const ElasticConstants c = elastic_constants(210.0, 0.3, dim, plane_stress);
  const int n = topology_num_nodes(t) * dim;
  double u[max_element_dofs], f[max_element_dofs], K[max_element_dofs * max_element_dofs];
  double stress[6];
  for (int r = 0; r < n; ++r) u[r] = 1e-3 * ((r * 7) % 5 - 2) + 2e-4 * X[r];
  out.put_status(linear_elastic_element(t, dim, X, u, c, f, K));
  for (int r = 0; r < n; ++r) out.put(f[r]);
  for (int r = 0; r < n * n; ++r) out.put(K[r]);
  out.put_status(linear_elastic_stress(t, dim, X, u, c, !plane_stress, 0.3, stress));
  for (int k = 0; k < 6; ++k) out.put(stress[k]);
  out.put(element_measure(t, dim, X));
}

/// Distorted QUAD4 (plane strain) and TRI3 (plane stress).
GROUT_INLINE_FUNCTION void probe_linear_elastic_2d(ProbeOutput& out) {
  const double quad[8] = {0.0, 0.0, 1.1, 0.1, 1.0, 0.9, -0.1, 1.2};
  const double tri[6] = {0.0, 0.0, 1.0, 0.2, 0.3, 0.8};
  element_probe(out, Topology::quad4, 2, quad, false);
  element_probe(out, Topology::tri3, 2, tri, true);
}

/// Distorted HEX8 and a TET4.
GROUT_INLINE_FUNCTION void probe_linear_elastic_3d(ProbeOutput& out) {
  const double hex[24] = {0.0, 0.0, 0.0, 1.0, 0.1, 0.0, 1.1, 1.0, 0.1, 0.0,  0.9, -0.1,
                          0.1, 0.0, 1.0, 1.0, 0.0, 1.1, 1.0, 1.1, 0.9, -0.1, 1.0, 1.0};
  const double tet[12] = {0.0, 0.0, 0.0, 1.0, 0.1, 0.0, 0.2, 0.9, 0.1, 0.1, 0.2, 1.1};
  element_probe(out, Topology::hex8, 3, hex, false);
  element_probe(out, Topology::tet4, 3, tet, false);
}

}  // namespace probes
}  // namespace grout
