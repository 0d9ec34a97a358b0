// check_input_against_mesh: what the input names must exist in the mesh it points to, and
// every set it names must hold what its role needs: faces on the boundary, nodes.

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <unordered_map>

#include "io/errors.hpp"
#include "io/input.hpp"
#include "io/input_schema.hpp"

namespace grout {

namespace {

template <class Entity>
std::string names_of(const std::vector<Entity>& entities) {
  if (entities.empty()) return "it has none";
  std::string text = "it has: ";
  for (std::size_t i = 0; i < entities.size(); ++i) {
    text += (i ? ", " : "") + entities[i].name;
  }
  return text;
}

class MeshCheck {
 public:
  /// `part`: the numbers of a distributed mesh's part (nullptr: `mesh` is the whole mesh).
  MeshCheck(const Input& input, const Mesh& mesh, const MeshPartNumbers* part)
      : input_(input), mesh_(mesh), part_(part), mesh_name_("mesh '" + mesh.file + "'") {}

  /// 1-based file numbers of a (local) element and node, as messages give them.
  GlobalIndex element_number(GlobalIndex e) const {
    return (part_ ? part_->element_gid[std::size_t(e)] : e) + 1;
  }
  GlobalIndex node_number(GlobalIndex n) const {
    return (part_ ? part_->node_gid[std::size_t(n)] : n) + 1;
  }
  /// True for the elements whose set entries this rank checks: all, or its owned ones.
  bool checks_element(GlobalIndex e) const {
    return !part_ || part_->element_owner[std::size_t(e)] == part_->rank;
  }

  [[noreturn]] void fail(const std::string& key_path, const std::string& message) const {
    throw InputError(input_.file + ": " + key_path + ": " + message);
  }

  const ElementBlock& block(const std::string& key_path, const std::string& name) const {
    const ElementBlock* b = mesh_.find_block(name);
    if (!b) {
      fail(key_path, "no element block '" + name + "' in " + mesh_name_ + " (" +
                         names_of(mesh_.blocks) + ")");
    }
    return *b;
  }
  /// The side set `name` of a load or a contact surface: it exists and has faces. That its
  /// faces lie on the boundary is checked by boundary_faces(), for every such set at once.
  void side_set(const std::string& key_path, const std::string& name) {
    const SideSet* set = mesh_.find_side_set(name);
    if (!set) {
      fail(key_path,
           "no side set '" + name + "' in " + mesh_name_ + " (" + names_of(mesh_.side_sets) + ")");
    }
    const GlobalIndex size = part_ ? part_->side_set_size[std::size_t(set - mesh_.side_sets.data())]
                                   : GlobalIndex(set->elements.size());
    if (size == 0)
      fail(key_path, "side set '" + name + "' in " + mesh_name_ + " is empty (it has no faces)");
    face_sets_.push_back({key_path, set});
  }
  /// The node set `name` of a Dirichlet condition: it exists and has nodes.
  void node_set(const std::string& key_path, const std::string& name) const {
    const NodeSet* set = mesh_.find_node_set(name);
    if (!set) {
      fail(key_path,
           "no node set '" + name + "' in " + mesh_name_ + " (" + names_of(mesh_.node_sets) + ")");
    }
    const GlobalIndex size = part_ ? part_->node_set_size[std::size_t(set - mesh_.node_sets.data())]
                                   : GlobalIndex(set->nodes.size());
    if (size == 0)
      fail(key_path, "node set '" + name + "' in " + mesh_name_ + " is empty (it has no nodes)");
  }
  /// Every face of the side sets passed to side_set() is a face of one element only: a face
  /// that two elements share is inside the mesh, where a pressure or a contact surface has no
  /// meaning (its load would act inside a body).
  void boundary_faces() const;
  const std::string& mesh_name() const { return mesh_name_; }

