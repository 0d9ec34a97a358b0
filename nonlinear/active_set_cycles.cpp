#include "nonlinear/active_set_cycles.hpp"

#include <algorithm>
#include <cmath>

namespace grout {

namespace {

bool same(double a, double b, double tolerance) {
  return std::isfinite(a) && std::isfinite(b) &&
         std::abs(a - b) <= tolerance * std::max(std::abs(a), std::abs(b));
}

}  // namespace

int record_node_status(NodeStatusHistory& node, int iterate, bool closed, double s, int max_changes,
                       double tolerance) {
  if (node.fixed >= 0) return node.fixed;
  if (iterate != node.iterate) {  // the first evaluation of a new iterate: the last one's status
    if (node.iterate >= 0) {      // is final, and so is its change
      if (node.before >= 0 && node.closed != node.before) {
        ++node.changes;
        double* left = node.left[int(node.before)];
        left[1] = left[0];
        left[0] = node.pending;
      }
      node.before = node.closed;
    }
    node.iterate = iterate;
  }
  node.closed = closed ? 1 : 0;
  if (node.before < 0 || node.closed == node.before) return -1;
  // The previous iterate was solved in state `before`; here the law leaves it by |s|.
  node.pending = std::abs(s);
  const int b = node.before, other = 1 - b;
  if (node.changes + 1 >= max_changes && same(node.pending, node.left[b][0], tolerance) &&
      same(node.left[other][0], node.left[other][1], tolerance)) {
    node.violation[b] = node.pending;
    node.violation[other] = node.left[other][0];
    node.fixed = node.violation[1] <= node.violation[0] ? 1 : 0;
  }
  return node.fixed;
}

}  // namespace grout
