// Small-strain linear-elastic element: stiffness properties, constant-strain patch,
// element measure and AD consistency, against independent references.
#include <gtest/gtest.h>

#include <Sacado.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "kernels/linear_elastic.hpp"
#include "unit_tests/distorted_elements.hpp"

namespace {

using grout::ElasticConstants;
using grout::ElementStatus;
using grout::Topology;

using grout_test::distorted_elements;
using grout_test::Element;

ElasticConstants test_constants(int dim, bool plane_stress) {
  return grout::elastic_constants(210.0, 0.3, dim, plane_stress);
}

double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

std::vector<double> stiffness(const Element& e, ElasticConstants c) {
  std::vector<double> u(e.dofs(), 0.0), f(e.dofs()), K(e.dofs() * e.dofs());
  EXPECT_EQ(grout::linear_elastic_element(e.t, e.dim, e.X.data(), u.data(), c, f.data(), K.data()),
            ElementStatus::ok);
  return K;
}

std::vector<double> multiply(const std::vector<double>& K, const std::vector<double>& u) {
  const std::size_t n = u.size();
  std::vector<double> r(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) r[i] += K[i * n + j] * u[j];
  return r;
}

/// Reference stress for the constant strain eps = sym(A), from E and nu directly (Voigt
/// constitutive matrices of Zienkiewicz & Taylor vol. 1, §4.2, §6.2). Same output order as
/// linear_elastic_stress.
std::array<double, 6> reference_stress(int dim, const double A[3][3], double E, double nu,
                                       bool plane_stress) {
  const double exx = A[0][0], eyy = A[1][1], gxy = A[0][1] + A[1][0];
  if (dim == 2 && plane_stress) {
    const double f = E / (1 - nu * nu);
    return {f * (exx + nu * eyy), f * (nu * exx + eyy), f * (1 - nu) / 2 * gxy, 0.0, 0.0, 0.0};
  }
  const double f = E / ((1 + nu) * (1 - 2 * nu));
  if (dim == 2)
    return {f * ((1 - nu) * exx + nu * eyy),
            f * (nu * exx + (1 - nu) * eyy),
            f * (1 - 2 * nu) / 2 * gxy,
            f * nu * (exx + eyy),
            0.0,
            0.0};
  const double ezz = A[2][2], gyz = A[1][2] + A[2][1], gxz = A[0][2] + A[2][0];
  return {f * ((1 - nu) * exx + nu * (eyy + ezz)),
          f * ((1 - nu) * eyy + nu * (exx + ezz)),
          f * ((1 - nu) * ezz + nu * (exx + eyy)),
          f * (1 - 2 * nu) / 2 * gxy,
          f * (1 - 2 * nu) / 2 * gyz,
          f * (1 - 2 * nu) / 2 * gxz};
}

double triangle_area_3d(const double* a, const double* b, const double* c, const double* d) {
  // Signed volume of the tetrahedron (a, b, c, d): (b - a) . ((c - a) x (d - a)) / 6.
  double u[3], v[3], w[3];
  for (int i = 0; i < 3; ++i) u[i] = b[i] - a[i], v[i] = c[i] - a[i], w[i] = d[i] - a[i];
  return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
          u[2] * (v[0] * w[1] - v[1] * w[0])) /
         6.0;
}

}  // namespace

TEST(ElasticConstants, LameAndPlaneStress) {
  const double E = 210.0, nu = 0.3;
  const ElasticConstants c3 = grout::elastic_constants(E, nu, 3, true);  // flag ignored in 3D
  EXPECT_NEAR(c3.lambda, E * nu / ((1 + nu) * (1 - 2 * nu)), 1e-12);
  EXPECT_NEAR(c3.mu, E / (2 * (1 + nu)), 1e-12);
  const ElasticConstants cs = grout::elastic_constants(E, nu, 2, true);
  EXPECT_NEAR(cs.lambda, 2 * c3.lambda * c3.mu / (c3.lambda + 2 * c3.mu), 1e-12);
  EXPECT_NEAR(cs.mu, c3.mu, 1e-12);
}

TEST(LinearElastic, StiffnessIsSymmetric) {
  for (const Element& e : distorted_elements()) {
    const std::vector<double> K = stiffness(e, test_constants(e.dim, false));
    const int n = e.dofs();
    const double scale = max_abs(K);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < i; ++j)
        EXPECT_NEAR(K[i * n + j], K[j * n + i], 1e-13 * scale) << "topology " << int(e.t);
  }
}

