// read_input, check_input_against_mesh and Expression: the YAML contract of docs/input.md.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "io/errors.hpp"
#include "io/expression.hpp"
#include "io/input.hpp"

namespace grout {
namespace {

const std::filesystem::path test_dir =
    std::filesystem::path(GROUT_BINARY_DIR) / "unit_tests" / "test_io_input";

/// Write `text` to <test_dir>/<name> and return its path.
std::string write_file(const std::string& name, const std::string& text) {
  std::filesystem::create_directories(test_dir);
  const std::string path = (test_dir / name).string();
  std::ofstream(path) << text;
  return path;
}

/// Expect `action` to throw an InputError whose message contains every one of `parts`.
void expect_input_error(const std::function<void()>& action,
                        const std::vector<std::string>& parts) {
  try {
    action();
    ADD_FAILURE() << "expected an InputError containing '" << parts.front() << "'";
  } catch (const InputError& e) {
    const std::string message = e.what();
    for (const std::string& part : parts) {
      EXPECT_NE(message.find(part), std::string::npos)
          << "message: " << message << "\nlacks:   " << part;
    }
  }
}

/// read_input on `text` written to <name>.yaml must fail naming the file and `parts`.
void expect_bad_input(const std::string& name, const std::string& text,
                      std::vector<std::string> parts) {
  SCOPED_TRACE(name);
  const std::string path = write_file(name + ".yaml", text);
  parts.push_back(name + ".yaml: ");
  expect_input_error([&] { read_input(path); }, parts);
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

const std::string minimal = R"yaml(grout:
  mesh: {file: mesh.exo}
  model: {dimension: 2}
  materials:
    steel: {block: body, law: linear_elastic, youngs_modulus: 200, poissons_ratio: 0.3}
)yaml";

const std::string full = R"yaml(%YAML 1.1
---
# the example of docs/input.md, with every key
grout:
  mesh: {file: meshes/patch.exo}
  model: {dimension: 2, plane: strain, strain: finite}
  materials:
    die:   {block: die,   law: neo_hookean, youngs_modulus: 1000, poissons_ratio: 0.4, density: 2}
    block: {block: id_2,  law: linear_elastic, youngs_modulus: 2.5e3, poissons_ratio: -0.25}
  dirichlet:
    bottom_y: {node_set: bottom, component: y, value: "0.0"}
    left_x:   {node_set: left,   component: x, value: 0}
    shear:    {node_set: left,   component: y, value: "x+2*y"}
    ramp:     {node_set: top,    component: x, value: 0.125}
  loads:
    top:      {side_set: top, type: pressure, value: "10.0*t"}
    side:
      side_set: right
      type: traction
      components: {x: "sin(pi*t)", y: -3}
  contact:
    interface: {slave: die_bottom, master: block_top, type: frictional, friction_coefficient: 0.3}
    glue:
      slave: die_side
      master: id_7
      type: tied
      c_n: 100
      c_t: 2.5
      integration: collocation
      collocation_points: 4
  time: {end: 2, steps: 10, stepping: adaptive, max_step_size: 0.5}
  solver:
    NOX: {Nonlinear Solver: Line Search Based}
    Newton: {max_iterations: 30, relative_tolerance: 1.0e-8}
    Linear Solver: {type: amesos2}
  output: {file: out/patch.e, summary: /tmp/patch_summary.csv}
...
)yaml";

TEST(InputRead, FullInputGivesEveryValue) {
  const std::string path = write_file("full.yaml", full);
  const Input in = read_input(path);
  const std::string dir = test_dir.string();

  EXPECT_EQ(in.file, path);
  EXPECT_EQ(in.directory, dir);
  EXPECT_EQ(in.mesh_file, dir + "/meshes/patch.exo");
  EXPECT_EQ(in.model.dimension, 2);
  EXPECT_EQ(in.model.plane, PlaneKind::strain);
  EXPECT_EQ(in.model.strain, StrainKind::finite);

  ASSERT_EQ(in.materials.size(), 2u);  // in file order
  EXPECT_EQ(in.materials[0].name, "die");
  EXPECT_EQ(in.materials[0].block, "die");
  EXPECT_EQ(in.materials[0].law, MaterialLaw::neo_hookean);
  EXPECT_EQ(in.materials[0].youngs_modulus, 1000.0);  // a YAML int read as a double
  EXPECT_EQ(in.materials[0].poissons_ratio, 0.4);
  EXPECT_EQ(in.materials[0].density, 2.0);
  EXPECT_EQ(in.materials[1].name, "block");
  EXPECT_EQ(in.materials[1].block, "id_2");
  EXPECT_EQ(in.materials[1].youngs_modulus, 2500.0);
  EXPECT_EQ(in.materials[1].poissons_ratio, -0.25);
  EXPECT_EQ(in.materials[1].density, 0.0);

  ASSERT_EQ(in.dirichlet.size(), 4u);
  EXPECT_EQ(in.dirichlet[0].name, "bottom_y");
  EXPECT_EQ(in.dirichlet[0].node_set, "bottom");
  EXPECT_EQ(in.dirichlet[0].component, 1);
  EXPECT_EQ(in.dirichlet[0].value(0.7, 1, 2, 3), 0.0);
  EXPECT_EQ(in.dirichlet[1].component, 0);
  EXPECT_EQ(in.dirichlet[1].value.text(), "0");  // a YAML number is an expression too
  EXPECT_DOUBLE_EQ(in.dirichlet[2].value(0.0, 1.0, 2.0, 0.0), 5.0);
  EXPECT_EQ(in.dirichlet[3].value.text(), "0.125");
  EXPECT_EQ(in.dirichlet[3].value(9, 9, 9, 9), 0.125);

  ASSERT_EQ(in.loads.size(), 2u);
  EXPECT_EQ(in.loads[0].side_set, "top");
  EXPECT_EQ(in.loads[0].type, LoadKind::pressure);
  EXPECT_DOUBLE_EQ(in.loads[0].value(0.5, 0, 0, 0), 5.0);
  EXPECT_TRUE(in.loads[0].components.empty());
  EXPECT_EQ(in.loads[1].name, "side");
  EXPECT_EQ(in.loads[1].type, LoadKind::traction);
  ASSERT_EQ(in.loads[1].components.size(), 2u);
  EXPECT_DOUBLE_EQ(in.loads[1].components[0](0.5, 0, 0, 0), 1.0);
  EXPECT_DOUBLE_EQ(in.loads[1].components[1](0.5, 0, 0, 0), -3.0);

  ASSERT_EQ(in.contact.size(), 2u);
  EXPECT_EQ(in.contact[0].name, "interface");
  EXPECT_EQ(in.contact[0].slave, "die_bottom");
  EXPECT_EQ(in.contact[0].master, "block_top");
  EXPECT_EQ(in.contact[0].type, ContactKind::frictional);
  EXPECT_EQ(in.contact[0].friction_coefficient, 0.3);
  EXPECT_EQ(in.contact[0].c_n, 0.0);
  EXPECT_EQ(in.contact[0].integration, ContactIntegration::exact);
  EXPECT_EQ(in.contact[0].collocation_points, 0);
  EXPECT_EQ(in.contact[1].type, ContactKind::tied);
  EXPECT_EQ(in.contact[1].master, "id_7");
  EXPECT_EQ(in.contact[1].c_n, 100.0);
  EXPECT_EQ(in.contact[1].c_t, 2.5);
  EXPECT_EQ(in.contact[1].integration, ContactIntegration::collocation);
  EXPECT_EQ(in.contact[1].collocation_points, 4);

  EXPECT_EQ(in.time.end, 2.0);
  EXPECT_EQ(in.time.steps, 10);
  EXPECT_TRUE(in.time.adaptive);
  EXPECT_EQ(in.time.max_step_size, 0.5);

  EXPECT_EQ(in.solver.newton.nox.get<std::string>("Nonlinear Solver"), "Line Search Based");
  EXPECT_EQ(in.solver.newton.max_iterations, 30);
  EXPECT_EQ(in.solver.newton.relative_tolerance, 1e-8);
  EXPECT_EQ(in.solver.linear.type, LinearSolverType::amesos2);
  EXPECT_EQ(in.solver.linear.where, path + ": grout/solver/Linear Solver");

  EXPECT_EQ(in.output.file, dir + "/out/patch.e");
  EXPECT_EQ(in.output.summary, "/tmp/patch_summary.csv");  // absolute paths stay
}

TEST(InputRead, MinimalInputGetsDefaults) {
  const std::string path = write_file("case.yaml", minimal);
  const Input in = read_input(path);
  const std::string dir = test_dir.string();
  EXPECT_EQ(in.mesh_file, dir + "/mesh.exo");
  EXPECT_EQ(in.model.plane, PlaneKind::strain);
  EXPECT_EQ(in.model.strain, StrainKind::small);
  ASSERT_EQ(in.materials.size(), 1u);
  EXPECT_EQ(in.materials[0].density, 0.0);
  EXPECT_TRUE(in.dirichlet.empty());
  EXPECT_TRUE(in.loads.empty());
  EXPECT_TRUE(in.contact.empty());
  EXPECT_EQ(in.time.end, 1.0);
  EXPECT_EQ(in.time.steps, 1);
  EXPECT_FALSE(in.time.adaptive);
  EXPECT_EQ(in.solver.newton.max_iterations, 25);
  EXPECT_EQ(in.solver.linear.type, LinearSolverType::automatic);
  EXPECT_EQ(in.solver.newton.nox.numParams(), 0);
  EXPECT_EQ(in.solver.linear.muelu.numParams(), 0);
  EXPECT_EQ(in.output.file, dir + "/case.e");
  EXPECT_EQ(in.output.summary, dir + "/case.csv");
}

TEST(InputRead, SelfContactNamesOneSideSetForBothSides) {
  const std::string path = write_file("self.yaml", minimal + R"yaml(  contact:
    fold: {self: inner, type: frictionless}
    pair: {slave: a, master: b, type: frictionless}
)yaml");
  const Input in = read_input(path);
  ASSERT_EQ(in.contact.size(), 2u);
  EXPECT_TRUE(in.contact[0].self);
  EXPECT_EQ(in.contact[0].slave, "inner");
  EXPECT_EQ(in.contact[0].master, "inner");
  EXPECT_FALSE(in.contact[1].self);
}

TEST(InputErrors, SelfContactKeys) {
  expect_bad_input("self_and_slave", minimal + R"yaml(  contact:
    pair: {self: a, slave: a, type: frictionless}
)yaml",
                   {"grout/contact/pair/slave: not with 'self'"});
  expect_bad_input("self_and_master", minimal + R"yaml(  contact:
    pair: {self: a, master: b, type: frictionless}
)yaml",
                   {"grout/contact/pair/master: not with 'self'"});
  expect_bad_input("no_sides", minimal + R"yaml(  contact:
    pair: {type: frictionless}
)yaml",
                   {"grout/contact/pair/slave: missing required key (or 'self'"});
  expect_bad_input("no_master", minimal + R"yaml(  contact:
    pair: {slave: a, type: frictionless}
)yaml",
                   {"grout/contact/pair/master: missing required key"});
  expect_bad_input("self_tied", minimal + R"yaml(  contact:
    pair: {self: a, type: tied}
)yaml",
                   {"grout/contact/pair/type: self-contact cannot be tied"});
}

