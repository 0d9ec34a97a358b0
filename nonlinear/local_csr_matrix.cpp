#include "nonlinear/local_csr_matrix.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace grout {

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
  // The entries past the last row's end (the unused capacity) are not the matrix's.
  const auto used = Kokkos::make_pair(std::size_t(0), nnz_);
  auto A = Teuchos::rcp(new Matrix(row_map, col_map, offsets_, Kokkos::subview(columns_, used),
                                   Kokkos::subview(values_, used)));
  A->expertStaticFillComplete(domain, range);
  *this = CsrBuilder(0, 0);
  return A;
}

}  // namespace grout
