// Newton through NOX (nonlinear/newton.hpp) on small distributed systems with known roots,
// on 1 and 2 ranks: quadratic convergence, a Jacobian graph that changes every iteration,
// the active-set-unchanged test, failure reasons, a line search, option parsing.

#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "io/errors.hpp"
#include "nonlinear/load_stepping.hpp"
#include "nonlinear/newton.hpp"

namespace grout {
namespace {

const double nan = std::numeric_limits<double>::quiet_NaN();

/// F(x) = L x + x³ − b, L = tridiag(−1, 3, −1), root x*ᵢ = 1 + ½ sin(i). Knobs make it
/// change its Jacobian graph, report active-set changes, fail or return NaN.
class CubicProblem : public NonlinearProblem {
 public:
  explicit CubicProblem(GO n = 40)
      : map_(Teuchos::rcp(new Map(n, 0, Tpetra::getDefaultComm()))), b_(map_), x_star_(map_) {
    auto xs = x_star_.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (LO i = 0; i < LO(xs.extent(0)); ++i) xs(i, 0) = 1.0 + 0.5 * std::sin(double(gid(i)));
    L_ = tridiagonal(nullptr);
    Vector x3(map_);
    x3.elementWiseMultiply(1.0, x_star_, x_star_, 0.0);
    Vector cube(map_);
    cube.elementWiseMultiply(1.0, x3, x_star_, 0.0);
    L_->apply(x_star_, b_);
    b_.update(1.0, cube, 1.0);
  }

  Teuchos::RCP<const Map> map() const override { return map_; }
  const Vector& root() const { return x_star_; }

  bool residual(const Vector& x, Vector& F) override {
    ++residual_calls;
    L_->apply(x, F);
    auto f = F.getLocalViewHost(Tpetra::Access::ReadWrite);
    const auto xv = x.getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto bv = b_.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (LO i = 0; i < LO(f.extent(0)); ++i) f(i, 0) += std::pow(xv(i, 0), 3) - bv(i, 0);
    const int rank = map_->getComm()->getRank();
    const int last = map_->getComm()->getSize() - 1;
    if (nan_from_call > 0 && residual_calls >= nan_from_call && rank == last) f(0, 0) = nan;
    // Fails on rank 0 only: the solver must agree on all ranks.
    if (fail_from_call > 0 && residual_calls >= fail_from_call && rank == 0) return false;
    return true;
  }

  bool jacobian(const Vector& x, Teuchos::RCP<Matrix>& J) override {
    ++jacobian_calls;
    J = tridiagonal(&x);  // a new matrix (and graph) every call (collective)
    // Fails on rank 0 only: the solver must agree on all ranks.
    return !(jacobian_calls == fail_jacobian_call && map_->getComm()->getRank() == 0);
  }

  int active_set_size() const override { return 7; }
  int active_set_changes() const override { return residual_calls <= changes_until_call ? 2 : 0; }

  int residual_calls = 0, jacobian_calls = 0;
  int changes_until_call = 0;  ///< active_set_changes() = 2 up to this residual call
  int nan_from_call = -1, fail_from_call = -1, fail_jacobian_call = -1;
  bool changing_graph = false;  ///< add a stored zero at a column that moves every call

 private:
  GO gid(LO i) const { return map_->getGlobalElement(i); }

