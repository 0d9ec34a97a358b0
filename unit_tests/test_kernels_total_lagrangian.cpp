// Total-Lagrangian finite-strain element and hyperelastic laws against closed-form
// homogeneous states (stretch, simple shear, rigid rotation), central differences and the
// small-strain limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "kernels/total_lagrangian.hpp"
#include "unit_tests/distorted_elements.hpp"

namespace {

using grout::ElasticConstants;
using grout::ElementStatus;
using grout::HyperelasticLaw;
using grout::Topology;

constexpr HyperelasticLaw laws[] = {HyperelasticLaw::neo_hookean,
                                    HyperelasticLaw::saint_venant_kirchhoff};

using grout_test::distorted_elements;
using grout_test::Element;

ElasticConstants constants() {
  return grout::elastic_constants(210.0, 0.3, 3, false);
}

/// u = (F - I) X at every node (F: 3 x 3, only the dim x dim block acts).
std::vector<double> homogeneous_displacement(const Element& e, const double F[3][3]) {
  std::vector<double> u(e.dofs(), 0.0);
  for (int a = 0; a < e.nodes(); ++a)
    for (int i = 0; i < e.dim; ++i)
      for (int J = 0; J < e.dim; ++J)
        u[a * e.dim + i] += (F[i][J] - (i == J ? 1.0 : 0.0)) * e.X[a * e.dim + J];
  return u;
}

/// Closed-form Cauchy stress of the compressible Neo-Hookean law,
/// sigma = mu/J (b - I) + lambda ln J / J I, b = F F^T (Bonet & Wood eq. 6.29).
std::array<std::array<double, 3>, 3> neo_hookean_cauchy(const double F[3][3], ElasticConstants c) {
  const double J = F[0][0] * (F[1][1] * F[2][2] - F[1][2] * F[2][1]) -
                   F[0][1] * (F[1][0] * F[2][2] - F[1][2] * F[2][0]) +
                   F[0][2] * (F[1][0] * F[2][1] - F[1][1] * F[2][0]);
  std::array<std::array<double, 3>, 3> s{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double b = 0.0;
      for (int K = 0; K < 3; ++K) b += F[i][K] * F[j][K];
      s[i][j] = c.mu / J * (b - (i == j)) + (i == j ? c.lambda * std::log(J) / J : 0.0);
    }
  return s;
}

/// Voigt order of total_lagrangian_cauchy_stress.
std::array<double, 6> voigt(int dim, const std::array<std::array<double, 3>, 3>& s) {
  if (dim == 2) return {s[0][0], s[1][1], s[0][1], s[2][2], 0.0, 0.0};
  return {s[0][0], s[1][1], s[2][2], s[0][1], s[1][2], s[0][2]};
}

void expect_stress(const Element& e, HyperelasticLaw law, const double F[3][3],
                   const std::array<std::array<double, 3>, 3>& expected) {
  const auto u = homogeneous_displacement(e, F);
  double stress[6];
  ASSERT_EQ(grout::total_lagrangian_cauchy_stress(e.t, e.dim, e.X.data(), u.data(), law,
                                                  constants(), stress),
            ElementStatus::ok);
  const auto ref = voigt(e.dim, expected);
  double scale = 0.0;
  for (double v : ref) scale = std::max(scale, std::abs(v));
  for (int k = 0; k < 6; ++k)
    EXPECT_NEAR(stress[k], ref[k], 1e-13 * scale) << "topology " << int(e.t) << " component " << k;
}

TEST(TotalLagrangian, NeoHookeanHomogeneousStretchMatchesClosedForm) {
  for (const Element& e : distorted_elements()) {
    // Plane strain keeps F33 = 1; 3D stretches all three directions.
    const double F[3][3] = {{1.6, 0.0, 0.0}, {0.0, 0.7, 0.0}, {0.0, 0.0, e.dim == 3 ? 1.2 : 1.0}};
    expect_stress(e, HyperelasticLaw::neo_hookean, F, neo_hookean_cauchy(F, constants()));
  }
}

TEST(TotalLagrangian, NeoHookeanSimpleShearMatchesClosedForm) {
  // F = I + gamma e1 (x) e2: J = 1, sigma = mu (b - I): sigma_xx = mu gamma^2,
  // sigma_xy = mu gamma, sigma_yy = sigma_zz = 0 (Bonet & Wood §6.4.3 example).
  const double gamma = 0.8, mu = constants().mu;
  std::array<std::array<double, 3>, 3> expected{};
  expected[0][0] = mu * gamma * gamma;
  expected[0][1] = expected[1][0] = mu * gamma;
  const double F[3][3] = {{1.0, gamma, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
  for (const Element& e : distorted_elements())
    expect_stress(e, HyperelasticLaw::neo_hookean, F, expected);
}

TEST(TotalLagrangian, SaintVenantKirchhoffSimpleShearMatchesClosedForm) {
  // E = [[0, g/2, 0], [g/2, g^2/2, 0], [0, 0, 0]], S = lambda tr(E) I + 2 mu E, sigma = F S F^T:
  // S_xx = S_zz = lambda g^2/2, S_xy = mu g, S_yy = lambda g^2/2 + mu g^2;
  // sigma_xx = S_xx + 2 g S_xy + g^2 S_yy, sigma_xy = S_xy + g S_yy, sigma_yy = S_yy.
  const double g = 0.5, lambda = constants().lambda, mu = constants().mu;
  const double Sxx = lambda * g * g / 2, Sxy = mu * g, Syy = lambda * g * g / 2 + mu * g * g;
  std::array<std::array<double, 3>, 3> expected{};
  expected[0][0] = Sxx + 2 * g * Sxy + g * g * Syy;
  expected[0][1] = expected[1][0] = Sxy + g * Syy;
  expected[1][1] = Syy;
  expected[2][2] = Sxx;
  const double F[3][3] = {{1.0, g, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
  for (const Element& e : distorted_elements())
    expect_stress(e, HyperelasticLaw::saint_venant_kirchhoff, F, expected);
}

TEST(TotalLagrangian, HomogeneousStretchNodalForcesOfUnitSquareAndCube) {
  // On the unit square / cube, int N_a,J dV = s_aJ / 2 (2D) or s_aJ / 4 (3D), s_aJ = ±1 the
  // node's reference-corner sign, so f_a,i = P_ii s_ai / 2 (or / 4) with the diagonal
  // P_ii = mu (l_i - 1/l_i) + lambda ln J / l_i of a stretch F = diag(l_i).
  const ElasticConstants c = constants();
  const double corner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                               {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  for (int dim : {2, 3}) {
    Element e{dim == 2 ? Topology::quad4 : Topology::hex8, dim, {}};
    for (int a = 0; a < e.nodes(); ++a)
      for (int i = 0; i < dim; ++i) e.X.push_back(0.5 * (1.0 + corner[a][i]));
    const double l[3] = {1.5, 0.8, dim == 3 ? 1.3 : 1.0};
    const double F[3][3] = {{l[0], 0, 0}, {0, l[1], 0}, {0, 0, l[2]}};
    const double J = l[0] * l[1] * l[2];
    const auto u = homogeneous_displacement(e, F);
    std::vector<double> f(e.dofs());
    ASSERT_EQ(
        grout::total_lagrangian_element<double>(e.t, dim, e.X.data(), u.data(),
                                                HyperelasticLaw::neo_hookean, c, f.data(), nullptr),
        ElementStatus::ok);
    for (int a = 0; a < e.nodes(); ++a)
      for (int i = 0; i < dim; ++i) {
        const double P = c.mu * (l[i] - 1.0 / l[i]) + c.lambda * std::log(J) / l[i];
        EXPECT_NEAR(f[a * dim + i], P * corner[a][i] / (dim == 2 ? 2.0 : 4.0), 1e-13 * c.lambda);
      }
  }
}

TEST(TotalLagrangian, RigidRotationBy90DegreesIsStressFree) {
  // u = (R - I) X with R a rotation by 90 degrees about z: F = R, E = 0, so P = 0 and
  // sigma = 0 for both laws; a small-strain element would give sigma = -2 mu I in-plane.
  const double R[3][3] = {{0.0, -1.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 0.0, 1.0}};
  for (HyperelasticLaw law : laws)
    for (const Element& e : distorted_elements()) {
      const auto u = homogeneous_displacement(e, R);
      std::vector<double> f(e.dofs());
      double stress[6], energy = 1.0;
      ASSERT_EQ(grout::total_lagrangian_element<double>(e.t, e.dim, e.X.data(), u.data(), law,
                                                        constants(), f.data(), &energy),
                ElementStatus::ok);
      ASSERT_EQ(grout::total_lagrangian_cauchy_stress(e.t, e.dim, e.X.data(), u.data(), law,
                                                      constants(), stress),
                ElementStatus::ok);
      for (double v : f) EXPECT_NEAR(v, 0.0, 1e-13 * constants().lambda);
      for (double v : stress) EXPECT_NEAR(v, 0.0, 1e-13 * constants().lambda);
      EXPECT_NEAR(energy, 0.0, 1e-13 * constants().lambda);
    }
}

std::vector<double> random_displacement(const Element& e, std::mt19937& rng, double size) {
  std::uniform_real_distribution<double> dist(-size, size);
  std::vector<double> u(e.dofs());
  for (double& v : u) v = dist(rng);
  return u;
}

TEST(TotalLagrangian, ADTangentMatchesCentralDifferences) {
  std::mt19937 rng(5);
  for (HyperelasticLaw law : laws)
    for (const Element& e : distorted_elements()) {
      const int n = e.dofs();
      const auto u = random_displacement(e, rng, 0.2);
      std::vector<double> f(n), K(n * n), fp(n), fm(n);
      ASSERT_EQ(grout::total_lagrangian_force_and_tangent(e.t, e.dim, e.X.data(), u.data(), law,
                                                          constants(), f.data(), K.data()),
                ElementStatus::ok);
      double scale = 0.0;
      for (double v : K) scale = std::max(scale, std::abs(v));
      const double h = 1e-6;
      for (int k = 0; k < n; ++k) {
        auto up = u, um = u;
        up[k] += h;
        um[k] -= h;
        grout::total_lagrangian_element<double>(e.t, e.dim, e.X.data(), up.data(), law, constants(),
                                                fp.data(), nullptr);
        grout::total_lagrangian_element<double>(e.t, e.dim, e.X.data(), um.data(), law, constants(),
                                                fm.data(), nullptr);
        // Central differences: error O(h^2 |f'''|) + O(eps |f| / h).
        for (int r = 0; r < n; ++r)
          EXPECT_NEAR(K[r * n + k], (fp[r] - fm[r]) / (2 * h), 1e-6 * scale)
              << "law " << int(law) << " topology " << int(e.t) << " entry " << r << "," << k;
      }
    }
}

TEST(TotalLagrangian, InternalForceIsTheEnergyGradient) {
  // f_int = d Pi_int / d u: the AD gradient of the stored energy equals the force.
  using Fad = Sacado::Fad::SFad<double, grout::max_element_dofs>;
  std::mt19937 rng(7);
  for (HyperelasticLaw law : laws)
    for (const Element& e : distorted_elements()) {
      const int n = e.dofs();
      const auto u = random_displacement(e, rng, 0.2);
      std::vector<Fad> u_ad(n), f_ad(n);
      for (int k = 0; k < n; ++k) u_ad[k] = Fad(grout::max_element_dofs, k, u[k]);
      Fad energy;
      ASSERT_EQ(grout::total_lagrangian_element<Fad>(e.t, e.dim, e.X.data(), u_ad.data(), law,
                                                     constants(), f_ad.data(), &energy),
                ElementStatus::ok);
      double scale = 0.0;
      for (int k = 0; k < n; ++k) scale = std::max(scale, std::abs(f_ad[k].val()));
      for (int k = 0; k < n; ++k) EXPECT_NEAR(energy.dx(k), f_ad[k].val(), 1e-13 * scale);
    }
}

TEST(TotalLagrangian, TangentAtZeroDisplacementIsTheSmallStrainStiffness) {
  for (HyperelasticLaw law : laws)
    for (const Element& e : distorted_elements()) {
      const int n = e.dofs();
      std::vector<double> u(n, 0.0), f(n), K(n * n), f_lin(n), K_lin(n * n);
      ASSERT_EQ(grout::total_lagrangian_force_and_tangent(e.t, e.dim, e.X.data(), u.data(), law,
                                                          constants(), f.data(), K.data()),
                ElementStatus::ok);
      ASSERT_EQ(grout::linear_elastic_element(e.t, e.dim, e.X.data(), u.data(), constants(),
                                              f_lin.data(), K_lin.data()),
                ElementStatus::ok);
      double scale = 0.0;
      for (double v : K_lin) scale = std::max(scale, std::abs(v));
      for (int k = 0; k < n * n; ++k) EXPECT_NEAR(K[k], K_lin[k], 1e-13 * scale);
      for (double v : f) EXPECT_NEAR(v, 0.0, 1e-13 * scale);
    }
}

TEST(TotalLagrangian, CollapsedDeformationIsReported) {
  // A reflection F = diag(-1, 1, 1) has det F = -1: an inadmissible iterate, not a mesh error.
  const double F[3][3] = {{-1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
  for (HyperelasticLaw law : laws)
    for (const Element& e : distorted_elements()) {
      const auto u = homogeneous_displacement(e, F);
      std::vector<double> f(e.dofs()), K(e.dofs() * e.dofs());
      EXPECT_EQ(grout::total_lagrangian_force_and_tangent(e.t, e.dim, e.X.data(), u.data(), law,
                                                          constants(), f.data(), K.data()),
                ElementStatus::collapsed);
    }
}

}  // namespace
