// 3D launch of the mortar pair kernels (kernels/mortar_integrate.hpp, mortar_integrate<3>) on
// flat non-matching interfaces (perf/mortar_interfaces.hpp): the per-pair results equal those
// of a plain loop calling integrate_mortar_3d on every candidate pair (so the per-slave hoisting
// of the dual basis and the early rejection change nothing), and the assembled D, M pass the
// mortar checks of docs/design.md §3: Σ D = slave area, Σ M = overlap area (the whole slave here),
// Σ_l M_jl f(x²_l) = D_jj f(x¹_j) for linear f, and the weighted gap equals gap · D_jj. Also
// mortar_integrate_each (pairs handed to a sink) against the stored launches, 2D and 3D.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

#include "kernels/coarse_search.hpp"
#include "kernels/mortar_3d.hpp"
#include "kernels/mortar_integrate.hpp"
#include "kernels/surface_normals.hpp"
#include "kernels/weighted_gap.hpp"
#include "perf/mortar_interfaces.hpp"

namespace {

using grout::MortarPairResult;
using grout::MortarStatus;
using grout::bench::FaceShape;
using grout::bench::MortarInterface;

struct Launch {
  Kokkos::View<int**> slave, master;
  Kokkos::View<double**> coords, normals;
  grout::SearchCandidates<Kokkos::HostSpace> candidates;  // CRS: offsets, masters
  Kokkos::View<MortarPairResult<double>*> results;
  MortarStatus normals_status = MortarStatus::ok, status = MortarStatus::ok;
};

Kokkos::View<int**> face_view(const std::vector<int>& rows, int cols, const char* label) {
  Kokkos::View<int**> v(std::string(label), rows.size() / cols, cols);
  for (size_t f = 0; f < v.extent(0); ++f)
    for (int k = 0; k < cols; ++k) v(f, k) = rows[f * cols + k];
  return v;
}

Launch launch(const MortarInterface& mi, const grout::MortarOptions& options) {
  Launch l;
  l.slave = face_view(mi.slave, mi.cols, "slave");
  l.master = face_view(mi.master, mi.cols, "master");
  l.coords = Kokkos::View<double**>("coords", mi.n_nodes(), 3);
  for (int i = 0; i < mi.n_nodes(); ++i)
    for (int d = 0; d < 3; ++d) l.coords(i, d) = mi.coords[3 * i + d];
  l.normals = Kokkos::View<double**>("normals", mi.n_nodes(), 3);
  l.normals_status = grout::compute_nodal_normals(l.slave, l.coords, l.normals);
  grout::CoarseSearchWorkspace<Kokkos::HostSpace> workspace;
  EXPECT_EQ(grout::coarse_search(workspace, l.slave, l.master, l.coords, 0.1, l.candidates),
            MortarStatus::ok);
  l.results = Kokkos::View<MortarPairResult<double>*>("results", l.candidates.n_pairs);
  l.status =
      grout::mortar_integrate_3d(l.slave, l.master, l.coords, l.normals, l.candidates.offsets,
                                 l.candidates.masters, options, l.results);
  return l;
}

void gather(const Launch& l, const Kokkos::View<int**>& faces, int f, double x[4][3]) {
  grout::gather_face_coordinates(faces, f, l.coords, x);
}

void expect_same(const MortarPairResult<double>& a, const MortarPairResult<double>& b) {
  ASSERT_EQ(a.n_slave, b.n_slave);
  ASSERT_EQ(a.n_master, b.n_master);
  EXPECT_DOUBLE_EQ(a.overlap, b.overlap);
  for (int j = 0; j < 4; ++j) {
    EXPECT_DOUBLE_EQ(a.D[j], b.D[j]);
    for (int k = 0; k < 4; ++k) EXPECT_DOUBLE_EQ(a.M[j][k], b.M[j][k]);
  }
}

struct Shapes {
  FaceShape slave, master;
};

class MortarIntegrate3D : public ::testing::TestWithParam<Shapes> {};

}  // namespace

