#pragma once
// The generalised-α family (Chung & Hulbert, J. Appl. Mech. 60 (1993) 371, eqs. 2–4):
//
//   M a_{n+1−αm} + f(u_{n+1−αf}, t_{n+1−αf}) = 0,   x_{n+1−α} = (1 − α) x_{n+1} + α x_n,
//   u_{n+1} = u_n + Δt v_n + Δt² ((½ − β) a_n + β a_{n+1}),
//   v_{n+1} = v_n + Δt ((1 − γ) a_n + γ a_{n+1}).
//
// Every scheme of the input is a member, set by its four coefficients (αm, αf, β, γ): the base
// holds them and the Newmark correctors, and the schemes below only set them (each with its
// source). For a linear f, (1 − αf) f(u_{n+1}) + αf f(u_n) (the effective residual of
// time_integrator.hpp) is f(u_{n+1−αf}) exactly.

#include "nonlinear/time_integrator.hpp"

namespace grout {

class GeneralizedAlphaFamily : public TimeIntegrator {
 public:
  double alpha_m() const final { return alpha_m_; }
  double alpha_f() const final { return alpha_f_; }
  double beta() const { return beta_; }
  double gamma() const { return gamma_; }

  /// ∂a_{n+1−αm}/∂u_{n+1} = (1 − αm)/(β Δt²).
  double mass_factor(double dt) const final { return (1.0 - alpha_m_) / (beta_ * dt * dt); }

  /// a_{n+1} = (u_{n+1} − u_n − Δt v_n)/(β Δt²) − (1/(2β) − 1) a_n, per component.
  void acceleration(const Vector& u_next, const Vector& u_n, const Vector& v_n, const Vector& a_n,
                    double dt, Vector& a_next) const final;
  /// v_{n+1} = v_n + Δt ((1 − γ) a_n + γ a_{n+1}).
  void velocity(const Vector& v_n, const Vector& a_n, const Vector& a_next, double dt,
                Vector& v_next) const final;

 protected:
  GeneralizedAlphaFamily(double alpha_m, double alpha_f, double beta, double gamma)
      : alpha_m_(alpha_m), alpha_f_(alpha_f), beta_(beta), gamma_(gamma) {}

 private:
  double alpha_m_, alpha_f_, beta_, gamma_;
};

/// Newmark's scheme (Newmark, J. Eng. Mech. Div. ASCE 85 (1959) 67): αm = αf = 0 and the given
/// β, γ; the default β = ¼, γ = ½ is the average-acceleration rule, second-order accurate,
/// unconditionally stable and without numerical dissipation for a linear f (its energy is kept
/// exactly). γ > ½ dissipates and is first order. The input asks β ≥ (γ + ½)²/4 (io/).
class Newmark final : public GeneralizedAlphaFamily {
 public:
  explicit Newmark(double beta = 0.25, double gamma = 0.5)
      : GeneralizedAlphaFamily(0.0, 0.0, beta, gamma) {}
  const char* name() const override { return "newmark"; }
};

/// The HHT-α scheme (Hilber, Hughes & Taylor, Earthq. Eng. Struct. Dyn. 5 (1977) 283) for a
/// spectral radius ρ∞ ∈ [½, 1] at Δt → ∞: αm = 0, αf = (1 − ρ∞)/(1 + ρ∞) (their −α),
/// γ = ½ + αf, β = ¼ (1 + αf)². Second order; ρ∞ = 1 is the average-acceleration rule.
class Hht final : public GeneralizedAlphaFamily {
 public:
  explicit Hht(double rho_infinity) : Hht(alpha_f_of(rho_infinity), 0) {}
  const char* name() const override { return "hht"; }

 private:
  static double alpha_f_of(double rho) { return (1.0 - rho) / (1.0 + rho); }
  Hht(double af, int) : GeneralizedAlphaFamily(0.0, af, 0.25 * (1.0 + af) * (1.0 + af), 0.5 + af) {}
};

/// The Bossak-α scheme (Wood, Bossak & Zienkiewicz, IJNME 15 (1980) 1562) for a spectral
/// radius ρ∞ ∈ [0, 1] at Δt → ∞: αm = (ρ∞ − 1)/(ρ∞ + 1) (≤ 0), αf = 0, γ = ½ − αm,
/// β = ¼ (1 − αm)². Second order; ρ∞ = 1 is the average-acceleration rule.
class Bossak final : public GeneralizedAlphaFamily {
 public:
  explicit Bossak(double rho_infinity) : Bossak(alpha_m_of(rho_infinity), 0) {}
  const char* name() const override { return "bossak"; }

 private:
  static double alpha_m_of(double rho) { return (rho - 1.0) / (rho + 1.0); }
  Bossak(double am, int)
      : GeneralizedAlphaFamily(am, 0.0, 0.25 * (1.0 - am) * (1.0 - am), 0.5 - am) {}
};

/// The generalised-α scheme (Chung & Hulbert, J. Appl. Mech. 60 (1993) 371, eq. 25) for a
/// spectral radius ρ∞ ∈ [0, 1] at Δt → ∞: αm = (2ρ∞ − 1)/(ρ∞ + 1), αf = ρ∞/(ρ∞ + 1),
/// γ = ½ − αm + αf, β = ¼ (1 − αm + αf)². Second order, with the least low-frequency
/// dissipation for a given ρ∞; ρ∞ = 1 gives αm = αf = ½, β = ¼, γ = ½.
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

/// The energy-momentum scheme (Simo & Tarnow, ZAMP 43 (1992) 757, with Gonzalez's discrete
/// gradient, CMAME 190 (2000) 1763): αm = αf = ½, β = ¼, γ = ½ (the generalised-α scheme at
/// ρ∞ = 1, for a linear f_int the same steps as the average-acceleration rule), with the
/// solid's force of a step the discrete gradient f_algo(u_n, u_{n+1}) of the stored energy
/// (kernels/energy_momentum.hpp). The u rows then read
///   M (v_{n+1} − v_n)/Δt + f_algo(u_n, u_{n+1}) − ½ (f_ext,n + f_ext,n+1) + ½ f_c,n+1 − M g = 0,
/// u_{n+1} − u_n = Δt/2 (v_n + v_{n+1}): a free hyperelastic body keeps its energy and angular
/// momentum exactly under finite strain (the average-acceleration rule keeps neither).
class EnergyMomentumScheme final : public GeneralizedAlphaFamily {
 public:
  EnergyMomentumScheme() : GeneralizedAlphaFamily(0.5, 0.5, 0.25, 0.5) {}
  const char* name() const override { return "energy_momentum"; }
  bool discrete_gradient_force() const override { return true; }
};

}  // namespace grout
