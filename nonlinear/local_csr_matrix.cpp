#include "nonlinear/local_csr_matrix.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace grout {

Teuchos::RCP<Matrix> local_csr_matrix(const Teuchos::RCP<const Map>& row_map,
                                      const Teuchos::RCP<const Map>& col_map,
                                      const std::vector<std::size_t>& ptr,
                                      const std::vector<LO>& ind, const std::vector<double>& val,
                                      const Teuchos::RCP<const Map>& domain,
                                      const Teuchos::RCP<const Map>& range) {
  using RowPtr = CsrRowOffsets;
  using ColInd = CsrColumns;
  using Values = CsrValues;
  // Allocated without the zero fill: every entry is written by the copies below.
  RowPtr ptr_view(Kokkos::view_alloc("grout::csr_row_ptr", Kokkos::WithoutInitializing),
                  ptr.size());
  ColInd ind_view(Kokkos::view_alloc("grout::csr_columns", Kokkos::WithoutInitializing),
                  ind.size());
  Values val_view(Kokkos::view_alloc("grout::csr_values", Kokkos::WithoutInitializing), val.size());
  std::copy(ptr.begin(), ptr.end(), ptr_view.data());
  std::copy(ind.begin(), ind.end(), ind_view.data());
  std::copy(val.begin(), val.end(), val_view.data());
  return local_csr_matrix(row_map, col_map, ptr_view, ind_view, val_view, domain, range);
}

Teuchos::RCP<Matrix> local_csr_matrix(const Teuchos::RCP<const Map>& row_map,
                                      const Teuchos::RCP<const Map>& col_map, CsrRowOffsets ptr,
                                      CsrColumns ind, CsrValues val,
                                      const Teuchos::RCP<const Map>& domain,
                                      const Teuchos::RCP<const Map>& range) {
  const std::size_t nnz = ptr.extent(0) > 0 ? std::size_t(ptr(ptr.extent(0) - 1)) : 0;
  if (ind.extent(0) != nnz) ind = Kokkos::subview(ind, Kokkos::make_pair(std::size_t(0), nnz));
  if (val.extent(0) != nnz) val = Kokkos::subview(val, Kokkos::make_pair(std::size_t(0), nnz));
  auto A = Teuchos::rcp(new Matrix(row_map, col_map, ptr, ind, val));
  A->expertStaticFillComplete(domain, range);
  return A;
}

CsrBuilder::CsrBuilder(LO rows, std::size_t capacity)
    : offsets_(Kokkos::view_alloc("grout::csr_row_ptr", Kokkos::WithoutInitializing),
               std::size_t(rows) + 1),
      columns_(Kokkos::view_alloc("grout::csr_columns", Kokkos::WithoutInitializing),
               std::max<std::size_t>(capacity, 1)),
      values_(Kokkos::view_alloc("grout::csr_values", Kokkos::WithoutInitializing),
              columns_.extent(0)) {
  offsets_(0) = 0;
}

void CsrBuilder::grow() {
  const std::size_t grown = columns_.extent(0) + columns_.extent(0) / 4 + 1;
  Kokkos::resize(columns_, grown);
  Kokkos::resize(values_, grown);
}

void CsrBuilder::too_many_rows() const {
  throw std::logic_error("CsrBuilder: a row closed past the last of " +
                         std::to_string(offsets_.extent(0) - 1));
}

Teuchos::RCP<Matrix> CsrBuilder::matrix(const Teuchos::RCP<const Map>& row_map,
                                        const Teuchos::RCP<const Map>& col_map,
                                        const Teuchos::RCP<const Map>& domain,
                                        const Teuchos::RCP<const Map>& range) {
  if (std::size_t(row_) + 1 != offsets_.extent(0))
    throw std::logic_error("CsrBuilder: " + std::to_string(row_) + " rows closed of " +
                           std::to_string(offsets_.extent(0) - 1));
  auto A = local_csr_matrix(row_map, col_map, offsets_, columns_, values_, domain, range);
  *this = CsrBuilder(0, 0);
  return A;
}

}  // namespace grout
