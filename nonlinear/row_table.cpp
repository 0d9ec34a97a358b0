#include "nonlinear/row_table.hpp"

#include <algorithm>

namespace grout {

void add_rows(const Matrix& A, const Vector& b, RowTable& table) {
  const auto& row_map = *A.getRowMap();
  const auto& col_map = *A.getColMap();
  const auto local = A.getLocalMatrixHost();
  const auto bv = b.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (LO i = 0; i < LO(row_map.getNodeNumElements()); ++i) {
    Row& r = table[row_map.getGlobalElement(i)];
    r.cols.clear(), r.vals.clear();
    for (auto p = local.graph.row_map(i); p < local.graph.row_map(i + 1); ++p) {
      if (local.values(p) == 0.0) continue;
      r.cols.push_back(col_map.getGlobalElement(local.graph.entries(p)));
      r.vals.push_back(local.values(p));
    }
    r.rhs = bv(i, 0);
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