TEST(LinearElastic, RigidBodyModesAreInTheKernel) {
  for (const Element& e : distorted_elements()) {
    const std::vector<double> K = stiffness(e, test_constants(e.dim, false));
    const double scale = max_abs(K) * (1.0 + max_abs(e.X));
    std::vector<std::vector<double>> modes;
    for (int i = 0; i < e.dim; ++i) {  // translations
      std::vector<double> r(e.dofs(), 0.0);
      for (int a = 0; a < e.nodes(); ++a) r[a * e.dim + i] = 1.0;
      modes.push_back(r);
    }
    const int num_rotations = e.dim == 2 ? 1 : 3;
    for (int k = 0; k < num_rotations; ++k) {  // infinitesimal rotations u = w x X
      double w[3] = {0, 0, 0};
      w[e.dim == 2 ? 2 : k] = 1.0;
      std::vector<double> r(e.dofs(), 0.0);
      for (int a = 0; a < e.nodes(); ++a) {
        const double x = e.X[a * e.dim], y = e.X[a * e.dim + 1],
                     z = e.dim == 3 ? e.X[a * e.dim + 2] : 0.0;
        const double wx[3] = {w[1] * z - w[2] * y, w[2] * x - w[0] * z, w[0] * y - w[1] * x};
        for (int i = 0; i < e.dim; ++i) r[a * e.dim + i] = wx[i];
      }
      modes.push_back(r);
    }
    for (const auto& r : modes)
      for (double v : multiply(K, r)) EXPECT_NEAR(v, 0.0, 1e-13 * scale) << "topology " << int(e.t);
  }
}

TEST(LinearElastic, InternalForceEqualsStiffnessTimesDisplacement) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> dist(-0.1, 0.1);
  for (const Element& e : distorted_elements()) {
    const ElasticConstants c = test_constants(e.dim, false);
    std::vector<double> u(e.dofs()), f(e.dofs()), f_only(e.dofs()), K(e.dofs() * e.dofs());
    for (double& v : u) v = dist(rng);
    ASSERT_EQ(
        grout::linear_elastic_element(e.t, e.dim, e.X.data(), u.data(), c, f.data(), K.data()),
        ElementStatus::ok);
    ASSERT_EQ(
        grout::linear_elastic_element(e.t, e.dim, e.X.data(), u.data(), c, f_only.data(), nullptr),
        ElementStatus::ok);
    const std::vector<double> Ku = multiply(K, u);
    const double scale = max_abs(Ku);
    for (int i = 0; i < e.dofs(); ++i) {
      EXPECT_NEAR(f[i], Ku[i], 1e-13 * scale) << "topology " << int(e.t);
      EXPECT_EQ(f[i], f_only[i]);
    }
  }
}

TEST(LinearElastic, ConstantStrainPatch) {
  // u = A X: constant strain, so sigma is the analytic one everywhere, the element is in
  // equilibrium (sum_a f_a = 0) and the averaged stress is exact.
  const double E = 210.0, nu = 0.3;
  const double A[3][3] = {
      {1.0e-3, 4.0e-4, -2.0e-4}, {-1.0e-4, -5.0e-4, 3.0e-4}, {2.5e-4, 1.5e-4, 7.0e-4}};
  for (const Element& e : distorted_elements()) {
    std::vector<bool> plane_stress_cases = {false};
    if (e.dim == 2) plane_stress_cases.push_back(true);
    for (bool plane_stress : plane_stress_cases) {
      const ElasticConstants c = grout::elastic_constants(E, nu, e.dim, plane_stress);
      std::vector<double> u(e.dofs(), 0.0), f(e.dofs());
      for (int a = 0; a < e.nodes(); ++a)
        for (int i = 0; i < e.dim; ++i)
          for (int j = 0; j < e.dim; ++j) u[a * e.dim + i] += A[i][j] * e.X[a * e.dim + j];
      ASSERT_EQ(
          grout::linear_elastic_element(e.t, e.dim, e.X.data(), u.data(), c, f.data(), nullptr),
          ElementStatus::ok);
      const double scale = max_abs(f);
      for (int i = 0; i < e.dim; ++i) {
        double sum = 0.0;
        for (int a = 0; a < e.nodes(); ++a) sum += f[a * e.dim + i];
        EXPECT_NEAR(sum, 0.0, 1e-13 * scale);
      }
      double stress[6];
      ASSERT_EQ(grout::linear_elastic_stress(e.t, e.dim, e.X.data(), u.data(), c, !plane_stress, nu,
                                             stress),
                ElementStatus::ok);
      const std::array<double, 6> expected = reference_stress(e.dim, A, E, nu, plane_stress);
      for (int k = 0; k < 6; ++k)
        EXPECT_NEAR(stress[k], expected[k], 1e-12 * 0.3)
            << "topology " << int(e.t) << " plane stress " << plane_stress << " component " << k;
    }
  }
}