TEST(InputRead, PathsRelativeToTheWorkingDirectoryStayRelative) {
  write_file("relative.yaml", replaced(minimal, "mesh.exo", "../meshes/./m.exo"));
  const std::filesystem::path cwd = std::filesystem::current_path();
  std::filesystem::current_path(test_dir);
  const Input in = read_input("relative.yaml");
  std::filesystem::current_path(cwd);
  EXPECT_EQ(in.directory, "");
  EXPECT_EQ(in.mesh_file, "../meshes/m.exo");
  EXPECT_EQ(in.output.file, "relative.e");
  EXPECT_EQ(in.output.summary, "relative.csv");
}

TEST(InputRead, ThreeDimensionalTractionAndEmptySummary) {
  const std::string text = replaced(minimal, "dimension: 2", "dimension: 3") + R"yaml(
  dirichlet:
    fix_z: {node_set: bottom, component: z, value: "-0.01*t*z"}
  loads:
    shear: {side_set: top, type: traction, components: {x: 1, y: 0, z: "-t"}}
  output: {summary: ""}
)yaml";
  const Input in = read_input(write_file("three_d.yaml", text));
  EXPECT_EQ(in.model.dimension, 3);
  EXPECT_EQ(in.dirichlet[0].component, 2);
  EXPECT_DOUBLE_EQ(in.dirichlet[0].value(2, 0, 0, 3), -0.06);
  ASSERT_EQ(in.loads[0].components.size(), 3u);
  EXPECT_DOUBLE_EQ(in.loads[0].components[2](0.25, 0, 0, 0), -0.25);
  EXPECT_EQ(in.output.summary, "");
}

