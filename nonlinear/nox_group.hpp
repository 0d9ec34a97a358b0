#pragma once

#include <memory>
// NOX::Abstract::Group over a NonlinearProblem (docs/design.md, "Toolchain notes": NOX route B): F
// and J come from the problem, the Newton step J Δx = −F from LinearSolver. The Jacobian (and its
// graph) is whatever the problem hands back at each iterate, so contact pairs and the
// active set may change it freely. Private to nonlinear/*.cpp.

#include <NOX_Abstract_Group.H>
#include <Teuchos_RCP.hpp>
#include <string>

#include "nonlinear/linear_solver.hpp"
#include "nonlinear/nonlinear_problem.hpp"
#include "nonlinear/nox_tpetra_vector.hpp"

namespace grout {

/// What the groups of one solve share. The problem is stateful (J is taken at the x of its
/// last residual() call), so every x gets a tag and the tag of the last evaluated x is kept.
struct NewtonContext {
  NewtonContext(NonlinearProblem& p, LinearSolver& l) : problem(p), linear(l) {}
  NonlinearProblem& problem;
  LinearSolver& linear;
  long next_x_tag = 0;
  long evaluated_x_tag = -1;
  int last_linear_iterations = 0;
  int total_linear_iterations = 0;
  /// NOX's forcing term is on (`Direction/Newton/Forcing Term Method` other than `Constant`):
  /// each Newton step's linear solve takes NOX's `Linear Solver/Tolerance` η_k.
  bool forcing = false;
  std::string failure;  ///< why the last Jacobian or Newton-step computation failed
};

class NoxGroup : public NOX::Abstract::Group {
 public:
  NoxGroup(const Teuchos::RCP<NewtonContext>& context, const grout::Vector& x0);
  NoxGroup(const NoxGroup& source, NOX::CopyType type);

  NOX::Abstract::Group& operator=(const NOX::Abstract::Group& source) override;
  NoxGroup& operator=(const NoxGroup& source) {
    *this = static_cast<const NOX::Abstract::Group&>(source);
    return *this;
  }
  void setX(const NOX::Abstract::Vector& y) override;
  void computeX(const NOX::Abstract::Group& grp, const NOX::Abstract::Vector& d,
                double step) override;

  /// Always returns Ok: an F that cannot be evaluated (problem says false, on any rank) or
  /// is not finite gets ‖F‖ = +inf, so a line search backs off and FiniteValue fails.
  ReturnType computeF() override;
  ReturnType computeJacobian() override;
  ReturnType computeGradient() override;
  ReturnType computeNewton(Teuchos::ParameterList& params) override;
  ReturnType applyJacobian(const NOX::Abstract::Vector& input,
                           NOX::Abstract::Vector& result) const override;
  ReturnType applyJacobianTranspose(const NOX::Abstract::Vector& input,
                                    NOX::Abstract::Vector& result) const override;

  bool isF() const override { return is_f_; }
  bool isJacobian() const override { return is_jacobian_; }
  bool isGradient() const override { return is_gradient_; }
  bool isNewton() const override { return is_newton_; }

  const NOX::Abstract::Vector& getX() const override { return *x_; }
  const NOX::Abstract::Vector& getF() const override { return *f_; }
  double getNormF() const override { return norm_f_; }
  const NOX::Abstract::Vector& getGradient() const override { return *gradient_; }
  const NOX::Abstract::Vector& getNewton() const override { return *newton_; }
  Teuchos::RCP<const NOX::Abstract::Vector> getXPtr() const override { return x_; }
  Teuchos::RCP<const NOX::Abstract::Vector> getFPtr() const override { return f_; }
  Teuchos::RCP<const NOX::Abstract::Vector> getGradientPtr() const override { return gradient_; }
  Teuchos::RCP<const NOX::Abstract::Vector> getNewtonPtr() const override { return newton_; }

  Teuchos::RCP<NOX::Abstract::Group> clone(NOX::CopyType type = NOX::DeepCopy) const override;

  /// At the last computeF(): the problem's active set, and whether F could be evaluated.
  int active_set_size() const { return active_set_size_; }
  int active_set_changes() const { return active_set_changes_; }
  double residual_floor() const { return residual_floor_; }
  bool residual_failed() const { return residual_failed_; }

 private:
  void new_x();  ///< x changed: F, J, gradient and Newton step are stale

  Teuchos::RCP<NewtonContext> context_;
  Teuchos::RCP<NoxTpetraVector> x_, f_, gradient_, newton_;
  Teuchos::RCP<Matrix> jacobian_;
  std::shared_ptr<const MultiplierRows> rows_;  ///< J's multiplier row kinds (declared)
  long x_tag_ = -1;
  /// The Newton iterate of the step x is (0: the initial guess; computeX from a group at
  /// iterate k gives k + 1, line-search trials included): handed to the problem before each
  /// residual (NonlinearProblem::set_newton_iterate). setX keeps it.
  int iterate_ = 0;
  bool is_f_ = false, is_jacobian_ = false, is_gradient_ = false, is_newton_ = false;
  double norm_f_ = 0.0;
  bool residual_failed_ = false;
  int active_set_size_ = 0, active_set_changes_ = 0;
  double residual_floor_ = 0.0;
};

}  // namespace grout
