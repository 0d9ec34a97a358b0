// Shape functions and quadrature rules against closed-form references.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "kernels/quadrature.hpp"
#include "kernels/shape_functions.hpp"

namespace {

using grout::Topology;

constexpr Topology all_topologies[] = {Topology::line2, Topology::tri3, Topology::quad4,
                                       Topology::tet4, Topology::hex8};

/// Reference coordinates of the nodes, Exodus order (independent of the kernel's tables).
std::vector<std::vector<double>> reference_nodes(Topology t) {
  switch (t) {
    case Topology::line2:
      return {{-1}, {1}};
    case Topology::tri3:
      return {{0, 0}, {1, 0}, {0, 1}};
    case Topology::quad4:
      return {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    case Topology::tet4:
      return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    case Topology::hex8:
      return {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
              {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  }
  return {};
}

/// A random point inside the reference element.
std::vector<double> random_reference_point(Topology t, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int d = grout::topology_dimension(t);
  std::vector<double> xi(3, 0.0);
  if (t == Topology::tri3 || t == Topology::tet4) {
    double sum = 0.0;
    for (int i = 0; i < d; ++i) sum += (xi[i] = u(rng));
    const double scale = u(rng) / (sum + 1e-3);  // sum of coordinates < 1
    for (int i = 0; i < d; ++i) xi[i] *= scale;
  } else {
    for (int i = 0; i < d; ++i) xi[i] = 2.0 * u(rng) - 1.0;
  }
  return xi;
}

double factorial(int n) {
  return n <= 1 ? 1.0 : n * factorial(n - 1);
}

/// Exact integral of xi^i eta^j zeta^k over the reference element.
double monomial_integral(Topology t, int i, int j, int k) {
  auto line = [](int p) { return p % 2 ? 0.0 : 2.0 / (p + 1); };
  switch (t) {
    case Topology::line2:
      return line(i);
    case Topology::quad4:
      return line(i) * line(j);
    case Topology::hex8:
      return line(i) * line(j) * line(k);
    // int_T xi^i eta^j = i! j! / (i + j + 2)!, int_tet xi^i eta^j zeta^k = i! j! k! / (i+j+k+3)!
    case Topology::tri3:
      return factorial(i) * factorial(j) / factorial(i + j + 2);
    case Topology::tet4:
      return factorial(i) * factorial(j) * factorial(k) / factorial(i + j + k + 3);
  }
  return 0.0;
}

}  // namespace

TEST(ShapeFunctions, PartitionOfUnityAndZeroDerivativeSum) {
  std::mt19937 rng(42);
  for (Topology t : all_topologies) {
    const int d = grout::topology_dimension(t);
    for (int trial = 0; trial < 20; ++trial) {
      const std::vector<double> xi = random_reference_point(t, rng);
      double N[8], dN[24];
      const int n = grout::shape_functions(t, xi.data(), N, dN);
      ASSERT_EQ(n, grout::topology_num_nodes(t));
      double sum = 0.0, dsum[3] = {0.0, 0.0, 0.0};
      for (int a = 0; a < n; ++a) {
        sum += N[a];
        for (int j = 0; j < d; ++j) dsum[j] += dN[a * d + j];
      }
      EXPECT_NEAR(sum, 1.0, 1e-14);
      for (int j = 0; j < d; ++j) EXPECT_NEAR(dsum[j], 0.0, 1e-14);
    }
  }
}

TEST(ShapeFunctions, KroneckerDeltaAtNodes) {
  for (Topology t : all_topologies) {
    const auto nodes = reference_nodes(t);
    for (std::size_t b = 0; b < nodes.size(); ++b) {
      double N[8];
      grout::shape_functions(t, nodes[b].data(), N, nullptr);
      for (std::size_t a = 0; a < nodes.size(); ++a)
        EXPECT_NEAR(N[a], a == b ? 1.0 : 0.0, 1e-15) << "topology " << int(t) << " node " << b;
    }
  }
}

TEST(ShapeFunctions, DerivativesMatchCentralDifferences) {
  // The shape functions are linear in each coordinate, so the central difference is exact up to
  // round-off ~ eps / h.
  std::mt19937 rng(7);
  const double h = 1e-3;
  for (Topology t : all_topologies) {
    const int d = grout::topology_dimension(t);
    for (int trial = 0; trial < 10; ++trial) {
      const std::vector<double> xi = random_reference_point(t, rng);
      double dN[24];
      const int n = grout::shape_functions(t, xi.data(), nullptr, dN);
      for (int j = 0; j < d; ++j) {
        std::vector<double> plus = xi, minus = xi;
        plus[j] += h;
        minus[j] -= h;
        double Np[8], Nm[8];
        grout::shape_functions(t, plus.data(), Np, nullptr);
        grout::shape_functions(t, minus.data(), Nm, nullptr);
        for (int a = 0; a < n; ++a) EXPECT_NEAR(dN[a * d + j], (Np[a] - Nm[a]) / (2 * h), 1e-12);
      }
    }
  }
}

TEST(Quadrature, GaussLegendreWeightsAndRange) {
  for (int n = 1; n <= grout::max_gauss_points_1d; ++n) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      double x = 0.0, w = 0.0;
      ASSERT_TRUE(grout::gauss_legendre_1d(n, i, x, w));
      EXPECT_GT(w, 0.0);
      EXPECT_LT(std::abs(x), 1.0);
      sum += w;
    }
    EXPECT_NEAR(sum, 2.0, 1e-15);
  }
  double x = 0.0, w = 0.0;
  EXPECT_FALSE(grout::gauss_legendre_1d(6, 0, x, w));
  EXPECT_FALSE(grout::gauss_legendre_1d(2, 2, x, w));
}

TEST(Quadrature, IntegratesMonomialsUpToDegreeExactly) {
  struct Case {
    Topology t;
    std::vector<int> degrees;
  };
  const std::vector<Case> cases = {{Topology::line2, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9}},
                                   {Topology::quad4, {1, 3, 5, 7, 9}},
                                   {Topology::hex8, {1, 3, 5, 7, 9}},
                                   {Topology::tri3, {1, 2, 3, 4, 5}},
                                   {Topology::tet4, {1, 2, 3}}};
  for (const Case& c : cases) {
    const int d = grout::topology_dimension(c.t);
    const bool tensor = c.t == Topology::line2 || c.t == Topology::quad4 || c.t == Topology::hex8;
    for (int degree : c.degrees) {
      const int num_points = grout::quadrature_num_points(c.t, degree);
      ASSERT_GT(num_points, 0) << "topology " << int(c.t) << " degree " << degree;
      ASSERT_LE(num_points, grout::max_quadrature_points);
      // Monomials of total degree <= degree (simplex) or per-direction degree <= degree (tensor).
      const int max_j = d > 1 ? degree : 0, max_k = d > 2 ? degree : 0;
      for (int i = 0; i <= degree; ++i)
        for (int j = 0; j <= max_j; ++j)
          for (int k = 0; k <= max_k; ++k) {
            if (!tensor && i + j + k > degree) continue;
            double sum = 0.0;
            for (int q = 0; q < num_points; ++q) {
              const grout::QuadraturePoint p = grout::quadrature_point(c.t, degree, q);
              sum += p.weight * std::pow(p.xi[0], i) * std::pow(p.xi[1], j) * std::pow(p.xi[2], k);
            }
            const double exact = monomial_integral(c.t, i, j, k);
            EXPECT_NEAR(sum, exact, 1e-14 * (1.0 + std::abs(exact)))
                << "topology " << int(c.t) << " degree " << degree << " monomial " << i << j << k;
          }
    }
  }
}

