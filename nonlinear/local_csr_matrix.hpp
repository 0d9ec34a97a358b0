#pragma once
// A fill-complete Tpetra matrix from CSR arrays a caller has built in local indices (the
// Jacobian, jacobian_matrix.cpp; the symmetric reduction's K̃, symmetric_condensation.cpp):
// one copy into the Kokkos views the matrix keeps, and no insertGlobalValues, sorting or
// column-map search.

#include <cstddef>
#include <vector>

#include "assembly/tpetra_types.hpp"

namespace grout {

/// The matrix on `row_map` × `col_map` whose row i holds columns ind[ptr[i]..ptr[i+1]) (local
/// indices of `col_map`) with values val[...]; fill-complete on (`domain`, `range`) by
/// expertStaticFillComplete, which skips Tpetra's checks: \pre each row sorted by column, no
/// column twice in a row, ptr.size() = rows + 1, ind.size() = val.size() = ptr.back().
/// Collective (the fill builds the Import from `domain` to `col_map`).
Teuchos::RCP<Matrix> local_csr_matrix(const Teuchos::RCP<const Map>& row_map,
                                      const Teuchos::RCP<const Map>& col_map,
                                      const std::vector<std::size_t>& ptr,
                                      const std::vector<LO>& ind, const std::vector<double>& val,
                                      const Teuchos::RCP<const Map>& domain,
                                      const Teuchos::RCP<const Map>& range);

}  // namespace grout
