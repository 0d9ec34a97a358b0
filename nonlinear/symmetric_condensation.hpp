#pragma once
// Symmetric (null-space) reduction of an assembled dual-mortar (u, λ) system J x = b, for
// frictionless and tied contact with fixed pairing and small strain, where the Newton system
// is a symmetric saddle point in disguise (docs/design.md §2, "Solve"; null-space method: Benzi,
// Golub, Liesen, "Numerical solution of saddle point problems", Acta Numerica 2005, §6;
// master/slave elimination of the dual mortar constraints: Wohlmuth 2000, Popp et al. 2010).
//
// J's rows split into displacement rows K u + C λ = b_u and multiplier rows, one per pair
// (λ_t, slave dof s(t)) (condensed_solve.hpp). Per slave node j (the pairs whose slave dofs
// share s / dofs_per_node) every λ-row of the node must be either
//   pure-λ:      P_j λ_j = p_j        (λ = 0 of an inactive node, τ_k·λ = 0 of an active
//                                     frictionless one), or
//   a constraint: G_j u = g_j         (ĉ g = 0 of an active node, the ties of a tied one),
// with rank P_j = r and k = d − r constraint rows (d = the node's pairs). Then λ_j = λ0_j +
// N_j μ_j, N_j (d × k) spanning ker P_j, and if C N_j = G_jᵀ R_j for an invertible R_j (the
// multiplier acts along the constraint's gradient, as D and M do for a fixed pairing) the
// system is
//        [ K   Gᵀ ] [ u  ]   [ b_u − C λ0 ]
//        [ G   0  ] [ μ' ] = [ g          ],   μ' = R μ,
// symmetric when K is. One slave dof per constraint row is eliminated: per node the k
// unprescribed slave dofs chosen by Gaussian elimination with complete pivoting on the node's
// slave block of G_j (each row scaled by its largest entry), u_e = G_e⁻¹ (g − G_f u_f).
// With u = T ũ + c (T = I on the kept dofs, −G_e⁻¹ G_f on the eliminated ones, c_e = G_e⁻¹ g),
//        K̃ ũ = b̃,   K̃ = Tᵀ K T,   b̃ = Tᵀ (b_u − C λ0 − K c),
// (K̃ built as K plus the corrections of the rows and columns that T couples, no general
// triple product: T is the identity but on the eliminated dofs),
// since Tᵀ Gᵀ = (G T)ᵀ = 0 removes μ. K̃ is symmetric positive (semi)definite for an elastic K:
// MUMPS factorises it as LDLᵀ. λ is then recovered per node from its pure-λ rows and its
// unprescribed slave force rows, C_s λ_j = b_s − K_s u (the kind B recovery of
// condensed_solve.hpp).
//
// condense() CHECKS every premise and returns false (on every rank alike) when one fails:
// K = J[u, u] symmetric (|K_ij − K_ji| ≤ 1e-12 × the row's largest entry), every λ-row
// pure-λ or pure-u, P_j of full rank, a slave pivot per constraint row above 1e-8 of its
// row, C N_j = G_jᵀ R_j to 1e-10 of C N_j's largest entry, no eliminated dof in another
// node's constraint, slave force rows without other nodes' multipliers, λ_j recoverable.
// Sticking frictional nodes on the reference geometry pass (their stick rows are
// displacement constraints, like ties). Slip (its rows mix u and λ) and `geometry: current`
// (normals, D and M depend on u: K and the tangential rows carry λ terms) fail them: the caller
// then uses MultiplierCondensation (not symmetric) instead.
//
// The reduced system lives on J's displacement GIDs, renumbered 0 .. n − 1 in GID order (new
// = old − the paired multipliers below old), so that a direct solver sees the same matrix on
// any number of ranks. An eliminated dof keeps its row as ũ_e = 0 (K̃_ee = K_ee, b̃_e = 0,
// and the pattern of (K T)'s row e and its transpose as explicit zeros): the size and, mostly, the
// pattern do not depend on the active set, and MUMPS reuses its analysis across Newton iterations
// while the pattern stays within the union of the earlier ones (mumps_solver.hpp).

#include <memory>
#include <string>

#include "nonlinear/condensed_solve.hpp"

namespace grout {

class SymmetricCondensation {
 public:
  /// Same pairing as MultiplierCondensation; throws std::invalid_argument on a repeated
  /// multiplier or slave dof.
  SymmetricCondensation(const MultiplierPairing& lambda_to_slave, int dofs_per_node = 1);
  ~SymmetricCondensation();

  /// Build K̃ and b̃ of J x = b (collective). J fill-complete with row map = range map =
  /// domain map = b's map. Returns false, the same on every rank, if J is not of the form
  /// above (reason() says why); matrix(), rhs() and expand() are then not to be used.
  /// `declared` (optional, multiplier_rows.hpp): each λ-row is pure-λ, a constraint or mixed
  /// (then condense() returns false) as its writer declares it, and J's row must agree (a
  /// disagreement is reported as a failed check naming the row, so that the caller falls
  /// back); undeclared rows are classified from J.
  bool condense(const Matrix& J, const Vector& b, const MultiplierRows* declared = nullptr);
  /// K̃ and b̃ on the reduced map. K̃'s values are symmetric; the product's exact zeros (J's
  /// prescribed rows and columns) are dropped, and the eliminated rows hold explicit zeros
  /// (in their row only) for the pattern (above).
  Teuchos::RCP<const Matrix> matrix() const;
  const Vector& rhs() const;
  /// T of u = T ũ + c (J's row map × K̃'s map), for tests: off the eliminated rows K̃ equals
  /// the product Tᵀ J T without its exact zeros.
  Teuchos::RCP<const Matrix> transformation() const;
  /// The solution x of J x = b (on J's row map) from the solution y of K̃ y = b̃ (collective).
  void expand(const Vector& y, Vector& x) const;
  /// Why the last condense() returned false (the first failed check found on any rank).
  const std::string& reason() const;

  struct Statistics {
    int nodes = 0;       ///< slave nodes (global)
    int eliminated = 0;  ///< eliminated slave dofs = constraint rows (global)
  };
  const Statistics& statistics() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace grout
