// Linear solves on 1 and 2 ranks (registered for both): |b − A x| must be small for the
// direct path (Debian's KLU2 is silently wrong on a multi-rank communicator unless the
// system is gathered to one rank, TOOLCHAIN.md) and for Belos + MueLu.

#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>

#include "io/errors.hpp"
#include "nonlinear/linear_solver.hpp"

namespace grout {
namespace {

// SPD tridiagonal (1D Laplacian + shift), distributed contiguously.
Teuchos::RCP<Matrix> tridiagonal(GO n) {
  const auto comm = Tpetra::getDefaultComm();
  const auto map = Teuchos::rcp(new Map(n, 0, comm));
  auto A = Teuchos::rcp(new Matrix(map, 3));
  for (LO i = 0; i < LO(map->getNodeNumElements()); ++i) {
    const GO g = map->getGlobalElement(i);
    std::vector<GO> cols;
    std::vector<double> vals;
    if (g > 0) cols.push_back(g - 1), vals.push_back(-1.0);
    cols.push_back(g), vals.push_back(2.5 + 0.001 * g);
    if (g + 1 < n) cols.push_back(g + 1), vals.push_back(-1.0);
    A->insertGlobalValues(g, Teuchos::ArrayView<const GO>(cols),
                          Teuchos::ArrayView<const double>(vals));
  }
  A->fillComplete();
  return A;
}

double relative_residual(const Matrix& A, const Vector& x, const Vector& b) {
  Vector r(b.getMap());
  A.apply(x, r);
  r.update(1.0, b, -1.0);
  return r.norm2() / b.norm2();
}

void check_solver(const Teuchos::ParameterList& params) {
  const auto A = tridiagonal(200);
  Vector b(A->getRowMap()), x(A->getRowMap());
  b.randomize();
  LinearSolver solver(params, "test");
  const int iterations = solver.solve(A, b, x);
  EXPECT_GE(iterations, 1);
  EXPECT_LT(relative_residual(*A, x, b), 1e-10);
}

TEST(LinearSolver, DirectSolveIsCorrectOnAnyRankCount) {
  Teuchos::ParameterList params;
  params.set("type", "amesos2");
  check_solver(params);
}

TEST(LinearSolver, BelosCgWithMueLuConverges) {
  Teuchos::ParameterList params;
  params.set("type", "belos");
  params.sublist("Belos").set("Solver Type", "CG");
  params.sublist("MueLu").set("verbosity", "none");
  check_solver(params);
}

TEST(LinearSolver, BelosGmresWithMueLuConverges) {
  Teuchos::ParameterList params;
  params.set("type", "belos");
  params.sublist("Belos").set("Solver Type", "GMRES");
  params.sublist("MueLu").set("verbosity", "none");
  check_solver(params);
}

// type: auto (the default) resolves through one threshold per dimension: the direct solver
// below it, the iterative path from it on; the solve reports the type it used.
TEST(LinearSolver, AutoPicksTheDirectSolverForSmallSystems) {
  for (int dim : {2, 3}) {
    const long long n = auto_iterative_threshold(dim);
    EXPECT_EQ(auto_linear_solver_type(n - 1, dim), default_direct_type(dim));
    EXPECT_EQ(auto_linear_solver_type(n, dim), "belos");
  }
  EXPECT_GT(auto_iterative_threshold(2), auto_iterative_threshold(3));
  EXPECT_EQ(default_direct_type(3), "mumps");
  EXPECT_EQ(default_direct_type(2), "amesos2");
  LinearSolver solver(Teuchos::ParameterList(), "test");
  const auto A = tridiagonal(200);
  Vector b(A->getRowMap()), x(A->getRowMap());
  b.randomize();
  EXPECT_EQ(solver.solve(A, b, x), 1);
  EXPECT_EQ(solver.last_type(), default_direct_type(2));  // no coordinates given: 2D
  EXPECT_LT(relative_residual(*A, x, b), 1e-10);
}

TEST(LinearSolver, UnknownTypeIsAnInputError) {
  Teuchos::ParameterList params;
  params.set("type", "superlu");
  try {
    LinearSolver solver(params, "case.yaml: grout/solver/Linear Solver");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("superlu"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("case.yaml"), std::string::npos);
  }
}

}  // namespace
}  // namespace grout
