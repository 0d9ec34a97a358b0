#pragma once
// How the active set of one contact interface is chosen at a Newton iterate, beyond the
// semi-smooth rule λ_n − ĉ g > 0 of the contact law (docs/design.md §2). Two start rules, both
// of which depend on where the iterate sits in the step's Newton iteration, given explicitly
// (NewtonPhase), never inferred from the order in which the residual and the Jacobian are
// asked for:
// - proximity (the step's start, before any Newton update): a node with no pressure and a
//   gap below start_gap × the mean size of its faces counts as active, as Kratos' active
//   check does. A body held only by contact then has its rigid motion fixed by several
//   contact rows from the first solve (with none, K is singular; with one, the first update
//   is a huge rigid motion). From the next iterate on only the law decides, so the converged
//   state satisfies the contact conditions exactly.
// - closure hold-back (after the first update: first_update_closures.hpp): while the active
//   set is far from settled, a node that closes late in the update stays open for one
//   iterate, at most once per step.
// And one rule against a cycling active set (active_set_cycles.hpp): a node whose statuses go
// round a cycle of the Newton map (at least max_status_changes changes in a step, each state
// left the last two times by the same violation) is fixed for the rest of the step in the
// state that its own solution violated less. Each node is decided by the rank that owns it, from
// its own history, so the decisions need no communication and do not depend on the rank count.

#include <vector>

#include "nonlinear/active_set_cycles.hpp"
#include "nonlinear/first_update_closures.hpp"

namespace grout {

/// Where an iterate sits in the Newton iteration of a load or time step.
enum class NewtonPhase {
  step_start,    ///< the step's initial guess: no Newton update yet
  first_update,  ///< after the first update (and its line-search trials)
  later,         ///< after two or more updates
};

/// The phase of Newton iterate k of a step (k = 0: the initial guess; line-search trials of
/// update k are iterate k).
inline NewtonPhase newton_phase(int iterate) {
  return iterate <= 0   ? NewtonPhase::step_start
         : iterate == 1 ? NewtonPhase::first_update
                        : NewtonPhase::later;
}

class ActiveSetPolicy {
 public:
  ActiveSetPolicy() = default;
  /// proximity: per owned slave node, start_gap × the mean size of its faces;
  /// max_closure_fraction: the contact input's start_closure (≥ 1: no hold-back).
  ActiveSetPolicy(std::vector<double> proximity, double max_closure_fraction);

  /// A new step: every node may be held back once again, and no node's status is fixed.
  void begin_step();
  /// Proximity rule: node q counts as active at this iterate although λ_n − ĉ g < 0.
  bool near(int q, double lambda_n, double gap, NewtonPhase phase) const {
    return phase == NewtonPhase::step_start && lambda_n <= 0.0 && gap <= proximity_[q];
  }
  /// Whether the hold-back applies at this phase (then the caller sums count_closures of
  /// its candidates over the ranks and calls held_back).
  bool holds_back(NewtonPhase phase) const {
    return phase != NewtonPhase::step_start && max_closure_fraction_ < 1.0;
  }
  /// Per owned node: 1 = open at this iterate (held_back_closures with the summed counts,
  /// each node at most once per step; none when !holds_back(phase)). Records the nodes held.
  std::vector<char> held_back(const std::vector<ClosureCandidate>& nodes,
                              const ClosureCounts& global, NewtonPhase phase);
  /// Cycle rule: records owned node q's status at Newton iterate `iterate` (closed: the law's
  /// decision with the start rules applied; s = λ_n − ĉ g). \return the status fixed for the
  /// rest of the step (0 open, 1 closed), or −1: the law decides (record_node_status).
  int fixed_status(int q, int iterate, bool closed, double s) {
    return record_node_status(status_history_[q], iterate, closed, s);
  }
  bool fixed(int q) const { return status_history_[q].fixed >= 0; }
  /// Once fixed: |λ_n − ĉ g| where the law left state `closed` (1) or open (0) in the cycle.
  double violation(int q, bool closed) const { return status_history_[q].violation[closed]; }
  /// The status fixed for node q (0 open, 1 closed; −1: none).
  int fixed_state(int q) const { return status_history_[q].fixed; }

 private:
  std::vector<double> proximity_;
  double max_closure_fraction_ = 1.0;
  std::vector<char> held_in_step_;                 ///< held back once in this step already
  std::vector<NodeStatusHistory> status_history_;  ///< per owned node, of this step
};

}  // namespace grout
