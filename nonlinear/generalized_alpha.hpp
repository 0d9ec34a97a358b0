#pragma once
// The generalised-α scheme (Chung & Hulbert, J. Appl. Mech. 60 (1993) 371, eq. 25) for a
// spectral radius ρ∞ ∈ [0, 1] at Δt → ∞: αm = (2ρ∞ − 1)/(ρ∞ + 1), αf = ρ∞/(ρ∞ + 1),
// γ = ½ − αm + αf, β = ¼ (1 − αm + αf)². Second order, with the least low-frequency
// dissipation for a given ρ∞; ρ∞ = 1 gives αm = αf = ½, β = ¼, γ = ½.

#include "nonlinear/generalized_alpha_family.hpp"

namespace grout {

class GeneralizedAlpha final : public GeneralizedAlphaFamily {
 public:
  explicit GeneralizedAlpha(double rho_infinity)
      : GeneralizedAlpha((2.0 * rho_infinity - 1.0) / (rho_infinity + 1.0),
                         rho_infinity / (rho_infinity + 1.0)) {}
  const char* name() const override { return "generalized_alpha"; }

 private:
  GeneralizedAlpha(double am, double af)
      : GeneralizedAlphaFamily(am, af, 0.25 * (1.0 - am + af) * (1.0 - am + af), 0.5 - am + af) {}
};

}  // namespace grout
