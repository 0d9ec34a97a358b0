// The two evaluation paths of grout::MortarCoupling, both on Grout's own code:
//  - values only: the kernel launches of kernels/ (compute_nodal_normals, coarse_search, and
//    the pair kernels of mortar_integrate<Dim>, bench_mortar's, through mortar_integrate_each:
//    each pair packed into a compact record instead of a padded MortarPairResult), then one
//    pass over the slave rows that assembles D and M (CRS) and evaluates
//    g̃_j = −n_j·(D_jj x¹_j − Σ_l M_jl x²_l) from the assembled row, as the driver does
//    (nonlinear/contact_rows.cpp; kernels/weighted_gap.hpp) — instead of accumulate_weighted_gaps,
//    which would stream the pair results a second time (mortar_coupling_read_back.cpp: a merge, or
//    a scatter into the last pattern); with standard multipliers the same launch for full pair
//    matrices (mortar_integrate_matrices' kernels), and D as CRS too;
//  - with derivatives: evaluate_contact_mortar (assembly/contact_mortar), the driver's own
//    contact evaluation: the same launch of the pair kernels in Sacado forward AD
//    (mortar_integrate_gradients, with the frames of compute_slave_frames), and the chain rule
//    for the weighted gap.
// Both give D, M, g̃, normals and tangents per slave row; M as CRS with ascending master ids.

#include <algorithm>
#include <limits>
#include <type_traits>

#include "assembly/contact_mortar.hpp"
#include "kernels/mortar_integrate.hpp"
#include "kernels/surface_normals.hpp"
#include "kernels/weighted_gap.hpp"
#include "mortar_coupling_impl.hpp"

