#pragma once
// The generalised-α family (Chung & Hulbert, J. Appl. Mech. 60 (1993) 371, eqs. 2–4):
//
//   M a_{n+1−αm} + f(u_{n+1−αf}, t_{n+1−αf}) = 0,   x_{n+1−α} = (1 − α) x_{n+1} + α x_n,
//   u_{n+1} = u_n + Δt v_n + Δt² ((½ − β) a_n + β a_{n+1}),
//   v_{n+1} = v_n + Δt ((1 − γ) a_n + γ a_{n+1}).
//
// Every scheme of the input is a member, set by its four coefficients (αm, αf, β, γ); this
// base holds them and the Newmark correctors. For a linear f, (1 − αf) f(u_{n+1}) + αf f(u_n)
// (the effective residual of time_integrator.hpp) is f(u_{n+1−αf}) exactly.

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

}  // namespace grout
