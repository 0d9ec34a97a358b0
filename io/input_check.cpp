// check_input_against_mesh: what the input names must exist in the mesh it points to.

#include <map>

#include "io/errors.hpp"
#include "io/input.hpp"

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
  MeshCheck(const Input& input, const Mesh& mesh)
      : input_(input), mesh_(mesh), mesh_name_("mesh '" + mesh.file + "'") {}

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
  void side_set(const std::string& key_path, const std::string& name) const {
    if (!mesh_.find_side_set(name)) {
      fail(key_path,
           "no side set '" + name + "' in " + mesh_name_ + " (" + names_of(mesh_.side_sets) + ")");
    }
  }
  void node_set(const std::string& key_path, const std::string& name) const {
    if (!mesh_.find_node_set(name)) {
      fail(key_path,
           "no node set '" + name + "' in " + mesh_name_ + " (" + names_of(mesh_.node_sets) + ")");
    }
  }
  const std::string& mesh_name() const { return mesh_name_; }

 private:
  const Input& input_;
  const Mesh& mesh_;
  std::string mesh_name_;
};

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

}  // namespace

const MaterialInput* find_material(const Input& input, const ElementBlock& block) {
  for (const MaterialInput& m : input.materials)
    if (block.named(m.block)) return &m;
  return nullptr;
}

void check_input_against_mesh(const Input& input, const Mesh& mesh) {
  check_mesh(mesh);
  const MeshCheck check(input, mesh);
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
    check.side_set(key + "/slave", c.slave);
    check.side_set(key + "/master", c.master);
    const auto [it, fresh] = pair_of_slave.emplace(mesh.find_side_set(c.slave)->name, c.name);
    if (!fresh) {
      check.fail(key + "/slave", "side set '" + c.slave +
                                     "' is already the slave of grout/contact/" + it->second +
                                     " (a slave side belongs to one contact pair)");
    }
  }
  check_no_reverse_pairs(input, mesh, check);
}

}  // namespace grout
