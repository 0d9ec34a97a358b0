#pragma once
// The bodies of a distributed mesh: io/mesh_bodies.hpp's connected components of the elements
// (two elements connected when they share a node), numbered as node_bodies numbers them (in
// the order of their lowest node), without any rank holding more than its part.
//
// Each node carries a label, first its global id. A round: every rank joins its elements
// (owned and ghost) by a union-find over its local nodes and gives each local component the
// lowest label among its nodes; then each node shared by several ranks takes the lowest label
// any of them holds (to its owner, Tpetra Export, and back, Import). Labels only decrease, and
// a component's lowest id crosses one more rank boundary with each round, so the rounds stop
// (no label changed on any rank) after at most one more than the longest chain of rank
// crossings along a body (two or three rounds for a mesh cut by RCB into convex pieces). At the
// end every node's label is the lowest node id of its body; the bodies' roots (owned nodes
// whose label is their own id) are gathered on every rank, one id per body, and a body's index
// is its root's rank among them.

#include <vector>

#include "assembly/tpetra_types.hpp"
#include "parallel/distributed_mesh.hpp"

namespace grout {

struct DistributedBodies {
  std::vector<int> owned_node_body;  ///< body of each owned node, in local order
  int num_bodies = 0;                ///< bodies of the whole mesh
};

/// Collective. Per local node (owned and ghost) of `mesh`, its body's label after the rounds
/// of the file comment: the lowest global node id of the body.
std::vector<GlobalIndex> distributed_node_body_labels(const Comm& comm,
                                                      const DistributedMesh& mesh);

/// Collective. The bodies of `mesh` (see the file comment): the same indices as
/// node_bodies(the replicated mesh) at the owned nodes. A node of no element is a body of its
/// own.
DistributedBodies distributed_node_bodies(const Comm& comm, const DistributedMesh& mesh);

}  // namespace grout
