// The axisymmetric 2D mortar pair kernel (integrate_mortar_2d_axisymmetric and the weighted
// dual basis of kernels/mortar_2d.hpp, reached through MortarPairKernel<2> with
// MortarOptions::axisymmetric) against independent quadrature: the dual coefficients solved
// here from 8-point Gauss integrals of the r-weighted element matrices, D and M of a flat pair
// (8-point Gauss on the overlap: exact), of a curved pair (a composite 200 × 8-point rule), the
// mortar patch test on a covered slave element, the plane kernel far from the axis, and the
// Sacado derivatives against central differences.
#include <gtest/gtest.h>

#include <Sacado.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "kernels/gauss_line.hpp"
#include "kernels/mortar_2d.hpp"
#include "kernels/mortar_integrate.hpp"
#include "kernels/surface_normals.hpp"
#include "kernels/weighted_gap.hpp"

namespace {

using grout::MortarPairResult;
using grout::MortarStatus;

// A = D_e M_e⁻¹ of the r-weighted LINE2 element matrices, by 8-point Gauss and Cramer's rule.
void weighted_dual_coefficients(double r1, double r2, double A[2][2]) {
  double De[2] = {0, 0}, Me[2][2] = {{0, 0}, {0, 0}};
  for (int g = 0; g < 8; ++g) {
    double xi, w;
    grout::gauss_line_point(8, g, xi, w);
    const double N[2] = {0.5 * (1 - xi), 0.5 * (1 + xi)};
    const double r = N[0] * r1 + N[1] * r2;
    for (int j = 0; j < 2; ++j) {
      De[j] += w * N[j] * r;
      for (int k = 0; k < 2; ++k) Me[j][k] += w * N[j] * N[k] * r;
    }
  }
  const double det = Me[0][0] * Me[1][1] - Me[0][1] * Me[1][0];
  const double Minv[2][2] = {{Me[1][1] / det, -Me[0][1] / det}, {-Me[1][0] / det, Me[0][0] / det}};
  for (int j = 0; j < 2; ++j)
    for (int k = 0; k < 2; ++k) A[j][k] = De[j] * Minv[j][k];
}

// D_j, M_jl of a slave segment xs (normals ns) and master xm by an independent rule: n_sub
// sub-intervals of the overlap [ξ_a, ξ_b] with 8 Gauss points each, η by projection along the
// interpolated normal, Φ from weighted_dual_coefficients.
void reference_pair(const double xs[2][2], const double ns[2][2], const double xm[2][2], int n_sub,
                    double D[2], double M[2][2]) {
  grout::MortarSlave2D<double> s;
  grout::mortar_slave_2d(xs, ns, s);
  double xi_a, xi_b;
  ASSERT_EQ(grout::mortar_overlap_2d(s, xm, xi_a, xi_b), MortarStatus::ok);
  double A[2][2];
  weighted_dual_coefficients(xs[0][0], xs[1][0], A);
  const double L2 = 0.5 * std::hypot(xs[1][0] - xs[0][0], xs[1][1] - xs[0][1]);
  D[0] = D[1] = 0.0;
  M[0][0] = M[0][1] = M[1][0] = M[1][1] = 0.0;
  const double h = (xi_b - xi_a) / n_sub;
  for (int i = 0; i < n_sub; ++i)
    for (int g = 0; g < 8; ++g) {
      double t, w;
      grout::gauss_line_point(8, g, t, w);
      const double xi = xi_a + h * (i + 0.5 * (1 + t));
      double x[2], n[2], eta;
      grout::slave_point_2d(xs, ns, xi, x, n);
      ASSERT_EQ(grout::project_along_normal_to_master_2d(xm, x, n, eta), MortarStatus::ok);
      const double Ns[2] = {0.5 * (1 - xi), 0.5 * (1 + xi)};
      const double Nm[2] = {0.5 * (1 - eta), 0.5 * (1 + eta)};
      const double wr = 2 * M_PI * x[0] * w * 0.5 * h * L2;
      for (int j = 0; j < 2; ++j) {
        const double phi = A[j][0] * Ns[0] + A[j][1] * Ns[1];
        D[j] += wr * phi;
        for (int l = 0; l < 2; ++l) M[j][l] += wr * phi * Nm[l];
      }
    }
}

// The launch's pair kernel with the axisymmetric option (the driver's path).
MortarStatus kernel_pair(const double xs[2][2], const double ns[2][2], const double xm[2][2],
                         MortarPairResult<double>& out) {
  double xs3[grout::max_face_nodes][3] = {}, ns3[grout::max_face_nodes][3] = {},
         xm3[grout::max_face_nodes][3] = {};
  for (int k = 0; k < 2; ++k)
    for (int d = 0; d < 2; ++d) xs3[k][d] = xs[k][d], ns3[k][d] = ns[k][d], xm3[k][d] = xm[k][d];
  grout::MortarOptions options;
  options.axisymmetric = true;
  return grout::MortarPairKernel<2>::integrate(2, xs3, ns3, 2, xm3, options, out);
}

void expect_pair_near(const MortarPairResult<double>& r, const double D[2], const double M[2][2],
                      double tol) {
  const double scale = std::abs(D[0]) + std::abs(D[1]);
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(r.D[j], D[j], tol * scale) << "D " << j;
    for (int l = 0; l < 2; ++l) EXPECT_NEAR(r.M[j][l], M[j][l], tol * scale) << "M " << j << l;
  }
}

}  // namespace

