// The free rigid modes of a body (kernels/free_rigid_modes.hpp) against hand-derived ones: a
// 2D block held in x on its top edge turns about any point of that edge and moves in y (two
// free modes, one turning); held in x and y there, or in y at two nodes, it cannot turn; a 3D
// box held in x and y on its top face turns about the two horizontal axes and moves in z, and
// the quarter model of it (symmetry planes x = 0, y = 0) only moves in z. Each free mode
// moves no prescribed dof, the basis is G-orthonormal, and the free part of an exact free
// rigid motion is that motion. Jacobi's eigenvectors satisfy A v = λ v (random symmetric 6×6).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "kernels/free_rigid_modes.hpp"

namespace {

using grout::max_rigid_modes;

struct Body {
  int dim = 2;
  std::vector<std::array<double, 3>> X;
  std::vector<std::array<bool, 3>> fixed;
  double X0[3] = {0.0, 0.0, 0.0};
  double L = 1.0;
};

// Nodes of [0, 2] x [-1, 0] (x [0, 1] in 3D) on a grid of spacing 0.25, none prescribed.
Body grid(int dim) {
  Body b;
  b.dim = dim;
  const int nz = dim == 3 ? 4 : 0;
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 4; ++j)
      for (int k = 0; k <= nz; ++k) {
        if (dim == 2)
          b.X.push_back({0.25 * i, -0.25 * j, 0.0});
        else
          b.X.push_back({0.25 * i, 0.25 * k, -0.25 * j});
        b.fixed.push_back({false, false, false});
      }
  b.X0[0] = 1.0;
  b.L = 0.8;
  return b;
}

void grams(const Body& b, double G[max_rigid_modes][max_rigid_modes],
           double P[max_rigid_modes][max_rigid_modes]) {
  const int n = grout::rigid_mode_count(b.dim);
  for (int a = 0; a < n; ++a)
    for (int c = 0; c < n; ++c) G[a][c] = P[a][c] = 0.0;
  for (std::size_t i = 0; i < b.X.size(); ++i) {
    double r[max_rigid_modes][3];
    for (int a = 0; a < n; ++a) grout::rigid_mode_value(b.dim, a, b.X[i].data(), b.X0, b.L, r[a]);
    for (int c = 0; c < b.dim; ++c)
      for (int a = 0; a < n; ++a)
        for (int e = 0; e < n; ++e) {
          G[a][e] += r[a][c] * r[e][c];
          if (b.fixed[i][c]) P[a][e] += r[a][c] * r[e][c];
        }
  }
}

grout::FreeRigidModes modes_of(const Body& b) {
  double G[max_rigid_modes][max_rigid_modes], P[max_rigid_modes][max_rigid_modes];
  grams(b, G, P);
  grout::FreeRigidModes m;
  EXPECT_TRUE(grout::free_rigid_modes(b.dim, G, P, m));
  // G-orthonormal, and no prescribed dof moves.
  for (int k = 0; k < m.count; ++k)
    for (int l = 0; l < m.count; ++l) {
      double g = 0.0;
      for (int a = 0; a < m.n; ++a)
        for (int e = 0; e < m.n; ++e) g += m.basis[k][a] * G[a][e] * m.basis[l][e];
      EXPECT_NEAR(g, k == l ? 1.0 : 0.0, 1e-12);
    }
  for (int k = 0; k < m.count; ++k)
    for (std::size_t i = 0; i < b.X.size(); ++i) {
      double w[3];
      grout::rigid_motion_value(b.dim, m.basis[k], b.X[i].data(), b.X0, b.L, w);
      for (int c = 0; c < b.dim; ++c)
        if (b.fixed[i][c]) EXPECT_NEAR(w[c], 0.0, 1e-12);
    }
  return m;
}

