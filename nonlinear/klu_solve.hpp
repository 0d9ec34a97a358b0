#pragma once
// KLU2 (Trilinos' templated KLU: Davis & Palamadai Natarajan, "Algorithm 907: KLU, a direct
// sparse solver for circuit simulation problems", ACM TOMS 37(3), 2010) called directly from
// its headers, as Amesos2's KLU2 calls it on one rank: the CRS arrays passed as the CCS of
// Kᵀ, analysed (BTF + AMD), factorised, and Kᵀᵀ x = b solved with klu_tsolve2. The answer is
// Amesos2's bit for bit; the driver then needs neither Amesos2 nor what it pulls in (Tacho,
// a second MUMPS): 3.3 k fewer start-up symbol relocations (docs/performance.md, "Process
// start-up").

#include "assembly/tpetra_types.hpp"

namespace grout {

/// Solves K x = b with KLU2. K lives on a 1-rank communicator with its column map equal to its
/// row map (the gathered matrix of gathered_solve.hpp). Throws std::runtime_error when the
/// analysis or the factorisation fails (e.g. a singular matrix).
void klu_solve(const Matrix& K, const Vector& b, Vector& x);

}  // namespace grout
