// The names io/ accepts in the `Belos` and `MueLu` sublists (io/solver_parameters.hpp) against
// the packages themselves, asked through the iterative module: the same names, but for the
// documented exclusions.

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "io/solver_parameters.hpp"
#include "nonlinear/iterative_module.hpp"

namespace grout {
namespace {

std::set<std::string> names_of(const std::vector<input_schema::Key>& keys) {
  std::set<std::string> names;
  for (const input_schema::Key& key : keys) names.insert(key.name);
  return names;
}

TEST(SolverParameters, BelosNamesAreBelosOwn) {
  const std::vector<std::string> belos = create_iterative_solver()->belos_parameter_names();
  std::set<std::string> expected(belos.begin(), belos.end());
  // No YAML value can be an output stream or a status test object; `Solver Type` is Grout's.
  EXPECT_EQ(expected.erase("Output Stream"), 1u);
  EXPECT_EQ(expected.erase("User Status Tests"), 1u);
  expected.insert("Solver Type");
  EXPECT_EQ(names_of(input_schema::belos_keys()), expected);
}

TEST(SolverParameters, MueLuNamesAreMueLuOwn) {
  const std::vector<std::string> muelu = create_iterative_solver()->muelu_parameter_names();
  const std::set<std::string> expected(muelu.begin(), muelu.end());
  EXPECT_EQ(names_of(input_schema::muelu_keys(Teuchos::ParameterList())), expected);
  Teuchos::ParameterList levels;
  levels.sublist("level 2");
  EXPECT_EQ(names_of(input_schema::muelu_keys(levels)).count("level 2"), 1u);
}

}  // namespace
}  // namespace grout
