#include "io/mesh_bodies.hpp"

#include <algorithm>
#include <numeric>

namespace grout {

namespace {

// Union-find root with path halving.
GlobalIndex root(std::vector<GlobalIndex>& parent, GlobalIndex n) {
  while (parent[n] != n) n = parent[n] = parent[parent[n]];
  return n;
}

}  // namespace

std::vector<int> node_bodies(const Mesh& mesh) {
  const GlobalIndex num_nodes = mesh.num_nodes();
  std::vector<GlobalIndex> parent(num_nodes);
  std::iota(parent.begin(), parent.end(), GlobalIndex(0));
  for (const ElementBlock& block : mesh.blocks) {
    const int k = block.nodes_per_element;
    for (std::size_t e = 0; k > 0 && e + k <= block.connectivity.size(); e += k) {
      GlobalIndex first = root(parent, block.connectivity[e]);
      for (int a = 1; a < k; ++a) {
        const GlobalIndex other = root(parent, block.connectivity[e + a]);
        if (other == first) continue;
        parent[std::max(other, first)] = std::min(other, first);  // the lower root stays
        first = std::min(other, first);
      }
    }
  }
  // Roots are the lowest node of their body (links always point to the lower index).
  std::vector<int> body(num_nodes, -1);
  int count = 0;
  for (GlobalIndex n = 0; n < num_nodes; ++n) {
    const GlobalIndex r = root(parent, n);
    body[n] = r == n ? count++ : body[r];
  }
  return body;
}

}  // namespace grout
