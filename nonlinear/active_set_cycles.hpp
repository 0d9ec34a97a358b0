#pragma once
// Breaking a cycle of the active set within a step.
//
// The semi-smooth Newton method (the primal-dual active set strategy: Hintermüller, Ito &
// Kunisch 2002, SIAM J. Optim. 13(3), 865–888; for mortar contact Hüeber & Wohlmuth 2005,
// CMAME 194, 3147–3166) chooses node j's status at iterate k from that iterate's
// s_j = λ_n − ĉ g_j: closed (the row ĉ g_j = 0) if s_j ≥ −tol, else open (λ_j = 0). It need not
// converge: even on a linear complementarity problem with a P-matrix the plain iteration can
// cycle (Ben Gharbia & Gilbert 2012, Math. Program. 134, 349–364), and the mortar problem is
// not linear (the pairing, and with it D and M, follows the current positions). A node then
// toggles: solved closed, it pulls (λ_n < 0, so s_j < 0 and it opens); solved open, it
// penetrates (g_j < 0, so s_j > 0 and it closes). Neither state satisfies the contact
// conditions exactly at its own solution, and Newton never sees an unchanged active set
// (inputs/start_family/README.md: one 3D node, 52 ↔ 53 active nodes for 25 iterations).
//
// The rule here: a node is fixed, for the rest of the step, in the state whose own solution
// violated the contact conditions less, once its statuses have gone round a cycle of the
// Newton map: it changed at least `max_status_changes` times between consecutive iterates of
// the step (A B A B A), and it left each state the last two times by the same violation to
// `cycle_tolerance` (relative): the iterates repeat themselves, and so would the next ones. The
// violation of a state is |s_j| at the first evaluation after an iterate solved in it, where
// the law left it: leaving "closed" (g_j ≈ 0), |s_j| ≈ |λ_n|, the tension it carried; leaving
// "open" (λ_j = 0), |s_j| = ĉ |g_j|, the penetration times ĉ; both are pressures, the NCP
// residual |λ_n − max(0, s_j)| of that state. The fixed node's row is then smooth (ĉ g_j = 0,
// or λ_j = 0), Newton converges on it as on any other node, and the converged state satisfies
// every other node's contact conditions to the Newton tolerance and the fixed node's to within
// what its state shows there (the driver prints both violations when it fixes the node;
// docs/design.md §2). A node that toggles while the iterates still move (a sliding contact
// edge, the first iterates after a start) leaves its states by other amounts each time and is
// never fixed: such steps are untouched, bit for bit (inputs/start_family/README.md).

#include <limits>

namespace grout {

/// Status changes of a node within a step before it can be fixed.
constexpr int max_status_changes = 4;
/// Relative difference below which two violations of one state are the same.
constexpr double cycle_tolerance = 1e-6;

/// One slave node's statuses over the Newton iterates of a step (plain data; reset per step).
struct NodeStatusHistory {
  int iterate = -1;         ///< iterate of the latest evaluation (−1: none in this step)
  signed char closed = 0;   ///< status at the latest evaluation (1 closed, 0 open)
  signed char before = -1;  ///< status at the last evaluation of the previous iterate (−1: none)
  int changes = 0;          ///< changes between consecutive iterates, up to `before`
  double pending = 0.0;     ///< |s_j| of the latest evaluation, if it left `before`
  /// Per state (0 open, 1 closed): |s_j| the last two times the law left it (+∞: not yet).
  double left[2][2] = {
      {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()},
      {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()}};
  double violation[2] = {0.0, 0.0};  ///< once fixed: the violations of open and closed
  signed char fixed = -1;  ///< −1: free; 0 or 1: the status fixed for the rest of the step
};

/// Records node's status `closed` (the law's, with the start rules applied) and s = λ_n − ĉ g at
/// an evaluation of Newton iterate `iterate` (line-search trials and repeated evaluations of an
/// iterate replace its status; the last one counts). \return the fixed status (0 open, 1 closed)
/// once the node cycles (the rule above), the state of the smaller violation (a tie keeps it
/// closed); else −1. \pre max_changes ≥ 4 (each state left twice).
int record_node_status(NodeStatusHistory& node, int iterate, bool closed, double s,
                       int max_changes = max_status_changes, double tolerance = cycle_tolerance);

}  // namespace grout
