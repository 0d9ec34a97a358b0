#include "nonlinear/time_integrator.hpp"

namespace grout {

TimeIntegrator TimeIntegrator::of(TimeScheme scheme, double rho) {
  TimeIntegrator t;
  t.scheme = scheme;
  switch (scheme) {
    case TimeScheme::newmark:
      break;
    case TimeScheme::hht:
      t.alpha_f = (1.0 - rho) / (1.0 + rho);
      t.gamma = 0.5 + t.alpha_f;
      t.beta = 0.25 * (1.0 + t.alpha_f) * (1.0 + t.alpha_f);
      break;
    case TimeScheme::bossak:
      t.alpha_m = (rho - 1.0) / (rho + 1.0);
      t.gamma = 0.5 - t.alpha_m;
      t.beta = 0.25 * (1.0 - t.alpha_m) * (1.0 - t.alpha_m);
      break;
    case TimeScheme::generalized_alpha:
      t.alpha_m = (2.0 * rho - 1.0) / (rho + 1.0);
      t.alpha_f = rho / (rho + 1.0);
      t.gamma = 0.5 - t.alpha_m + t.alpha_f;
      t.beta = 0.25 * (1.0 - t.alpha_m + t.alpha_f) * (1.0 - t.alpha_m + t.alpha_f);
      break;
    case TimeScheme::energy_momentum:
      t.alpha_m = t.alpha_f = 0.5;
      break;
  }
  return t;
}

TimeIntegrator time_integrator_from(const DynamicsInput& input) {
  switch (input.scheme) {
    case DynamicsScheme::hht:
      return TimeIntegrator::of(TimeScheme::hht, input.rho_infinity);
    case DynamicsScheme::bossak:
      return TimeIntegrator::of(TimeScheme::bossak, input.rho_infinity);
    case DynamicsScheme::generalized_alpha:
      return TimeIntegrator::of(TimeScheme::generalized_alpha, input.rho_infinity);
    case DynamicsScheme::energy_momentum:
      return TimeIntegrator::of(TimeScheme::energy_momentum, 1.0);
    case DynamicsScheme::newmark:
      break;
  }
  TimeIntegrator t = TimeIntegrator::of(TimeScheme::newmark, 1.0);
  t.beta = input.beta;
  t.gamma = input.gamma;
  return t;
}

const char* scheme_name(TimeScheme scheme) {
  switch (scheme) {
    case TimeScheme::newmark:
      return "newmark";
    case TimeScheme::hht:
      return "hht";
    case TimeScheme::bossak:
      return "bossak";
    case TimeScheme::generalized_alpha:
      return "generalized_alpha";
    case TimeScheme::energy_momentum:
      return "energy_momentum";
  }
  return "?";
}

}  // namespace grout
