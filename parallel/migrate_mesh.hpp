#pragma once
// Migration of a mesh read in slices to the owners of its entities (parallel/distributed_mesh.hpp,
// step 4). Internal to parallel/.

#include <vector>

#include "parallel/distributed_mesh.hpp"
#include "parallel/exodus_slices.hpp"

namespace grout {

/// \brief Collective. Given the part of each slice element (`element_part`, one per element of
/// `slices`), sends every element to its part (owned) and to every other part owning an
/// element that shares a node with it (ghost); every node to the ranks holding one of its
/// elements, owned by the lowest part among its contact elements (`contact`, one per slice
/// element, 1 for an element with a face on a contact side set; empty: none), or without
/// one the lowest part among its elements (part 0 for a node of no element); every set entry
/// to the ranks holding its element or node.
DistributedMesh migrate_mesh(const Comm& comm, const MeshHeader& header, const MeshSlices& slices,
                             const std::vector<int>& element_part,
                             const std::vector<char>& contact = {});

/// Sorted, unique global nodes of the slice elements.
std::vector<GlobalIndex> slice_element_nodes(const MeshSlices& slices);

}  // namespace grout