  // L (x null) or J(x) = L + diag(3x²).
  Teuchos::RCP<Matrix> tridiagonal(const Vector* x) const {
    const GO n = GO(map_->getGlobalNumElements());
    auto A = Teuchos::rcp(new Matrix(map_, 4));
    for (LO i = 0; i < LO(map_->getNodeNumElements()); ++i) {
      const GO g = gid(i);
      const double xi = x ? x->getLocalViewHost(Tpetra::Access::ReadOnly)(i, 0) : 0.0;
      std::vector<GO> cols{g};
      std::vector<double> vals{3.0 + 3.0 * xi * xi};
      if (g > 0) cols.push_back(g - 1), vals.push_back(-1.0);
      if (g + 1 < n) cols.push_back(g + 1), vals.push_back(-1.0);
      const GO extra = (g + 2 + 5 * jacobian_calls) % n;
      if (changing_graph && std::abs(extra - g) > 1) cols.push_back(extra), vals.push_back(0.0);
      A->insertGlobalValues(g, Teuchos::ArrayView<const GO>(cols),
                            Teuchos::ArrayView<const double>(vals));
    }
    A->fillComplete();
    return A;
  }

  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<Matrix> L_;
  Vector b_, x_star_;
};

/// diag(d(xᵢ)) on the map of x (the Jacobian of the componentwise problems below).
template <class Derivative>
Teuchos::RCP<Matrix> diagonal_matrix(const Vector& x, Derivative d) {
  auto J = Teuchos::rcp(new Matrix(x.getMap(), 1));
  const auto xv = x.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (LO i = 0; i < LO(xv.extent(0)); ++i) {
    const GO g = x.getMap()->getGlobalElement(i);
    J->insertGlobalValues(g, Teuchos::tuple<GO>(g), Teuchos::tuple<double>(d(xv(i, 0))));
  }
  J->fillComplete();
  return J;
}

/// F(x)ᵢ = atan(xᵢ): full Newton from 2 overshoots and diverges; a line search converges.
class AtanProblem : public NonlinearProblem {
 public:
  AtanProblem() : map_(Teuchos::rcp(new Map(6, 0, Tpetra::getDefaultComm()))) {}
  Teuchos::RCP<const Map> map() const override { return map_; }
  bool residual(const Vector& x, Vector& F) override {
    auto f = F.getLocalViewHost(Tpetra::Access::OverwriteAll);
    const auto xv = x.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (LO i = 0; i < LO(f.extent(0)); ++i) f(i, 0) = std::atan(xv(i, 0));
    return true;
  }
  bool jacobian(const Vector& x, Teuchos::RCP<Matrix>& J) override {
    J = diagonal_matrix(x, [](double v) { return 1.0 / (1.0 + v * v); });
    return true;
  }

 private:
  Teuchos::RCP<const Map> map_;
};

/// F(x)ᵢ = xᵢ − 1 + ε sgn(xᵢ − 1) (sgn(0) = 1), J = I: no root, |Fᵢ| ≥ ε everywhere, and
/// Newton from x < 1 oscillates between 1 ± ε with |Fᵢ| = 2ε — a residual stuck at a floor,
/// whose estimate residual_floor() = ε_est √n the problem reports.
class FloorProblem : public NonlinearProblem {
 public:
  FloorProblem(double eps, double eps_estimate)
      : map_(Teuchos::rcp(new Map(8, 0, Tpetra::getDefaultComm()))),
        eps_(eps),
        estimate_(eps_estimate * std::sqrt(8.0)) {}
  Teuchos::RCP<const Map> map() const override { return map_; }
  bool residual(const Vector& x, Vector& F) override {
    auto f = F.getLocalViewHost(Tpetra::Access::OverwriteAll);
    const auto xv = x.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (LO i = 0; i < LO(f.extent(0)); ++i)
      f(i, 0) = xv(i, 0) - 1.0 + (xv(i, 0) >= 1.0 ? eps_ : -eps_);
    return true;
  }
  bool jacobian(const Vector& x, Teuchos::RCP<Matrix>& J) override {
    J = diagonal_matrix(x, [](double) { return 1.0; });
    return true;
  }
  double residual_floor() const override { return estimate_; }

