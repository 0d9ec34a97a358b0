// grout::MortarCoupling (api/), the embedding API: Σ D = slave measure, the weighted gap of a
// known offset, force balance for any multiplier field, exact derivatives against central
// differences, the two evaluation paths against each other, the distributed evaluation
// against the serial one (on 2 ranks), repeated updates against new couplings, and the errors.

#include <gtest/gtest.h>
#include <mpi.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>

#include "grout/mortar_coupling.hpp"

namespace grout {
namespace {

constexpr double pi = 3.14159265358979323846;

/// Two surfaces as plain arrays, ids: slave rows 0 … n_s − 1, master rows n_s … .
struct Surfaces {
  int dim = 2, cols_s = 2, cols_m = 2;
  std::vector<double> xs, xm;
  std::vector<int> fs, fm;
  std::vector<long long> ids_s, ids_m;
  double slave_measure = 0.0;
  std::size_t ns() const { return xs.size() / dim; }
  std::size_t nm() const { return xm.size() / dim; }
};

void number(Surfaces& s) {
  s.ids_s.resize(s.ns());
  s.ids_m.resize(s.nm());
  for (std::size_t i = 0; i < s.ns(); ++i) s.ids_s[i] = (long long)i;
  for (std::size_t i = 0; i < s.nm(); ++i) s.ids_m[i] = (long long)(s.ns() + i);
}

/// 2D: slave arc of radius R (n segments, counter-clockwise: normal outward), master arc of
/// radius R + delta over a wider angle (m segments, clockwise: normal inward).
Surfaces arcs_2d(int n, int m, double R, double delta) {
  Surfaces s;
  const double t0 = 0.2, t1 = 1.2, pad = 0.05;
  for (int i = 0; i <= n; ++i) {
    const double t = t0 + (t1 - t0) * i / n;
    s.xs.insert(s.xs.end(), {R * std::cos(t), R * std::sin(t)});
    if (i < n) s.fs.insert(s.fs.end(), {i, i + 1});
  }
  for (int i = 0; i <= m; ++i) {
    const double t = t1 + pad - (t1 - t0 + 2 * pad) * i / m;
    s.xm.insert(s.xm.end(), {(R + delta) * std::cos(t), (R + delta) * std::sin(t)});
    if (i < m) s.fm.insert(s.fm.end(), {i, i + 1});
  }
  s.slave_measure = n * 2.0 * R * std::sin(0.5 * (t1 - t0) / n);
  number(s);
  return s;
}

/// 3D: slave QUAD4 faces on a cylinder of radius R (axis z, n × n, normal outward), master
/// TRI3 faces on radius R + delta over a wider patch (m × m cells cut in two, normal inward).
Surfaces cylinders_3d(int n, int m, double R, double delta) {
  Surfaces s;
  s.dim = 3;
  s.cols_s = 4;
  s.cols_m = 3;
  const double t0 = 0.2, t1 = 1.0, L = 0.8, pad = 0.05;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double t = t0 + (t1 - t0) * i / n;
      s.xs.insert(s.xs.end(), {R * std::cos(t), R * std::sin(t), L * j / n});
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      s.fs.insert(s.fs.end(), {a, a + 1, a + n + 2, a + n + 1});
    }
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) {
      const double t = t0 - pad + (t1 - t0 + 2 * pad) * i / m;
      s.xm.insert(s.xm.end(), {(R + delta) * std::cos(t), (R + delta) * std::sin(t),
                               -pad + (L + 2 * pad) * j / m});
    }
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const int a = j * (m + 1) + i, b = a + 1, c = a + m + 2, d = a + m + 1;
      s.fm.insert(s.fm.end(), {a, d, b});  // clockwise seen from outside
      s.fm.insert(s.fm.end(), {b, d, c});
    }
  s.slave_measure = n * 2.0 * R * std::sin(0.5 * (t1 - t0) / n) * L;
  number(s);
  return s;
}

/// The faces of rank r of p: [n r/p, n (r+1)/p) of each surface; every coordinate row.
std::vector<int> my_faces(const std::vector<int>& faces, int cols, int rank, int size) {
  const std::size_t n = faces.size() / cols;
  const std::size_t f0 = n * rank / size, f1 = n * (rank + 1) / size;
  return {faces.begin() + f0 * cols, faces.begin() + f1 * cols};
}