// output/parallel: single by default, per_rank when asked; a near miss is named.
TEST(InputRead, OutputParallelLayout) {
  EXPECT_EQ(read_input(write_file("single.yaml", minimal)).output.parallel, OutputParallel::single);
  const Input in =
      read_input(write_file("per_rank.yaml", minimal + "  output: {parallel: per_rank}\n"));
  EXPECT_EQ(in.output.parallel, OutputParallel::per_rank);
  expect_bad_input("per_rnak", minimal + "  output: {parallel: per_rnak}\n",
                   {"grout/output/parallel: unknown output layout 'per_rnak'",
                    "expected one of: single, per_rank", "did you mean 'per_rank'?"});
}

TEST(InputExpression, EvaluatesCopiesAndDefaults) {
  const Expression zero;
  EXPECT_EQ(zero.text(), "0");
  EXPECT_EQ(zero(1, 2, 3, 4), 0.0);

  const Expression e("10.0*t + x - y*z + sin(pi/2) + _pi - pi", "here");  // _pi == pi
  EXPECT_DOUBLE_EQ(e(0.5, 1, 2, 3), 5.0 + 1 - 6 + 1);

  Expression copy = e;  // parses again: its variables are its own
  Expression assigned;
  assigned = copy;
  EXPECT_DOUBLE_EQ(copy(1, 0, 0, 0), 11.0);
  EXPECT_DOUBLE_EQ(assigned(0, 2, 0, 0), 3.0);
  EXPECT_DOUBLE_EQ(e(0.5, 1, 2, 3), 1.0);
  EXPECT_EQ(assigned.text(), e.text());

  std::vector<Expression> many(3, Expression("t*t", "here"));
  many.push_back(Expression("x", "here"));
  EXPECT_DOUBLE_EQ(many[1](3, 0, 0, 0), 9.0);
  EXPECT_DOUBLE_EQ(many[3](3, 4, 0, 0), 4.0);
}

TEST(InputExpression, BadTextNamesWhereAndText) {
  expect_input_error([] { Expression("10*t +", "case.yaml: grout/loads/top/value"); },
                     {"case.yaml: grout/loads/top/value: cannot parse expression '10*t +': ",
                      "Unexpected end of expression"});
  expect_input_error([] { Expression("q*t", "f.yaml: k"); },
                     {"f.yaml: k: cannot parse expression 'q*t'", "\"q\"", "variables: t, x"});
  expect_input_error([] { Expression("", "f.yaml: k"); }, {"f.yaml: k: cannot parse", "empty"});
  expect_input_error([] { Expression("1, 2", "f.yaml: k"); }, {"expected one value"});
  expect_input_error([] { Expression("sin(x", "f.yaml: k"); }, {"'sin(x'"});
}

TEST(InputExpression, NonFiniteValuesAndAssignmentsNameTheKey) {
  const std::string key = "f.yaml: grout/dirichlet/left_x/value";
  expect_input_error([&] { Expression("0/0", key); },
                     {key + ": expression '0/0' is not a number (NaN)"});
  expect_input_error([&] { Expression("sqrt(-1)", key); }, {"'sqrt(-1)' is not a number"});
  expect_input_error([&] { Expression("10/0", key); }, {key + ": expression '10/0' is +infinity"});
  expect_input_error([&] { Expression("-1e308*10", key); }, {"is -infinity"});
  // Not finite only at some points: found where it is evaluated, with the point.
  const Expression log_x("log(x)*t", key);
  EXPECT_DOUBLE_EQ(log_x(1.0, 1.0, 0.0, 0.0), 0.0);
  expect_input_error(
      [&] { log_x(0.5, 0.0, 2.0, 0.0); },
      {key + ": expression 'log(x)*t' is -infinity at t = 0.5, x = 0, y = 2, z = 0"});
  const Expression one_over_t("1/t", key);  // at t = 0 only: never evaluated there by a run
  EXPECT_DOUBLE_EQ(one_over_t(0.5, 0.0, 0.0, 0.0), 2.0);
  // Assignments are rejected; comparisons stay.
  expect_input_error([&] { Expression("t=5", key); },
                     {key + ": cannot parse expression 't=5': assignment '=' at position 2"});
  expect_input_error([&] { Expression("x+=1", key); }, {"assignment"});
  EXPECT_DOUBLE_EQ(Expression("(t>=1)*2 + (t==0.5) + (t<=0)", key)(1.0, 0, 0, 0), 2.0);
  EXPECT_DOUBLE_EQ(Expression("t!=1", key)(0.0, 0, 0, 0), 1.0);
}

TEST(InputErrors, SolverSublistsAndIntegerRange) {
  expect_bad_input("misspelt_solver", minimal + "  solver:\n    Newtn: {max_iterations: 3}\n",
                   {"grout/solver: unknown key 'Newtn' (expected one of: Newton, NOX, Linear "
                    "Solver); did you mean 'Newton'?"});
  expect_bad_input("huge_steps", minimal + "  time: {steps: 99999999999}\n",
                   {"grout/time/steps: ", "integer '99999999999' (out of range"});
  try {
    read_input(write_file("huge_steps.yaml", minimal + "  time: {steps: 99999999999}\n"));
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find("a list"), std::string::npos) << e.what();
  }
}

