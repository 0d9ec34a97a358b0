#pragma once
// The energy-momentum scheme (Simo & Tarnow, ZAMP 43 (1992) 757, with Gonzalez's discrete
// gradient, CMAME 190 (2000) 1763): αm = αf = ½, β = ¼, γ = ½ (the generalised-α scheme at
// ρ∞ = 1, for a linear f_int the same steps as the average-acceleration rule), with the
// solid's force of a step the discrete gradient f_algo(u_n, u_{n+1}) of the stored energy
// (kernels/energy_momentum.hpp). The u rows then read
//   M (v_{n+1} − v_n)/Δt + f_algo(u_n, u_{n+1}) − ½ (f_ext,n + f_ext,n+1) + ½ f_c,n+1 − M g = 0,
// u_{n+1} − u_n = Δt/2 (v_n + v_{n+1}): a free hyperelastic body keeps its energy and angular
// momentum exactly under finite strain (the average-acceleration rule keeps neither).

#include "nonlinear/generalized_alpha_family.hpp"

namespace grout {

class EnergyMomentumScheme final : public GeneralizedAlphaFamily {
 public:
  EnergyMomentumScheme() : GeneralizedAlphaFamily(0.5, 0.5, 0.25, 0.5) {}
  const char* name() const override { return "energy_momentum"; }
  bool discrete_gradient_force() const override { return true; }
};

}  // namespace grout
