// The two evaluation paths of grout::MortarCoupling, both on Grout's own code:
//  - values only: the kernel launches of kernels/ (compute_nodal_normals, coarse_search,
//    mortar_integrate<Dim>; the pair kernels of bench_mortar), then one pass over the slave rows
//    that assembles D and M (CRS) and evaluates g̃_j = −n_j·(D_jj x¹_j − Σ_l M_jl x²_l) from the
//    assembled row, as the driver does (nonlinear/mechanics_problem.cpp) — instead of
//    accumulate_weighted_gaps, which would stream the pair results a second time; with
//    standard multipliers the same launch for full pair matrices (mortar_integrate_matrices),
//    and D as CRS too;
//  - with derivatives: evaluate_contact_mortar (assembly/contact_mortar), the driver's own
//    contact evaluation (Sacado forward AD through the same pair kernels), and the chain rule
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

bool MortarCoupling::Impl::evaluate_values() {
  const std::string what = "grout::MortarCoupling::update: ";
  MortarOptions kernel_options;
  kernel_options.scheme = options.integration;
  kernel_options.n_collocation = dim == 2 ? options.collocation_points
                                          : options.collocation_points * options.collocation_points;
  if (compute_nodal_normals(normal_faces, coords, nodal_normals) != MortarStatus::ok) return false;
  if (coarse_search(workspace, slave_faces, master_faces, coords, options.search_factor,
                    candidates) != MortarStatus::ok)
    throw MortarCouplingError(what + "the coarse search failed");
  // Pairs that fail (a far candidate whose projection does not converge) contribute zeros, as
  // in the driver; only inconsistent sizes are an error.
  const auto check = [&](MortarStatus status) {
    if (status == MortarStatus::capacity_exceeded)
      throw MortarCouplingError(what + "internal error: pair results too short");
  };
  const Kokkos::DefaultExecutionSpace space;
  if (options.multipliers == MultiplierBasis::dual) {
    if (results.extent(0) < std::size_t(candidates.n_pairs))
      results = Kokkos::View<MortarPairResult<double>*>(
          Kokkos::view_alloc("grout::MortarCoupling::pairs", Kokkos::WithoutInitializing),
          std::size_t(candidates.n_pairs));
    check(dim == 2
              ? mortar_integrate_2d(slave_faces, master_faces, coords, nodal_normals,
                                    candidates.offsets, candidates.masters, kernel_options, results)
              : mortar_integrate_3d(slave_faces, master_faces, coords, nodal_normals,
                                    candidates.offsets, candidates.masters, kernel_options,
                                    results));
    read_back(results);
    return true;
  }
  if (matrices.extent(0) < std::size_t(candidates.n_pairs))
    matrices = Kokkos::View<MortarPairMatrices<double>*>(
        Kokkos::view_alloc("grout::MortarCoupling::pair_matrices", Kokkos::WithoutInitializing),
        std::size_t(candidates.n_pairs));
  const MultiplierBasis basis = options.multipliers;
  check(dim == 2 ? mortar_integrate_matrices<2>(space, slave_faces, master_faces, coords,
                                                nodal_normals, candidates.offsets,
                                                candidates.masters, basis, kernel_options, matrices)
                 : mortar_integrate_matrices<3>(
                       space, slave_faces, master_faces, coords, nodal_normals, candidates.offsets,
                       candidates.masters, basis, kernel_options, matrices));
  read_back(matrices);
  return true;
}

namespace {

/// A row's entries being merged: (position in surface.nodes, value), n used; the storage only
/// grows (no allocation once it has reached the widest row).
struct RowEntries {
  std::vector<std::pair<int, double>>& storage;
  std::size_t n = 0;
  /// Adds value at `position` (a new entry if its slot is −1).
  void add(int* slot, int position, double value) {
    int& s = slot[position];
    if (s >= 0) {
      storage[std::size_t(s)].second += value;
      return;
    }
    if (n == storage.size()) storage.resize(2 * n + 16);
    s = int(n);
    storage[n++] = {position, value};
  }
  /// Insertion sort by position (a row has a handful of distinct nodes); clears the slots.
  void sort(int* slot) {
    for (std::size_t e = 0; e < n; ++e) {
      slot[storage[e].first] = -1;
      const auto entry = storage[e];
      std::size_t k = e;
      for (; k > 0 && storage[k - 1].first > entry.first; --k) storage[k] = storage[k - 1];
      storage[k] = entry;
    }
  }
  const std::pair<int, double>* begin() const { return storage.data(); }
  const std::pair<int, double>* end() const { return storage.data() + n; }
};

}  // namespace

