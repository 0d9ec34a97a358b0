// The small dense LU (kernels/small_dense_lu.hpp) against independent references: A A⁻¹ = I
// and A x = b on random matrices (fixed seed), the exact inverse of a permutation that needs
// pivoting, singular detection with the absolute and relative thresholds, and the derivative
// of A⁻¹ through Sacado against d(A⁻¹) = −A⁻¹ dA A⁻¹.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "kernels/sacado_fad.hpp"
#include "kernels/small_dense_lu.hpp"

namespace {

using grout::small_lu_factor;
using grout::small_lu_invert;
using grout::small_lu_solve;

// A random n×n matrix with entries in [−1, 1] (row stride lda), diagonally unweighted: its
// condition number is moderate for the sizes used, and pivoting happens.
std::vector<double> random_matrix(int n, int lda, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> a(std::size_t(n) * lda, 0.0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) a[i * lda + j] = u(rng);
  return a;
}

// max |(A B − I)_ij| and the 1-norm condition estimate |A|_1 |B|_1.
double identity_error(int n, const std::vector<double>& a, int lda, const std::vector<double>& b,
                      int ldb, double* condition) {
  double error = 0.0, norm_a = 0.0, norm_b = 0.0;
  for (int j = 0; j < n; ++j) {
    double ca = 0.0, cb = 0.0;
    for (int i = 0; i < n; ++i) ca += std::abs(a[i * lda + j]), cb += std::abs(b[i * ldb + j]);
    norm_a = std::max(norm_a, ca), norm_b = std::max(norm_b, cb);
  }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double s = 0.0;
      for (int k = 0; k < n; ++k) s += a[i * lda + k] * b[k * ldb + j];
      error = std::max(error, std::abs(s - (i == j ? 1.0 : 0.0)));
    }
  *condition = norm_a * norm_b;
  return error;
}

TEST(SmallDenseLu, InverseOfRandomMatricesIsTheInverseToRoundOff) {
  std::mt19937 rng(20261202);
  for (const int n : {1, 2, 3, 4, 5, 8, 13, 24}) {
    for (int trial = 0; trial < 20; ++trial) {
      const int lda = n + trial % 3;  // contiguous and strided storage
      const std::vector<double> a = random_matrix(n, lda, rng);
      std::vector<double> lu = a, inverse(std::size_t(n) * n, -7.0);
      std::vector<int> pivot(std::size_t(n), -1);
      ASSERT_TRUE(small_lu_invert(n, lu.data(), lda, pivot.data(), inverse.data(), n));
      double condition = 0.0;
      const double error = identity_error(n, a, lda, inverse, n, &condition);
      // Backward-stable LU: |A A⁻¹ − I| ≲ c n ε κ(A); c = 10.
      EXPECT_LT(error, 10.0 * n * 2.2e-16 * condition) << "n = " << n << ", trial " << trial;
      for (int k = 0; k < n; ++k) EXPECT_GE(pivot[k], k);
    }
  }
}

TEST(SmallDenseLu, SolveGivesTheManufacturedSolution) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const int n : {1, 3, 6, 11}) {
    const std::vector<double> a = random_matrix(n, n, rng);
    std::vector<double> x(static_cast<std::size_t>(n)), b(static_cast<std::size_t>(n), 0.0);
    for (double& v : x) v = u(rng);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) b[i] += a[i * n + j] * x[j];
    std::vector<double> lu = a;
    std::vector<int> pivot(static_cast<std::size_t>(n));
    ASSERT_TRUE(small_lu_factor(n, lu.data(), n, pivot.data()));
    // Strided right-hand side: every other entry of a buffer.
    std::vector<double> strided(std::size_t(2 * n), 99.0);
    for (int i = 0; i < n; ++i) strided[2 * i] = b[i];
    small_lu_solve(n, lu.data(), n, pivot.data(), strided.data(), 2);
    double inverse_norm = 0.0;  // |A⁻¹|_∞ bounds the error: |x − x̂| ≲ n ε |A⁻¹| |A| |x|
    {
      std::vector<double> work = a, inverse(std::size_t(n) * n);
      ASSERT_TRUE(small_lu_invert(n, work.data(), n, pivot.data(), inverse.data(), n));
      for (int i = 0; i < n; ++i) {
        double s = 0.0;
        for (int j = 0; j < n; ++j) s += std::abs(inverse[i * n + j]);
        inverse_norm = std::max(inverse_norm, s);
      }
    }
    for (int i = 0; i < n; ++i) {
      EXPECT_NEAR(strided[2 * i], x[i], 10.0 * n * n * 2.2e-16 * inverse_norm) << "n = " << n;
      EXPECT_EQ(strided[2 * i + 1], 99.0);  // the gaps are left alone
    }
  }
}

