#include "nonlinear/dirichlet.hpp"

#include <cmath>

namespace grout {

void apply_dirichlet(Matrix& K, Vector& rhs, const std::vector<double>& delta) {
  const auto& row_map = *K.getRowMap();
  const auto& col_map = *K.getColMap();
  const std::vector<double>& column_delta = delta;

  K.resumeFill();
  const auto local = K.getLocalMatrixHost();
  auto b = Kokkos::subview(rhs.getLocalViewHost(Tpetra::Access::ReadWrite), Kokkos::ALL(), 0);
  for (LO i = 0; i < LO(row_map.getNodeNumElements()); ++i) {
    const GO row = row_map.getGlobalElement(i);
    const double row_delta = column_delta[col_map.getLocalElement(row)];
    const auto begin = local.graph.row_map(i), end = local.graph.row_map(i + 1);
    if (!std::isnan(row_delta)) {
      double diagonal = 0.0;
      for (auto p = begin; p < end; ++p) {
        if (col_map.getGlobalElement(local.graph.entries(p)) == row) {
          diagonal = local.values(p) != 0.0 ? local.values(p) : 1.0;
          local.values(p) = diagonal;
        } else {
          local.values(p) = 0.0;
        }
      }
      b(i) = diagonal * row_delta;
      continue;
    }
    for (auto p = begin; p < end; ++p) {
      const double d = column_delta[local.graph.entries(p)];
      if (std::isnan(d)) continue;
      b(i) -= local.values(p) * d;
      local.values(p) = 0.0;
    }
  }
  K.fillComplete(K.getDomainMap(), K.getRangeMap());
}

}  // namespace grout
