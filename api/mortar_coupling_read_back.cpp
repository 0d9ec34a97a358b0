// grout::MortarCoupling's read-back on the values path: D, M (CRS, ascending master ids), the
// weighted gaps g̃_j = −n_j·(D_jj x¹_j − Σ_l M_jl x²_l) and the normals per slave row, from the
// packed pair records of the integration launch (PackPair, mortar_coupling_impl.hpp).
//  - merge (read_back_merge): per slave row, the pairs of its own faces merged through a slot
//    array and an insertion sort of the row's few columns; it also records the pattern: the
//    candidate lists, which pairs overlap, and for each pair entry its index in D/M.
//  - scatter (read_back_scatter): while the candidates and the set of overlapping pairs are
//    those of the recorded pattern (a host whose surfaces move little between two updates, and
//    every repeated update), the values are added into the kept pattern face by face, with no
//    merge, sort or column write. Each entry receives the same terms in the same order (faces,
//    then pairs, ascending) as in the merge, so both give the same numbers.

#include <algorithm>

#include "mortar_coupling_impl.hpp"

namespace grout {

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
  /// Insertion sort by position (a row has a handful of distinct nodes).
  void sort() {
    for (std::size_t e = 1; e < n; ++e) {
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

template <bool FullD, int NS, int NM>
void MortarCoupling::Impl::read_back_merge() {
  // D and M per slave row: the pairs of the row's own faces (row_faces), faces in order; each
  // row's nodes found through `slot` (their position in surface.nodes, which is in id order),
  // so a row costs its pair contributions plus a sort of its few distinct columns.
  using Pack = PackPair<FullD, NS, NM>;
  const std::size_t n_rows = slave.n_nodes, n_candidates = std::size_t(candidates.n_pairs);
  D.resize(n_rows);
  gaps.resize(n_rows);
  normals.resize(n_rows * dim);
  M_offsets.resize(n_rows + 1);
  M_offsets[0] = 0;
  M_columns.clear();
  M_values.clear();
  M_position.clear();
  D_crs_ready = FullD;
  if (FullD) {
    D_offsets.resize(n_rows + 1);
    D_offsets[0] = 0;
    D_columns.clear();
    D_values.clear();
    D_position.clear();
    D_dest.assign(n_candidates * NS * NS, -1);
  }
  M_dest.assign(n_candidates * NS * NM, -1);
  pattern_overlap.assign(n_candidates, 0);
  // Raw views of what the loop reads (the members would be reloaded after every store).
  const int* const offsets = candidates.offsets.data();
  const int* const masters = candidates.masters.data();
  const double* const records = pair_values.data();
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
        const double* const pair = records + std::size_t(p) * Pack::stride;
        if (!(pair[0] > 0.0)) continue;
        n_pairs += a == 0;
        if constexpr (FullD) {
          for (int b = 0; b < NS && slave_table(f, b) >= 0; ++b)
            row_D.add(slots, slave_table(f, b), pair[Pack::D + a * NS + b]);
        } else {
          D_r += pair[Pack::D + a];
        }
        const double* const M_a = pair + Pack::M + a * NM;
        const int m = masters[p];
        for (int l = 0; l < NM && master_table(m, l) >= 0; ++l)
          row_M.add(slots, master_table(m, l), M_a[l]);
      }
    }
    D[r] = D_r;  // standard: unused (D() throws)
    // v = Σ_k D_jk x¹_k − Σ_l M_jl x²_l (dual: D_jj x¹_j), g̃_j = −n_j · v. The slots now hold
    // each column's CRS index (for the pattern); slave and master nodes are distinct.
    double v[3] = {0.0, 0.0, 0.0};
    if (FullD) {
      row_D.sort();
      for (const auto& [position, value] : row_D) {
        slots[position] = int(D_columns.size());
        D_columns.push_back(surface.nodes[position]);
        D_values.push_back(value);
        D_position.push_back(position);
        for (int d = 0; d < dim; ++d) v[d] += value * coords(position, d);
      }
      D_offsets[r + 1] = D_columns.size();
    } else if (i >= 0) {
      for (int d = 0; d < dim; ++d) v[d] = D_r * coords(i, d);
    }
    row_M.sort();
    for (const auto& [position, value] : row_M) {
      slots[position] = int(M_columns.size());
      M_columns.push_back(surface.nodes[position]);
      M_values.push_back(value);
      M_position.push_back(position);
      for (int d = 0; d < dim; ++d) v[d] -= value * coords(position, d);
    }
    M_offsets[r + 1] = M_columns.size();
    store_row_gap(r, i, v);
    // The pattern: where each of the row's pair entries goes.
    for (int k = row_offsets[r]; k < row_offsets[r + 1]; ++k) {
      const auto [f, a] = faces_of_row[k];
      for (int p = offsets[f]; p < offsets[f + 1]; ++p) {
        if (!(records[std::size_t(p) * Pack::stride] > 0.0)) continue;
        pattern_overlap[p] = 1;
        if constexpr (FullD)
          for (int b = 0; b < NS && slave_table(f, b) >= 0; ++b)
            D_dest[(std::size_t(p) * NS + a) * NS + b] = slots[slave_table(f, b)];
        const int m = masters[p];
        for (int l = 0; l < NM && master_table(m, l) >= 0; ++l)
          M_dest[(std::size_t(p) * NS + a) * NM + l] = slots[master_table(m, l)];
      }
    }
    for (const auto& entry : row_D) slots[entry.first] = -1;
    for (const auto& entry : row_M) slots[entry.first] = -1;
  }
  pairs = n_pairs;
  pattern_offsets.assign(offsets, offsets + n_own_slave_faces + 1);
  pattern_masters.assign(masters, masters + n_candidates);
  pattern_valid = true;
}

