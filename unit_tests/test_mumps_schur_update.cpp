// Schur updates in MumpsSolver (MumpsOptions::schur_updates, nonlinear/schur_update.hpp), on
// 1 and 2 ranks: a sequence of SPD matrices like the Newton iterations' reduced contact
// systems (a 5-point grid operator; a "contact patch" of rows whose values change and that
// gains couplings once). Each solution equals an independent MUMPS LDLᵀ of the same matrix
// (a fresh solver, no Schur set) to 1e-12 with |b − A x|/|b| at round-off; the statistics
// show which path was taken: a new pattern → analysis with the changed rows as Schur set; a
// change inside that set → a dense update and no factorisation; a change outside → a new
// factorisation with the same analysis. The same paths on 1 and 2 ranks.

#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <cmath>
#include <map>
#include <set>
#include <vector>

#include "nonlinear/mumps_solver.hpp"
#include "nonlinear/schur_update.hpp"

namespace grout {
namespace {

constexpr int g = 24;  // grid side: n = 576 unknowns

// The grid operator with diagonal 4.5 (+ `patch_shift` on the patch rows), plus, if
// `coupled`, a symmetric coupling −c between rows p and q (both in the patch) with +c on
// their diagonals (keeps the matrix diagonally dominant: SPD), and `far_shift` on row 5's
// diagonal (outside the patch).
constexpr GO p = 10 * g + 10, q = 12 * g + 13;
bool in_patch(GO i) {
  const GO x = i % g, y = i / g;
  return x >= 9 && x <= 14 && y >= 9 && y <= 13;
}
Teuchos::RCP<Matrix> grid(bool coupled, double c, double patch_shift, double far_shift) {
  const auto comm = Tpetra::getDefaultComm();
  const GO n = GO(g) * g;
  std::vector<GO> mine;
  for (GO i = 0; i < n; ++i)
    if (i % comm->getSize() == comm->getRank()) mine.push_back(i);
  const auto map =
      Teuchos::rcp(new Map(Tpetra::global_size_t(n), mine.data(), mine.size(), 0, comm));
  auto A = Teuchos::rcp(new Matrix(map, 6));
  for (GO i : mine) {
    std::map<GO, double> row;
    const GO x = i % g, y = i / g;
    row[i] =
        4.5 + 0.01 * double(i % 7) + (in_patch(i) ? patch_shift : 0.0) + (i == 5 ? far_shift : 0.0);
    if (x > 0) row[i - 1] = -1.0;
    if (x + 1 < g) row[i + 1] = -1.0;
    if (y > 0) row[i - g] = -1.0;
    if (y + 1 < g) row[i + g] = -1.0;
    if (coupled && (i == p || i == q)) {
      row[i] += c;
      row[i == p ? q : p] = -c;
    }
    std::vector<GO> cols;
    std::vector<double> vals;
    for (const auto& [col, v] : row) cols.push_back(col), vals.push_back(v);
    A->insertGlobalValues(i, Teuchos::ArrayView<const GO>(cols),
                          Teuchos::ArrayView<const double>(vals));
  }
  A->fillComplete();
  return A;
}

MumpsOptions symmetric(bool schur_updates) {
  MumpsOptions options;
  options.symmetric = true;
  options.schur_updates = schur_updates;
  return options;
}

// Solve with `solver` and with a fresh solver; max |x − x_ref| / max |x_ref| and the residual.
void expect_solution(MumpsSolver& solver, const Teuchos::RCP<Matrix>& A) {
  Vector b(A->getRowMap()), x(A->getRowMap()), x_ref(A->getRowMap()), r(A->getRowMap());
  b.randomize();
  solver.solve(A, b, x);
  MumpsSolver reference(symmetric(false));
  reference.solve(A, b, x_ref);
  Vector d(A->getRowMap());
  d.update(1.0, x, -1.0, x_ref, 0.0);
  EXPECT_LT(d.normInf(), 1e-12 * x_ref.normInf());
  A->apply(x, r);
  r.update(1.0, b, -1.0);
  EXPECT_LT(r.norm2(), 1e-13 * b.norm2());
}

TEST(SchurUpdate, ChangedRowsOfTwoPatterns) {
  const long long n = 10;
  // old: (1,1)=2, (3,1)=5, (4,4)=1; new: (1,1)=2, (3,1)=6, (7,2)=1, (4,4)=1, (8,8)=0
  const std::vector<long long> old_keys{11, 31, 44}, new_keys{11, 31, 44, 72, 88};
  const std::vector<double> old_values{2, 5, 1}, new_values{2, 6, 1, 1, 0};
  EXPECT_EQ(changed_rows(old_keys, old_values, new_keys, new_values, n),
            (std::vector<long long>{1, 2, 3, 7}));
  EXPECT_TRUE(rows_within({1, 3}, {0, 1, 2, 3}));
  EXPECT_FALSE(rows_within({1, 5}, {0, 1, 2, 3}));
}

TEST(SchurUpdate, DenseCholeskyOfUpdatedSchurComplement) {
  // S = [[4, 1], [1, 3]] given as MUMPS leaves it (ICNTL(19) = 1: the lower triangle by
  // rows = the upper one column-major; the other undefined, here NaN), then
  // S + [[1, 0.5], [0.5, 0]] = [[5, 1.5], [1.5, 3]]: solve against x = (1, 2).
  std::vector<double> s = DenseSchur::prepare(2);
  s[0] = 4, s[2] = 1, s[3] = 3;
  DenseSchur dense;
  ASSERT_TRUE(dense.set_base(2, s));
  double x[2] = {4 + 2, 1 + 6};
  dense.solve(x);
  EXPECT_NEAR(x[0], 1.0, 1e-15);
  EXPECT_NEAR(x[1], 2.0, 1e-15);
  ASSERT_TRUE(dense.update({{0, 0, 1.0}, {1, 0, 0.5}}));
  double y[2] = {5 + 3, 1.5 + 6};
  dense.solve(y);
  EXPECT_NEAR(y[0], 1.0, 1e-15);
  EXPECT_NEAR(y[1], 2.0, 1e-15);
  EXPECT_FALSE(dense.update({{1, 1, -10.0}}));  // indefinite: refused
}

TEST(SchurUpdate, SolvesWithoutRefactorisingWhileOnlyTheSetChanges) {
  MumpsSolver solver(symmetric(true));
  const auto& stats = solver.statistics();
  expect_solution(solver, grid(false, 0.0, 0.0, 0.0));  // first: no base, no Schur set
  EXPECT_EQ(stats.analyses, 1);
  EXPECT_EQ(stats.schur_size, 0);
  // The patch's values change (the first change): a plain factorisation, same analysis.
  expect_solution(solver, grid(false, 0.0, 0.3, 0.0));
  EXPECT_EQ(stats.analyses, 1);
  EXPECT_EQ(stats.factorisations, 2);
  // New entries (p, q) and new patch values: analysis with the rows changed so far as Schur
  // set.
  expect_solution(solver, grid(true, 0.7, 0.2, 0.0));
  EXPECT_EQ(stats.analyses, 2);
  EXPECT_EQ(stats.factorisations, 3);
  EXPECT_EQ(stats.schur_size, 30);  // the 6 × 5 patch rows
  // Values change inside the patch only: dense update, no factorisation.
  expect_solution(solver, grid(true, 1.1, -0.2, 0.0));
  expect_solution(solver, grid(true, 0.05, 0.5, 0.0));
  EXPECT_EQ(stats.factorisations, 3);
  EXPECT_EQ(stats.schur_updates, 2);
  // A change outside the set: a factorisation with the same analysis (the new base).
  expect_solution(solver, grid(true, 0.05, 0.5, 0.25));
  EXPECT_EQ(stats.analyses, 2);
  EXPECT_EQ(stats.factorisations, 4);
  EXPECT_EQ(stats.schur_updates, 2);
  // ... and updates relative to it again.
  expect_solution(solver, grid(true, 0.4, 0.1, 0.25));
  EXPECT_EQ(stats.factorisations, 4);
  EXPECT_EQ(stats.schur_updates, 3);
  EXPECT_EQ(stats.solves, 7);
}

// The same sequence with every ordering: each solution is right (PT-SCOTCH's parallel
// analysis on 2 ranks included, which keeps no Schur set: mumps_solver.cpp).
TEST(SchurUpdate, EveryOrderingSolvesTheSequence) {
  for (const char* ordering : {"scotch", "ptscotch", "amd", "pord"}) {
    SCOPED_TRACE(ordering);
    MumpsOptions options = symmetric(true);
    options.ordering = ordering;
    MumpsSolver solver(options);
    expect_solution(solver, grid(false, 0.0, 0.0, 0.0));
    expect_solution(solver, grid(false, 0.0, 0.3, 0.0));
    expect_solution(solver, grid(true, 0.7, 0.2, 0.0));
    expect_solution(solver, grid(true, 1.1, -0.2, 0.0));
    expect_solution(solver, grid(true, 0.05, 0.5, 0.0));
  }
}

}  // namespace
}  // namespace grout
