#include "nonlinear/symmetric_condensation.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_RowMatrixTransposer.hpp>
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "kernels/small_dense_lu.hpp"
#include "nonlinear/local_csr_matrix.hpp"
#include "nonlinear/row_table.hpp"
#include "nonlinear/symmetry_check.hpp"

namespace grout {

namespace {

// Rank decisions on rows scaled to a largest |entry| of 1 (pure-λ rows, λ recovery).
constexpr double rank_tolerance = 1e-10;
// A slave pivot below this times its constraint row's largest |entry| is no pivot.
constexpr double pivot_tolerance = 1e-8;
// |C N − Gᵀ R| above this times max |C N| of the node: the multiplier does not act along the
// constraint's gradient.
constexpr double proportional_tolerance = 1e-10;

// Gaussian elimination with complete pivoting on the dense m×n matrix a (row-major), pivots
// only in the columns with allowed[c]: the (row, column) pivots in order, at most max_pivots,
// while the largest remaining |entry| exceeds tolerance (a's rows scaled as the caller wants).
std::vector<std::pair<int, int>> pivots_of(std::vector<double> a, int m, int n,
                                           const std::vector<char>& allowed, int max_pivots,
                                           double tolerance) {
  std::vector<char> row_used(m, 0), col_used(n, 0);
  std::vector<std::pair<int, int>> out;
  while (int(out.size()) < max_pivots) {
    int pi = -1, pc = -1;
    double best = tolerance;
    for (int i = 0; i < m; ++i)
      for (int c = 0; c < n; ++c)
        if (!row_used[i] && !col_used[c] && allowed[c] && std::abs(a[i * n + c]) > best)
          best = std::abs(a[i * n + c]), pi = i, pc = c;
    if (pi < 0) break;
    row_used[pi] = col_used[pc] = 1;
    out.emplace_back(pi, pc);
    for (int i = 0; i < m; ++i) {
      if (row_used[i]) continue;
      const double f = a[i * n + pc] / a[pi * n + pc];
      for (int c = 0; c < n; ++c) a[i * n + c] -= f * a[pi * n + c];
    }
  }
  return out;
}

// pivots_of with each row of a first scaled to a largest |entry| of 1.
std::vector<std::pair<int, int>> complete_pivots(std::vector<double> a, int m, int n,
                                                 const std::vector<char>& allowed, int max_pivots,
                                                 double tolerance) {
  for (int i = 0; i < m; ++i) {
    double s = 0.0;
    for (int c = 0; c < n; ++c) s = std::max(s, std::abs(a[i * n + c]));
    if (s > 0.0)
      for (int c = 0; c < n; ++c) a[i * n + c] /= s;
  }
  return pivots_of(std::move(a), m, n, allowed, max_pivots, tolerance);
}

// Inverse of the n×n matrix a (row-major) by the small dense LU with partial pivoting
// (kernels/small_dense_lu.hpp); false if singular (an exactly zero pivot).
bool invert(std::vector<double> a, int n, std::vector<double>& inverse) {
  inverse.assign(std::size_t(n) * n, 0.0);
  std::vector<int> pivot(static_cast<std::size_t>(n));
  return small_lu_invert(n, a.data(), n, pivot.data(), inverse.data(), n);
}

// λ -> (displacement row, C[row, λ]): the multiplier columns of J's displacement rows.
using MultiplierColumns = std::unordered_map<GO, std::vector<std::pair<GO, double>>>;

// What condense() keeps of one slave node (handled by the rank owning its dofs).
struct NodeData {
  std::vector<int> pairs;  ///< d pairs: the node's multipliers and slave dofs
  int k = 0;               ///< constraint rows = eliminated slave dofs
  std::vector<GO> eliminated;
  std::vector<double> c;                        ///< c_e = G_e⁻¹ g (k)
  std::vector<std::map<GO, double>> t_rows;     ///< u_e = c_e + Σ_f A_ef u_f (old GIDs f)
  std::vector<double> lambda0;                  ///< particular λ of P λ = p (d)
  std::vector<double> N;                        ///< d × k, ker P
  std::vector<GO> recovery_rows;                ///< k slave force rows giving μ
  std::vector<std::vector<double>> recovery_c;  ///< their λ coefficients (d each)
  std::vector<double> recovery_inverse;         ///< ((C_s N) of those rows)⁻¹, k × k
};

}  // namespace

struct SymmetricCondensation::Impl {
  int dofs_per_node = 1;
  const MultiplierRows* declared = nullptr;  ///< of the current condense(), or none
  std::vector<GO> lambda, slave;
  std::unordered_map<GO, int> by_lambda, by_slave;
  std::map<GO, std::vector<int>> nodes;  ///< slave node -> its pairs (replicated)

  std::string reason;
  Statistics stats;
  std::vector<NodeData> handled;
  RowTable rows;
  Teuchos::RCP<const Map> full_map, reduced_map, needed_map;
  Teuchos::RCP<Import> needed_import;
  Teuchos::RCP<Matrix> T, A;
  Teuchos::RCP<Vector> rhs;