 private:
  const Input& input_;
  const Mesh& mesh_;
  const MeshPartNumbers* part_;
  std::string mesh_name_;
  std::vector<std::pair<std::string, const SideSet*>> face_sets_;  // (key path, set)
};

using FaceKey = std::array<GlobalIndex, max_side_nodes>;  // sorted node ids, -1 padded

struct FaceKeyHash {
  std::size_t operator()(const FaceKey& key) const {
    std::size_t h = 0;
    for (GlobalIndex n : key) h = h * 1000003u ^ std::hash<GlobalIndex>()(n);
    return h;
  }
};

/// The nodes of side `side` (1-based, Exodus) of `element` (global, 0-based), sorted; false
/// when the element is in no block or the side is not one of its faces.
bool face_key(const Mesh& mesh, GlobalIndex element, int side, FaceKey& key) {
  const ElementBlock* block = mesh.block_of(element);
  if (!block) return false;
  int local[max_side_nodes];
  const int n = side_local_nodes(block->topology, side, local);
  if (n < 2) return false;
  key.fill(-1);
  const GlobalIndex e = element - block->first_element;
  for (int a = 0; a < n; ++a) key[a] = block->connectivity[e * block->nodes_per_element + local[a]];
  std::sort(key.begin(), key.begin() + n);
  return true;
}

// The faces of the named sets, then one pass over the faces of every element, counting the
// elements that have each: a boundary face has one.
void MeshCheck::boundary_faces() const {
  if (face_sets_.empty()) return;
  struct Count {
    int elements = 0;
    GlobalIndex first = -1, second = -1;  // the first two elements that have the face
  };
  std::unordered_map<FaceKey, Count, FaceKeyHash> count;
  FaceKey key;
  for (const auto& [key_path, set] : face_sets_) {
    for (std::size_t i = 0; i < set->elements.size(); ++i) {
      if (!checks_element(set->elements[i])) continue;
      if (!face_key(mesh_, set->elements[i], set->sides[i], key)) {
        fail(key_path, "side set '" + set->name + "' has side " + std::to_string(set->sides[i]) +
                           " of element " + std::to_string(element_number(set->elements[i])) +
                           ", which is not a face of an element of " + mesh_name_);
      }
      count.emplace(key, Count());
    }
  }
  for (const ElementBlock& block : mesh_.blocks) {
    const int sides = topology_num_sides(block.topology);
    for (GlobalIndex e = 0; e < block.num_elements(); ++e) {
      for (int side = 1; side <= sides; ++side) {
        if (!face_key(mesh_, block.first_element + e, side, key)) continue;
        const auto it = count.find(key);
        if (it == count.end()) continue;
        Count& c = it->second;
        (c.elements == 0 ? c.first : c.second) = block.first_element + e;
        ++c.elements;
      }
    }
  }
  for (const auto& [key_path, set] : face_sets_) {
    for (std::size_t i = 0; i < set->elements.size(); ++i) {
      if (!checks_element(set->elements[i])) continue;
      face_key(mesh_, set->elements[i], set->sides[i], key);
      const Count& c = count.at(key);
      if (c.elements < 2) continue;
      const GlobalIndex other = c.first == set->elements[i] ? c.second : c.first;
      fail(key_path, "side set '" + set->name + "' in " + mesh_name_ + " holds side " +
                         std::to_string(set->sides[i]) + " of element " +
                         std::to_string(element_number(set->elements[i])) +
                         ", an interior face (element " + std::to_string(element_number(other)) +
                         " has it too): a load or contact side set must lie on the boundary");
    }
  }
}

/// A pair and its reverse (slave and master swapped) constrain one interface twice: the two
/// sets of multipliers are not independent and Newton stops at its iteration limit.
void check_no_reverse_pairs(const Input& input, const Mesh& mesh, const MeshCheck& check) {
  const auto side = [&](const std::string& name) { return mesh.find_side_set(name)->name; };
  for (std::size_t i = 0; i < input.contact.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      const ContactInput &a = input.contact[j], &b = input.contact[i];
      if (side(a.slave) == side(b.master) && side(a.master) == side(b.slave)) {
        check.fail("grout/contact/" + b.name,
                   "slave '" + b.slave + "' and master '" + b.master +
                       "' are the master and slave of grout/contact/" + a.name +
                       ": a pair and its reverse constrain one interface twice (keep one)");
      }
    }
  }
}

/// model/plane: axisymmetric (docs/input.md, "Axisymmetric models"): x is the radius, so no
/// element node may lie at x < 0, and a node on the axis (x = 0) must have u_x held at 0 (the
/// hoop strain u_r/r is finite there only if u_r = 0; the 2 pi r weights vanish on the axis).
/// A node counts as on the axis when |x| <= 1e-10 of the mesh's extent in x.
void check_axisymmetric(const Input& input, const Mesh& mesh, const MeshCheck& check,
                        double x_max) {
  const double tol = 1e-10 * x_max;
  std::vector<char> held(mesh.num_nodes(), 0);  // u_x = 0 prescribed at t = 0 and t = end
  for (const DirichletInput& d : input.dirichlet) {
    const NodeSet* set = mesh.find_node_set(d.node_set);
    if (d.component != 0 || !set) continue;
    for (GlobalIndex n : set->nodes) {
      const double x = mesh.coordinates[n * 2], y = mesh.coordinates[n * 2 + 1];
      if (d.value(0.0, x, y, 0.0) == 0.0 && d.value(input.time.end, x, y, 0.0) == 0.0) held[n] = 1;
    }
  }
  for (const ElementBlock& b : mesh.blocks) {
    for (GlobalIndex e = 0; e < b.num_elements(); ++e) {
      if (!check.checks_element(b.first_element + e)) continue;
      for (int a = 0; a < b.nodes_per_element; ++a) {
        const GlobalIndex n = b.connectivity[e * b.nodes_per_element + a];
        const double r = mesh.coordinates[n * 2];
        const std::string node = "node " + std::to_string(check.node_number(n)) +
                                 " of element block '" + b.name + "' in " + check.mesh_name();
        if (r < -tol) {
          check.fail("grout/model/plane", node + " has x = " + input_schema::format_number(r) +
                                              " < 0: an axisymmetric mesh lies in x = r >= 0");
        }
        if (r <= tol && !held[n]) {
          check.fail("grout/dirichlet",
                     node +
                         " lies on the axis (x = 0) without u_x = 0: an axisymmetric model "
                         "needs a dirichlet condition with component: x, value: \"0\" on "
                         "every node of the axis");
        }
      }
    }
  }
}

}  // namespace

