#include "nonlinear/condensed_solve.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>

#include "kernels/small_dense_lu.hpp"
#include "nonlinear/row_table.hpp"

namespace grout {

namespace {

enum Kind : int { kIdentity = 0, kEliminated = 1, kSwapped = 2, kMasterPivot = 3, kRedundant = 4 };

// A multiplier-column entry |J[r, t]| at most this times the largest one of the whole system
// is round-off, never a pivot (kind R in the header).
constexpr double relative_pivot_tolerance = 1e-12;

}  // namespace

struct MultiplierCondensation::Impl {
  int dofs_per_node = 1;
  std::vector<GO> lambda, slave;
  std::unordered_map<GO, int> by_lambda, by_slave;

  // Of the last condense(), replicated per pair.
  std::vector<int> kind;
  std::vector<double> lambda_known, slave_known, pivot;
  std::vector<GO> pivot_row;            ///< row that eliminates λ_t (B: slave, D: master)
  std::unordered_map<GO, int> by_slot;  ///< reduced slot taken by a λ-row -> pair
  // Kind D multipliers are eliminated together: P[k][j] = J[r_k, t_j] over their pivot rows
  // r_k, λ_D = P⁻¹ (b_r − Σ_{c ∉ D} J[r, c] x_c). P is block diagonal over the groups of
  // multipliers sharing pivot rows; inverse_rows[j] = the nonzeros (k, P⁻¹[j][k]).
  std::vector<int> d_pairs;              ///< kind D pairs, in order
  std::unordered_map<int, int> d_index;  ///< pair -> index in d_pairs
  std::vector<std::vector<std::pair<int, double>>> inverse_rows;
  Teuchos::RCP<const Map> full_map, reduced_map;
  Teuchos::RCP<Matrix> A;
  Teuchos::RCP<Vector> rhs;
  RowTable rows;  // owned rows of J plus the imported ones
  Statistics stats;

  int pair_of_lambda(GO g) const {
    const auto it = by_lambda.find(g);
    return it == by_lambda.end() ? -1 : it->second;
  }
  int pair_of_slave(GO g) const {
    const auto it = by_slave.find(g);
    return it == by_slave.end() ? -1 : it->second;
  }
  GO group(int p) const { return slave[p] / dofs_per_node; }
  /// A slave displacement whose value is known (prescribed: kinds C, D and R).
  bool known_slave(int q) const {
    return q >= 0 && (kind[q] == kSwapped || kind[q] == kMasterPivot || kind[q] == kRedundant);
  }
  /// A multiplier whose value is known (kinds A and R).
  bool known_lambda(int p) const { return kind[p] == kIdentity || kind[p] == kRedundant; }
  int pair_of_slot(GO g) const {
    const auto it = by_slot.find(g);
    return it == by_slot.end() ? -1 : it->second;
  }

  // The largest |J[r, t]| over the displacement rows r and the paired multipliers t: the
  // scale of D and M (global; collective).
  double multiplier_column_scale(const Matrix& J) const {
    const auto& row_map = *J.getRowMap();
    const auto& col_map = *J.getColMap();
    const auto local = J.getLocalMatrixHost();
    GO first_lambda = std::numeric_limits<GO>::max();
    for (GO t : lambda) first_lambda = std::min(first_lambda, t);
    double scale = 0.0, scale_all = 0.0;
    for (LO i = 0; i < LO(row_map.getNodeNumElements()); ++i) {
      if (pair_of_lambda(row_map.getGlobalElement(i)) >= 0) continue;
      for (auto e = local.graph.row_map(i); e < local.graph.row_map(i + 1); ++e) {
        const GO c = col_map.getGlobalElement(local.graph.entries(e));
        if (c >= first_lambda && pair_of_lambda(c) >= 0)
          scale = std::max(scale, std::abs(local.values(e)));
      }
    }
    Teuchos::reduceAll(*J.getRowMap()->getComm(), Teuchos::REDUCE_MAX, scale,
                       Teuchos::outArg(scale_all));
    return scale_all;
  }

