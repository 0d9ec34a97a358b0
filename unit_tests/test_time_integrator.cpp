// Generalised-α coefficients (nonlinear/time_integrator.hpp) on the single-degree-of-freedom
// oscillator m a + k u = 0, m = 1, k = ω²: the one-step recursion of Chung & Hulbert (1993)
// written out by hand, checked against the exact solution u = cos ωt (second order), the
// energy of the average-acceleration rule (exactly conserved), and the spectral radius at
// ω Δt → ∞ (equal to the requested ρ∞).
#include <gtest/gtest.h>

#include <cmath>

#include "nonlinear/time_integrator.hpp"

namespace {

using grout::TimeIntegrator;
using grout::TimeScheme;

struct State {
  double u, v, a;
};

// One step: (1 − αm) a_{n+1} + αm a_n + ω² ((1 − αf) u_{n+1} + αf u_n) = 0, with a_{n+1}(u_{n+1}).
State step(const TimeIntegrator& ti, const State& s, double omega, double dt) {
  const double k = omega * omega, c0 = 1.0 / (ti.beta * dt * dt), c2 = 0.5 / ti.beta - 1.0;
  const double lhs = (1.0 - ti.alpha_m) * c0 + (1.0 - ti.alpha_f) * k;
  const double rhs = (1.0 - ti.alpha_m) * (c0 * (s.u + dt * s.v) + c2 * s.a) - ti.alpha_m * s.a -
                     ti.alpha_f * k * s.u;
  State next;
  next.u = rhs / lhs;
  next.a = ti.acceleration(next.u - s.u, s.v, s.a, dt);
  next.v = ti.velocity(s.v, s.a, next.a, dt);
  return next;
}

// Velocity error after one period: v(T) = 0 exactly, so it measures the phase error, O(Δt²)
// (the displacement at the peak would only show its square).
double error_after_one_period(const TimeIntegrator& ti, int steps) {
  const double omega = 2.0 * M_PI, dt = 1.0 / steps;
  State s{1.0, 0.0, -omega * omega};
  for (int n = 0; n < steps; ++n) s = step(ti, s, omega, dt);
  return std::abs(s.v) / omega;
}

const TimeScheme schemes[] = {TimeScheme::newmark, TimeScheme::hht, TimeScheme::bossak,
                              TimeScheme::generalized_alpha};

TEST(TimeIntegrator, SecondOrderAccurate) {
  for (TimeScheme scheme : schemes) {
    const TimeIntegrator ti = TimeIntegrator::of(scheme, 0.8);
    const double e1 = error_after_one_period(ti, 50), e2 = error_after_one_period(ti, 100);
    EXPECT_NEAR(std::log2(e1 / e2), 2.0, 0.1) << grout::scheme_name(scheme);
  }
}

TEST(TimeIntegrator, AverageAccelerationConservesEnergy) {
  const TimeIntegrator ti = TimeIntegrator::of(TimeScheme::newmark, 1.0);
  const double omega = 3.0, dt = 0.37;  // a large step: still exact energy
  State s{0.4, 1.3, -omega * omega * 0.4};
  const double E0 = 0.5 * s.v * s.v + 0.5 * omega * omega * s.u * s.u;
  for (int n = 0; n < 200; ++n) s = step(ti, s, omega, dt);
  EXPECT_NEAR(0.5 * s.v * s.v + 0.5 * omega * omega * s.u * s.u, E0, 1e-12 * E0);
}

TEST(TimeIntegrator, SpectralRadiusAtInfinityIsRhoInfinity) {
  for (TimeScheme scheme : {TimeScheme::hht, TimeScheme::bossak, TimeScheme::generalized_alpha}) {
    for (double rho : {0.6, 0.8, 1.0}) {
      const TimeIntegrator ti = TimeIntegrator::of(scheme, rho);
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
        s = step(ti, s, omega, dt);
        const double size = norm(s);
        if (n >= 1000) log_growth += std::log(size);
        s.u /= size, s.v /= size, s.a /= size;
      }
      EXPECT_NEAR(std::exp(log_growth / 1000.0), rho, 2e-3)
          << grout::scheme_name(scheme) << " rho_infinity " << rho;
    }
  }
}

TEST(TimeIntegrator, CoefficientsOfTheFamily) {
  // Chung & Hulbert (1993), eq. 25 at ρ∞ = 1: αm = αf = ½, β = ¼, γ = ½ (trapezoidal).
  const TimeIntegrator g = TimeIntegrator::of(TimeScheme::generalized_alpha, 1.0);
  EXPECT_DOUBLE_EQ(g.alpha_m, 0.5);
  EXPECT_DOUBLE_EQ(g.alpha_f, 0.5);
  EXPECT_DOUBLE_EQ(g.beta, 0.25);
  EXPECT_DOUBLE_EQ(g.gamma, 0.5);
  // energy_momentum: the same coefficients (its force term differs under finite strain only).
  const TimeIntegrator em = TimeIntegrator::of(TimeScheme::energy_momentum, 0.3);
  EXPECT_DOUBLE_EQ(em.alpha_m, 0.5);
  EXPECT_DOUBLE_EQ(em.alpha_f, 0.5);
  EXPECT_DOUBLE_EQ(em.beta, 0.25);
  EXPECT_DOUBLE_EQ(em.gamma, 0.5);
  EXPECT_STREQ(grout::scheme_name(TimeScheme::energy_momentum), "energy_momentum");
  // HHT at ρ∞ = ½: α = −1/3 (Hilber, Hughes, Taylor 1977), γ = 5/6, β = 4/9.
  const TimeIntegrator h = TimeIntegrator::of(TimeScheme::hht, 0.5);
  EXPECT_NEAR(h.alpha_f, 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(h.gamma, 5.0 / 6.0, 1e-15);
  EXPECT_NEAR(h.beta, 4.0 / 9.0, 1e-15);
}

}  // namespace