TEST(InputErrors, UnknownKeysAtEveryLevel) {
  expect_bad_input("top_key", minimal + "  mesh_file: a.exo\n",
                   {"grout: unknown key 'mesh_file'", "expected one of: mesh, model, materials"});
  expect_bad_input("model_key", replaced(minimal, "dimension: 2", "dimension: 2, dim: 2"),
                   {"grout/model: unknown key 'dim'", "dimension, plane, strain"});
  expect_bad_input(
      "material_key", replaced(minimal, "youngs_modulus:", "youngs_modulos:"),
      {"grout/materials/steel: unknown key 'youngs_modulos' (expected one of: block, law, "
       "youngs_modulus, poissons_ratio, density)",
       "did you mean 'youngs_modulus'?"});
  expect_bad_input("component_key", minimal + R"yaml(  loads:
    top: {side_set: top, type: traction, components: {x: 1, y: 2, w: 3}}
)yaml",
                   {"grout/loads/top/components: unknown key 'w' (expected one of: x, y)"});
  expect_bad_input("contact_key", minimal + R"yaml(  contact:
    pair: {slave: a, master: b, type: tied, mu: 0.2}
)yaml",
                   {"grout/contact/pair: unknown key 'mu'"});
  expect_bad_input("not_grout", "solver:\n  a: 1\n", {"single key 'grout:'", "'solver'"});
  expect_bad_input("two_top_keys", minimal + "output:\n  file: a.e\n",
                   {"single key 'grout:'", "'grout', 'output'"});
}

TEST(InputErrors, WrongTypes) {
  expect_bad_input("dimension_string", replaced(minimal, "dimension: 2", "dimension: two"),
                   {"grout/model/dimension: expected an integer, got a string 'two'"});
  expect_bad_input("modulus_string",
                   replaced(minimal, "youngs_modulus: 200", "youngs_modulus: stiff"),
                   {"grout/materials/steel/youngs_modulus: expected a number > 0, got a "
                    "string 'stiff'"});
  expect_bad_input("steps_double", minimal + "  time: {steps: 2.5}\n",
                   {"grout/time/steps: expected an integer >= 1, got a number '2.5'"});
  expect_bad_input("material_scalar", replaced(minimal, "steel: {", "steel: 3\n    iron: {"),
                   {"grout/materials/steel: expected a section of keys, got an integer '3'"});
  expect_bad_input("mesh_scalar", replaced(minimal, "mesh: {file: mesh.exo}", "mesh: mesh.exo"),
                   {"grout/mesh: expected a section of keys, got a string 'mesh.exo'"});
  expect_bad_input("value_bool", minimal + R"yaml(  dirichlet:
    fix: {node_set: left, component: x, value: true}
)yaml",
                   {"grout/dirichlet/fix/value: expected an expression", "a boolean 'true'"});
  expect_bad_input("block_empty", replaced(minimal, "block: body", "block: \"\""),
                   {"grout/materials/steel/block: expected a non-empty string"});
}

TEST(InputErrors, MissingRequiredKeys) {
  expect_bad_input("no_dimension", replaced(minimal, "{dimension: 2}", "{plane: strain}"),
                   {"grout/model/dimension: missing required key"});
  expect_bad_input("no_mesh", replaced(minimal, "  mesh: {file: mesh.exo}\n", ""),
                   {"grout/mesh: missing required key"});
  expect_bad_input("no_block", replaced(minimal, "block: body, ", ""),
                   {"grout/materials/steel/block: missing required key"});
  expect_bad_input("no_materials", replaced(minimal, minimal.substr(minimal.find("    steel")), ""),
                   {"grout/materials: expected at least one material"});
  expect_bad_input("no_friction", minimal + R"yaml(  contact:
    pair: {slave: a, master: b, type: frictional}
)yaml",
                   {"grout/contact/pair/friction_coefficient: missing required key"});
  expect_bad_input("no_pressure", minimal + R"yaml(  loads:
    top: {side_set: top, type: pressure}
)yaml",
                   {"grout/loads/top/value: missing required key"});
  expect_bad_input("no_traction", minimal + R"yaml(  loads:
    top: {side_set: top, type: traction, value: 3}
)yaml",
                   {"grout/loads/top/components: missing required key"});
  expect_bad_input("no_z_traction",
                   replaced(minimal, "dimension: 2", "dimension: 3") + R"yaml(  loads:
    top: {side_set: top, type: traction, components: {x: 1, y: 2}}
)yaml",
                   {"grout/loads/top/components/z: missing required key"});
}

TEST(InputErrors, UnknownChoices) {
  expect_bad_input("law", replaced(minimal, "law: linear_elastic", "law: plastic"),
                   {"grout/materials/steel/law: unknown material law 'plastic' (expected one "
                    "of: linear_elastic, neo_hookean)"});
  expect_bad_input("plane", replaced(minimal, "dimension: 2", "dimension: 2, plane: strains"),
                   {"grout/model/plane: unknown plane kind 'strains' (expected one of: strain, "
                    "stress, axisymmetric)"});
  expect_bad_input("axisymmetric_3d",
                   replaced(minimal, "dimension: 2", "dimension: 3, plane: axisymmetric"),
                   {"grout/model/plane: axisymmetric needs dimension: 2"});
  expect_bad_input("contact_type", minimal + R"yaml(  contact:
    pair: {slave: a, master: b, type: glued}
)yaml",
                   {"grout/contact/pair/type: unknown contact type 'glued'"});
  expect_bad_input("z_in_2d", minimal + R"yaml(  dirichlet:
    fix: {node_set: left, component: z, value: 0}
)yaml",
                   {"grout/dirichlet/fix/component: component z is not allowed in a 2D model"});
  expect_bad_input("mu_frictionless", minimal + R"yaml(  contact:
    pair: {slave: a, master: b, type: frictionless, friction_coefficient: 0.1}
)yaml",
                   {"grout/contact/pair/friction_coefficient: only for type frictional"});
}

