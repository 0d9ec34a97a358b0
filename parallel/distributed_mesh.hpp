#pragma once
// The distributed mesh: each rank holds the elements it owns, one layer of ghost elements
// (every element sharing a node with an owned one), the nodes of both, and the entries of
// the side and node sets on them; no rank holds a whole-mesh array at any point, from the
// file on (docs/design.md, "parallel/").
//
// Pipeline of read_distributed_mesh (all steps collective):
//   1. header on rank 0, broadcast; slices of nodes, elements and sets read by every rank
//      (parallel/exodus_slices.hpp);
//   2. element centroids: coordinates of the slice elements' nodes fetched from the ranks
//      whose node slice holds them (a directory keyed by node id);
//   3. Zoltan2 RCB on the centroids (parallel/element_partition.hpp), with contact side sets
//      the elements with a face on them weighted or partitioned apart, in bands of their
//      distance to the other surface (DistributionOptions, parallel/contact_bands.hpp);
//   4. node owners (lowest part among the node's elements, as assembly/partition.hpp; with
//      contact side sets, among its contact elements first, so that the contact work, which
//      follows the owned slave nodes, follows the contact elements' partition) and
//      ghost destinations, from the node directory; migration of elements, nodes and set
//      entries to the ranks that hold them (parallel/migrate_mesh.cpp);
//   5. the checks of check_mesh on owned entities, messages in global numbers.

#include <string>
#include <vector>

#include "assembly/mesh_part.hpp"
#include "assembly/tpetra_types.hpp"
#include "io/mesh.hpp"

namespace grout {

/// \brief One rank's part of a mesh. `local` is a plain Mesh over this rank's entities with
/// local indices, so code written for Mesh runs on it:
/// - nodes: [0, num_owned_nodes) owned, ascending global id, then ghost nodes, ascending;
/// - elements: block by block in the file's block order (every block present, possibly
///   empty); within a block the owned elements, ascending global id, then the ghosts;
///   `local.blocks[b].first_element` is the local index of the block's first element;
/// - side sets: the file's entries whose element is local, in the file's order, elements as
///   local indices; node sets: the entries whose node is local, in the file's order.
/// Names, ids, topologies and the file are the file's.
struct DistributedMesh {
  Mesh local;
  int rank = 0, num_ranks = 1;
  GlobalIndex global_num_nodes = 0, global_num_elements = 0;
  std::vector<GlobalIndex> block_global_first;  ///< file's first element of each block
  std::vector<GlobalIndex> block_global_size;   ///< file's element count of each block
  std::vector<GlobalIndex> side_set_global_size, node_set_global_size;

  GlobalIndex num_owned_nodes = 0;
  std::vector<GlobalIndex> node_gid;            ///< local node -> 0-based node of the file
  std::vector<int> node_owner;                  ///< owning rank of each local node
  std::vector<GlobalIndex> element_gid;         ///< local element -> 0-based global element
  std::vector<int> element_owner;               ///< owning rank of each local element
  std::vector<GlobalIndex> num_owned_in_block;  ///< owned elements of each block
  /// Per set, per local entry: its 0-based position in the file's set (a face's or node's
  /// number within the set, as the replicated Mesh orders them).
  std::vector<std::vector<GlobalIndex>> side_set_position, node_set_position;

  GlobalIndex num_local_nodes() const { return GlobalIndex(node_gid.size()); }
  GlobalIndex num_local_elements() const { return GlobalIndex(element_gid.size()); }
  GlobalIndex num_owned_elements() const;
  bool owns_node(GlobalIndex local_node) const { return node_owner[local_node] == rank; }
  bool owns_element(GlobalIndex local_element) const {
    return element_owner[local_element] == rank;
  }
  /// Local index of global node `gid`, or -1 when this rank does not hold it.
  GlobalIndex local_node(GlobalIndex gid) const;
  /// Local index of global element `gid`, or -1 when this rank does not hold it.
  GlobalIndex local_element(GlobalIndex gid) const;
};

/// The part SolidProblem reads (references into `mesh`, which must outlive its use).
inline MeshPart mesh_part(const DistributedMesh& mesh) {
  return MeshPart{mesh.local,      mesh.global_num_nodes, mesh.global_num_elements, mesh.node_gid,
                  mesh.node_owner, mesh.element_gid,      mesh.element_owner};
}

/// How the elements are partitioned.
struct DistributionOptions {
  /// The contact surface: side sets (names or "id_<n>"); the elements with a face on them
  /// (contact elements) weigh 1 + contact_weight, or count as a second criterion, or are
  /// partitioned apart (below), and their parts own their nodes first. Unused when none of
  /// the three is asked for.
  std::vector<std::string> contact_side_sets;
  /// Leave out the contact side sets the file lacks (the driver's input checks name them with
  /// their key) instead of an InputError.
  bool skip_missing_sets = false;
  double contact_weight = 0.0;
  /// Balance two criteria instead: elements (weight 1 each) and elements on the contact side
  /// sets (Zoltan's multi-criteria RCB: one cut per level, the direction whose cut balances
  /// both best), so each part gets its share of both as far as one plane allows.
  bool balance_contact = false;
  /// Partition the elements with a face on the contact side sets and the other elements
  /// separately, one RCB each (weights 1): each part gets its share of both within RCB's 1 %
  /// whatever the geometry, at the price of contact elements whose neighbours may lie on
  /// another part (a surface-sized ghost layer).
  bool separate_contact = false;
  /// With separate_contact: the master side sets of the contact pairs. Their elements are
  /// contact elements too (partitioned apart, owning their nodes first), and the contact
  /// elements are sorted by their distance to the other surface, cut into bands of equal
  /// count, each band partitioned by its own RCB (parallel/contact_bands.hpp): every part gets
  /// its share of the contact zone on both surfaces, which grows from the closest faces,
  /// instead of one part all of it.
  std::vector<std::string> master_side_sets;
};

/// \brief Collective. Reads the Exodus mesh `path` in slices and distributes it (see the
/// file comment). Throws InputError (on the rank that found it; ErrorOnOtherRank on the
/// others) with the messages of read_exodus and check_mesh, elements and nodes named by
/// their global (file) numbers.
DistributedMesh read_distributed_mesh(const Comm& comm, const std::string& path,
                                      const DistributionOptions& options = {});

/// What one rank holds.
struct MeshHoldings {
  GlobalIndex owned_nodes = 0, ghost_nodes = 0, owned_elements = 0, ghost_elements = 0;
  GlobalIndex owned_side_set_entries = 0;  ///< faces of owned elements in all side sets
};
MeshHoldings mesh_holdings(const DistributedMesh& mesh);

/// \brief Collective. One line per rank, "rank r: nodes owned + ghost = n (x % of N),
/// elements owned + ghost = ... , side-set faces owned ...", gathered to rank 0 (the text is
/// empty elsewhere), for the driver's --timers report.
std::string describe_holdings(const Comm& comm, const DistributedMesh& mesh);

}  // namespace grout
