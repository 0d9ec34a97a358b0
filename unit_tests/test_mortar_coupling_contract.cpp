// grout::MortarCoupling, what a host relies on beyond the values (docs/embedding.md): the
// coverage flag of partly covered slave rows, the lifetime of the results across update(), the
// index spaces and their accessors, the forces summed to the owners of the nodes, and the
// orientation checks. Runs on 1 and 2 ranks (each rank passes a slice of the faces).

#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>

#include "grout/mortar_coupling.hpp"

namespace grout {
namespace {

/// Two flat surfaces: a slave of n LINE2 on y = 0, x ∈ [0, 1] (2D), or n × n QUAD4 on z = 0 over
/// [0, 1]² (3D), normal +y / +z; a master of m LINE2 / m × m TRI3 at height delta over
/// x ∈ [a, b] (and y ∈ [−0.5, 1.5]), normal −y / −z. Ids: slave rows, then master rows.
struct Flat {
  int dim = 2, cols_s = 2, cols_m = 2;
  std::vector<double> xs, xm;
  std::vector<int> fs, fm;
  std::vector<long long> ids_s, ids_m;
  std::size_t ns() const { return xs.size() / dim; }
  std::size_t nm() const { return xm.size() / dim; }
};

Flat flat(int dim, int n, int m, double a, double b, double delta) {
  Flat s;
  s.dim = dim;
  if (dim == 2) {
    // LINE2 x₁ → x₂ has the normal (dy, −dx)/L: the slave's faces run right to left (+y),
    // the master's left to right (−y).
    for (int i = 0; i <= n; ++i) {
      s.xs.insert(s.xs.end(), {double(i) / n, 0.0});
      if (i < n) s.fs.insert(s.fs.end(), {i + 1, i});
    }
    for (int i = 0; i <= m; ++i) {
      s.xm.insert(s.xm.end(), {a + (b - a) * i / m, delta});
      if (i < m) s.fm.insert(s.fm.end(), {i, i + 1});
    }
  } else {
    s.cols_s = 4, s.cols_m = 3;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) s.xs.insert(s.xs.end(), {double(i) / n, double(j) / n, 0.0});
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int c = j * (n + 1) + i;
        s.fs.insert(s.fs.end(), {c, c + 1, c + n + 2, c + n + 1});
      }
    for (int j = 0; j <= m; ++j)
      for (int i = 0; i <= m; ++i)
        s.xm.insert(s.xm.end(), {a + (b - a) * i / m, -0.5 + 2.0 * j / m, delta});
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const int c = j * (m + 1) + i;
        s.fm.insert(s.fm.end(), {c, c + m + 1, c + 1, c + 1, c + m + 1, c + m + 2});  // clockwise
      }
  }
  for (std::size_t i = 0; i < s.ns(); ++i) s.ids_s.push_back((long long)i);
  for (std::size_t i = 0; i < s.nm(); ++i) s.ids_m.push_back((long long)(s.ns() + i));
  return s;
}

int ranks(int* rank = nullptr) {
  int r = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (rank) *rank = r;
  return size;
}

/// This rank's slice of the faces (every coordinate row on every rank).
std::vector<int> slice(const std::vector<int>& faces, int cols) {
  int rank = 0;
  const int size = ranks(&rank);
  const std::size_t n = faces.size() / cols, f0 = n * rank / size, f1 = n * (rank + 1) / size;
  return {faces.begin() + f0 * cols, faces.begin() + f1 * cols};
}

MortarCoupling couple(const Flat& s, MortarCouplingOptions o = {}, bool distributed = true,
                      const std::vector<double>& inside_s = {},
                      const std::vector<double>& inside_m = {}) {
  static std::vector<int> fs, fm;
  fs = distributed ? slice(s.fs, s.cols_s) : s.fs;
  fm = distributed ? slice(s.fm, s.cols_m) : s.fm;
  SurfaceArrays a = surface_arrays(s.cols_s, fs, s.xs, s.dim, s.ids_s);
  SurfaceArrays b = surface_arrays(s.cols_m, fm, s.xm, s.dim, s.ids_m);
  a.inside_points = inside_s.empty() ? nullptr : inside_s.data();
  b.inside_points = inside_m.empty() ? nullptr : inside_m.data();
  return MortarCoupling(s.dim, a, b, o, distributed ? MPI_COMM_WORLD : MPI_COMM_NULL);
}

