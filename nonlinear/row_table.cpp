#include "nonlinear/row_table.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace grout {

namespace {

// Local row i of A and b into `r` (global columns, exact zeros dropped).
template <class LocalMatrix, class RhsView>
void copy_row(const LocalMatrix& local, const Map& col_map, const RhsView& bv, LO i, Row& r) {
  r.cols.clear(), r.vals.clear();
  for (auto p = local.graph.row_map(i); p < local.graph.row_map(i + 1); ++p) {
    if (local.values(p) == 0.0) continue;
    r.cols.push_back(col_map.getGlobalElement(local.graph.entries(p)));
    r.vals.push_back(local.values(p));
  }
  r.rhs = bv(i, 0);
}

}  // namespace

void add_rows(const Matrix& A, const Vector& b, RowTable& table) {
  const auto& row_map = *A.getRowMap();
  const auto local = A.getLocalMatrixHost();
  const auto bv = b.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (LO i = 0; i < LO(row_map.getNodeNumElements()); ++i)
    copy_row(local, *A.getColMap(), bv, i, table[row_map.getGlobalElement(i)]);
}

void add_owned_rows(const Matrix& A, const Vector& b, const std::vector<GO>& gids,
                    RowTable& table) {
  const auto& row_map = *A.getRowMap();
  const auto local = A.getLocalMatrixHost();
  const auto bv = b.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (const GO g : gids) {
    const LO i = row_map.getLocalElement(g);
    if (i == Teuchos::OrdinalTraits<LO>::invalid())
      throw std::out_of_range("add_owned_rows: row " + std::to_string(g) + " is not owned here");
    copy_row(local, *A.getColMap(), bv, i, table[g]);
  }
}

void import_rows(const Matrix& J, const Vector& b, std::vector<GO> gids, RowTable& table) {
  std::sort(gids.begin(), gids.end());
  gids.erase(std::unique(gids.begin(), gids.end()), gids.end());
  const auto comm = J.getRowMap()->getComm();
  const auto target = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                           gids.data(), gids.size(), 0, comm));
  const Import importer(J.getRowMap(), target);
  Matrix Jt(target, 0);
  Jt.doImport(J, importer, Tpetra::INSERT);
  Jt.fillComplete(J.getDomainMap(), J.getRangeMap());
  Vector bt(target);
  bt.doImport(b, importer, Tpetra::INSERT);
  add_rows(Jt, bt, table);
}

}  // namespace grout
