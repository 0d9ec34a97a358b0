// Pair kernels with the full D (kernels/mortar_matrices.hpp) and the multiplier-basis choice
// (kernels/multiplier_basis.hpp) against hand integration: the standard basis gives
// D_jk = ∫ N_j N_k dA over the overlap (LINE2 partly covered, TRI3 and a parallelogram QUAD4
// fully covered: the element mass matrices), M_jl = ∫ N_j N²_l dA by an independent Gauss rule;
// the dual basis through the same kernels reproduces the dual pair kernels' D_jj and M_jl.
#include <gtest/gtest.h>

#include <cmath>

#include "kernels/mortar_integrate.hpp"
#include "kernels/mortar_matrices.hpp"

namespace {

using grout::max_face_nodes;
using grout::MortarPairMatrices;
using grout::MortarPairResult;
using grout::MortarStatus;
using grout::MultiplierBasis;

// 8-point Gauss–Legendre on [−1, 1]: the independent reference rule.
constexpr double gl8_x[8] = {-0.96028985649753623168, -0.79666647741362673959,
                             -0.52553240991632898582, -0.18343464249564980494,
                             0.18343464249564980494,  0.52553240991632898582,
                             0.79666647741362673959,  0.96028985649753623168};
constexpr double gl8_w[8] = {0.10122853629037625915, 0.22238103445337447054, 0.31370664587788728734,
                             0.36268378337836198297, 0.36268378337836198297, 0.31370664587788728734,
                             0.22238103445337447054, 0.10122853629037625915};

TEST(MultiplierBasis, Coefficients) {
  double x2[max_face_nodes][3] = {{0, 0, 0}, {2, 1, 0}};
  double A[max_face_nodes][max_face_nodes];
  ASSERT_EQ(grout::multiplier_basis_coefficients(MultiplierBasis::dual, 2, 2, x2, A),
            MortarStatus::ok);
  EXPECT_EQ(A[0][0], 2.0);
  EXPECT_EQ(A[0][1], -1.0);
  ASSERT_EQ(grout::multiplier_basis_coefficients(MultiplierBasis::standard, 2, 2, x2, A),
            MortarStatus::ok);
  EXPECT_EQ(A[0][0], 1.0);
  EXPECT_EQ(A[0][1], 0.0);
  double quad[max_face_nodes][3] = {{0, 0, 0}, {2, 0, 0}, {2.5, 1, 0}, {0.5, 1, 0}};
  ASSERT_EQ(grout::multiplier_basis_coefficients(MultiplierBasis::standard, 3, 4, quad, A),
            MortarStatus::ok);
  for (int j = 0; j < 4; ++j)
    for (int k = 0; k < 4; ++k) EXPECT_EQ(A[j][k], j == k ? 1.0 : 0.0);
  double dual[max_face_nodes][max_face_nodes];
  ASSERT_EQ(grout::dual_basis_coefficients_3d(4, quad, dual), MortarStatus::ok);
  ASSERT_EQ(grout::multiplier_basis_coefficients(MultiplierBasis::dual, 3, 4, quad, A),
            MortarStatus::ok);
  for (int j = 0; j < 4; ++j)
    for (int k = 0; k < 4; ++k) EXPECT_EQ(A[j][k], dual[j][k]);
  double line[max_face_nodes][3] = {{1, 1, 0}, {1, 1, 0}};
  EXPECT_EQ(grout::multiplier_basis_coefficients(MultiplierBasis::standard, 2, 2, line, A),
            MortarStatus::degenerate);
}

// Slave LINE2 (0,0)→(2,0) (normal −y), master (3,−g)→(0.5,−g): overlap x ∈ [0.5, 2].
TEST(MortarMatrices, Line2PartialOverlapStandard) {
  const double xs[2][2] = {{0, 0}, {2, 0}}, ns[2][2] = {{0, -1}, {0, -1}};
  const double xm[2][2] = {{3, -0.01}, {0.5, -0.01}};
  grout::MortarSlave2D<double> slave;
  ASSERT_EQ(grout::mortar_slave_2d(xs, ns, slave), MortarStatus::ok);
  double A[max_face_nodes][max_face_nodes];
  double xs3[max_face_nodes][3] = {{0, 0, 0}, {2, 0, 0}};
  grout::multiplier_basis_coefficients(MultiplierBasis::standard, 2, 2, xs3, A);
  MortarPairMatrices<double> out;
  ASSERT_EQ(grout::integrate_mortar_matrices_2d(slave, A, xm, 5, out), MortarStatus::ok);
  double D[2][2] = {}, M[2][2] = {};
  for (int g = 0; g < 8; ++g) {  // x = 1.25 + 0.75 t on [0.5, 2]
    const double x = 1.25 + 0.75 * gl8_x[g], w = 0.75 * gl8_w[g];
    const double N[2] = {1 - x / 2, x / 2}, Nm[2] = {(x - 0.5) / 2.5, (3 - x) / 2.5};
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) D[j][k] += w * N[j] * N[k], M[j][k] += w * N[j] * Nm[k];
  }
  EXPECT_NEAR(D[0][1], 0.28125, 1e-15);  // hand integration of x/2 − x²/4 over [0.5, 2]
  EXPECT_NEAR(out.overlap, 1.5, 1e-15);
  for (int j = 0; j < 2; ++j)
    for (int k = 0; k < 2; ++k) {
      EXPECT_NEAR(out.D[j][k], D[j][k], 1e-15) << j << k;
      EXPECT_NEAR(out.M[j][k], M[j][k], 1e-15) << j << k;
    }
}

