#include "io/mesh.hpp"

namespace grout {

namespace {
template <class Entity>
const Entity* find_by_name(const std::vector<Entity>& entities, std::string_view name) {
  for (const auto& e : entities) {
    if (e.name == name || "id_" + std::to_string(e.id) == name) return &e;
  }
  return nullptr;
}
}  // namespace

bool ElementBlock::named(std::string_view key) const {
  return name == key || "id_" + std::to_string(id) == key;
}

const ElementBlock* Mesh::block_of(GlobalIndex element) const {
  for (const auto& b : blocks)
    if (b.contains(element)) return &b;
  return nullptr;
}

const ElementBlock* Mesh::find_block(std::string_view name) const {
  return find_by_name(blocks, name);
}
const SideSet* Mesh::find_side_set(std::string_view name) const {
  return find_by_name(side_sets, name);
}
const NodeSet* Mesh::find_node_set(std::string_view name) const {
  if (const NodeSet* set = find_by_name(node_sets, name)) return set;
  // grout_mesh names a side set's node set "<side set>_nodes" (since 2026-11-24); inputs
  // written before that name it "<side set>" and keep working.
  return find_by_name(node_sets, std::string(name) + "_nodes");
}

}  // namespace grout