TEST(ElementMeasure, MatchesIndependentFormulas) {
  for (const Element& e : distorted_elements()) {
    const double* X = e.X.data();
    double expected = 0.0;
    if (e.t == Topology::tri3 || e.t == Topology::quad4) {  // shoelace
      for (int a = 0; a < e.nodes(); ++a) {
        const int b = (a + 1) % e.nodes();
        expected += 0.5 * (X[2 * a] * X[2 * b + 1] - X[2 * b] * X[2 * a + 1]);
      }
    } else if (e.t == Topology::tet4) {
      expected = triangle_area_3d(X, X + 3, X + 6, X + 9);
    } else {
      // Trilinear hex: 24 tetrahedra (cell centre, face centre, one face edge), exact for the
      // trilinear volume (Grandy, "Efficient computation of volume of hexahedral cells",
      // LLNL UCRL-ID-128886, 1997). Faces from topology.hpp (outward).
      double centre[3] = {0, 0, 0};
      for (int a = 0; a < 8; ++a)
        for (int i = 0; i < 3; ++i) centre[i] += X[3 * a + i] / 8.0;
      for (int side = 1; side <= 6; ++side) {
        int nodes[4];
        grout::side_local_nodes(Topology::hex8, side, nodes);
        double face[3] = {0, 0, 0};
        for (int k = 0; k < 4; ++k)
          for (int i = 0; i < 3; ++i) face[i] += X[3 * nodes[k] + i] / 4.0;
        for (int k = 0; k < 4; ++k)  // outward face triangle (face centre, n_k, n_k+1)
          expected += triangle_area_3d(centre, face, X + 3 * nodes[k], X + 3 * nodes[(k + 1) % 4]);
      }
    }
    EXPECT_NEAR(grout::element_measure(e.t, e.dim, X), expected, 1e-13 * std::abs(expected))
        << "topology " << int(e.t);
  }
  // Sides: length of an edge, area of a planar quad face.
  const double edge[4] = {1, 1, 4, 5};
  EXPECT_NEAR(grout::element_measure(Topology::line2, 2, edge), 5.0, 1e-14);
  const double face[12] = {0, 0, 0, 2, 0, 0, 3, 1, 0, 0, 1, 0};  // trapezoid, area 2.5
  EXPECT_NEAR(grout::element_measure(Topology::quad4, 3, face), 2.5, 1e-14);
}

TEST(LinearElastic, InvertedElementIsReported) {
  for (const Element& e : distorted_elements()) {
    // Mirror the element (x -> -x): every Jacobian determinant changes sign.
    std::vector<double> X = e.X;
    for (int a = 0; a < e.nodes(); ++a) X[a * e.dim] *= -1.0;
    std::vector<double> u(e.dofs(), 0.0), f(e.dofs()), K(e.dofs() * e.dofs());
    const ElasticConstants c = test_constants(e.dim, false);
    EXPECT_EQ(grout::linear_elastic_element(e.t, e.dim, X.data(), u.data(), c, f.data(), K.data()),
              ElementStatus::inverted);
    double stress[6];
    EXPECT_EQ(grout::linear_elastic_stress(e.t, e.dim, X.data(), u.data(), c, true, 0.3, stress),
              ElementStatus::inverted);
  }
  // A bow-tie quad4 (nodes 2 and 3 swapped) is inverted at some Gauss points only.
  const double bow_tie[8] = {0, 0, 1, 0, 0, 1, 1, 1};
  const double u[8] = {0};
  double f[8], K[64];
  EXPECT_EQ(
      grout::linear_elastic_element(Topology::quad4, 2, bow_tie, u, test_constants(2, false), f, K),
      ElementStatus::inverted);
}

TEST(LinearElastic, UnsupportedCombinations) {
  const double X[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const double u[12] = {0};
  double f[12], stress[6];
  const ElasticConstants c = test_constants(3, false);
  EXPECT_EQ(grout::linear_elastic_element(Topology::tri3, 3, X, u, c, f, nullptr),
            ElementStatus::unsupported);
  EXPECT_EQ(grout::linear_elastic_element(Topology::line2, 1, X, u, c, f, nullptr),
            ElementStatus::unsupported);
  EXPECT_EQ(grout::linear_elastic_stress(Topology::tet4, 2, X, u, c, true, 0.3, stress),
            ElementStatus::unsupported);
}

TEST(LinearElastic, ForwardADJacobianEqualsStiffness) {
  using Fad = Sacado::Fad::SFad<double, grout::max_element_dofs>;
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> dist(-0.1, 0.1);
  for (const Element& e : distorted_elements()) {
    const int n = e.dofs();
    const ElasticConstants c = test_constants(e.dim, false);
    std::vector<double> u(n), f(n), K(n * n);
    for (double& v : u) v = dist(rng);
    ASSERT_EQ(
        grout::linear_elastic_element(e.t, e.dim, e.X.data(), u.data(), c, f.data(), K.data()),
        ElementStatus::ok);
    std::vector<Fad> u_ad(n), f_ad(n);
    for (int k = 0; k < n; ++k) u_ad[k] = Fad(grout::max_element_dofs, k, u[k]);
    ASSERT_EQ(
        grout::linear_elastic_element(e.t, e.dim, e.X.data(), u_ad.data(), c, f_ad.data(), nullptr),
        ElementStatus::ok);
    const double scale = max_abs(K);
    for (int i = 0; i < n; ++i) {
      EXPECT_NEAR(f_ad[i].val(), f[i], 1e-14 * scale);
      for (int k = 0; k < n; ++k)
        EXPECT_NEAR(f_ad[i].dx(k), K[i * n + k], 1e-12 * scale) << "topology " << int(e.t);
    }
  }
}