// The dual basis through the matrices kernels: row sums of D and M equal the dual kernels'.
TEST(MortarMatrices, DualThroughMatricesEqualsDualKernels) {
  const double xs[max_face_nodes][3] = {{0, 0, 0}, {2, 0.3, 0}};
  const double ns[max_face_nodes][3] = {{-0.1, -1, 0}, {0.2, -1, 0}};
  const double xm[max_face_nodes][3] = {{3, -0.05, 0}, {0.5, -0.02, 0}};
  double nsu[max_face_nodes][3] = {};
  for (int a = 0; a < 2; ++a) {
    const double l = std::hypot(ns[a][0], ns[a][1]);
    nsu[a][0] = ns[a][0] / l, nsu[a][1] = ns[a][1] / l;
  }
  grout::MortarOptions options;
  for (auto scheme : {grout::MortarIntegration::exact, grout::MortarIntegration::collocation}) {
    options.scheme = scheme;
    using Kernel = grout::MortarPairKernel<2>;
    Kernel::SlaveFace<double> slave;
    Kernel::prepare(2, xs, nsu, options, MultiplierBasis::dual, slave);
    MortarPairMatrices<double> full;
    MortarPairResult<double> diag;
    ASSERT_EQ(Kernel::integrate(slave, 2, xm, options, full), MortarStatus::ok);
    ASSERT_EQ(Kernel::integrate(slave, 2, xm, options, diag), MortarStatus::ok);
    for (int j = 0; j < 2; ++j) {
      EXPECT_NEAR(full.D[j][0] + full.D[j][1], diag.D[j], 1e-15);
      for (int l = 0; l < 2; ++l) EXPECT_NEAR(full.M[j][l], diag.M[j][l], 1e-15);
    }
  }
}

/// ∫ over the slave face (TRI3 by the collapsed 8×8 rule, QUAD4 by 8×8) of g(ξ) dA.
template <class G>
double slave_integral(int n, const double x[max_face_nodes][3], G&& g) {
  double sum = 0.0;
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b) {
      double xi[2], w;
      if (n == 4) {
        xi[0] = gl8_x[a], xi[1] = gl8_x[b], w = gl8_w[a] * gl8_w[b];
      } else {  // Duffy: ξ = (1+u)/2, η = (1−ξ)(1+v)/2
        xi[0] = 0.5 * (1 + gl8_x[a]);
        xi[1] = (1 - xi[0]) * 0.5 * (1 + gl8_x[b]);
        w = gl8_w[a] * gl8_w[b] * 0.25 * (1 - xi[0]);
      }
      sum += w * grout::face_area_element(n, x, xi) * g(xi);
    }
  return sum;
}

// Slaves fully covered by a larger axis-aligned QUAD4 master at z = 0.01 (normal −z): the
// standard D is the element mass matrix, M_jl = ∫ N_j N²_l, both by the reference rule.
TEST(MortarMatrices, FullyCoveredStandard3D) {
  const double tri[max_face_nodes][3] = {{0, 0, 0}, {1, 0.2, 0}, {0.3, 0.9, 0}};
  const double quad[max_face_nodes][3] = {{0, 0, 0}, {1, 0, 0}, {1.4, 0.8, 0}, {0.4, 0.8, 0}};
  // Master square [−1, 2]², node order (−1,−1), (−1,2), (2,2), (2,−1): ξ from y, η from x.
  const double xm[max_face_nodes][3] = {{-1, -1, 0.01}, {-1, 2, 0.01}, {2, 2, 0.01}, {2, -1, 0.01}};
  for (int n : {3, 4}) {
    const auto& xs = n == 3 ? tri : quad;
    double A[max_face_nodes][max_face_nodes];
    ASSERT_EQ(grout::multiplier_basis_coefficients(MultiplierBasis::standard, 3, n, xs, A),
              MortarStatus::ok);
    MortarPairMatrices<double> out;
    ASSERT_EQ(grout::integrate_mortar_matrices_3d(n, xs, A, 4, xm, out), MortarStatus::ok);
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        const double ref = slave_integral(n, xs, [&](const double xi[2]) {
          double N[max_face_nodes];
          grout::face_shape_functions(n, xi, N);
          return N[j] * N[k];
        });
        EXPECT_NEAR(out.D[j][k], ref, 1e-15) << n << " D " << j << k;
      }
      for (int l = 0; l < 4; ++l) {
        const double ref = slave_integral(n, xs, [&](const double xi[2]) {
          double N[max_face_nodes], x[3], Nm[max_face_nodes];
          grout::face_shape_functions(n, xi, N);
          grout::face_position(n, xs, xi, x);
          const double eta[2] = {2 * (x[1] + 1) / 3 - 1, 2 * (x[0] + 1) / 3 - 1};
          grout::face_shape_functions(4, eta, Nm);
          return N[j] * Nm[l];
        });
        EXPECT_NEAR(out.M[j][l], ref, 1e-15) << n << " M " << j << l;
      }
    }
    if (n == 3) {  // the TRI3 mass matrix in closed form, area 0.435: A(1 + δ_jk)/12
      const double area = 0.5 * (1 * 0.9 - 0.2 * 0.3);
      EXPECT_NEAR(out.D[0][0], area / 6, 1e-15);
      EXPECT_NEAR(out.D[0][1], area / 12, 1e-15);
    }
  }
}

}  // namespace
