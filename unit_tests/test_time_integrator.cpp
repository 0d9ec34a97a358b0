// The time schemes (nonlinear/time_integrator.hpp and one class per scheme) on the
// single-degree-of-freedom oscillator m a + k u = 0, m = 1, k = ω²: the one-step recursion of
// Chung & Hulbert (1993) written out by hand around the schemes' own correctors (one dof per
// rank), checked against the exact solution u = cos ωt (second order), the energy of the
// average-acceleration rule (exactly conserved), and the spectral radius at ω Δt → ∞ (equal
// to the requested ρ∞); the coefficients against the papers; the tangent's mass factor against
// a central difference of the corrector; the factory against the input's scheme.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <cmath>
#include <memory>

#include "nonlinear/generalized_alpha_family.hpp"

namespace {

using namespace grout;

struct State {
  double u, v, a;
};

// One dof on every rank: the correctors work on Tpetra vectors.
Teuchos::RCP<const Map> one_dof_map() {
  return Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(), 1, 0,
                              Tpetra::getDefaultComm()));
}
Vector vector_of(double x) {
  static const auto map = one_dof_map();
  Vector v(map);
  v.putScalar(x);
  return v;
}
double value(const Vector& v) {
  return v.getLocalViewHost(Tpetra::Access::ReadOnly)(0, 0);
}

double corrected_acceleration(const TimeIntegrator& ti, const State& s, double u_next, double dt) {
  Vector a_next = vector_of(0.0);
  ti.acceleration(vector_of(u_next), vector_of(s.u), vector_of(s.v), vector_of(s.a), dt, a_next);
  return value(a_next);
}

// One step: (1 − αm) a_{n+1} + αm a_n + ω² ((1 − αf) u_{n+1} + αf u_n) = 0, with a_{n+1}(u_{n+1}).
State step(const GeneralizedAlphaFamily& ti, const State& s, double omega, double dt) {
  const double k = omega * omega, c0 = 1.0 / (ti.beta() * dt * dt), c2 = 0.5 / ti.beta() - 1.0;
  const double am = ti.alpha_m(), af = ti.alpha_f();
  const double lhs = (1.0 - am) * c0 + (1.0 - af) * k;
  const double rhs = (1.0 - am) * (c0 * (s.u + dt * s.v) + c2 * s.a) - am * s.a - af * k * s.u;
  State next;
  next.u = rhs / lhs;
  next.a = corrected_acceleration(ti, s, next.u, dt);
  Vector v_next = vector_of(0.0);
  ti.velocity(vector_of(s.v), vector_of(s.a), vector_of(next.a), dt, v_next);
  next.v = value(v_next);
  return next;
}

// Velocity error after one period: v(T) = 0 exactly, so it measures the phase error, O(Δt²)
// (the displacement at the peak would only show its square).
double error_after_one_period(const GeneralizedAlphaFamily& ti, int steps) {
  const double omega = 2.0 * M_PI, dt = 1.0 / steps;
  State s{1.0, 0.0, -omega * omega};
  for (int n = 0; n < steps; ++n) s = step(ti, s, omega, dt);
  return std::abs(s.v) / omega;
}

TEST(TimeIntegrator, AverageAccelerationConservesEnergy) {
  const Newmark ti;
  const double omega = 3.0, dt = 0.37;  // a large step: still exact energy
  State s{0.4, 1.3, -omega * omega * 0.4};
  const double E0 = 0.5 * s.v * s.v + 0.5 * omega * omega * s.u * s.u;
  for (int n = 0; n < 200; ++n) s = step(ti, s, omega, dt);
  EXPECT_NEAR(0.5 * s.v * s.v + 0.5 * omega * omega * s.u * s.u, E0, 1e-12 * E0);
}

// The schemes with a ρ∞ (0, 1, 2), and newmark (3).
std::unique_ptr<GeneralizedAlphaFamily> scheme_at(int which, double rho) {
  if (which == 0) return std::make_unique<Hht>(rho);
  if (which == 1) return std::make_unique<Bossak>(rho);
  if (which == 2) return std::make_unique<GeneralizedAlpha>(rho);
  return std::make_unique<Newmark>();
}

TEST(TimeIntegrator, SecondOrderAccurate) {
  for (int which = 0; which < 4; ++which) {
    const auto ti = scheme_at(which, 0.8);
    const double e1 = error_after_one_period(*ti, 50), e2 = error_after_one_period(*ti, 100);
    EXPECT_NEAR(std::log2(e1 / e2), 2.0, 0.1) << ti->name();
  }
}

TEST(TimeIntegrator, SpectralRadiusAtInfinityIsRhoInfinity) {
  for (int which = 0; which < 3; ++which) {
    for (double rho : {0.6, 0.8, 1.0}) {
      const auto ti = scheme_at(which, rho);
      const double omega = 1e5, dt = 1.0;
      State s{1.0, 0.0, -omega * omega};
      auto norm = [&](const State& x) {
        return std::sqrt(x.u * x.u * omega * omega + x.v * x.v + x.a * x.a / (omega * omega));
      };
      // Mean decay rate over steps 1000..2000, the state renormalised every step (the
      // recursion is linear). At Δt → ∞ the eigenvalue −ρ∞ is double (a Jordan block), so the
      // norm decays as n ρ∞ⁿ: the factor (2000/1000)^(1/1000) = 1.0007 stays within the bound.
      double log_growth = 0.0;
      for (int n = 0; n < 2000; ++n) {
        s = step(*ti, s, omega, dt);
        const double size = norm(s);
        if (n >= 1000) log_growth += std::log(size);
        s.u /= size, s.v /= size, s.a /= size;
      }
      EXPECT_NEAR(std::exp(log_growth / 1000.0), rho, 2e-3)
          << ti->name() << " rho_infinity " << rho;
    }
  }
}