  bool is_lambda(GO g) const { return by_lambda.count(g) != 0; }
  std::string reduce_node(NodeData& nd, MultiplierColumns& columns);
  void build_reduced_matrix(const Matrix& J, const std::vector<GO>& skipped,
                            const std::vector<GO>& eliminated,
                            const std::unordered_map<GO, const std::map<GO, double>*>& t_row_of);
};

SymmetricCondensation::SymmetricCondensation(const MultiplierPairing& lambda_to_slave,
                                             int dofs_per_node)
    : impl_(std::make_unique<Impl>()) {
  if (dofs_per_node < 1) throw std::invalid_argument("SymmetricCondensation: dofs_per_node < 1");
  Impl& m = *impl_;
  m.dofs_per_node = dofs_per_node;
  for (const auto& [t, s] : lambda_to_slave) {
    const int p = int(m.lambda.size());
    if (!m.by_lambda.emplace(t, p).second || !m.by_slave.emplace(s, p).second)
      throw std::invalid_argument("SymmetricCondensation: multiplier " + std::to_string(t) +
                                  " or slave dof " + std::to_string(s) + " paired twice");
    m.lambda.push_back(t);
    m.slave.push_back(s);
    m.nodes[s / dofs_per_node].push_back(p);
  }
}

SymmetricCondensation::~SymmetricCondensation() = default;

Teuchos::RCP<const Matrix> SymmetricCondensation::matrix() const {
  return impl_->A;
}
Teuchos::RCP<const Matrix> SymmetricCondensation::transformation() const {
  return impl_->T;
}
const Vector& SymmetricCondensation::rhs() const {
  return *impl_->rhs;
}
const std::string& SymmetricCondensation::reason() const {
  return impl_->reason;
}
const SymmetricCondensation::Statistics& SymmetricCondensation::statistics() const {
  return impl_->stats;
}

namespace {

// The first non-empty `why` of any rank (lowest rank first), on every rank; empty if none.
std::string agree(const Comm& comm, const std::string& why) {
  const int size = comm.getSize();
  int mine = why.empty() ? size : comm.getRank(), first = size;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, mine, Teuchos::outArg(first));
  if (first == size) return std::string();
  int length = int(why.size());
  Teuchos::broadcast(comm, first, Teuchos::outArg(length));
  std::string out = comm.getRank() == first ? why : std::string(std::size_t(length), ' ');
  if (length > 0) Teuchos::broadcast(comm, first, length, &out[0]);
  return out;
}

}  // namespace

