// Linear solves on 1 and 2 ranks (registered for both): |b − A x| must be small for the
// direct path (Debian's KLU2 is silently wrong on a multi-rank communicator unless the
// system is gathered to one rank, docs/design.md, "Toolchain notes") and for Belos + MueLu. MUMPS
// on the gathered system (`MUMPS/gather`, type: auto in 2D) gives the same bits on 2 ranks as on
// rank 0's own 1-rank communicator, and a singular system fails on every rank.

#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <cmath>
#include <cstring>
#include <stdexcept>

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

// Nonsymmetric 5-point operator on a g × g grid (large enough for MUMPS's dense fronts to go
// through the BLAS), rows distributed contiguously over `comm`; b_i = 1 + sin(i).
// singular: the first row is zero.
Teuchos::RCP<Matrix> grid(int g, const Teuchos::RCP<const Comm>& comm, bool singular = false) {
  const GO n = GO(g) * g;
  const auto map = Teuchos::rcp(new Map(n, 0, comm));
  auto A = Teuchos::rcp(new Matrix(map, 5));
  for (LO i = 0; i < LO(map->getNodeNumElements()); ++i) {
    const GO r = map->getGlobalElement(i), x = r % g, y = r / g;
    std::vector<GO> cols;
    std::vector<double> vals;
    const double s = singular && r == 0 ? 0.0 : 1.0;
    if (y > 0) cols.push_back(r - g), vals.push_back(s * -1.1);
    if (x > 0) cols.push_back(r - 1), vals.push_back(s * -0.7);
    cols.push_back(r), vals.push_back(s * (4.0 + 1e-3 * double(r % 11)));
    if (x + 1 < g) cols.push_back(r + 1), vals.push_back(s * -1.3);
    if (y + 1 < g) cols.push_back(r + g), vals.push_back(s * -0.9);
    A->insertGlobalValues(r, Teuchos::ArrayView<const GO>(cols),
                          Teuchos::ArrayView<const double>(vals));
  }
  A->fillComplete();
  return A;
}

