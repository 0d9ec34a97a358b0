#include "nonlinear/nox_group.hpp"

#include "assembly/agree_on_errors.hpp"
#include "io/errors.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

namespace grout {

namespace {

Teuchos::RCP<NoxTpetraVector> new_vector(const Teuchos::RCP<const Map>& map) {
  return Teuchos::rcp(new NoxTpetraVector(Teuchos::rcp(new grout::Vector(map))));
}

// True on every rank iff `evaluate` returned true on every rank (a failure on one rank must
// not leave the others iterating alone); an exception on one rank is thrown on every rank.
bool all_ranks(const std::function<bool()>& evaluate, const Comm& comm) {
  bool ok = false;
  agree_on_errors(comm, [&] { ok = evaluate(); });
  int local = ok ? 1 : 0, global = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, local, Teuchos::outArg(global));
  return global == 1;
}

}  // namespace

NoxGroup::NoxGroup(const Teuchos::RCP<NewtonContext>& context, const grout::Vector& x0)
    : context_(context) {
  const auto map = context_->problem.map();
  x_ = new_vector(map);
  f_ = new_vector(map);
  gradient_ = new_vector(map);
  newton_ = new_vector(map);
  Tpetra::deep_copy(x_->tpetra(), x0);
  new_x();
}

NoxGroup::NoxGroup(const NoxGroup& source, NOX::CopyType type) : context_(source.context_) {
  const auto map = context_->problem.map();
  x_ = new_vector(map);
  f_ = new_vector(map);
  gradient_ = new_vector(map);
  newton_ = new_vector(map);
  if (type == NOX::DeepCopy) {
    *this = source;
  } else {
    new_x();
  }
}

NOX::Abstract::Group& NoxGroup::operator=(const NOX::Abstract::Group& base) {
  const auto& source = dynamic_cast<const NoxGroup&>(base);
  if (&source == this) return *this;
  context_ = source.context_;
  static_cast<NOX::Abstract::Vector&>(*x_) = *source.x_;
  static_cast<NOX::Abstract::Vector&>(*f_) = *source.f_;
  static_cast<NOX::Abstract::Vector&>(*gradient_) = *source.gradient_;
  static_cast<NOX::Abstract::Vector&>(*newton_) = *source.newton_;
  jacobian_ = source.jacobian_;  // shared: only read after the copy
  rows_ = source.rows_;
  x_tag_ = source.x_tag_;
  iterate_ = source.iterate_;
  is_f_ = source.is_f_;
  is_jacobian_ = source.is_jacobian_;
  is_gradient_ = source.is_gradient_;
  is_newton_ = source.is_newton_;
  norm_f_ = source.norm_f_;
  residual_failed_ = source.residual_failed_;
  active_set_size_ = source.active_set_size_;
  active_set_changes_ = source.active_set_changes_;
  residual_floor_ = source.residual_floor_;
  return *this;
}

void NoxGroup::new_x() {
  x_tag_ = context_->next_x_tag++;
  is_f_ = is_jacobian_ = is_gradient_ = is_newton_ = false;
  residual_failed_ = false;
}

void NoxGroup::setX(const NOX::Abstract::Vector& y) {
  static_cast<NOX::Abstract::Vector&>(*x_) = y;
  new_x();
}

void NoxGroup::computeX(const NOX::Abstract::Group& grp, const NOX::Abstract::Vector& d,
                        double step) {
  x_->update(1.0, grp.getX(), step, d, 0.0);  // x = x_grp + step d
  iterate_ = dynamic_cast<const NoxGroup&>(grp).iterate_ + 1;
  new_x();
}

NOX::Abstract::Group::ReturnType NoxGroup::computeF() {
  if (is_f_) return Ok;
  auto& problem = context_->problem;
  problem.set_newton_iterate(iterate_);
  const bool ok = all_ranks([&] { return problem.residual(x_->tpetra(), f_->tpetra()); },
                            *x_->tpetra().getMap()->getComm());
  context_->evaluated_x_tag = x_tag_;
  residual_failed_ = !ok;
  if (ok) {
    norm_f_ = f_->norm();  // collective, on every rank
    if (!std::isfinite(norm_f_)) norm_f_ = std::numeric_limits<double>::infinity();
  } else {
    f_->init(std::numeric_limits<double>::quiet_NaN());
    norm_f_ = std::numeric_limits<double>::infinity();
  }
  active_set_size_ = problem.active_set_size();
  active_set_changes_ = problem.active_set_changes();
  residual_floor_ = problem.residual_floor();
  is_f_ = true;
  return Ok;
}

