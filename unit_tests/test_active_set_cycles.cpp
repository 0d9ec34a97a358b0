// The cycle rule of nonlinear/active_set_cycles.hpp on hand-made status sequences: a node that
// toggles between open and closed with repeating violations is fixed after max_status_changes
// changes, in the state of the smaller violation |s|; line-search trials of one iterate count
// once; a node that settles, or toggles with changing violations, is never fixed;
// ActiveSetPolicy keeps one history per node and forgets it at a new step.
#include <gtest/gtest.h>

#include "nonlinear/active_set_cycles.hpp"
#include "nonlinear/active_set_policy.hpp"

namespace grout {
namespace {

constexpr bool open = false, closed = true;

TEST(ActiveSetCycles, FixesATogglingNodeInTheLessViolatedState) {
  // inputs/start_family/README.md, random3d_013 at a/8: the node penetrates when open
  // (s = −ĉ g = 20.5) and pulls when closed (s = λ_n = −165): open is the lesser violation.
  NodeStatusHistory node;
  EXPECT_EQ(record_node_status(node, 0, open, -43.9), -1);
  EXPECT_EQ(record_node_status(node, 1, closed, 20.5), -1);  // 1 change: open left by 20.5
  EXPECT_EQ(record_node_status(node, 2, open, -165.0), -1);  // 2: closed left by 165
  EXPECT_EQ(record_node_status(node, 3, closed, 20.5), -1);  // 3
  EXPECT_EQ(record_node_status(node, 4, open, -165.0), 0);   // 4: fixed open
  EXPECT_EQ(node.violation[0], 20.5);
  EXPECT_EQ(node.violation[1], 165.0);
  // Fixed for the rest of the step, whatever the law says.
  for (int k = 5; k < 30; ++k) EXPECT_EQ(record_node_status(node, k, k % 2 != 0, 1.0), 0);

  // The mirror case: a small tension against a deep penetration keeps the node closed.
  NodeStatusHistory other;
  EXPECT_EQ(record_node_status(other, 0, closed, 1.0), -1);
  EXPECT_EQ(record_node_status(other, 1, open, -1e-3), -1);  // closed left by 1e-3
  EXPECT_EQ(record_node_status(other, 2, closed, 7.0), -1);  // open left by 7
  EXPECT_EQ(record_node_status(other, 3, open, -1e-3), -1);  // closed left by 1e-3
  EXPECT_EQ(record_node_status(other, 4, closed, 7.0), 1);   // open left by 7: fixed closed
  EXPECT_EQ(other.violation[1], 1e-3);
  EXPECT_EQ(other.violation[0], 7.0);
}

TEST(ActiveSetCycles, WaitsUntilTheIteratesRepeat) {
  // random3d_013's first closing comes from another iterate (s = 21.08, then 20.52 each time):
  // the cycle is recognised at the fifth change, when both states have repeated.
  NodeStatusHistory node;
  const double s[] = {-43.9, 21.08, -165.0, 20.52, -165.0, 20.52};
  for (int k = 0; k < 5; ++k) EXPECT_EQ(record_node_status(node, k, s[k] > 0, s[k]), -1);
  EXPECT_EQ(record_node_status(node, 5, closed, 20.52), 0);
  // A node that toggles while the iterates move (a sliding contact edge) leaves its states by
  // other amounts each time: never fixed, however often it changes.
  NodeStatusHistory sliding;
  for (int k = 0; k < 40; ++k)
    EXPECT_EQ(record_node_status(sliding, k, k % 2 != 0, (k % 2 != 0 ? 1.0 : -1.0) * (1 + k)), -1);
  EXPECT_EQ(sliding.changes, 38);
}

TEST(ActiveSetCycles, CountsTheLastEvaluationOfEachIterate) {
  // Line-search trials of iterate 1 toggle; only the status of its last one is the iterate's.
  NodeStatusHistory node;
  record_node_status(node, 0, open, -1.0);
  for (bool trial : {closed, open, closed, open, closed}) record_node_status(node, 1, trial, 2.0);
  EXPECT_EQ(node.changes, 0);  // iterate 1 is not final yet
  EXPECT_EQ(record_node_status(node, 2, closed, 0.5), -1);
  EXPECT_EQ(node.changes, 1);  // 0 → 1 changed; 1 → 2 did not
  // A re-evaluation of the same iterate (the Jacobian's, after a trial) changes nothing.
  EXPECT_EQ(record_node_status(node, 2, closed, 0.5), -1);
  EXPECT_EQ(node.changes, 1);
  EXPECT_EQ(node.fixed, -1);
}

TEST(ActiveSetCycles, NeverFixesANodeThatSettles) {
  // Closes in the first update's overshoot, opens, closes for good (start-family random_014 and
  // random_088, converged at the next iterate): three changes, however long the step.
  NodeStatusHistory node;
  const bool states[] = {open, closed, open, closed};
  int k = 0;
  for (bool state : states) EXPECT_EQ(record_node_status(node, k++, state, 1.0), -1);
  for (; k < 40; ++k) EXPECT_EQ(record_node_status(node, k, closed, 1.0), -1);
  EXPECT_EQ(node.changes, max_status_changes - 1);
  // Changes are counted within a step, between iterates: a node that stays put has none.
  NodeStatusHistory quiet;
  for (int i = 0; i < 40; ++i) EXPECT_EQ(record_node_status(quiet, i, closed, 1.0), -1);
  EXPECT_EQ(quiet.changes, 0);
}

TEST(ActiveSetCycles, FixesEachNodeOfACyclingSet) {
  // Two nodes out of phase (one closes as the other opens): the set's size never changes, but
  // each node toggles, and each is fixed.
  NodeStatusHistory a, b;
  int fixed_a = -1, fixed_b = -1;
  for (int k = 0; k < 5; ++k) {
    fixed_a = record_node_status(a, k, k % 2 == 0, k % 2 == 0 ? 3.0 : -1.0);
    fixed_b = record_node_status(b, k, k % 2 != 0, k % 2 != 0 ? 3.0 : -1.0);
  }
  EXPECT_EQ(fixed_a, 1);  // closed left by 1, open by 3
  EXPECT_EQ(fixed_b, 1);
}

TEST(ActiveSetCycles, PolicyKeepsOneHistoryPerNodeAndStep) {
  ActiveSetPolicy policy(std::vector<double>(3, 0.1), 1.0);
  for (int k = 0; k < 5; ++k) {
    policy.fixed_status(0, k, k % 2 != 0, k % 2 != 0 ? 5.0 : -1.0);  // toggles
    policy.fixed_status(1, k, closed, 1.0);                          // stays closed
  }
  EXPECT_TRUE(policy.fixed(0));
  EXPECT_EQ(policy.fixed_status(0, 5, closed, 5.0), 1);  // closed left by 1, open by 5
  EXPECT_EQ(policy.violation(0, true), 1.0);
  EXPECT_EQ(policy.violation(0, false), 5.0);
  EXPECT_EQ(policy.fixed_state(0), 1);
  EXPECT_FALSE(policy.fixed(1));
  EXPECT_FALSE(policy.fixed(2));
  policy.begin_step();  // a new step (or the same one again after a cut-back)
  EXPECT_FALSE(policy.fixed(0));
  EXPECT_EQ(policy.fixed_status(0, 0, open, -1.0), -1);
}

}  // namespace
}  // namespace grout
