// MUMPS direct solves (nonlinear/mumps_solver.hpp) on 1 and 2 ranks (registered for both):
// |b − A x| / |b| at round-off for a nonsymmetric saddle-point system (zero diagonal in the
// constraint rows, like the (u, λ) contact system) on a row map that is neither contiguous
// nor ordered by rank; the analysis is reused while only values change or the pattern stays
// inside the analysed one, the factorisation while values do not change either, and both are
// redone when new entries appear; the same matrix gives the same solution to the last bit.
// The answer agrees with Amesos2 KLU2 (independent solver). A symmetric matrix's placeholder
// entries keep the analysis on 2 ranks as on 1.

#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include "io/errors.hpp"
#include "nonlinear/linear_solver.hpp"
#include "nonlinear/mumps_solver.hpp"

namespace grout {
namespace {

// Grid of g × g "displacement" unknowns with a nonsymmetric 5-point stencil, plus
// `constraints` multiplier unknowns: constraint k ties u(a_k) − u(b_k) = 0 (row of B, zero
// diagonal) and adds B^T λ to the equilibrium rows; constraints from `active` on (if ≥ 0)
// are inactive, λ_k = 0 (identity row), like open contact nodes. Row GIDs are spread cyclically
// over the ranks and numbered backwards (a non-contiguous map). `scale` changes the values only.
Teuchos::RCP<Matrix> saddle_point(int g, int constraints, double scale = 1.0,
                                  bool symmetric = false, int active = -1) {
  const auto comm = Tpetra::getDefaultComm();
  const GO n_u = GO(g) * g, n = n_u + constraints;
  std::vector<GO> mine;
  for (GO i = n - 1; i >= 0; --i)
    if (i % comm->getSize() == comm->getRank()) mine.push_back(i);
  const auto map =
      Teuchos::rcp(new Map(Tpetra::global_size_t(n), mine.data(), mine.size(), 0, comm));
  const double skew = symmetric ? 0.0 : 0.3;
  std::map<GO, std::map<GO, double>> rows;
  for (GO i = 0; i < n_u; ++i) {
    const GO x = i % g, y = i / g;
    rows[i][i] = scale * (4.5 + 0.01 * double(i % 7));
    if (x > 0) rows[i][i - 1] = scale * (-1.0 - skew);
    if (x + 1 < g) rows[i][i + 1] = scale * (-1.0 + skew);
    if (y > 0) rows[i][i - g] = scale * (-1.0 + 0.5 * skew);
    if (y + 1 < g) rows[i][i + g] = scale * (-1.0 - 0.5 * skew);
  }
  for (int k = 0; k < constraints; ++k) {
    if (active >= 0 && k >= active) {  // inactive: λ_k = 0
      rows[n_u + k][n_u + k] = 1.0;
      continue;
    }
    const GO lambda = n_u + k, a = (7 * GO(k) + 3) % n_u, b = (13 * GO(k) + 5 * g + 1) % n_u;
    if (a == b) continue;
    rows[lambda][a] += 1.0;
    rows[lambda][b] -= 1.0;
    rows[a][lambda] += 1.0;
    rows[b][lambda] -= 1.0;
  }
  auto A = Teuchos::rcp(new Matrix(map, 8));
  for (GO row : mine) {
    std::vector<GO> cols;
    std::vector<double> vals;
    for (const auto& [c, v] : rows[row]) cols.push_back(c), vals.push_back(v);
    A->insertGlobalValues(row, Teuchos::ArrayView<const GO>(cols),
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

double relative_difference(const Vector& x, const Vector& y) {
  Vector d(x.getMap());
  d.update(1.0, x, -1.0, y, 0.0);
  return d.normInf() / x.normInf();
}

TEST(MumpsSolver, SaddlePointSolveReachesRoundOff) {
  const auto A = saddle_point(12, 10);
  Vector b(A->getRowMap()), x(A->getRowMap());
  b.randomize();
  MumpsSolver solver;
  solver.solve(A, b, x);
  EXPECT_LT(relative_residual(*A, x, b), 1e-13);
  EXPECT_EQ(solver.statistics().analyses, 1);
  EXPECT_EQ(solver.statistics().factorisations, 1);
}

// SCOTCH's nested dissection draws random numbers; MumpsSolver fixes their seed before each
// analysis, so that the ordering and the pivots depend on the matrix alone. Two solvers
// (their analyses one after the other in this process, the generator's state moved on) give
// the same solution to the last bit on one rank. On two ranks MUMPS's dynamic scheduling of
// the fronts over the ranks follows the timing, so the rounding may differ (4e-16 seen under
// load): there the solutions agree to round-off. The grid is large enough for SCOTCH's
// coarsening (a few hundred vertices or fewer are ordered without it).
TEST(MumpsSolver, SameMatrixSameSolutionBitwiseOnOneRank) {
  const auto A = saddle_point(70, 40);
  Vector b(A->getRowMap()), x1(A->getRowMap()), x2(A->getRowMap());
  b.putScalar(1.0);
  MumpsSolver first, second;
  first.solve(A, b, x1);
  second.solve(A, b, x2);
  if (A->getRowMap()->getComm()->getSize() == 1) {
    Vector d(A->getRowMap());
    d.update(1.0, x1, -1.0, x2, 0.0);
    EXPECT_EQ(d.normInf(), 0.0);
  } else {
    EXPECT_LT(relative_difference(x1, x2), 1e-13);
  }
}

TEST(MumpsSolver, AgreesWithKlu2) {
  const auto A = saddle_point(10, 8);
  Vector b(A->getRowMap()), x_mumps(A->getRowMap()), x_klu(A->getRowMap());
  b.randomize();
  Teuchos::ParameterList mumps, klu;
  klu.set("type", "amesos2");
  mumps.set("type", "mumps");
  LinearSolver(mumps, "test", {}).solve(A, b, x_mumps);
  LinearSolver(klu, "test", {}).solve(A, b, x_klu);
  EXPECT_LT(relative_difference(x_klu, x_mumps), 1e-10);
}

TEST(MumpsSolver, AnalysisReusedWhileOnlyValuesChange) {
  MumpsSolver solver;
  for (double scale : {1.0, 2.0, 0.5}) {
    const auto A = saddle_point(12, 10, scale);
    Vector b(A->getRowMap()), x(A->getRowMap());
    b.randomize();
    solver.solve(A, b, x);
    EXPECT_LT(relative_residual(*A, x, b), 1e-13) << "scale " << scale;
  }
  EXPECT_EQ(solver.statistics().analyses, 1);
  EXPECT_EQ(solver.statistics().factorisations, 3);
  EXPECT_EQ(solver.statistics().solves, 3);
}

TEST(MumpsSolver, FactorisationReusedWhileValuesDoNotChange) {
  const auto A = saddle_point(12, 10);
  MumpsSolver solver;
  for (int i = 0; i < 3; ++i) {
    Vector b(A->getRowMap()), x(A->getRowMap());
    b.randomize();
    solver.solve(A, b, x);
    EXPECT_LT(relative_residual(*A, x, b), 1e-13);
  }
  EXPECT_EQ(solver.statistics().analyses, 1);
  EXPECT_EQ(solver.statistics().factorisations, 1);
  EXPECT_EQ(solver.statistics().solves, 3);
}

TEST(MumpsSolver, NewPatternIsAnalysedAgain) {
  MumpsSolver solver;
  // Of 14 constraints: more active ones (new entries: analysed again), new values only, fewer
  // active (a pattern inside the analysed one: kept, with explicit zeros), another size.
  struct Step {
    int grid, active;
    double scale;
    int analyses;
  };
  const std::vector<Step> steps = {
      {12, 6, 1.0, 1}, {12, 14, 1.0, 2}, {12, 14, 2.0, 2}, {12, 10, 1.0, 2}, {13, 10, 1.0, 3}};
  for (const Step& step : steps) {
    const auto A = saddle_point(step.grid, 14, step.scale, false, step.active);
    Vector b(A->getRowMap()), x(A->getRowMap());
    b.randomize();
    solver.solve(A, b, x);
    EXPECT_LT(relative_residual(*A, x, b), 1e-13) << step.active << " active";
    EXPECT_EQ(solver.statistics().analyses, step.analyses) << step.active << " active";
  }
  EXPECT_EQ(solver.statistics().factorisations, 5);
}

// Symmetric storage (lower triangle): an explicit zero above the diagonal in row r holds the
// place of its mirror (c, r) in the pattern (mumps_numbering.hpp), which a later matrix fills
// from row c. On 2 ranks rows r = 5 and c = 20 live on different ranks (cyclic map): the
// placeholder must reach row c's rank, or that rank sees a new entry and MUMPS analyses again.
Teuchos::RCP<Matrix> chain_with_coupling(bool coupled) {
  const auto comm = Tpetra::getDefaultComm();
  const GO n = 40, r = 5, c = 20;
  std::vector<GO> mine;
  for (GO i = 0; i < n; ++i)
    if (i % comm->getSize() == comm->getRank()) mine.push_back(i);
  const auto map =
      Teuchos::rcp(new Map(Tpetra::global_size_t(n), mine.data(), mine.size(), 0, comm));
  auto A = Teuchos::rcp(new Matrix(map, 4));
  for (GO i : mine) {
    std::vector<GO> cols = {i};
    std::vector<double> vals = {4.0};
    if (i > 0) cols.push_back(i - 1), vals.push_back(-1.0);
    if (i + 1 < n) cols.push_back(i + 1), vals.push_back(-1.0);
    if (i == r) cols.push_back(c), vals.push_back(coupled ? -0.5 : 0.0);
    if (i == c && coupled) cols.push_back(r), vals.push_back(-0.5);
    A->insertGlobalValues(i, Teuchos::ArrayView<const GO>(cols),
                          Teuchos::ArrayView<const double>(vals));
  }
  A->fillComplete();
  return A;
}

TEST(MumpsSolver, SymmetricPlaceholderKeepsTheAnalysisOnAnyRankCount) {
  MumpsOptions options;
  options.symmetric = true;
  MumpsSolver solver(options);
  for (bool coupled : {false, true}) {
    const auto A = chain_with_coupling(coupled);
    Vector b(A->getRowMap()), x(A->getRowMap());
    b.randomize();
    solver.solve(A, b, x);
    EXPECT_LT(relative_residual(*A, x, b), 1e-14) << "coupled " << coupled;
  }
  EXPECT_EQ(solver.statistics().analyses, 1);
  EXPECT_EQ(solver.statistics().factorisations, 2);
}

TEST(MumpsSolver, EveryOrderingAndSymmetricLdlt) {
  for (const char* ordering : {"scotch", "ptscotch", "amd", "pord"}) {
    for (bool symmetric : {false, true}) {
      const auto A = saddle_point(9, 6, 1.0, symmetric);
      Vector b(A->getRowMap()), x(A->getRowMap());
      b.randomize();
      MumpsOptions options;
      options.ordering = ordering;
      options.symmetric = symmetric;
      MumpsSolver solver(options);
      solver.solve(A, b, x);
      EXPECT_LT(relative_residual(*A, x, b), 1e-13) << ordering << " symmetric " << symmetric;
    }
  }
}

TEST(MumpsSolver, SingularMatrixThrowsOnEveryRank) {
  // Constraint rows that tie the same pair twice: two identical rows.
  const auto comm = Tpetra::getDefaultComm();
  const GO n = 6;
  const auto map = Teuchos::rcp(new Map(Tpetra::global_size_t(n), 0, comm));
  auto A = Teuchos::rcp(new Matrix(map, 3));
  for (LO i = 0; i < LO(map->getNodeNumElements()); ++i) {
    const GO g = map->getGlobalElement(i);
    const GO cols[2] = {g < 3 ? g : GO(0), 1};
    const double vals[2] = {g < 3 ? 2.0 : 1.0, g < 3 ? 0.5 : 1.0};
    A->insertGlobalValues(g, Teuchos::ArrayView<const GO>(cols, g == 1 ? 1 : 2),
                          Teuchos::ArrayView<const double>(vals, g == 1 ? 1 : 2));
  }
  A->fillComplete();
  Vector b(map), x(map);
  b.putScalar(1.0);
  MumpsSolver solver;
  EXPECT_THROW(solver.solve(A, b, x), std::runtime_error);
  // The solver stays usable.
  const auto B = saddle_point(6, 3);
  Vector c(B->getRowMap()), y(B->getRowMap());
  c.randomize();
  solver.solve(B, c, y);
  EXPECT_LT(relative_residual(*B, y, c), 1e-13);
}

TEST(MumpsSolver, BadOptionsAreInputErrors) {
  const std::string where = "case.yaml: grout/solver/Linear Solver/MUMPS";
  Teuchos::ParameterList unknown_ordering, unknown_key, gather_not_bool;
  unknown_ordering.set("ordering", "metis");
  unknown_key.set("pivoting", 0.1);
  gather_not_bool.set("gather", "yes");
  for (const auto* params : {&unknown_ordering, &unknown_key, &gather_not_bool}) {
    try {
      mumps_options_from(*params, where);
      FAIL() << "expected InputError";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace grout
