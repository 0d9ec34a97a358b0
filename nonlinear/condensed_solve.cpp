#include "nonlinear/condensed_solve.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace grout {

namespace {

enum Kind : int { kIdentity = 0, kEliminated = 1, kSwapped = 2 };

struct Row {
  std::vector<GO> cols;
  std::vector<double> vals;
  double rhs = 0.0;
};

using RowTable = std::unordered_map<GO, Row>;

// The locally stored rows of a fill-complete matrix (and b), by global row.
void add_rows(const Matrix& A, const Vector& b, RowTable& table) {
  const auto& row_map = *A.getRowMap();
  const auto& col_map = *A.getColMap();
  const auto local = A.getLocalMatrixHost();
  const auto bv = b.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (LO i = 0; i < LO(row_map.getNodeNumElements()); ++i) {
    Row& r = table[row_map.getGlobalElement(i)];
    r.cols.clear(), r.vals.clear();
    for (auto p = local.graph.row_map(i); p < local.graph.row_map(i + 1); ++p) {
      if (local.values(p) == 0.0) continue;
      r.cols.push_back(col_map.getGlobalElement(local.graph.entries(p)));
      r.vals.push_back(local.values(p));
    }
    r.rhs = bv(i, 0);
  }
}

// Rows `gids` of J and b on this rank (collective; gids may be owned elsewhere).
void import_rows(const Matrix& J, const Vector& b, std::vector<GO> gids, RowTable& table) {
  std::sort(gids.begin(), gids.end());
  gids.erase(std::unique(gids.begin(), gids.end()), gids.end());
  const auto comm = J.getRowMap()->getComm();
  const auto target = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                           gids.data(), gids.size(), 0, comm));
  const Import importer(J.getRowMap(), target);
  Matrix Jt(target, 0);
  Jt.doImport(J, importer, Tpetra::INSERT);
  Jt.fillComplete(J.getDomainMap(), J.getRangeMap());
  Vector bt(target);
  bt.doImport(b, importer, Tpetra::INSERT);
  add_rows(Jt, bt, table);
}

}  // namespace

struct MultiplierCondensation::Impl {
  int dofs_per_node = 1;
  std::vector<GO> lambda, slave;
  std::unordered_map<GO, int> by_lambda, by_slave;

  // Of the last condense(), replicated per pair.
  std::vector<int> kind;
  std::vector<double> lambda_known, slave_known, pivot;
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