// Step 3 of condense() for one handled node: the λ-rows' structure, the eliminated slave
// dofs, T's rows, C N ∝ Gᵀ and the recovery of λ (header). `columns`: the multiplier columns
// of the displacement rows, by multiplier. Returns why the node fails a check, or "".
std::string SymmetricCondensation::Impl::reduce_node(NodeData& nd, MultiplierColumns& columns) {
  Impl& m = *this;
  std::string why;
  const int d = int(nd.pairs.size());
  const std::vector<char> all_columns(std::size_t(d), 1);
  const GO node = m.slave[nd.pairs.front()] / m.dofs_per_node;
  const std::string at = "slave node " + std::to_string(node) + ": ";
  std::unordered_map<GO, int> own;  // the node's multipliers -> 0 .. d-1
  for (int i = 0; i < d; ++i) own[m.lambda[nd.pairs[i]]] = i;
  std::vector<double> P, p_rhs;  // pure-λ rows (r × d)
  std::vector<const Row*> G;     // constraint rows
  for (int i = 0; i < d && why.empty(); ++i) {
    const Row& row = m.rows.at(m.lambda[nd.pairs[i]]);
    bool has_u = false, has_lambda = false;
    std::vector<double> coefficients(d, 0.0);
    for (std::size_t e = 0; e < row.cols.size(); ++e) {
      const auto it = own.find(row.cols[e]);
      if (it != own.end()) {
        has_lambda = true, coefficients[it->second] += row.vals[e];
      } else if (m.is_lambda(row.cols[e])) {
        why = at + "a multiplier row holds another node's multiplier";
      } else {
        has_u = true;
      }
    }
    const GO gid = m.lambda[nd.pairs[i]];
    if (const LambdaRow* kind = m.declared ? m.declared->find(gid) : nullptr) {
      // The declaration decides; J's row must not contradict it.
      const bool said_lambda = *kind == LambdaRow::identity || *kind == LambdaRow::pure_lambda;
      if (*kind == LambdaRow::mixed) {
        why = at + "a multiplier row is declared mixed (friction slip or geometry: current)";
        break;
      }
      if ((said_lambda && has_u) || (*kind == LambdaRow::constraint && has_lambda)) {
        why = at + "multiplier row " + std::to_string(gid) +
              " does not have the structure its writer declared";
        break;
      }
    }
    if (has_u && has_lambda)
      why = at +
            "a multiplier row mixes displacements and multipliers (friction or "
            "geometry: current)";
    else if (!has_u && !has_lambda)
      why = at + "an empty multiplier row";
    else if (has_lambda)
      P.insert(P.end(), coefficients.begin(), coefficients.end()), p_rhs.push_back(row.rhs);
    else
      G.push_back(&row);
  }
  if (!why.empty()) return why;
  const int r = int(p_rhs.size()), k = int(G.size());
  nd.k = k;
  // P λ = p: λ0 on P's pivot columns, N = ker P (d × k).
  const auto p_pivots = complete_pivots(P, r, d, all_columns, r, rank_tolerance);
  if (int(p_pivots.size()) < r) {
    return at + "its multiplier-only rows are dependent";
  }
  std::vector<int> pivot_cols, free_cols;
  {
    std::vector<char> is_pivot(d, 0);
    for (const auto& [i, c] : p_pivots) pivot_cols.push_back(c), is_pivot[c] = 1;
    for (int c = 0; c < d; ++c)
      if (!is_pivot[c]) free_cols.push_back(c);
  }
  nd.lambda0.assign(d, 0.0);
  nd.N.assign(std::size_t(d) * k, 0.0);
  if (r > 0) {
    std::vector<double> Pp(std::size_t(r) * r), Pinv;
    for (int i = 0; i < r; ++i)
      for (int j = 0; j < r; ++j) Pp[i * r + j] = P[i * d + pivot_cols[j]];
    invert(Pp, r, Pinv);
    for (int j = 0; j < r; ++j)
      for (int i = 0; i < r; ++i) nd.lambda0[pivot_cols[j]] += Pinv[j * r + i] * p_rhs[i];
    for (int f = 0; f < k; ++f)
      for (int j = 0; j < r; ++j)
        for (int i = 0; i < r; ++i)
          nd.N[pivot_cols[j] * k + f] -= Pinv[j * r + i] * P[i * d + free_cols[f]];
  }
  for (int f = 0; f < k; ++f) nd.N[free_cols[f] * k + f] = 1.0;
  if (k == 0) return "";

  // Slave pivots: complete pivoting on the node's slave block of G, rows scaled by their
  // largest entry over all columns; prescribed slave dofs (rows holding their diagonal
  // only) never pivot.
  std::vector<double> Gs(std::size_t(k) * d, 0.0);
  std::vector<char> allowed(d, 1);
  for (int c = 0; c < d; ++c) {
    const GO s = m.slave[nd.pairs[c]];
    const Row& srow = m.rows.at(s);
    bool diagonal_only = true;
    for (GO col : srow.cols) diagonal_only = diagonal_only && col == s;
    allowed[c] = !diagonal_only;
  }
  for (int i = 0; i < k; ++i) {
    double scale = 0.0;
    for (double v : G[i]->vals) scale = std::max(scale, std::abs(v));
    for (std::size_t e = 0; e < G[i]->cols.size(); ++e) {
      const auto it = m.by_slave.find(G[i]->cols[e]);
      if (it == m.by_slave.end()) continue;
      const auto pos = std::find(nd.pairs.begin(), nd.pairs.end(), it->second);
      if (pos != nd.pairs.end()) Gs[i * d + int(pos - nd.pairs.begin())] += G[i]->vals[e] / scale;
    }
  }
  // Gs's rows are already scaled by their whole row's largest entry (not their slave block's).
  const auto g_pivots = pivots_of(Gs, k, d, allowed, k, pivot_tolerance);
  if (int(g_pivots.size()) < k) {
    return at + "no unprescribed slave dof pivots its constraint rows";
  }
  std::vector<GO> e_gid(k);
  for (int l = 0; l < k; ++l) e_gid[l] = m.slave[nd.pairs[g_pivots[l].second]];
  nd.eliminated = e_gid;
  // G_e (k × k, rows in G's order, columns the eliminated dofs), its inverse.
  std::vector<std::map<GO, double>> g_rows(k);
  for (int i = 0; i < k; ++i)
    for (std::size_t e = 0; e < G[i]->cols.size(); ++e) g_rows[i][G[i]->cols[e]] += G[i]->vals[e];
  std::vector<double> Ge(std::size_t(k) * k, 0.0), Ginv;
  for (int i = 0; i < k; ++i)
    for (int l = 0; l < k; ++l)
      if (auto it = g_rows[i].find(e_gid[l]); it != g_rows[i].end()) Ge[i * k + l] = it->second;
  if (!invert(Ge, k, Ginv)) {
    return at + "singular constraint block";
  }
  // u_e = G_e⁻¹ (g − G_f u_f): row l of Ginv gives e_l.
  nd.c.assign(k, 0.0);
  nd.t_rows.assign(k, {});
  for (int l = 0; l < k; ++l)
    for (int i = 0; i < k; ++i) {
      const double w = Ginv[l * k + i];
      nd.c[l] += w * G[i]->rhs;
      for (const auto& [col, v] : g_rows[i])
        if (std::find(e_gid.begin(), e_gid.end(), col) == e_gid.end()) nd.t_rows[l][col] -= w * v;
    }
  // C N (rows r, k columns) and R = G_e⁻ᵀ (C N)[e, :]; C N = Gᵀ R on every row.
  std::map<GO, std::vector<double>> CN;
  double cn_max = 0.0;
  for (int c = 0; c < d; ++c)
    for (const auto& [row, v] : columns[m.lambda[nd.pairs[c]]]) {
      auto& out = CN[row];
      out.resize(k, 0.0);
      for (int f = 0; f < k; ++f) out[f] += v * nd.N[c * k + f];
    }
  for (const auto& [row, v] : CN)
    for (double x : v) cn_max = std::max(cn_max, std::abs(x));
  std::vector<double> R(std::size_t(k) * k, 0.0);
  for (int i = 0; i < k; ++i)
    for (int f = 0; f < k; ++f)
      for (int l = 0; l < k; ++l)
        if (auto it = CN.find(e_gid[l]); it != CN.end())
          R[i * k + f] += Ginv[l * k + i] * it->second[f];
  std::set<GO> check_rows;
  for (const auto& [row, v] : CN) check_rows.insert(row);
  for (const auto& g : g_rows)
    for (const auto& [col, v] : g) check_rows.insert(col);
  for (GO row : check_rows) {
    for (int f = 0; f < k && why.empty(); ++f) {
      double gr = 0.0;
      for (int i = 0; i < k; ++i)
        if (auto it = g_rows[i].find(row); it != g_rows[i].end()) gr += it->second * R[i * k + f];
      const auto it = CN.find(row);
      const double cn = it != CN.end() ? it->second[f] : 0.0;
      if (!(std::abs(cn - gr) <= proportional_tolerance * cn_max))
        why = at + "its multiplier does not act along its constraint's gradient (row " +
              std::to_string(row) + ")";
    }
  }
  if (!why.empty()) return why;
  // Recovery: μ from k of the node's slave force rows, (C_s N) μ = b_s − K_s u − C_s λ0.
  std::vector<double> CsN(std::size_t(d) * k, 0.0);
  std::vector<std::vector<double>> cs(d, std::vector<double>(d, 0.0));
  for (int s = 0; s < d; ++s) {
    const Row& srow = m.rows.at(m.slave[nd.pairs[s]]);
    for (std::size_t e = 0; e < srow.cols.size(); ++e) {
      if (const auto it = own.find(srow.cols[e]); it != own.end())
        cs[s][it->second] += srow.vals[e];
      else if (m.is_lambda(srow.cols[e]))
        why = at + "its slave force row holds another node's multiplier";
    }
    for (int f = 0; f < k; ++f)
      for (int c = 0; c < d; ++c) CsN[s * k + f] += cs[s][c] * nd.N[c * k + f];
  }
  if (!why.empty()) return why;
  const auto r_pivots = complete_pivots(CsN, d, k, all_columns, k, rank_tolerance);
  if (int(r_pivots.size()) < k) {
    return at + "its multipliers cannot be recovered from its slave force rows";
  }
  std::vector<double> Ms(std::size_t(k) * k);
  for (int i = 0; i < k; ++i) {
    const int s = r_pivots[i].first;
    nd.recovery_rows.push_back(m.slave[nd.pairs[s]]);
    nd.recovery_c.push_back(cs[s]);
    for (int f = 0; f < k; ++f) Ms[i * k + f] = CsN[s * k + f];
  }
  if (!invert(Ms, k, nd.recovery_inverse)) return at + "singular recovery block";
  return "";
}