NOX::Abstract::Group::ReturnType NoxGroup::computeJacobian() {
  if (is_jacobian_) return Ok;
  auto& problem = context_->problem;
  if (!is_f_) computeF();
  if (residual_failed_) {
    context_->failure = "jacobian evaluation failed (no residual at this iterate)";
    return Failed;
  }
  if (context_->evaluated_x_tag != x_tag_) {
    // The problem last evaluated another x (a line-search trial): bring it back here.
    grout::Vector scratch(f_->tpetra().getMap());
    problem.set_newton_iterate(iterate_);
    all_ranks([&] { return problem.residual(x_->tpetra(), scratch); },
              *x_->tpetra().getMap()->getComm());
    context_->evaluated_x_tag = x_tag_;
  }
  const bool ok = all_ranks([&] { return problem.jacobian(x_->tpetra(), jacobian_); },
                            *x_->tpetra().getMap()->getComm());
  if (!ok || jacobian_.is_null()) {
    context_->failure = "jacobian evaluation failed";
    return Failed;
  }
  const MultiplierRows* rows = problem.multiplier_rows();  // of J's evaluation point
  rows_ = rows ? std::make_shared<const MultiplierRows>(*rows) : nullptr;
  is_jacobian_ = true;
  return Ok;
}

NOX::Abstract::Group::ReturnType NoxGroup::computeGradient() {
  if (is_gradient_) return Ok;
  if (!is_f_ || !is_jacobian_) return BadDependency;
  const ReturnType status = applyJacobianTranspose(*f_, *gradient_);  // g = Jᵀ F
  is_gradient_ = status == Ok;
  return status;
}

NOX::Abstract::Group::ReturnType NoxGroup::computeNewton(Teuchos::ParameterList& params) {
  if (is_newton_) return Ok;
  if (!is_f_ || !is_jacobian_) return BadDependency;
  grout::Vector rhs(f_->tpetra().getMap());
  rhs.update(-1.0, f_->tpetra(), 0.0);
  newton_->init(0.0);
  // Inexact Newton (Eisenstat and Walker, SIAM J. Sci. Comput. 17 (1996) 16-32): NOX's
  // forcing term η_k asks for |J s + F| <= η_k |F|; the iterative solve takes η_k as its
  // relative tolerance, a direct solve is exact anyway. Without a forcing term NOX's own
  // default `Tolerance` (1e-10) is not the solver's: the `Linear Solver` settings stand.
  const double tolerance = context_->forcing && params.isType<double>("Tolerance")
                               ? params.get<double>("Tolerance")
                               : 0.0;
  // The forcing term holds for this solve only, however it ends.
  struct ToleranceForThisSolve {
    LinearSolver& linear;
    ToleranceForThisSolve(LinearSolver& solver, double value) : linear(solver) {
      linear.set_relative_tolerance(value);
    }
    ~ToleranceForThisSolve() { linear.set_relative_tolerance(0.0); }
  };
  try {
    const ToleranceForThisSolve forcing(context_->linear, tolerance);
    context_->last_linear_iterations =
        context_->linear.solve(jacobian_, rhs, newton_->tpetra(), rows_.get());
  } catch (const ExitCodeError&) {
    throw;  // e.g. the iterative module cannot be loaded: no smaller step cures that
  } catch (const std::exception& e) {
    context_->failure = std::string("linear solve failed: ") + e.what();
    return Failed;
  }
  context_->total_linear_iterations += context_->last_linear_iterations;
  context_->problem.limit_step(x_->tpetra(), newton_->tpetra());
  is_newton_ = true;
  return Ok;
}

NOX::Abstract::Group::ReturnType NoxGroup::applyJacobian(const NOX::Abstract::Vector& input,
                                                         NOX::Abstract::Vector& result) const {
  if (!is_jacobian_) return BadDependency;
  jacobian_->apply(NoxTpetraVector::tpetra(input), dynamic_cast<NoxTpetraVector&>(result).tpetra());
  return Ok;
}

NOX::Abstract::Group::ReturnType NoxGroup::applyJacobianTranspose(
    const NOX::Abstract::Vector& input, NOX::Abstract::Vector& result) const {
  if (!is_jacobian_) return BadDependency;
  jacobian_->apply(NoxTpetraVector::tpetra(input), dynamic_cast<NoxTpetraVector&>(result).tpetra(),
                   Teuchos::TRANS);
  return Ok;
}

Teuchos::RCP<NOX::Abstract::Group> NoxGroup::clone(NOX::CopyType type) const {
  return Teuchos::rcp(new NoxGroup(*this, type));
}

}  // namespace grout
