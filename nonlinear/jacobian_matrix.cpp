#include "nonlinear/jacobian_matrix.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

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

  // The terms of each local row (a counting sort by row), each row's in key order.
  std::vector<LO> term_row(terms.size());
  std::vector<std::size_t> term_start(std::size_t(n_rows) + 1, 0);
  for (std::size_t t = 0; t < terms.size(); ++t) {
    term_row[t] = map->getLocalElement(terms[t].row);
    if (term_row[t] == invalid) throw std::logic_error("jacobian_matrix: a term of another rank");
    ++term_start[std::size_t(term_row[t]) + 1];
  }
  std::partial_sum(term_start.begin(), term_start.end(), term_start.begin());
  std::vector<std::size_t> term_order(terms.size());
  {
    std::vector<std::size_t> next(term_start.begin(), term_start.end() - 1);
    for (std::size_t t = 0; t < terms.size(); ++t) term_order[next[term_row[t]]++] = t;
  }
  for (LO i = 0; i < n_rows; ++i)
    std::sort(term_order.begin() + std::ptrdiff_t(term_start[i]),
              term_order.begin() + std::ptrdiff_t(term_start[i + 1]),
              [&](std::size_t a, std::size_t b) { return terms[a].key < terms[b].key; });

  // Column map: K_solid's columns in its order (its local indices carry over), then the other
  // columns of the terms and of the multiplier diagonals, ascending (on one rank the column
  // map is then the row map, as Tpetra's own fillComplete would make it).
  std::vector<GO> columns(K_cols.getNodeNumElements());
  for (std::size_t j = 0; j < columns.size(); ++j) columns[j] = K_cols.getGlobalElement(LO(j));
  std::vector<GO> extra;
  for (const JacobianTerm& t : terms)
    if (K_cols.getLocalElement(t.col) == invalid) extra.push_back(t.col);
  for (LO i = n_u; i < n_rows; ++i) extra.push_back(map->getGlobalElement(i));
  std::sort(extra.begin(), extra.end());
  extra.erase(std::unique(extra.begin(), extra.end()), extra.end());
  std::unordered_map<GO, LO> extra_index;
  for (GO g : extra) {
    extra_index.emplace(g, LO(columns.size()));
    columns.push_back(g);
  }
  const auto local_column = [&](GO g) {
    const LO j = K_cols.getLocalElement(g);
    return j != invalid ? j : extra_index.at(g);
  };

  // Rows: K_solid's entries, then the terms in key order, then the multiplier diagonal; equal
  // columns summed in that order; columns ascending within a row.
  struct Item {
    LO col;
    int seq;
    double value;
  };
  std::vector<std::size_t> row_ptr(std::size_t(n_rows) + 1, 0);
  std::vector<LO> col_ind;
  std::vector<double> vals;
  col_ind.reserve(K.values.extent(0) + terms.size() + std::size_t(n_rows - n_u));
  vals.reserve(col_ind.capacity());
  std::vector<Item> items;
  for (LO i = 0; i < n_rows; ++i) {
    const std::size_t t0 = term_start[i], t1 = term_start[i + 1];
    const bool has_solid = i < n_u;
    if (has_solid && K_rows.getGlobalElement(i) != map->getGlobalElement(i))
      throw std::logic_error("jacobian_matrix: J's rows must start with K_solid's, in order");
    if (has_solid && t0 == t1) {  // K_solid's row as it is (sorted, merged)
      for (auto p = K.graph.row_map(i); p < K.graph.row_map(i + 1); ++p) {
        col_ind.push_back(K.graph.entries(p));
        vals.push_back(K.values(p));
      }
      row_ptr[i + 1] = col_ind.size();
      continue;
    }
    items.clear();
    if (has_solid)
      for (auto p = K.graph.row_map(i); p < K.graph.row_map(i + 1); ++p)
        items.push_back({K.graph.entries(p), 0, K.values(p)});
    for (std::size_t k = t0; k < t1; ++k) {
      const JacobianTerm& t = terms[term_order[k]];
      items.push_back({local_column(t.col), int(1 + k - t0), t.value});
    }
    if (!has_solid)
      items.push_back({extra_index.at(map->getGlobalElement(i)), int(1 + t1 - t0), 0.0});
    std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) {
      return a.col < b.col || (a.col == b.col && a.seq < b.seq);
    });
    for (std::size_t k = 0; k < items.size(); ++k) {
      if (k > 0 && items[k].col == items[k - 1].col) {
        vals.back() += items[k].value;
        continue;
      }
      col_ind.push_back(items[k].col);
      vals.push_back(items[k].value);
    }
    row_ptr[i + 1] = col_ind.size();
  }

  using RowPtr = Matrix::local_graph_device_type::row_map_type::non_const_type;
  using ColInd = Matrix::local_graph_device_type::entries_type::non_const_type;
  using Values = Matrix::local_matrix_device_type::values_type;
  RowPtr ptr(Kokkos::view_alloc("grout::jacobian_row_ptr", Kokkos::WithoutInitializing),
             row_ptr.size());
  ColInd ind(Kokkos::view_alloc("grout::jacobian_columns", Kokkos::WithoutInitializing),
             col_ind.size());
  Values val(Kokkos::view_alloc("grout::jacobian_values", Kokkos::WithoutInitializing),
             vals.size());
  std::copy(row_ptr.begin(), row_ptr.end(), ptr.data());
  std::copy(col_ind.begin(), col_ind.end(), ind.data());
  std::copy(vals.begin(), vals.end(), val.data());
  const Teuchos::RCP<const Map> column_map =
      Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(), columns.data(),
                           columns.size(), map->getIndexBase(), map->getComm()));
  auto J = Teuchos::rcp(new Matrix(map, column_map, ptr, ind, val));
  J->expertStaticFillComplete(map, map);
  return J;
}

}  // namespace grout
