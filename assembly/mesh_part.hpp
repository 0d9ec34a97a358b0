#pragma once
// One rank's part of a mesh as the solid reads it: a plain Mesh over the rank's entities in
// local indices and their global (file) numbers and owners. The replicated mesh is the part
// whose local numbers are the global ones (SolidProblem's first constructor builds it from
// assembly/partition.hpp); the distributed mesh gives its own (parallel/distributed_mesh.hpp,
// mesh_part()).

#include <vector>

#include "io/mesh.hpp"

namespace grout {

/// \brief References to one rank's entities; the referenced vectors must outlive the call
/// that reads them. `local` must hold every element that has an owned node or is owned, and
/// their nodes (one ghost layer, as parallel/migrate_mesh.cpp builds it, is enough); its
/// side and node sets hold the entries whose element or node is local.
struct MeshPart {
  const Mesh& local;
  GlobalIndex global_num_nodes = 0, global_num_elements = 0;
  const std::vector<GlobalIndex>& node_gid;     ///< local node -> 0-based global node
  const std::vector<int>& node_owner;           ///< owning rank of each local node
  const std::vector<GlobalIndex>& element_gid;  ///< local element -> 0-based global element
  const std::vector<int>& element_owner;        ///< owning rank of each local element
};

}  // namespace grout
