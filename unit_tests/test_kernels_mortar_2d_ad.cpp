// Sacado forward-AD derivatives of the 2D mortar kernel (D, M, weighted gap g̃, with the slave
// nodal normals computed from the coordinates) against central finite differences, on randomly
// perturbed configurations (fixed seed) and across an overlap-topology switch.
#include <gtest/gtest.h>

#include <Sacado.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "kernels/mortar_2d.hpp"
#include "kernels/surface_normals.hpp"
#include "kernels/weighted_gap.hpp"

namespace {

using grout::MortarPairResult;
using grout::MortarStatus;

constexpr int n_vars = 12;  // slave chain s0..s3 (x, y) then master m0, m1 (x, y)
constexpr int n_out = 8;    // D₀ D₁ M₀₀ M₀₁ M₁₀ M₁₁ g̃₀ g̃₁
using Fad = Sacado::Fad::SFad<double, n_vars>;

// The pair (slave s1→s2, master m0→m1); slave nodal normals averaged over (s0 s1, s1 s2) and
// (s1 s2, s2 s3), so the outputs depend on all twelve coordinates.
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
  MortarPairResult<Scalar> r;
  const MortarStatus s = grout::integrate_mortar_2d(xs, ns, xm, r);
  Scalar g[grout::max_face_nodes];
  grout::weighted_gap_pair<2>(r, xs, ns, xm, g);
  out[0] = r.D[0], out[1] = r.D[1];
  out[2] = r.M[0][0], out[3] = r.M[0][1], out[4] = r.M[1][0], out[5] = r.M[1][1];
  out[6] = g[0], out[7] = g[1];
  return s;
}

// Values and AD Jacobian at v.
MortarStatus jacobian_ad(const double v[n_vars], double val[n_out], double J[n_out][n_vars]) {
  Fad x[n_vars], y[n_out];
  for (int i = 0; i < n_vars; ++i) x[i] = Fad(n_vars, i, v[i]);
  const MortarStatus s = evaluate(x, y);
  for (int o = 0; o < n_out; ++o) {
    val[o] = y[o].val();
    for (int i = 0; i < n_vars; ++i) J[o][i] = y[o].dx(i);
  }
  return s;
}

// Finite-difference column i: central (side 0), forward (+1) or backward (−1).
void fd_column(const double v[n_vars], int i, double h, int side, double col[n_out]) {
  double vp[n_vars], vm[n_vars], fp[n_out], fm[n_out];
  for (int k = 0; k < n_vars; ++k) vp[k] = vm[k] = v[k];
  vp[i] += side >= 0 ? h : 0.0;
  vm[i] -= side <= 0 ? h : 0.0;
  evaluate(vp, fp);
  evaluate(vm, fm);
  const double step = side == 0 ? 2 * h : h;
  for (int o = 0; o < n_out; ++o) col[o] = (fp[o] - fm[o]) / step;
}

void expect_ad_matches_fd(const double v[n_vars], double tol) {
  double val[n_out], J[n_out][n_vars];
  ASSERT_EQ(jacobian_ad(v, val, J), MortarStatus::ok);
  double largest = 0.0, worst = 0.0;
  for (int i = 0; i < n_vars; ++i) {
    double col[n_out];
    fd_column(v, i, 1e-6, 0, col);
    for (int o = 0; o < n_out; ++o) {
      EXPECT_NEAR(J[o][i], col[o], tol) << "out " << o << " var " << i;
      largest = std::max(largest, std::abs(J[o][i]));
      worst = std::max(worst, std::abs(J[o][i] - col[o]));
    }
  }
  EXPECT_GT(largest, 0.1);  // a non-trivial Jacobian
  if (std::getenv("GROUT_VERBOSE"))
    std::printf("max |J| %.3e, max |J - FD| %.3e\n", largest, worst);
}

