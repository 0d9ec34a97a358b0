// Plane stress under finite strain (kernels/plane_stress_material.hpp and the *_plane_stress
// laws of kernels/hyperelastic_material.hpp): the local Newton's S_33 = 0 to round-off, the
// uniaxial stretch of a sheet against its closed form, the small-strain limit (plane-stress
// Hooke), the derivative of the thickness stretch and the element's AD tangent against central
// differences, f_int = dPi/du, S(C) against P(F), and the energy-momentum element's energy.
#include <gtest/gtest.h>

#include <Sacado.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "kernels/energy_momentum.hpp"
#include "kernels/total_lagrangian.hpp"
#include "unit_tests/distorted_elements.hpp"

namespace {

using grout::ElasticConstants;
using grout::ElementStatus;
using grout::HyperelasticLaw;
using grout::MaterialStatus;
using grout_test::distorted_elements;
using grout_test::Element;

constexpr HyperelasticLaw laws[] = {HyperelasticLaw::neo_hookean_plane_stress,
                                    HyperelasticLaw::saint_venant_kirchhoff_plane_stress};

ElasticConstants constants(double nu = 0.3) {
  return grout::elastic_constants(210.0, nu, 2, false);  // the 3D Lamé constants
}

std::vector<Element> plane_elements() {
  std::vector<Element> out;
  for (const Element& e : distorted_elements())
    if (e.dim == 2) out.push_back(e);
  return out;
}

/// u = (F - I) X at every node of a 2D element (the 2 x 2 block of F).
std::vector<double> homogeneous_displacement(const Element& e, const double F[3][3]) {
  std::vector<double> u(e.dofs(), 0.0);
  for (int a = 0; a < e.nodes(); ++a)
    for (int i = 0; i < 2; ++i)
      for (int J = 0; J < 2; ++J) u[a * 2 + i] += (F[i][J] - (i == J ? 1.0 : 0.0)) * e.X[a * 2 + J];
  return u;
}

/// A random in-plane F = I + A, |A_ij| <= size, F_33 = 1 (the element's F; the law ignores F_33).
void random_F(std::mt19937& rng, double size, double F[3][3]) {
  std::uniform_real_distribution<double> dist(-size, size);
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J) F[i][J] = (i == J ? 1.0 : 0.0) + (i < 2 && J < 2 ? dist(rng) : 0.0);
}

TEST(PlaneStress, ThicknessStretchMakesTheOutOfPlaneStressVanish) {
  // For in-plane F up to |F - I| = 0.5 and nu from 0 to 0.499 (nu = -0.3: |F - I| <= 0.2, as
  // the Neo-Hookean sheet has no thickness stretch under strong compression for nu < 0), the 3D
  // law at the completed F has P_33 = F_33 S_33 = 0 to round-off of its terms (mu F_33,
  // lambda ln J / F_33).
  std::mt19937 rng(3);
  for (double nu : {-0.3, 0.0, 0.3, 0.45, 0.499})
    for (HyperelasticLaw law : laws)
      for (int trial = 0; trial < 50; ++trial) {
        const ElasticConstants c = constants(nu);
        double F[3][3], F_full[3][3], P[3][3], W = 0.0;
        random_F(rng, nu < 0.0 ? 0.2 : 0.5, F);
        if (law == HyperelasticLaw::saint_venant_kirchhoff_plane_stress) {
          // St. Venant-Kirchhoff has C_33 > 0 only for E_11 + E_22 < (lambda + 2 mu) / (2 lambda).
          const double trE2 = 0.5 * (F[0][0] * F[0][0] + F[1][0] * F[1][0] + F[0][1] * F[0][1] +
                                     F[1][1] * F[1][1] - 2.0);
          if (!(2.0 * c.lambda * trE2 < c.lambda + 2.0 * c.mu)) continue;
        }
        ASSERT_EQ(grout::complete_deformation_gradient(law, c, F, F_full), MaterialStatus::ok)
            << "nu " << nu << " law " << int(law);
        ASSERT_EQ(grout::first_piola_kirchhoff(grout::three_dimensional_law(law), c, F_full, P, W),
                  MaterialStatus::ok);
        const double scale =
            c.mu * F_full[2][2] + std::abs(c.lambda) * (1.0 + std::abs(std::log(F_full[2][2])));
        EXPECT_NEAR(P[2][2], 0.0, 1e-14 * scale) << "nu " << nu << " law " << int(law);
        // The plane-stress law gives the same P (it evaluates the 3D law at the same F).
        double P_ps[3][3], W_ps = 0.0;
        ASSERT_EQ(grout::first_piola_kirchhoff(law, c, F, P_ps, W_ps), MaterialStatus::ok);
        for (int i = 0; i < 3; ++i)
          for (int J = 0; J < 3; ++J) EXPECT_EQ(P_ps[i][J], P[i][J]);
        EXPECT_EQ(W_ps, W);
      }
}

