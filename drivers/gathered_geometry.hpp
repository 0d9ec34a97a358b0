#pragma once
// The single results file's mesh from the distributed mesh (parallel/distributed_mesh.hpp):
// rank 0 defines the file from the mesh's outline (names, ids, the file's sizes) and receives
// its arrays one at a time, each gathered from the ranks that own its entries (RootGather), as
// the results are: no rank holds a whole-mesh array but rank 0, for the array it is writing.
// The arrays are the file's, entry for entry, so the results file is the one the replicated
// mesh gives.

#include <utility>
#include <vector>

#include "io/exodus.hpp"
#include "parallel/distributed_mesh.hpp"

namespace grout {

/// The outline of the mesh's file: every block and set in the file's order, the file's sizes.
MeshOutline distributed_outline(const DistributedMesh& mesh);

/// Collective. Coordinate `component` of every node (the owners' values), on rank 0; empty
/// elsewhere.
std::vector<double> gather_coordinates(const Comm& comm, const DistributedMesh& mesh,
                                       int component);
/// Collective. Block `b`'s connectivity (0-based global nodes, element-major, the file's
/// element order), from the owners of its elements, on rank 0; empty elsewhere.
std::vector<GlobalIndex> gather_connectivity(const Comm& comm, const DistributedMesh& mesh,
                                             std::size_t b);
/// Collective. Side set `s` in the file's order: (0-based global elements, 1-based sides),
/// each entry from its element's owner, on rank 0; empty elsewhere.
std::pair<std::vector<GlobalIndex>, std::vector<int>> gather_side_set(const Comm& comm,
                                                                      const DistributedMesh& mesh,
                                                                      std::size_t s);
/// Collective. Node set `s` in the file's order (0-based global nodes), each entry from its
/// node's owner, on rank 0; empty elsewhere.
std::vector<GlobalIndex> gather_node_set(const Comm& comm, const DistributedMesh& mesh,
                                         std::size_t s);

}  // namespace grout