template <class Results>
void MortarCoupling::Impl::read_back(const Results& pair_results) {
  // D and M per slave row: the pairs of the row's own faces (row_faces), faces in order; each
  // row's nodes found through `slot` (their position in surface.nodes, which is in id order),
  // so a row costs its pair contributions plus a sort of its few distinct columns.
  using Pair = typename Results::value_type;
  constexpr bool full_D = std::is_same<Pair, MortarPairMatrices<double>>::value;
  const std::size_t n_rows = slave.n_nodes;
  D.resize(n_rows);
  gaps.resize(n_rows);
  normals.resize(n_rows * dim);
  M_offsets.resize(n_rows + 1);
  M_offsets[0] = 0;
  M_columns.clear();
  M_values.clear();
  D_crs_ready = full_D;
  if (full_D) {
    D_offsets.resize(n_rows + 1);
    D_offsets[0] = 0;
    D_columns.clear();
    D_values.clear();
  }
  // Raw views of what the loop reads (the members would be reloaded after every store).
  const int* const offsets = candidates.offsets.data();
  const int* const masters = candidates.masters.data();
  const Pair* const pair_data = pair_results.data();
  const std::pair<int, int>* const faces_of_row = row_faces.data();
  const int* const row_offsets = row_face_offsets.data();
  const auto master_table = master_faces;
  const auto slave_table = normal_faces;
  int* const slots = slot.data();
  int n_pairs = 0;  // counted at each face's first node (every own face node is a slave row)
  for (std::size_t r = 0; r < n_rows; ++r) {
    const int i = slave_row_position[r];
    double D_r = 0.0;
    RowEntries row_M{row_entries}, row_D{row_D_entries};
    for (int k = row_offsets[r]; k < row_offsets[r + 1]; ++k) {
      const auto [f, a] = faces_of_row[k];
      for (int p = offsets[f]; p < offsets[f + 1]; ++p) {
        const Pair& pair = pair_data[p];
        if (!(pair.overlap > 0.0)) continue;
        n_pairs += a == 0;
        if constexpr (full_D) {
          for (int b = 0; b < pair.n_slave; ++b) row_D.add(slots, slave_table(f, b), pair.D[a][b]);
        } else {
          D_r += pair.D[a];
        }
        const int m = masters[p];
        for (int l = 0; l < pair.n_master; ++l) row_M.add(slots, master_table(m, l), pair.M[a][l]);
      }
    }
    D[r] = D_r;  // standard: unused (D() throws)
    // v = Σ_k D_jk x¹_k − Σ_l M_jl x²_l (dual: D_jj x¹_j), g̃_j = −n_j · v.
    double v[3] = {0.0, 0.0, 0.0};
    if (full_D) {
      row_D.sort(slots);
      for (const auto& [position, value] : row_D) {
        D_columns.push_back(surface.nodes[position]);
        D_values.push_back(value);
        for (int d = 0; d < dim; ++d) v[d] += value * coords(position, d);
      }
      D_offsets[r + 1] = D_columns.size();
    } else if (i >= 0) {
      for (int d = 0; d < dim; ++d) v[d] = D_r * coords(i, d);
    }
    row_M.sort(slots);
    for (const auto& [position, value] : row_M) {
      M_columns.push_back(surface.nodes[position]);
      M_values.push_back(value);
      for (int d = 0; d < dim; ++d) v[d] -= value * coords(position, d);
    }
    M_offsets[r + 1] = M_columns.size();
    double g = 0.0;
    for (int d = 0; d < dim; ++d) {
      const double n = i >= 0 ? nodal_normals(i, d) : 0.0;
      normals[r * dim + d] = n;
      g -= n * v[d];
    }
    gaps[r] = g;
  }
  pairs = n_pairs;
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
  o.scheme = options.integration;
  o.collocation_points = options.collocation_points;
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
