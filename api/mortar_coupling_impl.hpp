#pragma once
// Private state of grout::MortarCoupling (not installed). The interface is held as Grout's own
// ContactSurface (assembly/contact_surface.hpp): slave faces of this rank first (integrate = 1),
// then, with a communicator, the other ranks' slave faces around its nodes (integrate = 0, for
// the nodal normals); the master faces are the host's (serial) or those the parallel search
// ghosted (assembly/contact_distribution.hpp). Node ids are the host's global ids.

#include <Kokkos_Core.hpp>
#include <utility>
#include <vector>

#include "assembly/contact_surface.hpp"
#include "grout/mortar_coupling.hpp"
#include "kernels/coarse_search.hpp"

namespace grout {

/// One surface as the host passed it (copied).
struct HostSurface {
  int cols = 2;
  std::vector<int> faces;      ///< n_faces × cols, host rows, −1 padding
  std::vector<long long> ids;  ///< per host row
  std::size_t n_nodes = 0;
  std::vector<double> x;        ///< n_nodes × dim, current coordinates
  long long first_face_id = 0;  ///< global id of face 0 (faces are numbered in rank order)
  std::size_t n_faces() const { return faces.size() / cols; }
  int face_nodes(std::size_t f) const {
    int n = 0;
    while (n < cols && faces[f * cols + n] >= 0) ++n;
    return n;
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

  // Kernel path (no derivatives): the launches of kernels/ on Views.
  Kokkos::View<int**> normal_faces, master_faces;
  Kokkos::View<const int**> slave_faces;  ///< the first n_own_slave_faces rows of normal_faces
  Kokkos::View<double**> coords, nodal_normals;
  Kokkos::View<double***> nodal_tangents;
  Kokkos::View<double*> g_tilde;
  SearchCandidates<Kokkos::HostSpace> candidates;
  CoarseSearchWorkspace<Kokkos::HostSpace> workspace;
  Kokkos::View<MortarPairResult<double>*> results;

  // Results, per slave row.
  std::vector<double> D, gaps, normals, tangents;
  std::vector<std::size_t> M_offsets;
  std::vector<long long> M_columns;
  std::vector<double> M_values;
  std::vector<int> M_position;  ///< per M entry: its master node's position in surface.nodes
  std::vector<long long> master_nodes;  ///< sorted unique M_columns
  std::vector<int> M_master;            ///< per M entry: index in master_nodes
  std::vector<int> master_index;        ///< work array of finish_M, per surface.nodes
  int pairs = 0;
  std::vector<DerivativeTriplet> dD, dM, dg;

  void build();                 ///< surface, host_row, row maps and views from the face sets
  void refresh_coordinates();   ///< x and coords from the host arrays
  void clear_results();         ///< zero D, gaps, frames; empty M and the derivatives
  void evaluate_values();       ///< kernel launches (values only)
  void evaluate_derivatives();  ///< evaluate_contact_mortar (values and exact derivatives)
  void finish_M();              ///< master_nodes, M_master (from M_position)
};

}  // namespace grout
