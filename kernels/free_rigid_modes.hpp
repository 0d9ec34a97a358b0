#pragma once
// The free rigid motions of a body (those that move none of its prescribed dofs) and the part
// of a displacement field along them: the data of the Newton step's limit on a free rigid
// rotation (nonlinear/free_rotation_limit.hpp).
//
// Rigid modes about a point X0, lengths scaled by L (so that translations and rotations have
// the same size): r_a(X) = e_a for a < d, and the rotations r_{d+k}(X) = e_k × (X − X0)/L
// (3D, k = 0, 1, 2) or e_z × (X − X0)/L (2D, one). A rigid motion is w(X) = Σ_a β_a r_a(X).
// Gram matrices over the dofs (n, c) of a body: G_ab = Σ r_a(X_n)_c r_b(X_n)_c over all of
// them, P_ab the same sum over the prescribed ones. A rigid motion β is free iff βᵀPβ = 0.
// The free modes are the generalized eigenvectors P v = μ G v with μ ≤ free_tolerance:
// G = C Cᵀ (Cholesky), the symmetric eigenproblem of C⁻¹ P C⁻ᵀ by cyclic Jacobi rotations
// (Golub & Van Loan, "Matrix Computations", 4th ed., §8.5.3), v = C⁻ᵀ y. They come out
// G-orthonormal, so that the least-squares rigid fit β = G⁻¹b of a field δ over the body
// (b_a = Σ r_a · δ) has the free part β_f = Σ_k v_k (v_kᵀ b) (its G-orthogonal projection).
//
// Plain data, fixed capacities, nothing allocated or thrown.

#include <cmath>

#include "kernels/kernel_macros.hpp"