// Step 7 of condense(): K̃ = Tᵀ K T, with the eliminated rows' pattern (below), into A.
// `skipped`: the paired multipliers, sorted; `eliminated`: the eliminated dofs, sorted;
// `t_row_of`: T's rows of the eliminated dofs handled here.
void SymmetricCondensation::Impl::build_reduced_matrix(
    const Matrix& J, const std::vector<GO>& skipped, const std::vector<GO>& eliminated,
    const std::unordered_map<GO, const std::map<GO, double>*>& t_row_of) {
  Impl& m = *this;
  const auto comm = J.getRowMap()->getComm();
  const auto& row_map = *J.getRowMap();
  const auto new_gid = [&](GO g) {
    return g - GO(std::lower_bound(skipped.begin(), skipped.end(), g) - skipped.begin());
  };
  // K̃ = Tᵀ K T without a general triple product: T = I + (A on the eliminated rows), so
  //   K̃_ij = K_ij + Σ_e K_ie A_ej + Σ_e A_ei (K T)_ej,   (K T)_ej = K_ej + Σ_e' K_ee' A_e'j,
  // for kept i, j (e, e' eliminated): J's rows, plus K_ie A_e on the rows with an
  // eliminated column (a), plus A_eᵀ (K T)_e on the rows of A_e's columns (b), sent to
  // their owners. T's rows are touched only on ~the slave dofs: the rest of K̃ is K's.
  // A's rows (reduced column GIDs) of the eliminated dofs among this rank's columns of J:
  // handled here, or imported from the rank that handles them.
  std::unordered_map<GO, std::vector<std::pair<GO, double>>> a_rows;
  for (const auto& [e, t_row] : t_row_of) {
    auto& out = a_rows[e];
    for (const auto& [f, v] : *t_row) out.emplace_back(new_gid(f), v);
  }
  const auto& j_cols = *J.getColMap();
  const LO n_j_cols = LO(j_cols.getNodeNumElements());
  {
    std::vector<GO> remote;
    for (LO c = 0; c < n_j_cols; ++c) {
      const GO g = j_cols.getGlobalElement(c);
      if (!row_map.isNodeGlobalElement(g) &&
          std::binary_search(eliminated.begin(), eliminated.end(), g))
        remote.push_back(g);
    }
    RowTable remote_t_rows;
    Vector zero(J.getRowMap());
    import_rows(*m.T, zero, remote, remote_t_rows);
    for (const auto& [e, r] : remote_t_rows) {
      auto& out = a_rows[e];
      for (std::size_t q = 0; q < r.cols.size(); ++q) out.emplace_back(r.cols[q], r.vals[q]);
    }
  }
  const auto is_eliminated = [&](GO g) {
    return std::binary_search(eliminated.begin(), eliminated.end(), g);
  };
  // (b): A_eᵀ (K T)_e of the eliminated dofs handled here, row by row of Aᵀ (Gustavson's
  // row-wise sparse product, with a dense accumulator over the columns met): the rows this
  // rank owns go to `received` directly, the others are exported to their owners (summed
  // there).
  std::unordered_map<GO, int> slot_of;  // reduced GID -> slot (the columns and rows met)
  std::vector<GO> slot_gid;
  const auto slot = [&](GO c) {
    const auto [it, added] = slot_of.emplace(c, int(slot_gid.size()));
    if (added) slot_gid.push_back(c);
    return it->second;
  };
  std::vector<double> sum;
  std::vector<char> met;
  std::vector<int> touched;
  const auto add = [&](int s, double v) {
    if (s >= int(sum.size())) sum.resize(slot_gid.size(), 0.0), met.resize(slot_gid.size(), 0);
    if (!met[s]) met[s] = 1, touched.push_back(s);
    sum[s] += v;
  };
  std::vector<std::vector<std::pair<int, double>>> kt_rows;  // (K T)_e per handled e
  std::vector<std::vector<std::pair<int, double>>> at_rows;  // Aᵀ: slot i -> (e, A_ei)
  for (const auto& [e, t_row] : t_row_of) {
    const Row& row = m.rows.at(e);
    for (std::size_t q = 0; q < row.cols.size(); ++q) {
      const GO f = row.cols[q];
      if (m.is_lambda(f)) continue;
      if (const auto it = a_rows.find(f); it != a_rows.end())
        for (const auto& [c, a] : it->second) add(slot(c), row.vals[q] * a);
      else
        add(slot(new_gid(f)), row.vals[q]);
    }
    kt_rows.emplace_back();
    for (int s : touched) kt_rows.back().emplace_back(s, sum[s]), sum[s] = 0.0, met[s] = 0;
    touched.clear();
    for (const auto& [i, a] : a_rows.at(e)) {
      const int s = slot(i);
      if (s >= int(at_rows.size())) at_rows.resize(slot_gid.size());
      at_rows[s].emplace_back(int(kt_rows.size()) - 1, a);
    }
  }
  std::unordered_map<GO, std::vector<std::pair<GO, double>>> received;  // owned reduced row ->
  std::vector<GO> spread_rows;  // rows for other ranks, and their entries
  std::vector<std::vector<std::pair<GO, double>>> spread;
  for (int s = 0; s < int(at_rows.size()); ++s) {
    if (at_rows[s].empty()) continue;
    for (const auto& [k, a] : at_rows[s])
      for (const auto& [c, v] : kt_rows[k]) add(c, a * v);
    std::vector<std::pair<GO, double>> out;
    out.reserve(touched.size());
    for (int c : touched) out.emplace_back(slot_gid[c], sum[c]), sum[c] = 0.0, met[c] = 0;
    touched.clear();
    if (m.reduced_map->isNodeGlobalElement(slot_gid[s])) {
      auto& r = received[slot_gid[s]];
      r.insert(r.end(), out.begin(), out.end());
    } else {
      spread_rows.push_back(slot_gid[s]), spread.push_back(std::move(out));
    }
  }
  // The rows for other ranks go to their owners in one all-to-all: the owner of reduced row i
  // is that of its dof in J's row map (the reduced map keeps J's distribution), whose
  // directory J's map keeps from one Newton iteration to the next. (A Tpetra export of a
  // matrix over the new reduced map took 40-50 ms per Newton iteration on 2 ranks at 1e5
  // unknowns, 0.03 ms on 1.)
  {
    const auto old_gid = [&](GO i) {  // the inverse of new_gid: the k-th dof that is kept
      GO g = i;
      for (GO below = 0;;) {
        const GO now =
            GO(std::upper_bound(skipped.begin(), skipped.end(), i + below) - skipped.begin());
        if (now == below) break;
        below = now;
        g = i + below;
      }
      return g;
    };
    std::vector<GO> originals(spread_rows.size());
    for (std::size_t r = 0; r < spread_rows.size(); ++r) originals[r] = old_gid(spread_rows[r]);
    std::vector<int> owners(spread_rows.size(), -1);
    row_map.getRemoteIndexList(Teuchos::ArrayView<const GO>(originals),
                               Teuchos::ArrayView<int>(owners));
    const int ranks = comm->getSize();
    std::vector<std::vector<Triple>> out(static_cast<std::size_t>(ranks));
    std::string why;  // thrown on every rank after the exchange, never on one alone before it
    for (std::size_t r = 0; r < spread_rows.size(); ++r) {
      if (owners[r] < 0 || owners[r] >= ranks) {
        if (why.empty())
          why = "symmetric reduction: no owner for reduced row " + std::to_string(spread_rows[r]);
        continue;
      }
      for (const auto& [c, v] : spread[r]) out[owners[r]].push_back({spread_rows[r], c, v});
    }
    for (const Triple& e : send_to_ranks(*comm, out)) received[e.row].emplace_back(e.col, e.value);
    if (const std::string any = agree(*comm, why); !any.empty()) throw std::logic_error(any);
  }
  // The eliminated rows get K_ee on the diagonal and zeros where K T has entries in row e:
  // the pattern K̃ would have with e kept (its column e too: MumpsSolver reads a zero above
  // the diagonal as its mirror). Then K̃'s pattern stays within the union of the Newton
  // iterations' patterns when a dof is eliminated in some and kept in others, and MUMPS
  // keeps its analysis (without them, 7 analyses in 7 Newton iterations on the 3D Hertz
  // spheres instead of 3).
  std::unordered_map<GO, std::map<GO, double>> extra;  // reduced row -> (column, value)
  for (const auto& [e, t_row] : t_row_of) {
    const GO ne = new_gid(e);
    const Row& row = m.rows.at(e);
    auto& out = extra[ne];
    for (std::size_t q = 0; q < row.cols.size(); ++q) {
      const GO f = row.cols[q];
      if (m.is_lambda(f)) continue;
      if (f == e) {
        out[ne] = row.vals[q] != 0.0 ? row.vals[q] : 1.0;
      } else if (const auto it = a_rows.find(f); it != a_rows.end()) {
        for (const auto& [c, v] : it->second) out.emplace(c, 0.0);  // (K T)'s row e
      } else {
        out.emplace(new_gid(f), 0.0);
      }
    }
    if (out.count(ne) == 0) out[ne] = 1.0;
  }
  // The column map: J's displacement columns (renumbered, in J's order, so that a sorted
  // row of J stays sorted), then the other columns of (a), (b) and the eliminated rows.
  std::vector<GO> col_gids;
  std::vector<LO> j_col_new(n_j_cols, -1);  // J's column -> K̃'s column (kept dofs only)
  std::unordered_map<GO, LO> col_lid;
  col_gids.reserve(n_j_cols);
  col_lid.reserve(std::size_t(n_j_cols) * 2);
  for (LO c = 0; c < n_j_cols; ++c) {
    const GO g = j_cols.getGlobalElement(c);
    if (m.is_lambda(g)) continue;
    const LO l = LO(col_gids.size());
    col_gids.push_back(new_gid(g));
    col_lid.emplace(col_gids.back(), l);
    if (!is_eliminated(g)) j_col_new[c] = l;
  }
  const auto lid_of = [&](GO c) {
    const auto [it, added] = col_lid.emplace(c, LO(col_gids.size()));
    if (added) col_gids.push_back(c);
    return it->second;
  };
  const auto local = J.getLocalMatrixHost();
  const bool sorted = J.getCrsGraph()->isSorted();
  const LO n = LO(m.reduced_map->getNodeNumElements());
  std::vector<LO> j_row(n);  // K̃'s row -> J's row
  for (LO i = 0, r = 0; i < LO(row_map.getNodeNumElements()); ++i)
    if (!m.is_lambda(row_map.getGlobalElement(i))) j_row[r++] = i;
  // Room for J's entries; the contact rows' fill may grow it (CsrBuilder).
  CsrBuilder rows(n, local.values.extent(0));
  std::vector<std::pair<LO, double>> row_entries;
  for (LO i = 0; i < n; ++i) {
    const GO ng = m.reduced_map->getGlobalElement(i);
    const LO ji = j_row[i];
    const auto begin = local.graph.row_map(ji), end = local.graph.row_map(ji + 1);
    row_entries.clear();
    bool general = !sorted;
    if (const auto it = extra.find(ng); it != extra.end()) {
      for (const auto& [c, v] : it->second) row_entries.emplace_back(lid_of(c), v);
      general = true;
    } else {
      for (auto p = begin; p < end; ++p) {
        const LO c = local.graph.entries(p);
        if (j_col_new[c] >= 0) {
          row_entries.emplace_back(j_col_new[c], local.values(p));
        } else if (local.values(p) != 0.0) {
          const auto it = a_rows.find(j_cols.getGlobalElement(c));
          if (it == a_rows.end()) continue;  // a multiplier column
          for (const auto& [f, a] : it->second)
            row_entries.emplace_back(lid_of(f), local.values(p) * a);
          general = true;
        }
      }
      if (const auto it = received.find(ng); it != received.end()) {
        for (const auto& [c, v] : it->second) row_entries.emplace_back(lid_of(c), v);
        general = true;
      }
    }
    if (general) {
      // Sum the repeated columns, then drop the exact zeros (below) as of the product's.
      std::stable_sort(row_entries.begin(), row_entries.end(),
                       [](const auto& a, const auto& b) { return a.first < b.first; });
      std::size_t out = 0;
      for (std::size_t q = 0; q < row_entries.size(); ++q) {
        if (out > 0 && row_entries[out - 1].first == row_entries[q].first)
          row_entries[out - 1].second += row_entries[q].second;
        else
          row_entries[out++] = row_entries[q];
      }
      row_entries.resize(out);
    }
    const bool keep_zeros = extra.count(ng) != 0;  // the eliminated rows' pattern
    for (const auto& [c, v] : row_entries)
      if (v != 0.0 || keep_zeros) rows.append(c, v);
    rows.end_row();
  }
  const auto col_map =
      Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                           col_gids.data(), col_gids.size(), 0, comm));
  // Rows sorted and merged (J's sorted rows keep their order under j_col_new, the others were
  // sorted above), written into the views K̃ keeps (at 3e5 unknowns the earlier ArrayRCP
  // route's zero fill and second copy were a quarter of the reduction; at 1e6 a copy from
  // vectors was 0.5 GB of fresh pages a Newton iteration).
  m.A = rows.matrix(m.reduced_map, col_map, m.reduced_map, m.reduced_map);
}

