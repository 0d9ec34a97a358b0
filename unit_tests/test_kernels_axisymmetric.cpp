// The axisymmetric solid kernels (kernels/axisymmetric_elastic.hpp, the axisymmetric path of
// kernels/total_lagrangian.hpp and kernels/surface_load.hpp) against what holds independently:
// virtual work (an equilibrated constant stress gives element forces equal to the consistent
// forces of its boundary tractions), the closed-form stress of a linear field, central
// differences of the finite-strain force, the small-strain limit of the finite-strain element,
// and the force of a uniform pressure on an annulus, p π (r₂² − r₁²).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "kernels/axisymmetric_elastic.hpp"
#include "kernels/surface_load.hpp"
#include "kernels/total_lagrangian.hpp"

namespace {

using grout::ElasticConstants;
using grout::ElementStatus;
using grout::Topology;

const ElasticConstants constants = grout::elastic_constants(200.0, 0.3, 3, false);

// A distorted quad4 and a tri3 off the axis (counter-clockwise, x = r, y = z).
const double quad[8] = {0.5, 0.2, 1.3, 0.1, 1.45, 0.9, 0.6, 1.15};
const double tri[6] = {0.4, 0.3, 1.2, 0.2, 0.7, 1.1};

// u = (a r, b z + c): constant strain (eps_rr = eps_tt = a, eps_zz = b), an equilibrated
// constant stress (div sigma = 0: sigma_rr = sigma_tt, sigma_rz = 0).
void linear_field(int nodes, const double* X, double a, double b, double c, double* u) {
  for (int k = 0; k < nodes; ++k) {
    u[2 * k] = a * X[2 * k];
    u[2 * k + 1] = b * X[2 * k + 1] + c;
  }
}

// Consistent forces of the traction sigma n on every side, axisymmetric surface_load.
void boundary_forces(Topology t, const double* X, const double sigma[2][2], double* f) {
  const int nodes = grout::topology_num_nodes(t);
  for (int r = 0; r < 2 * nodes; ++r) f[r] = 0.0;
  for (int a = 0; a < nodes; ++a) {
    const int b = (a + 1) % nodes;
    const double Xs[4] = {X[2 * a], X[2 * a + 1], X[2 * b], X[2 * b + 1]};
    const double T[2] = {Xs[2] - Xs[0], Xs[3] - Xs[1]};
    const double L = std::hypot(T[0], T[1]);
    const double n[2] = {T[1] / L, -T[0] / L};  // outward for a counter-clockwise element
    const double tr[2] = {sigma[0][0] * n[0] + sigma[0][1] * n[1],
                          sigma[1][0] * n[0] + sigma[1][1] * n[1]};
    const double t_nodal[4] = {tr[0], tr[1], tr[0], tr[1]};
    double fs[4];
    ASSERT_EQ(grout::surface_load(Topology::line2, 2, Xs, nullptr, t_nodal, fs, true),
              ElementStatus::ok);
    for (int d = 0; d < 2; ++d) f[2 * a + d] += fs[d], f[2 * b + d] += fs[2 + d];
  }
}

void expect_virtual_work(Topology t, const double* X) {
  const int nodes = grout::topology_num_nodes(t);
  double u[8], f[8], fb[8], s[6];
  const double a = 1e-3, b = -2e-3;
  linear_field(nodes, X, a, b, 0.37, u);
  ASSERT_EQ(grout::axisymmetric_elastic_element<double>(t, X, u, constants, f, nullptr),
            ElementStatus::ok);
  const double tr = 2 * a + b, l = constants.lambda, m = constants.mu;
  const double sigma[2][2] = {{l * tr + 2 * m * a, 0.0}, {0.0, l * tr + 2 * m * b}};
  boundary_forces(t, X, sigma, fb);
  double scale = 0.0;
  for (int r = 0; r < 2 * nodes; ++r) scale = std::max(scale, std::abs(fb[r]));
  for (int r = 0; r < 2 * nodes; ++r) EXPECT_NEAR(f[r], fb[r], 1e-13 * scale) << "dof " << r;
  ASSERT_EQ(grout::axisymmetric_elastic_stress(t, X, u, constants, s), ElementStatus::ok);
  EXPECT_NEAR(s[0], sigma[0][0], 1e-13 * std::abs(sigma[0][0]));  // rr
  EXPECT_NEAR(s[1], sigma[1][1], 1e-13 * std::abs(sigma[1][1]));  // zz
  EXPECT_NEAR(s[2], 0.0, 1e-13 * std::abs(sigma[1][1]));          // rz
  EXPECT_NEAR(s[3], sigma[0][0], 1e-13 * std::abs(sigma[0][0]));  // tt = rr here
}

}  // namespace