namespace {

/// `self: [a, b, ...]`: the sets' union is one surface, so no face may be in two of them (its
/// contact terms would count twice).
void check_self_sets_disjoint(const Mesh& mesh, const ContactInput& c, const MeshCheck& check) {
  std::map<std::pair<GlobalIndex, int>, std::string> set_of;  // (element, side) -> set
  for (const std::string& name : contact_side_sets(c, false)) {
    const SideSet& set = *mesh.find_side_set(name);
    for (std::size_t i = 0; i < set.elements.size(); ++i) {
      if (!check.checks_element(set.elements[i])) continue;
      const auto [it, fresh] = set_of.emplace(std::make_pair(set.elements[i], set.sides[i]), name);
      if (!fresh && it->second != name) {
        check.fail("grout/contact/" + c.name + "/self",
                   "side sets '" + it->second + "' and '" + name + "' both hold side " +
                       std::to_string(set.sides[i]) + " of element " +
                       std::to_string(check.element_number(set.elements[i])) +
                       " (the self-contact surface is their union: a face counts once)");
      }
    }
  }
}

}  // namespace

const MaterialInput* find_material(const Input& input, const ElementBlock& block) {
  for (const MaterialInput& m : input.materials)
    if (block.named(m.block)) return &m;
  return nullptr;
}