 private:
  Teuchos::RCP<const Map> map_;
  double eps_, estimate_;
};

// Quiet unless GROUT_TEST_VERBOSE is set (then every solve prints its Newton log).
NewtonOptions quiet_options() {
  NewtonOptions options;
  options.verbose = std::getenv("GROUT_TEST_VERBOSE") != nullptr;
  return options;
}

NewtonReport solve(NonlinearProblem& problem, Vector& x, const NewtonOptions& options) {
  LinearSolver linear(Teuchos::ParameterList(), "test", {});
  const NewtonReport report = solve_newton(problem, x, linear, options, "  test");
  if (options.verbose && problem.map()->getComm()->getRank() == 0) {
    std::printf("  -> %s after %d iterations\n", report.reason.c_str(), report.iterations);
  }
  return report;
}

double distance(const Vector& a, const Vector& b) {
  Vector d(a.getMap());
  d.update(1.0, a, -1.0, b, 0.0);
  return d.normInf();
}

TEST(Newton, ConvergesQuadraticallyToTheRoot) {
  CubicProblem problem;
  Vector x(problem.map());  // x0 = 0
  const NewtonReport report = solve(problem, x, quiet_options());
  ASSERT_TRUE(report.converged) << report.reason;
  EXPECT_EQ(report.reason, "converged");
  EXPECT_LT(distance(x, problem.root()), 1e-10);
  const auto& h = report.residual_history;
  ASSERT_EQ(int(h.size()), report.iterations + 1);
  EXPECT_GE(report.linear_iterations, report.iterations);
  EXPECT_LE(h.back(), 1e-10 * h.front());
  // |F_{k+1}| <= C |F_k|^2 wherever F_{k+1} is above round-off, and log-ratio -> 2.
  int checked = 0;
  for (std::size_t k = 0; k + 1 < h.size(); ++k) {
    if (h[k] > 1e-1 || h[k + 1] < 1e-13) continue;
    EXPECT_LE(h[k + 1], 10.0 * h[k] * h[k]) << "iteration " << k + 1;
    EXPECT_GT(std::log(h[k + 1]) / std::log(h[k]), 1.8) << "iteration " << k + 1;
    ++checked;
  }
  EXPECT_GE(checked, 1);
}

// NOX's forcing term reaches the iterative solve (inexact Newton, nonlinear/nox_group.cpp):
// each step is solved to η_k only, so the same root costs fewer Krylov iterations in all;
// without it every step is solved to Belos's own tolerance, whatever NOX's default.
TEST(Newton, ForcingTermLoosensTheIterativeSolves) {
  Teuchos::ParameterList params;
  params.set("type", "belos");
  params.sublist("Belos").set("Solver Type", "CG");
  const auto run = [&](bool forcing, int& newton_iterations) {
    CubicProblem problem(4000);
    Vector x(problem.map());  // x0 = 0
    NewtonOptions options = quiet_options();
    options.relative_tolerance = 1e-12;
    if (forcing) {
      Teuchos::ParameterList& newton = options.nox.sublist("Direction").sublist("Newton");
      newton.set("Forcing Term Method", "Type 2");
      newton.set("Forcing Term Initial Tolerance", 1e-2);
      newton.set("Forcing Term Maximum Tolerance", 1e-2);
      newton.set("Forcing Term Minimum Tolerance", 1e-12);
    }
    LinearSolver linear(params, "test", {});
    const NewtonReport report = solve_newton(problem, x, linear, options, "  test");
    EXPECT_TRUE(report.converged) << report.reason;
    EXPECT_LT(distance(x, problem.root()), 1e-10);
    newton_iterations = report.iterations;
    return report.linear_iterations;
  };
  int exact_newton = 0, inexact_newton = 0;
  const int exact = run(false, exact_newton);
  const int inexact = run(true, inexact_newton);
  EXPECT_LT(inexact, exact) << "Newton iterations " << inexact_newton << " against "
                            << exact_newton;
  EXPECT_GE(inexact_newton, exact_newton);
}

TEST(Newton, JacobianGraphMayChangeEveryIteration) {
  CubicProblem problem;
  problem.changing_graph = true;
  Vector x(problem.map());
  const NewtonReport report = solve(problem, x, quiet_options());
  ASSERT_TRUE(report.converged) << report.reason;
  EXPECT_GE(problem.jacobian_calls, 3);
  EXPECT_LT(distance(x, problem.root()), 1e-10);
}

TEST(Newton, KeepsIteratingWhileTheActiveSetChanges) {
  CubicProblem problem;
  problem.changes_until_call = 3;
  Vector x(problem.map());
  Tpetra::deep_copy(x, problem.root());  // |F| tiny from the start
  const NewtonReport report = solve(problem, x, quiet_options());
  ASSERT_TRUE(report.converged) << report.reason;
  EXPECT_EQ(report.iterations, 3);
  EXPECT_EQ(report.active_change_history, (std::vector<int>{2, 2, 2, 0}));
  EXPECT_EQ(report.active_set_history, (std::vector<int>{7, 7, 7, 7}));
  for (double r : report.residual_history) EXPECT_LT(r, 1e-12);

  CubicProblem plain;  // without the active-set test, x0 = root is converged at once
  plain.changes_until_call = 3;
  Tpetra::deep_copy(x, plain.root());
  NewtonOptions options = quiet_options();
  options.require_unchanged_active_set = false;
  EXPECT_EQ(solve(plain, x, options).iterations, 0);
}

TEST(Newton, MaxIterationsIsAFailureWithReason) {
  CubicProblem problem;
  Vector x(problem.map());
  NewtonOptions options = quiet_options();
  options.max_iterations = 2;
  const NewtonReport report = solve(problem, x, options);
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.reason, "max iterations (2)");
  EXPECT_EQ(report.iterations, 2);
  EXPECT_EQ(report.residual_history.size(), 3u);
}

TEST(Newton, FailedResidualStopsOnAllRanks) {
  CubicProblem problem;
  problem.fail_from_call = 3;
  Vector x(problem.map());
  const NewtonReport report = solve(problem, x, quiet_options());
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.reason, "residual evaluation failed");
  EXPECT_EQ(report.iterations, 2);
}

