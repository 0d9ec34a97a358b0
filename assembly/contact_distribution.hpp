#pragma once
// Parallel coarse search for distributed contact: which master faces a rank needs.
//
// Each rank evaluates only its own slave faces. The master faces are distributed as well
// (each has one owning rank). Per search:
//   1. every rank bounds its slave faces by one region, the union of their enlarged boxes
//      (face_bounding_box with the search factor), and the regions are all-gathered;
//   2. every rank sends each other rank the owned master faces whose enlarged box overlaps
//      that rank's region, with their nodes, coordinates and any per-node data (one
//      all-to-all of counts and one of the records);
//   3. every rank gets, sorted by face id, the master faces that can overlap its slave faces.
// A (slave, master) pair whose enlarged boxes overlap has the master in the region of the
// slave's rank, so a local coarse search against the received faces finds exactly the pairs
// of a search against the whole master surface. No rank gathers a whole surface (unless
// its slave faces face all of it).
//
// The interface is plain data (face ids, connectivity, coordinates, an MPI communicator) so
// that a caller with its own mesh can use it as it is.

#include <mpi.h>

#include <array>
#include <vector>

#include "io/mesh.hpp"
#include "kernels/mortar_types.hpp"

namespace grout {

/// Faces of one rank as plain data; per face node: global node id, 3 coordinates (the ones
/// the boxes are computed from; unused components 0) and `payload_size` extra values that
/// travel with the face (displacements, reference coordinates, ...).
struct FaceSet {
  int dimension = 2;
  int payload_size = 0;
  std::vector<GlobalIndex> ids;                                     ///< global face ids
  std::vector<int> num_nodes;                                       ///< 2, 3 or 4
  std::vector<std::array<GlobalIndex, max_face_nodes>> nodes;       ///< −1 padded
  std::vector<std::array<double, 3 * max_face_nodes>> coordinates;  ///< node a: [3a, 3a+3)
  std::vector<double>
      payload;  ///< face f, node a, value v: ((f·max_face_nodes + a)·payload_size + v)
  std::size_t size() const { return ids.size(); }
  /// Appends a face (payload: payload_size values per node, num_nodes nodes).
  void add(GlobalIndex id, int n, const GlobalIndex* face_nodes, const double (*x)[3],
           const double* node_payload = nullptr);
};

/// Closed axis-aligned box; empty when no face contributed.
struct SearchRegion {
  bool empty = true;
  double lo[3] = {0.0, 0.0, 0.0}, hi[3] = {0.0, 0.0, 0.0};
};

/// Union of the enlarged boxes (face_bounding_box, `factor`) of the faces, or of the faces
/// whose `include` flag is set when `include` is non-empty.
SearchRegion search_region(const FaceSet& faces, double factor,
                           const std::vector<char>& include = {});

/// Collective. Every rank passes the master faces it owns (each face owned by one rank) and
/// the region of its slave faces. Returns the master faces of all ranks whose enlarged box
/// (face_bounding_box, `factor`) overlaps this rank's region, sorted by id, with their
/// nodes, coordinates and payload as the owner passed them.
FaceSet ghost_master_faces(const FaceSet& owned_master, const SearchRegion& region, double factor,
                           MPI_Comm comm);

/// The faces of `a` and `b` (each sorted by id, with the same payload size), sorted by id,
/// each id once (a face in both keeps a's record).
FaceSet merge_face_sets(const FaceSet& a, const FaceSet& b);

/// Collective all-to-all of variable-length messages: send[r] goes to rank r (send.size()
/// = comm size, an empty message for no data). Returns the messages received, concatenated
/// in rank order; recv_counts (if given) gets their sizes.
std::vector<double> exchange_with_ranks(const std::vector<std::vector<double>>& send, MPI_Comm comm,
                                        std::vector<int>* recv_counts = nullptr);
std::vector<long long> exchange_with_ranks(const std::vector<std::vector<long long>>& send,
                                           MPI_Comm comm, std::vector<int>* recv_counts = nullptr);

}  // namespace grout