TEST_P(MortarIntegrate3D, LaunchEqualsPlainLoopOverPairs) {
  const MortarInterface mi =
      grout::bench::flat_interface_3d(6, GetParam().slave, GetParam().master);
  const grout::MortarOptions options;
  const Launch l = launch(mi, options);
  ASSERT_EQ(l.normals_status, MortarStatus::ok);
  ASSERT_EQ(l.status, MortarStatus::ok);
  int overlapping = 0, total = 0;
  for (size_t s = 0; s < l.slave.extent(0); ++s) {
    double xs[4][3], ns[4][3], xm[4][3];
    gather(l, l.slave, s, xs);
    const int n_slave = grout::gather_face_coordinates(l.slave, s, l.normals, ns);
    for (int p = l.candidates.offsets(s); p < l.candidates.offsets(s + 1); ++p, ++total) {
      const int n_master =
          grout::gather_face_coordinates(l.master, l.candidates.masters(p), l.coords, xm);
      MortarPairResult<double> ref;
      const MortarStatus st = grout::integrate_mortar_3d(n_slave, xs, ns, n_master, xm, ref);
      ASSERT_TRUE(st == MortarStatus::ok || st == MortarStatus::no_overlap);
      overlapping += st == MortarStatus::ok;
      expect_same(l.results(p), ref);
    }
  }
  EXPECT_GT(total, overlapping);  // the enlarged boxes give non-overlapping candidates too
  EXPECT_GE(overlapping, static_cast<int>(l.slave.extent(0)));
}

TEST_P(MortarIntegrate3D, CollocationLaunchEqualsPlainLoop) {
  const MortarInterface mi =
      grout::bench::flat_interface_3d(4, GetParam().slave, GetParam().master);
  grout::MortarOptions options;
  options.scheme = grout::MortarIntegration::collocation;
  options.n_collocation = 9;  // 3 × 3 points per slave face
  const Launch l = launch(mi, options);
  ASSERT_EQ(l.normals_status, MortarStatus::ok);
  ASSERT_EQ(l.status, MortarStatus::ok);
  for (size_t s = 0; s < l.slave.extent(0); ++s) {
    double xs[4][3], ns[4][3], xm[4][3];
    gather(l, l.slave, s, xs);
    const int n_slave = grout::gather_face_coordinates(l.slave, s, l.normals, ns);
    for (int p = l.candidates.offsets(s); p < l.candidates.offsets(s + 1); ++p) {
      const int n_master =
          grout::gather_face_coordinates(l.master, l.candidates.masters(p), l.coords, xm);
      MortarPairResult<double> ref;
      grout::integrate_mortar_3d_collocation(n_slave, xs, ns, n_master, xm, 3, ref);
      expect_same(l.results(p), ref);
    }
  }
}

