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

// The values io/ admits for the MueLu names it checks them for are those MueLu lists when it
// refuses a value; "cycle type" has no list in MueLu's message: both values build.
TEST(SolverParameters, MueLuValuesAreMueLuOwn) {
  const auto solver = create_iterative_solver();
  int checked = 0;
  for (const input_schema::Key& key : input_schema::muelu_keys(Teuchos::ParameterList())) {
    if (key.choices.empty()) continue;
    ++checked;
    Teuchos::ParameterList bogus;
    bogus.set(key.name, std::string("zzbogus"));
    const std::string message = solver->muelu_rejects(bogus);
    ASSERT_FALSE(message.empty()) << key.name << ": MueLu accepts any value";
    for (const std::string& value : key.choices) {
      if (key.name == "cycle type") {
        Teuchos::ParameterList list;
        list.set(key.name, value);
        EXPECT_EQ(solver->muelu_rejects(list), "") << key.name << ": " << value;
      } else {
        EXPECT_NE(message.find("\"" + value + "\""), std::string::npos)
            << key.name << ": " << value << " is not in MueLu's list: " << message;
      }
    }
  }
  EXPECT_EQ(checked, 5);
}

}  // namespace
}  // namespace grout
