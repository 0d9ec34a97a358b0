#include "nonlinear/active_set_policy.hpp"

#include <algorithm>

namespace grout {

ActiveSetPolicy::ActiveSetPolicy(std::vector<double> proximity, double max_closure_fraction)
    : proximity_(std::move(proximity)),
      max_closure_fraction_(max_closure_fraction),
      held_in_step_(proximity_.size(), 0),
      status_history_(proximity_.size()) {}

void ActiveSetPolicy::begin_step() {
  std::fill(held_in_step_.begin(), held_in_step_.end(), 0);
  std::fill(status_history_.begin(), status_history_.end(), NodeStatusHistory());
}

std::vector<char> ActiveSetPolicy::held_back(const std::vector<ClosureCandidate>& nodes,
                                             const ClosureCounts& global, NewtonPhase phase) {
  std::vector<char> held(nodes.size(), 0);
  if (holds_back(phase)) held = held_back_closures(nodes, global, max_closure_fraction_);
  for (std::size_t q = 0; q < nodes.size(); ++q) {  // once per node and step
    if (held_in_step_[q]) held[q] = 0;
    if (held[q]) held_in_step_[q] = 1;
  }
  return held;
}

}  // namespace grout
