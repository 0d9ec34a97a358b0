#pragma once
// One-step implicit time integration of M a + f(u, t) = 0: the interface every scheme of
// `grout/dynamics/scheme` implements (docs/design.md §4, "Implicit dynamics"). A scheme owns
// only the time discretisation; DynamicProblem wraps it around the quasi-static problem F_s:
//
//   u rows:  M a_{n+1−αm}(u) + (1 − αf) F_s(u_{n+1}; t_{n+1}) + αf F_s(u_n; t_n) − M g = 0,
//            a_{n+1−αm} = (1 − αm) a_{n+1} + αm a_n,
//   tangent: the u rows of ∂F_s/∂u scaled by (1 − αf), plus mass_factor(Δt) M.
//
// Predictor: every scheme starts Newton from u_{n+1} = u_n (the last converged state, with the
// prescribed values of t_{n+1}). Correctors: a_{n+1}(u_{n+1}) and v_{n+1}(a_{n+1}).
// Schemes: Newmark, Hht, Bossak, GeneralizedAlpha and EnergyMomentumScheme, all of the
// generalised-α family (generalized_alpha_family.hpp).

#include <memory>

#include "assembly/tpetra_types.hpp"
#include "io/input.hpp"

namespace grout {

class TimeIntegrator {
 public:
  virtual ~TimeIntegrator() = default;

  /// The scheme's name in the input (`dynamics/scheme`).
  virtual const char* name() const = 0;

  /// αm, αf of the effective residual (file comment).
  virtual double alpha_m() const = 0;
  virtual double alpha_f() const = 0;
  /// ∂a_{n+1−αm}/∂u_{n+1}: the mass term's factor in the tangent.
  virtual double mass_factor(double dt) const = 0;
  /// True where the solid's force in F_s(u_{n+1}) is 2 f_algo(u_n, u_{n+1}) − f_int(u_n), the
  /// discrete gradient of the stored energy (kernels/energy_momentum.hpp), not f_int(u_{n+1}).
  virtual bool discrete_gradient_force() const { return false; }

  /// Corrector: a_{n+1} from u_{n+1} and the state (u_n, v_n, a_n), per owned dof.
  virtual void acceleration(const Vector& u_next, const Vector& u_n, const Vector& v_n,
                            const Vector& a_n, double dt, Vector& a_next) const = 0;
  /// Corrector: v_{n+1} from v_n, a_n and a_{n+1}.
  virtual void velocity(const Vector& v_n, const Vector& a_n, const Vector& a_next, double dt,
                        Vector& v_next) const = 0;
};

/// The scheme the input's `dynamics` section names, with its coefficients.
std::unique_ptr<const TimeIntegrator> make_time_integrator(const DynamicsInput& input);

}  // namespace grout
