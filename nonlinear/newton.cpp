// Newton through NOX: a "Line Search Based" solver on a NoxGroup, with the status tests of
// docs/design.md §2 (residual tolerance AND unchanged active set, OR a failure test) and one
// log line per iteration from a NOX::Observer.

#include "nonlinear/newton.hpp"

#include <NOX_Solver_Factory.H>
#include <NOX_Solver_Generic.H>
#include <NOX_Solver_LineSearchBased.H>
#include <NOX_StatusTest_Combo.H>
#include <NOX_StatusTest_FiniteValue.H>
#include <NOX_StatusTest_MaxIters.H>
#include <NOX_StatusTest_NormF.H>
#include <NOX_StatusTest_NormUpdate.H>
#include <NOX_StatusTest_RelativeNormF.H>
#include <NOX_Utils.H>
#include <NOX_Observer.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "io/errors.hpp"
#include "nonlinear/nox_group.hpp"

namespace grout {

// ---------------------------------------------------------------------------- NOX pieces

namespace {

/// Converged iff the problem's active set did not change at the current iterate
/// (semi-smooth Newton, docs/design.md §2: the residual test alone is not enough).
class ActiveSetUnchanged : public NOX::StatusTest::Generic {
 public:
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver,
                                          NOX::StatusTest::CheckType type) override {
    if (type == NOX::StatusTest::None) {
      status_ = NOX::StatusTest::Unevaluated;
      return status_;
    }
    changes_ = dynamic_cast<const NoxGroup&>(solver.getSolutionGroup()).active_set_changes();
    status_ = changes_ == 0 ? NOX::StatusTest::Converged : NOX::StatusTest::Unconverged;
    return status_;
  }
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& stream, int indent = 0) const override {
    stream << std::string(indent, ' ') << status_ << "Active set changes = " << changes_
           << " (must be 0)\n";
    return stream;
  }

 private:
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
  int changes_ = -1;
};

/// Converged iff ‖F‖₂ ≤ factor · residual_floor() at the current iterate: the residual is at
/// its round-off level, where further iterates only move it around. The estimate is only
/// trusted when it is finite, positive and well below the residual of the first iterate,
/// factor · floor ≤ max_floor_ratio · ‖F₀‖₂: a floor near ‖F₀‖ (a penalty or modulus so large
/// that ε times it swamps the load, or an overflowing residual) would accept any iterate,
/// the first one included.
class ResidualAtRoundOff : public NOX::StatusTest::Generic {
 public:
  static constexpr double max_floor_ratio = 1e-4;
  explicit ResidualAtRoundOff(double factor) : factor_(factor) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver,
                                          NOX::StatusTest::CheckType type) override {
    if (type == NOX::StatusTest::None) {
      status_ = NOX::StatusTest::Unevaluated;
      return status_;
    }
    const auto& group = dynamic_cast<const NoxGroup&>(solver.getSolutionGroup());
    norm_f_ = group.getNormF();
    if (solver.getNumIterations() == 0) norm_f0_ = norm_f_;
    threshold_ = factor_ * group.residual_floor();
    const bool trusted = std::isfinite(threshold_) && threshold_ > 0.0 && std::isfinite(norm_f0_) &&
                         threshold_ <= max_floor_ratio * norm_f0_;
    status_ = trusted && std::isfinite(norm_f_) && norm_f_ <= threshold_
                  ? NOX::StatusTest::Converged
                  : NOX::StatusTest::Unconverged;
    return status_;
  }
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& stream, int indent = 0) const override {
    stream << std::string(indent, ' ') << status_ << "F-Norm = " << norm_f_ << " <= " << threshold_
           << " (floor_factor * round-off estimate, if <= " << max_floor_ratio << " * " << norm_f0_
           << ")\n";
    return stream;
  }

 private:
  double factor_;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
  double norm_f_ = 0.0, norm_f0_ = std::numeric_limits<double>::quiet_NaN(), threshold_ = 0.0;
};

/// Records the report's histories after every iteration and prints the log line on
/// rank 0. Norms are collective: computed on all ranks, printed on one.
class IterationLog : public NOX::Observer {
 public:
  IterationLog(NewtonReport& report, const NewtonContext& context, const std::string& prefix,
               bool verbose, bool root)
      : report_(report), context_(context), prefix_(prefix), print_(verbose && root) {}