TEST(FreeRigidModes, BlockHeldInXOnTopTurns) {
  Body b = grid(2);
  for (std::size_t i = 0; i < b.X.size(); ++i)
    if (b.X[i][1] == 0.0) b.fixed[i][0] = true;
  const auto m = modes_of(b);
  EXPECT_EQ(m.count, 2);
  EXPECT_TRUE(m.rotates);
  EXPECT_FALSE(m.translation_free[0]);
  EXPECT_TRUE(m.translation_free[1]);
  // The free part of a turn by 0.3 about (0.7, 0) plus u_y = 0.05 is that motion.
  double b_moments[max_rigid_modes] = {};
  std::vector<std::array<double, 2>> field;
  for (const auto& X : b.X) field.push_back({-0.3 * (X[1] - 0.0), 0.3 * (X[0] - 0.7) + 0.05});
  for (std::size_t i = 0; i < b.X.size(); ++i)
    for (int a = 0; a < 3; ++a) {
      double r[3];
      grout::rigid_mode_value(2, a, b.X[i].data(), b.X0, b.L, r);
      b_moments[a] += r[0] * field[i][0] + r[1] * field[i][1];
    }
  double beta[max_rigid_modes];
  grout::free_rigid_part(m, b_moments, beta);
  for (std::size_t i = 0; i < b.X.size(); ++i) {
    double w[3];
    grout::rigid_motion_value(2, beta, b.X[i].data(), b.X0, b.L, w);
    EXPECT_NEAR(w[0], field[i][0], 1e-12);
    EXPECT_NEAR(w[1], field[i][1], 1e-12);
  }
}

TEST(FreeRigidModes, BlockHeldInXAndYOnTopOrYAtTwoNodesDoesNotTurn) {
  Body b = grid(2);
  for (std::size_t i = 0; i < b.X.size(); ++i)
    if (b.X[i][1] == 0.0) b.fixed[i] = {true, true, false};
  auto m = modes_of(b);
  EXPECT_EQ(m.count, 0);
  EXPECT_FALSE(m.rotates);

  Body c = grid(2);
  c.fixed[0][1] = c.fixed[c.X.size() - 1][1] = true;  // u_y at (0, 0) and (2, -1)
  m = modes_of(c);
  EXPECT_EQ(m.count, 1);
  EXPECT_FALSE(m.rotates);
  EXPECT_TRUE(m.translation_free[0]);
}

TEST(FreeRigidModes, BoxHeldOnTopTurnsAboutHorizontalAxesQuarterModelDoesNot) {
  Body b = grid(3);
  for (std::size_t i = 0; i < b.X.size(); ++i)
    if (b.X[i][2] == 0.0) b.fixed[i][0] = b.fixed[i][1] = true;
  auto m = modes_of(b);
  EXPECT_EQ(m.count, 3);  // u_z, turns about x and y through the top face
  EXPECT_TRUE(m.rotates);
  EXPECT_TRUE(m.translation_free[2]);

  for (std::size_t i = 0; i < b.X.size(); ++i) {  // symmetry planes x = 0 and y = 0
    if (b.X[i][0] == 0.0) b.fixed[i][0] = true;
    if (b.X[i][1] == 0.0) b.fixed[i][1] = true;
  }
  m = modes_of(b);
  EXPECT_EQ(m.count, 1);
  EXPECT_FALSE(m.rotates);
}

TEST(FreeRigidModes, JacobiEigenpairs) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double A[max_rigid_modes][max_rigid_modes], A0[max_rigid_modes][max_rigid_modes],
      V[max_rigid_modes][max_rigid_modes];
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j <= i; ++j) A[i][j] = A[j][i] = A0[i][j] = A0[j][i] = u(rng);
  grout::symmetric_jacobi_eigen(6, A, V);
  for (int e = 0; e < 6; ++e)
    for (int i = 0; i < 6; ++i) {
      double Av = 0.0;
      for (int j = 0; j < 6; ++j) Av += A0[i][j] * V[j][e];
      EXPECT_NEAR(Av, A[e][e] * V[i][e], 1e-13);
    }
}

}  // namespace