TEST(SmallDenseLu, PermutationNeedsPivotingAndIsInvertedExactly) {
  // A cyclic permutation: every leading diagonal entry is 0, so only pivoting finds a pivot;
  // its inverse is its transpose, exactly.
  const int n = 4;
  double a[n][n] = {}, inverse[n][n];
  for (int i = 0; i < n; ++i) a[i][(i + 1) % n] = 1.0;
  double lu[n][n];
  std::copy(&a[0][0], &a[0][0] + n * n, &lu[0][0]);
  int pivot[n];
  ASSERT_TRUE(small_lu_invert(n, &lu[0][0], n, pivot, &inverse[0][0], n));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) EXPECT_EQ(inverse[i][j], a[j][i]) << i << ", " << j;
}

TEST(SmallDenseLu, SingularMatricesAreDetected) {
  int pivot[3];
  // Rank 2: row 3 = (row 1 + row 2) / 2, with multipliers 1/2, 3/4 and 1/2 in the
  // elimination (binary-exact), so the last pivot is exactly 0.
  double rank2[3][3] = {{4.0, 1.0, 2.0}, {2.0, 3.0, 1.0}, {3.0, 2.0, 1.5}};
  EXPECT_FALSE(small_lu_factor(3, &rank2[0][0], 3, pivot));
  // A zero column: no pivot at all in it.
  double zero_column[3][3] = {{1.0, 0.0, 2.0}, {3.0, 0.0, 1.0}, {-1.0, 0.0, 4.0}};
  double inverse[3][3] = {};
  EXPECT_FALSE(small_lu_invert(3, &zero_column[0][0], 3, pivot, &inverse[0][0], 3));
  // Nearly singular, 1e-15 relative: not singular against 0, singular against 1e-14 · max|a|
  // (the dual basis's threshold, kernels/dual_basis.hpp).
  const double near[2][2] = {{1.0, 1.0}, {1.0, 1.0 + 1e-15}};
  double work[2][2];
  std::copy(&near[0][0], &near[0][0] + 4, &work[0][0]);
  EXPECT_TRUE(small_lu_factor(2, &work[0][0], 2, pivot, 0.0));
  std::copy(&near[0][0], &near[0][0] + 4, &work[0][0]);
  EXPECT_FALSE(small_lu_factor(2, &work[0][0], 2, pivot, 1e-14));
}

TEST(SmallDenseLu, DerivativeOfTheInverseIsMinusAinvDaAinv) {
  // A(t) = A0 + t dA with Sacado forward AD: d(A⁻¹)/dt = −A⁻¹ dA A⁻¹ (differentiating
  // A A⁻¹ = I), the inverse from the double LU as reference.
  using Fad = Sacado::Fad::SFad<double, 1>;
  std::mt19937 rng(3);
  const int n = 5;
  const std::vector<double> a0 = random_matrix(n, n, rng), da = random_matrix(n, n, rng);
  Fad a[n * n], inverse[n * n];
  for (int k = 0; k < n * n; ++k) {
    a[k] = Fad(1, 0, a0[std::size_t(k)]);
    a[k].fastAccessDx(0) = da[std::size_t(k)];
  }
  int pivot[n];
  ASSERT_TRUE(small_lu_invert(n, a, n, pivot, inverse, n));
  std::vector<double> work = a0, reference(std::size_t(n) * n);
  ASSERT_TRUE(small_lu_invert(n, work.data(), n, pivot, reference.data(), n));
  double scale = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double d = 0.0;  // −(A⁻¹ dA A⁻¹)_ij
      for (int k = 0; k < n; ++k)
        for (int l = 0; l < n; ++l)
          d -= reference[i * n + k] * da[std::size_t(k * n + l)] * reference[l * n + j];
      scale = std::max(scale, std::abs(d));
      EXPECT_NEAR(inverse[i * n + j].val(), reference[i * n + j], 1e-13);
      EXPECT_NEAR(inverse[i * n + j].dx(0), d, 1e-11 * std::max(1.0, std::abs(d)))
          << i << ", " << j;
    }
  EXPECT_GT(scale, 0.0);
}

}  // namespace
