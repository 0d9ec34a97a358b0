#include "nonlinear/time_integrator.hpp"

#include "nonlinear/generalized_alpha_family.hpp"

namespace grout {

std::unique_ptr<const TimeIntegrator> make_time_integrator(const DynamicsInput& input) {
  switch (input.scheme) {
    case DynamicsScheme::hht:
      return std::make_unique<Hht>(input.rho_infinity);
    case DynamicsScheme::bossak:
      return std::make_unique<Bossak>(input.rho_infinity);
    case DynamicsScheme::generalized_alpha:
      return std::make_unique<GeneralizedAlpha>(input.rho_infinity);
    case DynamicsScheme::energy_momentum:
      return std::make_unique<EnergyMomentumScheme>();
    case DynamicsScheme::newmark:
      break;
  }
  return std::make_unique<Newmark>(input.beta, input.gamma);
}

}  // namespace grout