MortarCoupling couple(const Surfaces& s, MortarCouplingOptions o = {},
                      MPI_Comm comm = MPI_COMM_NULL) {
  int rank = 0, size = 1;
  if (comm != MPI_COMM_NULL) MPI_Comm_rank(comm, &rank), MPI_Comm_size(comm, &size);
  static thread_local std::vector<int> fs, fm;  // must outlive the constructor call only
  fs = my_faces(s.fs, s.cols_s, rank, size);
  fm = my_faces(s.fm, s.cols_m, rank, size);
  return MortarCoupling(s.dim, surface_arrays(s.cols_s, fs, s.xs, s.dim, s.ids_s),
                        surface_arrays(s.cols_m, fm, s.xm, s.dim, s.ids_m), o, comm);
}

double sum_over_ranks(double v, MPI_Comm comm) {
  if (comm == MPI_COMM_NULL) return v;
  double sum = 0.0;
  MPI_Allreduce(&v, &sum, 1, MPI_DOUBLE, MPI_SUM, comm);
  return sum;
}

std::vector<Surfaces> cases() {
  return {arcs_2d(12, 17, 1.0, 0.01), cylinders_3d(6, 8, 1.0, 0.01)};
}

TEST(MortarCoupling, SumOfDEqualsSlaveMeasure) {
  for (MPI_Comm comm : {MPI_COMM_NULL, MPI_COMM_WORLD})
    for (const Surfaces& s : cases())
      for (bool derivatives : {false, true}) {
        MortarCouplingOptions o;
        o.derivatives = derivatives;
        const MortarCoupling c = couple(s, o, comm);
        double sum = 0.0;
        for (double d : c.D()) sum += d;
        EXPECT_NEAR(sum_over_ranks(sum, comm), s.slave_measure, 1e-12)
            << s.dim << "D, derivatives " << derivatives;
      }
}

/// The arcs/cylinders unrolled onto a flat inclined plane, (r, θ, z) → θ τ₁ + z τ₂ + (r − 1) n:
/// the slave is a grid of Δθ (× Δz) segments (rectangles), the master the slave plane moved by
/// delta along the slave normal n, over a wider patch.
constexpr double flat_t1[3] = {0.8, 0.6, 0.0}, flat_t2[3] = {-0.36, 0.48, 0.8};
std::array<double, 3> flat_normal(int dim) {
  return {dim == 2 ? 0.6 : 0.48, dim == 2 ? -0.8 : -0.64, dim == 2 ? 0.0 : 0.6};
}
Surfaces flat(int dim, double delta, int n = 0, int m = 0) {
  Surfaces s = dim == 2 ? arcs_2d(n ? n : 8, m ? m : 11, 1.0, delta)
                        : cylinders_3d(n ? n : 4, m ? m : 6, 1.0, delta);
  const std::array<double, 3> normal = flat_normal(dim);
  for (auto* x : {&s.xs, &s.xm})
    for (std::size_t i = 0; i < x->size() / dim; ++i) {
      double* p = &(*x)[i * dim];
      const double r = std::hypot(p[0], p[1]), theta = std::atan2(p[1], p[0]);
      const double z = dim == 3 ? p[2] : 0.0;
      for (int d = 0; d < dim; ++d)
        p[d] = theta * flat_t1[d] + z * flat_t2[d] + (r - 1.0) * normal[d];
    }
  s.slave_measure = dim == 2 ? 1.0 : 0.8 * 0.8;  // Δθ = 1 (2D); 0.8 × 0.8 (3D)
  return s;
}

TEST(MortarCoupling, WeightedGapOfKnownOffset) {
  // g̃_j = −n·(D_jj x_j − Σ_l M_jl x_l) = delta Σ_l M_jl = delta D_jj exactly.
  const double delta = 0.003;
  for (int dim : {2, 3}) {
    const Surfaces s = flat(dim, delta);
    const std::array<double, 3> n = flat_normal(dim);
    for (bool derivatives : {false, true}) {
      MortarCouplingOptions o;
      o.derivatives = derivatives;
      const MortarCoupling c = couple(s, o);
      for (std::size_t j = 0; j < c.num_slave_nodes(); ++j) {
        EXPECT_NEAR(c.weighted_gaps()[j], delta * c.D()[j], 1e-14) << dim << "D node " << j;
        double nn = 0.0;
        for (int d = 0; d < dim; ++d) nn += c.normals()[j * dim + d] * n[d];
        EXPECT_NEAR(std::abs(nn), 1.0, 1e-12);
      }
    }
  }
}

