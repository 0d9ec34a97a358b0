#pragma once
// Prescribed displacements by symmetric row and column elimination.

#include <vector>

#include "assembly/tpetra_types.hpp"

namespace grout {

/// \brief Impose du_i = delta_i on the dofs where `delta` (indexed by K's column map) is not NaN,
/// keeping K symmetric (Hughes, The Finite Element Method, §1.14):
///   free rows:        rhs_i -= Σ_j K_ij delta_j over prescribed j, then K_ij = 0;
///   prescribed rows:  K_ij = 0 for j != i, rhs_i = K_ii delta_i (K_ii = 1 if it was 0).
/// K must be fill-complete; it is left fill-complete.
void apply_dirichlet(Matrix& K, Vector& rhs, const std::vector<double>& delta);

}  // namespace grout