TEST(InputErrors, OutOfRangeNumbers) {
  expect_bad_input("modulus_negative",
                   replaced(minimal, "youngs_modulus: 200", "youngs_modulus: -5"),
                   {"grout/materials/steel/youngs_modulus: expected a number > 0, got '-5'"});
  expect_bad_input("poisson_half", replaced(minimal, "poissons_ratio: 0.3", "poissons_ratio: 0.5"),
                   {"grout/materials/steel/poissons_ratio: expected a number in (-1, 0.5), "
                    "got '0.5'"});
  expect_bad_input("density_negative", replaced(minimal, "0.3}", "0.3, density: -1.5}"),
                   {"grout/materials/steel/density: expected a number >= 0, got '-1.5'"});
  expect_bad_input("dimension_four", replaced(minimal, "dimension: 2", "dimension: 4"),
                   {"grout/model/dimension: expected 2 or 3, got '4'"});
  expect_bad_input("max_step_fixed", minimal + "  time: {max_step_size: 0.1}\n",
                   {"grout/time/max_step_size: only with stepping: adaptive"});
  expect_bad_input("end_zero", minimal + "  time: {end: 0}\n",
                   {"grout/time/end: expected a number > 0, got '0'"});
  expect_bad_input("steps_zero", minimal + "  time: {steps: 0}\n",
                   {"grout/time/steps: expected an integer >= 1, got an integer '0'"});
  expect_bad_input("mu_negative", minimal + R"yaml(  contact:
    pair: {slave: a, master: b, type: frictional, friction_coefficient: -0.2}
)yaml",
                   {"grout/contact/pair/friction_coefficient: expected a number >= 0, got '-0.2'"});
  expect_bad_input("c_n_zero", minimal + R"yaml(  contact:
    pair: {slave: a, master: b, type: tied, c_n: 0}
)yaml",
                   {"grout/contact/pair/c_n: expected a number > 0, got '0'"});
}

TEST(InputErrors, BadExpressions) {
  expect_bad_input("expression_syntax", minimal + R"yaml(  loads:
    top: {side_set: top, type: pressure, value: "10*t +"}
)yaml",
                   {"grout/loads/top/value: cannot parse expression '10*t +'"});
  expect_bad_input("expression_variable", minimal + R"yaml(  dirichlet:
    fix: {node_set: left, component: x, value: "s*t"}
)yaml",
                   {"grout/dirichlet/fix/value: cannot parse expression 's*t'", "\"s\""});
}

TEST(InputErrors, FileAndYamlErrors) {
  const std::string missing = (test_dir / "no_such_case.yaml").string();
  expect_input_error([&] { read_input(missing); }, {"no_such_case.yaml: cannot read input file"});
  expect_input_error([&] { read_input(test_dir.string()); }, {"cannot read input file"});

  const std::string unclosed = replaced(minimal, "{file: mesh.exo}", "{file: mesh.exo");
  expect_bad_input("yaml_syntax", unclosed, {"YAML error: line 3, column 3: expected one of"});
  expect_bad_input("yaml_duplicate", minimal + "  model: {dimension: 3}\n",
                   {"YAML error: line 7, column 1: duplicate key 'model'"});
  expect_bad_input("yaml_tabs", minimal + "\tmesh: 3\n", {"YAML error", "Indentation"});
  expect_bad_input("yaml_empty", "", {"single key 'grout:' (found: none)"});
  try {
    read_input(write_file("yaml_noise.yaml", unclosed));
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find("Throw"), std::string::npos) << message;
    EXPECT_EQ(message.find(".cpp"), std::string::npos) << message;
    EXPECT_EQ(message.find("Parser was in state"), std::string::npos) << message;
  }
}

/// A 2D mesh with two blocks, three side sets and two node sets (no geometry needed).
Mesh two_block_mesh() {
  Mesh mesh;
  mesh.file = "mesh.exo";
  mesh.dimension = 2;
  // The die, element 1 (nodes 5-8), on top of the block, element 2 (nodes 1-4): unit squares.
  mesh.coordinates = {0, 0, 1, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 2, 0, 2};
  mesh.blocks.resize(2);
  mesh.blocks[0].name = "die";
  mesh.blocks[0].id = 1;
  mesh.blocks[0].connectivity = {4, 5, 6, 7};
  mesh.blocks[1].name = "block";
  mesh.blocks[1].id = 2;
  mesh.blocks[1].first_element = 1;
  mesh.blocks[1].connectivity = {0, 1, 2, 3};
  for (ElementBlock& b : mesh.blocks) {
    b.topology = Topology::quad4;
    b.nodes_per_element = 4;
  }
  // (element, Exodus side): quad side 1 is nodes 1-2, side 3 nodes 3-4.
  const std::vector<std::pair<const char*, std::pair<GlobalIndex, int>>> sides = {
      {"die_bottom", {0, 1}}, {"block_top", {1, 3}}, {"top", {0, 3}}};
  for (const auto& [name, side] : sides) {
    mesh.side_sets.emplace_back();
    mesh.side_sets.back().name = name;
    mesh.side_sets.back().id = int(mesh.side_sets.size());
    mesh.side_sets.back().elements = {side.first};
    mesh.side_sets.back().sides = {side.second};
  }
  const std::vector<std::pair<const char*, std::vector<GlobalIndex>>> nodes = {
      {"bottom", {0, 1}}, {"left", {0, 3, 4, 7}}};
  for (const auto& [name, list] : nodes) {
    mesh.node_sets.emplace_back();
    mesh.node_sets.back().name = name;
    mesh.node_sets.back().id = int(mesh.node_sets.size());
    mesh.node_sets.back().nodes = list;
  }
  return mesh;
}

const std::string on_mesh = R"yaml(grout:
  mesh: {file: mesh.exo}
  model: {dimension: 2}
  materials:
    die:   {block: die,  law: linear_elastic, youngs_modulus: 1000, poissons_ratio: 0.4}
    block: {block: id_2, law: linear_elastic, youngs_modulus: 1000, poissons_ratio: 0.4}
  dirichlet:
    left_x: {node_set: left, component: x, value: 0}
  loads:
    top: {side_set: top, type: traction, components: {x: 0, y: "-t"}}
  contact:
    interface: {slave: die_bottom, master: block_top, type: frictionless}
)yaml";