TEST(MortarCoupling, ForcesBalanceForAnyMultiplier) {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (MPI_Comm comm : {MPI_COMM_NULL, MPI_COMM_WORLD})
    for (const Surfaces& s : cases())
      for (auto scheme : {MortarIntegration::exact, MortarIntegration::collocation})
        for (auto basis : {MultiplierBasis::dual, MultiplierBasis::standard}) {
          MortarCouplingOptions o;
          o.integration = scheme;
          o.multipliers = basis;
          const MortarCoupling c = couple(s, o, comm);
          std::vector<double> lambda(c.num_slave_nodes() * s.dim);
          for (double& l : lambda) l = u(rng);
          const ContactForces f = c.contact_forces(lambda);
          for (int d = 0; d < s.dim; ++d) {
            double total = 0.0, scale = 0.0;
            for (std::size_t j = 0; j < f.slave.size() / s.dim; ++j)
              total += f.slave[j * s.dim + d], scale += std::abs(f.slave[j * s.dim + d]);
            for (std::size_t l = 0; l < f.master_nodes.size(); ++l)
              total += f.master[l * s.dim + d];
            EXPECT_NEAR(sum_over_ranks(total, comm), 0.0, 1e-13 * (1.0 + scale));
          }
        }
}

// The values-only path (kernel launches) and the derivative path (evaluate_contact_mortar).
TEST(MortarCoupling, BothPathsAgree) {
  for (const Surfaces& s : cases()) {
    MortarCouplingOptions o;
    const MortarCoupling a = couple(s, o);
    o.derivatives = true;
    const MortarCoupling b = couple(s, o);
    ASSERT_EQ(a.M_offsets(), b.M_offsets());
    ASSERT_EQ(a.M_columns(), b.M_columns());
    EXPECT_EQ(a.overlapping_pairs(), b.overlapping_pairs());
    for (std::size_t j = 0; j < a.num_slave_nodes(); ++j) {
      EXPECT_NEAR(a.D()[j], b.D()[j], 1e-13);
      EXPECT_NEAR(a.weighted_gaps()[j], b.weighted_gaps()[j], 1e-14);
    }
    for (std::size_t k = 0; k < a.M_values().size(); ++k)
      EXPECT_NEAR(a.M_values()[k], b.M_values()[k], 1e-13);
    for (std::size_t k = 0; k < a.normals().size(); ++k)
      EXPECT_NEAR(a.normals()[k], b.normals()[k], 1e-14);
    for (std::size_t k = 0; k < a.tangents().size(); ++k)
      EXPECT_NEAR(a.tangents()[k], b.tangents()[k], 1e-14);
  }
}

// A distributed evaluation sums (over the ranks) to the serial one; normals agree everywhere.
TEST(MortarCoupling, DistributedEqualsSerial) {
  for (const Surfaces& s : cases()) {
    const MortarCoupling serial = couple(s);
    const MortarCoupling dist = couple(s, {}, MPI_COMM_WORLD);
    for (std::size_t j = 0; j < serial.num_slave_nodes(); ++j) {
      EXPECT_NEAR(sum_over_ranks(dist.D()[j], MPI_COMM_WORLD), serial.D()[j], 1e-14);
      EXPECT_NEAR(sum_over_ranks(dist.weighted_gaps()[j], MPI_COMM_WORLD),
                  serial.weighted_gaps()[j], 1e-15);
      if (dist.D()[j] != 0.0) {
        for (int d = 0; d < s.dim; ++d)
          EXPECT_NEAR(dist.normals()[j * s.dim + d], serial.normals()[j * s.dim + d], 1e-15);
      }
    }
  }
}

// Dense matrix (rows × (n_nodes · dim)) of one quantity's triplets.
using Dense = std::map<std::pair<int, long long>, double>;

