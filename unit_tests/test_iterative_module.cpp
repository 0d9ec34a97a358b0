// The iterative path (Belos + MueLu) is the module grout_iterative, loaded at the first
// iterative solve (nonlinear/iterative_module.hpp). On 1 and 2 ranks: a process that solves
// directly maps no MueLu, Belos or Xpetra library; a belos solve loads the module (and MueLu
// with it) and converges; a module that cannot be found or loaded is an error naming every path
// tried and dlerror()'s reason. The tests run in this order in one process (gtest's default).

#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "io/errors.hpp"
#include "nonlinear/iterative_module.hpp"
#include "nonlinear/linear_solver.hpp"

namespace grout {
namespace {

// The shared objects this process has mapped whose path contains `name` (/proc/self/maps).
bool mapped(const std::string& name) {
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line))
    if (line.find(name) != std::string::npos) return true;
  return false;
}

// SPD tridiagonal (1D Laplacian + shift), distributed contiguously.
Teuchos::RCP<Matrix> tridiagonal(GO n) {
  const auto map = Teuchos::rcp(new Map(n, 0, Tpetra::getDefaultComm()));
  auto A = Teuchos::rcp(new Matrix(map, 3));
  for (LO i = 0; i < LO(map->getNodeNumElements()); ++i) {
    const GO g = map->getGlobalElement(i);
    std::vector<GO> cols;
    std::vector<double> vals;
    if (g > 0) cols.push_back(g - 1), vals.push_back(-1.0);
    cols.push_back(g), vals.push_back(2.5);
    if (g + 1 < n) cols.push_back(g + 1), vals.push_back(-1.0);
    A->insertGlobalValues(g, Teuchos::ArrayView<const GO>(cols),
                          Teuchos::ArrayView<const double>(vals));
  }
  A->fillComplete();
  return A;
}

double solve_with(const std::string& type) {
  Teuchos::ParameterList params;
  params.set("type", type);
  const auto A = tridiagonal(300);
  Vector b(A->getRowMap()), x(A->getRowMap()), r(A->getRowMap());
  b.putScalar(1.0);
  LinearSolver solver(params, "test", {});
  solver.solve(A, b, x);
  A->apply(x, r);
  r.update(1.0, b, -1.0);
  return r.norm2() / b.norm2();
}

TEST(IterativeModule, DirectSolvesLoadNoIterativeLibrary) {
  EXPECT_LT(solve_with("mumps"), 1e-12);
  EXPECT_LT(solve_with("amesos2"), 1e-12);
  EXPECT_FALSE(iterative_module_loaded());
  for (const char* library :
       {"libgrout_iterative", "libtrilinos_muelu", "libtrilinos_belos", "libtrilinos_xpetra"})
    EXPECT_FALSE(mapped(library)) << library << " is mapped before any iterative solve";
}

TEST(IterativeModule, BelosSolveLoadsTheModule) {
  EXPECT_LT(solve_with("belos"), 1e-10);
  EXPECT_TRUE(iterative_module_loaded());
  EXPECT_TRUE(mapped("libgrout_iterative.so"));
  EXPECT_TRUE(mapped("libtrilinos_muelu"));
}

TEST(IterativeModule, SearchOrderStartsWithTheEnvironment) {
  setenv("GROUT_PLUGIN_DIR", "/nonexistent/plugins", 1);
  const auto directories = iterative_module_directories();
  unsetenv("GROUT_PLUGIN_DIR");
  ASSERT_GE(directories.size(), 2u);
  EXPECT_EQ(directories.front(), "/nonexistent/plugins");
  EXPECT_NE(directories.back().find("/../lib/grout"), std::string::npos);  // beside the exe
}

TEST(IterativeModule, UnloadableModuleIsAnErrorNamingThePaths) {
  // A directory without the module, and one whose module is not a shared object.
  const std::string broken = std::string(GROUT_BINARY_DIR) + "/test_iterative_module_broken_" +
                             std::to_string(Tpetra::getDefaultComm()->getRank());
  std::remove((broken + "/" + iterative_module_file).c_str());
  std::filesystem::create_directories(broken);
  std::ofstream(broken + "/" + iterative_module_file) << "not an ELF file\n";
  try {
    open_iterative_module({"/nonexistent/plugins", broken});
    FAIL() << "expected ExitCodeError";
  } catch (const ExitCodeError& e) {
    EXPECT_EQ(e.exit_code(), exit_code_incomplete_installation);
    const std::string what = e.what();
    EXPECT_NE(what.find("/nonexistent/plugins/libgrout_iterative.so: no such file"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find(broken + "/libgrout_iterative.so: "), std::string::npos) << what;
    EXPECT_NE(what.find("GROUT_PLUGIN_DIR"), std::string::npos) << what;
  }
  std::remove((broken + "/" + iterative_module_file).c_str());
}

}  // namespace
}  // namespace grout
