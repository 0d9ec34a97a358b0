// CsrBuilder (nonlinear/local_csr_matrix.hpp) against the same matrix inserted the plain Tpetra
// way, on 1 and 2 ranks: a builder given room for one entry grows many times over and keeps
// every entry, rows with no entry included; a builder refuses open rows and rows past the last.

#include <gtest/gtest.h>

#include <Teuchos_DefaultComm.hpp>
#include <vector>

#include "nonlinear/local_csr_matrix.hpp"

namespace grout {
namespace {

TEST(CsrBuilder, GrowsFromOneEntryAndMatchesInsertedMatrix) {
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const LO n_local = 7;
  const GO n_global = GO(n_local) * comm->getSize();
  const auto map = Teuchos::rcp(new Map(n_global, n_local, 0, comm));
  const auto col_map = Teuchos::rcp(new Map(n_global, 0, comm, Tpetra::LocallyReplicated));
  // Row g: columns g, g + 1, ..., up to (g mod 4) + 1 entries (row 3 of each rank is empty).
  const auto columns_of = [&](GO g) {
    std::vector<GO> cols;
    if (g % n_local == 3) return cols;
    for (GO c = g; c < n_global && c <= g + g % 4; ++c) cols.push_back(c);
    return cols;
  };
  CsrBuilder rows(n_local, 1);
  Matrix expected(map, 4);
  for (LO i = 0; i < n_local; ++i) {
    const GO g = map->getGlobalElement(i);
    for (GO c : columns_of(g)) {
      const double v = 1.0 + double(g) + 0.25 * double(c);
      rows.append(LO(c), v);  // the replicated column map numbers column c as c
      expected.insertGlobalValues(g, Teuchos::tuple<GO>(c), Teuchos::tuple<double>(v));
    }
    rows.end_row();
  }
  expected.fillComplete(map, map);
  EXPECT_GT(rows.size(), std::size_t(4));  // grown from room for one
  const auto A = rows.matrix(map, col_map, map, map);
  EXPECT_EQ(A->getGlobalNumEntries(), expected.getGlobalNumEntries());
  for (LO i = 0; i < n_local; ++i) {
    const GO g = map->getGlobalElement(i);
    const std::vector<GO> cols = columns_of(g);
    EXPECT_EQ(A->getNumEntriesInGlobalRow(g), cols.size());
    Matrix::nonconst_global_inds_host_view_type ci("ci", 8), ce("ce", 8);
    Matrix::nonconst_values_host_view_type vi("vi", 8), ve("ve", 8);
    std::size_t ni = 0, ne = 0;
    A->getGlobalRowCopy(g, ci, vi, ni);
    expected.getGlobalRowCopy(g, ce, ve, ne);
    ASSERT_EQ(ni, ne);
    for (std::size_t k = 0; k < ni; ++k) {
      EXPECT_EQ(ci(k), ce(k)) << "row " << g;
      EXPECT_EQ(vi(k), ve(k)) << "row " << g;
    }
  }
}

TEST(CsrBuilder, RefusesOpenRows) {
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto map = Teuchos::rcp(new Map(GO(2) * comm->getSize(), 2, 0, comm));
  CsrBuilder rows(2, 4);
  rows.append(0, 1.0);
  rows.end_row();  // the second row never closed
  EXPECT_THROW(rows.matrix(map, map, map, map), std::logic_error);
  rows.end_row();
  EXPECT_THROW(rows.end_row(), std::logic_error);  // a third row of two
}

}  // namespace
}  // namespace grout
