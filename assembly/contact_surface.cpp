#include "assembly/contact_surface.hpp"

#include <algorithm>

#include "io/errors.hpp"

namespace grout {

namespace {

SurfaceFaces faces_of(const Mesh& mesh, const Input& input, const ContactInput& contact,
                      const std::string& role, const std::string& set_name) {
  const std::string key = input.file + ": grout/contact/" + contact.name + "/" + role;
  const SideSet* set = mesh.find_side_set(set_name);
  if (!set) throw InputError(key + ": no side set '" + set_name + "' in mesh '" + mesh.file + "'");
  if (set->elements.empty()) throw InputError(key + ": side set '" + set_name + "' is empty");
  SurfaceFaces faces;
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
    faces.nodes.push_back(nodes);
    faces.num_nodes.push_back(n);
    faces.blocks.push_back(&block);
  }
  return faces;
}

std::vector<GlobalIndex> unique_nodes(const SurfaceFaces& faces) {
  std::vector<GlobalIndex> nodes;
  for (std::size_t f = 0; f < faces.size(); ++f)
    nodes.insert(nodes.end(), faces.nodes[f].begin(), faces.nodes[f].begin() + faces.num_nodes[f]);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

}  // namespace

ContactSurface build_contact_surface(const Mesh& mesh, const Input& input,
                                     const ContactInput& contact) {
  ContactSurface s;
  s.name = contact.name;
  s.type = contact.type;
  s.dimension = mesh.dimension;
  s.slave = faces_of(mesh, input, contact, "slave", contact.slave);
  s.master = faces_of(mesh, input, contact, "master", contact.master);
  s.slave_nodes = unique_nodes(s.slave);
  for (std::size_t i = 0; i < s.slave_nodes.size(); ++i) s.slave_index[s.slave_nodes[i]] = int(i);
  s.slave_node_faces.resize(s.slave_nodes.size());
  for (std::size_t f = 0; f < s.slave.size(); ++f)
    for (int a = 0; a < s.slave.num_nodes[f]; ++a)
      s.slave_node_faces[s.slave_index[s.slave.nodes[f][a]]].push_back(int(f));

  const std::vector<GlobalIndex> master_nodes = unique_nodes(s.master);
  for (GlobalIndex n : master_nodes) {
    if (s.slave_index.count(n)) {
      throw InputError(input.file + ": grout/contact/" + contact.name + ": slave '" +
                       contact.slave + "' and master '" + contact.master + "' share node " +
                       std::to_string(n + 1) + " (contact bodies must not share nodes)");
    }
  }
  std::merge(s.slave_nodes.begin(), s.slave_nodes.end(), master_nodes.begin(), master_nodes.end(),
             std::back_inserter(s.nodes));
  return s;
}

}  // namespace grout