void expect_mesh_error(const std::string& name, const std::string& text, const Mesh& mesh,
                       std::vector<std::string> parts) {
  SCOPED_TRACE(name);
  const Input input = read_input(write_file(name + ".yaml", text));
  parts.push_back(name + ".yaml: ");
  expect_input_error([&] { check_input_against_mesh(input, mesh); }, parts);
}

TEST(InputMeshCheck, ValidInputPasses) {
  const Input input = read_input(write_file("on_mesh.yaml", on_mesh));
  EXPECT_NO_THROW(check_input_against_mesh(input, two_block_mesh()));
}

TEST(InputMeshCheck, MissingEntitiesAreNamed) {
  const Mesh mesh = two_block_mesh();
  expect_mesh_error("no_node_set", replaced(on_mesh, "node_set: left", "node_set: lft"), mesh,
                    {"grout/dirichlet/left_x/node_set: no node set 'lft' in mesh 'mesh.exo' (it "
                     "has: bottom, left)"});
  expect_mesh_error("no_side_set", replaced(on_mesh, "side_set: top", "side_set: id_9"), mesh,
                    {"grout/loads/top/side_set: no side set 'id_9' in mesh 'mesh.exo'",
                     "die_bottom, block_top, top"});
  expect_mesh_error("no_master", replaced(on_mesh, "master: block_top", "master: blk_top"), mesh,
                    {"grout/contact/interface/master: no side set 'blk_top'"});
  expect_mesh_error("no_slave", replaced(on_mesh, "slave: die_bottom", "slave: die_bot"), mesh,
                    {"grout/contact/interface/slave: no side set 'die_bot'"});
  expect_mesh_error("no_self",
                    replaced(on_mesh, "slave: die_bottom, master: block_top", "self: die_bot"),
                    mesh, {"grout/contact/interface/self: no side set 'die_bot'"});
  expect_mesh_error("no_block", replaced(on_mesh, "block: id_2", "block: blok"), mesh,
                    {"grout/materials/block/block: no element block 'blok' in mesh 'mesh.exo' "
                     "(it has: die, block)"});
}

// A set that exists but cannot hold its role: an empty load, contact or Dirichlet set, or a
// load or contact side set with a face inside the mesh (one check for every such set).
TEST(InputMeshCheck, SetsHoldWhatTheirRoleNeeds) {
  const auto emptied = [](const std::string& name) {
    Mesh mesh = two_block_mesh();
    for (SideSet& set : mesh.side_sets) {
      if (set.name == name) set.elements.clear(), set.sides.clear();
    }
    for (NodeSet& set : mesh.node_sets) {
      if (set.name == name) set.nodes.clear();
    }
    return mesh;
  };
  expect_mesh_error("empty_load", on_mesh, emptied("top"),
                    {"grout/loads/top/side_set: side set 'top' in mesh 'mesh.exo' is empty (it "
                     "has no faces)"});
  expect_mesh_error("empty_slave", on_mesh, emptied("die_bottom"),
                    {"grout/contact/interface/slave: side set 'die_bottom' in mesh 'mesh.exo' is "
                     "empty (it has no faces)"});
  expect_mesh_error("empty_master", on_mesh, emptied("block_top"),
                    {"grout/contact/interface/master: side set 'block_top' in mesh 'mesh.exo' is "
                     "empty"});
  expect_mesh_error("empty_dirichlet", on_mesh, emptied("left"),
                    {"grout/dirichlet/left_x/node_set: node set 'left' in mesh 'mesh.exo' is "
                     "empty (it has no nodes)"});

  // The die glued onto the block (it shares the block's top nodes 3 and 4): the die's bottom
  // face is then inside one body.
  Mesh glued = two_block_mesh();
  glued.blocks[0].connectivity = {3, 2, 6, 7};
  const std::string no_contact = replaced(
      on_mesh,
      "  contact:\n    interface: {slave: die_bottom, master: block_top, type: frictionless}\n",
      "");
  expect_mesh_error("interior_load", replaced(no_contact, "side_set: top", "side_set: die_bottom"),
                    glued,
                    {"grout/loads/top/side_set: side set 'die_bottom' in mesh 'mesh.exo' holds "
                     "side 1 of element 1, an interior face (element 2 has it too): a load or "
                     "contact side set must lie on the boundary"});
  expect_mesh_error("interior_contact", on_mesh, glued,
                    {"grout/contact/interface/slave: side set 'die_bottom' in mesh 'mesh.exo' "
                     "holds side 1 of element 1, an interior face (element 2 has it too)"});
  // A side number that is no face of the element.
  Mesh bad_side = two_block_mesh();
  bad_side.side_sets[2].sides = {7};
  expect_mesh_error("bad_side", on_mesh, bad_side,
                    {"grout/loads/top/side_set: side set 'top' has side 7 of element 1, which is "
                     "not a face of an element of mesh 'mesh.exo'"});
}

