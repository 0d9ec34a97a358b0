#include "assembly/contact_surface.hpp"

#include <algorithm>
#include <cmath>

#include "io/errors.hpp"
#include "io/mesh_bodies.hpp"

namespace grout {

namespace {

using FaceFilter = std::function<bool(const GlobalIndex* nodes, int n)>;

// The faces of the side sets (one, or the sets of `self: [a, b, ...]`, one surface) that
// `keep` accepts (all if `keep` is empty), in side-set order; a face's id is its position in
// the sets taken one after the other.
SurfaceFaces faces_of(const Mesh& mesh, const Input& input, const ContactInput& contact,
                      const std::string& role, const std::vector<std::string>& set_names,
                      const FaceFilter& keep = {}) {
  const std::string key = input.file + ": grout/contact/" + contact.name + "/" + role;
  SurfaceFaces faces;
  GlobalIndex first_id = 0;  // of the set's first face
  for (const std::string& set_name : set_names) {
    const SideSet* set = mesh.find_side_set(set_name);
    if (!set)
      throw InputError(key + ": no side set '" + set_name + "' in mesh '" + mesh.file + "'");
    if (set->elements.empty()) throw InputError(key + ": side set '" + set_name + "' is empty");
    for (std::size_t i = 0; i < set->elements.size(); ++i) {
      const ElementBlock* found = mesh.block_of(set->elements[i]);
      if (!found) {
        throw InputError(key + ": side set '" + set_name + "' names element " +
                         std::to_string(set->elements[i] + 1) + ", which is in no block");
      }
      const ElementBlock& block = *found;
      int local[max_side_nodes];
      const int n = side_local_nodes(block.topology, set->sides[i], local);
      if (n < 2) {
        throw InputError(key + ": side set '" + set_name + "' has side " +
                         std::to_string(set->sides[i]) + " of element " +
                         std::to_string(set->elements[i] + 1) + ", which is not a face");
      }
      std::array<GlobalIndex, max_face_nodes> nodes{-1, -1, -1, -1};
      const GlobalIndex e = set->elements[i] - block.first_element;
      for (int a = 0; a < n; ++a)
        nodes[a] = block.connectivity[e * block.nodes_per_element + local[a]];
      if (keep && !keep(nodes.data(), n)) continue;
      faces.nodes.push_back(nodes);
      faces.ids.push_back(first_id + GlobalIndex(i));
      faces.num_nodes.push_back(n);
      faces.blocks.push_back(&block);
    }
    first_id += GlobalIndex(set->elements.size());
  }
  return faces;
}

/// A slave face must not lie on a body that carries master faces (a slave side set with
/// faces of both bodies would put a body in contact with itself).
void check_bodies(const Mesh& mesh, const Input& input, const ContactInput& contact,
                  const SurfaceFaces& slave, const SurfaceFaces& master) {
  const std::vector<int> body = node_bodies(mesh);  // connected components of the elements
  std::vector<int> master_bodies;
  for (std::size_t f = 0; f < master.size(); ++f) master_bodies.push_back(body[master.nodes[f][0]]);
  std::sort(master_bodies.begin(), master_bodies.end());
  for (std::size_t f = 0; f < slave.size(); ++f) {
    if (std::binary_search(master_bodies.begin(), master_bodies.end(), body[slave.nodes[f][0]])) {
      throw InputError(input.file + ": grout/contact/" + contact.name + "/slave: side set '" +
                       contact.slave + "' has a face (face " + std::to_string(f + 1) + ", node " +
                       std::to_string(slave.nodes[f][0] + 1) +
                       ") on the body of master side set '" + contact.master +
                       "' (slave and master faces must lie on different bodies)");
    }
  }
}

std::vector<GlobalIndex> unique_nodes(const SurfaceFaces& faces) {
  std::vector<GlobalIndex> nodes;
  for (std::size_t f = 0; f < faces.size(); ++f)
    nodes.insert(nodes.end(), faces.nodes[f].begin(), faces.nodes[f].begin() + faces.num_nodes[f]);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

void index_slave_nodes(ContactSurface& s) {
  s.slave_nodes = unique_nodes(s.slave);
  for (std::size_t i = 0; i < s.slave_nodes.size(); ++i) s.slave_index[s.slave_nodes[i]] = int(i);
  s.slave_node_faces.resize(s.slave_nodes.size());
  for (std::size_t f = 0; f < s.slave.size(); ++f)
    for (int a = 0; a < s.slave.num_nodes[f]; ++a)
      s.slave_node_faces[s.slave_index[s.slave.nodes[f][a]]].push_back(int(f));
}

}  // namespace

void set_slave_faces(ContactSurface& s, SurfaceFaces slave) {
  s.slave = std::move(slave);
  s.slave_index.clear();
  s.slave_node_faces.clear();
  index_slave_nodes(s);
}

std::string shared_node_message(const Input& input, const ContactInput& contact, GlobalIndex n) {
  return input.file + ": grout/contact/" + contact.name + ": slave '" + contact.slave +
         "' and master '" + contact.master + "' share node " + std::to_string(n + 1) +
         " (contact bodies must not share nodes)";
}

ContactSurface build_contact_surface(const Mesh& mesh, const Input& input,
                                     const ContactInput& contact) {
  ContactSurface s;
  s.name = contact.name;
  s.type = contact.type;
  s.dimension = mesh.dimension;
  s.self = contact.self;
  s.slave = faces_of(mesh, input, contact, contact.self ? "self" : "slave",
                     contact_side_sets(contact, false));
  s.master = faces_of(mesh, input, contact, contact.self ? "self" : "master",
                      contact_side_sets(contact, true));
  if (!contact.self) check_bodies(mesh, input, contact, s.slave, s.master);
  index_slave_nodes(s);

  const std::vector<GlobalIndex> master_nodes = unique_nodes(s.master);
  for (GlobalIndex n : master_nodes) {
    if (!contact.self && s.slave_index.count(n))
      throw InputError(shared_node_message(input, contact, n));
  }
  std::merge(s.slave_nodes.begin(), s.slave_nodes.end(), master_nodes.begin(), master_nodes.end(),
             std::back_inserter(s.nodes));
  s.nodes.erase(std::unique(s.nodes.begin(), s.nodes.end()), s.nodes.end());
  return s;
}

void set_master_faces(ContactSurface& s, SurfaceFaces master) {
  s.master = std::move(master);
  const std::vector<GlobalIndex> master_nodes = unique_nodes(s.master);
  s.nodes.clear();
  std::merge(s.slave_nodes.begin(), s.slave_nodes.end(), master_nodes.begin(), master_nodes.end(),
             std::back_inserter(s.nodes));
  s.nodes.erase(std::unique(s.nodes.begin(), s.nodes.end()), s.nodes.end());
}

namespace {

// Calls visit(nodes, n) for each face of the side sets, in side-set order.
template <class Visit>
void for_each_side(const Mesh& mesh, const std::vector<std::string>& set_names, Visit visit) {
  for (const std::string& set_name : set_names) {
    const SideSet* set = mesh.find_side_set(set_name);
    if (!set) continue;
    for (std::size_t i = 0; i < set->elements.size(); ++i) {
      const ElementBlock* block = mesh.block_of(set->elements[i]);
      if (!block) continue;
      int local[max_side_nodes];
      GlobalIndex nodes[max_side_nodes];
      const int n = side_local_nodes(block->topology, set->sides[i], local);
      const GlobalIndex e = set->elements[i] - block->first_element;
      for (int a = 0; a < n; ++a)
        nodes[a] = block->connectivity[e * block->nodes_per_element + local[a]];
      visit(nodes, n);
    }
  }
}

}  // namespace

std::vector<signed char> self_contact_sides(GlobalIndex n_faces,
                                            const std::vector<long long>& pairs,
                                            const std::vector<signed char>& keep) {
  std::vector<std::vector<GlobalIndex>> neighbours(n_faces);
  for (std::size_t k = 0; k + 1 < pairs.size(); k += 2) {
    neighbours[pairs[k]].push_back(pairs[k + 1]);
    neighbours[pairs[k + 1]].push_back(pairs[k]);
  }
  for (auto& n : neighbours) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  std::vector<signed char> side(n_faces, -1);
  std::vector<GlobalIndex> queue;
  const auto spread = [&] {  // breadth-first from the faces in the queue
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const GlobalIndex f = queue[head];
      for (GlobalIndex g : neighbours[f]) {
        if (side[g] >= 0) continue;
        side[g] = static_cast<signed char>(1 - side[f]);
        queue.push_back(g);
      }
    }
  };
  if (GlobalIndex(keep.size()) == n_faces) {
    side = keep;  // kept; their new partners first, from the kept faces in ascending id
    for (GlobalIndex f = 0; f < n_faces; ++f)
      if (side[f] >= 0) queue.push_back(f);
    spread();
  }
  for (GlobalIndex start = 0; start < n_faces; ++start) {
    if (side[start] >= 0 || neighbours[start].empty()) continue;
    side[start] = 1;
    queue.assign(1, start);
    spread();
  }
  return side;
}

double face_size(const Mesh& mesh, const GlobalIndex* nodes, int n) {
  const int dim = mesh.dimension;
  double extent = 0.0;  // longest edge
  for (int a = 0; a < n; ++a) {
    const GlobalIndex p = nodes[a], q = nodes[(a + 1) % n];
    double d2 = 0.0;
    for (int d = 0; d < dim; ++d) {
      const double dx = mesh.coordinates[p * dim + d] - mesh.coordinates[q * dim + d];
      d2 += dx * dx;
    }
    extent = std::max(extent, std::sqrt(d2));
  }
  return extent;
}

double mean_face_size(const Mesh& mesh, const std::vector<std::string>& set_names) {
  double sum = 0.0;
  std::size_t count = 0;
  for_each_side(mesh, set_names, [&](const GlobalIndex* nodes, int n) {
    sum += face_size(mesh, nodes, n);
    ++count;
  });
  return count ? sum / double(count) : 0.0;
}

std::vector<GlobalIndex> side_set_nodes(const Mesh& mesh,
                                        const std::vector<std::string>& set_names) {
  std::vector<GlobalIndex> nodes;
  for_each_side(mesh, set_names,
                [&](const GlobalIndex* face, int n) { nodes.insert(nodes.end(), face, face + n); });
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

}  // namespace grout