TEST(AxisymmetricElement, ConstantStressForcesAreTheBoundaryTractionForces) {
  expect_virtual_work(Topology::quad4, quad);
  expect_virtual_work(Topology::tri3, tri);
}

TEST(AxisymmetricElement, StiffnessIsTheSymmetricDerivativeOfTheForce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(-1e-3, 1e-3);
  for (const Topology t : {Topology::quad4, Topology::tri3}) {
    const double* X = t == Topology::quad4 ? quad : tri;
    const int n = 2 * grout::topology_num_nodes(t);
    double u[8], f[8], K[64], f0[8];
    for (int r = 0; r < n; ++r) u[r] = d(rng);
    ASSERT_EQ(grout::axisymmetric_elastic_element<double>(t, X, u, constants, f, K),
              ElementStatus::ok);
    double scale = 0.0;
    for (int r = 0; r < n * n; ++r) scale = std::max(scale, std::abs(K[r]));
    for (int r = 0; r < n; ++r) {
      double Ku = 0.0;
      for (int c = 0; c < n; ++c) {
        Ku += K[r * n + c] * u[c];
        EXPECT_NEAR(K[r * n + c], K[c * n + r], 1e-13 * scale);
      }
      EXPECT_NEAR(f[r], Ku, 1e-13 * scale * 1e-3);  // f is linear: f = K u
    }
    // A radial translation strains the hoop direction; an axial one is free.
    for (int k = 0; k < n / 2; ++k) u[2 * k] = 0.0, u[2 * k + 1] = 0.25;
    grout::axisymmetric_elastic_element<double>(t, X, u, constants, f0, nullptr);
    for (int r = 0; r < n; ++r) EXPECT_NEAR(f0[r], 0.0, 1e-13 * scale);
    for (int k = 0; k < n / 2; ++k) u[2 * k] = 0.25, u[2 * k + 1] = 0.0;
    grout::axisymmetric_elastic_element<double>(t, X, u, constants, f0, nullptr);
    double largest = 0.0;
    for (int r = 0; r < n; ++r) largest = std::max(largest, std::abs(f0[r]));
    EXPECT_GT(largest, 1e-3 * scale);
  }
}

TEST(AxisymmetricElement, AnElementTouchingTheAxisStaysFinite) {
  // Nodes on r = 0 (with u_r = 0 there) give finite forces: no quadrature point on the axis.
  const double X[8] = {0.0, 0.0, 0.5, 0.0, 0.5, 0.5, 0.0, 0.5};
  double u[8], f[8], K[64];
  linear_field(4, X, 1e-3, 2e-3, 0.0, u);
  ASSERT_EQ(grout::axisymmetric_elastic_element<double>(Topology::quad4, X, u, constants, f, K),
            ElementStatus::ok);
  for (double v : f) EXPECT_TRUE(std::isfinite(v));
  const double Xbad[8] = {-0.5, 0.0, 0.1, 0.0, 0.1, 0.5, -0.5, 0.5};  // r < 0 at the points
  EXPECT_EQ(grout::axisymmetric_elastic_element<double>(Topology::quad4, Xbad, u, constants, f, K),
            ElementStatus::inverted);
}

TEST(AxisymmetricFiniteStrain, TangentMatchesCentralDifferences) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> d(-0.05, 0.05);
  for (const auto law :
       {grout::HyperelasticLaw::saint_venant_kirchhoff, grout::HyperelasticLaw::neo_hookean}) {
    for (const Topology t : {Topology::quad4, Topology::tri3}) {
      const double* X = t == Topology::quad4 ? quad : tri;
      const int n = 2 * grout::topology_num_nodes(t);
      double u[8], f[8], K[64];
      for (int r = 0; r < n; ++r) u[r] = d(rng);
      ASSERT_EQ(grout::total_lagrangian_force_and_tangent(t, 2, X, u, law, constants, f, K, true),
                ElementStatus::ok);
      double scale = 0.0;
      for (int r = 0; r < n * n; ++r) scale = std::max(scale, std::abs(K[r]));
      const double h = 1e-6;
      for (int c = 0; c < n; ++c) {
        double up[8], um[8], fp[8], fm[8];
        for (int r = 0; r < n; ++r) up[r] = um[r] = u[r];
        up[c] += h, um[c] -= h;
        grout::total_lagrangian_force_and_tangent(t, 2, X, up, law, constants, fp, nullptr, true);
        grout::total_lagrangian_force_and_tangent(t, 2, X, um, law, constants, fm, nullptr, true);
        for (int r = 0; r < n; ++r)
          EXPECT_NEAR(K[r * n + c], (fp[r] - fm[r]) / (2 * h), 1e-7 * scale);
      }
    }
  }
}