  void runPostIterate(const NOX::Solver::Generic& solver) override {
    const int k = solver.getNumIterations();
    if (report_.residual_history.empty() && k > 0) {
      record(0, solver.getPreviousSolutionGroup(), 0.0, 0, 0.0);
    }
    if (k < int(report_.residual_history.size())) return;  // no new iterate (failed step)
    const auto& group = solver.getSolutionGroup();
    double dx = 0.0;
    if (k > 0) {
      auto step = group.getX().clone(NOX::DeepCopy);
      step->update(-1.0, solver.getPreviousSolutionGroup().getX(), 1.0);
      dx = step->norm(NOX::Abstract::Vector::TwoNorm);
    }
    double length = 0.0;
    if (k > 0) {
      const auto* line_search = dynamic_cast<const NOX::Solver::LineSearchBased*>(&solver);
      length = line_search ? line_search->getStepSize() : 1.0;
    }
    record(k, group, dx, k > 0 ? context_.last_linear_iterations : 0, length);
  }

  /// After a solve that NOX abandoned by throwing before any iteration ended (e.g. no
  /// Jacobian at x0): the history still starts with iteration 0.
  void finish(const NoxGroup& group) {
    if (report_.residual_history.empty() && group.isF()) record(0, group, 0.0, 0, 0.0);
  }

 private:
  void record(int k, const NOX::Abstract::Group& base, double dx, int linear, double length) {
    const auto& group = dynamic_cast<const NoxGroup&>(base);
    report_.residual_history.push_back(group.getNormF());
    report_.active_set_history.push_back(group.active_set_size());
    report_.active_change_history.push_back(group.active_set_changes());
    report_.step_length_history.push_back(length);
    if (!print_) return;
    // A damped update (line search) says so: "step 0.25" after the linear iterations.
    char damped[32] = "";
    if (k > 0 && length != 1.0) std::snprintf(damped, sizeof damped, "  step %.3g", length);
    std::printf("%s newton %d  |F| = %.3e  |dx| = %.3e  active %d (%d changed)  linear %d%s\n",
                prefix_.c_str(), k, group.getNormF(), dx, group.active_set_size(),
                group.active_set_changes(), linear, damped);
    std::fflush(stdout);
  }

  NewtonReport& report_;
  const NewtonContext& context_;
  std::string prefix_;
  bool print_;
};

/// The NOX names Grout sets or passes through, for the error message.
std::string nox_settings_summary(const NewtonOptions& options) {
  const std::string solver = options.nox.isType<std::string>("Nonlinear Solver")
                                 ? options.nox.get<std::string>("Nonlinear Solver")
                                 : "Line Search Based";
  std::string text =
      " (Nonlinear Solver: '" + solver + "', line search: '" + options.line_search + "'";
  if (options.nox.isSublist("Direction") &&
      options.nox.sublist("Direction").isType<std::string>("Method"))
    text +=
        ", Direction/Method: '" + options.nox.sublist("Direction").get<std::string>("Method") + "'";
  return text + ")";
}

/// Whether the input turns NOX's forcing term on (`Direction/Newton/Forcing Term Method`:
/// `Type 1` or `Type 2`, not `Constant`): inexact Newton on the iterative path.
bool forcing_term_on(const NewtonOptions& options) {
  if (!options.nox.isSublist("Direction")) return false;
  const Teuchos::ParameterList& direction = options.nox.sublist("Direction");
  if (!direction.isSublist("Newton")) return false;
  const Teuchos::ParameterList& newton = direction.sublist("Newton");
  return newton.isType<std::string>("Forcing Term Method") &&
         newton.get<std::string>("Forcing Term Method") != "Constant";
}

Teuchos::RCP<Teuchos::ParameterList> nox_parameters(const NewtonOptions& options, int rank,
                                                    const Teuchos::RCP<NOX::Observer>& observer) {
  auto params = Teuchos::rcp(new Teuchos::ParameterList("NOX"));
  params->set("Nonlinear Solver", "Line Search Based");
  params->sublist("Line Search").set("Method", options.line_search);
  auto& direction = params->sublist("Direction");
  direction.set("Method", "Newton");
  // A failed linear solve must stop Newton, not be "rescued" with a stale direction.
  direction.sublist("Newton").set("Rescue Bad Newton Solve", false);
  auto& printing = params->sublist("Printing");
  printing.set("Output Information", static_cast<int>(NOX::Utils::Error));
  printing.set("MyPID", rank);
  // Evaluate every test every time, so that the report can tell which one failed.
  params->sublist("Solver Options").set("Status Test Check Type", "Complete");
  params->setParameters(options.nox);
  params->sublist("Solver Options").set("Observer", observer);
  return params;
}

}  // namespace

