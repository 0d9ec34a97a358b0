#pragma once
// Slave and master surfaces of a contact interface, from the side sets the input names:
// the whole interface (build_contact_surface), or the part one rank evaluates in distributed
// contact (assembly/contact_sides.hpp, then set_master_faces with the faces the parallel
// search ghosted, assembly/contact_distribution.hpp).

#include <array>
#include <functional>
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
  std::vector<GlobalIndex> ids;  ///< index of each face in its side set (ascending)
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
  /// Per slave face: 1 if its (slave, master) pairs are evaluated. Empty: every face. The
  /// D, M and frames of a slave node are complete if all its faces are evaluated.
  std::vector<char> integrate;
  /// Self-contact (slave and master faces from one side set, `ids` comparable): the coarse
  /// search drops a pair of faces that share a node or whose normals do not face each other.
  bool self = false;
  /// Self-contact: per face of the side set (by id), 1 = slave side, 0 = master side, −1 =
  /// neither; only (slave side, master side) pairs are kept. Empty: no side filter.
  std::vector<signed char> self_side;
};

/// Faces of the side sets `contact.slave` and `contact.master`. Throws InputError naming the
/// file and key if a side set is missing, empty, or the two share a node.
ContactSurface build_contact_surface(const Mesh& mesh, const Input& input,
                                     const ContactInput& contact);

/// The part of an interface that one rank evaluates (assembly/contact_sides.hpp builds it),
/// with `owns(node)` true for the nodes it owns:
/// - surface.slave: the slave faces with an owned node (integrate = 1), then, for the nodal
///   normals of their nodes, every other slave face around those nodes (integrate = 0), in
///   side-set order; surface.master is empty (set_master_faces);
/// - owned_master: the master faces whose lowest-numbered node is owned (each master face
///   has exactly one owner);
/// - shared_node: the lowest owned node that is on both surfaces (an input error the caller
///   reports on every rank), or −1.
struct LocalContactFaces {
  ContactSurface surface;
  SurfaceFaces owned_master;
  GlobalIndex shared_node = -1;
};

/// The input error for a node (0-based) on both surfaces of `contact`.
std::string shared_node_message(const Input& input, const ContactInput& contact, GlobalIndex node);

/// Sets the slave faces of `s` and indexes their nodes (slave_nodes, slave_index,
/// slave_node_faces); `s.integrate` is left as it is. For callers with their own surfaces
/// (api/ MortarCoupling); then set_master_faces.
void set_slave_faces(ContactSurface& s, SurfaceFaces slave);

/// Sets the master faces of `s` (ascending ids) and its node list (slave and master nodes).
void set_master_faces(ContactSurface& s, SurfaceFaces master);

/// Self-contact sides (docs/input.md "Self-contact"): `pairs` holds candidate pairs of faces
/// (ids in [0, n_faces), two values per pair, in any order, repeats allowed). The faces and
/// pairs form a graph; each connected component is 2-coloured by a breadth-first search from
/// its lowest face id, which is a slave face (1), its partners master faces (0), theirs slave
/// faces, and so on (neighbours visited in ascending id). Faces of no pair: −1. An odd cycle
/// leaves a pair on one side (dropped by the search). The same pairs in any order give the
/// same sides. `keep` (n_faces values, or empty): sides chosen before, kept as they are; the
/// search spreads from them (in ascending id) to their new partners before it colours the
/// components with no kept face.
std::vector<signed char> self_contact_sides(GlobalIndex n_faces,
                                            const std::vector<long long>& pairs,
                                            const std::vector<signed char>& keep = {});

/// Mean longest edge of the faces of side sets (one, or those of `self: [a, b, ...]`), summed
/// in side-set order (the same value on every rank of a replicated mesh); 0 if there is no
/// such set.
double mean_face_size(const Mesh& mesh, const std::vector<std::string>& set_names);
/// Longest edge of a face (its n nodes, in order).
double face_size(const Mesh& mesh, const GlobalIndex* nodes, int n);

/// The nodes of side sets (one, or those of `self: [a, b, ...]`), sorted and unique (empty if
/// there is no such set).
std::vector<GlobalIndex> side_set_nodes(const Mesh& mesh,
                                        const std::vector<std::string>& set_names);

}  // namespace grout