TEST(Newton, NanResidualStopsOnAllRanks) {
  CubicProblem problem;
  problem.nan_from_call = 2;
  Vector x(problem.map());
  const NewtonReport report = solve(problem, x, quiet_options());
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.reason, "non-finite residual");
  EXPECT_EQ(report.iterations, 1);
}

TEST(Newton, FailedJacobianStopsOnAllRanks) {
  for (int call : {1, 3}) {
    CubicProblem problem;
    problem.fail_jacobian_call = call;
    Vector x(problem.map());
    const NewtonReport report = solve(problem, x, quiet_options());
    EXPECT_FALSE(report.converged);
    EXPECT_EQ(report.reason, "jacobian evaluation failed");
    EXPECT_EQ(report.iterations, call - 1);
    EXPECT_EQ(int(report.residual_history.size()), call);
  }
}

TEST(Newton, BacktrackingRescuesAnOvershootingFullStep) {
  AtanProblem problem;
  Vector x(problem.map());
  NewtonOptions options = quiet_options();
  options.max_iterations = 6;
  x.putScalar(2.0);
  const NewtonReport full = solve(problem, x, options);
  EXPECT_FALSE(full.converged);
  EXPECT_GT(full.residual_history.back(), full.residual_history.front());

  for (const std::string method : {"Backtrack", "Polynomial"}) {
    options.line_search = method;
    options.max_iterations = 25;
    x.putScalar(2.0);
    const NewtonReport report = solve(problem, x, options);
    EXPECT_TRUE(report.converged) << method << ": " << report.reason;
    EXPECT_LT(x.normInf(), 1e-9) << method;
  }
}

// march_steps (load_stepping.hpp): from x = 2 the full step overshoots atan's root (the
// test above); the default options retry the failed step once at the same increment with
// Backtrack, which converges, so the step passes with no cut-back and damped updates.
TEST(MarchSteps, RetriesAFailedFullStepWithBacktrackBeforeCutting) {
  AtanProblem problem;
  LinearSolver linear(Teuchos::ParameterList(), "test", {});
  SteppingOptions stepping;
  stepping.max_cuts = 0;  // a cut-back would be a failure
  const auto start_at_two = [](double, Vector& x) { x.putScalar(2.0); };
  NewtonOptions options = quiet_options();
  ASSERT_EQ(options.line_search, "Full Step");
  ASSERT_EQ(options.fallback_line_search, "Backtrack");
  int accepted = 0;
  double min_length = 1.0;
  march_steps(problem, linear, options, stepping, start_at_two, [&](ConvergedStep& step) {
    ++accepted;
    EXPECT_EQ(step.time, 1.0);
    EXPECT_LT(step.state->normInf(), 1e-9);
    for (std::size_t k = 1; k < step.newton->step_length_history.size(); ++k)
      min_length = std::min(min_length, step.newton->step_length_history[k]);
  });
  EXPECT_EQ(accepted, 1);
  EXPECT_LT(min_length, 1.0);  // the retry's damped updates

  // A line search the input chose holds for every attempt: no retry, so the step fails.
  options.fallback_line_search.clear();
  EXPECT_THROW(march_steps(problem, linear, options, stepping, start_at_two,
                           [](ConvergedStep&) { ADD_FAILURE() << "converged"; }),
               ConvergenceError);
}

// A failure at the step's start point (here its residual) is not retried: the line search
// acts after the first solve, so the retry would fail the same way. With no cut-back allowed
// the step ends at once, after one residual evaluation.
TEST(MarchSteps, AFailureAtTheStartPointIsNotRetried) {
  CubicProblem problem;
  problem.fail_from_call = 1;
  LinearSolver linear(Teuchos::ParameterList(), "test", {});
  SteppingOptions stepping;
  stepping.max_cuts = 0;
  EXPECT_THROW(march_steps(
                   problem, linear, quiet_options(), stepping, [](double, Vector&) {},
                   [](ConvergedStep&) { ADD_FAILURE() << "converged"; }),
               ConvergenceError);
  EXPECT_EQ(problem.residual_calls, 1);
}

