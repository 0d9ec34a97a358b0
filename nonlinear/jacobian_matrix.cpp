#include "nonlinear/jacobian_matrix.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "nonlinear/local_csr_matrix.hpp"

namespace grout {

Teuchos::RCP<Matrix> jacobian_matrix(const Matrix& K_solid, const Teuchos::RCP<const Map>& map,
                                     const std::vector<JacobianTerm>& terms) {
  const LO invalid = Teuchos::OrdinalTraits<LO>::invalid();
  const LO n_rows = LO(map->getNodeNumElements());
  const LO n_u = LO(K_solid.getNodeNumRows());
  const auto& K_rows = *K_solid.getRowMap();
  const auto& K_cols = *K_solid.getColMap();
  const auto K = K_solid.getLocalMatrixHost();
  if (n_u > n_rows) throw std::logic_error("jacobian_matrix: K_solid has more rows than J");

  // Each term's local row and K_solid column, looked up once (consecutive terms mostly share
  // their row and often their column: the master rows collect ~4 terms per entry, 0.5–0.7 M
  // terms per Newton iteration on the 3D Hertz spheres at 11 k nodes, and a look-up in a
  // non-contiguous map is a hash probe).
  std::vector<LO> term_row(terms.size()), term_col(terms.size());
  std::vector<GO> extra;  // columns outside K_solid's: the terms', then the multiplier diagonals
  {
    GO last_row = 0, last_col = 0;
    LO row = invalid, col = invalid;
    for (std::size_t t = 0; t < terms.size(); ++t) {
      if (t == 0 || terms[t].row != last_row)
        last_row = terms[t].row, row = map->getLocalElement(last_row);
      if (t == 0 || terms[t].col != last_col) {
        last_col = terms[t].col, col = K_cols.getLocalElement(last_col);
        if (col == invalid) extra.push_back(last_col);
      }
      if (row == invalid) throw std::logic_error("jacobian_matrix: a term of another rank");
      term_row[t] = row;
      term_col[t] = col;
    }
  }
  for (LO i = n_u; i < n_rows; ++i) extra.push_back(map->getGlobalElement(i));
  std::sort(extra.begin(), extra.end());
  extra.erase(std::unique(extra.begin(), extra.end()), extra.end());

  // Column map: K_solid's columns in its order (its local indices carry over), then the other
  // columns of the terms and of the multiplier diagonals, ascending (on one rank the column
  // map is then the row map, as Tpetra's own fillComplete would make it).
  const LO n_k_cols = LO(K_cols.getNodeNumElements());
  std::vector<GO> columns(std::size_t(n_k_cols) + extra.size());
  for (LO j = 0; j < n_k_cols; ++j) columns[std::size_t(j)] = K_cols.getGlobalElement(j);
  std::copy(extra.begin(), extra.end(), columns.begin() + n_k_cols);
  const auto extra_column = [&](GO g) {
    return n_k_cols + LO(std::lower_bound(extra.begin(), extra.end(), g) - extra.begin());
  };
  for (std::size_t t = 0, last = 0; t < terms.size(); ++t) {
    if (term_col[t] != invalid) continue;
    const bool same = last > 0 && terms[last - 1].col == terms[t].col;
    term_col[t] = same ? term_col[last - 1] : extra_column(terms[t].col);
    last = t + 1;
  }

  // The terms of each local row (a counting sort by row), each row's by column and, within a
  // column, in key order (keys are unique within a row).
  std::vector<std::size_t> term_start(std::size_t(n_rows) + 1, 0);
  for (std::size_t t = 0; t < terms.size(); ++t) ++term_start[std::size_t(term_row[t]) + 1];
  std::partial_sum(term_start.begin(), term_start.end(), term_start.begin());
  std::vector<std::size_t> term_order(terms.size());
  {
    std::vector<std::size_t> next(term_start.begin(), term_start.end() - 1);
    for (std::size_t t = 0; t < terms.size(); ++t) term_order[next[term_row[t]]++] = t;
  }
  const auto by_column_then_key = [&](std::size_t a, std::size_t b) {
    return term_col[a] < term_col[b] || (term_col[a] == term_col[b] && terms[a].key < terms[b].key);
  };
  for (LO i = 0; i < n_rows; ++i)
    std::sort(term_order.begin() + std::ptrdiff_t(term_start[i]),
              term_order.begin() + std::ptrdiff_t(term_start[i + 1]), by_column_then_key);

  // Rows: per column ascending, K_solid's entry, then the terms in key order, then the
  // multiplier diagonal's stored zero, summed in that order (a merge of K_solid's sorted row
  // with the sorted terms), written into the views J keeps (local_csr_matrix.hpp), with room
  // for the most the rows can hold: K_solid's entries, the terms and the multiplier diagonals.
  const bool k_sorted = K_solid.getCrsGraph()->isSorted();
  CsrBuilder rows(n_rows, K.values.extent(0) + terms.size() + std::size_t(n_rows - n_u));
  // K_solid's row; sorted first if its graph is not (Tpetra's fill-complete rows are)
  std::vector<std::pair<LO, double>> k_row;
  for (LO i = 0; i < n_rows; ++i) {
    const std::size_t t0 = term_start[i], t1 = term_start[i + 1];
    const bool has_solid = i < n_u;
    if (has_solid && K_rows.getGlobalElement(i) != map->getGlobalElement(i))
      throw std::logic_error("jacobian_matrix: J's rows must start with K_solid's, in order");
    if (has_solid && t0 == t1 && k_sorted) {  // K_solid's row as it is (sorted, merged)
      for (auto p = K.graph.row_map(i); p < K.graph.row_map(i + 1); ++p)
        rows.append(K.graph.entries(p), K.values(p));
      rows.end_row();
      continue;
    }
    k_row.clear();
    if (has_solid)
      for (auto p = K.graph.row_map(i); p < K.graph.row_map(i + 1); ++p)
        k_row.emplace_back(K.graph.entries(p), K.values(p));
    if (!k_sorted)
      std::stable_sort(k_row.begin(), k_row.end(),
                       [](const auto& a, const auto& b) { return a.first < b.first; });
    const LO diagonal = has_solid ? invalid : extra_column(map->getGlobalElement(i));
    bool diagonal_pending = !has_solid;
    std::size_t p = 0, q = t0;
    while (p < k_row.size() || q < t1 || diagonal_pending) {
      LO c = diagonal_pending ? diagonal : std::numeric_limits<LO>::max();
      if (p < k_row.size()) c = std::min(c, k_row[p].first);
      if (q < t1) c = std::min(c, term_col[term_order[q]]);
      double v = 0.0;
      bool have = false;
      for (; p < k_row.size() && k_row[p].first == c; ++p)  // one, or K's repeats in order
        v = have ? v + k_row[p].second : k_row[p].second, have = true;
      for (; q < t1 && term_col[term_order[q]] == c; ++q)
        v = have ? v + terms[term_order[q]].value : terms[term_order[q]].value, have = true;
      if (diagonal_pending && c == diagonal) v = have ? v + 0.0 : 0.0, diagonal_pending = false;
      rows.append(c, v);
    }
    rows.end_row();
  }

  const Teuchos::RCP<const Map> column_map =
      Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(), columns.data(),
                           columns.size(), map->getIndexBase(), map->getComm()));
  return rows.matrix(map, column_map, map, map);
}

}  // namespace grout