TEST_P(MortarIntegrate3D, SumsPatchTestAndWeightedGap) {
  const MortarInterface mi =
      grout::bench::flat_interface_3d(8, GetParam().slave, GetParam().master);
  const Launch l = launch(mi, grout::MortarOptions{});
  ASSERT_EQ(l.normals_status, MortarStatus::ok);
  ASSERT_EQ(l.status, MortarStatus::ok);
  const int n_nodes = mi.n_nodes();
  auto f = [&](int node) {  // linear in the in-plane coordinates
    return 1.0 + 2.0 * l.coords(node, 0) - 3.0 * l.coords(node, 1);
  };
  std::vector<double> D(n_nodes, 0.0), Mf(n_nodes, 0.0);
  double sum_d = 0.0, sum_m = 0.0, overlap = 0.0;
  for (size_t s = 0; s < l.slave.extent(0); ++s)
    for (int p = l.candidates.offsets(s); p < l.candidates.offsets(s + 1); ++p) {
      const MortarPairResult<double>& r = l.results(p);
      overlap += r.overlap;
      for (int j = 0; j < r.n_slave; ++j) {
        D[l.slave(s, j)] += r.D[j];
        sum_d += r.D[j];
        for (int k = 0; k < r.n_master; ++k) {
          sum_m += r.M[j][k];
          Mf[l.slave(s, j)] += r.M[j][k] * f(l.master(l.candidates.masters(p), k));
        }
      }
    }
  EXPECT_NEAR(sum_d, mi.slave_measure, 1e-12);
  EXPECT_NEAR(sum_m, mi.slave_measure, 1e-12);  // fully covered: overlap = slave area
  EXPECT_NEAR(overlap, mi.slave_measure, 1e-12);
  Kokkos::View<double*> g_tilde("g_tilde", n_nodes);
  grout::accumulate_weighted_gaps(l.slave, l.master, l.coords, l.normals, l.candidates.offsets,
                                  l.candidates.masters, l.results, g_tilde);
  const double h = 1.0 / 8;
  for (int j = 0; j < mi.n_slave_nodes; ++j) {
    ASSERT_GT(D[j], 0.0) << "node " << j;
    EXPECT_NEAR(Mf[j], D[j] * f(j), 1e-13 * h * h) << "node " << j;
    EXPECT_NEAR(g_tilde(j), mi.gap * D[j], 1e-13 * mi.gap * h * h) << "node " << j;
  }
}

namespace {
std::string shapes_name(const ::testing::TestParamInfo<Shapes>& info) {
  const char* names[] = {"line2", "tri3", "quad4"};
  return std::string(names[int(info.param.slave)]) + "_on_" + names[int(info.param.master)];
}
}  // namespace

INSTANTIATE_TEST_SUITE_P(Shapes, MortarIntegrate3D,
                         ::testing::Values(Shapes{FaceShape::quad4, FaceShape::quad4},
                                           Shapes{FaceShape::tri3, FaceShape::tri3},
                                           Shapes{FaceShape::quad4, FaceShape::tri3},
                                           Shapes{FaceShape::tri3, FaceShape::quad4}),
                         shapes_name);

TEST(MortarIntegrate3DLaunch, DegenerateSlaveFaceReported) {
  MortarInterface mi = grout::bench::flat_interface_3d(2, FaceShape::quad4, FaceShape::quad4);
  for (int d = 0; d < 3; ++d) mi.coords[3 * 1 + d] = mi.coords[3 * 0 + d];  // collapse an edge
  for (int d = 0; d < 3; ++d) mi.coords[3 * 4 + d] = mi.coords[3 * 3 + d];  // … and another
  const Launch l = launch(mi, grout::MortarOptions{});
  EXPECT_EQ(l.normals_status, MortarStatus::degenerate);
  EXPECT_EQ(l.status, MortarStatus::degenerate);
  for (size_t p = 0; p < l.results.extent(0); ++p) EXPECT_TRUE(std::isfinite(l.results(p).overlap));
}