TEST(MortarCoupling, DerivativesMatchCentralDifferences) {
  for (Surfaces s : {arcs_2d(4, 5, 1.0, 0.02), cylinders_3d(2, 3, 1.0, 0.02)}) {
    MortarCouplingOptions o;
    o.derivatives = true;
    MortarCoupling c = couple(s, o);
    Dense dD, dM, dg;
    for (const auto& t : c.D_derivatives()) dD[{t.row, t.column}] += t.value;
    for (const auto& t : c.M_derivatives()) dM[{t.row, t.column}] += t.value;
    for (const auto& t : c.gap_derivatives()) dg[{t.row, t.column}] += t.value;
    ASSERT_FALSE(dD.empty() || dM.empty() || dg.empty());
    const std::vector<std::size_t> offsets = c.M_offsets();
    const std::vector<long long> columns = c.M_columns();
    const double h = 1e-6;
    double worst = 0.0;
    const std::size_t n_nodes = s.ns() + s.nm();
    for (std::size_t node = 0; node < n_nodes; ++node)
      for (int d = 0; d < s.dim; ++d) {
        const long long column = (long long)node * s.dim + d;
        double& x = node < s.ns() ? s.xs[node * s.dim + d] : s.xm[(node - s.ns()) * s.dim + d];
        const double x0 = x;
        x = x0 + h;
        c.update(s.xs, s.xm);
        const std::vector<double> Dp = c.D(), Mp = c.M_values(), gp = c.weighted_gaps();
        ASSERT_EQ(c.M_columns(), columns);
        x = x0 - h;
        c.update(s.xs, s.xm);
        const std::vector<double> Dm = c.D(), Mm = c.M_values(), gm = c.weighted_gaps();
        x = x0;
        for (std::size_t j = 0; j < Dp.size(); ++j) {
          const double fd_D = (Dp[j] - Dm[j]) / (2 * h), fd_g = (gp[j] - gm[j]) / (2 * h);
          const auto at = [&](const Dense& m, int row) {
            const auto it = m.find({row, column});
            return it == m.end() ? 0.0 : it->second;
          };
          EXPECT_NEAR(at(dD, int(j)), fd_D, 1e-6) << s.dim << "D: D_" << j << " / " << column;
          EXPECT_NEAR(at(dg, int(j)), fd_g, 1e-6) << s.dim << "D: g_" << j << " / " << column;
          worst =
              std::max({worst, std::abs(at(dD, int(j)) - fd_D), std::abs(at(dg, int(j)) - fd_g)});
          for (std::size_t k = offsets[j]; k < offsets[j + 1]; ++k) {
            const double fd_M = (Mp[k] - Mm[k]) / (2 * h);
            EXPECT_NEAR(at(dM, int(k)), fd_M, 1e-6) << s.dim << "D: M_" << k << " / " << column;
            worst = std::max(worst, std::abs(at(dM, int(k)) - fd_M));
          }
        }
      }
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", worst);
    RecordProperty("worst_" + std::to_string(s.dim) + "d", text);
  }
}