TEST(Quadrature, PointsInsideElementAndUnsupportedDegrees) {
  for (Topology t : all_topologies)
    for (int degree = 0; degree <= 9; ++degree) {
      const int num_points = grout::quadrature_num_points(t, degree);
      for (int q = 0; q < num_points; ++q) {
        const grout::QuadraturePoint p = grout::quadrature_point(t, degree, q);
        if (t == Topology::tri3 || t == Topology::tet4) {
          EXPECT_GT(p.xi[0], 0.0);
          EXPECT_GE(p.xi[1], 0.0);
          EXPECT_LT(p.xi[0] + p.xi[1] + p.xi[2], 1.0);
        } else {
          for (int i = 0; i < 3; ++i) EXPECT_LT(std::abs(p.xi[i]), 1.0);
        }
      }
    }
  EXPECT_EQ(grout::quadrature_num_points(Topology::tri3, 6), 0);
  EXPECT_EQ(grout::quadrature_num_points(Topology::tet4, 4), 0);
  EXPECT_EQ(grout::quadrature_num_points(Topology::hex8, 10), 0);
  EXPECT_EQ(grout::quadrature_point(Topology::quad4, 3, 4).weight, 0.0);
}

TEST(ShapeGradients, ReproduceLinearFieldsOnDistortedElements) {
  // sum_a X_a,i dN_a/dX_j = delta_ij for any (non-inverted) isoparametric element.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  for (Topology t : {Topology::tri3, Topology::quad4, Topology::tet4, Topology::hex8}) {
    const int d = grout::topology_dimension(t);
    const auto nodes = reference_nodes(t);
    std::vector<double> X;
    for (const auto& node : nodes)
      for (int i = 0; i < d; ++i)
        X.push_back(1.3 * node[i] + 0.4 * node[(i + 1) % d] + jitter(rng));
    for (int trial = 0; trial < 5; ++trial) {
      const std::vector<double> xi = random_reference_point(t, rng);
      double N[8], G[24], det_J = 0.0;
      ASSERT_EQ(grout::shape_gradients(t, d, X.data(), xi.data(), N, G, det_J),
                grout::ElementStatus::ok);
      EXPECT_GT(det_J, 0.0);
      for (int i = 0; i < d; ++i)
        for (int j = 0; j < d; ++j) {
          double sum = 0.0;
          for (std::size_t a = 0; a < nodes.size(); ++a) sum += X[a * d + i] * G[a * d + j];
          EXPECT_NEAR(sum, i == j ? 1.0 : 0.0, 1e-13);
        }
    }
  }
}

