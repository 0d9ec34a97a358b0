#pragma once
// Limiting the closing of the active set while it is far from settled.
//
// The semi-smooth Newton method chooses the active set at iterate k + 1 from the iterate
// (λ_n − ĉ g > 0). From a start with a few active slave nodes (the proximity start of a step
// that begins at first touch) the first update carries the load on those few nodes: the
// bodies sink into each other well past the converged approach and every node of the
// overshoot becomes active (2D Hertz, docs/performance.md: 7 → 49 nodes, converged 37). The
// superset is then released a few edge nodes per iteration (49 → 45 → 41 → 39 → 37), one
// factorisation each. Here, at an iterate where more nodes close than were active before
// (the active set is far from settled), a closing node (inactive at the last evaluation,
// active by λ_n − ĉ g now, open at the last evaluation) stays inactive for this iterate when
// it closes late in the update: its closing fraction
//     s_j = g_prev / (g_prev − g),   g_prev the gap at the last evaluation, g the gap now,
// (the fraction of the update, along the straight path from the last to the new positions,
// at which node j's gap reaches 0) is above `max_fraction`. That is the active set of the
// point x_prev + max_fraction (x − x_prev) for the closing nodes. A node is held back at most
// once per step, and a held-back node counts as an active-set change, so that the iterate is
// never taken as converged: the converged state satisfies the contact conditions exactly and
// does not depend on this limit. A step that only grows its contact zone by a few nodes (most
// multi-step runs) is left alone.

#include <vector>

namespace grout {

/// One owned slave node at the first update of a step.
struct ClosureCandidate {
  bool paired = false;      ///< has a master (D_jj above its tolerance)
  bool was_active = false;  ///< active at the previous iterate (the step's start)
  bool closing = false;     ///< not was_active, and active by λ_n − ĉ g now
  double gap = 0.0;         ///< g_j now
  double gap_old = 0.0;     ///< g_j at the last converged state (same D, M, normals)
};

/// Counts over the owned nodes (summed over the ranks by the caller).
struct ClosureCounts {
  double active_before = 0.0;  ///< paired, was_active
  double closing = 0.0;        ///< paired, closing, open at the last converged state
};

ClosureCounts count_closures(const std::vector<ClosureCandidate>& nodes);

/// Per node: 1 = keep inactive at this iterate. All 0 unless global.closing >
/// global.active_before; else 1 for each closing node, open at the last converged state
/// (gap_old > 0), whose closing fraction gap_old / (gap_old − gap) exceeds max_fraction.
/// \pre 0 < max_fraction; max_fraction >= 1 never holds a node back.
std::vector<char> held_back_closures(const std::vector<ClosureCandidate>& nodes,
                                     const ClosureCounts& global, double max_fraction);

}  // namespace grout