TEST(MortarCoupling, ClearErrors) {
  const Surfaces s = arcs_2d(4, 5, 1.0, 0.01);
  const auto throws_with = [](const std::function<void()>& f, const std::string& text) {
    try {
      f();
      ADD_FAILURE() << "no error; expected '" << text << "'";
    } catch (const MortarCouplingError& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  };
  const auto make = [&](const Surfaces& t, MortarCouplingOptions o = {}, int cols = 2) {
    MortarCoupling(t.dim, surface_arrays(cols, t.fs, t.xs, t.dim),
                   surface_arrays(2, t.fm, t.xm, t.dim), o);
  };
  MortarCouplingOptions standard;
  standard.multipliers = MultiplierBasis::standard;
  throws_with([&] { couple(s, standard).D(); }, "D is not diagonal with standard multipliers");
  standard.derivatives = true;
  throws_with([&] { make(s, standard); }, "exact derivatives are available for dual multipliers");
  throws_with(
      [&] {
        MortarCoupling(4, surface_arrays(2, s.fs, s.xs, 2), surface_arrays(2, s.fm, s.xm, 2));
      },
      "dim = 4");
  Surfaces quads = s;
  quads.fs.resize(4);  // one "face" of 4 nodes in 2D
  throws_with([&] { make(quads, {}, 4); }, "nodes_per_face = 4 in 2D");
  Surfaces bad_index = s;
  bad_index.fs[3] = 99;
  throws_with([&] { make(bad_index); }, "face 1 node 1 = 99 is not a coordinate row");
  Surfaces degenerate = s;
  degenerate.xs[2] = degenerate.xs[0], degenerate.xs[3] = degenerate.xs[1];  // rows 0, 1 coincide
  throws_with([&] { make(degenerate); }, "slave surface: face 0 (rows 0 1) is degenerate");
  Surfaces nan = s;
  nan.xm[3] = std::nan("");
  throws_with([&] { make(nan); }, "master surface: coordinate 1 of row 1 is nan");
  throws_with([&] { surface_arrays(2, {0, 1, 2}, s.xs, 2); }, "3 face entries");
  MortarCoupling c = couple(s);
  throws_with([&] { c.update(s.xs, std::vector<double>(3)); }, "3 master coordinates");
  throws_with([&] { c.contact_forces(std::vector<double>(1)); }, "1 multiplier values");
  // The same checks on update (the serial value path checks through the gather and the
  // normals launch), then a valid update works again.
  throws_with([&] { c.update(nan.xs, nan.xm); }, "master surface: coordinate 1 of row 1 is nan");
  throws_with([&] { c.update(degenerate.xs, degenerate.xm); },
              "slave surface: face 0 (rows 0 1) is degenerate");
  Surfaces flat_master = s;
  flat_master.xm[4] = flat_master.xm[2], flat_master.xm[5] = flat_master.xm[3];
  throws_with([&] { c.update(flat_master.xs, flat_master.xm); },
              "master surface: face 1 (rows 1 2) is degenerate");
  c.update(s.xs, s.xm);
  EXPECT_EQ(c.D(), couple(s).D());
  throws_with([&] { c.D_derivatives(); }, "derivatives were not requested");
  const std::vector<long long> twice(s.nm(), 7), overlapping(s.nm(), 0);
  const auto with_ids = [&](const std::vector<long long>& ids) {
    MortarCoupling(2, surface_arrays(2, s.fs, s.xs, 2, s.ids_s),
                   surface_arrays(2, s.fm, s.xm, 2, ids));
  };
  throws_with([&] { with_ids(twice); }, "master surface: node id 7 is given twice");
  std::vector<long long> shared = s.ids_m;
  shared[2] = 3;
  throws_with([&] { with_ids(shared); }, "node id 3 is on both surfaces");
  // A master that faces no slave: zeros, no NaN.
  Surfaces far = s;
  for (std::size_t i = 0; i < far.xm.size(); i += 2) far.xm[i] += 10.0;
  const MortarCoupling none = couple(far);
  EXPECT_EQ(none.overlapping_pairs(), 0);
  for (std::size_t j = 0; j < none.num_slave_nodes(); ++j) {
    EXPECT_EQ(none.D()[j], 0.0);
    EXPECT_EQ(none.weighted_gaps()[j], 0.0);
    EXPECT_TRUE(std::isfinite(none.normals()[2 * j]));
  }
  EXPECT_TRUE(none.M_values().empty());
}

// ---- Standard multipliers: D is the full matrix D_jk = ∫ N¹_j N¹_k dA ----

/// Dense D (slave rows × slave ids) and M (slave rows × master ids − n_s) of a coupling, summed
/// over the ranks (ids as numbered by `number`).
struct DenseDM {
  std::vector<double> D, M;
};
DenseDM dense(const MortarCoupling& c, const Surfaces& s, MPI_Comm comm) {
  const std::size_t ns = s.ns(), nm = s.nm();
  DenseDM out{std::vector<double>(ns * ns, 0.0), std::vector<double>(ns * nm, 0.0)};
  for (std::size_t j = 0; j < ns; ++j) {
    for (std::size_t k = c.D_offsets()[j]; k < c.D_offsets()[j + 1]; ++k)
      out.D[j * ns + std::size_t(c.D_columns()[k])] += c.D_values()[k];
    for (std::size_t k = c.M_offsets()[j]; k < c.M_offsets()[j + 1]; ++k)
      out.M[j * nm + std::size_t(c.M_columns()[k]) - ns] += c.M_values()[k];
  }
  if (comm != MPI_COMM_NULL) {
    MPI_Allreduce(MPI_IN_PLACE, out.D.data(), int(out.D.size()), MPI_DOUBLE, MPI_SUM, comm);
    MPI_Allreduce(MPI_IN_PLACE, out.M.data(), int(out.M.size()), MPI_DOUBLE, MPI_SUM, comm);
  }
  return out;
}

/// The consistent mass matrix ∫ N_j N_k dA of the slave faces of `flat` (independent reference):
/// LINE2 of length h: h/3, h/6; a rectangle of area A (QUAD4, nodes in cyclic order): A/9 on
/// the diagonal, A/18 along an edge, A/36 across.
std::vector<double> slave_mass_matrix(const Surfaces& s) {
  const std::size_t ns = s.ns();
  std::vector<double> mass(ns * ns, 0.0);
  const auto x = [&](int node, int d) { return s.xs[std::size_t(node) * s.dim + d]; };
  const auto dist = [&](int a, int b) {
    double l2 = 0.0;
    for (int d = 0; d < s.dim; ++d) l2 += (x(b, d) - x(a, d)) * (x(b, d) - x(a, d));
    return std::sqrt(l2);
  };
  for (std::size_t f = 0; f < s.fs.size() / s.cols_s; ++f) {
    const int* n = &s.fs[f * s.cols_s];
    if (s.dim == 2) {
      const double h = dist(n[0], n[1]);
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) mass[n[a] * ns + n[b]] += h * (a == b ? 1.0 / 3 : 1.0 / 6);
    } else {
      const double A = dist(n[0], n[1]) * dist(n[1], n[2]);
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
          mass[n[a] * ns + n[b]] += A * (a == b ? 1.0 / 9 : (a - b + 4) % 2 ? 1.0 / 18 : 1.0 / 36);
    }
  }
  return mass;
}

