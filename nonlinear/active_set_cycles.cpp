#include "nonlinear/active_set_cycles.hpp"

#include <cmath>

namespace grout {

int record_node_status(NodeStatusHistory& node, int iterate, bool closed, double s,
                       int max_changes) {
  if (node.fixed >= 0) return node.fixed;
  if (iterate != node.iterate) {  // the first evaluation of a new iterate: the last one's status
    if (node.iterate >= 0) {      // is final
      if (node.before >= 0 && node.closed != node.before) ++node.changes;
      node.before = node.closed;
    }
    node.iterate = iterate;
  }
  node.closed = closed ? 1 : 0;
  const bool changed = node.before >= 0 && node.closed != node.before;
  // The previous iterate was solved in state `before`; here the law leaves it by |s|.
  if (changed) node.violation[int(node.before)] = std::abs(s);
  if (node.changes + (changed ? 1 : 0) >= max_changes)
    node.fixed = node.violation[1] <= node.violation[0] ? 1 : 0;
  return node.fixed;
}

}  // namespace grout