bool SymmetricCondensation::condense(const Matrix& J, const Vector& b,
                                     const MultiplierRows* declared) {
  Impl& m = *impl_;
  m.declared = declared;
  const auto comm = J.getRowMap()->getComm();
  const auto& row_map = *J.getRowMap();
  const int n_pairs = int(m.lambda.size());
  m.reason.clear();
  m.stats = Statistics();
  m.handled.clear();
  m.rows.clear();
  m.A = m.T = Teuchos::null;
  m.rhs = Teuchos::null;
  m.full_map = J.getRowMap();
  std::string why;
  // The phases under --timers: "grout: linear solve: symmetric reduction: <phase>".
  std::optional<Teuchos::TimeMonitor> phase;
  const auto start = [&](const char* name) {
    phase.reset();
    phase.emplace(*Teuchos::TimeMonitor::getNewTimer(
        std::string("grout: linear solve: symmetric reduction: ") + name));
  };
  start("checks");

  // 1. The nodes this rank handles: those whose multipliers and slave dofs it owns.
  std::vector<GO> needed;
  for (const auto& [node, pairs] : m.nodes) {
    if (!row_map.isNodeGlobalElement(m.lambda[pairs.front()])) continue;
    for (int p : pairs) {
      if (!row_map.isNodeGlobalElement(m.lambda[p]) || !row_map.isNodeGlobalElement(m.slave[p]))
        why =
            "slave node " + std::to_string(node) + ": its dofs and multipliers on different ranks";
      needed.push_back(m.lambda[p]);
      needed.push_back(m.slave[p]);
    }
    m.handled.emplace_back();
    m.handled.back().pairs = pairs;
  }
  if (!(m.reason = agree(*comm, why)).empty()) return false;
  // Every handled node's rows are this rank's (checked above): read in place, no transfer.
  add_owned_rows(J, b, needed, m.rows);
  // The cheapest check first (friction and the current geometry fail it): every multiplier
  // row holds either displacements only or this node's multipliers only.
  for (const NodeData& nd : m.handled) {
    for (int p : nd.pairs) {
      bool has_u = false, has_lambda = false;
      for (GO c : m.rows.at(m.lambda[p]).cols) {
        const auto it = m.by_lambda.find(c);
        if (it == m.by_lambda.end())
          has_u = true;
        else if (std::find(nd.pairs.begin(), nd.pairs.end(), it->second) != nd.pairs.end())
          has_lambda = true;
        else
          has_u = has_lambda = true;  // another node's multiplier: fails below
      }
      if (has_u && has_lambda && why.empty())
        why = "slave node " + std::to_string(m.slave[p] / m.dofs_per_node) +
              ": a multiplier row mixes displacements and multipliers (friction or geometry: "
              "current)";
    }
  }
  if (!(m.reason = agree(*comm, why)).empty()) return false;

  // 2. Cᵀ: the multiplier columns of the displacement rows, by multiplier, on the handling
  //    rank (Tpetra's transpose of C, whose domain map is the handled multipliers).
  MultiplierColumns columns;
  {
    std::vector<GO> handled_lambda;
    for (const NodeData& nd : m.handled)
      for (int p : nd.pairs) handled_lambda.push_back(m.lambda[p]);
    const auto lambda_map =
        Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                             handled_lambda.data(), handled_lambda.size(), 0, comm));
    const auto& col_map = *J.getColMap();
    const auto local = J.getLocalMatrixHost();
    const LO n_rows = LO(row_map.getNodeNumElements());
    std::vector<std::size_t> counts(n_rows, 0);
    std::vector<std::vector<GO>> cols(n_rows);
    std::vector<std::vector<double>> vals(n_rows);
    std::vector<char> lambda_col(col_map.getNodeNumElements());
    for (LO c = 0; c < LO(lambda_col.size()); ++c)
      lambda_col[c] = m.is_lambda(col_map.getGlobalElement(c));
    for (LO i = 0; i < n_rows; ++i) {
      if (m.is_lambda(row_map.getGlobalElement(i))) continue;
      for (auto p = local.graph.row_map(i); p < local.graph.row_map(i + 1); ++p) {
        if (local.values(p) != 0.0 && lambda_col[local.graph.entries(p)])
          cols[i].push_back(col_map.getGlobalElement(local.graph.entries(p))),
              vals[i].push_back(local.values(p));
      }
      counts[i] = cols[i].size();
    }
    auto C = Teuchos::rcp(new Matrix(J.getRowMap(), Teuchos::ArrayView<const std::size_t>(counts)));
    for (LO i = 0; i < n_rows; ++i)
      if (!cols[i].empty())
        C->insertGlobalValues(row_map.getGlobalElement(i), Teuchos::ArrayView<const GO>(cols[i]),
                              Teuchos::ArrayView<const double>(vals[i]));
    C->fillComplete(lambda_map, J.getRowMap());
    const auto Ct = Tpetra::RowMatrixTransposer<double, LO, GO, Node>(C).createTranspose();
    const auto ct = Ct->getLocalMatrixHost();
    for (LO i = 0; i < LO(lambda_map->getNodeNumElements()); ++i) {
      auto& column = columns[lambda_map->getGlobalElement(i)];
      for (auto p = ct.graph.row_map(i); p < ct.graph.row_map(i + 1); ++p)
        if (ct.values(p) != 0.0)
          column.emplace_back(Ct->getColMap()->getGlobalElement(ct.graph.entries(p)), ct.values(p));
    }
  }

  // 3. Per handled node: the λ-rows' structure, the eliminated slave dofs, T's rows, C N ∝ Gᵀ
  //    and the recovery of λ (reduce_node).
  for (NodeData& nd : m.handled)
    if (!(why = m.reduce_node(nd, columns)).empty()) break;
  if (!(m.reason = agree(*comm, why)).empty()) return false;

  // 4. The eliminated dofs (replicated); none may occur in another node's constraint.
  std::vector<GO> eliminated;
  {
    std::vector<long long> local(std::size_t(n_pairs), -1), global(local.size(), -1);
    for (const NodeData& nd : m.handled)
      for (GO e : nd.eliminated) local[m.by_slave.at(e)] = e;
    if (n_pairs > 0)
      Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, n_pairs, local.data(), global.data());
    for (long long e : global)
      if (e >= 0) eliminated.push_back(e);
    std::sort(eliminated.begin(), eliminated.end());
    for (const NodeData& nd : m.handled)
      for (const auto& t_row : nd.t_rows)
        for (const auto& [col, v] : t_row)
          if (std::binary_search(eliminated.begin(), eliminated.end(), col) && why.empty())
            why = "dof " + std::to_string(col) +
                  " is eliminated by one slave node and constrained by another";
  }
  if (!(m.reason = agree(*comm, why)).empty()) return false;

  // 5. K symmetric.
  start("symmetry");
  if (!(m.reason = agree(*comm, check_symmetric(J, m.by_lambda))).empty()) return false;

  start("maps and T");
  // 6. The reduced map: J's GIDs that are no paired multiplier, renumbered new = old − (the
  //    multipliers below old). An eliminated dof keeps its row, as ũ_e = 0 (K̃_ee = K_ee, b̃_e
  //    = 0): the reduced system has the same size and mostly the same pattern whatever the
  //    active set, so that MUMPS keeps its analysis from one Newton iteration to the next.
  std::vector<GO> skipped = m.lambda;
  std::sort(skipped.begin(), skipped.end());
  const auto new_gid = [&](GO g) {
    return g - GO(std::lower_bound(skipped.begin(), skipped.end(), g) - skipped.begin());
  };
  std::vector<GO> reduced;
  for (LO i = 0; i < LO(row_map.getNodeNumElements()); ++i) {
    const GO g = row_map.getGlobalElement(i);
    if (!std::binary_search(skipped.begin(), skipped.end(), g)) reduced.push_back(new_gid(g));
  }
  m.reduced_map = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                       reduced.data(), reduced.size(), 0, comm));

  // 7. T (J's row map × reduced map): 1 on the kept dofs, A_ef on the eliminated ones; zero
  //    multiplier rows and eliminated columns. K̃ = Tᵀ J T = Tᵀ K T, plus K_ee on the
  //    eliminated rows, and the pattern they would have if kept as zeros (below).
  std::unordered_map<GO, const std::map<GO, double>*> t_row_of;
  for (const NodeData& nd : m.handled)
    for (int l = 0; l < nd.k; ++l) t_row_of[nd.eliminated[l]] = &nd.t_rows[l];
  {
    const LO n_rows = LO(row_map.getNodeNumElements());
    std::vector<std::size_t> counts(n_rows, 0);
    for (LO i = 0; i < n_rows; ++i) {
      const GO g = row_map.getGlobalElement(i);
      if (const auto it = t_row_of.find(g); it != t_row_of.end())
        counts[i] = it->second->size();
      else if (!m.is_lambda(g))
        counts[i] = 1;
    }
    m.T = Teuchos::rcp(new Matrix(J.getRowMap(), Teuchos::ArrayView<const std::size_t>(counts)));
    std::vector<GO> cols;
    std::vector<double> vals;
    for (LO i = 0; i < n_rows; ++i) {
      const GO g = row_map.getGlobalElement(i);
      cols.clear(), vals.clear();
      if (const auto it = t_row_of.find(g); it != t_row_of.end()) {
        for (const auto& [f, v] : *it->second) cols.push_back(new_gid(f)), vals.push_back(v);
      } else if (!m.is_lambda(g)) {
        cols.push_back(new_gid(g)), vals.push_back(1.0);
      }
      if (!cols.empty())
        m.T->insertGlobalValues(g, Teuchos::ArrayView<const GO>(cols),
                                Teuchos::ArrayView<const double>(vals));
    }
    m.T->fillComplete(m.reduced_map, J.getRowMap());
  }
  start("reduced matrix");
  m.build_reduced_matrix(J, skipped, eliminated, t_row_of);
  start("right-hand side and recovery");

  // 8. b̃ = Tᵀ (b − J w), w = c on the eliminated dofs and λ0 on the multipliers.
  {
    Vector w(J.getRowMap()), r(J.getRowMap());
    {
      auto wv = w.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (LO i = 0; i < LO(row_map.getNodeNumElements()); ++i) wv(i, 0) = 0.0;
      for (const NodeData& nd : m.handled) {
        for (int c = 0; c < int(nd.pairs.size()); ++c)
          wv(row_map.getLocalElement(m.lambda[nd.pairs[c]]), 0) = nd.lambda0[c];
        for (int l = 0; l < nd.k; ++l) wv(row_map.getLocalElement(nd.eliminated[l]), 0) = nd.c[l];
      }
    }
    J.apply(w, r);
    r.update(1.0, b, -1.0);
    m.rhs = Teuchos::rcp(new Vector(m.reduced_map));
    m.T->apply(r, *m.rhs, Teuchos::TRANS);
  }

  // 9. For expand(): the displacement columns of the recovery rows.
  {
    std::vector<GO> cols;
    for (const NodeData& nd : m.handled)
      for (GO s : nd.recovery_rows)
        for (GO c : m.rows.at(s).cols)
          if (!m.is_lambda(c)) cols.push_back(c);
    std::sort(cols.begin(), cols.end());
    cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
    m.needed_map = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                        cols.data(), cols.size(), 0, comm));
    m.needed_import = Teuchos::rcp(new Import(J.getRowMap(), m.needed_map));
  }
  int counts[2] = {0, 0}, counts_all[2] = {0, 0};
  counts[0] = int(m.handled.size());
  for (const NodeData& nd : m.handled) counts[1] += nd.k;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 2, counts, counts_all);
  m.stats.nodes = counts_all[0];
  m.stats.eliminated = counts_all[1];
  return true;
}