template <bool FullD, int NS, int NM>
bool MortarCoupling::Impl::read_back_scatter() {
  using Pack = PackPair<FullD, NS, NM>;
  const std::size_t n_faces = n_own_slave_faces, n_candidates = std::size_t(candidates.n_pairs);
  const int* const offsets = candidates.offsets.data();
  const int* const masters = candidates.masters.data();
  if (!pattern_valid || pattern_masters.size() != n_candidates ||
      pattern_offsets.size() != n_faces + 1 ||
      !std::equal(pattern_offsets.begin(), pattern_offsets.end(), offsets) ||
      !std::equal(pattern_masters.begin(), pattern_masters.end(), masters))
    return false;
  // Values into the pattern, face by face: entry += the pair's terms (no_overlap pairs have
  // none); a pair that overlaps now and did not then, or the reverse, ends the scatter.
  std::fill(M_values.begin(), M_values.end(), 0.0);
  if (FullD)
    std::fill(D_values.begin(), D_values.end(), 0.0);
  else
    std::fill(D.begin(), D.end(), 0.0);
  const double* const records = pair_values.data();
  const int* const face_rows = own_face_rows.data();
  const char* const overlaps = pattern_overlap.data();
  const int* const M_to = M_dest.data();
  const int* const D_to = D_dest.data();
  double* const M_v = M_values.data();
  double* const D_v = FullD ? D_values.data() : D.data();
  int n_pairs = 0;
  for (std::size_t f = 0; f < n_faces; ++f)
    for (int p = offsets[f]; p < offsets[f + 1]; ++p) {
      const double* const pair = records + std::size_t(p) * Pack::stride;
      const bool overlap = pair[0] > 0.0;
      if (overlap != bool(overlaps[p])) return false;
      if (!overlap) continue;
      ++n_pairs;
      for (int a = 0; a < NS; ++a) {
        if constexpr (FullD) {
          for (int b = 0; b < NS; ++b) {
            const int k = D_to[(std::size_t(p) * NS + a) * NS + b];
            if (k >= 0) D_v[k] += pair[Pack::D + a * NS + b];
          }
        } else {
          const int row = face_rows[f * NS + a];
          if (row >= 0) D_v[row] += pair[Pack::D + a];
        }
        for (int l = 0; l < NM; ++l) {
          const int k = M_to[(std::size_t(p) * NS + a) * NM + l];
          if (k >= 0) M_v[k] += pair[Pack::M + a * NM + l];
        }
      }
    }
  // Gaps and normals per row, from the assembled rows (as read_back_merge).
  for (std::size_t r = 0; r < slave.n_nodes; ++r) {
    const int i = slave_row_position[r];
    double v[3] = {0.0, 0.0, 0.0};
    if (FullD) {
      for (std::size_t k = D_offsets[r]; k < D_offsets[r + 1]; ++k)
        for (int d = 0; d < dim; ++d) v[d] += D_values[k] * coords(D_position[k], d);
    } else if (i >= 0) {
      for (int d = 0; d < dim; ++d) v[d] = D[r] * coords(i, d);
    }
    for (std::size_t k = M_offsets[r]; k < M_offsets[r + 1]; ++k)
      for (int d = 0; d < dim; ++d) v[d] -= M_values[k] * coords(M_position[k], d);
    store_row_gap(r, i, v);
  }
  pairs = n_pairs;
  D_crs_ready = FullD;
  return true;
}

void MortarCoupling::Impl::read_back() {
  const bool full_D = options.multipliers != MultiplierBasis::dual;
  const auto run = [&](auto merge, auto scatter) {
    if (!(this->*scatter)()) (this->*merge)();
  };
  if (dim == 2) {
    if (full_D)
      run(&Impl::read_back_merge<true, 2, 2>, &Impl::read_back_scatter<true, 2, 2>);
    else
      run(&Impl::read_back_merge<false, 2, 2>, &Impl::read_back_scatter<false, 2, 2>);
  } else {
    if (full_D)
      run(&Impl::read_back_merge<true, 4, 4>, &Impl::read_back_scatter<true, 4, 4>);
    else
      run(&Impl::read_back_merge<false, 4, 4>, &Impl::read_back_scatter<false, 4, 4>);
  }
}

}  // namespace grout
