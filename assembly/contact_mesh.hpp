#pragma once
// The mesh as the contact interfaces read it (nonlinear/contact_interface.hpp): the replicated
// mesh, or one rank's part of the distributed mesh (parallel/distributed_mesh.hpp) with the
// global numbers of its entities. Contact works in global node numbers throughout, so that the
// two give the same surfaces, multipliers and sums:
// - a side set's faces: this rank's entries (`local_faces`: on a part, the entries whose
//   element it holds, each with its position in the file's set), or all of them in the file's
//   order (`all_faces`: on a part gathered from the owners of their elements, surface-sized),
//   each face with its nodes' global numbers and coordinates;
// - bodies (the connected components of the whole mesh's elements, io/mesh_bodies.hpp): on a
//   part each local node's body is the lowest global node of its body
//   (parallel/distributed_bodies.hpp), on the replicated mesh node_bodies' index.

#include <mpi.h>

#include <array>
#include <string>
#include <vector>

#include "io/mesh.hpp"
#include "kernels/mortar_types.hpp"

namespace grout {

/// What contact needs of one rank's part of a distributed mesh (pointers into a
/// DistributedMesh, which must outlive the ContactMesh, and its bodies).
struct ContactMeshPart {
  GlobalIndex global_num_nodes = 0;
  int rank = 0;
  const std::vector<GlobalIndex>* node_gid = nullptr;     ///< local node -> global node
  const std::vector<int>* element_owner = nullptr;        ///< owning rank of each local element
  const std::vector<GlobalIndex>* element_gid = nullptr;  ///< local element -> global element
  /// Per side set, per local entry: its position in the file's set; the file's set sizes.
  const std::vector<std::vector<GlobalIndex>>* side_set_position = nullptr;
  const std::vector<GlobalIndex>* side_set_global_size = nullptr;
  /// Per local node: the lowest global node of its body (empty: bodies unknown, -1).
  std::vector<GlobalIndex> node_body;
};

/// Faces of one side set, one entry per face: element (global), side, block (index in the
/// mesh's blocks, -1: the element is in none), number of face nodes (side_local_nodes; < 2:
/// the side is not a face), the nodes (global, outward order), their coordinates (3 per node),
/// the body of the first node, and the position in the file's set.
struct SideFaces {
  GlobalIndex set_size = 0;  ///< entries of the file's set
  std::vector<GlobalIndex> positions, elements;
  std::vector<int> sides, blocks, num_nodes;
  std::vector<std::array<GlobalIndex, max_face_nodes>> nodes;
  std::vector<std::array<double, 3 * max_face_nodes>> X;
  std::vector<GlobalIndex> bodies;
  std::size_t size() const { return positions.size(); }
};

class ContactMesh {
 public:
  /// The replicated mesh (global numbers are its own).
  explicit ContactMesh(const Mesh& replicated);
  /// One rank's part `local` of a distributed mesh; `comm` the ranks sharing the mesh.
  ContactMesh(const Mesh& local, const ContactMeshPart& part, MPI_Comm comm);

  const Mesh& mesh() const { return mesh_; }
  bool distributed() const { return part_ != nullptr; }
  int dimension() const { return mesh_.dimension; }
  GlobalIndex num_global_nodes() const;
  MPI_Comm comm() const { return comm_; }
  /// The global number of local node `n`.
  GlobalIndex global_node(GlobalIndex n) const;
  /// This rank's entries of side set `name` (null if the mesh has none: every rank agrees).
  bool has_side_set(const std::string& name) const { return mesh_.find_side_set(name); }
  SideFaces local_faces(const std::string& name) const;
  /// \brief Every face of side set `name`, in the file's order. On a part: collective, each
  /// face sent by the owner of its element to every rank (an all-gather of the set).
  SideFaces all_faces(const std::string& name) const;
  /// The body of local node `n` (equal for the nodes of one body, different otherwise).
  GlobalIndex body(GlobalIndex n) const;

 private:
  const Mesh& mesh_;
  const ContactMeshPart* part_ = nullptr;
  MPI_Comm comm_ = MPI_COMM_SELF;
  mutable std::vector<int> replicated_bodies_;  ///< node_bodies(mesh_), on first use
};

}  // namespace grout