TEST(PlaneStress, NoThicknessStretchIsReportedAsCollapsed) {
  // Neo-Hookean, nu = -0.5: no root for det C_2 < 0.199 (F_2 = 0.6 I: 0.1296); with 0.7 I
  // (0.2401) there is one. St. Venant-Kirchhoff: C_33 = 1 - 2 lambda (E_11 + E_22) / (lambda +
  // 2 mu) <= 0 for F_2 = 1.6 I at nu = 0.3 (1 - 2 * 1.5 * 1.56 / 3.5 < 0). det F_2 <= 0: both.
  const double F_small[3][3] = {{0.6, 0.0, 0.0}, {0.0, 0.6, 0.0}, {0.0, 0.0, 1.0}};
  const double F_fine[3][3] = {{0.7, 0.0, 0.0}, {0.0, 0.7, 0.0}, {0.0, 0.0, 1.0}};
  const double F_large[3][3] = {{1.6, 0.0, 0.0}, {0.0, 1.6, 0.0}, {0.0, 0.0, 1.0}};
  const double F_flip[3][3] = {{-1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
  double G[3][3];
  const auto nh = HyperelasticLaw::neo_hookean_plane_stress;
  const auto svk = HyperelasticLaw::saint_venant_kirchhoff_plane_stress;
  EXPECT_EQ(grout::complete_deformation_gradient(nh, constants(-0.5), F_small, G),
            MaterialStatus::collapsed);
  EXPECT_EQ(grout::complete_deformation_gradient(nh, constants(-0.5), F_fine, G),
            MaterialStatus::ok);
  EXPECT_EQ(grout::complete_deformation_gradient(svk, constants(0.3), F_large, G),
            MaterialStatus::collapsed);
  for (auto law : laws)
    EXPECT_EQ(grout::complete_deformation_gradient(law, constants(0.3), F_flip, G),
              MaterialStatus::collapsed);
}

TEST(PlaneStress, NeoHookeanUniaxialStretchMatchesClosedForm) {
  // A sheet stretched by lambda_1 along x, free in y and z: F = diag(l, s, t), P_22 = P_33 = 0.
  // Neo-Hookean P_aa = mu (F_aa - 1/F_aa) + lambda ln J / F_aa, J = l s t, so P_22 = P_33 = 0
  // read mu (s^2 - 1) + lambda ln J = 0 = mu (t^2 - 1) + lambda ln J: t = s, and
  //   mu (s^2 - 1) + lambda ln(l s^2) = 0   =>   l = s^-2 exp(mu (1 - s^2) / lambda),
  // explicit in the lateral stretch s. Then lambda ln J = -mu (s^2 - 1) and
  //   P_11 = mu (l - 1/l) - mu (s^2 - 1) / l = mu (l^2 - s^2) / l,
  //   sigma_11 = P_11 l / J = mu (l^2 - s^2) / (l s^2).
  // The element, given u = (F_2 - I) X with F_2 = diag(l, s), must reproduce these: P_22 = 0
  // (the in-plane force balance of the free edge), sigma_22 = sigma_33 = 0, F_33 = s.
  for (double nu : {0.0, 0.3, 0.49})
    for (double s : {0.6, 0.9, 1.05}) {
      const ElasticConstants c = constants(nu);
      if (c.lambda == 0.0) continue;  // nu = 0: t = s = 1 for every l (no contraction)
      const double l = std::exp(c.mu * (1.0 - s * s) / c.lambda) / (s * s);
      const double F[3][3] = {{l, 0.0, 0.0}, {0.0, s, 0.0}, {0.0, 0.0, 1.0}};
      double F_full[3][3], P[3][3], W = 0.0;
      ASSERT_EQ(grout::complete_deformation_gradient(HyperelasticLaw::neo_hookean_plane_stress, c,
                                                     F, F_full),
                MaterialStatus::ok);
      EXPECT_NEAR(F_full[2][2], s, 1e-14);
      ASSERT_EQ(grout::first_piola_kirchhoff(HyperelasticLaw::neo_hookean_plane_stress, c, F, P, W),
                MaterialStatus::ok);
      const double P11 = c.mu * (l * l - s * s) / l;
      EXPECT_NEAR(P[0][0], P11, 1e-13 * std::abs(P11)) << "nu " << nu << " s " << s;
      EXPECT_NEAR(P[1][1], 0.0, 1e-13 * std::abs(P11));
      const double sigma11 = c.mu * (l * l - s * s) / (l * s * s);
      for (const Element& e : plane_elements()) {
        const auto u = homogeneous_displacement(e, F);
        double stress[6];
        ASSERT_EQ(grout::total_lagrangian_cauchy_stress(e.t, e.dim, e.X.data(), u.data(),
                                                        HyperelasticLaw::neo_hookean_plane_stress,
                                                        c, stress),
                  ElementStatus::ok);
        const double expected[4] = {sigma11, 0.0, 0.0, 0.0};  // xx, yy, xy, zz
        for (int k = 0; k < 4; ++k)
          EXPECT_NEAR(stress[k], expected[k], 1e-13 * std::abs(sigma11))
              << "topology " << int(e.t) << " component " << k;
      }
    }
}

TEST(PlaneStress, SaintVenantKirchhoffUniaxialStretchMatchesClosedForm) {
  // F = diag(l, s, t), S = lambda tr E I + 2 mu E: S_22 = S_33 = 0 give E_22 = E_33 and
  // lambda E_11 + (2 lambda + 2 mu) E_22 = 0, E_22 = -lambda / (2 (lambda + mu)) E_11 = -nu E_11;
  // S_11 = (lambda + 2 mu) E_11 + 2 lambda E_22 = E_Young E_11, E_11 = (l^2 - 1)/2, s = t =
  // sqrt(1 - 2 nu E_11), sigma_11 = l^2 S_11 / (l s^2).
  const double E = 210.0;
  for (double nu : {0.0, 0.3, 0.49})
    for (double l : {0.8, 1.2, 1.5}) {
      const ElasticConstants c = constants(nu);
      const double E11 = 0.5 * (l * l - 1.0), s = std::sqrt(1.0 - 2.0 * nu * E11);
      const double sigma11 = l * E * E11 / (s * s);
      const double F[3][3] = {{l, 0.0, 0.0}, {0.0, s, 0.0}, {0.0, 0.0, 1.0}};
      for (const Element& e : plane_elements()) {
        const auto u = homogeneous_displacement(e, F);
        double stress[6];
        ASSERT_EQ(grout::total_lagrangian_cauchy_stress(
                      e.t, e.dim, e.X.data(), u.data(),
                      HyperelasticLaw::saint_venant_kirchhoff_plane_stress, c, stress),
                  ElementStatus::ok);
        const double expected[4] = {sigma11, 0.0, 0.0, 0.0};
        for (int k = 0; k < 4; ++k)
          EXPECT_NEAR(stress[k], expected[k], 1e-13 * std::abs(sigma11))
              << "nu " << nu << " l " << l << " component " << k;
      }
    }
}

TEST(PlaneStress, SmallStrainLimitIsPlaneStressHooke) {
  // P(I + eps G) = C*:sym(eps G) + O(eps^2) with the plane-stress Hooke law, lambda* =
  // E nu / (1 - nu^2) (elastic_constants with plane_stress = true). Relative error ~ eps.
  std::mt19937 rng(11);
  for (HyperelasticLaw law : laws)
    for (int trial = 0; trial < 10; ++trial) {
      const double eps = 1e-6;
      double F[3][3];
      random_F(rng, 1.0, F);
      for (int i = 0; i < 2; ++i)
        for (int J = 0; J < 2; ++J) F[i][J] = (i == J ? 1.0 : 0.0) + eps * (F[i][J] - (i == J));
      double P[3][3], W = 0.0;
      ASSERT_EQ(grout::first_piola_kirchhoff(law, constants(), F, P, W), MaterialStatus::ok);
      const ElasticConstants h = grout::elastic_constants(210.0, 0.3, 2, true);
      double strain[2][2];
      for (int i = 0; i < 2; ++i)
        for (int J = 0; J < 2; ++J) strain[i][J] = 0.5 * (F[i][J] + F[J][i]) - (i == J);
      const double tr = strain[0][0] + strain[1][1];
      for (int i = 0; i < 2; ++i)
        for (int J = 0; J < 2; ++J) {
          const double hooke = h.lambda * tr * (i == J) + 2.0 * h.mu * strain[i][J];
          EXPECT_NEAR(P[i][J], hooke, 1e-5 * 210.0 * eps) << "law " << int(law);
        }
    }
}

TEST(PlaneStress, ThicknessStretchDerivativeMatchesCentralDifferences) {
  // dF_33/dF_iJ by forward AD through the local Newton (with its extra step at h = 0) against
  // central differences of the double Newton: error O(h^2) + O(eps / h).
  using Fad = Sacado::Fad::SFad<double, 4>;
  std::mt19937 rng(13);
  for (HyperelasticLaw law : laws)
    for (int trial = 0; trial < 20; ++trial) {
      double F[3][3];
      random_F(rng, 0.3, F);
      Fad F_ad[3][3], F_full_ad[3][3];
      for (int i = 0; i < 3; ++i)
        for (int J = 0; J < 3; ++J) F_ad[i][J] = F[i][J];
      for (int k = 0; k < 4; ++k) F_ad[k / 2][k % 2].diff(k, 4);
      ASSERT_EQ(grout::complete_deformation_gradient(law, constants(), F_ad, F_full_ad),
                MaterialStatus::ok);
      const double h = 1e-6;
      for (int k = 0; k < 4; ++k) {
        double Fp[3][3], Fm[3][3], Gp[3][3], Gm[3][3];
        std::copy(&F[0][0], &F[0][0] + 9, &Fp[0][0]);
        std::copy(&F[0][0], &F[0][0] + 9, &Fm[0][0]);
        Fp[k / 2][k % 2] += h;
        Fm[k / 2][k % 2] -= h;
        ASSERT_EQ(grout::complete_deformation_gradient(law, constants(), Fp, Gp),
                  MaterialStatus::ok);
        ASSERT_EQ(grout::complete_deformation_gradient(law, constants(), Fm, Gm),
                  MaterialStatus::ok);
        EXPECT_NEAR(F_full_ad[2][2].dx(k), (Gp[2][2] - Gm[2][2]) / (2 * h), 1e-8)
            << "law " << int(law) << " component " << k;
      }
    }
}

std::vector<double> random_displacement(const Element& e, std::mt19937& rng, double size) {
  std::uniform_real_distribution<double> dist(-size, size);
  std::vector<double> u(e.dofs());
  for (double& v : u) v = dist(rng);
  return u;
}

TEST(PlaneStress, ElementTangentMatchesCentralDifferences) {
  // The consistent plane-stress tangent (AD through F_33) against central differences of f_int.
  std::mt19937 rng(5);
  for (HyperelasticLaw law : laws)
    for (const Element& e : plane_elements()) {
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
        ASSERT_EQ(grout::total_lagrangian_element<double>(e.t, e.dim, e.X.data(), up.data(), law,
                                                          constants(), fp.data(), nullptr),
                  ElementStatus::ok);
        ASSERT_EQ(grout::total_lagrangian_element<double>(e.t, e.dim, e.X.data(), um.data(), law,
                                                          constants(), fm.data(), nullptr),
                  ElementStatus::ok);
        for (int r = 0; r < n; ++r)
          EXPECT_NEAR(K[r * n + k], (fp[r] - fm[r]) / (2 * h), 1e-7 * scale)
              << "law " << int(law) << " topology " << int(e.t) << " entry " << r << "," << k;
      }
      // The plane-strain tangent differs (the test can fail): F_33 = 1 stiffens the sheet.
      const HyperelasticLaw strain_law = grout::three_dimensional_law(law);
      std::vector<double> K_strain(n * n);
      grout::total_lagrangian_force_and_tangent(e.t, e.dim, e.X.data(), u.data(), strain_law,
                                                constants(), f.data(), K_strain.data());
      double diff = 0.0;
      for (int k = 0; k < n * n; ++k) diff = std::max(diff, std::abs(K_strain[k] - K[k]));
      EXPECT_GT(diff, 1e-2 * scale);
    }
}

double element_energy(const Element& e, HyperelasticLaw law, const std::vector<double>& u) {
  std::vector<double> f(e.dofs());
  double W = 0.0;
  EXPECT_EQ(grout::total_lagrangian_element<double>(e.t, e.dim, e.X.data(), u.data(), law,
                                                    constants(), f.data(), &W),
            ElementStatus::ok);
  return W;
}

TEST(PlaneStress, InternalForceIsTheEnergyGradient) {
  // W_ps(F_2) = W(F_2, F_33(F_2)) has dW_ps/dF_2 = P_2 since P_33 = 0 (file comment of
  // kernels/plane_stress_material.hpp): f_int = dPi/du, by central differences of Pi.
  std::mt19937 rng(17);
  for (HyperelasticLaw law : laws)
    for (const Element& e : plane_elements()) {
      const auto u = random_displacement(e, rng, 0.2);
      std::vector<double> f(e.dofs());
      grout::total_lagrangian_element<double>(e.t, e.dim, e.X.data(), u.data(), law, constants(),
                                              f.data(), nullptr);
      double scale = 0.0;
      for (double v : f) scale = std::max(scale, std::abs(v));
      const double h = 1e-5;
      for (int k = 0; k < e.dofs(); ++k) {
        auto up = u, um = u;
        up[k] += h;
        um[k] -= h;
        const double dPi = (element_energy(e, law, up) - element_energy(e, law, um)) / (2 * h);
        EXPECT_NEAR(f[k], dPi, 1e-7 * scale) << "law " << int(law) << " dof " << k;
      }
    }
}

TEST(PlaneStress, SecondPiolaKirchhoffOfCMatchesFirstPiolaKirchhoff) {
  // The law of C (used by the energy-momentum element) at C = F^T F with C_33 = 1 (ignored):
  // F_2 S_2 = P_2, S_33 = 0, and the same W; strain_energy_of_C gives that W too.
  std::mt19937 rng(19);
  for (HyperelasticLaw law : laws)
    for (int trial = 0; trial < 20; ++trial) {
      double F[3][3], C[3][3], P[3][3], S[3][3], W_F = 0.0, W_C = 0.0, W_only = 0.0;
      random_F(rng, 0.3, F);
      for (int I = 0; I < 3; ++I)
        for (int K = 0; K < 3; ++K) {
          C[I][K] = 0.0;
          for (int i = 0; i < 3; ++i) C[I][K] += F[i][I] * F[i][K];
        }
      ASSERT_EQ(grout::first_piola_kirchhoff(law, constants(), F, P, W_F), MaterialStatus::ok);
      ASSERT_EQ(grout::second_piola_kirchhoff(law, constants(), C, S, W_C), MaterialStatus::ok);
      ASSERT_EQ(grout::strain_energy_of_C(law, constants(), C, W_only), MaterialStatus::ok);
      EXPECT_NEAR(W_C, W_F, 1e-13 * constants().mu);
      EXPECT_NEAR(W_only, W_F, 1e-13 * constants().mu);
      EXPECT_NEAR(S[2][2], 0.0, 1e-12 * constants().mu);
      for (int i = 0; i < 2; ++i)
        for (int J = 0; J < 2; ++J)
          EXPECT_NEAR(F[i][0] * S[0][J] + F[i][1] * S[1][J], P[i][J], 1e-12 * constants().mu);
    }
}

TEST(PlaneStress, EnergyMomentumWorkIsTheEnergyChange) {
  // f_algo . (u - u_n) = Pi(u) - Pi(u_n) with the sheet's W_ps (Gonzalez's discrete gradient
  // holds for any hyperelastic law of C_2), f_algo = (f + f_int(u_n)) / 2.
  std::mt19937 rng(23);
  for (HyperelasticLaw law : laws)
    for (const Element& e : plane_elements()) {
      const auto u_n = random_displacement(e, rng, 0.15);
      const auto u = random_displacement(e, rng, 0.15);
      std::vector<double> f(e.dofs()), f_n(e.dofs());
      ASSERT_EQ(grout::energy_momentum_element<double>(e.t, e.dim, e.X.data(), u_n.data(), u.data(),
                                                       law, constants(), f.data()),
                ElementStatus::ok);
      grout::total_lagrangian_element<double>(e.t, e.dim, e.X.data(), u_n.data(), law, constants(),
                                              f_n.data(), nullptr);
      double work = 0.0, scale = 0.0;
      for (int k = 0; k < e.dofs(); ++k) {
        const double f_algo = 0.5 * (f[k] + f_n[k]);
        work += f_algo * (u[k] - u_n[k]);
        scale += std::abs(f_algo * (u[k] - u_n[k]));
      }
      const double dPi = element_energy(e, law, u) - element_energy(e, law, u_n);
      EXPECT_NEAR(work, dPi, 1e-12 * scale) << "law " << int(law) << " topology " << int(e.t);
    }
}

}  // namespace
