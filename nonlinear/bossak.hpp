#pragma once
// The Bossak-α scheme (Wood, Bossak & Zienkiewicz, IJNME 15 (1980) 1562) for a spectral
// radius ρ∞ ∈ [0, 1] at Δt → ∞: αm = (ρ∞ − 1)/(ρ∞ + 1) (≤ 0), αf = 0, γ = ½ − αm,
// β = ¼ (1 − αm)². Second order; ρ∞ = 1 is the average-acceleration rule.

#include "nonlinear/generalized_alpha_family.hpp"

namespace grout {

class Bossak final : public GeneralizedAlphaFamily {
 public:
  explicit Bossak(double rho_infinity) : Bossak(alpha_m_of(rho_infinity), 0) {}
  const char* name() const override { return "bossak"; }

 private:
  static double alpha_m_of(double rho) { return (rho - 1.0) / (rho + 1.0); }
  Bossak(double am, int)
      : GeneralizedAlphaFamily(am, 0.0, 0.25 * (1.0 - am) * (1.0 - am), 0.5 - am) {}
};

}  // namespace grout
