#pragma once
// A nonlinear system F(x) = 0 as the Newton solver (NOX) sees it.

#include <Teuchos_RCP.hpp>

#include "assembly/tpetra_types.hpp"
#include "nonlinear/multiplier_rows.hpp"

namespace grout {

/// F(x) = 0 on a fixed map. The Jacobian's graph may change between calls (contact pairs
/// and the active set change from one Newton iterate to the next), so jacobian() may hand
/// back a new matrix. Prescribed dofs are the problem's business: it keeps them at their
/// values (F = 0 there, J rows/columns eliminated with a positive diagonal).
class NonlinearProblem {
 public:
  virtual ~NonlinearProblem() = default;
  virtual Teuchos::RCP<const Map> map() const = 0;
  /// F(x). Returns false when F cannot be evaluated at x (inverted element, NaN), so that
  /// the line search or the load stepping can back off.
  virtual bool residual(const Vector& x, Vector& F) = 0;
  /// J(x) = dF/dx at the x of the last residual() call.
  virtual bool jacobian(const Vector& x, Teuchos::RCP<Matrix>& J) = 0;
  /// Size of the contact active set at the last residual() call, and how many nodes
  /// changed status (open/stick/slip) since the call before. 0 without contact.
  virtual int active_set_size() const { return 0; }
  virtual int active_set_changes() const { return 0; }
  /// Round-off estimate of ‖F‖₂ at the last residual() call: no iterate can be expected to
  /// bring ‖F‖₂ much below it (NewtonOptions::floor_factor). 0 = unknown.
  virtual double residual_floor() const { return 0.0; }
  /// The Newton iterate of the current step that the next residual() calls evaluate (0: the
  /// step's initial guess; k: after k Newton updates, line-search trials of update k
  /// included). Set by the Newton solver before each evaluation, so that what depends on the
  /// iterate (the contact active set's start rules) never depends on the order of residual()
  /// and jacobian() calls. Default: ignored.
  virtual void set_newton_iterate(int /*k*/) {}
  /// The kinds of the multiplier rows of J at the last residual() call, as the problem
  /// declares them (multiplier_rows.hpp; the condensations are built from them), or nullptr.
  virtual const MultiplierRows* multiplier_rows() const { return nullptr; }
  /// May shorten parts of the Newton step `step` computed at x (the x of the last residual()
  /// call) before the line search takes it: F and J stay as they are, so a converged state
  /// does not depend on it. Collective. Default: the step as solved.
  virtual void limit_step(const Vector& /*x*/, Vector& /*step*/) {}
};

}  // namespace grout
