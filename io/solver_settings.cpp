// solver_settings_from: the `grout/solver` section typed once (io/solver_settings.hpp).

#include "io/solver_settings.hpp"

#include "io/errors.hpp"
#include "io/input_schema.hpp"
#include "io/solver_parameters.hpp"

namespace grout {

namespace {

using input_schema::Key;
using input_schema::Section;

const std::vector<std::string> line_searches = {"Full Step", "Backtrack", "Polynomial",
                                                "More'-Thuente"};

NewtonOptions read_newton(const Section& solver) {
  const Section newton =
      solver.section("Newton", {Key::integer("max_iterations").at_least(1).defaults("25"),
                                Key::number("absolute_tolerance")
                                    .at_least(0)
                                    .at_most(max_absolute_tolerance)
                                    .defaults("1e-10"),
                                Key::number("relative_tolerance")
                                    .at_least(0)
                                    .below(max_relative_tolerance)
                                    .defaults("1e-10"),
                                Key::number("floor_factor").at_least(0).defaults("10"),
                                Key::number("update_tolerance").at_least(0).defaults("0"),
                                Key::choice("line_search", line_searches, "line search"),
                                Key::boolean("require_unchanged_active_set").defaults("true")});
  NewtonOptions options;
  options.where = (solver.file().empty() ? "" : solver.file() + ": ") + solver.path();
  options.max_iterations = newton.integer("max_iterations");
  options.absolute_tolerance = newton.number("absolute_tolerance");
  options.relative_tolerance = newton.number("relative_tolerance");
  options.floor_factor = newton.number("floor_factor");
  options.update_tolerance = newton.number("update_tolerance");
  if (newton.has("line_search")) {
    options.line_search = newton.string("line_search");
    options.fallback_line_search.clear();  // the input's choice holds for every attempt
  }
  options.require_unchanged_active_set = newton.boolean("require_unchanged_active_set");
  options.nox = input_schema::read_nox(solver);
  if (options.nox.isSublist("Line Search") || options.nox.isParameter("Nonlinear Solver"))
    options.fallback_line_search.clear();
  return options;
}

MumpsOptions read_mumps(const Section& mumps) {
  MumpsOptions options;
  options.ordering = mumps.string("ordering");
  options.symmetric = mumps.boolean("symmetric");
  options.gather = mumps.boolean("gather");
  return options;
}

const std::vector<Key> mumps_keys = {
    Key::choice("ordering", {"scotch", "ptscotch", "amd", "pord"}, "ordering").defaults("scotch"),
    Key::boolean("symmetric").defaults("false"), Key::boolean("gather").defaults("false")};

// The `Linear Solver` sublist `list`, named `path` (in `file`, "" for none) in errors.
LinearSolverSettings read_linear(const Teuchos::ParameterList& list, const std::string& path,
                                 const std::string& file) {
  // `MUMPS: 5` and `MueLu: 7` are refused here: each must be a section of keys.
  const Section checked(
      list, path, file,
      {Key::choice("type", {"auto", "mumps", "amesos2", "belos"}, "linear solver").defaults("auto"),
       Key::boolean("condense_multipliers"), Key::boolean("reuse_preconditioner"),
       Key::boolean("symmetric_reduction").defaults("true"),
       Key::choice("near_null_space", {"rigid_body", "translations"}, "near-null space")
           .defaults("rigid_body"),
       Key::section("MUMPS"), Key::section("Belos"), Key::section("MueLu")});
  LinearSolverSettings settings;
  settings.where = (file.empty() ? "" : file + ": ") + path;
  const std::string type = checked.string("type");
  settings.type = type == "mumps"     ? LinearSolverType::mumps
                  : type == "amesos2" ? LinearSolverType::amesos2
                  : type == "belos"   ? LinearSolverType::belos
                                      : LinearSolverType::automatic;
  const Section mumps = checked.section("MUMPS", mumps_keys);
  settings.mumps = read_mumps(mumps);
  settings.mumps_given = checked.has("MUMPS");
  settings.mumps_ordering_given = mumps.has("ordering");
  const Section belos = checked.section("Belos", input_schema::belos_keys());
  settings.belos_solver = belos.string("Solver Type");
  Teuchos::ParameterList given = input_schema::typed_copy(belos);
  given.remove("Solver Type", false);
  settings.belos.setParameters(given);  // over grout_belos_defaults()
  settings.muelu = input_schema::read_muelu(checked);
  if (checked.has("condense_multipliers"))
    settings.condense_multipliers = checked.boolean("condense_multipliers");
  if (checked.has("reuse_preconditioner"))
    settings.reuse_preconditioner = checked.boolean("reuse_preconditioner");
  settings.symmetric_reduction = checked.boolean("symmetric_reduction");
  settings.translations_only = checked.string("near_null_space") == "translations";
  return settings;
}

}  // namespace

std::string linear_solver_type_name(LinearSolverType type) {
  switch (type) {
    case LinearSolverType::mumps:
      return "mumps";
    case LinearSolverType::amesos2:
      return "amesos2";
    case LinearSolverType::belos:
      return "belos";
    case LinearSolverType::automatic:
      break;
  }
  return "auto";
}

Teuchos::ParameterList grout_belos_defaults() {
  Teuchos::ParameterList defaults;
  defaults.set("Convergence Tolerance", 1e-12);
  defaults.set("Maximum Iterations", 2000);
  return defaults;
}

SolverSettings solver_settings_from(const Teuchos::ParameterList& solver, const std::string& file) {
  const Section section(
      solver, "grout/solver", file,
      {Key::section("Newton"), Key::section("NOX"), Key::section("Linear Solver")});
  SolverSettings settings;
  settings.newton = read_newton(section);
  settings.linear =
      read_linear(section.raw_section("Linear Solver"), "grout/solver/Linear Solver", file);
  return settings;
}

NewtonOptions newton_options_from(const Teuchos::ParameterList& solver_sublist,
                                  const std::string& file) {
  return solver_settings_from(solver_sublist, file).newton;
}

LinearSolverSettings linear_solver_settings_from(const Teuchos::ParameterList& params,
                                                 const std::string& where) {
  return read_linear(params, where, "");
}

MumpsOptions mumps_options_from(const Teuchos::ParameterList& params, const std::string& where) {
  return read_mumps(Section(params, where, "", mumps_keys));
}

}  // namespace grout