// ---------------------------------------------------------------------------- solve

NewtonReport solve_newton(NonlinearProblem& problem, Vector& x, LinearSolver& linear,
                          const NewtonOptions& options, const std::string& log_prefix) {
  using namespace NOX::StatusTest;
  const int rank = problem.map()->getComm()->getRank();
  NewtonReport report;
  auto context = Teuchos::rcp(new NewtonContext(problem, linear));
  context->forcing = forcing_term_on(options);
  auto group = Teuchos::rcp(new NoxGroup(context, x));

  // converged = (|F| <= abs OR |F|/|F0| < rel OR |F| <= floor_factor * round-off estimate)
  //             AND [|dx|_inf < upd] AND [active set unchanged]
  auto residual_small = Teuchos::rcp(new Combo(Combo::OR));
  residual_small->addStatusTest(Teuchos::rcp(
      new NormF(options.absolute_tolerance, NOX::Abstract::Vector::TwoNorm, NormF::Unscaled)));
  residual_small->addStatusTest(Teuchos::rcp(new RelativeNormF(options.relative_tolerance)));
  if (options.floor_factor > 0.0) {
    residual_small->addStatusTest(Teuchos::rcp(new ResidualAtRoundOff(options.floor_factor)));
  }
  auto converged = Teuchos::rcp(new Combo(Combo::AND));
  converged->addStatusTest(residual_small);
  if (options.update_tolerance > 0.0) {
    converged->addStatusTest(Teuchos::rcp(new NormUpdate(
        options.update_tolerance, NOX::Abstract::Vector::MaxNorm, NormUpdate::Unscaled)));
  }
  if (options.require_unchanged_active_set) {
    converged->addStatusTest(Teuchos::rcp(new ActiveSetUnchanged));
  }
  auto finite = Teuchos::rcp(new FiniteValue);
  auto max_iterations = Teuchos::rcp(new MaxIters(options.max_iterations));
  auto tests = Teuchos::rcp(new Combo(Combo::OR));
  tests->addStatusTest(converged);  // first: converging on the last iteration counts
  tests->addStatusTest(finite);
  tests->addStatusTest(max_iterations);

  auto observer =
      Teuchos::rcp(new IterationLog(report, *context, log_prefix, options.verbose, rank == 0));
  // NOX checks its parameters (solver, line search and direction names) while it builds the
  // solver: what it rejects is a bad `NOX` or `Newton` sublist, an input error.
  Teuchos::RCP<NOX::Solver::Generic> solver;
  try {
    solver = NOX::Solver::buildSolver(group, tests, nox_parameters(options, rank, observer));
  } catch (...) {
    throw InputError(options.where + "/NOX: NOX rejects these settings" +
                     nox_settings_summary(options) + ": " +
                     without_source_paths(message_of(std::current_exception())));
  }
  std::string thrown;
  StatusType status = Unconverged;
  try {
    status = solver->solve();
  } catch (const InputError&) {
    throw;  // found while evaluating (already agreed over the ranks)
  } catch (const ExitCodeError&) {
    throw;
  } catch (...) {  // NOX throws std::exceptions and "NOX Error" as a string literal
    thrown = without_source_paths(message_of(std::current_exception()));
  }

  observer->finish(*group);
  report.iterations = solver->getNumIterations();
  report.linear_iterations = context->total_linear_iterations;
  report.converged = thrown.empty() && status == Converged;
  if (report.converged) {
    report.reason = "converged";
  } else if (finite->getStatus() == Failed) {
    report.reason = group->residual_failed() ? "residual evaluation failed" : "non-finite residual";
  } else if (max_iterations->getStatus() == Failed) {
    report.reason = "max iterations (" + std::to_string(options.max_iterations) + ")";
  } else if (!context->failure.empty()) {
    report.reason = without_source_paths(context->failure);
  } else if (!thrown.empty()) {
    report.reason = "NOX error: " + thrown;
  } else {
    report.reason = "line search failed";
  }
  Tpetra::deep_copy(x, NoxTpetraVector::tpetra(group->getX()));
  return report;
}

}  // namespace grout