  // Row `row` with every multiplier and every known displacement substituted: entries on
  // reduced unknowns (GIDs of the reduced map; a swapped slot s stands for λ_t(s)).
  void reduce(const Row& row, std::map<GO, double>& out, double& rhs_out) const {
    out.clear();
    rhs_out = row.rhs;
    const auto add_u = [&](GO c, double v) {
      const int q = pair_of_slave(c);
      if (q >= 0 && kind[q] == kSwapped)
        rhs_out -= v * slave_known[q];
      else
        out[c] += v;
    };
    for (std::size_t e = 0; e < row.cols.size(); ++e) {
      const GO c = row.cols[e];
      const double v = row.vals[e];
      const int p = pair_of_lambda(c);
      if (p < 0) {
        add_u(c, v);
        continue;
      }
      if (kind[p] == kIdentity) {
        rhs_out -= v * lambda_known[p];
      } else if (kind[p] == kSwapped) {
        out[slave[p]] += v;
      } else {  // λ_t = (b_s − Σ J[s,c] x_c) / D
        const Row& s_row = rows.at(slave[p]);
        const double f = v / pivot[p];
        rhs_out -= f * s_row.rhs;
        for (std::size_t k = 0; k < s_row.cols.size(); ++k) {
          const GO c2 = s_row.cols[k];
          if (c2 == c) continue;
          const int p2 = pair_of_lambda(c2);
          if (p2 >= 0)
            rhs_out += f * s_row.vals[k] * lambda_known[p2];  // kind A (checked)
          else
            add_u(c2, -f * s_row.vals[k]);
        }
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

void MultiplierCondensation::condense(const Matrix& J, const Vector& b) {
  Impl& m = *impl_;
  const auto comm = J.getRowMap()->getComm();
  const auto& row_map = *J.getRowMap();
  const int n_pairs = int(m.lambda.size());
  m.full_map = J.getRowMap();
  m.rows.clear();
  add_rows(J, b, m.rows);

  // 1. Classify the pairs from their owners' rows; replicate.
  enum { kIsIdentity, kLambda, kDiagonalOnly, kSlaveValue, kPivot, kFields };
  std::vector<double> local(std::size_t(n_pairs) * kFields, 0.0), global(local.size(), 0.0);
  std::vector<std::pair<int, int>> slave_lambda_columns;  // (pair, other pair) in slave rows
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
      if (only_diagonal && diagonal != 0.0) {
        local[p * kFields + kIsIdentity] = 1.0;
        local[p * kFields + kLambda] = row.rhs / diagonal;
      }
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
  m.kind.assign(n_pairs, kIdentity);
  m.lambda_known.assign(n_pairs, 0.0);
  m.slave_known.assign(n_pairs, 0.0);
  m.pivot.assign(n_pairs, 0.0);
  std::string error;
  for (int p = 0; p < n_pairs; ++p) {
    const double* f = &global[std::size_t(p) * kFields];
    m.lambda_known[p] = f[kLambda];
    m.slave_known[p] = f[kSlaveValue];
    m.pivot[p] = f[kPivot];
    if (f[kIsIdentity] != 0.0)
      m.kind[p] = kIdentity;
    else if (f[kPivot] != 0.0)
      m.kind[p] = kEliminated;
    else if (f[kDiagonalOnly] != 0.0)
      m.kind[p] = kSwapped;
    else if (error.empty())
      error = "multiplier " + std::to_string(m.lambda[p]) + ": its slave row " +
              std::to_string(m.slave[p]) +
              " has no entry in its column and is not a prescribed (diagonal-only) row";
  }
  int bad_local = 0;
  for (const auto& [p, q] : slave_lambda_columns)
    if (m.kind[p] == kEliminated && m.kind[q] != kIdentity) bad_local = 1;
  int bad = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, bad_local, Teuchos::outArg(bad));
  if (bad && error.empty()) error = "a slave row couples to more than one unknown multiplier";
  if (!error.empty())
    throw std::runtime_error("condense_multipliers: cannot condense the multipliers: " + error);
  {
    int counts[4] = {0, 0, 0, 0};
    for (int p = 0; p < n_pairs; ++p) ++counts[m.kind[p]];
    m.stats = Statistics();
    m.stats.identity = counts[kIdentity];
    m.stats.eliminated = counts[kEliminated];
    m.stats.swapped = counts[kSwapped];
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
  std::map<GO, std::vector<int>> groups;  // node -> its B/C pairs, of owned B/C slots
  for (GO g : reduced)
    if (const int p = m.pair_of_slave(g); p >= 0 && m.kind[p] != kIdentity) groups[m.group(p)];
  if (!groups.empty())
    for (int p = 0; p < n_pairs; ++p)
      if (m.kind[p] != kIdentity)
        if (auto it = groups.find(m.group(p)); it != groups.end()) it->second.push_back(p);
  {
    std::vector<GO> needed;
    for (const auto& [node, pairs] : groups)
      for (int p : pairs)
        if (!row_map.isNodeGlobalElement(m.lambda[p])) needed.push_back(m.lambda[p]);
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
  std::map<GO, std::map<GO, double>> assigned;  // slot -> reduced row (scaled)
  std::map<GO, double> assigned_rhs;
  int zero_diagonals = 0;
  for (const auto& [node, pairs] : groups) {
    const int n = int(pairs.size());
    std::vector<std::map<GO, double>> R(n);
    std::vector<double> r(n);
    std::vector<std::vector<double>> w(n, std::vector<double>(n, 0.0));  // row i at slot k
    for (int i = 0; i < n; ++i) {
      m.reduce(m.rows.at(m.lambda[pairs[i]]), R[i], r[i]);
      double row_max = 0.0;
      for (const auto& [c, v] : R[i]) row_max = std::max(row_max, std::abs(v));
      for (int k = 0; k < n; ++k) {
        const auto it = R[i].find(m.slave[pairs[k]]);
        if (it != R[i].end() && row_max > 0.0) w[i][k] = std::abs(it->second) / row_max;
      }
    }
    // The permutation (row perm[k] at slot k) maximising Π w; greedy beyond 6 rows.
    std::vector<int> perm(n), best(n);
    for (int i = 0; i < n; ++i) perm[i] = best[i] = i;
    const auto score = [&](const std::vector<int>& q) {
      double s = 0.0;
      for (int k = 0; k < n; ++k) s += w[q[k]][k] > 0.0 ? std::log(w[q[k]][k]) : -1e300;
      return s;
    };
    if (n <= 6) {
      double best_score = score(perm);
      while (std::next_permutation(perm.begin(), perm.end()))
        if (const double s = score(perm); s > best_score) best_score = s, best = perm;
    } else {
      std::vector<char> used(n, 0);
      for (int k = 0; k < n; ++k) {
        int choice = -1;
        for (int i = 0; i < n; ++i)
          if (!used[i] && (choice < 0 || w[i][k] > w[choice][k])) choice = i;
        used[choice] = 1, best[k] = choice;
      }
    }
    for (int k = 0; k < n; ++k) {
      const GO slot = m.slave[pairs[k]];
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
    auto bv = m.rhs->getLocalViewHost(Tpetra::Access::OverwriteAll);
    std::map<GO, double> out;
    for (std::size_t i = 0; i < reduced.size(); ++i) {
      const GO g = reduced[i];
      const std::map<GO, double>* R = &out;
      if (auto it = assigned.find(g); it != assigned.end()) {
        R = &it->second;
        bv(i, 0) = assigned_rhs.at(g);
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
      if (m.pair_of_lambda(c) < 0 && !(q >= 0 && m.kind[q] == kSwapped)) needed.push_back(c);
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
  const auto yn = y_needed.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto yv = y.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto y_at = [&](GO g) { return yn(needed_map->getLocalElement(g), 0); };

  auto xv = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (LO i = 0; i < LO(row_map.getNodeNumElements()); ++i) {
    const GO g = row_map.getGlobalElement(i);
    const int p = m.pair_of_lambda(g);
    if (p < 0) {
      const int q = m.pair_of_slave(g);
      xv(i, 0) = q >= 0 && m.kind[q] == kSwapped ? m.slave_known[q]
                                                 : yv(m.reduced_map->getLocalElement(g), 0);
      continue;
    }
    if (m.kind[p] == kIdentity) {
      xv(i, 0) = m.lambda_known[p];
    } else if (m.kind[p] == kSwapped) {
      xv(i, 0) = y_at(m.slave[p]);
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
        else if (q >= 0 && m.kind[q] == kSwapped)
          v -= s_row.vals[e] * m.slave_known[q];
        else
          v -= s_row.vals[e] * y_at(c);
      }
      xv(i, 0) = v / m.pivot[p];
    }
  }
}

}  // namespace grout
