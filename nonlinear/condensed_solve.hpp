#pragma once
// Static condensation of the dual-mortar multipliers (Popp et al. 2009/2010, "condensed"
// system), done generically on an assembled (u, λ) system J x = b (docs/design.md §2, "Solve").
//
// Every multiplier dof t is paired with one slave displacement dof s(t), whose force row
// holds D_t λ_t (J[s, t] = D_t ≠ 0) and no other multiplier that is not known directly.
// Per pair, in this order of preference:
//   A  λ-row t is an identity row (only J[t, t] ≠ 0): λ_t = b_t / J[t, t], substituted
//      everywhere; the slave row s stays in the reduced system.
//   B  J[s, t] ≠ 0: λ_t = (b_s − Σ_u J[s, u] x_u − Σ_A J[s, t'] λ_t') / J[s, t] is
//      substituted into every other row with a λ_t column; row s is consumed and a λ-row of
//      the same node takes its place in the reduced system.
//   C  row s holds only its diagonal (a prescribed slave dof, whose λ column was eliminated):
//      x_s = b_s / J[s, s] is known; the unknown of slot s becomes λ_t, and a λ-row of the
//      node takes the place of row s.
//   D  as C, but no λ-row of the node holds λ_t (tied or sticking: the rows constrain only
//      displacements), so slot s would get a zero diagonal. λ_t is eliminated with another
//      displacement row r instead, the one with the largest |J[r, t]| (a master row, where
//      −M_jl λ_t acts): λ_t = (b_r − Σ_{c≠t} J[r, c] x_c) / J[r, t], substituted (with the
//      multipliers of row r) into every other row with a λ_t column. Row s stays the
//      prescribed row x_s = b_s / J[s, s], and a λ-row of the node (the tie, now on the
//      master dofs) takes slot r. The reduced system keeps only displacement unknowns.
//      A pivot must be a coupling, not round-off: |J[r, t]| > 1e-12 × the largest |J[r', t']|
//      over all displacement rows r' and paired multipliers t' (the scale of D and M).
//   R  as D, but no row other than the prescribed ones holds λ_t above that bound: the slave
//      dof and every master dof it is tied to are prescribed (a tie on a Dirichlet boundary;
//      e.g. the dual basis makes M_jl vanish analytically for a master node l whose shape
//      function is linear over the slave node's support, and the integration leaves ~1e-17
//      there). λ_t then acts on prescribed dofs only, whose reactions absorb it: it is not
//      determined by the system (in exact arithmetic J has a zero column t and a λ-row that
//      constrains prescribed dofs only), and is set to λ_t = 0, the minimum-norm choice: the
//      Dirichlet reaction carries the load there. Its entries below the bound are dropped as
//      round-off, row s stays the prescribed row, and the node keeps one λ-row fewer than it
//      has pairs: the λ-rows left out are those the assignment below does not place; a row
//      that is round-off next to the node's other λ-rows (the tie of prescribed dofs only,
//      ĉ (D u_s − Σ M_jl u_l) / D with every u prescribed) is never placed. A full direct
//      solve of such a J keeps the noise and divides by it (huge λ_t, a master dof pinned by
//      a round-off row); the condensation matches a direct solve of J with those entries
//      zeroed and λ_t = 0 imposed. MechanicsProblem itself writes such a tie as the row
//      λ_t = 0 (kind A); kind R is the condensation's own guard for any other J.
// The reduced system lives on the displacement dofs of J's row map (every GID that is not a
// paired multiplier). Within a node (the pairs whose slave dofs share s / dofs_per_node),
// the λ-rows are assigned to the node's B/C/D slots by the permutation with the largest
// product of |diagonal| / max|row|, then each such row is scaled so that its diagonal is
// positive and as large as |J[s, s]|: the reduced matrix keeps a stiffness-like diagonal
// (for relaxation smoothers and MueLu); it is not symmetric. The row assignment and scaling
// do not change the solution.
//
// Any other structure (a slave row with two unknown multipliers, a pair of type C whose
// slave row has off-diagonal entries) is reported with std::runtime_error on every rank.

#include <memory>
#include <utility>
#include <vector>

#include "assembly/tpetra_types.hpp"
#include "nonlinear/multiplier_rows.hpp"

namespace grout {

/// (multiplier GID, slave displacement GID), one entry per multiplier dof; the same complete
/// list on every rank.
using MultiplierPairing = std::vector<std::pair<GO, GO>>;

class MultiplierCondensation {
 public:
  /// Throws std::invalid_argument if a multiplier or a slave dof occurs twice, or a
  /// multiplier is also a slave dof.
  MultiplierCondensation(const MultiplierPairing& lambda_to_slave, int dofs_per_node = 1);
  ~MultiplierCondensation();

  /// Build the reduced system of J x = b (collective). J fill-complete with row map = range
  /// map = domain map = b's map.
  /// `declared` (optional): the kinds of the multiplier rows as their writer declares them
  /// (multiplier_rows.hpp): a pair is of kind A iff its λ-row is declared an identity (or
  /// pure-λ on its own multiplier alone); undeclared rows are classified from J. Throws
  /// std::logic_error, on every rank, if a declared identity row of J holds anything but its
  /// diagonal.
  void condense(const Matrix& J, const Vector& b, const MultiplierRows* declared = nullptr);
  /// The reduced matrix and right-hand side, on the displacement dofs of J's row map.
  Teuchos::RCP<const Matrix> matrix() const;
  const Vector& rhs() const;
  /// The solution x of J x = b (on J's row map) from the solution y of the reduced system.
  void expand(const Vector& y, Vector& x) const;

  struct Statistics {
    int identity = 0;        ///< pairs of kind A
    int eliminated = 0;      ///< pairs of kind B
    int swapped = 0;         ///< pairs of kind C
    int zero_diagonals = 0;  ///< reduced rows left with a zero diagonal (direct solver only)
    int master_pivots = 0;   ///< pairs of kind D
    int redundant = 0;       ///< pairs of kind R (λ = 0: all its dofs prescribed)
  };
  /// Of the last condense(), global.
  const Statistics& statistics() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace grout