void SymmetricCondensation::expand(const Vector& y, Vector& x) const {
  const Impl& m = *impl_;
  const auto& row_map = *m.full_map;
  // u = T y + c; the multiplier entries are 0 until recovered below.
  m.T->apply(y, x);
  {
    auto xv = x.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (const NodeData& nd : m.handled)
      for (int l = 0; l < nd.k; ++l) xv(row_map.getLocalElement(nd.eliminated[l]), 0) += nd.c[l];
  }
  Vector u_needed(m.needed_map);
  u_needed.doImport(x, *m.needed_import, Tpetra::INSERT);
  const auto un = u_needed.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto xv = x.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (const NodeData& nd : m.handled) {
    const int d = int(nd.pairs.size()), k = nd.k;
    std::vector<double> lambda = nd.lambda0;
    if (k > 0) {
      // (C_s N) μ = b_s − K_s u − C_s λ0 on the recovery rows.
      std::vector<double> rhs(k, 0.0);
      for (int i = 0; i < k; ++i) {
        const Row& srow = m.rows.at(nd.recovery_rows[i]);
        double v = srow.rhs;
        for (std::size_t e = 0; e < srow.cols.size(); ++e)
          if (!m.is_lambda(srow.cols[e]))
            v -= srow.vals[e] * un(m.needed_map->getLocalElement(srow.cols[e]), 0);
        for (int c = 0; c < d; ++c) v -= nd.recovery_c[i][c] * nd.lambda0[c];
        rhs[i] = v;
      }
      for (int f = 0; f < k; ++f) {
        double mu = 0.0;
        for (int i = 0; i < k; ++i) mu += nd.recovery_inverse[f * k + i] * rhs[i];
        for (int c = 0; c < d; ++c) lambda[c] += nd.N[c * k + f] * mu;
      }
    }
    for (int c = 0; c < d; ++c) xv(row_map.getLocalElement(m.lambda[nd.pairs[c]]), 0) = lambda[c];
  }
}

}  // namespace grout