TEST(AxisymmetricDualBasis, ClosedFormIsTheWeightedBiorthogonalBasis) {
  for (const auto& r : {std::array<double, 2>{1.0, 1.0}, std::array<double, 2>{0.0, 0.7},
                        std::array<double, 2>{2.5, 0.0}, std::array<double, 2>{0.3, 4.1}}) {
    double A[2][2], Aref[2][2];
    ASSERT_EQ(grout::line2_dual_coefficients_axisymmetric(r[0], r[1], A), MortarStatus::ok);
    weighted_dual_coefficients(r[0], r[1], Aref);
    for (int j = 0; j < 2; ++j) {
      EXPECT_NEAR(A[0][j] + A[1][j], 1.0, 1e-14);  // Σ_j Φ_j = 1
      for (int k = 0; k < 2; ++k) EXPECT_NEAR(A[j][k], Aref[j][k], 1e-13);
    }
  }
  double A[2][2];
  grout::line2_dual_coefficients_axisymmetric(3.0, 3.0, A);
  EXPECT_NEAR(A[0][0], 2.0, 1e-14);  // the plane closed form for r₁ = r₂
  EXPECT_NEAR(A[0][1], -1.0, 1e-14);
  EXPECT_EQ(grout::line2_dual_coefficients_axisymmetric(0.0, 0.0, A), MortarStatus::degenerate);
  EXPECT_EQ(grout::line2_dual_coefficients_axisymmetric(-0.1, 1.0, A), MortarStatus::degenerate);
}

TEST(AxisymmetricMortarPair, FlatPairMatchesExactQuadrature) {
  // Slave on y = 1 from r = 0 (on the axis) to 0.9, normal −y; master on y = 1, reversed.
  const double ns[2][2] = {{0, -1}, {0, -1}};
  for (const double r0 : {0.0, 0.2}) {
    const double xs[2][2] = {{0.9, 1.0}, {r0, 1.0}};
    const double xm[2][2] = {{0.5, 1.0}, {1.4, 1.0}};
    MortarPairResult<double> r;
    ASSERT_EQ(kernel_pair(xs, ns, xm, r), MortarStatus::ok);
    double D[2], M[2][2];
    reference_pair(xs, ns, xm, 1, D, M);
    expect_pair_near(r, D, M, 1e-14);
    EXPECT_NEAR(r.overlap, M_PI * (0.9 * 0.9 - 0.5 * 0.5), 1e-14);  // ∫ 2π r dr on [0.5, 0.9]
  }
}

TEST(AxisymmetricMortarPair, CurvedPairMatchesCompositeQuadrature) {
  const double xs[2][2] = {{1.3, 1.02}, {0.4, 0.95}};
  double ns[2][2] = {{-0.2, -1.0}, {0.25, -1.0}};
  for (auto& n : ns) {
    const double l = std::hypot(n[0], n[1]);
    n[0] /= l, n[1] /= l;
  }
  const double xm[2][2] = {{0.6, 0.9}, {1.6, 0.97}};
  MortarPairResult<double> r;
  ASSERT_EQ(kernel_pair(xs, ns, xm, r), MortarStatus::ok);
  double D[2], M[2][2];
  reference_pair(xs, ns, xm, 200, D, M);
  expect_pair_near(r, D, M, 1e-9);  // a 6-point rule on a rational integrand
}

TEST(AxisymmetricMortarPair, PatchTestOnACoveredSlaveElement) {
  // Three master segments cover the slave [0.1, 1.0] on y = 0: Σ_l M_jl f(x²_l) = D_jj f(x¹_j)
  // for f = 1 and f = r (linear), and D_jj = ∫ N_j 2π r ds (biorthogonality).
  const double xs[2][2] = {{1.0, 0.0}, {0.1, 0.0}};
  const double ns[2][2] = {{0, 1}, {0, 1}};
  const double cuts[4] = {1.3, 0.77, 0.31, 0.0};
  double D[2] = {0, 0}, M1[2] = {0, 0}, Mr[2] = {0, 0};
  for (int p = 0; p < 3; ++p) {
    const double xm[2][2] = {{cuts[p + 1], 0.0}, {cuts[p], 0.0}};
    MortarPairResult<double> r;
    ASSERT_EQ(kernel_pair(xs, ns, xm, r), MortarStatus::ok);
    for (int j = 0; j < 2; ++j) {
      D[j] += r.D[j];
      for (int l = 0; l < 2; ++l) M1[j] += r.M[j][l], Mr[j] += r.M[j][l] * xm[l][0];
    }
  }
  const double L = 0.9;
  const double Dexact[2] = {2 * M_PI * L * (1.0 / 3 + 0.1 / 6), 2 * M_PI * L * (0.1 / 3 + 1.0 / 6)};
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(D[j], Dexact[j], 1e-14 * Dexact[0]);
    EXPECT_NEAR(M1[j], D[j], 1e-14 * Dexact[0]);
    EXPECT_NEAR(Mr[j], D[j] * xs[j][0], 1e-14 * Dexact[0]);
  }
}