// One rank's part of a distributed mesh (check_input_against_mesh with MeshPartNumbers): the
// two-block mesh as a part of a larger file, file nodes 11-18 and elements 21-22, this rank (0)
// owning the die (element 21) and holding the block as a ghost. A set is empty when the file's
// is, whatever the part holds; messages give the file's numbers; a ghost's faces are its
// owner's to check.
TEST(InputMeshCheck, DistributedPartChecksOwnedEntitiesInFileNumbers) {
  const std::vector<GlobalIndex> node_gid = {10, 11, 12, 13, 14, 15, 16, 17},
                                 element_gid = {20, 21};
  const std::vector<int> owner = {0, 1};
  std::vector<GlobalIndex> side_sizes = {1, 1, 1}, node_sizes = {2, 4};
  const MeshPartNumbers part{node_gid, element_gid, owner, 0, side_sizes, node_sizes, 1.0};
  const std::string no_contact = replaced(
      on_mesh,
      "  contact:\n    interface: {slave: die_bottom, master: block_top, type: frictionless}\n",
      "");
  const auto check = [&](const std::string& name, const std::string& text, const Mesh& mesh) {
    const Input input = read_input(write_file(name + ".yaml", text));
    check_input_against_mesh(input, mesh, part);
  };
  // Sets with no entry on this rank but entries in the file: no error (the replicated check
  // of the same local mesh reports them empty).
  Mesh part_mesh = two_block_mesh();
  part_mesh.side_sets[2].elements.clear(), part_mesh.side_sets[2].sides.clear();
  part_mesh.node_sets[1].nodes.clear();
  EXPECT_NO_THROW(check("part_sets", no_contact, part_mesh));
  // Empty in the file: the replicated message.
  side_sizes[2] = 0;
  expect_input_error([&] { check("file_empty_side_set", no_contact, part_mesh); },
                     {"file_empty_side_set.yaml: grout/loads/top/side_set: side set 'top' in mesh "
                      "'mesh.exo' is empty (it has no faces)"});
  side_sizes[2] = 1, node_sizes[1] = 0;
  expect_input_error([&] { check("file_empty_node_set", no_contact, part_mesh); },
                     {"file_empty_node_set.yaml: grout/dirichlet/left_x/node_set: node set 'left' "
                      "in mesh 'mesh.exo' is empty (it has no nodes)"});
  node_sizes[1] = 4;
  // An interior face of the owned die, in file numbers; the same face through the ghost block
  // (block_top) is not this rank's to report.
  Mesh glued = two_block_mesh();
  glued.blocks[0].connectivity = {3, 2, 6, 7};
  expect_input_error(
      [&] {
        check("part_interior", replaced(no_contact, "side_set: top", "side_set: die_bottom"),
              glued);
      },
      {"part_interior.yaml: grout/loads/top/side_set: side set 'die_bottom' in mesh 'mesh.exo' "
       "holds side 1 of element 21, an interior face (element 22 has it too)"});
  EXPECT_NO_THROW(check("part_ghost_interior",
                        replaced(no_contact, "side_set: top", "side_set: block_top"), glued));
}

TEST(InputMeshCheck, OneMaterialPerBlock) {
  const Mesh mesh = two_block_mesh();
  const std::string one = replaced(on_mesh,
                                   "    block: {block: id_2, law: linear_elastic, "
                                   "youngs_modulus: 1000, poissons_ratio: 0.4}\n",
                                   "");
  expect_mesh_error("block_without_material", one, mesh,
                    {"grout/materials: element block 'block' of mesh 'mesh.exo' has no material"});
  expect_mesh_error("block_two_materials", replaced(on_mesh, "block: id_2", "block: id_1"), mesh,
                    {"grout/materials/block/block: element block 'die' already has material "
                     "'die'"});
}

TEST(InputMeshCheck, DimensionsMustAgree) {
  Mesh mesh3 = two_block_mesh();  // its 2D elements and sets dropped: a 3D mesh of no elements
  mesh3.dimension = 3;
  mesh3.coordinates.clear();
  for (ElementBlock& b : mesh3.blocks) b.connectivity.clear();
  mesh3.side_sets.clear();
  mesh3.node_sets.clear();
  expect_mesh_error("dimension_mismatch", on_mesh, mesh3,
                    {"grout/model/dimension: the model is 2D but mesh 'mesh.exo' is 3D"});

  const Mesh mesh = two_block_mesh();
  Input input = read_input(write_file("hand_edited.yaml", on_mesh));
  input.dirichlet[0].component = 2;
  expect_input_error([&] { check_input_against_mesh(input, mesh); },
                     {"hand_edited.yaml: grout/dirichlet/left_x/component: component z is not "
                      "allowed in a 2D model"});
  input = read_input(write_file("hand_edited.yaml", on_mesh));
  input.loads[0].components.pop_back();
  expect_input_error([&] { check_input_against_mesh(input, mesh); },
                     {"hand_edited.yaml: grout/loads/top/components: expected 2 traction "
                      "components in a 2D model, got 1"});
}

}  // namespace
}  // namespace grout