/// F(x)ᵢ = xᵢ + xᵢ³/10 − t cᵢ along a path through a load t (set by begin_step), and
/// F(x)ᵢ = xᵢ − t cᵢ with `linear`: then x(t) = t c, which the secant predictor hits exactly.
/// The residual fails where some xᵢ exceeds `limit`.
class PathProblem : public NonlinearProblem {
 public:
  PathProblem() : map_(Teuchos::rcp(new Map(6, 0, Tpetra::getDefaultComm()))) {}
  Teuchos::RCP<const Map> map() const override { return map_; }
  bool residual(const Vector& x, Vector& F) override {
    auto f = F.getLocalViewHost(Tpetra::Access::OverwriteAll);
    const auto xv = x.getLocalViewHost(Tpetra::Access::ReadOnly);
    bool ok = true;
    for (LO i = 0; i < LO(f.extent(0)); ++i) {
      const double xi = xv(i, 0), c = 1.0 + double(map_->getGlobalElement(i));
      f(i, 0) = xi + (linear ? 0.0 : 0.1 * xi * xi * xi) - t * c;
      ok = ok && xi <= limit;
    }
    int here = ok ? 1 : 0, all = 0;
    Teuchos::reduceAll(*map_->getComm(), Teuchos::REDUCE_MIN, 1, &here, &all);
    return all == 1;
  }
  bool jacobian(const Vector& x, Teuchos::RCP<Matrix>& J) override {
    J = diagonal_matrix(x, [&](double v) { return 1.0 + (linear ? 0.0 : 0.3 * v * v); });
    return true;
  }
  double t = 0.0, limit = std::numeric_limits<double>::infinity();
  bool linear = true;

 private:
  Teuchos::RCP<const Map> map_;
};

/// Newton iterations of every step of march_steps on `problem` (`steps` steps to t = `end`).
std::vector<int> iterations_per_step(PathProblem& problem, bool extrapolate, int steps = 4,
                                     double end = 1.0) {
  LinearSolver linear(Teuchos::ParameterList(), "test", {});
  SteppingOptions stepping;
  stepping.end_time = end;
  stepping.steps = steps;
  stepping.max_cuts = 0;  // a cut-back would be a failure
  stepping.extrapolate = extrapolate;
  std::vector<int> iterations;
  march_steps(
      problem, linear, quiet_options(), stepping, [&](double t, Vector&) { problem.t = t; },
      [&](ConvergedStep& step) { iterations.push_back(step.newton->iterations); });
  return iterations;
}

// The secant predictor (SteppingOptions::extrapolate): on a linear path x(t) = t c every step
// after the first starts at its solution (no Newton update), where the last converged state
// takes one update per step.
TEST(MarchSteps, TheSecantPredictorStartsALinearPathAtItsSolution) {
  PathProblem problem;
  EXPECT_EQ(iterations_per_step(problem, false), std::vector<int>({1, 1, 1, 1}));
  EXPECT_EQ(iterations_per_step(problem, true), std::vector<int>({1, 0, 0, 0}));
}

// A step whose predicted start fails (here its residual: x beyond `limit`) is retried from
// the last converged state, with no cut-back.
TEST(MarchSteps, AStepFailingFromThePredictedStartIsRetriedFromTheLastState) {
  PathProblem problem;
  problem.linear = false;
  // For the largest c = 6: x(0.25) = 1.2869, x(0.5) = 2.0887 (x + x³/10 = 6 t); the predicted
  // start of the step to 0.5 is 2.5738 > limit, Newton's iterates from x(0.25) stay below
  // 2.2890.
  problem.limit = 2.4;
  EXPECT_EQ(iterations_per_step(problem, false, 2, 0.5).size(), 2u);
  EXPECT_EQ(iterations_per_step(problem, true, 2, 0.5).size(), 2u);
}

TEST(NewtonOptions, AnInputLineSearchTurnsTheRetryOff) {
  EXPECT_EQ(newton_options_from(Teuchos::ParameterList()).fallback_line_search, "Backtrack");
  Teuchos::ParameterList solver;
  solver.sublist("Newton").set("line_search", std::string("Full Step"));
  EXPECT_EQ(newton_options_from(solver).fallback_line_search, "");
  Teuchos::ParameterList nox;
  nox.sublist("NOX").sublist("Line Search").set("Method", std::string("Polynomial"));
  EXPECT_EQ(newton_options_from(nox).fallback_line_search, "");
}

