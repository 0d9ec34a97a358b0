// The two evaluation paths of grout::MortarCoupling, both on Grout's own code:
//  - values only: the kernel launches of kernels/ (compute_nodal_normals, coarse_search,
//    mortar_integrate<Dim>, accumulate_weighted_gaps), the path perf/bench_mortar times;
//  - with derivatives: evaluate_contact_mortar (assembly/contact_mortar), the driver's own
//    contact evaluation (Sacado forward AD through the same pair kernels), and the chain rule
//    for the weighted gap.
// Both give D, M, g̃, normals and tangents per slave row; M as CRS with ascending master ids.

#include <algorithm>
#include <limits>

#include "assembly/contact_mortar.hpp"
#include "kernels/mortar_integrate.hpp"
#include "kernels/surface_normals.hpp"
#include "kernels/weighted_gap.hpp"
#include "mortar_coupling_impl.hpp"

namespace grout {

namespace {

/// Sorts a row's (master position, value) entries by position (positions are in id order).
void sort_row(std::vector<std::pair<int, double>>& row) {
  std::sort(row.begin(), row.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
}

}  // namespace

void MortarCoupling::Impl::clear_results() {
  const std::size_t n_rows = slave.n_nodes;
  D.assign(n_rows, 0.0);
  gaps.assign(n_rows, 0.0);
  normals.assign(n_rows * dim, 0.0);
  tangents.assign(n_rows * (dim - 1) * dim, 0.0);
  M_offsets.assign(n_rows + 1, 0);
  M_columns.clear();
  M_values.clear();
  M_position.clear();
  dD.clear();
  dM.clear();
  dg.clear();
}

void MortarCoupling::Impl::evaluate_values() {
  const std::string what = "grout::MortarCoupling::update: ";
  MortarOptions kernel_options;
  kernel_options.scheme = options.integration;
  kernel_options.n_collocation = dim == 2 ? options.collocation_points
                                          : options.collocation_points * options.collocation_points;
  if (compute_nodal_normals(normal_faces, coords, nodal_normals) != MortarStatus::ok)
    throw MortarCouplingError(what + "a slave face has no normal (degenerate)");
  compute_nodal_tangents(nodal_normals, nodal_tangents);
  if (coarse_search(workspace, slave_faces, master_faces, coords, options.search_factor,
                    candidates) != MortarStatus::ok)
    throw MortarCouplingError(what + "the coarse search failed");
  if (results.extent(0) < std::size_t(candidates.n_pairs))
    results = Kokkos::View<MortarPairResult<double>*>(
        Kokkos::view_alloc("grout::MortarCoupling::pairs", Kokkos::WithoutInitializing),
        std::size_t(candidates.n_pairs));
  const MortarStatus status =
      dim == 2
          ? mortar_integrate_2d(slave_faces, master_faces, coords, nodal_normals,
                                candidates.offsets, candidates.masters, kernel_options, results)
          : mortar_integrate_3d(slave_faces, master_faces, coords, nodal_normals,
                                candidates.offsets, candidates.masters, kernel_options, results);
  // Pairs that fail (a far candidate whose projection does not converge) contribute zeros, as
  // in the driver; only inconsistent sizes are an error.
  if (status == MortarStatus::capacity_exceeded)
    throw MortarCouplingError(what + "internal error: pair results too short");
  accumulate_weighted_gaps(slave_faces, master_faces, coords, nodal_normals, candidates.offsets,
                           candidates.masters, results, g_tilde);

  // D and M per slave row: the pairs of the row's own faces, faces in order.
  const std::size_t n_rows = slave.n_nodes;
  clear_results();
  pairs = 0;
  for (std::size_t f = 0; f < n_own_slave_faces; ++f)
    for (int p = candidates.offsets(f); p < candidates.offsets(f + 1); ++p)
      if (results(p).overlap > 0.0) ++pairs;
  std::vector<std::pair<int, double>> row;  // (master position in surface.nodes, M_jl)
  for (std::size_t r = 0; r < n_rows; ++r) {
    M_offsets[r + 1] = M_offsets[r];
    const int j = slave_row_index[r], i = slave_row_position[r];
    if (j < 0) continue;
    for (int d = 0; d < dim; ++d) {
      normals[r * dim + d] = nodal_normals(i, d);
      for (int k = 0; k < dim - 1; ++k)
        tangents[(r * (dim - 1) + k) * dim + d] = nodal_tangents(i, k, d);
    }
    gaps[r] = g_tilde(i);
    row.clear();
    double D_r = 0.0;
    for (int f : surface.slave_node_faces[j]) {
      if (std::size_t(f) >= n_own_slave_faces) continue;
      int a = 0;
      while (surface.slave.nodes[f][a] != slave.ids[r]) ++a;
      for (int p = candidates.offsets(f); p < candidates.offsets(f + 1); ++p) {
        const MortarPairResult<double>& pair = results(p);
        if (!(pair.overlap > 0.0)) continue;
        D_r += pair.D[a];
        const int m = candidates.masters(p);
        for (int l = 0; l < pair.n_master; ++l) {
          const int id = master_faces(m, l);  // positions are in id order
          auto it =
              std::find_if(row.begin(), row.end(), [&](const auto& e) { return e.first == id; });
          if (it == row.end())
            row.emplace_back(id, pair.M[a][l]);
          else
            it->second += pair.M[a][l];
        }
      }
    }
    D[r] = D_r;
    sort_row(row);
    for (const auto& [i_m, value] : row) {
      M_columns.push_back(surface.nodes[i_m]);
      M_position.push_back(i_m);
      M_values.push_back(value);
    }
    M_offsets[r + 1] = M_columns.size();
  }
}

void MortarCoupling::Impl::evaluate_derivatives() {
  ContactMortarOptions o;
  o.scheme = options.integration;
  o.collocation_points = options.collocation_points;
  o.search_factor = options.search_factor;
  o.derivatives = true;
  const ContactMortar mortar = evaluate_contact_mortar(surface, x, o);
  pairs = mortar.pairs;

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
      M_position.push_back(int(i_m));
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
    double g = 0.0;
    for (int d = 0; d < dim; ++d) {
      g -= frame.n[d] * v[d];
      for (const auto& [dof, dn] : frame.dn[d]) g_grad.emplace_back(dof, -v[d] * dn);
    }
    gaps[r] = g;  // exactly 0 on a row without pairs (D = 0, no M entries)
    compress_gradient(g_grad);
    for (const auto& [dof, dv] : g_grad) dg.push_back({int(r), dof, dv});
  }
}

}  // namespace grout