TEST(MortarCoupling, StandardDIsTheSlaveMassMatrix) {
  MortarCouplingOptions o;
  o.multipliers = MultiplierBasis::standard;
  for (MPI_Comm comm : {MPI_COMM_NULL, MPI_COMM_WORLD})
    for (int dim : {2, 3}) {
      const Surfaces s = flat(dim, 0.003);
      const DenseDM c = dense(couple(s, o, comm), s, comm);
      const std::vector<double> mass = slave_mass_matrix(s);
      double sum = 0.0;
      for (std::size_t k = 0; k < mass.size(); ++k) {
        EXPECT_NEAR(c.D[k], mass[k], 1e-15) << dim << "D entry " << k;
        sum += c.D[k];
      }
      EXPECT_NEAR(sum, s.slave_measure, 1e-14) << dim << "D";
    }
}

// Curved, non-matching: Σ_jk D_jk = slave measure, D symmetric, row sums Σ_k D_jk = ∫ N_j dA =
// the dual D_jj (biorthogonality), Σ_l M_jl = Σ_k D_jk per row; exact and collocation for M.
TEST(MortarCoupling, StandardRowSumsEqualDualDiagonal) {
  for (MPI_Comm comm : {MPI_COMM_NULL, MPI_COMM_WORLD})
    for (const Surfaces& s : cases())
      for (auto scheme : {MortarIntegration::exact, MortarIntegration::collocation}) {
        MortarCouplingOptions o;
        o.integration = scheme;
        const MortarCoupling dual = couple(s, o, comm);
        o.multipliers = MultiplierBasis::standard;
        const MortarCoupling standard = couple(s, o, comm);
        const DenseDM c = dense(standard, s, comm);
        const std::size_t ns = s.ns(), nm = s.nm();
        double sum = 0.0;
        for (std::size_t j = 0; j < ns; ++j) {
          double row_D = 0.0, row_M = 0.0;
          for (std::size_t k = 0; k < ns; ++k) {
            row_D += c.D[j * ns + k];
            if (scheme == MortarIntegration::exact)
              EXPECT_NEAR(c.D[j * ns + k], c.D[k * ns + j], 1e-15);
          }
          for (std::size_t l = 0; l < nm; ++l) row_M += c.M[j * nm + l];
          sum += row_D;
          EXPECT_NEAR(row_M, row_D, 1e-14) << s.dim << "D row " << j;
          if (scheme == MortarIntegration::exact)
            EXPECT_NEAR(row_D, sum_over_ranks(dual.D()[j], comm), 1e-14) << s.dim << "D row " << j;
        }
        if (scheme == MortarIntegration::exact) EXPECT_NEAR(sum, s.slave_measure, 1e-13);
      }
}

TEST(MortarCoupling, StandardWeightedGapOfKnownOffset) {
  // g̃_j = −n·(Σ_k D_jk x¹_k − Σ_l M_jl x²_l) = delta Σ_k D_jk on the flat offset.
  const double delta = 0.003;
  MortarCouplingOptions o;
  o.multipliers = MultiplierBasis::standard;
  for (int dim : {2, 3}) {
    const Surfaces s = flat(dim, delta);
    const MortarCoupling c = couple(s, o);
    for (std::size_t j = 0; j < c.num_slave_nodes(); ++j) {
      double row = 0.0;
      for (std::size_t k = c.D_offsets()[j]; k < c.D_offsets()[j + 1]; ++k) row += c.D_values()[k];
      EXPECT_GT(row, 0.0);
      EXPECT_NEAR(c.weighted_gaps()[j], delta * row, 1e-15) << dim << "D node " << j;
    }
  }
}