// Slave chain along x (s1 = (0,0) with normal (0,−1), s2 = (1,0)), master below it (the slave
// normal side), oriented against the slave;
// the left master node at x = xm0_left, so its projection is ξ ≈ 2·xm0_left − 1.
void base_configuration(double v[n_vars], double xm0_left) {
  const double base[n_vars] = {-1.0, 0.0,   0.0, 0.0,   1.0,      0.0,
                               2.0,  -0.15, 1.6, -0.05, xm0_left, -0.05};
  for (int i = 0; i < n_vars; ++i) v[i] = base[i];
}

}  // namespace

TEST(Mortar2DAD, FadMatchesCentralDifferencesOnRandomConfigurations) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  for (int t = 0; t < 20; ++t) {
    double v[n_vars];
    base_configuration(v, 0.3);
    for (double& c : v) c += u(rng);
    expect_ad_matches_fd(v, 1e-8);
  }
}

TEST(Mortar2DAD, FadMatchesDifferencesAcrossOverlapTopologySwitch) {
  // End point ξ_a is the projection of master node m1 for x_m1 > 0 and slave node s1 (ξ = −1)
  // for x_m1 < 0. FD with h ≪ ε stays on one side; at the switch, one-sided differences give
  // the one-sided limits of the derivative.
  const int var = 10;  // x of master node m1
  for (double eps : {1e-3, -1e-3}) {
    double v[n_vars];
    base_configuration(v, eps);
    expect_ad_matches_fd(v, 1e-8);
    double val[n_out], J[n_out][n_vars];
    jacobian_ad(v, val, J);
    if (eps < 0.0)
      EXPECT_EQ(J[0][var], 0.0);  // slave-node end point: D does not see the master node
    else
      EXPECT_GT(std::abs(J[0][var]), 0.1);
  }
  double v0[n_vars], vl[n_vars], vr[n_vars];
  base_configuration(v0, 0.0);
  base_configuration(vl, -1e-10);
  base_configuration(vr, 1e-10);
  double val_l[n_out], val_r[n_out], J_l[n_out][n_vars], J_r[n_out][n_vars];
  jacobian_ad(vl, val_l, J_l);
  jacobian_ad(vr, val_r, J_r);
  double fwd[n_out], bwd[n_out];
  fd_column(v0, var, 1e-7, +1, fwd);
  fd_column(v0, var, 1e-7, -1, bwd);
  for (int o = 0; o < n_out; ++o) {
    EXPECT_NEAR(val_l[o], val_r[o], 1e-9);  // values continuous across the switch
    EXPECT_NEAR(fwd[o], J_r[o][var], 1e-6);
    EXPECT_NEAR(bwd[o], J_l[o][var], 1e-6);
  }
  EXPECT_GT(std::abs(J_r[0][var] - J_l[0][var]), 0.1);  // a genuine kink
}

TEST(Mortar2DAD, CollocationAndDualBasisCompileWithFad) {
  double v[n_vars];
  base_configuration(v, 0.3);
  Fad xs[2][2], ns[2][2], xm[2][2];
  for (int k = 0; k < 2; ++k)
    for (int d = 0; d < 2; ++d) {
      xs[k][d] = Fad(n_vars, 2 + 2 * k + d, v[2 + 2 * k + d]);
      ns[k][d] = d == 1 ? 1.0 : 0.0;
      xm[k][d] = Fad(n_vars, 8 + 2 * k + d, v[8 + 2 * k + d]);
    }
  MortarPairResult<Fad> r;
  EXPECT_EQ(grout::integrate_mortar_2d_collocation(xs, ns, xm, 50, r), MortarStatus::ok);
  EXPECT_GT(r.overlap.val(), 0.0);
  Fad A[2][2];
  ASSERT_EQ(grout::dual_basis_coefficients_line2(xs, A), MortarStatus::ok);
  EXPECT_NEAR(A[0][1].val(), -1.0, 1e-14);
  for (int i = 0; i < n_vars; ++i) EXPECT_NEAR(A[0][0].dx(i), 0.0, 1e-12);
}