TEST(TimeIntegrator, CoefficientsOfTheFamily) {
  // Chung & Hulbert (1993), eq. 25 at ρ∞ = 1: αm = αf = ½, β = ¼, γ = ½ (trapezoidal).
  const GeneralizedAlpha g(1.0);
  EXPECT_DOUBLE_EQ(g.alpha_m(), 0.5);
  EXPECT_DOUBLE_EQ(g.alpha_f(), 0.5);
  EXPECT_DOUBLE_EQ(g.beta(), 0.25);
  EXPECT_DOUBLE_EQ(g.gamma(), 0.5);
  EXPECT_FALSE(g.discrete_gradient_force());
  // energy_momentum: the same coefficients, with the discrete-gradient solid force.
  const EnergyMomentumScheme em;
  EXPECT_DOUBLE_EQ(em.alpha_m(), 0.5);
  EXPECT_DOUBLE_EQ(em.alpha_f(), 0.5);
  EXPECT_DOUBLE_EQ(em.beta(), 0.25);
  EXPECT_DOUBLE_EQ(em.gamma(), 0.5);
  EXPECT_TRUE(em.discrete_gradient_force());
  EXPECT_STREQ(em.name(), "energy_momentum");
  // HHT at ρ∞ = ½: α = −1/3 (Hilber, Hughes, Taylor 1977), γ = 5/6, β = 4/9.
  const Hht h(0.5);
  EXPECT_DOUBLE_EQ(h.alpha_m(), 0.0);
  EXPECT_NEAR(h.alpha_f(), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(h.gamma(), 5.0 / 6.0, 1e-15);
  EXPECT_NEAR(h.beta(), 4.0 / 9.0, 1e-15);
  // Bossak at ρ∞ = ½: αm = −1/3 (Wood, Bossak, Zienkiewicz 1980), γ = 5/6, β = 4/9.
  const Bossak b(0.5);
  EXPECT_NEAR(b.alpha_m(), -1.0 / 3.0, 1e-15);
  EXPECT_DOUBLE_EQ(b.alpha_f(), 0.0);
  EXPECT_NEAR(b.gamma(), 5.0 / 6.0, 1e-15);
  EXPECT_NEAR(b.beta(), 4.0 / 9.0, 1e-15);
}

// The tangent's mass factor is ∂a_{n+1−αm}/∂u_{n+1} = (1 − αm) ∂a_{n+1}/∂u_{n+1}: a central
// difference of the corrector (linear in u_{n+1}: exact to round-off).
TEST(TimeIntegrator, MassFactorIsTheDerivativeOfTheCorrector) {
  for (int which = 0; which < 3; ++which) {
    const auto ti = scheme_at(which, 0.7);
    const State s{0.3, -1.1, 2.5};
    const double dt = 0.05, u = 0.31, h = 1e-3;
    const double fd =
        (1.0 - ti->alpha_m()) *
        (corrected_acceleration(*ti, s, u + h, dt) - corrected_acceleration(*ti, s, u - h, dt)) /
        (2.0 * h);
    EXPECT_NEAR(ti->mass_factor(dt), fd, 1e-7 * std::abs(fd)) << ti->name();
  }
}

TEST(TimeIntegrator, FactoryGivesTheInputsScheme) {
  DynamicsInput input;
  input.rho_infinity = 0.6;
  const struct {
    DynamicsScheme scheme;
    const char* name;
    double alpha_m, alpha_f;
  } cases[] = {{DynamicsScheme::newmark, "newmark", 0.0, 0.0},
               {DynamicsScheme::hht, "hht", 0.0, 0.25},
               {DynamicsScheme::bossak, "bossak", -0.25, 0.0},
               {DynamicsScheme::generalized_alpha, "generalized_alpha", 0.125, 0.375},
               {DynamicsScheme::energy_momentum, "energy_momentum", 0.5, 0.5}};
  for (const auto& c : cases) {
    input.scheme = c.scheme;
    const auto ti = make_time_integrator(input);
    EXPECT_STREQ(ti->name(), c.name);
    EXPECT_NEAR(ti->alpha_m(), c.alpha_m, 1e-15) << c.name;
    EXPECT_NEAR(ti->alpha_f(), c.alpha_f, 1e-15) << c.name;
    EXPECT_EQ(ti->discrete_gradient_force(), c.scheme == DynamicsScheme::energy_momentum);
  }
  // newmark takes β and γ from the input: (1 − 0)/(β Δt²) at β = 0.3, Δt = 0.1.
  input.scheme = DynamicsScheme::newmark;
  input.beta = 0.3, input.gamma = 0.6;
  EXPECT_NEAR(make_time_integrator(input)->mass_factor(0.1), 1.0 / 0.003, 1e-9);
}

}  // namespace