// Patch test: a linear field u = u₀ + c·x (c in the interface plane) on non-matching flat
// meshes is transferred exactly, Σ_k D_jk u(x¹_k) = Σ_l M_jl u(x²_l), for both bases (the
// mortar projection reproduces what both discretisations represent).
TEST(MortarCoupling, LinearFieldReproduced) {
  for (auto basis : {MultiplierBasis::dual, MultiplierBasis::standard})
    for (int dim : {2, 3}) {
      const Surfaces s = flat(dim, 0.004, dim == 2 ? 9 : 5, dim == 2 ? 13 : 7);
      MortarCouplingOptions o;
      o.multipliers = basis;
      const MortarCoupling c = couple(s, o);
      double grad[3];
      for (int d = 0; d < 3; ++d) grad[d] = 0.7 * flat_t1[d] - (dim == 3 ? 1.3 : 0.0) * flat_t2[d];
      const auto u = [&](const double* x) {
        double v = 0.25;
        for (int d = 0; d < dim; ++d) v += grad[d] * x[d];
        return v;
      };
      const std::size_t ns = s.ns();
      for (std::size_t j = 0; j < ns; ++j) {
        double Du = 0.0, Mu = 0.0, scale = 0.0;
        for (std::size_t k = c.D_offsets()[j]; k < c.D_offsets()[j + 1]; ++k) {
          Du += c.D_values()[k] * u(&s.xs[std::size_t(c.D_columns()[k]) * dim]);
          scale += std::abs(c.D_values()[k]);
        }
        for (std::size_t k = c.M_offsets()[j]; k < c.M_offsets()[j + 1]; ++k)
          Mu += c.M_values()[k] * u(&s.xm[(std::size_t(c.M_columns()[k]) - ns) * dim]);
        EXPECT_GT(scale, 0.0);
        EXPECT_NEAR(Du, Mu, 1e-14 * (1.0 + scale))
            << dim << "D basis " << int(basis) << " row " << j;
      }
    }
}

TEST(MortarCoupling, StandardDistributedEqualsSerial) {
  MortarCouplingOptions o;
  o.multipliers = MultiplierBasis::standard;
  for (const Surfaces& s : cases()) {
    const MortarCoupling serial = couple(s, o);
    const MortarCoupling dist = couple(s, o, MPI_COMM_WORLD);
    const DenseDM a = dense(serial, s, MPI_COMM_NULL), b = dense(dist, s, MPI_COMM_WORLD);
    for (std::size_t k = 0; k < a.D.size(); ++k) EXPECT_NEAR(a.D[k], b.D[k], 1e-15);
    for (std::size_t k = 0; k < a.M.size(); ++k) EXPECT_NEAR(a.M[k], b.M[k], 1e-15);
    for (std::size_t j = 0; j < serial.num_slave_nodes(); ++j)
      EXPECT_NEAR(sum_over_ranks(dist.weighted_gaps()[j], MPI_COMM_WORLD),
                  serial.weighted_gaps()[j], 1e-15);
  }
}

