#pragma once
// Solving a sequence of symmetric matrices that differ only in a few rows, with one sparse
// factorisation: the dense Schur complement on those rows is updated instead
// (MumpsSolver, MumpsOptions::schur_updates; docs/performance.md, "Condensed,
// symmetric and Schur-updated direct solves").
//
// Split the unknowns into B (the rows that change) and I (all others). With A = [A_II A_IB;
// A_BI A_BB], block elimination of I gives
//      S(A) = A_BB − A_BI A_II⁻¹ A_IB,     x_B = S⁻¹ (b_B − A_BI A_II⁻¹ b_I),
//      x_I = A_II⁻¹ (b_I − A_IB x_B)
// (Golub & Van Loan, "Matrix Computations", 4th ed., §3.2.10 and §4.2.8). A matrix A' whose
// rows outside B are A's (so A'_II = A_II, A'_IB = A_IB; symmetric, so its columns outside B
// too) has S(A') = S(A) + (A'_BB − A_BB): an exact identity, no approximation. MUMPS
// factorises A_II once and returns S(A) (ICNTL(19)); every later A' of the sequence costs one
// dense Cholesky factorisation of S(A') (|B|³/3 flops) plus MUMPS's reduction and expansion
// (ICNTL(26) = 1, 2) instead of a sparse factorisation.
//
// This file holds the plain-data part: which rows changed between two matrices on sorted
// key patterns, and the dense Schur complement with its updates and Cholesky factor.

#include <cstdint>
#include <vector>

namespace grout {

/// The rows (and, the matrix being symmetric and stored as one triangle, columns) of the
/// entries that differ between two matrices given as sorted unique keys row · n + col with
/// their values (a key missing from one side counts as 0 there). Sorted, unique, 0-based.
std::vector<long long> changed_rows(const std::vector<long long>& old_keys,
                                    const std::vector<double>& old_values,
                                    const std::vector<long long>& new_keys,
                                    const std::vector<double>& new_values, long long n);

/// true if every entry of `rows` (sorted) is in `set` (sorted).
bool rows_within(const std::vector<long long>& rows, const std::vector<long long>& set);

/// One entry of A' − A inside B × B, in B's local numbering (i ≥ j or any order: it is
/// added to both (i, j) and (j, i), once if i = j).
struct SchurDelta {
  int i = 0, j = 0;
  double value = 0.0;
};

/// The dense Schur complement S(A) on B (|B| = size) of a base matrix A, and the Cholesky
/// factor of S(A') = S(A) + (A'_BB − A_BB) of the current matrix.
class DenseSchur {
 public:
  /// Set S(A) from MUMPS's centralised Schur complement (ICNTL(19) = 1: size × size, the
  /// lower triangle by rows, the other undefined) and factorise it. Returns false if S(A) is
  /// not positive definite (A not SPD) or an entry was not written (still NaN): the caller
  /// must not use it then.
  bool set_base(int size, std::vector<double>& mumps_schur);
  /// A buffer of size² NaNs for MUMPS to write S(A) into.
  static std::vector<double> prepare(int size);
  /// Factorise S(A) + the deltas (Cholesky, LAPACK dpotrf). false if not positive definite.
  bool update(const std::vector<SchurDelta>& deltas);
  /// x ← S(A')⁻¹ x (dpotrs) with the last successful factorisation.
  void solve(double* x) const;
  int size() const { return size_; }

 private:
  bool factorise(std::vector<double> matrix);
  int size_ = 0;
  std::vector<double> base_;    // S(A), full, column-major
  std::vector<double> factor_;  // Cholesky factor (lower) of the current S(A')
};

}  // namespace grout
