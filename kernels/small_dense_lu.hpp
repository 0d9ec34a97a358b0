#pragma once
// One small dense LU with partial pivoting, for the few-unknown systems of the contact
// algebra: the pivot blocks of the multiplier condensation (nonlinear/condensed_solve.cpp),
// the per-node blocks of the symmetric reduction (nonlinear/symmetric_condensation.cpp) and
// the dual basis's element mass matrix (kernels/dual_basis.hpp; QUAD4: dual_basis_3d.hpp).
//
//   P A = L U        (Golub & Van Loan, "Matrix Computations", 4th ed., Alg. 3.4.1)
//
// L is unit lower triangular, U upper triangular, P the row swaps: at step k the row of the
// largest |a_ik|, i ≥ k, of the current Schur complement becomes the pivot row (partial
// pivoting; for Sacado scalars the comparisons use the value part). A x = b is then solved by
// x = U⁻¹ L⁻¹ P b, and A⁻¹ column by column from the unit vectors. Gauss–Jordan elimination
// with the same partial pivoting (what the callers did before) meets the same pivots, so a
// pivot threshold keeps its meaning.
//
// Plain data: the matrix is row-major in caller memory with a row stride `lda` ≥ n (a
// Scalar[N][N] array holds an n×n matrix with lda = N), the pivots in an int[n]; nothing is
// allocated, nothing is thrown, so that device code can call it.

#include <cmath>

#include "kernels/kernel_macros.hpp"

namespace grout {

/// \brief In-place LU factorisation with partial pivoting, P A = L U, of the n×n matrix `a`
/// (row-major, row stride lda): on return U is on and above the diagonal, L's multipliers
/// below it, and row k was swapped with row pivot[k] ≥ k at step k.
/// \return false, with `a` partly factorised, if a pivot's magnitude is not above
/// `singular_at` (0: an exactly zero pivot; a relative threshold tol · max|a_ij| is the
/// caller's to compute; a Sacado scalar compares by its value).
template <class Scalar, class Bound = double>
GROUT_INLINE_FUNCTION bool small_lu_factor(int n, Scalar* a, int lda, int* pivot,
                                           const Bound& singular_at = Bound(0)) {
  using std::abs;
  for (int k = 0; k < n; ++k) {
    int p = k;
    for (int i = k + 1; i < n; ++i)
      if (abs(a[i * lda + k]) > abs(a[p * lda + k])) p = i;
    pivot[k] = p;
    if (!(abs(a[p * lda + k]) > singular_at)) return false;
    if (p != k)
      for (int j = 0; j < n; ++j) {
        const Scalar t = a[k * lda + j];
        a[k * lda + j] = a[p * lda + j];
        a[p * lda + j] = t;
      }
    for (int i = k + 1; i < n; ++i) {
      const Scalar l = a[i * lda + k] / a[k * lda + k];
      a[i * lda + k] = l;
      for (int j = k + 1; j < n; ++j) a[i * lda + j] -= l * a[k * lda + j];
    }
  }
  return true;
}

/// \brief b ← A⁻¹ b with the factorisation of small_lu_factor (`lu`, `pivot`): the row swaps,
/// forward substitution with L, back substitution with U. b has stride `incb` (1: contiguous;
/// the row stride of a matrix: one of its columns).
template <class Scalar>
GROUT_INLINE_FUNCTION void small_lu_solve(int n, const Scalar* lu, int lda, const int* pivot,
                                          Scalar* b, int incb = 1) {
  for (int k = 0; k < n; ++k)
    if (pivot[k] != k) {
      const Scalar t = b[k * incb];
      b[k * incb] = b[pivot[k] * incb];
      b[pivot[k] * incb] = t;
    }
  for (int i = 1; i < n; ++i)
    for (int j = 0; j < i; ++j) b[i * incb] -= lu[i * lda + j] * b[j * incb];
  for (int i = n - 1; i >= 0; --i) {
    for (int j = i + 1; j < n; ++j) b[i * incb] -= lu[i * lda + j] * b[j * incb];
    b[i * incb] /= lu[i * lda + i];
  }
}

/// \brief inverse = A⁻¹ (row-major, row stride ldi) by small_lu_factor of `a` in place, then
/// one small_lu_solve per unit vector; `pivot` is n ints of workspace.
/// \return false (inverse not set) if small_lu_factor finds a pivot not above `singular_at`.
template <class Scalar, class Bound = double>
GROUT_INLINE_FUNCTION bool small_lu_invert(int n, Scalar* a, int lda, int* pivot, Scalar* inverse,
                                           int ldi, const Bound& singular_at = Bound(0)) {
  if (!small_lu_factor(n, a, lda, pivot, singular_at)) return false;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) inverse[i * ldi + j] = i == j ? 1.0 : 0.0;
  for (int j = 0; j < n; ++j) small_lu_solve(n, a, lda, pivot, inverse + j, ldi);
  return true;
}

}  // namespace grout
