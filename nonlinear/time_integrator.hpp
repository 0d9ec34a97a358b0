#pragma once
// One-step implicit time integration of M a + f(u, t) = 0, generalised-α family (Chung &
// Hulbert, J. Appl. Mech. 60 (1993) 371, eqs. 2–4 and 25):
//
//   M a_{n+1−αm} + f(u_{n+1−αf}, t_{n+1−αf}) = 0,   x_{n+1−α} = (1 − α) x_{n+1} + α x_n,
//   u_{n+1} = u_n + Δt v_n + Δt² ((½ − β) a_n + β a_{n+1}),
//   v_{n+1} = v_n + Δt ((1 − γ) a_n + γ a_{n+1}).
//
// Schemes (ρ∞ = spectral radius at Δt → ∞, 1 = no numerical dissipation):
//   newmark            αm = αf = 0, β = ¼, γ = ½ (average acceleration; or the given β, γ)
//   hht                (Hilber, Hughes, Taylor 1977) αm = 0, αf = (1 − ρ∞)/(1 + ρ∞),
//                      γ = ½ + αf, β = ¼ (1 + αf)²;  ρ∞ ∈ [½, 1]
//   bossak             (Wood, Bossak, Zienkiewicz 1980) αm = (ρ∞ − 1)/(ρ∞ + 1), αf = 0,
//                      γ = ½ − αm, β = ¼ (1 − αm)²;  ρ∞ ∈ [0, 1]
//   generalized_alpha  αm = (2ρ∞ − 1)/(ρ∞ + 1), αf = ρ∞/(ρ∞ + 1), γ = ½ − αm + αf,
//                      β = ¼ (1 − αm + αf)²;  ρ∞ ∈ [0, 1]
//   energy_momentum    αm = αf = ½, β = ¼, γ = ½: generalized_alpha at ρ∞ = 1 (for a linear
//                      f_int the same steps as newmark), with the finite-strain solid's
//                      (f_{n+1} + f_n)/2 replaced by the energy-momentum force f_algo(u_n,
//                      u_{n+1}) (kernels/energy_momentum.hpp; DynamicProblem)
// All are second-order accurate and unconditionally stable for linear problems.
// The integrator owns only these coefficients; DynamicProblem applies them.

#include <string>

#include "io/input.hpp"

namespace grout {

enum class TimeScheme { newmark, hht, bossak, generalized_alpha, energy_momentum };

struct TimeIntegrator {
  TimeScheme scheme = TimeScheme::newmark;
  double alpha_m = 0.0, alpha_f = 0.0, beta = 0.25, gamma = 0.5;

  /// The coefficients of `scheme` for spectral radius rho_infinity (ignored by newmark).
  static TimeIntegrator of(TimeScheme scheme, double rho_infinity);

  /// a_{n+1} = (u_{n+1} − u_n − Δt v_n)/(β Δt²) − (1/(2β) − 1) a_n, per component.
  double acceleration(double du, double v_n, double a_n, double dt) const {
    return (du - dt * v_n) / (beta * dt * dt) - (0.5 / beta - 1.0) * a_n;
  }
  /// v_{n+1} from a_n and a_{n+1}.
  double velocity(double v_n, double a_n, double a_next, double dt) const {
    return v_n + dt * ((1.0 - gamma) * a_n + gamma * a_next);
  }
  /// ∂a_{n+1−αm}/∂u_{n+1} = (1 − αm)/(β Δt²): the mass term's factor in the Jacobian.
  double mass_factor(double dt) const { return (1.0 - alpha_m) / (beta * dt * dt); }
};

/// The integrator the input's `dynamics` section describes.
TimeIntegrator time_integrator_from(const DynamicsInput& input);

/// "newmark", "hht", "bossak", "generalized_alpha", "energy_momentum".
const char* scheme_name(TimeScheme scheme);

}  // namespace grout
