#pragma once
// The HHT-α scheme (Hilber, Hughes & Taylor, Earthq. Eng. Struct. Dyn. 5 (1977) 283) for a
// spectral radius ρ∞ ∈ [½, 1] at Δt → ∞: αm = 0, αf = (1 − ρ∞)/(1 + ρ∞) (their −α),
// γ = ½ + αf, β = ¼ (1 + αf)². Second order; ρ∞ = 1 is the average-acceleration rule.

#include "nonlinear/generalized_alpha_family.hpp"

namespace grout {

class Hht final : public GeneralizedAlphaFamily {
 public:
  explicit Hht(double rho_infinity) : Hht(alpha_f_of(rho_infinity), 0) {}
  const char* name() const override { return "hht"; }

 private:
  static double alpha_f_of(double rho) { return (1.0 - rho) / (1.0 + rho); }
  Hht(double af, int) : GeneralizedAlphaFamily(0.0, af, 0.25 * (1.0 + af) * (1.0 + af), 0.5 + af) {}
};

}  // namespace grout