/// Per slave node id, the sum over the ranks of a per-row value.
std::vector<double> summed(const MortarCoupling& c, const std::vector<double>& v) {
  std::vector<double> total(c.num_slave_nodes(), 0.0);
  for (std::size_t r = 0; r < c.num_slave_nodes(); ++r) total[c.slave_id(r)] += v[r];
  MPI_Allreduce(MPI_IN_PLACE, total.data(), int(total.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  return total;
}

// 2D: slave [0, 1] in 10 segments (h = 0.1), master over [−0.5, 0.55] at δ = 1e-3 (7 segments).
// Dual basis of a LINE2 face: Φ₁ = 2 − 3ξ', Φ₂ = 3ξ' − 1 (ξ' ∈ [0, 1] from node 1). Node 0.5:
// its left face is covered, its right face [0.5, 0.6] on ξ' ∈ [0, 0.5]: D = h/2 + h ∫₀^½ (2 − 3t)
// dt = h/2 + 5h/8 = 9h/8 (≠ w = h: partial). Node 0.6: D = h ∫₀^½ (3t − 1) dt = −h/8 < 0, a
// false penetration g̃ = −n·(D x¹ − Σ M x²) ≠ δ D: the driver's "no master" (uncovered).
TEST(MortarCouplingContract, RowStatusFlagsPartlyCoveredRows) {
  const double h = 0.1, delta = 1e-3;
  const Flat s = flat(2, 10, 7, -0.5, 0.55, delta);
  for (bool derivatives : {false, true})
    for (auto basis : {MultiplierBasis::dual, MultiplierBasis::standard}) {
      if (derivatives && basis == MultiplierBasis::standard) continue;
      MortarCouplingOptions o;
      o.multipliers = basis;
      o.derivatives = derivatives;
      const MortarCoupling c = couple(s, o);
      const std::string what = std::string(derivatives ? "derivatives, " : "values, ") +
                               (basis == MultiplierBasis::dual ? "dual" : "standard");
      std::vector<double> c_row(c.num_slave_nodes(), 0.0);  // D_jj or Σ_k D_jk
      for (std::size_t r = 0; r < c.num_slave_nodes(); ++r)
        for (std::size_t k = c.D_offsets()[r]; k < c.D_offsets()[r + 1]; ++k)
          c_row[r] += c.D_values()[k];
      const std::vector<double> D = summed(c, c_row), g = summed(c, c.weighted_gaps());
      for (std::size_t r = 0; r < c.num_slave_nodes(); ++r) {
        const long long id = c.slave_id(r);
        const double x = id * h;
        const RowStatus expected = x < 0.45   ? RowStatus::full
                                   : x < 0.55 ? RowStatus::partial
                                   : x < 0.65 && basis == MultiplierBasis::standard
                                       ? RowStatus::partial  // Σ_k D_jk = ∫_cov N_j = h/8
                                       : RowStatus::uncovered;
        EXPECT_EQ(int(c.row_status()[r]), int(expected)) << what << ", node x = " << x;
        if (c.row_status()[r] == RowStatus::full) {  // a full row measures the gap exactly
          EXPECT_NEAR(g[id] / D[id], delta, 1e-13) << what << ", node x = " << x;
          EXPECT_NEAR(D[id], id == 0 ? h / 2 : h, 1e-15) << what << ", node x = " << x;
        }
      }
      if (basis == MultiplierBasis::dual) {  // the hand integrals of the two boundary nodes
        EXPECT_NEAR(D[5], 9 * h / 8, 1e-15) << what;
        EXPECT_NEAR(D[6], -h / 8, 1e-15) << what;
        EXPECT_LT(g[6], 0.0) << what << ": the false penetration the flag reports";
      }
    }
}

// 3D: slave [0, 1]² in 4 × 4 QUAD4, master over x ∈ [−0.5, 0.6]: every row whose D_jj ≤ 0 or
// whose nodal gap is not δ is flagged, nodes with x ≤ 0.25 are full, x = 1 uncovered.
TEST(MortarCouplingContract, RowStatusFlagsNegativeD3D) {
  const double delta = 1e-3;
  const Flat s = flat(3, 4, 11, -0.5, 0.6, delta);
  const MortarCoupling c = couple(s);
  const std::vector<double> D = summed(c, c.D()), g = summed(c, c.weighted_gaps());
  int negative = 0;
  for (std::size_t r = 0; r < c.num_slave_nodes(); ++r) {
    const long long id = c.slave_id(r);
    const double x = s.xs[id * 3];
    const RowStatus status = c.row_status()[r];
    negative += D[id] < 0.0;
    if (D[id] <= 0.0 || std::abs(g[id] / D[id] - delta) > 1e-12) {
      EXPECT_NE(int(status), int(RowStatus::full)) << "node " << id << ", D = " << D[id];
    }
    if (x < 0.3) {
      EXPECT_EQ(int(status), int(RowStatus::full)) << "node " << id;
    }
    if (x > 0.99) {
      EXPECT_EQ(int(status), int(RowStatus::uncovered)) << "node " << id;
    }
    if (std::abs(x - 0.5) < 1e-12) {
      EXPECT_NE(int(status), int(RowStatus::full)) << "node " << id;
    }
  }
  EXPECT_GT(negative, 0) << "the case should have negative D (dual basis, partly covered)";
}

TEST(MortarCouplingContract, ResultsAreOverwrittenByUpdate) {
  for (int dim : {2, 3}) {
    Flat s = flat(dim, 4, 5, -0.5, 1.5, 1e-3);
    MortarCoupling c = couple(s);
    const std::vector<double>& g = c.weighted_gaps();
    const std::vector<double>& D = c.D();
    const double* g_data = g.data();
    const std::vector<double> kept = g;                                        // the host's copy
    for (std::size_t i = 0; i < s.nm(); ++i) s.xm[i * dim + dim - 1] += 2e-3;  // δ: 1e-3 → 3e-3
    c.update(s.xs, s.xm);
    EXPECT_EQ(&g, &c.weighted_gaps()) << "the same vector for the coupling's life";
    EXPECT_EQ(g_data, g.data()) << "per-row arrays keep their storage";
    for (std::size_t r = 0; r < g.size(); ++r) {
      EXPECT_NEAR(g[r], 3e-3 * D[r], 1e-15) << "overwritten with the new gap, row " << r;
      EXPECT_NEAR(kept[r], 1e-3 * D[r], 1e-15) << "the copy keeps the old one, row " << r;
    }
  }
}

TEST(MortarCouplingContract, IndexAccessorsTranslate) {
  for (int dim : {2, 3}) {
    const Flat s = flat(dim, 3, 4, -0.5, 1.5, 1e-3);
    MortarCouplingOptions o;
    o.derivatives = true;
    const MortarCoupling c = couple(s, o);
    for (std::size_t r = 0; r < c.num_slave_nodes(); ++r) {
      EXPECT_EQ(c.slave_id(r), s.ids_s[r]);
      EXPECT_EQ(c.slave_row(c.slave_id(r)), (long long)r);
    }
    EXPECT_EQ(c.slave_row(s.ids_m[0]), -1) << "a master id is no slave row";
    std::map<std::pair<long long, long long>, double> M;  // (slave row, master id) → M
    for (std::size_t k = 0; k < c.M_values().size(); ++k) {
      const MEntry e = c.M_entry(k);
      EXPECT_GE(k, c.M_offsets()[e.row]);
      EXPECT_LT(k, c.M_offsets()[e.row + 1]);
      EXPECT_EQ(e.master_node, c.M_columns()[k]);
      M[{(long long)e.row, e.master_node}] = c.M_values()[k];
    }
    // ∂g̃_j/∂x²_l = n_j M_jl at a master node l (the normals depend on the slave only): the
    // gap derivative's columns decoded by dof(), the M entries found by M_entry().
    int master_columns = 0;
    for (const DerivativeTriplet& t : c.gap_derivatives()) {
      const Dof d = c.dof(t.column);
      EXPECT_EQ(d.node * dim + d.component, t.column);
      if (d.node < (long long)s.ns()) continue;
      ++master_columns;
      const auto it = M.find({t.row, d.node});
      ASSERT_NE(it, M.end()) << "row " << t.row << ", master node " << d.node;
      EXPECT_NEAR(t.value, c.normals()[t.row * dim + d.component] * it->second, 1e-15);
    }
    EXPECT_GT(master_columns, 0);
    for (const DerivativeTriplet& t : c.M_derivatives())  // rows: positions in M_values
      EXPECT_LT(std::size_t(t.row), c.M_values().size());
  }
}

TEST(MortarCouplingContract, ForcesSummedToOwnersEqualOneRank) {
  int rank = 0;
  const int size = ranks(&rank);
  for (int dim : {2, 3}) {
    const Flat s = flat(dim, 5, 7, -0.3, 1.2, 1e-3);
    const MortarCoupling c = couple(s), serial = couple(s, {}, false);
    std::vector<double> lambda(s.ns() * dim);
    for (std::size_t i = 0; i < lambda.size(); ++i) lambda[i] = 1.0 + 0.1 * std::sin(double(i));
    const ContactForces f = c.contact_forces(lambda, ForceSum::owners);
    const ContactForces one = serial.contact_forces(lambda);
    // Owners: the lowest rank passing a node; here every rank passes every row: rank 0.
    if (rank != 0) {
      EXPECT_TRUE(f.master_nodes.empty());
      for (double v : f.slave) EXPECT_EQ(v, 0.0);
      continue;
    }
    ASSERT_EQ(f.master_nodes, one.master_nodes) << dim << "D on " << size << " ranks";
    for (std::size_t i = 0; i < f.master.size(); ++i)
      EXPECT_NEAR(f.master[i], one.master[i], 1e-15) << dim << "D, master entry " << i;
    for (std::size_t i = 0; i < f.slave.size(); ++i)
      EXPECT_NEAR(f.slave[i], one.slave[i], 1e-15) << dim << "D, slave entry " << i;
  }
}

/// A surface with the node order of every face reversed (normals into the body).
std::vector<int> reversed(const std::vector<int>& faces, int cols) {
  std::vector<int> r = faces;
  for (std::size_t f = 0; f < faces.size() / cols; ++f)
    std::reverse(r.begin() + f * cols, r.begin() + (f + 1) * cols);
  return r;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const MortarCouplingError& e) {
    return e.what();
  }
  return "";
}

TEST(MortarCouplingContract, FlippedSurfaceIsReported) {
  for (int dim : {2, 3})
    for (bool derivatives : {false, true}) {
      Flat s = flat(dim, 4, 5, -0.5, 1.5, 1e-3);
      MortarCouplingOptions o;
      o.derivatives = derivatives;
      EXPECT_EQ(error_of([&] { couple(s, o); }), "");
      Flat flipped = s;
      flipped.fs = reversed(s.fs, s.cols_s);
      const std::string e = error_of([&] { couple(flipped, o); });
      EXPECT_NE(e.find("face the same way"), std::string::npos) << e;
      // With inside points (below the slave, above the master) the surface is named.
      std::vector<double> below(s.fs.size() / s.cols_s * dim, 0.0),
          above(s.fm.size() / s.cols_m * dim);
      for (std::size_t f = 0; f < below.size() / dim; ++f) below[f * dim + dim - 1] = -1.0;
      for (std::size_t f = 0; f < above.size() / dim; ++f) above[f * dim + dim - 1] = 1.0;
      // (inside points are per face of the SurfaceArrays: this rank's slice)
      const auto mine = [&](const std::vector<double>& p, std::size_t n_faces) {
        int rank = 0;
        const int size = ranks(&rank);
        const std::size_t f0 = n_faces * rank / size, f1 = n_faces * (rank + 1) / size;
        return std::vector<double>(p.begin() + f0 * dim, p.begin() + f1 * dim);
      };
      const std::size_t n_s = s.fs.size() / s.cols_s, n_m = s.fm.size() / s.cols_m;
      EXPECT_EQ(error_of([&] { couple(s, o, true, mine(below, n_s), mine(above, n_m)); }), "");
      const std::string named =
          error_of([&] { couple(flipped, o, true, mine(below, n_s), mine(above, n_m)); });
      EXPECT_NE(named.find("slave surface: face"), std::string::npos) << named;
      EXPECT_NE(named.find("into its body"), std::string::npos) << named;
      Flat master_flipped = s;
      master_flipped.fm = reversed(s.fm, s.cols_m);
      const std::string m =
          error_of([&] { couple(master_flipped, o, true, mine(below, n_s), mine(above, n_m)); });
      EXPECT_NE(m.find("master surface: face"), std::string::npos) << m;
    }
}

}  // namespace
}  // namespace grout
