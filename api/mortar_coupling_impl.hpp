#pragma once
// Private state of grout::MortarCoupling (not installed). The interface is held as Grout's own
// ContactSurface (assembly/contact_surface.hpp): slave faces of this rank first (integrate = 1),
// then, with a communicator, the other ranks' slave faces around its nodes (integrate = 0, for
// the nodal normals); the master faces are the host's (serial) or those the parallel search
// ghosted (assembly/contact_distribution.hpp). Node ids are the host's global ids.

#include <Kokkos_Core.hpp>
#include <functional>
#include <utility>
#include <vector>

#include "assembly/contact_surface.hpp"
#include "grout/mortar_coupling.hpp"
#include "kernels/coarse_search.hpp"
#include "kernels/mortar_types.hpp"
#include "kernels/weighted_gap.hpp"
#include "node_directory.hpp"

namespace grout {

/// Runs `phase`; with a communicator, an error on any rank is thrown on every rank (the lowest
/// failing rank's message), so that no rank is left waiting in a collective.
void agree_on_error(MPI_Comm comm, const std::function<void()>& phase);

/// One surface as the host passed it (copied).
struct HostSurface {
  int cols = 2;
  std::vector<int> faces;      ///< n_faces × cols, host rows, −1 padding
  std::vector<long long> ids;  ///< per host row
  std::size_t n_nodes = 0;
  /// n_nodes × dim coordinates: kept current on the distributed and derivative paths; the
  /// serial value path reads the host's arrays in update (these are the constructor's).
  std::vector<double> x;
  long long first_face_id = 0;  ///< global id of face 0 (faces are numbered in rank order)
  std::size_t n_faces() const { return faces.size() / cols; }
  int face_nodes(std::size_t f) const {
    int n = 0;
    while (n < cols && faces[f * cols + n] >= 0) ++n;
    return n;
  }
};

/// Sink of mortar_integrate_each: packs one pair (MortarPairResult: dual D_jj, or
/// MortarPairMatrices: full D_jk) into its record of MortarCoupling::Impl::pair_values,
/// [overlap, D, M] with NS slave and NM master nodes (D at offset D, M at offset M, row-major);
/// a pair without overlap gets only its overlap, which the read-back tests first.
template <bool FullD, int NS, int NM>
struct PackPair {
  static constexpr int D = 1, M = 1 + (FullD ? NS * NS : NS), stride = M + NS * NM;
  Kokkos::View<double*> records;
  template <class Pair>
  KOKKOS_INLINE_FUNCTION void operator()(int, int p, const Pair& pair) const {
    double* o = records.data() + std::size_t(p) * stride;
    o[0] = pair.overlap;
    if (!(pair.overlap > 0.0)) return;
    for (int j = 0; j < NS; ++j) {
      if constexpr (FullD) {
        for (int k = 0; k < NS; ++k) o[D + j * NS + k] = pair.D[j][k];
      } else {
        o[D + j] = pair.D[j];
      }
      for (int l = 0; l < NM; ++l) o[M + j * NM + l] = pair.M[j][l];
    }
  }
};

struct MortarCoupling::Impl {
  int dim = 2;
  MortarCouplingOptions options;
  MPI_Comm comm = MPI_COMM_NULL;
  int rank = 0, size = 1;
  HostSurface slave, master;
  bool built = false;  ///< surface and views match the current face sets (serial: once)

  // The local interface.
  ContactSurface surface;
  std::size_t n_own_slave_faces = 0;
  std::vector<std::array<double, 3>> x;       ///< per surface.nodes
  std::vector<std::pair<int, int>> host_row;  ///< per surface.nodes: (0 slave / 1 master, row)
  std::vector<int> slave_row_index;           ///< slave row → index in surface.slave_nodes, −1
  std::vector<int> slave_row_position;        ///< slave row → position in surface.nodes, −1
  /// Per slave row, the (own slave face, local node) pairs it is on (CRS): the read-back of D
  /// and M visits a row's faces without a search.
  std::vector<int> row_face_offsets;
  std::vector<std::pair<int, int>> row_faces;

  // Kernel path (no derivatives): the launches of kernels/ on Views.
  Kokkos::View<int**> normal_faces, master_faces;
  Kokkos::View<const int**> slave_faces;  ///< the first n_own_slave_faces rows of normal_faces
  Kokkos::View<double**> coords, nodal_normals;
  Kokkos::View<double***> nodal_tangents;
  SearchCandidates<Kokkos::HostSpace> candidates;
  CoarseSearchWorkspace<Kokkos::HostSpace> workspace;
  /// Per candidate pair, what the read-back uses of its MortarPairResult (dual basis) or
  /// MortarPairMatrices (other bases), packed: [overlap, D (n_s or n_s × n_s), M (n_s × n_m)],
  /// n_s, n_m the widest slave and master faces (2D: 7 or 9 doubles against the padded
  /// structs' 22 or 34); the remaining entries of a pair without overlap are not written.
  Kokkos::View<double*> pair_values;
  int slave_width = 2, master_width = 2;  ///< n_s, n_m