  // Kind D (see the header): the displacement row r that is no slave dof, not taken by
  // another pair, with the largest |J[r, t]| above round-off (relative_pivot_tolerance ×
  // multiplier_column_scale); a pair without one is kind R, λ_t = 0 (collective).
  void select_master_pivots(const Matrix& J, std::vector<int> open) {
    const auto comm = J.getRowMap()->getComm();
    const auto& row_map = *J.getRowMap();
    const auto& col_map = *J.getColMap();
    const auto local = J.getLocalMatrixHost();
    if (open.empty()) return;  // replicated: the same on every rank
    const double round_off = relative_pivot_tolerance * multiplier_column_scale(J);
    std::unordered_map<GO, int> column_to_open;
    std::vector<GO> taken;
    std::unordered_map<GO, int> candidate_columns;  // every kind D candidate's λ
    for (int p : open) candidate_columns[lambda[p]] = p;
    while (!open.empty()) {
      column_to_open.clear();
      for (std::size_t k = 0; k < open.size(); ++k) column_to_open[lambda[open[k]]] = int(k);
      const std::size_t n = open.size();
      std::vector<double> best(n, 0.0), best_all(n, 0.0), value(n, 0.0), value_all(n, 0.0);
      std::vector<long long> row(n, -1), row_all(n, -1);
      for (LO i = 0; i < LO(row_map.getNodeNumElements()); ++i) {
        const GO g = row_map.getGlobalElement(i);
        if (pair_of_lambda(g) >= 0 || pair_of_slave(g) >= 0) continue;
        if (std::find(taken.begin(), taken.end(), g) != taken.end()) continue;
        // A row that holds two candidates' λ only if no other row will do: its elimination
        // would refer to the other's pivot row.
        int held = 0;
        for (auto e = local.graph.row_map(i); e < local.graph.row_map(i + 1); ++e)
          held += candidate_columns.count(col_map.getGlobalElement(local.graph.entries(e)));
        const double penalty = held > 1 ? 1e-6 : 1.0;
        for (auto e = local.graph.row_map(i); e < local.graph.row_map(i + 1); ++e) {
          const auto it = column_to_open.find(col_map.getGlobalElement(local.graph.entries(e)));
          if (it == column_to_open.end()) continue;
          const int k = it->second;
          if (std::abs(local.values(e)) <= round_off) continue;  // no coupling: never a pivot
          const double a = penalty * std::abs(local.values(e));
          if (a > best[k] || (a == best[k] && a > 0.0 && g > row[k]))
            best[k] = a, row[k] = g, value[k] = local.values(e);
        }
      }
      Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, int(n), best.data(), best_all.data());
      for (std::size_t k = 0; k < n; ++k)
        if (best[k] != best_all[k] || best[k] == 0.0) row[k] = -1, value[k] = 0.0;
      Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, int(n), row.data(), row_all.data());
      for (std::size_t k = 0; k < n; ++k)
        if (row[k] != row_all[k]) value[k] = 0.0;
      Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, int(n), value.data(), value_all.data());
      std::vector<int> still_open;
      std::vector<GO> chosen;
      for (std::size_t k = 0; k < n; ++k) {
        const int p = open[k];
        if (row_all[k] < 0) {  // no row holds λ_t above round-off: λ_t = 0 (kind R)
          kind[p] = kRedundant, lambda_known[p] = 0.0;
          continue;
        }
        if (std::find(chosen.begin(), chosen.end(), GO(row_all[k])) != chosen.end()) {
          still_open.push_back(p);  // taken by an earlier pair this round: next round
          continue;
        }
        chosen.push_back(row_all[k]);
        kind[p] = kMasterPivot, pivot_row[p] = row_all[k], pivot[p] = value_all[k];
      }
      taken.insert(taken.end(), chosen.begin(), chosen.end());
      open.swap(still_open);
    }
  }

  // P and its inverse, block by block (replicated; collective).
  void invert_pivot_block(const Matrix& J) {
    d_pairs.clear(), d_index.clear(), inverse_rows.clear();
    for (int p = 0; p < int(kind.size()); ++p)
      if (kind[p] == kMasterPivot) d_index[p] = int(d_pairs.size()), d_pairs.push_back(p);
    const int n = int(d_pairs.size());
    if (n == 0) return;
    if (double(n) * n > 4e6)
      throw std::runtime_error(
          "condense_multipliers: too many multipliers of prescribed slave "
          "dofs on tied or sticking nodes (" +
          std::to_string(n) + ")");
    std::unordered_map<GO, int> row_to_k, column_to_j;
    for (int k = 0; k < n; ++k) row_to_k[pivot_row[d_pairs[k]]] = k;
    for (int j = 0; j < n; ++j) column_to_j[lambda[d_pairs[j]]] = j;
    const auto& row_map = *J.getRowMap();
    const auto& col_map = *J.getColMap();
    const auto local = J.getLocalMatrixHost();
    std::vector<double> P(std::size_t(n) * n, 0.0), P_all(P.size(), 0.0);
    for (LO i = 0; i < LO(row_map.getNodeNumElements()); ++i) {
      const auto rk = row_to_k.find(row_map.getGlobalElement(i));
      if (rk == row_to_k.end()) continue;
      for (auto e = local.graph.row_map(i); e < local.graph.row_map(i + 1); ++e) {
        const auto cj = column_to_j.find(col_map.getGlobalElement(local.graph.entries(e)));
        if (cj != column_to_j.end()) P[std::size_t(rk->second) * n + cj->second] += local.values(e);
      }
    }
    Teuchos::reduceAll(*J.getRowMap()->getComm(), Teuchos::REDUCE_SUM, int(P.size()), P.data(),
                       P_all.data());
    // Blocks: connected components of P's graph (union-find).
    std::vector<int> parent(n);
    for (int k = 0; k < n; ++k) parent[k] = k;
    const std::function<int(int)> root = [&](int k) {
      return parent[k] == k ? k : parent[k] = root(parent[k]);
    };
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        if (P_all[std::size_t(k) * n + j] != 0.0) parent[root(k)] = root(j);
    std::map<int, std::vector<int>> blocks;
    for (int k = 0; k < n; ++k) blocks[root(k)].push_back(k);
    inverse_rows.assign(n, {});
    for (const auto& [r, members] : blocks) {
      // P_b⁻¹ by the small dense LU with partial pivoting (kernels/small_dense_lu.hpp);
      // singular: an exactly zero pivot.
      const int m = int(members.size());
      std::vector<double> a(std::size_t(m) * m), inverse(std::size_t(m) * m);
      std::vector<int> pivot(static_cast<std::size_t>(m));
      for (int x = 0; x < m; ++x)
        for (int y = 0; y < m; ++y) a[x * m + y] = P_all[std::size_t(members[x]) * n + members[y]];
      if (!small_lu_invert(m, a.data(), m, pivot.data(), inverse.data(), m))
        throw std::runtime_error(
            "condense_multipliers: singular pivot block for the multipliers "
            "of prescribed slave dofs on tied or sticking nodes");
      // P λ = q: rows of P are pivot rows k, columns multipliers j, so λ_j = Σ_k P⁻¹[j][k] q_k.
      for (int x = 0; x < m; ++x)
        for (int y = 0; y < m; ++y)
          if (const double v = inverse[x * m + y]; v != 0.0)
            inverse_rows[members[x]].emplace_back(members[y], v);
    }
  }

  // Row `row` with every multiplier and every known displacement substituted: entries on
  // reduced unknowns (GIDs of the reduced map; a swapped slot s stands for λ_t(s)).
  void reduce(const Row& row, std::map<GO, double>& out, double& rhs_out) const {
    out.clear();
    rhs_out = 0.0;
    accumulate(row, -1, false, 1.0, out, rhs_out, 0);
  }
  /// factor × λ_D[j] in row form (as accumulate()): λ_D[j] = Σ_k P⁻¹[j][k] (b_r_k −
  /// Σ_{c ∉ D} J[r_k, c] x_c).
  void accumulate_d(int j, double factor, std::map<GO, double>& out, double& rhs_out,
                    int depth) const {
    for (const auto& [k, a] : inverse_rows[j])
      accumulate(rows.at(pivot_row[d_pairs[k]]), -1, true, factor * a, out, rhs_out, depth + 1);
  }
  // Adds factor × (row with its multipliers and known displacements substituted, column
  // `exclude` and, if skip_d, the kind D columns left out) to out / rhs_out. An eliminated
  // λ_t of kind B is (b_s − Σ_{c≠t} J[s,c] x_c) / J[s,t] of its slave row s; kind D see
  // accumulate_d().
  void accumulate(const Row& row, GO exclude, bool skip_d, double factor, std::map<GO, double>& out,
                  double& rhs_out, int depth) const {
    if (depth > 4) throw std::logic_error("condense_multipliers: substitution too deep");
    rhs_out += factor * row.rhs;
    for (std::size_t e = 0; e < row.cols.size(); ++e) {
      const GO c = row.cols[e];
      if (c == exclude) continue;
      const double v = factor * row.vals[e];
      const int p = pair_of_lambda(c);
      if (p < 0) {
        const int q = pair_of_slave(c);
        if (known_slave(q))
          rhs_out -= v * slave_known[q];
        else
          out[c] += v;
      } else if (known_lambda(p)) {
        rhs_out -= v * lambda_known[p];
      } else if (kind[p] == kSwapped) {
        out[slave[p]] += v;
      } else {
        if (kind[p] == kEliminated)
          accumulate(rows.at(pivot_row[p]), c, false, -v / pivot[p], out, rhs_out, depth + 1);
        else if (!skip_d)  // v λ_t = v P⁻¹ (b_r − ...): the row form gets −v P⁻¹ (...)
          accumulate_d(d_index.at(p), -v, out, rhs_out, depth);
      }
    }
  }
};

