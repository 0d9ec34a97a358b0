#include "nonlinear/first_update_closures.hpp"

namespace grout {

namespace {

bool open_before(const ClosureCandidate& node) {
  return node.paired && node.closing && node.gap_old > 0.0;
}

}  // namespace

ClosureCounts count_closures(const std::vector<ClosureCandidate>& nodes) {
  ClosureCounts counts;
  for (const ClosureCandidate& node : nodes) {
    if (node.paired && node.was_active) counts.active_before += 1.0;
    if (open_before(node)) counts.closing += 1.0;
  }
  return counts;
}

std::vector<char> held_back_closures(const std::vector<ClosureCandidate>& nodes,
                                     const ClosureCounts& global, double max_fraction) {
  std::vector<char> held(nodes.size(), 0);
  if (max_fraction >= 1.0 || !(global.closing > global.active_before)) return held;
  for (std::size_t q = 0; q < nodes.size(); ++q) {
    const ClosureCandidate& node = nodes[q];
    if (!open_before(node)) continue;
    // s = g_old / (g_old − g) > max_fraction  ⇔  g_old > max_fraction (g_old − g), g_old > 0;
    // a node still open now (g ≥ 0, active by a positive λ_n) has s ≥ 1.
    held[q] = node.gap_old > max_fraction * (node.gap_old - node.gap) ? 1 : 0;
  }
  return held;
}

}  // namespace grout
