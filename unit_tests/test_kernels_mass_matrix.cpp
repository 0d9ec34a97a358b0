// Element mass matrices (kernels/mass_matrix.hpp) against closed forms and an independent
// brute-force quadrature.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "kernels/mass_matrix.hpp"
#include "unit_tests/distorted_elements.hpp"

namespace {

using grout::ElementStatus;
using grout::Topology;
using grout_test::distorted_elements;
using grout_test::Element;

TEST(MassMatrix, UnitSquareAndTriangleClosedForms) {
  // Unit square, ρ = 3: M = ρ/36 [4 2 1 2; 2 4 2 1; 1 2 4 2; 2 1 2 4] (Hughes, eq. 7.2.6 form).
  const double square[8] = {0, 0, 1, 0, 1, 1, 0, 1};
  double M[16];
  ASSERT_EQ(grout::element_mass(Topology::quad4, 2, square, 3.0, false, M), ElementStatus::ok);
  const double q[4][4] = {{4, 2, 1, 2}, {2, 4, 2, 1}, {1, 2, 4, 2}, {2, 1, 2, 4}};
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) EXPECT_NEAR(M[a * 4 + b], 3.0 / 36.0 * q[a][b], 1e-15);
  // Triangle of area A: M = ρ A / 12 [2 1 1; 1 2 1; 1 1 2].
  const double tri[6] = {0.1, -0.2, 2.1, 0.3, 0.4, 1.7};
  const double area = 0.5 * ((2.1 - 0.1) * (1.7 + 0.2) - (0.4 - 0.1) * (0.3 + 0.2));
  double T[9];
  ASSERT_EQ(grout::element_mass(Topology::tri3, 2, tri, 2.0, false, T), ElementStatus::ok);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      EXPECT_NEAR(T[a * 3 + b], 2.0 * area / 12.0 * (a == b ? 2.0 : 1.0), 1e-14);
}

TEST(MassMatrix, TotalMassRowSumsAndSymmetryOnDistortedElements) {
  const double rho = 2.5;
  for (const Element& e : distorted_elements()) {
    const int n = e.nodes();
    const double volume = grout::element_measure(e.t, e.dim, e.X.data());
    double M[64], L[64];
    ASSERT_EQ(grout::element_mass(e.t, e.dim, e.X.data(), rho, false, M), ElementStatus::ok);
    ASSERT_EQ(grout::element_mass(e.t, e.dim, e.X.data(), rho, true, L), ElementStatus::ok);
    double total = 0.0;
    for (int a = 0; a < n; ++a) {
      double row = 0.0;
      for (int b = 0; b < n; ++b) {
        row += M[a * n + b];
        EXPECT_NEAR(M[a * n + b], M[b * n + a], 1e-15 * volume);
        if (a != b) {
          EXPECT_EQ(L[a * n + b], 0.0);
        }
      }
      EXPECT_NEAR(L[a * n + a], row, 1e-14 * volume) << "lumped = row sum, node " << a;
      EXPECT_GT(L[a * n + a], 0.0);
      total += row;
    }
    EXPECT_NEAR(total, rho * volume, 1e-13 * volume) << "topology " << int(e.t);
  }
}

// Brute force: a much finer tensor rule on quad4/hex8 (5 points per direction, exact for the
// degree-2/4 integrands) must give the same consistent matrix.
TEST(MassMatrix, ExactAgainstAFinerRule) {
  for (const Element& e : distorted_elements()) {
    if (e.t != Topology::quad4 && e.t != Topology::hex8) continue;
    const int n = e.nodes();
    double M[64], R[64] = {};
    ASSERT_EQ(grout::element_mass(e.t, e.dim, e.X.data(), 1.0, false, M), ElementStatus::ok);
    const int points = grout::quadrature_num_points(e.t, 9);
    for (int q = 0; q < points; ++q) {
      const grout::QuadraturePoint p = grout::quadrature_point(e.t, 9, q);
      double N[8], G[24], det_J = 0.0;
      grout::shape_gradients(e.t, e.dim, e.X.data(), p.xi, N, G, det_J);
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) R[a * n + b] += N[a] * N[b] * p.weight * det_J;
    }
    for (int k = 0; k < n * n; ++k) EXPECT_NEAR(M[k], R[k], 1e-14);
  }
}

TEST(MassMatrix, InvertedElementIsReported) {
  const double flipped[8] = {0, 0, 0, 1, 1, 1, 1, 0};
  double M[16];
  EXPECT_EQ(grout::element_mass(Topology::quad4, 2, flipped, 1.0, false, M),
            ElementStatus::inverted);
  EXPECT_EQ(grout::element_mass(Topology::quad4, 3, flipped, 1.0, false, M),
            ElementStatus::unsupported);
}

}  // namespace