MultiplierCondensation::MultiplierCondensation(const MultiplierPairing& lambda_to_slave,
                                               int dofs_per_node)
    : impl_(std::make_unique<Impl>()) {
  if (dofs_per_node < 1) throw std::invalid_argument("MultiplierCondensation: dofs_per_node < 1");
  impl_->dofs_per_node = dofs_per_node;
  for (const auto& [t, s] : lambda_to_slave) {
    const int p = int(impl_->lambda.size());
    if (!impl_->by_lambda.emplace(t, p).second)
      throw std::invalid_argument("MultiplierCondensation: multiplier " + std::to_string(t) +
                                  " paired twice");
    if (!impl_->by_slave.emplace(s, p).second)
      throw std::invalid_argument("MultiplierCondensation: slave dof " + std::to_string(s) +
                                  " carries two multipliers (a slave node on two interfaces "
                                  "cannot be condensed)");
    impl_->lambda.push_back(t);
    impl_->slave.push_back(s);
  }
  for (GO t : impl_->lambda)
    if (impl_->by_slave.count(t))
      throw std::invalid_argument("MultiplierCondensation: multiplier " + std::to_string(t) +
                                  " is also a slave dof");
}

MultiplierCondensation::~MultiplierCondensation() = default;

Teuchos::RCP<const Matrix> MultiplierCondensation::matrix() const {
  return impl_->A;
}
const Vector& MultiplierCondensation::rhs() const {
  return *impl_->rhs;
}
const MultiplierCondensation::Statistics& MultiplierCondensation::statistics() const {
  return impl_->stats;
}

