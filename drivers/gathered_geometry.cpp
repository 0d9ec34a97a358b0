#include "drivers/gathered_geometry.hpp"

#include "drivers/root_gather.hpp"

namespace grout {

namespace {

/// Indices (global numbers, < 2^53) carried as doubles through RootGather, back to integers.
std::vector<GlobalIndex> as_indices(const std::vector<double>& values) {
  return std::vector<GlobalIndex>(values.begin(), values.end());
}

}  // namespace

MeshOutline distributed_outline(const DistributedMesh& mesh) {
  MeshOutline outline = mesh_outline(mesh.local);  // names, ids and topologies of the file
  outline.num_nodes = mesh.global_num_nodes;
  outline.block_sizes = mesh.block_global_size;
  for (std::size_t b = 0; b < outline.blocks.size(); ++b)
    outline.blocks[b].first_element = mesh.block_global_first[b];
  outline.side_set_sizes = mesh.side_set_global_size;
  outline.node_set_sizes = mesh.node_set_global_size;
  return outline;
}

std::vector<double> gather_coordinates(const Comm& comm, const DistributedMesh& mesh,
                                       int component) {
  const int dim = mesh.local.dimension;
  std::vector<GlobalIndex> ids;
  std::vector<double> values;
  for (GlobalIndex n = 0; n < mesh.num_owned_nodes; ++n) {
    ids.push_back(mesh.node_gid[std::size_t(n)]);
    values.push_back(mesh.local.coordinates[std::size_t(n * dim + component)]);
  }
  return RootGather(comm, ids, mesh.global_num_nodes).gather(values);
}

std::vector<GlobalIndex> gather_connectivity(const Comm& comm, const DistributedMesh& mesh,
                                             std::size_t b) {
  const ElementBlock& block = mesh.local.blocks[b];
  const int npe = block.nodes_per_element;
  std::vector<GlobalIndex> ids;  // (element's place in the block) * npe + a
  std::vector<double> values;
  for (GlobalIndex k = 0; k < mesh.num_owned_in_block[b]; ++k) {  // owned come first
    const GlobalIndex place =
        mesh.element_gid[std::size_t(block.first_element + k)] - mesh.block_global_first[b];
    for (int a = 0; a < npe; ++a) {
      ids.push_back(place * npe + a);
      values.push_back(double(mesh.node_gid[std::size_t(block.connectivity[k * npe + a])]));
    }
  }
  return as_indices(RootGather(comm, ids, mesh.block_global_size[b] * npe).gather(values));
}

std::pair<std::vector<GlobalIndex>, std::vector<int>> gather_side_set(const Comm& comm,
                                                                      const DistributedMesh& mesh,
                                                                      std::size_t s) {
  const SideSet& set = mesh.local.side_sets[s];
  std::vector<GlobalIndex> ids;
  std::vector<double> elements, sides;
  for (std::size_t i = 0; i < set.elements.size(); ++i) {
    if (!mesh.owns_element(set.elements[i])) continue;
    ids.push_back(mesh.side_set_position[s][i]);
    elements.push_back(double(mesh.element_gid[std::size_t(set.elements[i])]));
    sides.push_back(set.sides[i]);
  }
  const RootGather to_root(comm, ids, mesh.side_set_global_size[s]);
  const std::vector<double> side_values = to_root.gather(sides);
  return {as_indices(to_root.gather(elements)),
          std::vector<int>(side_values.begin(), side_values.end())};
}

std::vector<GlobalIndex> gather_node_set(const Comm& comm, const DistributedMesh& mesh,
                                         std::size_t s) {
  const NodeSet& set = mesh.local.node_sets[s];
  std::vector<GlobalIndex> ids;
  std::vector<double> nodes;
  for (std::size_t i = 0; i < set.nodes.size(); ++i) {
    if (!mesh.owns_node(set.nodes[i])) continue;
    ids.push_back(mesh.node_set_position[s][i]);
    nodes.push_back(double(mesh.node_gid[std::size_t(set.nodes[i])]));
  }
  return as_indices(RootGather(comm, ids, mesh.node_set_global_size[s]).gather(nodes));
}

}  // namespace grout
