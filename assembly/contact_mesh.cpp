#include "assembly/contact_mesh.hpp"

#include <algorithm>
#include <numeric>

#include "assembly/contact_distribution.hpp"
#include "io/mesh_bodies.hpp"
#include "kernels/topology.hpp"

namespace grout {

ContactMesh::ContactMesh(const Mesh& replicated) : mesh_(replicated) {}

ContactMesh::ContactMesh(const Mesh& local, const ContactMeshPart& part, MPI_Comm comm)
    : mesh_(local), part_(&part), comm_(comm) {}

GlobalIndex ContactMesh::num_global_nodes() const {
  return part_ ? part_->global_num_nodes : mesh_.num_nodes();
}

GlobalIndex ContactMesh::global_node(GlobalIndex n) const {
  return part_ ? (*part_->node_gid)[std::size_t(n)] : n;
}

GlobalIndex ContactMesh::body(GlobalIndex n) const {
  if (part_) return part_->node_body.empty() ? -1 : part_->node_body[std::size_t(n)];
  if (replicated_bodies_.empty()) replicated_bodies_ = node_bodies(mesh_);
  return replicated_bodies_[std::size_t(n)];
}

SideFaces ContactMesh::local_faces(const std::string& name) const {
  const SideSet& set = *mesh_.find_side_set(name);
  const auto s = std::size_t(&set - mesh_.side_sets.data());
  const int dim = mesh_.dimension;
  SideFaces out;
  out.set_size = part_ ? (*part_->side_set_global_size)[s] : GlobalIndex(set.elements.size());
  for (std::size_t i = 0; i < set.elements.size(); ++i) {
    const GlobalIndex element = set.elements[i];
    const ElementBlock* block = mesh_.block_of(element);
    int local[max_side_nodes] = {};
    const int n = block ? side_local_nodes(block->topology, set.sides[i], local) : 0;
    std::array<GlobalIndex, max_face_nodes> nodes{-1, -1, -1, -1};
    std::array<double, 3 * max_face_nodes> X{};
    GlobalIndex body = -1;
    for (int a = 0; a < n && a < max_face_nodes; ++a) {
      const GlobalIndex node =
          block->connectivity[(element - block->first_element) * block->nodes_per_element +
                              local[a]];
      nodes[a] = global_node(node);
      for (int d = 0; d < dim; ++d) X[3 * a + d] = mesh_.coordinates[node * dim + d];
      if (a == 0) body = this->body(node);
    }
    out.positions.push_back(part_ ? (*part_->side_set_position)[s][i] : GlobalIndex(i));
    out.elements.push_back(part_ ? (*part_->element_gid)[std::size_t(element)] : element);
    out.sides.push_back(set.sides[i]);
    out.blocks.push_back(block ? int(block - mesh_.blocks.data()) : -1);
    out.num_nodes.push_back(n);
    out.nodes.push_back(nodes);
    out.X.push_back(X);
    out.bodies.push_back(body);
  }
  return out;
}

SideFaces ContactMesh::all_faces(const std::string& name) const {
  SideFaces mine = local_faces(name);
  if (!part_) return mine;
  // Each face once: from the owner of its element. Record: position, element, side, block,
  // number of nodes, body, the nodes, then their coordinates (as doubles).
  const SideSet& set = *mesh_.find_side_set(name);
  constexpr int ints = 6 + max_face_nodes, reals = 3 * max_face_nodes;
  std::vector<long long> int_record;
  std::vector<double> real_record;
  for (std::size_t i = 0; i < mine.size(); ++i) {
    if ((*part_->element_owner)[std::size_t(set.elements[i])] != part_->rank) continue;
    int_record.insert(int_record.end(), {mine.positions[i], mine.elements[i], mine.sides[i],
                                         mine.blocks[i], mine.num_nodes[i], mine.bodies[i]});
    int_record.insert(int_record.end(), mine.nodes[i].begin(), mine.nodes[i].end());
    real_record.insert(real_record.end(), mine.X[i].begin(), mine.X[i].end());
  }
  int n_ranks = 1;
  MPI_Comm_size(comm_, &n_ranks);
  const std::vector<long long> all_ints = exchange_with_ranks(
      std::vector<std::vector<long long>>(std::size_t(n_ranks), int_record), comm_);
  const std::vector<double> all_reals = exchange_with_ranks(
      std::vector<std::vector<double>>(std::size_t(n_ranks), real_record), comm_);
  const std::size_t count = all_ints.size() / ints;
  std::vector<std::size_t> order(count);  // by position in the file's set
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return all_ints[a * ints] < all_ints[b * ints]; });
  SideFaces out;
  out.set_size = mine.set_size;
  for (std::size_t k : order) {
    const long long* r = &all_ints[k * ints];
    out.positions.push_back(r[0]);
    out.elements.push_back(r[1]);
    out.sides.push_back(int(r[2]));
    out.blocks.push_back(int(r[3]));
    out.num_nodes.push_back(int(r[4]));
    out.bodies.push_back(r[5]);
    std::array<GlobalIndex, max_face_nodes> nodes{};
    std::copy(r + 6, r + 6 + max_face_nodes, nodes.begin());
    out.nodes.push_back(nodes);
    std::array<double, 3 * max_face_nodes> X{};
    std::copy(&all_reals[k * reals], &all_reals[k * reals] + reals, X.begin());
    out.X.push_back(X);
  }
  return out;
}

}  // namespace grout
