#pragma once
// Slave and master surfaces of a contact interface, from the side sets the input names.
// Replicated on every rank (contact surfaces are small next to the volume mesh).

#include <array>
#include <string>
#include <unordered_map>
#include <vector>

#include "io/input.hpp"
#include "io/mesh.hpp"
#include "kernels/mortar_types.hpp"

namespace grout {

struct SurfaceFaces {
  std::vector<std::array<GlobalIndex, max_face_nodes>> nodes;  ///< global nodes, outward order
  std::vector<int> num_nodes;                                  ///< 2 (line2), 3 or 4
  std::vector<const ElementBlock*> blocks;                     ///< block of each face's element
  std::size_t size() const { return nodes.size(); }
};

struct ContactSurface {
  std::string name;  ///< key under grout/contact
  ContactKind type = ContactKind::frictionless;
  int dimension = 2;
  SurfaceFaces slave, master;
  std::vector<GlobalIndex> slave_nodes;              ///< sorted, unique
  std::unordered_map<GlobalIndex, int> slave_index;  ///< global node -> index in slave_nodes
  std::vector<std::vector<int>> slave_node_faces;    ///< slave node index -> slave faces
  std::vector<GlobalIndex> nodes;                    ///< slave and master nodes, sorted
};

/// Faces of the side sets `contact.slave` and `contact.master`. Throws InputError naming the
/// file and key if a side set is missing, empty, or the two share a node.
ContactSurface build_contact_surface(const Mesh& mesh, const Input& input,
                                     const ContactInput& contact);

}  // namespace grout