TEST(Newton, UpdateToleranceAddsAStepTest) {
  CubicProblem problem;
  Vector x(problem.map());
  NewtonOptions options = quiet_options();
  options.update_tolerance = 1e-8;
  const NewtonReport report = solve(problem, x, options);
  ASSERT_TRUE(report.converged) << report.reason;
  EXPECT_LT(distance(x, problem.root()), 1e-10);
}

TEST(Newton, LogsOneLinePerIterationOnRankZero) {
  CubicProblem problem;
  Vector x(problem.map());
  NewtonOptions options;  // verbose
  LinearSolver linear(Teuchos::ParameterList(), "test", {});
  testing::internal::CaptureStdout();
  const NewtonReport report = solve_newton(problem, x, linear, options, "  test");
  const std::string out = testing::internal::GetCapturedStdout();
  if (problem.map()->getComm()->getRank() != 0) {
    EXPECT_EQ(out, "");
    return;
  }
  EXPECT_NE(out.find("  test newton 0  |F| = "), std::string::npos) << out;
  EXPECT_NE(out.find("active 7 (0 changed)  linear 1"), std::string::npos) << out;
  std::size_t lines = 0;
  for (char c : out) lines += c == '\n';
  EXPECT_EQ(lines, std::size_t(report.iterations + 1)) << out;
}

TEST(NewtonOptions, ReadsNewtonAndPassesNoxThrough) {
  Teuchos::ParameterList solver;
  auto& newton = solver.sublist("Newton");
  newton.set("max_iterations", 7);
  newton.set("absolute_tolerance", 1e-8);
  newton.set("relative_tolerance", 0);  // an int where a double is expected is fine
  newton.set("line_search", std::string("Backtrack"));
  newton.set("require_unchanged_active_set", false);
  solver.sublist("NOX").sublist("Line Search").sublist("Backtrack").set("Max Iters", 9);
  const NewtonOptions options = newton_options_from(solver);
  EXPECT_EQ(options.max_iterations, 7);
  EXPECT_EQ(options.absolute_tolerance, 1e-8);
  EXPECT_EQ(options.relative_tolerance, 0.0);
  EXPECT_EQ(options.line_search, "Backtrack");
  EXPECT_FALSE(options.require_unchanged_active_set);
  EXPECT_EQ(options.nox.sublist("Line Search").sublist("Backtrack").get<int>("Max Iters"), 9);
  EXPECT_EQ(newton_options_from(Teuchos::ParameterList()).max_iterations, 25);
}

TEST(NewtonOptions, UnknownKeyIsAnInputErrorNamingIt) {
  Teuchos::ParameterList solver;
  solver.sublist("Newton").set("max_iter", 3);
  try {
    newton_options_from(solver);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("grout/solver/Newton: unknown key 'max_iter'"),
              std::string::npos)
        << e.what();
  }
  Teuchos::ParameterList bad;
  bad.sublist("Newton").set("line_search", std::string("Zigzag"));
  EXPECT_THROW(newton_options_from(bad), InputError);
}

TEST(Newton, StopsAtTheResidualRoundOffFloor) {
  // ‖F₀‖ ≈ √8; every later iterate has ‖F‖ = 2ε√8 = 5.7e-9: the relative (1e-10 ‖F₀‖) and
  // absolute (1e-10) tests can never pass. With the floor estimated at ε√8, the default
  // floor_factor 10 accepts ‖F‖ ≤ 2.8e-8, after one step.
  FloorProblem problem(1e-9, 1e-9);
  NewtonOptions options = quiet_options();
  options.max_iterations = 8;
  Vector x(problem.map());
  const NewtonReport report = solve(problem, x, options);
  EXPECT_TRUE(report.converged) << report.reason;
  EXPECT_EQ(report.iterations, 1);
  EXPECT_NEAR(report.residual_history.back(), 2e-9 * std::sqrt(8.0), 1e-12);
  options.floor_factor = 0.0;  // off: the floor cannot be passed
  Vector x_off(problem.map());
  const NewtonReport off = solve(problem, x_off, options);
  EXPECT_FALSE(off.converged);
  EXPECT_EQ(off.reason, "max iterations (8)");
  // An estimate 100 × below the actual floor: 10 × estimate < ‖F‖, not converged.
  FloorProblem underestimated(1e-9, 1e-11);
  options.floor_factor = 10.0;
  Vector x_under(underestimated.map());
  EXPECT_FALSE(solve(underestimated, x_under, options).converged);
}