  // Results, per slave row.
  std::vector<double> D, gaps, normals, tangents;
  std::vector<std::size_t> M_offsets;
  std::vector<long long> M_columns;
  std::vector<double> M_values;
  /// D as CRS (columns slave node ids): standard basis, from the pairs; dual, the diagonal,
  /// filled on first read (fill_diagonal_D).
  std::vector<std::size_t> D_offsets;
  std::vector<long long> D_columns;
  std::vector<double> D_values;
  bool D_crs_ready = false;
  /// Work arrays of the read-back: per surface.nodes, the slot of a master node in the current
  /// row (−1 when absent); the row's (position, value) entries.
  std::vector<int> slot;
  std::vector<std::pair<int, double>> row_entries, row_D_entries;
  /// The pattern of the last merge: the candidate lists it was made for, which pairs overlapped,
  /// per pair entry (p, slave node a, master node l / slave node b) its index in M_values /
  /// D_values (−1: padding), per M/D entry its node's position in surface.nodes. Valid until
  /// the faces change (build).
  bool pattern_valid = false;
  std::vector<int> pattern_offsets, pattern_masters, M_dest, D_dest, M_position, D_position;
  std::vector<char> pattern_overlap;
  std::vector<int> own_face_rows;  ///< own slave face × slave_width: host slave row, −1
  std::vector<double> view_x[2];   ///< update(View): gathered strided coordinates
  bool tangents_ready = false;     ///< tangents are filled on first read after an update
  int pairs = 0;
  std::vector<DerivativeTriplet> dD, dM, dg;
  /// The host's slave rows then master rows, by id: owners and sums over the ranks.
  NodeDirectory directory;
  std::vector<int> slave_owner, master_owner;  ///< per host row: the owning rank
  std::vector<RowStatus> status;               ///< per slave row (fill_row_status)
  bool status_ready = false;

  /// row_status from c_j (D_jj or Σ_k D_jk) and w_j = ∫ N¹_j dA over the row's own faces,
  /// both summed over the ranks by id (mortar_coupling_status.cpp). Collective.
  void fill_row_status();
  /// The orientation check's local sums over the overlapping pairs of the values path:
  /// sums[0] = Σ overlap n_s·n_m, sums[1] = Σ overlap; bad = the first (slave face id, master
  /// face id) with n_s·n_m > 0, or (−1, −1).
  void orientation_sums(double sums[2], long long bad[2]) const;

  void build();  ///< surface, host_row, row maps and views from the face sets
  /// x (derivatives) or coords (values) from the host arrays; false if one is not finite.
  bool refresh_coordinates(const double* xs, const double* xm);
  void clear_results();  ///< zero D, gaps, frames; empty M and the derivatives
  /// Kernel launches (values only); false if a slave face has no normal (degenerate).
  bool evaluate_values();
  /// Integration launch (mortar_integrate_each) into pair_values, with NS × NM faces.
  template <int Dim, bool FullD, int NS, int NM>
  MortarStatus integrate_pairs();
  /// D, M (CRS), gaps, normals per slave row from pair_values (mortar_coupling_read_back.cpp):
  /// read_back_scatter if the pattern holds, else read_back_merge (which records it).
  void read_back();
  template <bool FullD, int NS, int NM>
  void read_back_merge();
  template <bool FullD, int NS, int NM>
  bool read_back_scatter();
  /// Slave row r (its node at position i of the slave surface, −1 if none): the normal n_r and
  /// the weighted gap g̃_r = −n_r · v, v = Σ_k D_rk x_k − Σ_l M_rl x_l (the assembled row).
  void store_row_gap(std::size_t r, int i, const double v[3]) {
    for (int d = 0; d < dim; ++d) normals[r * dim + d] = i >= 0 ? nodal_normals(i, d) : 0.0;
    gaps[r] = weighted_gap_of_row(dim, &normals[r * dim], v);
  }
  void fill_diagonal_D();
  void evaluate_derivatives();  ///< evaluate_contact_mortar (values and exact derivatives)
  void fill_tangents();         ///< tangents per slave row (values path: on first read)
  /// Position of a node id in surface.nodes (sorted).
  int position_of(long long id) const;
  /// Master node ids with an M entry (ascending) and each M entry's index among them.
  void master_nodes_of_M(std::vector<long long>& nodes, std::vector<int>& entry_node) const;
};

}  // namespace grout
