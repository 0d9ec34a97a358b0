#pragma once
// MumpsSolver's Schur updates across the ranks (MumpsOptions::schur_updates; the algebra and
// the dense factor are in schur_update.hpp): which rows changed since the last factorised
// matrix (the base), which rows form the Schur set B of the next analysis, and the update
// S(A') = S(A) + (A' − A)_BB on rank 0 instead of a sparse factorisation.

#include <mpi.h>

#include <cstddef>
#include <vector>

#include "assembly/tpetra_types.hpp"
#include "nonlinear/mumps_pattern.hpp"
#include "nonlinear/schur_update.hpp"

namespace grout {

struct MumpsSchur {
  std::vector<long long> rows;          ///< the Schur set B of the last analysis (sorted, 0-based)
  std::vector<long long> changed_ever;  ///< rows changed since the layout's first factorisation
  std::vector<double> base_values;      ///< the last factorised matrix's values, pattern order
  double full_flops = 0.0;  ///< its factorisation's flops with the Schur block's Cholesky
  DenseSchur dense;         ///< rank 0: S(A) and the factor of the current S(A')
};

/// The rows (and columns) whose entries differ between the base (keys, values) and the
/// current matrix, on any rank: sorted, unique, the same on every rank. Collective.
std::vector<long long> rows_changed_on_any_rank(const std::vector<long long>& base_keys,
                                                const std::vector<double>& base_values,
                                                const std::vector<long long>& keys,
                                                const std::vector<double>& values, GO n,
                                                MPI_Comm comm);

/// Adds `rows` to schur.changed_ever, emptied first when there is no base. Returns whether
/// rows had changed before this matrix (since the layout's first factorisation).
bool note_changed_rows(MumpsSchur& schur, const std::vector<long long>& rows, bool have_base);

/// Whether a Schur set of `size` rows pays: its dense Cholesky factorisation (size³/3 flops)
/// at most half the last sparse factorisation (with its Schur block), and at most 6000 rows
/// (288 MB per dense copy).
bool schur_pays(std::size_t size, double full_flops);

/// The Schur set for the next analysis, chosen at an analysis the pattern asks for anyway (so
/// never an extra one): every row changed so far (rows that changed once change again in the
/// next Newton iterations), or those changed since the last factorisation (`rows`), or none.
/// None at the first change (`changed_before` false): a factorisation with a Schur set costs
/// more than one without (MUMPS orders the set last; 1.6–1.9× the flops on the 3D Hertz
/// spheres), which pays only if the set is reused, and a single change is no evidence that the
/// rows keep changing.
std::vector<long long> next_schur_set(const MumpsSchur& schur, const std::vector<long long>& rows,
                                      bool changed_before);

/// S(A') = S(A) + (A' − A)_BB from the entries of `values` that differ from the base inside
/// B × B (any rank), and its dense Cholesky factorisation on rank 0. Returns, on every rank
/// alike, false if S(A') is not positive definite (the caller factorises A' then). Collective.
bool update_schur(MumpsSchur& schur, const MumpsPattern& pattern, const std::vector<double>& values,
                  GO n, MPI_Comm comm);

}  // namespace grout
