#pragma once
// Element partition by recursive coordinate bisection of element centroids, and node
// ownership. Computed identically on every rank from the replicated mesh, so no
// communication is needed and the partition is reproducible.

#include <vector>

#include "io/mesh.hpp"

namespace grout {

struct Partition {
  int num_parts = 1;
  std::vector<int> element_part;  ///< part (rank) of each global element
  std::vector<int> node_part;     ///< owner of each node: lowest part among its elements
};

/// Split the elements into `num_parts` parts of (nearly) equal size by recursive bisection
/// along the longest extent of the centroids' bounding box. Nodes attached to no element
/// belong to part 0.
Partition partition_mesh(const Mesh& mesh, int num_parts);

}  // namespace grout
