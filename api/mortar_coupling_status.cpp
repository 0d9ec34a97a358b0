// grout::MortarCoupling's checks of the result: the coverage of each slave row (row_status) and
// the orientation of the two surfaces against each other (check_orientation).
//
// Coverage: with the dual basis, D_jj = ∫_cov Φ_j dA over the part of node j's faces that a
// master covers; Φ_j is biorthogonal to the N¹_k on each face and Σ_k N¹_k = 1, so on a fully
// covered face ∫ Φ_j dA = ∫ N¹_j dA (Popp et al. 2010, eq. 30; docs/embedding.md, "Partly
// covered rows"). With the standard basis Σ_k D_jk = ∫_cov N¹_j dA. Either way
// c_j = w_j = ∫ N¹_j dA over the node's faces exactly when they are all covered.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "kernels/face_node_weight.hpp"
#include "kernels/face_normal.hpp"
#include "mortar_coupling_impl.hpp"

namespace grout {

void MortarCoupling::Impl::fill_row_status() {
  const std::size_t n_rows = slave.n_nodes;
  const bool dual = options.multipliers == MultiplierBasis::dual;
  std::vector<double> cw(2 * n_rows, 0.0);  // per row: c_j, w_j (standard: D's CRS is ready)
  for (std::size_t r = 0; r < n_rows; ++r) {
    double c = dual ? D[r] : 0.0;
    if (!dual)
      for (std::size_t k = D_offsets[r]; k < D_offsets[r + 1]; ++k) c += D_values[k];
    double w = 0.0;
    for (int k = row_face_offsets[r]; k < row_face_offsets[r + 1]; ++k) {
      const auto [f, a] = row_faces[k];
      const int n = surface.slave.num_nodes[f];
      double xf[max_face_nodes][3] = {};
      for (int b = 0; b < n; ++b) {
        const int i = position_of(surface.slave.nodes[f][b]);
        for (int d = 0; d < dim; ++d) xf[b][d] = options.derivatives ? x[i][d] : coords(i, d);
      }
      w += face_node_weight(dim, n, xf, a);
    }
    cw[2 * r] = c, cw[2 * r + 1] = w;
  }
  if (comm != MPI_COMM_NULL) cw = directory.sum_to_senders(slave.ids, cw, 2);
  double c_max = 0.0;
  for (std::size_t r = 0; r < n_rows; ++r) c_max = std::max(c_max, cw[2 * r]);
  if (comm != MPI_COMM_NULL) MPI_Allreduce(MPI_IN_PLACE, &c_max, 1, MPI_DOUBLE, MPI_MAX, comm);
  // The driver's "no master": D_jj ≤ 1e-8 max D (nonlinear/mechanics_problem.cpp).
  const double c_tol = 1e-8 * c_max;
  status.resize(n_rows);
  for (std::size_t r = 0; r < n_rows; ++r) {
    const double c = cw[2 * r], w = cw[2 * r + 1];
    status[r] = !(c > c_tol) || !(w > 0.0)    ? RowStatus::uncovered
                : std::abs(c - w) <= 1e-6 * w ? RowStatus::full
                                              : RowStatus::partial;
  }
  status_ready = true;
}

void MortarCoupling::Impl::orientation_sums(double sums[2], long long bad[2]) const {
  sums[0] = sums[1] = 0.0;
  bad[0] = bad[1] = -1;
  const bool full_D = options.multipliers != MultiplierBasis::dual;
  const int stride = dim == 2
                         ? (full_D ? PackPair<true, 2, 2>::stride : PackPair<false, 2, 2>::stride)
                         : (full_D ? PackPair<true, 4, 4>::stride : PackPair<false, 4, 4>::stride);
  const auto normal = [&](const Kokkos::View<int**>& table, int f, double n[3]) {
    double xf[max_face_nodes][3] = {};
    int k = 0;
    for (; k < int(table.extent(1)) && table(f, k) >= 0; ++k)
      for (int d = 0; d < dim; ++d) xf[k][d] = coords(table(f, k), d);
    return face_normal(dim, k, xf, n) == MortarStatus::ok;
  };
  for (std::size_t f = 0; f < n_own_slave_faces; ++f) {
    double ns[3] = {0.0, 0.0, 0.0};
    if (!normal(normal_faces, int(f), ns)) continue;
    for (int p = candidates.offsets(f); p < candidates.offsets(f + 1); ++p) {
      const double overlap = pair_values(std::size_t(p) * stride);
      if (!(overlap > 0.0)) continue;
      const int m = candidates.masters(p);
      double nm[3] = {0.0, 0.0, 0.0};
      if (!normal(master_faces, m, nm)) continue;
      const double cos = ns[0] * nm[0] + ns[1] * nm[1] + ns[2] * nm[2];
      sums[0] += overlap * cos;
      sums[1] += overlap;
      if (cos > 0.0 && bad[0] < 0) bad[0] = surface.slave.ids[f], bad[1] = surface.master.ids[m];
    }
  }
}

void MortarCoupling::check_orientation() const {
  // Surfaces that face each other have n_slave · n_master ≈ −1 on their overlapping pairs; +1
  // means that the faces of one of them are ordered into its body, which flips the sign of
  // its normals (for the slave: of every weighted gap). Collective with a communicator.
  const Impl& m = *impl_;
  double sums[2];
  long long bad[2];
  m.orientation_sums(sums, bad);
  if (m.comm != MPI_COMM_NULL) {
    MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, m.comm);
    long long first[2] = {bad[0] < 0 ? std::numeric_limits<long long>::max() : bad[0], 0};
    MPI_Allreduce(MPI_IN_PLACE, first, 1, MPI_LONG_LONG, MPI_MIN, m.comm);
    if (first[0] != bad[0]) bad[1] = std::numeric_limits<long long>::max();
    MPI_Allreduce(MPI_IN_PLACE, &bad[1], 1, MPI_LONG_LONG, MPI_MIN, m.comm);
    bad[0] = first[0];
  }
  if (!(sums[0] > 0.0)) return;
  char mean[32];
  std::snprintf(mean, sizeof mean, "%+.3f", sums[0] / sums[1]);
  throw MortarCouplingError(
      "grout::MortarCoupling: the slave and master surfaces face the same way: the overlap-"
      "weighted mean of n_slave · n_master over their overlapping faces is " +
      std::string(mean) + " (-1 for surfaces facing each other; e.g. slave face " +
      std::to_string(bad[0]) + " and master face " + std::to_string(bad[1]) +
      "). The faces of one surface are ordered into its body, which flips its normals (the "
      "slave's: the sign of every weighted gap). Reverse that surface's node order (LINE2 x1 -> "
      "x2 has the normal (dy, -dx)/L; TRI3/QUAD4 counter-clockwise seen from outside the body), "
      "or pass inside_points to name it");
}

}  // namespace grout