void fill_rhs(Vector& b) {
  auto v = b.getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (LO i = 0; i < LO(b.getLocalLength()); ++i)
    v(i, 0) = 1.0 + std::sin(double(b.getMap()->getGlobalElement(i)));
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
  LinearSolver solver(params, "test", {});
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

// type: auto (the default) resolves through the thresholds of each dimension: in 2D the
// gathered KLU2 for the smallest systems, the direct solver up to the iterative threshold,
// the iterative path from it on; the solve reports the type it used.
TEST(LinearSolver, AutoPicksTheDirectSolverForSmallSystems) {
  for (int dim : {2, 3}) {
    const long long n = auto_iterative_threshold(dim);
    EXPECT_EQ(auto_linear_solver_type(n - 1, dim), default_direct_type(dim));
    EXPECT_EQ(auto_linear_solver_type(n, dim), "belos");
  }
  const long long small = auto_small_direct_threshold(2);
  EXPECT_EQ(small, 2000);
  EXPECT_EQ(auto_linear_solver_type(small - 1, 2), "amesos2");
  EXPECT_EQ(auto_linear_solver_type(small, 2), "mumps_gathered");
  EXPECT_EQ(auto_small_direct_threshold(3), 0);
  EXPECT_EQ(auto_linear_solver_type(1, 3), "mumps");
  EXPECT_GT(auto_iterative_threshold(2), auto_iterative_threshold(3));
  EXPECT_EQ(default_direct_type(3), "mumps");
  EXPECT_EQ(default_direct_type(2), "mumps_gathered");
  // No coordinates given: 2D. Both sides of the small-system threshold, solved.
  for (const int n : {200, int(small)}) {
    LinearSolver solver(Teuchos::ParameterList(), "test", {});
    const auto A = tridiagonal(n);
    Vector b(A->getRowMap()), x(A->getRowMap());
    b.randomize();
    EXPECT_EQ(solver.solve(A, b, x), 1);
    EXPECT_EQ(solver.last_type(), n < small ? "amesos2" : "mumps_gathered") << n;
    EXPECT_LT(relative_residual(*A, x, b), 1e-10) << n;
  }
  // A MUMPS sublist asks for MUMPS: kept below the small-system threshold.
  Teuchos::ParameterList with_mumps;
  with_mumps.sublist("MUMPS").set("ordering", "amd");
  LinearSolver solver(with_mumps, "test", {});
  const auto A = tridiagonal(200);
  Vector b(A->getRowMap()), x(A->getRowMap());
  b.randomize();
  solver.solve(A, b, x);
  EXPECT_EQ(solver.last_type(), "mumps_gathered");
}

// type: auto falls back to the direct solver when its iterative solve fails (here: Belos
// limited to one iteration), for that system and every later one; an explicit type: belos
// keeps the failure.
TEST(LinearSolver, AutoFallsBackToTheDirectSolverWhenTheIterativeSolveFails) {
  const auto A = tridiagonal(auto_iterative_threshold(2));
  Vector b(A->getRowMap()), x(A->getRowMap());
  b.randomize();
  Teuchos::ParameterList params;
  params.sublist("Belos").set("Maximum Iterations", 1);
  LinearSolver solver(params, "test", {});
  EXPECT_NO_THROW(solver.solve(A, b, x));
  EXPECT_EQ(solver.last_type(), "mumps_gathered");
  EXPECT_LT(relative_residual(*A, x, b), 1e-10);
  x.putScalar(0.0);
  solver.solve(A, b, x);
  EXPECT_EQ(solver.last_type(), "mumps_gathered");
  EXPECT_LT(relative_residual(*A, x, b), 1e-10);
  params.set("type", "belos");
  LinearSolver belos(params, "test", {});
  EXPECT_ANY_THROW(belos.solve(A, b, x));
}

TEST(LinearSolver, GatheredMumpsIsCorrectOnAnyRankCount) {
  Teuchos::ParameterList params;
  params.set("type", "mumps");
  params.sublist("MUMPS").set("gather", true);
  check_solver(params);
}

// The gathered solve on all ranks against the same system solved on rank 0's own 1-rank
// communicator: the same bits (on 1 rank both are 1-rank solves).
TEST(LinearSolver, GatheredMumpsIsTheSameBitForBitOnAnyRankCount) {
  const int g = 70;
  const auto comm = Tpetra::getDefaultComm();
  const auto A = grid(g, comm);
  Vector b(A->getRowMap()), x(A->getRowMap());
  fill_rhs(b);
  LinearSolver all(Teuchos::ParameterList(), "test", {});  // type: auto, 2D: gathered MUMPS
  EXPECT_EQ(all.solve(A, b, x), 1);
  EXPECT_EQ(all.last_type(), "mumps_gathered");
  EXPECT_LT(relative_residual(*A, x, b), 1e-12);
  // x gathered to rank 0.
  const GO n = GO(g) * g;
  const bool root = comm->getRank() == 0;
  const auto root_map = Teuchos::rcp(new Map(n, root ? n : 0, 0, comm));
  Vector x_root(root_map);
  x_root.doExport(x, Export(A->getRowMap(), root_map), Tpetra::INSERT);
  const auto self = comm->split(root ? 0 : 1, comm->getRank());
  if (!root) return;
  const auto A1 = grid(g, self);
  Vector b1(A1->getRowMap()), x1(A1->getRowMap());
  fill_rhs(b1);
  LinearSolver one(Teuchos::ParameterList(), "test", {});
  one.solve(A1, b1, x1);
  auto a = x_root.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto c = x1.getLocalViewHost(Tpetra::Access::ReadOnly);
  GO differing = 0;
  for (GO i = 0; i < n; ++i)
    if (std::memcmp(&a(i, 0), &c(i, 0), sizeof(double)) != 0) ++differing;
  EXPECT_EQ(differing, 0) << "of " << n << " entries";
}

// A singular system fails on rank 0 and throws on every rank (no rank left waiting).
TEST(LinearSolver, GatheredSingularSystemThrowsOnEveryRank) {
  for (const char* type : {"mumps_gathered", "amesos2"}) {
    Teuchos::ParameterList params;
    if (std::string(type) == "amesos2") {
      params.set("type", "amesos2");
    } else {
      params.set("type", "mumps");
      params.sublist("MUMPS").set("gather", true);
    }
    LinearSolver solver(params, "test", {});
    const auto A = grid(20, Tpetra::getDefaultComm(), true);
    Vector b(A->getRowMap()), x(A->getRowMap());
    fill_rhs(b);
    EXPECT_THROW(solver.solve(A, b, x), std::runtime_error) << type;
  }
}

TEST(LinearSolver, UnknownTypeIsAnInputError) {
  Teuchos::ParameterList params;
  params.set("type", "superlu");
  try {
    LinearSolver solver(params, "case.yaml: grout/solver/Linear Solver", {});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("superlu"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("case.yaml"), std::string::npos);
  }
}

}  // namespace
}  // namespace grout
