// jacobian_matrix (nonlinear/jacobian_matrix.hpp) against the same matrix assembled the plain
// Tpetra way (insertGlobalValues of K_solid's rows, then of every term in key order, then
// fillComplete), on 1 and 2 ranks: same entries bit for bit, including sums of terms that hit
// K_solid's entries or each other, multiplier columns another rank owns, and multiplier rows
// whose only entry is the stored zero diagonal.

#include <gtest/gtest.h>

#include <Teuchos_DefaultComm.hpp>
#include <algorithm>
#include <map>
#include <vector>

#include "nonlinear/jacobian_matrix.hpp"

namespace grout {
namespace {

constexpr GO kNodesPerRank = 5;  // 2 displacement dofs per node
constexpr GO kSlavesPerRank = 3;

struct Problem {
  Teuchos::RCP<const Map> u_map, map;
  Teuchos::RCP<Matrix> K;
  std::vector<JacobianTerm> terms;  // this rank's rows, in emission order (rows mixed)
};

// K_solid: a chain of nodes, each dof coupled to the dofs of its node and the neighbours'
// (values that do not add up exactly in another order); multipliers numbered after the
// displacements, kSlavesPerRank on each rank.
Problem make_problem() {
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const int rank = comm->getRank(), ranks = comm->getSize();
  const GO n_nodes = kNodesPerRank * ranks, n_u = 2 * n_nodes;
  const GO n_lambda = kSlavesPerRank * ranks;
  Problem p;
  std::vector<GO> owned_u, owned;
  for (GO k = 0; k < 2 * kNodesPerRank; ++k) owned_u.push_back(2 * kNodesPerRank * rank + k);
  owned = owned_u;
  for (GO s = 0; s < kSlavesPerRank; ++s) owned.push_back(n_u + kSlavesPerRank * rank + s);
  p.u_map = Teuchos::rcp(new Map(n_u, owned_u.data(), owned_u.size(), 0, comm));
  p.map = Teuchos::rcp(new Map(n_u + n_lambda, owned.data(), owned.size(), 0, comm));
  p.K = Teuchos::rcp(new Matrix(p.u_map, 8));
  for (GO row : owned_u) {
    const GO node = row / 2;
    std::vector<GO> cols;
    std::vector<double> vals;
    for (GO m = std::max<GO>(0, node - 1); m <= std::min(n_nodes - 1, node + 1); ++m)
      for (int d = 0; d < 2; ++d) {
        cols.push_back(2 * m + d);
        vals.push_back(row == 2 * m + d ? 4.0 + 1.0 / 3.0 : -0.1 * double(row + 1) / 7.0);
      }
    p.K->insertGlobalValues(row, cols, vals);
  }
  p.K->fillComplete(p.u_map, p.u_map);

  // Terms: for each owned slave multiplier s (node = first node of the next rank's block, so
  // its master rows are another rank's on 2 ranks): the λ row against displacement columns,
  // displacement rows against λ columns of this and the other rank, several terms of one
  // (row, col) and terms on K_solid's entries. The last multiplier of each rank gets none.
  long long key = 0;
  std::vector<JacobianTerm> all;
  for (int r = 0; r < ranks; ++r)
    for (GO s = 0; s + 1 < kSlavesPerRank; ++s) {
      const GO lambda = n_u + kSlavesPerRank * r + s;
      const GO node = (kNodesPerRank * (r + 1) + s) % n_nodes;
      const GO other_lambda = n_u + (kSlavesPerRank * (r + 1) + s) % n_lambda;
      for (int d = 0; d < 2; ++d) {
        all.push_back({lambda, 2 * node + d, key++, 0.3 + 0.01 * double(s)});
        all.push_back({lambda, 2 * node + d, key++, 1.0 / 7.0});  // same (row, col) again
        all.push_back({2 * node + d, lambda, key++, -0.7 / 3.0});
        all.push_back({2 * node + d, other_lambda, key++, 0.11});
        all.push_back({2 * node + d, 2 * node + d, key++, 1e-3 / 3.0});  // on K's diagonal
      }
    }
  for (const JacobianTerm& t : all)
    if (p.map->isNodeGlobalElement(t.row)) p.terms.push_back(t);
  return p;
}

// The plain Tpetra assembly of the same J.
Teuchos::RCP<Matrix> reference(const Problem& p) {
  auto J = Teuchos::rcp(new Matrix(p.map, 32));
  const auto& K_cols = *p.K->getColMap();
  const auto local = p.K->getLocalMatrixHost();
  for (LO i = 0; i < LO(p.u_map->getNodeNumElements()); ++i) {
    std::vector<GO> cols;
    std::vector<double> vals;
    for (auto q = local.graph.row_map(i); q < local.graph.row_map(i + 1); ++q) {
      cols.push_back(K_cols.getGlobalElement(local.graph.entries(q)));
      vals.push_back(local.values(q));
    }
    J->insertGlobalValues(p.u_map->getGlobalElement(i), cols, vals);
  }
  std::vector<JacobianTerm> sorted = p.terms;  // each row's terms in key order
  std::sort(sorted.begin(), sorted.end(), [](const JacobianTerm& a, const JacobianTerm& b) {
    return a.row < b.row || (a.row == b.row && a.key < b.key);
  });
  for (const JacobianTerm& t : sorted)
    J->insertGlobalValues(t.row, Teuchos::tuple(t.col), Teuchos::tuple(t.value));
  for (LO i = LO(p.u_map->getNodeNumElements()); i < LO(p.map->getNodeNumElements()); ++i) {
    const GO g = p.map->getGlobalElement(i);
    J->insertGlobalValues(g, Teuchos::tuple(g), Teuchos::tuple(0.0));
  }
  J->fillComplete(p.map, p.map);
  return J;
}

// Row `row` of A as (global column, value), sorted by column.
std::map<GO, double> row_of(const Matrix& A, GO row) {
  const LO i = A.getRowMap()->getLocalElement(row);
  const auto local = A.getLocalMatrixHost();
  std::map<GO, double> entries;
  for (auto q = local.graph.row_map(i); q < local.graph.row_map(i + 1); ++q)
    entries[A.getColMap()->getGlobalElement(local.graph.entries(q))] = local.values(q);
  return entries;
}

TEST(JacobianMatrix, EqualsThePlainTpetraAssemblyBitForBit) {
  const Problem p = make_problem();
  ASSERT_FALSE(p.terms.empty());
  // The terms handed over in reverse emission order: J sums each row's in key order anyway.
  const std::vector<JacobianTerm> reversed(p.terms.rbegin(), p.terms.rend());
  const auto J = jacobian_matrix(*p.K, p.map, reversed);
  const auto R = reference(p);
  ASSERT_TRUE(J->isFillComplete());
  EXPECT_TRUE(J->getRowMap()->isSameAs(*p.map));
  EXPECT_TRUE(J->getDomainMap()->isSameAs(*p.map));
  EXPECT_TRUE(J->getRangeMap()->isSameAs(*p.map));
  EXPECT_EQ(J->getGlobalNumEntries(), R->getGlobalNumEntries());
  for (LO i = 0; i < LO(p.map->getNodeNumElements()); ++i) {
    const GO row = p.map->getGlobalElement(i);
    const auto j_row = row_of(*J, row), r_row = row_of(*R, row);
    ASSERT_EQ(j_row.size(), r_row.size()) << "row " << row;
    for (const auto& [col, value] : r_row) {
      ASSERT_EQ(j_row.count(col), 1u) << "row " << row << " col " << col;
      EXPECT_EQ(j_row.at(col), value) << "row " << row << " col " << col;  // bit for bit
    }
  }
  // Every multiplier row stores its diagonal (zero where no term hits it).
  for (LO i = LO(p.u_map->getNodeNumElements()); i < LO(p.map->getNodeNumElements()); ++i) {
    const GO g = p.map->getGlobalElement(i);
    EXPECT_EQ(row_of(*J, g).count(g), 1u) << "multiplier row " << g;
  }
  // J x through the Tpetra operator (import onto J's own column map) equals R x.
  Vector x(p.map), y(p.map), z(p.map);
  {
    auto xv = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (LO i = 0; i < LO(xv.extent(0)); ++i)
      xv(i, 0) = 1.0 + 0.25 * double(p.map->getGlobalElement(i) % 7);
  }
  J->apply(x, y);
  R->apply(x, z);
  z.update(-1.0, y, 1.0);
  EXPECT_LE(z.normInf(), 1e-14 * y.normInf());
}

TEST(JacobianMatrix, OnOneRankTheColumnMapIsTheRowMap) {
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  if (comm->getSize() != 1) GTEST_SKIP() << "one rank only";
  const Problem p = make_problem();
  const auto J = jacobian_matrix(*p.K, p.map, p.terms);
  EXPECT_TRUE(J->getColMap()->isSameAs(*p.map));
}

TEST(JacobianMatrix, RefusesTermsOfAnotherRank) {
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  if (comm->getSize() != 2) GTEST_SKIP() << "two ranks only";
  Problem p = make_problem();
  // A row rank 1 - r owns, given to this rank.
  const GO foreign = p.map->getGlobalElement(0) == 0 ? 2 * kNodesPerRank : 0;
  p.terms.insert(p.terms.begin(), JacobianTerm{foreign, foreign, 0, 1.0});
  EXPECT_THROW(jacobian_matrix(*p.K, p.map, p.terms), std::logic_error);
}

}  // namespace
}  // namespace grout
