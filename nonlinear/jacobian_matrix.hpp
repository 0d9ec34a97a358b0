#pragma once
// The (u, λ) Jacobian of MechanicsProblem assembled from its parts: the solid tangent K_solid
// on the owned displacement rows, the contact terms (row, column, value triplets), and a zero
// diagonal in every multiplier row. The local CRS arrays are built directly, so the matrix
// needs no insertGlobalValues per row and no fillComplete column-map search: on the 2D Hertz
// level-3 case those took 0.34 G of the run's 3.3 G instructions (three Newton iterations).

#include <vector>

#include "assembly/contact_terms.hpp"
#include "assembly/tpetra_types.hpp"

namespace grout {

/// J on `map` (owned displacement rows first, in the order of K_solid's row map, then owned
/// multiplier rows): row i < K_solid's local rows is K_solid's row i, plus `terms` (owned
/// rows only, in any order; keys unique within a row), plus a stored zero diagonal in each
/// multiplier row. Every entry (r, c) is the sum, in this order, of K_solid(r, c) and the terms of
/// (r, c) in key order: the same bits on any number of ranks when K_solid's and the terms' are.
/// Fill-complete on (map, map); collective.
Teuchos::RCP<Matrix> jacobian_matrix(const Matrix& K_solid, const Teuchos::RCP<const Map>& map,
                                     const std::vector<JacobianTerm>& terms);

}  // namespace grout
