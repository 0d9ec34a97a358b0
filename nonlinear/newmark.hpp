#pragma once
// Newmark's scheme (Newmark, J. Eng. Mech. Div. ASCE 85 (1959) 67): αm = αf = 0 and the given
// β, γ; the default β = ¼, γ = ½ is the average-acceleration rule, second-order accurate,
// unconditionally stable and without numerical dissipation for a linear f (its energy is kept
// exactly). γ > ½ dissipates and is first order. The input asks β ≥ (γ + ½)²/4 (io/).

#include "nonlinear/generalized_alpha_family.hpp"

namespace grout {

class Newmark final : public GeneralizedAlphaFamily {
 public:
  explicit Newmark(double beta = 0.25, double gamma = 0.5)
      : GeneralizedAlphaFamily(0.0, 0.0, beta, gamma) {}
  const char* name() const override { return "newmark"; }
};

}  // namespace grout