namespace grout {

constexpr int max_rigid_modes = 6;

GROUT_INLINE_FUNCTION int rigid_mode_count(int dim) {
  return dim == 3 ? 6 : 3;
}

/// \brief r_a(X): the dim components of rigid mode `a` at X (about X0, lengths over L).
GROUT_INLINE_FUNCTION void rigid_mode_value(int dim, int a, const double* X, const double* X0,
                                            double L, double* r) {
  for (int c = 0; c < dim; ++c) r[c] = 0.0;
  if (a < dim) {
    r[a] = 1.0;
    return;
  }
  double d[3] = {0.0, 0.0, 0.0};
  for (int c = 0; c < dim; ++c) d[c] = (X[c] - X0[c]) / L;
  if (dim == 2) {  // e_z × d
    r[0] = -d[1];
    r[1] = d[0];
    return;
  }
  const int k = a - 3;  // e_k × d
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  r[i] = -d[j];
  r[j] = d[i];
}

/// \brief w(X) = Σ_a β_a r_a(X), its dim components in w.
GROUT_INLINE_FUNCTION void rigid_motion_value(int dim, const double* beta, const double* X,
                                              const double* X0, double L, double* w) {
  for (int c = 0; c < dim; ++c) w[c] = 0.0;
  for (int a = 0; a < rigid_mode_count(dim); ++a) {
    double r[3];
    rigid_mode_value(dim, a, X, X0, L, r);
    for (int c = 0; c < dim; ++c) w[c] += beta[a] * r[c];
  }
}

/// \brief Eigenvalues (on the diagonal of `a` on return) and eigenvectors (columns of `v`) of
/// the symmetric n×n matrix `a`, n ≤ max_rigid_modes, by cyclic Jacobi rotations until the
/// off-diagonal part is below 1e-15 of the Frobenius norm (Golub & Van Loan §8.5.3).
GROUT_INLINE_FUNCTION void symmetric_jacobi_eigen(int n, double a[max_rigid_modes][max_rigid_modes],
                                                  double v[max_rigid_modes][max_rigid_modes]) {
  double norm2 = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      v[i][j] = i == j ? 1.0 : 0.0;
      norm2 += a[i][j] * a[i][j];
    }
  for (int sweep = 0; sweep < 60; ++sweep) {
    double off2 = 0.0;
    for (int p = 0; p < n; ++p)
      for (int q = p + 1; q < n; ++q) off2 += 2.0 * a[p][q] * a[p][q];
    if (off2 <= 1e-30 * norm2 || off2 == 0.0) return;
    for (int p = 0; p < n; ++p)
      for (int q = p + 1; q < n; ++q) {
        if (a[p][q] == 0.0) continue;
        // The rotation (c, s) that zeroes a_pq (Golub & Van Loan Alg. 8.5.1).
        const double tau = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t = (tau >= 0.0 ? 1.0 : -1.0) / (std::fabs(tau) + std::sqrt(1.0 + tau * tau));
        const double c = 1.0 / std::sqrt(1.0 + t * t), s = t * c;
        for (int k = 0; k < n; ++k) {  // A ← A J
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < n; ++k) {  // A ← Jᵀ A
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < n; ++k) {  // V ← V J
          const double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
  }
}

/// The free rigid modes of a body.
struct FreeRigidModes {
  int n = 0;      ///< rigid modes: 3 (2D) or 6 (3D)
  int count = 0;  ///< free modes
  double basis[max_rigid_modes][max_rigid_modes] =
      {};                                            ///< basis[k]: free mode k (β), G-orthonormal
  bool translation_free[3] = {false, false, false};  ///< e_c moves no prescribed dof
  /// A free mode turns the body: max_k |rotation part of v_k| > rotation_tolerance.
  bool rotates = false;
};

constexpr double free_tolerance = 1e-12;     ///< μ of a free mode, relative to G
constexpr double rotation_tolerance = 1e-8;  ///< |rotation part| of a G-normalised mode

/// \brief The free rigid modes from G and P (n×n, n = rigid_mode_count(dim)).
/// \return false if G is not positive definite (the body's nodes are collinear, or none).
GROUT_INLINE_FUNCTION bool free_rigid_modes(int dim,
                                            const double G[max_rigid_modes][max_rigid_modes],
                                            const double P[max_rigid_modes][max_rigid_modes],
                                            FreeRigidModes& out) {
  const int n = rigid_mode_count(dim);
  out = FreeRigidModes{};
  out.n = n;
  // Cholesky G = C Cᵀ (C lower triangular).
  double C[max_rigid_modes][max_rigid_modes] = {};
  double trace = 0.0;
  for (int i = 0; i < n; ++i) trace += G[i][i];
  for (int j = 0; j < n; ++j) {
    double d = G[j][j];
    for (int k = 0; k < j; ++k) d -= C[j][k] * C[j][k];
    if (!(d > 1e-12 * trace)) return false;
    C[j][j] = std::sqrt(d);
    for (int i = j + 1; i < n; ++i) {
      double s = G[i][j];
      for (int k = 0; k < j; ++k) s -= C[i][k] * C[j][k];
      C[i][j] = s / C[j][j];
    }
  }
  // Z = C⁻¹ P (forward substitution per column), then A = Z C⁻ᵀ = C⁻¹ P C⁻ᵀ.
  double Z[max_rigid_modes][max_rigid_modes] = {}, A[max_rigid_modes][max_rigid_modes] = {};
  for (int col = 0; col < n; ++col)
    for (int i = 0; i < n; ++i) {
      double s = P[i][col];
      for (int k = 0; k < i; ++k) s -= C[i][k] * Z[k][col];
      Z[i][col] = s / C[i][i];
    }
  for (int row = 0; row < n; ++row)
    for (int i = 0; i < n; ++i) {  // A[row][i] = (C⁻¹ Z[row][:]ᵀ)_i
      double s = Z[row][i];
      for (int k = 0; k < i; ++k) s -= C[i][k] * A[row][k];
      A[row][i] = s / C[i][i];
    }
  for (int i = 0; i < n; ++i)  // symmetric up to round-off
    for (int j = i + 1; j < n; ++j) A[i][j] = A[j][i] = 0.5 * (A[i][j] + A[j][i]);
  double Y[max_rigid_modes][max_rigid_modes];
  symmetric_jacobi_eigen(n, A, Y);
  for (int e = 0; e < n; ++e) {
    if (!(A[e][e] <= free_tolerance)) continue;
    // v = C⁻ᵀ y (back substitution).
    double* v = out.basis[out.count++];
    for (int i = n - 1; i >= 0; --i) {
      double s = Y[i][e];
      for (int k = i + 1; k < n; ++k) s -= C[k][i] * v[k];
      v[i] = s / C[i][i];
    }
    double rot2 = 0.0;
    for (int a = dim; a < n; ++a) rot2 += v[a] * v[a];
    if (std::sqrt(rot2) > rotation_tolerance) out.rotates = true;
  }
  for (int c = 0; c < dim; ++c) out.translation_free[c] = P[c][c] == 0.0;
  return true;
}

/// \brief β_f = Σ_k v_k (v_kᵀ b): the free part of the least-squares rigid fit of a field whose
/// moments on the rigid modes are b.
GROUT_INLINE_FUNCTION void free_rigid_part(const FreeRigidModes& modes, const double* b,
                                           double* beta) {
  for (int a = 0; a < modes.n; ++a) beta[a] = 0.0;
  for (int k = 0; k < modes.count; ++k) {
    double vb = 0.0;
    for (int a = 0; a < modes.n; ++a) vb += modes.basis[k][a] * b[a];
    for (int a = 0; a < modes.n; ++a) beta[a] += modes.basis[k][a] * vb;
  }
}

}  // namespace grout