void MultiplierCondensation::condense(const Matrix& J, const Vector& b,
                                      const MultiplierRows* declared) {
  Impl& m = *impl_;
  const auto comm = J.getRowMap()->getComm();
  const auto& row_map = *J.getRowMap();
  const int n_pairs = int(m.lambda.size());
  m.full_map = J.getRowMap();
  m.rows.clear();
  add_rows(J, b, m.rows);

  // 1. Classify the pairs from their owners' rows; replicate.
  enum { kIsIdentity, kLambda, kDiagonalOnly, kSlaveValue, kPivot, kInNodeRows, kFields };
  std::vector<double> local(std::size_t(n_pairs) * kFields, 0.0), global(local.size(), 0.0);
  std::vector<std::pair<int, int>> slave_lambda_columns;  // (pair, other pair) in slave rows
  GO declared_mismatch = -1;  // a declared identity row of J with more than its diagonal
  for (LO i = 0; i < LO(row_map.getNodeNumElements()); ++i) {
    const GO g = row_map.getGlobalElement(i);
    const Row& row = m.rows.at(g);
    if (const int p = m.pair_of_lambda(g); p >= 0) {
      double diagonal = 0.0;
      bool only_diagonal = true;
      for (std::size_t e = 0; e < row.cols.size(); ++e)
        if (row.cols[e] == g)
          diagonal += row.vals[e];
        else
          only_diagonal = false;
      bool identity = only_diagonal && diagonal != 0.0;
      if (const LambdaRow* kind = declared ? declared->find(g) : nullptr) {
        if (*kind == LambdaRow::identity && !identity) declared_mismatch = g;
        identity = *kind == LambdaRow::identity || (*kind == LambdaRow::pure_lambda && identity);
      }
      if (identity) {
        local[p * kFields + kIsIdentity] = 1.0;
        local[p * kFields + kLambda] = row.rhs / diagonal;
      }
      for (GO c : row.cols)  // multipliers of the same node in this λ-row
        if (const int q = m.pair_of_lambda(c); q >= 0 && m.group(q) == m.group(p))
          local[q * kFields + kInNodeRows] = 1.0;
    }
    if (const int p = m.pair_of_slave(g); p >= 0) {
      double diagonal = 0.0, D = 0.0;
      bool only_diagonal = true;
      for (std::size_t e = 0; e < row.cols.size(); ++e) {
        const GO c = row.cols[e];
        if (c == g)
          diagonal += row.vals[e];
        else
          only_diagonal = false;
        if (c == m.lambda[p]) D += row.vals[e];
        if (const int q = m.pair_of_lambda(c); q >= 0 && q != p)
          slave_lambda_columns.emplace_back(p, q);
      }
      local[p * kFields + kPivot] = D;
      if (only_diagonal && diagonal != 0.0) {
        local[p * kFields + kDiagonalOnly] = 1.0;
        local[p * kFields + kSlaveValue] = row.rhs / diagonal;
      }
    }
  }
  if (n_pairs > 0)
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, int(local.size()), local.data(), global.data());
  {
    GO mismatch = -1;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, declared_mismatch, Teuchos::outArg(mismatch));
    if (mismatch >= 0)
      throw std::logic_error("MultiplierCondensation: multiplier row " + std::to_string(mismatch) +
                             " is declared an identity row but holds more than its diagonal");
  }
  m.kind.assign(n_pairs, kIdentity);
  m.lambda_known.assign(n_pairs, 0.0);
  m.slave_known.assign(n_pairs, 0.0);
  m.pivot.assign(n_pairs, 0.0);
  m.pivot_row.assign(n_pairs, -1);
  std::vector<int> master_pivots;  // kind C pairs whose node's λ-rows lack their multiplier
  std::string error;
  for (int p = 0; p < n_pairs; ++p) {
    const double* f = &global[std::size_t(p) * kFields];
    m.lambda_known[p] = f[kLambda];
    m.slave_known[p] = f[kSlaveValue];
    m.pivot[p] = f[kPivot];
    if (f[kIsIdentity] != 0.0)
      m.kind[p] = kIdentity;
    else if (f[kPivot] != 0.0)
      m.kind[p] = kEliminated, m.pivot_row[p] = m.slave[p];
    else if (f[kDiagonalOnly] != 0.0)
      m.kind[p] = kSwapped;
    else if (error.empty())
      error = "multiplier " + std::to_string(m.lambda[p]) + ": its slave row " +
              std::to_string(m.slave[p]) +
              " has no entry in its column and is not a prescribed (diagonal-only) row";
    if (m.kind[p] == kSwapped && f[kInNodeRows] == 0.0) master_pivots.push_back(p);
  }
  int bad_local = 0;
  for (const auto& [p, q] : slave_lambda_columns)
    if (m.kind[p] == kEliminated && m.kind[q] != kIdentity) bad_local = 1;
  int bad = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, bad_local, Teuchos::outArg(bad));
  if (bad && error.empty()) error = "a slave row couples to more than one unknown multiplier";
  if (!error.empty())
    throw std::runtime_error("condense_multipliers: cannot condense the multipliers: " + error);
  m.select_master_pivots(J, master_pivots);
  m.invert_pivot_block(J);
  m.by_slot.clear();
  for (int p = 0; p < n_pairs; ++p)
    if (!m.known_lambda(p)) m.by_slot[m.kind[p] == kMasterPivot ? m.pivot_row[p] : m.slave[p]] = p;
  {
    int counts[5] = {0, 0, 0, 0, 0};
    for (int p = 0; p < n_pairs; ++p) ++counts[m.kind[p]];
    m.stats = Statistics();
    m.stats.identity = counts[kIdentity];
    m.stats.eliminated = counts[kEliminated];
    m.stats.swapped = counts[kSwapped];
    m.stats.master_pivots = counts[kMasterPivot];
    m.stats.redundant = counts[kRedundant];
  }

  // 2. The reduced map: the displacement dofs of J's row map.
  std::vector<GO> reduced;
  for (LO i = 0; i < LO(row_map.getNodeNumElements()); ++i) {
    const GO g = row_map.getGlobalElement(i);
    if (m.pair_of_lambda(g) < 0) reduced.push_back(g);
  }
  m.reduced_map = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                       reduced.data(), reduced.size(), 0, comm));

  // 3. Rows needed here: the λ-rows of the nodes of owned B/C slots, then the slave rows of
  //    every eliminated multiplier in the rows to reduce and of the owned multipliers.
  std::map<GO, std::vector<int>> groups;  // node -> its B/C/D/R pairs, of owned B/C/D slots
  for (GO g : reduced)
    if (const int p = m.pair_of_slot(g); p >= 0) groups[m.group(p)];
  if (!groups.empty())
    for (int p = 0; p < n_pairs; ++p)
      if (m.kind[p] != kIdentity)
        if (auto it = groups.find(m.group(p)); it != groups.end()) it->second.push_back(p);
  {
    std::vector<GO> needed;
    for (const auto& [node, pairs] : groups)
      for (int p : pairs)
        if (!row_map.isNodeGlobalElement(m.lambda[p])) needed.push_back(m.lambda[p]);
    for (int p = 0; p < n_pairs; ++p)  // few rows: every rank holds them all
      if (m.kind[p] == kMasterPivot && !row_map.isNodeGlobalElement(m.pivot_row[p]))
        needed.push_back(m.pivot_row[p]);
    import_rows(J, b, needed, m.rows);
  }
  {
    std::vector<GO> needed;
    const auto need_slaves_of = [&](const Row& row) {
      for (GO c : row.cols)
        if (const int p = m.pair_of_lambda(c); p >= 0 && m.kind[p] == kEliminated)
          if (!row_map.isNodeGlobalElement(m.slave[p])) needed.push_back(m.slave[p]);
    };
    for (const auto& [g, row] : m.rows) need_slaves_of(row);
    for (LO i = 0; i < LO(row_map.getNodeNumElements()); ++i) {
      const int p = m.pair_of_lambda(row_map.getGlobalElement(i));
      if (p >= 0 && m.kind[p] == kEliminated && !row_map.isNodeGlobalElement(m.slave[p]))
        needed.push_back(m.slave[p]);
    }
    import_rows(J, b, needed, m.rows);
  }

  // 4. Reduced rows.
  const auto slot_of = [&](int p) {
    return m.kind[p] == kMasterPivot ? m.pivot_row[p] : m.slave[p];
  };
  std::map<GO, std::map<GO, double>> assigned;  // slot -> reduced row (scaled)
  std::map<GO, double> assigned_rhs;
  int zero_diagonals = 0;
  for (const auto& [node, pairs] : groups) {
    // The node's λ-rows (one per pair) fill the slots of its pairs of kinds B, C and D; a
    // kind R pair has none, so as many of its λ-rows are left out (header).
    std::vector<int> slots;
    for (int p : pairs)
      if (!m.known_lambda(p)) slots.push_back(p);
    const int n = int(pairs.size()), n_slots = int(slots.size());
    std::vector<std::map<GO, double>> R(n);
    std::vector<double> r(n), row_max(n, 0.0);
    for (int i = 0; i < n; ++i) {
      m.reduce(m.rows.at(m.lambda[pairs[i]]), R[i], r[i]);
      for (const auto& [c, v] : R[i]) row_max[i] = std::max(row_max[i], std::abs(v));
    }
    // w[i][k]: row i at slot k. A row that is round-off next to the node's other rows (a
    // tie whose dofs are all prescribed) fits no slot.
    const double group_max = *std::max_element(row_max.begin(), row_max.end());
    std::vector<std::vector<double>> w(n, std::vector<double>(n_slots, 0.0));
    for (int i = 0; i < n; ++i) {
      if (row_max[i] <= relative_pivot_tolerance * group_max) continue;
      for (int k = 0; k < n_slots; ++k) {
        const auto it = R[i].find(slot_of(slots[k]));
        if (it != R[i].end()) w[i][k] = std::abs(it->second) / row_max[i];
      }
    }
    // The rows perm[k] at slots k < n_slots maximising Π w; greedy beyond 6 rows.
    std::vector<int> perm(n), best(n);
    for (int i = 0; i < n; ++i) perm[i] = best[i] = i;
    const auto score = [&](const std::vector<int>& q) {
      double s = 0.0;
      for (int k = 0; k < n_slots; ++k) s += w[q[k]][k] > 0.0 ? std::log(w[q[k]][k]) : -1e300;
      return s;
    };
    if (n <= 6) {
      double best_score = score(perm);
      while (std::next_permutation(perm.begin(), perm.end()))
        if (const double s = score(perm); s > best_score) best_score = s, best = perm;
    } else {
      std::vector<char> used(n, 0);
      for (int k = 0; k < n_slots; ++k) {
        int choice = -1;
        for (int i = 0; i < n; ++i)
          if (!used[i] && (choice < 0 || w[i][k] > w[choice][k])) choice = i;
        used[choice] = 1, best[k] = choice;
      }
    }
    for (int k = 0; k < n_slots; ++k) {
      const GO slot = slot_of(slots[k]);
      if (!m.reduced_map->isNodeGlobalElement(slot)) continue;
      const int i = best[k];
      double diagonal = 0.0;
      if (auto it = R[i].find(slot); it != R[i].end()) diagonal = it->second;
      double scale = 1.0;
      if (diagonal == 0.0) {
        ++zero_diagonals;
      } else {
        double reference = 0.0;  // |J[s, s]|: a stiffness-like diagonal
        const Row& s_row = m.rows.at(slot);
        for (std::size_t e = 0; e < s_row.cols.size(); ++e)
          if (s_row.cols[e] == slot) reference += s_row.vals[e];
        scale = reference != 0.0 ? std::abs(reference) / diagonal : (diagonal < 0 ? -1.0 : 1.0);
      }
      auto& out = assigned[slot];
      for (const auto& [c, v] : R[i]) out[c] = scale * v;
      assigned_rhs[slot] = scale * r[i];
    }
  }
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, zero_diagonals,
                     Teuchos::outArg(m.stats.zero_diagonals));

  m.rhs = Teuchos::rcp(new Vector(m.reduced_map));
  std::vector<std::vector<GO>> row_cols(reduced.size());
  std::vector<std::vector<double>> row_vals(reduced.size());
  std::vector<std::size_t> counts(reduced.size());
  {
    // Rows without a multiplier column or a known (prescribed slave) displacement column,
    // most of them, are copied as they are; reduce() gives the same row (one value per
    // column, the same right-hand side).
    GO first_lambda = std::numeric_limits<GO>::max();
    for (GO t : m.lambda) first_lambda = std::min(first_lambda, t);
    std::vector<GO> known;  // sorted GIDs of the known slave displacements
    for (int p = 0; p < n_pairs; ++p)
      if (m.known_slave(p)) known.push_back(m.slave[p]);
    std::sort(known.begin(), known.end());
    const auto plain = [&](const Row& row) {
      for (GO c : row.cols) {
        if (c >= first_lambda && m.pair_of_lambda(c) >= 0) return false;
        if (!known.empty() && c >= known.front() && c <= known.back() &&
            std::binary_search(known.begin(), known.end(), c))
          return false;
      }
      return true;
    };
    auto bv = m.rhs->getLocalViewHost(Tpetra::Access::OverwriteAll);
    std::map<GO, double> out;
    for (std::size_t i = 0; i < reduced.size(); ++i) {
      const GO g = reduced[i];
      const std::map<GO, double>* R = &out;
      if (assigned.find(g) == assigned.end() && m.pair_of_slave(g) < 0) {
        const Row& row = m.rows.at(g);
        if (plain(row)) {
          row_cols[i] = row.cols, row_vals[i] = row.vals;
          if (std::find(row.cols.begin(), row.cols.end(), g) == row.cols.end())
            row_cols[i].push_back(g), row_vals[i].push_back(0.0);  // keep a diagonal entry
          counts[i] = row_cols[i].size();
          bv(i, 0) = row.rhs;
          continue;
        }
      }
      if (auto it = assigned.find(g); it != assigned.end()) {
        R = &it->second;
        bv(i, 0) = assigned_rhs.at(g);
      } else if (const int q = m.pair_of_slave(g);
                 q >= 0 && (m.kind[q] == kMasterPivot || m.kind[q] == kRedundant)) {
        // prescribed slave dof whose multiplier a master row eliminates or that is redundant:
        // x_s = b_s / J[s, s]
        const Row& s_row = m.rows.at(g);
        out.clear();
        for (std::size_t e = 0; e < s_row.cols.size(); ++e) out[g] += s_row.vals[e];
        bv(i, 0) = s_row.rhs;
      } else {
        m.reduce(m.rows.at(g), out, bv(i, 0));
      }
      auto& cols = row_cols[i];
      auto& vals = row_vals[i];
      for (const auto& [c, v] : *R) cols.push_back(c), vals.push_back(v);
      if (std::find(cols.begin(), cols.end(), g) == cols.end())  // keep a diagonal entry
        cols.push_back(g), vals.push_back(0.0);
      counts[i] = cols.size();
    }
  }
  m.A = Teuchos::rcp(new Matrix(m.reduced_map, Teuchos::ArrayView<const std::size_t>(counts)));
  for (std::size_t i = 0; i < reduced.size(); ++i)
    m.A->insertGlobalValues(reduced[i], Teuchos::ArrayView<const GO>(row_cols[i]),
                            Teuchos::ArrayView<const double>(row_vals[i]));
  m.A->fillComplete(m.reduced_map, m.reduced_map);
}

