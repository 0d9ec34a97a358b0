#pragma once
// The bodies of a distributed mesh (the connected components of the whole mesh's elements, as
// io/mesh_bodies.hpp finds them on the replicated mesh) without the whole mesh on any rank.

#include <vector>

#include "parallel/distributed_mesh.hpp"

namespace grout {

/// \brief Collective. Per local node of `mesh`, the lowest global node of its body. Label
/// propagation: each rank joins its local elements' nodes (union-find) and gives each local
/// component its lowest label; the owners take the lowest label their nodes have on any rank
/// and send it back to the ghosts; repeated until no label changes anywhere (each round carries
/// a body's lowest node across one more rank boundary).
std::vector<GlobalIndex> distributed_node_bodies(const Comm& comm, const DistributedMesh& mesh);

}  // namespace grout
