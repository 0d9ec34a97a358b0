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
/// belong to part 0. If `contact_elements` (element indices) is given, a range holding two or
/// more of them is cut along the longest extent of their centroids instead, so that each part
/// gets its share of the contact surface (two stacked bodies are cut side by side rather than
/// one from the other, whose contact would all fall on one part).
Partition partition_mesh(const Mesh& mesh, int num_parts,
                         const std::vector<GlobalIndex>& contact_elements = {});

}  // namespace grout