namespace {

/// Stores each pair handed to it at its CRS position (mortar_integrate_each's sink).
template <class Pair>
struct StorePair {
  Kokkos::View<Pair*> out;
  KOKKOS_INLINE_FUNCTION void operator()(int, int p, const Pair& pair) const { out(p) = pair; }
};

/// mortar_integrate_each on the interface mi (2D or 3D) against the stored launch
/// (mortar_integrate / mortar_integrate_matrices): the same pairs, bit for bit.
template <int Dim, class Pair>
void expect_each_equals_stored(const MortarInterface& mi, grout::MultiplierBasis basis) {
  const Kokkos::View<int**> slave = face_view(mi.slave, mi.cols, "slave");
  const Kokkos::View<int**> master = face_view(mi.master, mi.cols, "master");
  Kokkos::View<double**> coords("coords", mi.n_nodes(), Dim), normals("normals", mi.n_nodes(), Dim);
  for (int i = 0; i < mi.n_nodes(); ++i)
    for (int d = 0; d < Dim; ++d) coords(i, d) = mi.coords[Dim * i + d];
  ASSERT_EQ(grout::compute_nodal_normals(slave, coords, normals), MortarStatus::ok);
  grout::CoarseSearchWorkspace<Kokkos::HostSpace> workspace;
  grout::SearchCandidates<Kokkos::HostSpace> c;
  ASSERT_EQ(grout::coarse_search(workspace, slave, master, coords, 0.1, c), MortarStatus::ok);
  Kokkos::View<Pair*> stored("stored", c.n_pairs), each("each", c.n_pairs);
  const Kokkos::DefaultExecutionSpace space;
  const grout::MortarOptions options;
  MortarStatus status;
  if constexpr (std::is_same<Pair, MortarPairResult<double>>::value) {
    status = grout::mortar_integrate<Dim>(space, slave, master, coords, normals, c.offsets,
                                          c.masters, options, stored);
  } else {
    status = grout::mortar_integrate_matrices<Dim>(space, slave, master, coords, normals, c.offsets,
                                                   c.masters, basis, options, stored);
  }
  ASSERT_EQ(status, MortarStatus::ok);
  const auto each_launch = [&](grout::MultiplierBasis b) {
    return grout::mortar_integrate_each<Dim, Pair>(space, slave, master, coords, normals, c.offsets,
                                                   c.masters, b, options, StorePair<Pair>{each});
  };
  ASSERT_EQ(each_launch(basis), MortarStatus::ok);
  int overlapping = 0;
  for (int p = 0; p < c.n_pairs; ++p) {
    const Pair &a = each(p), &b = stored(p);
    overlapping += a.overlap > 0.0;
    ASSERT_EQ(a.n_slave, b.n_slave);
    ASSERT_EQ(a.n_master, b.n_master);
    EXPECT_EQ(a.overlap, b.overlap);
    for (int j = 0; j < a.n_slave; ++j)
      for (int l = 0; l < a.n_master; ++l) EXPECT_EQ(a.M[j][l], b.M[j][l]);
    if constexpr (std::is_same<Pair, MortarPairResult<double>>::value) {
      for (int j = 0; j < a.n_slave; ++j) EXPECT_EQ(a.D[j], b.D[j]);
    } else {
      for (int j = 0; j < a.n_slave; ++j)
        for (int k = 0; k < a.n_slave; ++k) EXPECT_EQ(a.D[j][k], b.D[j][k]);
    }
  }
  EXPECT_GE(overlapping, mi.n_slave());
  // A dual result for another basis would be wrong (D is not diagonal): refused.
  if constexpr (std::is_same<Pair, MortarPairResult<double>>::value) {
    EXPECT_EQ(each_launch(grout::MultiplierBasis::standard), MortarStatus::degenerate);
  }
}

}  // namespace

// mortar_integrate_each (each pair handed to a sink, no pair array) runs the pair kernels of
// the stored launches: 2D and 3D, dual and standard multipliers.
TEST(MortarIntegrateEach, EqualsTheStoredLaunch) {
  using grout::MortarPairMatrices;
  using grout::MultiplierBasis;
  const MortarInterface line = grout::bench::line_interface_2d(20, true);
  expect_each_equals_stored<2, MortarPairResult<double>>(line, MultiplierBasis::dual);
  expect_each_equals_stored<2, MortarPairMatrices<double>>(line, MultiplierBasis::standard);
  for (FaceShape shape : {FaceShape::quad4, FaceShape::tri3}) {
    const MortarInterface flat = grout::bench::flat_interface_3d(4, shape, shape);
    expect_each_equals_stored<3, MortarPairResult<double>>(flat, MultiplierBasis::dual);
    expect_each_equals_stored<3, MortarPairMatrices<double>>(flat, MultiplierBasis::standard);
  }
}