// The Kokkos View entry points: the same results as the arrays, from LayoutRight Views used in
// place and LayoutLeft (strided) Views gathered; wrong extents are reported.
/// The cylinders with both surfaces of TRI3 faces (each slave QUAD4 cut along a diagonal).
Surfaces cylinders_3d_tri3(int n, int m, double R, double delta) {
  Surfaces s = cylinders_3d(n, m, R, delta);
  std::vector<int> tris;
  for (std::size_t f = 0; f < s.fs.size() / 4; ++f) {
    const int* q = &s.fs[4 * f];
    tris.insert(tris.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
  }
  s.fs = tris;
  s.cols_s = 3;
  return s;
}

/// Every result of the values path of `c` equals that of `fresh` (a new coupling at the same
/// coordinates): exactly, since both sum the same pair terms in the same order.
void expect_same_results(const MortarCoupling& c, const MortarCoupling& fresh,
                         const std::string& what) {
  EXPECT_EQ(c.overlapping_pairs(), fresh.overlapping_pairs()) << what;
  EXPECT_EQ(c.D_offsets(), fresh.D_offsets()) << what;
  EXPECT_EQ(c.D_columns(), fresh.D_columns()) << what;
  EXPECT_EQ(c.D_values(), fresh.D_values()) << what;
  if (c.multipliers() == MultiplierBasis::dual) {
    EXPECT_EQ(c.D(), fresh.D()) << what;
  }
  EXPECT_EQ(c.M_offsets(), fresh.M_offsets()) << what;
  EXPECT_EQ(c.M_columns(), fresh.M_columns()) << what;
  EXPECT_EQ(c.M_values(), fresh.M_values()) << what;
  EXPECT_EQ(c.weighted_gaps(), fresh.weighted_gaps()) << what;
  EXPECT_EQ(c.normals(), fresh.normals()) << what;
}

// A sequence of updates (the values path keeps the pattern of D and M while the candidate
// pairs and the overlapping ones are unchanged, and scatters into it) gives what a new coupling
// at each configuration gives: the master slid along the interface by 0.15 and 0.35 of a slave
// element (other pairs overlap), pressed in (same pairs, other values), and the same again.
TEST(MortarCoupling, UpdatesEqualNewCouplings) {
  const std::vector<Surfaces> surfaces = {arcs_2d(12, 17, 1.0, 0.01), cylinders_3d(6, 8, 1.0, 0.01),
                                          cylinders_3d_tri3(6, 8, 1.0, 0.01)};
  for (const Surfaces& s0 : surfaces)
    for (auto basis : {MultiplierBasis::dual, MultiplierBasis::standard}) {
      MortarCouplingOptions o;
      o.multipliers = basis;
      MortarCoupling c = couple(s0, o);
      Surfaces s = s0;
      const double h = s.dim == 2 ? 1.0 / 12 : 0.8 / 6;  // slave element: Δθ or Δz
      const auto slide = [&](double fraction) {          // master along θ (2D) or z (3D)
        for (std::size_t i = 0; i < s.nm(); ++i) {
          double* x = &s.xm[i * s.dim];
          if (s.dim == 3) {
            x[2] = s0.xm[i * 3 + 2] + fraction * h;
            continue;
          }
          const double c_ = std::cos(fraction * h), s_ = std::sin(fraction * h);
          const double* x0 = &s0.xm[i * 2];
          x[0] = c_ * x0[0] - s_ * x0[1];
          x[1] = s_ * x0[0] + c_ * x0[1];
        }
      };
      const auto press = [&](double depth) {  // master radially by −depth (r ≈ 1)
        for (std::size_t i = 0; i < s.nm(); ++i) {
          double* x = &s.xm[i * s.dim];
          const double r = std::hypot(x[0], x[1]), k = (r - depth) / r;
          x[0] *= k;
          x[1] *= k;
        }
      };
      const std::string what = std::to_string(s.dim) + "D, " + std::to_string(s.cols_s) +
                               "-node slave faces, " +
                               (basis == MultiplierBasis::dual ? "dual" : "standard");
      for (int step = 0; step < 5; ++step) {
        if (step == 0) slide(0.15);
        if (step == 1) slide(0.35);
        if (step == 2) press(0.001);
        // steps 3 and 4: the same coordinates again
        c.update(s.xs, s.xm);
        expect_same_results(c, couple(s, o), what + ", step " + std::to_string(step));
      }
      double sum = 0.0;  // the last configuration still covers the slave
      for (double d : c.D_values()) sum += d;
      EXPECT_NEAR(sum, s.slave_measure, 1e-12) << what;
    }
}

TEST(MortarCoupling, ViewsGiveTheArraysResults) {
  using Coords = Kokkos::View<double**, Kokkos::LayoutRight, Kokkos::HostSpace>;
  using Left = Kokkos::View<double**, Kokkos::LayoutLeft, Kokkos::HostSpace>;
  using Faces = Kokkos::View<int**, Kokkos::LayoutRight, Kokkos::HostSpace>;
  for (Surfaces s : cases()) {
    const int dim = s.dim;
    const auto coords = [&](const std::vector<double>& x) {
      Coords v("x", x.size() / dim, dim);
      for (std::size_t i = 0; i < v.extent(0); ++i)
        for (int d = 0; d < dim; ++d) v(i, d) = x[i * dim + d];
      return v;
    };
    const auto faces = [&](const std::vector<int>& f, int cols) {
      Faces v("faces", f.size() / cols, cols);
      for (std::size_t i = 0; i < v.extent(0); ++i)
        for (int a = 0; a < cols; ++a) v(i, a) = f[i * cols + a];
      return v;
    };
    Left xm_left("xm", s.nm(), dim);
    for (std::size_t i = 0; i < s.nm(); ++i)
      for (int d = 0; d < dim; ++d) xm_left(i, d) = s.xm[i * dim + d];
    MortarCoupling arrays = couple(s);
    MortarCoupling views(SurfaceViews{faces(s.fs, s.cols_s), coords(s.xs), {}},
                         SurfaceViews{faces(s.fm, s.cols_m), xm_left, {}});
    EXPECT_EQ(views.D(), arrays.D());
    EXPECT_EQ(views.M_columns(), arrays.M_columns());
    EXPECT_EQ(views.M_values(), arrays.M_values());
    // A rigid shift of the master: update from Views and from arrays agree.
    for (std::size_t i = 0; i < s.nm(); ++i) s.xm[i * dim] += 0.01;
    arrays.update(s.xs, s.xm);
    views.update(coords(s.xs), coords(s.xm));
    EXPECT_EQ(views.weighted_gaps(), arrays.weighted_gaps());
    EXPECT_EQ(views.M_values(), arrays.M_values());
    try {
      views.update(coords(s.xs), Coords("short", 2, dim));
      ADD_FAILURE() << "no error for a short View";
    } catch (const MortarCouplingError& e) {
      EXPECT_NE(std::string(e.what()).find("Views of"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace grout