namespace grout {
namespace {

const std::string dynamic_input = R"yaml(grout:
  mesh: {file: m.exo}
  model: {dimension: 2}
  materials:
    steel: {block: b, law: linear_elastic, youngs_modulus: 1.0, poissons_ratio: 0.3, density: 7.8}
  gravity: {y: -9.81}
  initial_velocity:
    spin: {block: b, x: "-y", y: "x"}
  dynamics: {scheme: generalized_alpha, rho_infinity: 0.8, mass: lumped}
)yaml";

// docs/input.md, contact `start_gap`: 0.05 by default, 0 with dynamics (the mass matrix holds
// a body held only by contact), a value given is kept either way.
TEST(InputDynamics, ProximityStartIsOffByDefaultInDynamics) {
  const std::string pair = "  contact:\n    c: {slave: s, master: m, type: frictionless}\n";
  const std::string given =
      "  contact:\n    c: {slave: s, master: m, type: frictionless, start_gap: 0.2}\n";
  EXPECT_EQ(read_input(write_file("gap_static.yaml", minimal + pair)).contact.at(0).start_gap,
            0.05);
  EXPECT_EQ(
      read_input(write_file("gap_dynamic.yaml", dynamic_input + pair)).contact.at(0).start_gap,
      0.0);
  EXPECT_EQ(read_input(write_file("gap_given.yaml", dynamic_input + given)).contact.at(0).start_gap,
            0.2);
}

TEST(InputDynamics, ReadsSchemeGravityAndInitialVelocity) {
  const Input input = read_input(write_file("dynamics.yaml", dynamic_input));
  EXPECT_TRUE(input.dynamics.enabled);
  EXPECT_EQ(input.dynamics.scheme, DynamicsScheme::generalized_alpha);
  EXPECT_DOUBLE_EQ(input.dynamics.rho_infinity, 0.8);
  EXPECT_EQ(input.dynamics.mass, MassKind::lumped);
  EXPECT_EQ(input.dynamics.contact_treatment, ContactTreatment::stabilized);  // default
  EXPECT_DOUBLE_EQ(input.gravity[1], -9.81);
  ASSERT_EQ(input.initial_velocity.size(), 1u);
  EXPECT_EQ(input.initial_velocity[0].block, "b");
  EXPECT_DOUBLE_EQ(input.initial_velocity[0].components[0](0.0, 2.0, 3.0, 0.0), -3.0);
  EXPECT_FALSE(read_input(write_file("static.yaml", minimal)).dynamics.enabled);
  const Input updated = read_input(write_file(
      "velocity_update.yaml",
      replaced(dynamic_input, "mass: lumped", "mass: lumped, contact_treatment: velocity_update")));
  EXPECT_EQ(updated.dynamics.contact_treatment, ContactTreatment::velocity_update_tangential);
  const Input impact = read_input(
      write_file("sliding_impact.yaml",
                 replaced(dynamic_input, "mass: lumped",
                          "mass: lumped, contact_treatment: velocity_update, sliding: impact")));
  EXPECT_EQ(impact.dynamics.contact_treatment, ContactTreatment::velocity_update_impact);
  const Input balanced = read_input(
      write_file("sliding_balanced.yaml",
                 replaced(dynamic_input, "mass: lumped",
                          "mass: lumped, contact_treatment: velocity_update, sliding: balanced")));
  EXPECT_EQ(balanced.dynamics.contact_treatment, ContactTreatment::velocity_update_balanced);
  const Input standard = read_input(write_file(
      "standard.yaml",
      replaced(dynamic_input, "mass: lumped", "mass: lumped, contact_treatment: standard")));
  const Input stabilized = read_input(write_file(
      "stabilized.yaml",
      replaced(dynamic_input, "mass: lumped", "mass: lumped, contact_treatment: stabilized")));
  EXPECT_EQ(stabilized.dynamics.contact_treatment, ContactTreatment::stabilized);
  EXPECT_EQ(standard.dynamics.contact_treatment, ContactTreatment::standard);
  const Input energy_momentum = read_input(write_file(
      "energy_momentum.yaml",
      replaced(dynamic_input, "generalized_alpha, rho_infinity: 0.8", "energy_momentum")));
  EXPECT_EQ(energy_momentum.dynamics.scheme, grout::DynamicsScheme::energy_momentum);
}

TEST(InputDynamics, ErrorsNameTheKey) {
  expect_bad_input("predictor_dynamics", dynamic_input + "  time: {predictor: extrapolated}\n",
                   {"grout/time/predictor: extrapolated is for quasi-static analyses"});
  expect_bad_input("predictor_unknown", minimal + "  time: {predictor: quadratic}\n",
                   {"grout/time/predictor"});
  EXPECT_TRUE(
      read_input(write_file("predictor.yaml", minimal + "  time: {predictor: extrapolated}\n"))
          .time.extrapolate);
  EXPECT_FALSE(read_input(write_file("predictor_default.yaml", minimal)).time.extrapolate);
  expect_bad_input("no_density", replaced(dynamic_input, ", density: 7.8", ""),
                   {"grout/materials/steel/density: required > 0"});
  expect_bad_input("gravity_quasi_static",
                   replaced(dynamic_input,
                            "  dynamics: {scheme: generalized_alpha, rho_infinity: "
                            "0.8, mass: lumped}\n",
                            ""),
                   {"grout/initial_velocity: needs a 'dynamics' section"});
  expect_bad_input("newmark_rho", replaced(dynamic_input, "generalized_alpha", "newmark"),
                   {"grout/dynamics/rho_infinity: only for the schemes"});
  expect_bad_input("energy_momentum_rho",
                   replaced(dynamic_input, "generalized_alpha", "energy_momentum"),
                   {"grout/dynamics/rho_infinity: only for the schemes"});
  expect_bad_input("energy_momentum_gamma",
                   replaced(dynamic_input, "generalized_alpha, rho_infinity: 0.8",
                            "energy_momentum, gamma: 0.6"),
                   {"grout/dynamics/gamma: only for scheme newmark (the energy_momentum scheme "
                    "sets it)"});
  expect_bad_input(
      "hht_beta", replaced(dynamic_input, "generalized_alpha, rho_infinity: 0.8", "hht, beta: 0.3"),
      {"grout/dynamics/beta: only for scheme newmark"});
  expect_bad_input(
      "hht_rho",
      replaced(dynamic_input, "generalized_alpha, rho_infinity: 0.8", "hht, rho_infinity: 0.3"),
      {"grout/dynamics/rho_infinity: must be >= 0.5 for hht"});
  expect_bad_input("bad_scheme", replaced(dynamic_input, "generalized_alpha", "verlet"),
                   {"grout/dynamics/scheme", "verlet"});
  expect_bad_input("unstable_newmark",
                   replaced(dynamic_input, "generalized_alpha, rho_infinity: 0.8",
                            "newmark, gamma: 0.9, beta: 0.25"),
                   {"grout/dynamics/beta: must be >= (gamma + 1/2)^2 / 4"});
  expect_bad_input(
      "balanced_friction",
      replaced(dynamic_input, "mass: lumped",
               "mass: lumped, contact_treatment: velocity_update, sliding: balanced") +
          "  contact:\n    rub: {slave: s, master: m, type: frictional, friction_coefficient: "
          "0.3}\n",
      {"grout/dynamics/sliding: balanced is for frictionless and tied contact",
       "'rub' is frictional"});
  expect_bad_input("sliding_stabilized",
                   replaced(dynamic_input, "mass: lumped", "mass: lumped, sliding: impact"),
                   {"grout/dynamics/sliding: only with contact_treatment: velocity_update"});
  expect_bad_input("sliding_bad",
                   replaced(dynamic_input, "mass: lumped",
                            "mass: lumped, contact_treatment: velocity_update, sliding: normal"),
                   {"grout/dynamics/sliding", "normal"});
}

}  // namespace
}  // namespace grout