TEST(ShapeGradients, RejectsMismatchedDimension) {
  const double X[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const double xi[2] = {0.2, 0.2};
  double G[9], det_J = 0.0;
  EXPECT_EQ(grout::shape_gradients(Topology::tri3, 3, X, xi, nullptr, G, det_J),
            grout::ElementStatus::unsupported);
}

TEST(SideAreaVector, FollowsNodeOrder) {
  // 2D edge (0,0) -> (2,0): outward normal (dy, -dx) = -y, |a| = length / 2 (xi in [-1,1]).
  const double edge[4] = {0, 0, 2, 0};
  const double xi[2] = {0.3, 0.0};
  double a[3] = {0, 0, 0};
  EXPECT_EQ(grout::side_area_vector(Topology::line2, 2, edge, xi, nullptr, a), 2);
  EXPECT_NEAR(a[0], 0.0, 1e-15);
  EXPECT_NEAR(a[1], -1.0, 1e-15);
  // 3D triangle counter-clockwise seen from +z: a = +z * 2 * area.
  const double tri[9] = {0, 0, 1, 3, 0, 1, 0, 2, 1};
  EXPECT_EQ(grout::side_area_vector(Topology::tri3, 3, tri, xi, nullptr, a), 3);
  EXPECT_NEAR(a[0], 0.0, 1e-15);
  EXPECT_NEAR(a[1], 0.0, 1e-15);
  EXPECT_NEAR(a[2], 6.0, 1e-15);
  EXPECT_EQ(grout::side_area_vector(Topology::quad4, 2, tri, xi, nullptr, a), 0);
}