TEST(AxisymmetricFiniteStrain, SmallDisplacementsGiveTheSmallStrainForce) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  const double eps = 1e-7;
  for (const Topology t : {Topology::quad4, Topology::tri3}) {
    const double* X = t == Topology::quad4 ? quad : tri;
    const int n = 2 * grout::topology_num_nodes(t);
    double u[8], us[8], f_lin[8], f_tl[8];
    for (int r = 0; r < n; ++r) u[r] = d(rng), us[r] = eps * u[r];
    grout::axisymmetric_elastic_element<double>(t, X, u, constants, f_lin, nullptr);
    ASSERT_EQ(grout::total_lagrangian_force_and_tangent(
                  t, 2, X, us, grout::HyperelasticLaw::saint_venant_kirchhoff, constants, f_tl,
                  nullptr, true),
              ElementStatus::ok);
    double scale = 0.0;
    for (int r = 0; r < n; ++r) scale = std::max(scale, std::abs(f_lin[r]));
    for (int r = 0; r < n; ++r) EXPECT_NEAR(f_tl[r] / eps, f_lin[r], 1e-5 * scale);  // O(eps)
  }
}

TEST(AxisymmetricFiniteStrain, HomogeneousStretchGivesTheLawsCauchyStress) {
  // u = ((s_r − 1) r, (s_z − 1) z): F = diag(s_r, s_z, s_r) with F_tt = 1 + u_r/R = s_r.
  const double sr = 1.1, sz = 0.85;
  for (const Topology t : {Topology::quad4, Topology::tri3}) {
    const double* X = t == Topology::quad4 ? quad : tri;
    const int nodes = grout::topology_num_nodes(t);
    double u[8] = {}, s[6] = {};
    for (int k = 0; k < nodes; ++k)
      u[2 * k] = (sr - 1) * X[2 * k], u[2 * k + 1] = (sz - 1) * X[2 * k + 1];
    const auto law = grout::HyperelasticLaw::neo_hookean;
    ASSERT_EQ(grout::total_lagrangian_cauchy_stress(t, 2, X, u, law, constants, s, true),
              ElementStatus::ok);
    const double F[3][3] = {{sr, 0, 0}, {0, sz, 0}, {0, 0, sr}};
    double P[3][3], W;
    ASSERT_EQ(grout::first_piola_kirchhoff(law, constants, F, P, W), grout::MaterialStatus::ok);
    const double J = sr * sz * sr;
    EXPECT_NEAR(s[0], P[0][0] * sr / J, 1e-12 * std::abs(P[0][0]));
    EXPECT_NEAR(s[1], P[1][1] * sz / J, 1e-12 * std::abs(P[1][1]));
    EXPECT_NEAR(s[2], 0.0, 1e-12 * std::abs(P[1][1]));
    EXPECT_NEAR(s[3], P[2][2] * sr / J, 1e-12 * std::abs(P[2][2]));  // hoop
    EXPECT_NEAR(s[3], s[0], 1e-12 * std::abs(s[0]));
  }
}

TEST(AxisymmetricSurfaceLoad, PressureOnAnAnnulusIsPTimesItsArea) {
  // Side from r1 to r2 on z = 0, outward normal −z: f_z = p π (r2² − r1²) in total, and the
  // nodal split is the exact ∫ N_a 2π r dr.
  const double r1 = 0.3, r2 = 1.7, p = 4.0;
  const double X[4] = {r1, 0.0, r2, 0.0};  // this order gives the outward normal (0, −1)
  const double pn[2] = {p, p};
  double f[4];
  ASSERT_EQ(grout::surface_load(Topology::line2, 2, X, pn, nullptr, f, true), ElementStatus::ok);
  EXPECT_NEAR(f[1] + f[3], p * M_PI * (r2 * r2 - r1 * r1), 1e-13 * p * r2 * r2);
  const double L = r2 - r1;
  EXPECT_NEAR(f[1], 2 * M_PI * p * L * (r1 / 3 + r2 / 6), 1e-13 * p * r2 * r2);
  EXPECT_NEAR(f[0], 0.0, 1e-14);
  EXPECT_NEAR(f[2], 0.0, 1e-14);
}