namespace grout {

void MortarCoupling::Impl::clear_results() {
  const std::size_t n_rows = slave.n_nodes;
  D.assign(n_rows, 0.0);
  gaps.assign(n_rows, 0.0);
  normals.assign(n_rows * dim, 0.0);
  tangents.assign(n_rows * (dim - 1) * dim, 0.0);
  M_offsets.assign(n_rows + 1, 0);
  M_columns.clear();
  M_values.clear();
  dD.clear();
  dM.clear();
  dg.clear();
}

template <int Dim, bool FullD, int NS, int NM>
MortarStatus MortarCoupling::Impl::integrate_pairs() {
  using Pack = PackPair<FullD, NS, NM>;
  using Pair = std::conditional_t<FullD, MortarPairMatrices<double>, MortarPairResult<double>>;
  const std::size_t size = std::size_t(candidates.n_pairs) * Pack::stride;
  if (pair_values.extent(0) < size)
    pair_values = Kokkos::View<double*>(
        Kokkos::view_alloc("grout::MortarCoupling::pair_values", Kokkos::WithoutInitializing),
        size);
  const MortarOptions kernel_options =
      mortar_options(Dim, options.integration, options.collocation_points);
  return mortar_integrate_each<Dim, Pair>(Kokkos::DefaultExecutionSpace(), slave_faces,
                                          master_faces, coords, nodal_normals, candidates.offsets,
                                          candidates.masters, options.multipliers, kernel_options,
                                          Pack{pair_values});
}

bool MortarCoupling::Impl::evaluate_values() {
  const std::string what = "grout::MortarCoupling::update: ";
  if (compute_nodal_normals(normal_faces, coords, nodal_normals) != MortarStatus::ok) return false;
  if (coarse_search(workspace, slave_faces, master_faces, coords, options.search_factor,
                    candidates) != MortarStatus::ok)
    throw MortarCouplingError(what + "the coarse search failed");
  // The pair kernels of mortar_integrate, each pair packed for the read-back (PackPair) instead
  // of stored as a padded MortarPairResult (176 bytes, 56 of them used in 2D): the read-back
  // streams the pairs once more, the internal path's weighted-gap launch once. Pairs that fail
  // (a far candidate whose projection does not converge) contribute zeros, as in the driver;
  // only inconsistent sizes are an error.
  const bool full_D = options.multipliers != MultiplierBasis::dual;
  const MortarStatus status =
      dim == 2 ? (full_D ? integrate_pairs<2, true, 2, 2>() : integrate_pairs<2, false, 2, 2>())
               : (full_D ? integrate_pairs<3, true, 4, 4>() : integrate_pairs<3, false, 4, 4>());
  if (status == MortarStatus::capacity_exceeded)
    throw MortarCouplingError(what + "internal error: pair candidates too short");
  read_back();
  return true;
}

void MortarCoupling::Impl::fill_diagonal_D() {
  // The dual D as CRS: each row with an overlapping pair (an M entry) has its diagonal entry.
  const std::size_t n_rows = slave.n_nodes;
  D_offsets.assign(n_rows + 1, 0);
  D_columns.clear();
  D_values.clear();
  for (std::size_t r = 0; r < n_rows; ++r) {
    if (M_offsets[r + 1] > M_offsets[r]) {
      D_columns.push_back(slave.ids[r]);
      D_values.push_back(D[r]);
    }
    D_offsets[r + 1] = D_columns.size();
  }
  D_crs_ready = true;
}

void MortarCoupling::Impl::fill_tangents() {
  tangents.assign(slave.n_nodes * (dim - 1) * dim, 0.0);
  if (!options.derivatives) {  // the tangents kernel on the nodal normals of the last update
    compute_nodal_tangents(nodal_normals, nodal_tangents);
    for (std::size_t r = 0; r < slave.n_nodes; ++r) {
      const int i = slave_row_position[r];
      if (i < 0) continue;
      for (int k = 0; k < dim - 1; ++k)
        for (int d = 0; d < dim; ++d)
          tangents[(r * (dim - 1) + k) * dim + d] = nodal_tangents(i, k, d);
    }
  }
  tangents_ready = true;
}

void MortarCoupling::Impl::evaluate_derivatives() {
  ContactMortarOptions o;
  o.mortar = mortar_options(dim, options.integration, options.collocation_points);
  o.search_factor = options.search_factor;
  o.derivatives = true;
  const ContactMortar mortar = evaluate_contact_mortar(surface, x, o);
  pairs = mortar.pairs;
  tangents_ready = true;
  D_crs_ready = false;  // the frames' tangents, filled below

  const std::size_t n_rows = slave.n_nodes;
  clear_results();
  const auto position = [&](long long id) {
    return std::size_t(std::lower_bound(surface.nodes.begin(), surface.nodes.end(), id) -
                       surface.nodes.begin());
  };
  SparseGradient g_grad;
  for (std::size_t r = 0; r < n_rows; ++r) {
    M_offsets[r + 1] = M_offsets[r];
    const int j = slave_row_index[r];
    if (j < 0) continue;
    const SlaveFrame& frame = mortar.frames[j];
    for (int d = 0; d < dim; ++d) {
      normals[r * dim + d] = frame.n[d];
      for (int k = 0; k < dim - 1; ++k) tangents[(r * (dim - 1) + k) * dim + d] = frame.t[k][d];
    }
    const MortarValue& Dj = mortar.D[j];
    D[r] = Dj.value;
    for (const auto& [dof, v] : Dj.gradient) dD.push_back({int(r), dof, v});
    // g̃_j = −n_j · v_j, v_j = D_jj x¹_j − Σ_l M_jl x²_l, and its derivative (product rule).
    const auto& xj = x[slave_row_position[r]];
    double v[3] = {0.0, 0.0, 0.0};
    for (int d = 0; d < dim; ++d) v[d] = Dj.value * xj[d];
    g_grad.clear();
    for (int d = 0; d < dim; ++d) {
      for (const auto& [dof, dv] : Dj.gradient) g_grad.emplace_back(dof, -frame.n[d] * xj[d] * dv);
      g_grad.emplace_back(slave.ids[r] * dim + d, -frame.n[d] * Dj.value);
    }
    const auto begin = mortar.M.lower_bound({j, std::numeric_limits<GlobalIndex>::min()});
    const auto end = mortar.M.lower_bound({j + 1, std::numeric_limits<GlobalIndex>::min()});
    for (auto it = begin; it != end; ++it) {
      const long long master = it->first.second;
      const MortarValue& Mjl = it->second;
      const std::size_t i_m = position(master);
      const auto& xl = x[i_m];
      const int k = int(M_values.size());
      M_columns.push_back(master);
      M_values.push_back(Mjl.value);
      for (const auto& [dof, dv] : Mjl.gradient) dM.push_back({k, dof, dv});
      for (int d = 0; d < dim; ++d) {
        v[d] -= Mjl.value * xl[d];
        for (const auto& [dof, dv] : Mjl.gradient)
          g_grad.emplace_back(dof, frame.n[d] * xl[d] * dv);
        g_grad.emplace_back(master * dim + d, frame.n[d] * Mjl.value);
      }
    }
    M_offsets[r + 1] = M_columns.size();
    for (int d = 0; d < dim; ++d)
      for (const auto& [dof, dn] : frame.dn[d]) g_grad.emplace_back(dof, -v[d] * dn);
    // Exactly 0 on a row without pairs (D = 0, no M entries).
    gaps[r] = weighted_gap_of_row(dim, frame.n, v);
    compress_gradient(g_grad);
    for (const auto& [dof, dv] : g_grad) dg.push_back({int(r), dof, dv});
  }
}

}  // namespace grout