void MultiplierCondensation::expand(const Vector& y, Vector& x) const {
  const Impl& m = *impl_;
  const auto& row_map = *m.full_map;
  // Reduced values needed here: swapped slots of owned multipliers, the displacement
  // columns of the slave rows of owned eliminated multipliers.
  std::vector<GO> needed;
  for (LO i = 0; i < LO(row_map.getNodeNumElements()); ++i) {
    const int p = m.pair_of_lambda(row_map.getGlobalElement(i));
    if (p < 0) continue;
    if (m.kind[p] == kSwapped) needed.push_back(m.slave[p]);
    if (m.kind[p] != kEliminated) continue;
    for (GO c : m.rows.at(m.slave[p]).cols) {
      const int q = m.pair_of_slave(c);
      if (m.pair_of_lambda(c) < 0 && !m.known_slave(q)) needed.push_back(c);
    }
  }
  std::sort(needed.begin(), needed.end());
  needed.erase(std::unique(needed.begin(), needed.end()), needed.end());
  const auto comm = row_map.getComm();
  const auto needed_map =
      Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(), needed.data(),
                           needed.size(), 0, comm));
  Vector y_needed(needed_map);
  y_needed.doImport(y, Import(m.reduced_map, needed_map), Tpetra::INSERT);
  {
    const auto yn = y_needed.getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto yv = y.getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto y_at = [&](GO g) { return yn(needed_map->getLocalElement(g), 0); };

    auto xv = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (LO i = 0; i < LO(row_map.getNodeNumElements()); ++i) {
      const GO g = row_map.getGlobalElement(i);
      const int p = m.pair_of_lambda(g);
      if (p < 0) {
        const int q = m.pair_of_slave(g);
        xv(i, 0) = m.known_slave(q) ? m.slave_known[q] : yv(m.reduced_map->getLocalElement(g), 0);
        continue;
      }
      if (m.known_lambda(p)) {
        xv(i, 0) = m.lambda_known[p];
      } else if (m.kind[p] == kSwapped) {
        xv(i, 0) = y_at(m.slave[p]);
      } else if (m.kind[p] == kMasterPivot) {
        xv(i, 0) = 0.0;  // below, from the other entries of x
      } else {
        const Row& s_row = m.rows.at(m.slave[p]);
        double v = s_row.rhs;
        for (std::size_t e = 0; e < s_row.cols.size(); ++e) {
          const GO c = s_row.cols[e];
          if (c == g) continue;
          const int p2 = m.pair_of_lambda(c);
          const int q = m.pair_of_slave(c);
          if (p2 >= 0)
            v -= s_row.vals[e] * m.lambda_known[p2];
          else if (m.known_slave(q))
            v -= s_row.vals[e] * m.slave_known[q];
          else
            v -= s_row.vals[e] * y_at(c);
        }
        xv(i, 0) = v / m.pivot[p];
      }
    }
  }
  if (m.stats.master_pivots == 0) return;
  // Kind D: λ_D = P⁻¹ (b_r − Σ_{c ∉ D} J[r, c] x_c), the pivot rows substituted down to the
  // reduced unknowns y.
  std::vector<GO> columns;
  std::vector<std::tuple<LO, int, std::map<GO, double>, double>> owned_d;  // (row, pair, R, r)
  for (LO i = 0; i < LO(row_map.getNodeNumElements()); ++i) {
    const int p = m.pair_of_lambda(row_map.getGlobalElement(i));
    if (p < 0 || m.kind[p] != kMasterPivot) continue;
    std::map<GO, double> R;
    double r = 0.0;
    m.accumulate_d(m.d_index.at(p), 1.0, R, r, 0);
    for (const auto& [c, v] : R) columns.push_back(c);
    owned_d.emplace_back(i, p, std::move(R), r);
  }
  std::sort(columns.begin(), columns.end());
  columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
  const auto columns_map =
      Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(), columns.data(),
                           columns.size(), 0, comm));
  Vector y_columns(columns_map);
  y_columns.doImport(y, Import(m.reduced_map, columns_map), Tpetra::INSERT);
  const auto yc = y_columns.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto xv = x.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (const auto& [i, p, R, r] : owned_d) {
    double v = r;
    for (const auto& [c, a] : R) v -= a * yc(columns_map->getLocalElement(c), 0);
    xv(i, 0) = v;
  }
}

}  // namespace grout
