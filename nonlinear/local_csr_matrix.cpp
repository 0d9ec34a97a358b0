#include "nonlinear/local_csr_matrix.hpp"

#include <algorithm>

namespace grout {

Teuchos::RCP<Matrix> local_csr_matrix(const Teuchos::RCP<const Map>& row_map,
                                      const Teuchos::RCP<const Map>& col_map,
                                      const std::vector<std::size_t>& ptr,
                                      const std::vector<LO>& ind, const std::vector<double>& val,
                                      const Teuchos::RCP<const Map>& domain,
                                      const Teuchos::RCP<const Map>& range) {
  using RowPtr = Matrix::local_graph_device_type::row_map_type::non_const_type;
  using ColInd = Matrix::local_graph_device_type::entries_type::non_const_type;
  using Values = Matrix::local_matrix_device_type::values_type;
  // Allocated without the zero fill: every entry is written by the copies below.
  RowPtr ptr_view(Kokkos::view_alloc("grout::csr_row_ptr", Kokkos::WithoutInitializing),
                  ptr.size());
  ColInd ind_view(Kokkos::view_alloc("grout::csr_columns", Kokkos::WithoutInitializing),
                  ind.size());
  Values val_view(Kokkos::view_alloc("grout::csr_values", Kokkos::WithoutInitializing), val.size());
  std::copy(ptr.begin(), ptr.end(), ptr_view.data());
  std::copy(ind.begin(), ind.end(), ind_view.data());
  std::copy(val.begin(), val.end(), val_view.data());
  auto A = Teuchos::rcp(new Matrix(row_map, col_map, ptr_view, ind_view, val_view));
  A->expertStaticFillComplete(domain, range);
  return A;
}

}  // namespace grout
