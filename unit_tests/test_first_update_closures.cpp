// The closing-limit rule of nonlinear/first_update_closures.hpp on hand-made nodes: the
// closing fraction s = g_prev / (g_prev − g) against the straight-line interpolation of the
// gaps, the "far from settled" switch, and the nodes it must never hold back.
#include <gtest/gtest.h>

#include "nonlinear/first_update_closures.hpp"

namespace grout {
namespace {

ClosureCandidate closing(double gap_old, double gap) {
  ClosureCandidate node;
  node.paired = true;
  node.closing = true;
  node.gap_old = gap_old;
  node.gap = gap;
  return node;
}

ClosureCandidate active() {
  ClosureCandidate node;
  node.paired = true;
  node.was_active = true;
  return node;
}

TEST(FirstUpdateClosures, HoldsBackTheNodesThatCloseLateInTheUpdate) {
  // Gap 1 → −1 closes at s = 0.5; 1 → −3 at 0.25; 3 → −1 at 0.75; 1 → −0.01 at 0.99.
  const std::vector<ClosureCandidate> nodes = {active(), closing(1.0, -1.0), closing(1.0, -3.0),
                                               closing(3.0, -1.0), closing(1.0, -0.01)};
  const ClosureCounts counts = count_closures(nodes);
  EXPECT_EQ(counts.active_before, 1.0);
  EXPECT_EQ(counts.closing, 4.0);
  const std::vector<char> held = held_back_closures(nodes, counts, 0.6);
  EXPECT_EQ(held, (std::vector<char>{0, 0, 0, 1, 1}));
  // The same decision as the gap at the interpolated point x_prev + f (x − x_prev): > 0.
  for (std::size_t q = 1; q < nodes.size(); ++q) {
    const double at_f = nodes[q].gap_old + 0.6 * (nodes[q].gap - nodes[q].gap_old);
    EXPECT_EQ(held[q] != 0, at_f > 0.0) << "node " << q;
  }
}

TEST(FirstUpdateClosures, LeavesASettlingActiveSetAlone) {
  // Two closing nodes against three active ones: not far from settled.
  const std::vector<ClosureCandidate> nodes = {active(), active(), active(), closing(1.0, -0.01),
                                               closing(2.0, -0.5)};
  const ClosureCounts counts = count_closures(nodes);
  EXPECT_EQ(held_back_closures(nodes, counts, 0.5), std::vector<char>(5, 0));
  // The decision is on the global counts (all ranks), not on this rank's.
  EXPECT_EQ(held_back_closures(nodes, {1.0, 10.0}, 0.5), (std::vector<char>{0, 0, 0, 1, 1}));
}

TEST(FirstUpdateClosures, NeverHoldsNodesClosedBeforeUnpairedOrOff) {
  ClosureCandidate touching = closing(0.0, -1.0);  // closed at the last evaluation
  ClosureCandidate penetrating = closing(-0.5, -1.0);
  ClosureCandidate unpaired = closing(1.0, -0.01);
  unpaired.paired = false;
  const std::vector<ClosureCandidate> nodes = {touching, penetrating, unpaired,
                                               closing(1.0, -0.01)};
  const ClosureCounts counts = count_closures(nodes);
  EXPECT_EQ(counts.closing, 1.0);
  EXPECT_EQ(held_back_closures(nodes, counts, 0.5), (std::vector<char>{0, 0, 0, 1}));
  EXPECT_EQ(held_back_closures(nodes, counts, 1.0), std::vector<char>(4, 0));  // off
}

}  // namespace
}  // namespace grout