TEST(AxisymmetricMortarPair, FarFromTheAxisItIsThePlaneKernelTimesTwoPiR) {
  const double shift = 1e6;
  const double xs[2][2] = {{shift + 1.3, 1.02}, {shift + 0.4, 0.95}};
  double ns[2][2] = {{-0.2, -1.0}, {0.25, -1.0}};
  const double xm[2][2] = {{shift + 0.6, 0.9}, {shift + 1.6, 0.97}};
  MortarPairResult<double> axi, plane;
  ASSERT_EQ(kernel_pair(xs, ns, xm, axi), MortarStatus::ok);
  ASSERT_EQ(grout::integrate_mortar_2d(xs, ns, xm, plane), MortarStatus::ok);
  const double scale = 2 * M_PI * shift;
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(axi.D[j] / scale, plane.D[j], 1e-5 * std::abs(plane.D[0]));
    for (int l = 0; l < 2; ++l) EXPECT_NEAR(axi.M[j][l] / scale, plane.M[j][l], 1e-5 * plane.D[0]);
  }
}

namespace {

constexpr int n_vars = 12;  // slave chain s0..s3 (x, y) then master m0, m1 (x, y)
constexpr int n_out = 8;    // D₀ D₁ M₀₀ M₀₁ M₁₀ M₁₁ g̃₀ g̃₁
using Fad = Sacado::Fad::SFad<double, n_vars>;

// The pair (slave s1→s2, master m0→m1), slave normals averaged from the chain.
template <class Scalar>
MortarStatus evaluate(const Scalar v[n_vars], Scalar out[n_out]) {
  Scalar ne[3][2];
  for (int e = 0; e < 3; ++e) {
    const Scalar xe[2][2] = {{v[2 * e], v[2 * e + 1]}, {v[2 * e + 2], v[2 * e + 3]}};
    grout::line2_normal(xe, ne[e]);
  }
  Scalar ns[2][2];
  for (int j = 0; j < 2; ++j) {
    for (int d = 0; d < 2; ++d) ns[j][d] = ne[j][d] + ne[j + 1][d];
    grout::normalize_vector<2>(ns[j]);
  }
  const Scalar xs[2][2] = {{v[2], v[3]}, {v[4], v[5]}};
  const Scalar xm[2][2] = {{v[8], v[9]}, {v[10], v[11]}};
  grout::MortarSlave2D<Scalar> s;
  grout::mortar_slave_2d(xs, ns, s);
  MortarPairResult<Scalar> r;
  const MortarStatus st = grout::integrate_mortar_2d_axisymmetric(s, xm, 6, r);
  Scalar g[grout::max_face_nodes];
  grout::weighted_gap_pair<2>(r, xs, ns, xm, g);
  out[0] = r.D[0], out[1] = r.D[1];
  out[2] = r.M[0][0], out[3] = r.M[0][1], out[4] = r.M[1][0], out[5] = r.M[1][1];
  out[6] = g[0], out[7] = g[1];
  return st;
}

}  // namespace

TEST(AxisymmetricMortarPair, FadMatchesCentralDifferences) {
  // The chain of test_kernels_mortar_2d_ad shifted to r ∈ [0.2, 3.2] (slave s1→s2 on [1.2, 2.2]).
  const double base[n_vars] = {0.2, 0.0, 1.2, 0.0, 2.2, 0.0, 3.2, -0.15, 2.8, -0.05, 1.5, -0.05};
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  for (int t = 0; t < 10; ++t) {
    double v[n_vars];
    for (int i = 0; i < n_vars; ++i) v[i] = base[i] + u(rng);
    Fad x[n_vars], y[n_out];
    for (int i = 0; i < n_vars; ++i) x[i] = Fad(n_vars, i, v[i]);
    ASSERT_EQ(evaluate(x, y), MortarStatus::ok);
    double largest = 0.0;
    for (int i = 0; i < n_vars; ++i) {
      double vp[n_vars], vm[n_vars], fp[n_out], fm[n_out];
      for (int k = 0; k < n_vars; ++k) vp[k] = vm[k] = v[k];
      const double h = 1e-6;
      vp[i] += h, vm[i] -= h;
      evaluate(vp, fp);
      evaluate(vm, fm);
      for (int o = 0; o < n_out; ++o) {
        EXPECT_NEAR(y[o].dx(i), (fp[o] - fm[o]) / (2 * h), 1e-7) << "out " << o << " var " << i;
        largest = std::max(largest, std::abs(y[o].dx(i)));
      }
    }
    EXPECT_GT(largest, 0.1);
  }
}
