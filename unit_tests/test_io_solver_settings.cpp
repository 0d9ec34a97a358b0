// grout/solver read into SolverSettings (io/solver_settings.hpp): defaults, typed values, and
// every key checked against a schema (docs/input.md, "grout/solver").

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/errors.hpp"
#include "io/input.hpp"
#include "io/solver_settings.hpp"

namespace grout {
namespace {

const std::string minimal = R"yaml(grout:
  mesh: {file: mesh.exo}
  model: {dimension: 2}
  materials:
    steel: {block: body, law: linear_elastic, youngs_modulus: 200, poissons_ratio: 0.3}
)yaml";

/// The settings of `minimal` with `solver` as its `solver:` section (flow style).
SolverSettings read(const std::string& solver) {
  return read_input_text(minimal + "  solver: " + solver + "\n", "case.yaml").solver;
}

/// read(solver) must throw an InputError whose message is exactly `message`.
void expect_error(const std::string& solver, const std::string& message) {
  SCOPED_TRACE(solver);
  try {
    read(solver);
    ADD_FAILURE() << "expected an InputError: " << message;
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

TEST(SolverSettings, DefaultsAreTheSolversDefaults) {
  const SolverSettings s = read_input_text(minimal, "case.yaml").solver;
  EXPECT_EQ(s.newton.max_iterations, 25);
  EXPECT_EQ(s.newton.absolute_tolerance, 1e-10);
  EXPECT_EQ(s.newton.relative_tolerance, 1e-10);
  EXPECT_EQ(s.newton.floor_factor, 10.0);
  EXPECT_EQ(s.newton.update_tolerance, 0.0);
  EXPECT_EQ(s.newton.line_search, "Full Step");
  EXPECT_EQ(s.newton.fallback_line_search, "Backtrack");
  EXPECT_TRUE(s.newton.require_unchanged_active_set);
  EXPECT_EQ(s.newton.where, "case.yaml: grout/solver");
  EXPECT_EQ(s.linear.type, LinearSolverType::automatic);
  EXPECT_EQ(s.linear.mumps.ordering, "scotch");
  EXPECT_FALSE(s.linear.mumps.symmetric);
  EXPECT_FALSE(s.linear.mumps.gather);
  EXPECT_FALSE(s.linear.mumps_given);
  EXPECT_FALSE(s.linear.mumps_ordering_given);
  EXPECT_EQ(s.linear.belos_solver, "");
  EXPECT_EQ(s.linear.belos.get<double>("Convergence Tolerance"), 1e-12);
  EXPECT_EQ(s.linear.belos.get<int>("Maximum Iterations"), 2000);
  EXPECT_EQ(s.linear.belos.numParams(), 2);
  EXPECT_EQ(s.linear.muelu.numParams(), 0);
  EXPECT_FALSE(s.linear.condense_multipliers.has_value());
  EXPECT_FALSE(s.linear.reuse_preconditioner.has_value());  // the coarse levels kept
  EXPECT_TRUE(s.linear.symmetric_reduction);
  EXPECT_FALSE(s.linear.translations_only);  // the rotations in the near-null space
  EXPECT_EQ(s.linear.where, "case.yaml: grout/solver/Linear Solver");
}

TEST(SolverSettings, ReadsEveryKeyTyped) {
  const SolverSettings s = read(R"yaml(
    Newton:
      max_iterations: 7
      absolute_tolerance: 0
      relative_tolerance: 1.0e-8
      floor_factor: 100
      update_tolerance: 1.0e-6
      line_search: Polynomial
      require_unchanged_active_set: false
    NOX:
      Line Search: {Polynomial: {Max Iters: 9, Minimum Step: 1}}
      Direction: {Newton: {Rescue Bad Newton Solve: true}}
    Linear Solver:
      type: belos
      condense_multipliers: false
      reuse_preconditioner: true
      symmetric_reduction: false
      near_null_space: translations
      MUMPS: {ordering: amd, gather: true, symmetric: false}
      Belos: {Solver Type: GMRES, Maximum Iterations: 50, Convergence Tolerance: 1.0e-9}
      MueLu:
        'sa: damping factor': 1
        'coarse: max size': 100
        level 1: {'smoother: type': RELAXATION}
)yaml");
  EXPECT_EQ(s.newton.max_iterations, 7);
  EXPECT_EQ(s.newton.absolute_tolerance, 0.0);
  EXPECT_EQ(s.newton.relative_tolerance, 1e-8);
  EXPECT_EQ(s.newton.floor_factor, 100.0);
  EXPECT_EQ(s.newton.update_tolerance, 1e-6);
  EXPECT_EQ(s.newton.line_search, "Polynomial");
  EXPECT_EQ(s.newton.fallback_line_search, "");  // the input's choice holds on the retries
  EXPECT_FALSE(s.newton.require_unchanged_active_set);
  // A YAML integer where NOX takes a double is passed on as a double.
  const Teuchos::ParameterList& polynomial =
      s.newton.nox.sublist("Line Search").sublist("Polynomial");
  EXPECT_EQ(polynomial.get<int>("Max Iters"), 9);
  EXPECT_TRUE(polynomial.isType<double>("Minimum Step"));
  EXPECT_TRUE(
      s.newton.nox.sublist("Direction").sublist("Newton").get<bool>("Rescue Bad Newton Solve"));
  EXPECT_EQ(s.linear.type, LinearSolverType::belos);
  EXPECT_EQ(s.linear.condense_multipliers, std::optional<bool>(false));
  EXPECT_EQ(s.linear.reuse_preconditioner, std::optional<bool>(true));
  EXPECT_FALSE(s.linear.symmetric_reduction);
  EXPECT_TRUE(s.linear.translations_only);
  EXPECT_EQ(s.linear.mumps.ordering, "amd");
  EXPECT_TRUE(s.linear.mumps.gather);
  EXPECT_TRUE(s.linear.mumps_given);
  EXPECT_TRUE(s.linear.mumps_ordering_given);
  EXPECT_EQ(s.linear.belos_solver, "GMRES");
  EXPECT_FALSE(s.linear.belos.isParameter("Solver Type"));
  EXPECT_EQ(s.linear.belos.get<int>("Maximum Iterations"), 50);
  EXPECT_EQ(s.linear.belos.get<double>("Convergence Tolerance"), 1e-9);
  EXPECT_TRUE(s.linear.muelu.isType<double>("sa: damping factor"));  // MueLu takes a double
  EXPECT_EQ(s.linear.muelu.get<double>("sa: damping factor"), 1.0);
  EXPECT_EQ(s.linear.muelu.get<int>("coarse: max size"), 100);
  EXPECT_EQ(s.linear.muelu.sublist("level 1").get<std::string>("smoother: type"), "RELAXATION");
}

TEST(SolverSettings, LinearSolverShapeAndType) {
  expect_error("{Linear Solver: {type: 5}}",
               "case.yaml: grout/solver/Linear Solver/type: expected a non-empty string, got an "
               "integer '5'");
  expect_error("{Linear Solver: [mumps]}",
               "case.yaml: grout/solver/Linear Solver: expected a section of keys, got a list "
               "'{mumps}'");
  expect_error("{Linear Solver: {type: superlu}}",
               "case.yaml: grout/solver/Linear Solver/type: unknown linear solver 'superlu' "
               "(expected one of: auto, mumps, amesos2, belos)");
  expect_error("{Linear Solver: {near_null_space: rotations}}",
               "case.yaml: grout/solver/Linear Solver/near_null_space: unknown near-null space "
               "'rotations' (expected one of: rigid_body, translations)");
  expect_error("{Linear Solver: {MUMPS: 5}}",
               "case.yaml: grout/solver/Linear Solver/MUMPS: expected a section of keys, got an "
               "integer '5'");
  expect_error("{Linear Solver: {MueLu: 7}}",
               "case.yaml: grout/solver/Linear Solver/MueLu: expected a section of keys, got an "
               "integer '7'");
  expect_error("{Linear Solver: {Belos: fast}}",
               "case.yaml: grout/solver/Linear Solver/Belos: expected a section of keys, got a "
               "string 'fast'");
}

TEST(SolverSettings, MisspeltKeysAreNamedWithASuggestion) {
  expect_error("{Linear Solver: {typ: mumps}}",
               "case.yaml: grout/solver/Linear Solver: unknown key 'typ' (expected one of: type, "
               "condense_multipliers, reuse_preconditioner, symmetric_reduction, near_null_space, "
               "MUMPS, Belos, MueLu); did you mean 'type'?");
  expect_error("{Linear Solver: {condense_multiplier: true}}",
               "case.yaml: grout/solver/Linear Solver: unknown key 'condense_multiplier' (expected "
               "one of: type, condense_multipliers, reuse_preconditioner, symmetric_reduction, "
               "near_null_space, MUMPS, Belos, MueLu); did you mean 'condense_multipliers'?");
  expect_error("{Linear Solver: {MUMPS: {orderin: amd}}}",
               "case.yaml: grout/solver/Linear Solver/MUMPS: unknown key 'orderin' (expected one "
               "of: ordering, symmetric, gather); did you mean 'ordering'?");
  expect_error("{Newton: {max_iteration: 3}}",
               "case.yaml: grout/solver/Newton: unknown key 'max_iteration' (expected one of: "
               "max_iterations, absolute_tolerance, relative_tolerance, floor_factor, "
               "update_tolerance, line_search, require_unchanged_active_set); did you mean "
               "'max_iterations'?");
  // NOX's sublists at every level.
  expect_error("{NOX: {Line Serch: {Method: Backtrack}}}",
               "case.yaml: grout/solver/NOX: unknown key 'Line Serch' (expected one of: Nonlinear "
               "Solver, Direction, Line Search, Printing, Solver Options, Trust Region, Cauchy "
               "Direction); did you mean 'Line Search'?");
  expect_error("{NOX: {Line Search: {Backtrack: {Max Iter: 5}}}}",
               "case.yaml: grout/solver/NOX/Line Search/Backtrack: unknown key 'Max Iter' "
               "(expected one of: Default Step, Minimum Step, Recovery Step, Max Iters, Recovery "
               "Step Type, User Defined Norm, Merit Function, Reduction Factor); did you mean "
               "'Max Iters'?");
  // Belos and MueLu: their own names (docs/input.md), too many to list in the message.
  expect_error("{Linear Solver: {Belos: {Maximum Iteration: 50}}}",
               "case.yaml: grout/solver/Linear Solver/Belos: unknown key 'Maximum Iteration' (not "
               "one of the 43 names it accepts: docs/input.md); did you mean 'Maximum "
               "Iterations'?");
  expect_error("{Linear Solver: {MueLu: {'smoother: typ': RELAXATION}}}",
               "case.yaml: grout/solver/Linear Solver/MueLu: unknown key 'smoother: typ' (not one "
               "of the 194 names it accepts: docs/input.md); did you mean 'smoother: type'?");
  expect_error("{Linear Solver: {MueLu: {level 1: {'coarse: maxsize': 9}}}}",
               "case.yaml: grout/solver/Linear Solver/MueLu/level 1: unknown key 'coarse: "
               "maxsize' (not one of the 194 names it accepts: docs/input.md); did you mean "
               "'coarse: max size'?");
}

TEST(SolverSettings, ValuesOutsideTheirRangeAreRefused) {
  expect_error("{Linear Solver: {Belos: {Maximum Iterations: 0}}}",
               "case.yaml: grout/solver/Linear Solver/Belos/Maximum Iterations: expected an "
               "integer >= 1, got an integer '0'");
  expect_error("{Linear Solver: {Belos: {Maximum Iterations: -5}}}",
               "case.yaml: grout/solver/Linear Solver/Belos/Maximum Iterations: expected an "
               "integer >= 1, got an integer '-5'");
  expect_error("{Linear Solver: {Belos: {Convergence Tolerance: 2}}}",
               "case.yaml: grout/solver/Linear Solver/Belos/Convergence Tolerance: expected a "
               "number in (0, 1), got '2'");
  expect_error("{Linear Solver: {MueLu: {'coarse: max size': many}}}",
               "case.yaml: grout/solver/Linear Solver/MueLu/coarse: max size: expected an integer "
               ">= 1, got a string 'many'");
  expect_error("{Linear Solver: {MueLu: {'multigrid algorithm': smoothed}}}",
               "case.yaml: grout/solver/Linear Solver/MueLu/multigrid algorithm: unknown MueLu "
               "multigrid algorithm 'smoothed' (expected one of: unsmoothed, sa, pg, emin, matlab, "
               "pcoarsen, classical, smoothed reitzinger, unsmoothed reitzinger)");
  expect_error("{Linear Solver: {MueLu: {level 1: {'reuse: type': all}}}}",
               "case.yaml: grout/solver/Linear Solver/MueLu/level 1/reuse: type: unknown MueLu "
               "reuse type 'all' (expected one of: none, tP, RP, emin, RAP, full, S)");
  expect_error("{Newton: {absolute_tolerance: -1.0e-8}}",
               "case.yaml: grout/solver/Newton/absolute_tolerance: expected a number in [0, 1], "
               "got '-1e-08'");
  expect_error("{Newton: {absolute_tolerance: 1.0e300}}",
               "case.yaml: grout/solver/Newton/absolute_tolerance: expected a number in [0, 1], "
               "got '1e+300'");
  expect_error("{Newton: {relative_tolerance: 2}}",
               "case.yaml: grout/solver/Newton/relative_tolerance: expected a number in [0, 1), "
               "got '2'");
  expect_error("{Newton: {relative_tolerance: 1}}",
               "case.yaml: grout/solver/Newton/relative_tolerance: expected a number in [0, 1), "
               "got '1'");
  expect_error("{Newton: {update_tolerance: -1}}",
               "case.yaml: grout/solver/Newton/update_tolerance: expected a number >= 0, got '-1'");
  expect_error("{Newton: {max_iterations: 0}}",
               "case.yaml: grout/solver/Newton/max_iterations: expected an integer >= 1, got an "
               "integer '0'");
  expect_error("{Newton: {line_search: Zigzag}}",
               "case.yaml: grout/solver/Newton/line_search: unknown line search 'Zigzag' "
               "(expected one of: Full Step, Backtrack, Polynomial, More'-Thuente)");
  expect_error("{Newton: {require_unchanged_active_set: 1}}",
               "case.yaml: grout/solver/Newton/require_unchanged_active_set: expected true or "
               "false, got an integer '1'");
  expect_error("{Linear Solver: {condense_multipliers: maybe}}",
               "case.yaml: grout/solver/Linear Solver/condense_multipliers: expected true or "
               "false, got a string 'maybe'");
}

TEST(SolverSettings, SublistsReadOnTheirOwnNameTheirPlace) {
  const std::string where = "case.yaml: grout/solver/Linear Solver";
  Teuchos::ParameterList linear;
  linear.set("type", std::string("mumps"));
  linear.sublist("MUMPS").set("symmetric", true);
  const LinearSolverSettings s = linear_solver_settings_from(linear, where);
  EXPECT_EQ(s.type, LinearSolverType::mumps);
  EXPECT_TRUE(s.mumps.symmetric);
  EXPECT_EQ(s.where, where);
  linear.sublist("MUMPS").set("pivoting", 0.1);
  try {
    linear_solver_settings_from(linear, where);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(where + "/MUMPS: unknown key 'pivoting'", 0), 0u)
        << e.what();
  }
  Teuchos::ParameterList solver;
  solver.sublist("Newton").set("max_iterations", 0);
  try {
    newton_options_from(solver);  // no file: the message starts with the key
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "grout/solver/Newton/max_iterations: expected an integer >= 1, got an integer '0'");
  }
}

}  // namespace
}  // namespace grout
