// The names Belos, MueLu and NOX accept in the sublists passed through to them
// (io/solver_parameters.hpp).

#include "io/solver_parameters.hpp"

namespace grout::input_schema {

std::vector<Key> belos_keys() {
  return {Key::string("Solver Type"),
          Key::boolean("Adaptive Block Size"),
          Key::boolean("Add Roots"),
          Key::boolean("Assert Positive Definiteness"),
          Key::integer("Block Size").at_least(1),
          Key::number("Condition Limit"),
          Key::number("Convergence Tolerance").above(0).below(1),
          Key::boolean("Damp Poly"),
          Key::integer("Deflation Quorum"),
          Key::boolean("Estimate Condition Number"),
          Key::string("Explicit Residual Scaling"),
          Key::boolean("Explicit Residual Test"),
          Key::boolean("Flexible Gmres"),
          Key::boolean("Fold Convergence Detection Into Allreduce"),
          Key::string("Implicit Residual Scaling"),
          Key::number("Implicit Tolerance Scale Factor"),
          Key::number("Lambda"),
          Key::integer("Maximum Degree"),
          Key::integer("Maximum Iterations").at_least(1),
          Key::integer("Maximum Restarts").at_least(0),
          Key::integer("Num Blocks").at_least(1),
          Key::integer("Num Deflated Blocks"),
          Key::integer("Num Recycled Blocks"),
          Key::integer("Num Saved Blocks"),
          Key::string("Orthogonalization"),
          Key::number("Orthogonalization Constant"),
          Key::section("Orthogonalization Parameters"),
          Key::string("Outer Solver"),
          Key::integer("Output Frequency").at_least(-1),
          Key::integer("Output Style"),
          Key::number("Polynomial Tolerance"),
          Key::string("Polynomial Type"),
          Key::boolean("Random RHS"),
          Key::number("Rel Mat Err"),
          Key::number("Rel RHS Err"),
          Key::string("Residual Norm"),
          Key::string("Residual Scaling"),
          Key::boolean("Show Maximum Residual Norm Only"),
          Key::integer("Term Iter Max"),
          Key::string("Timer Label"),
          Key::boolean("Use Single Reduction"),
          Key::string("User Status Tests Combo Type"),
          Key::integer("Verbosity").at_least(0)};
}

Teuchos::ParameterList typed_copy(const Section& section) {
  Teuchos::ParameterList copy = section.list();
  for (const Key& key : section.keys()) {
    if (key.type == ValueType::number && section.has(key.name))
      copy.set(key.name, section.number(key.name));
  }
  return copy;
}

Teuchos::ParameterList read_muelu(const Section& linear) {
  const Section muelu = linear.section(
      "MueLu",
      muelu_keys(linear.has("MueLu") ? linear.list().sublist("MueLu") : Teuchos::ParameterList()));
  Teuchos::ParameterList typed = typed_copy(muelu);
  for (const Key& key : muelu.keys()) {
    if (key.name.rfind("level ", 0) == 0 && muelu.has(key.name)) {
      const Section level = muelu.section(key.name, muelu_keys(Teuchos::ParameterList()));
      typed.sublist(key.name) = typed_copy(level);
    }
  }
  return typed;
}

namespace {

// NOX's line searches (NOX_LineSearch_Backtrack.H, _Polynomial.H, _MoreThuente.H,
// _FullStep.H): the keys of their sublists of `Line Search`.
std::vector<Key> line_search_keys(const std::string& method) {
  const std::vector<Key> common = {Key::number("Default Step").above(0),
                                   Key::number("Minimum Step").at_least(0),
                                   Key::number("Recovery Step").at_least(0),
                                   Key::integer("Max Iters").at_least(1),
                                   Key::string("Recovery Step Type"),
                                   Key::any("User Defined Norm"),
                                   Key::any("Merit Function")};
  std::vector<Key> keys = common;
  if (method == "Full Step") return {Key::number("Full Step").above(0)};
  if (method == "Backtrack") keys.push_back(Key::number("Reduction Factor").above(0).below(1));
  if (method == "Polynomial") {
    for (const char* name :
         {"Min Bounds Factor", "Max Bounds Factor", "Alpha Factor", "Allowed Relative Increase"})
      keys.push_back(Key::number(name));
    for (const char* name : {"Interpolation Type", "Sufficient Decrease Condition"})
      keys.push_back(Key::string(name));
    for (const char* name : {"Force Interpolation", "Use Counters", "Optimize Slope Calculation"})
      keys.push_back(Key::boolean(name));
    keys.push_back(Key::integer("Maximum Iteration for Increase").at_least(0));
  }
  if (method == "More'-Thuente") {
    for (const char* name :
         {"Sufficient Decrease", "Curvature Condition", "Interval Width", "Maximum Step"})
      keys.push_back(Key::number(name));
    keys.push_back(Key::string("Sufficient Decrease Condition"));
    keys.push_back(Key::boolean("Optimize Slope Calculation"));
  }
  return keys;
}

const std::vector<std::string> line_search_methods = {"Full Step", "Backtrack", "Polynomial",
                                                      "More'-Thuente"};

Teuchos::ParameterList read_line_search(const Section& nox) {
  std::vector<Key> keys = {Key::string("Method")};
  for (const std::string& method : line_search_methods) keys.push_back(Key::section(method));
  const Section search = nox.section("Line Search", keys);
  Teuchos::ParameterList typed = typed_copy(search);
  for (const std::string& method : line_search_methods) {
    if (search.has(method))
      typed.sublist(method) = typed_copy(search.section(method, line_search_keys(method)));
  }
  return typed;
}

// NOX_Direction_Newton.H: `Direction/Newton` and its `Linear Solver/Tolerance`.
Teuchos::ParameterList read_direction(const Section& nox) {
  const Section direction = nox.section("Direction", {Key::string("Method"), Key::section("Newton"),
                                                      Key::section("Steepest Descent")});
  Teuchos::ParameterList typed = typed_copy(direction);
  if (direction.has("Newton")) {
    const Section newton = direction.section(
        "Newton", {Key::string("Forcing Term Method"),
                   Key::number("Forcing Term Initial Tolerance").at_least(0),
                   Key::number("Forcing Term Minimum Tolerance").at_least(0),
                   Key::number("Forcing Term Maximum Tolerance").at_least(0),
                   Key::number("Forcing Term Alpha"), Key::number("Forcing Term Gamma"),
                   Key::boolean("Rescue Bad Newton Solve"), Key::section("Linear Solver")});
    typed.sublist("Newton") = typed_copy(newton);
    if (newton.has("Linear Solver")) {
      typed.sublist("Newton").sublist("Linear Solver") =
          typed_copy(newton.section("Linear Solver", {Key::number("Tolerance").at_least(0)}));
    }
  }
  if (direction.has("Steepest Descent")) {
    typed.sublist("Steepest Descent") =
        typed_copy(direction.section("Steepest Descent", {Key::string("Scaling Type")}));
  }
  return typed;
}

}  // namespace

Teuchos::ParameterList read_nox(const Section& solver) {
  const Section nox = solver.section(
      "NOX", {Key::string("Nonlinear Solver"), Key::section("Direction"),
              Key::section("Line Search"), Key::section("Printing"), Key::section("Solver Options"),
              Key::section("Trust Region"), Key::section("Cauchy Direction")});
  Teuchos::ParameterList typed = typed_copy(nox);
  if (nox.has("Line Search")) typed.sublist("Line Search") = read_line_search(nox);
  if (nox.has("Direction")) typed.sublist("Direction") = read_direction(nox);
  if (nox.has("Printing")) {  // NOX_Utils.H; `Output Information` is a number or a sublist
    typed.sublist("Printing") = typed_copy(
        nox.section("Printing", {Key::any("Output Information"), Key::integer("Output Precision"),
                                 Key::integer("Output Processor"), Key::integer("MyPID")}));
  }
  if (nox.has("Solver Options")) {  // NOX_Solver_LineSearchBased.H
    typed.sublist("Solver Options") =
        typed_copy(nox.section("Solver Options", {Key::string("Status Test Check Type")}));
  }
  if (nox.has("Trust Region")) {  // NOX_Solver_TrustRegionBased.H
    std::vector<Key> keys;
    for (const char* name :
         {"Minimum Trust Region Radius", "Maximum Trust Region Radius", "Minimum Improvement Ratio",
          "Contraction Trigger Ratio", "Contraction Factor", "Expansion Trigger Ratio",
          "Expansion Factor", "Recovery Step"})
      keys.push_back(Key::number(name));
    keys.push_back(Key::boolean("Use Ared/Pred Ratio Calculation"));
    typed.sublist("Trust Region") = typed_copy(nox.section("Trust Region", keys));
  }
  return typed;
}

}  // namespace grout::input_schema