TEST(Newton, RoundOffFloorNearTheFirstResidualIsNotTrusted) {
  // A floor estimate as large as ‖F₀‖ (ε times a huge penalty or modulus) would accept the
  // very first iterate. It is trusted only when floor_factor · floor ≤ 1e-4 ‖F₀‖: here it
  // is not, and the absolute and relative tests cannot pass the actual floor (1e-9).
  FloorProblem problem(1e-9, 1.0);  // estimate √8 ≈ ‖F₀‖
  NewtonOptions options = quiet_options();
  options.max_iterations = 4;
  Vector x(problem.map());
  const NewtonReport report = solve(problem, x, options);
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.reason, "max iterations (4)");
  // An estimate 1e-6 ‖F₀‖ is trusted (10 × 1e-6 ‖F₀‖ ≤ 1e-4 ‖F₀‖), and the first iterate,
  // at the actual floor 2e-9 √8, is below 10 × the estimate: converged after one iteration.
  FloorProblem small_floor(1e-9, 1e-6);
  Vector x_small(small_floor.map());
  const NewtonReport small = solve(small_floor, x_small, options);
  EXPECT_TRUE(small.converged) << small.reason;
  EXPECT_EQ(small.iterations, 1);
}

/// F(x) = s (x - 1) with s so large that F overflows to ±inf; the floor estimate overflows too.
class OverflowProblem : public NonlinearProblem {
 public:
  OverflowProblem() : map_(Teuchos::rcp(new Map(4, 0, Tpetra::getDefaultComm()))) {}
  Teuchos::RCP<const Map> map() const override { return map_; }
  bool residual(const Vector& x, Vector& F) override {
    auto f = F.getLocalViewHost(Tpetra::Access::OverwriteAll);
    const auto xv = x.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (LO i = 0; i < LO(f.extent(0)); ++i) f(i, 0) = 1e308 * 10.0 * (xv(i, 0) - 1.0);
    return true;
  }
  bool jacobian(const Vector& x, Teuchos::RCP<Matrix>& J) override {
    J = diagonal_matrix(x, [](double) { return 1.0; });
    return true;
  }
  double residual_floor() const override { return std::numeric_limits<double>::infinity(); }

 private:
  Teuchos::RCP<const Map> map_;
};

TEST(Newton, InfiniteResidualNeverConverges) {
  OverflowProblem problem;
  Vector x(problem.map());
  const NewtonReport report = solve(problem, x, quiet_options());
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.reason, "non-finite residual");
}

TEST(NewtonOptions, ErrorsNameTheInputFile) {
  Teuchos::ParameterList solver;
  solver.sublist("Newton").set("max_iterations", 0);  // NOX's MaxIters aborts on < 1
  try {
    newton_options_from(solver, "case.yaml");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "case.yaml: grout/solver/Newton/max_iterations: expected an integer >= 1, got an "
                 "integer '0'");
  }
}

TEST(Newton, SettingsNoxRejectsAreAnInputErrorNamingTheKey) {
  Teuchos::ParameterList solver;
  solver.sublist("NOX").set("Nonlinear Solver", std::string("Newton Raphson Deluxe"));
  NewtonOptions options = newton_options_from(solver, "case.yaml");
  options.verbose = false;
  FloorProblem problem(0.0, 0.0);
  Vector x(problem.map());
  try {
    solve(problem, x, options);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("case.yaml: grout/solver/NOX: NOX rejects these settings", 0), 0u)
        << message;
    EXPECT_NE(message.find("Newton Raphson Deluxe"), std::string::npos) << message;
    EXPECT_EQ(message.find(".cpp:"), std::string::npos) << message;
    EXPECT_EQ(message.find(".H:"), std::string::npos) << message;
  }
}

TEST(NewtonOptions, ReadsFloorFactor) {
  Teuchos::ParameterList solver;
  solver.sublist("Newton").set("floor_factor", 100.0);
  EXPECT_EQ(newton_options_from(solver).floor_factor, 100.0);
  EXPECT_EQ(newton_options_from(Teuchos::ParameterList()).floor_factor, 10.0);
}

}  // namespace
}  // namespace grout