namespace {

void check_input(const Input& input, const Mesh& mesh, const MeshPartNumbers* part) {
  MeshCheck check(input, mesh, part);
  const int dim = input.model.dimension;
  if (mesh.dimension != dim) {
    check.fail("grout/model/dimension", "the model is " + std::to_string(dim) + "D but " +
                                            check.mesh_name() + " is " +
                                            std::to_string(mesh.dimension) + "D");
  }

  // Every element block has exactly one material.
  std::map<const ElementBlock*, std::string> material_of;
  for (const MaterialInput& m : input.materials) {
    const std::string key = "grout/materials/" + m.name + "/block";
    const ElementBlock& b = check.block(key, m.block);
    const auto [it, inserted] = material_of.emplace(&b, m.name);
    if (!inserted) {
      check.fail(key, "element block '" + b.name + "' already has material '" + it->second +
                          "' (one material per block)");
    }
  }
  for (const ElementBlock& b : mesh.blocks) {
    if (!material_of.count(&b)) {
      check.fail("grout/materials", "element block '" + b.name + "' of " + check.mesh_name() +
                                        " has no material (every block needs one)");
    }
  }

  const char* const axes = "xyz";
  for (const DirichletInput& d : input.dirichlet) {
    const std::string key = "grout/dirichlet/" + d.name;
    check.node_set(key + "/node_set", d.node_set);
    if (d.component < 0 || d.component >= dim) {
      const bool axis = d.component >= 0 && d.component < 3;
      check.fail(key + "/component",
                 "component " +
                     (axis ? std::string(1, axes[d.component]) : std::to_string(d.component)) +
                     " is not allowed in a " + std::to_string(dim) + "D model");
    }
  }
  for (const LoadInput& l : input.loads) {
    const std::string key = "grout/loads/" + l.name;
    check.side_set(key + "/side_set", l.side_set);
    if (l.type == LoadKind::traction && int(l.components.size()) != dim) {
      check.fail(key + "/components", "expected " + std::to_string(dim) +
                                          " traction components in a " + std::to_string(dim) +
                                          "D model, got " + std::to_string(l.components.size()));
    }
  }
  std::map<std::string, std::string> pair_of_slave;
  for (const ContactInput& c : input.contact) {
    const std::string key = "grout/contact/" + c.name;
    if (c.self) {
      for (const std::string& set : contact_side_sets(c, false)) check.side_set(key + "/self", set);
      check_self_sets_disjoint(mesh, c, check);
    } else {
      check.side_set(key + "/slave", c.slave);
      check.side_set(key + "/master", c.master);
    }
    for (const std::string& set : contact_side_sets(c, false)) {
      const auto [it, fresh] = pair_of_slave.emplace(mesh.find_side_set(set)->name, c.name);
      if (!fresh) {
        check.fail(key + (c.self ? "/self" : "/slave"),
                   "side set '" + set + "' is already the slave of grout/contact/" + it->second +
                       " (a slave side belongs to one contact pair)");
      }
    }
  }
  check.boundary_faces();
  check_no_reverse_pairs(input, mesh, check);
  if (input.model.plane == PlaneKind::axisymmetric && mesh.dimension == 2) {
    double x_max = 0.0;
    for (GlobalIndex n = 0; n < mesh.num_nodes(); ++n)
      x_max = std::max(x_max, std::abs(mesh.coordinates[n * 2]));
    check_axisymmetric(input, mesh, check, part ? part->x_max : x_max);
  }
}

}  // namespace

void check_input_against_mesh(const Input& input, const Mesh& mesh) {
  check_mesh(mesh);
  check_input(input, mesh, nullptr);
}

void check_input_against_mesh(const Input& input, const Mesh& local, const MeshPartNumbers& part) {
  check_input(input, local, &part);
}

}  // namespace grout
