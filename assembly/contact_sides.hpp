#pragma once
// What one contact interface reads of its side sets (nonlinear/contact_interface.hpp), on the
// replicated mesh or on one rank's part of the distributed mesh (assembly/contact_mesh.hpp),
// with the same values either way:
// - the part of the surfaces this rank evaluates (LocalContactFaces of contact_surface.hpp):
//   the slave faces with an owned node and their neighbours, from the whole slave surface (on
//   a part gathered: a neighbour's element may lie beyond the ghost layer), and the master
//   faces whose lowest node is owned (their elements are local);
// - the coordinates of those faces' nodes;
// - the global quantities: the slave nodes of the whole side set(s) (the multiplier
//   numbering), the mean slave face size summed in side-set order (ĉ = E/h), the number of
//   slave faces (self-contact), the block of each side's first face (E);
// - the input checks of build_contact_surface: sets that exist and are not empty, faces of
//   elements in a block, slave and master faces on different bodies.

#include <array>
#include <functional>
#include <unordered_map>
#include <vector>

#include "assembly/contact_mesh.hpp"
#include "assembly/contact_surface.hpp"

namespace grout {

struct ContactSides {
  LocalContactFaces local;
  /// Reference coordinates of the nodes of local.surface's slave faces and local.owned_master.
  std::unordered_map<GlobalIndex, std::array<double, 3>> X;
  std::vector<GlobalIndex> all_slave_nodes;  ///< sorted, unique
  double mean_slave_face_size = 0.0;
  GlobalIndex num_slave_faces = 0;
  const ElementBlock* slave_block = nullptr;   ///< block of the slave side's first face
  const ElementBlock* master_block = nullptr;  ///< block of the master side's first face
};

/// \brief Collective on a distributed part (gathers the slave side set(s), surface-sized).
/// `owns(node)`: whether this rank owns global node `node`. Throws InputError with the
/// messages of build_contact_surface (the same outcome on every rank, except that of
/// shared_node, which the caller reduces).
ContactSides read_contact_sides(const ContactMesh& mesh, const Input& input,
                                const ContactInput& contact,
                                const std::function<bool(GlobalIndex)>& owns);

/// Longest edge of a face of n nodes with coordinates x (3 per node, in order), as face_size.
double face_size_of(int dim, const std::array<double, 3>* x, int n);

}  // namespace grout
