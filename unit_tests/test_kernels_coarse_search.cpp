// Coarse search (kernels/coarse_search.hpp): the binned search must return exactly the
// brute-force candidate lists, and keep the candidate count per slave face bounded on 1e5
// faces in reasonable time.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "kernels/coarse_search.hpp"

namespace {

using grout::max_pair_candidates;
using grout::MortarStatus;

struct Mesh {
  Kokkos::View<double**> coords;
  Kokkos::View<int**> slave, master;
};

// n_s slave and n_m master random faces (2D segments or 3D mixed tri/quad, −1 padded) of size
// up to `size` in the unit box; each face owns its nodes.
Mesh random_mesh(int dim, int n_s, int n_m, double size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int cols = dim == 2 ? 2 : 4;
  Mesh mesh{Kokkos::View<double**>("coords", (n_s + n_m) * cols, dim),
            Kokkos::View<int**>("slave", n_s, cols), Kokkos::View<int**>("master", n_m, cols)};
  int node = 0;
  for (auto* faces : {&mesh.slave, &mesh.master})
    for (int f = 0; f < static_cast<int>(faces->extent(0)); ++f) {
      const int n_nodes = dim == 2 ? 2 : (u(rng) < 0.5 ? 3 : 4);
      double c[3];
      for (int d = 0; d < dim; ++d) c[d] = u(rng);
      for (int k = 0; k < cols; ++k) {
        (*faces)(f, k) = k < n_nodes ? node : -1;
        if (k >= n_nodes) continue;
        for (int d = 0; d < dim; ++d) mesh.coords(node, d) = c[d] + size * (u(rng) - 0.5);
        ++node;
      }
    }
  return mesh;
}

struct Candidates {
  Kokkos::View<int*> count;
  Kokkos::View<int**> ids;
  MortarStatus status;
};

Candidates search(const Mesh& m, double factor, bool brute) {
  Candidates c{Kokkos::View<int*>("count", m.slave.extent(0)),
               Kokkos::View<int**>("ids", m.slave.extent(0), max_pair_candidates),
               MortarStatus::ok};
  c.status = brute ? grout::coarse_search_brute_force(Kokkos::DefaultExecutionSpace(), m.slave,
                                                      m.master, m.coords, factor, c.count, c.ids)
                   : grout::coarse_search(m.slave, m.master, m.coords, factor, c.count, c.ids);
  return c;
}

void expect_identical(const Candidates& a, const Candidates& b) {
  ASSERT_EQ(a.status, b.status);
  for (size_t s = 0; s < a.count.extent(0); ++s) {
    ASSERT_EQ(a.count(s), b.count(s)) << "slave " << s;
    for (int c = 0; c < max_pair_candidates; ++c) ASSERT_EQ(a.ids(s, c), b.ids(s, c));
  }
}

}  // namespace

TEST(CoarseSearch, IdenticalToBruteForceOnSmallRandomCases) {
  for (int dim : {2, 3})
    for (unsigned seed = 1; seed <= 5; ++seed) {
      const Mesh m = random_mesh(dim, 60, 80, 0.15, seed);
      const auto binned = search(m, 0.3, false), brute = search(m, 0.3, true);
      EXPECT_EQ(brute.status, MortarStatus::ok);
      expect_identical(binned, brute);
      int total = 0;
      for (size_t s = 0; s < binned.count.extent(0); ++s) total += binned.count(s);
      EXPECT_GT(total, 0);
    }
}

TEST(CoarseSearch, CapacityExceededKeepsSmallestIds) {
  // 40 masters inside one slave box: both searches report the overflow and keep ids 0..31.
  Mesh m = random_mesh(2, 1, 40, 0.0, 9);
  m.coords(0, 0) = 0.0, m.coords(0, 1) = 0.5, m.coords(1, 0) = 1.0, m.coords(1, 1) = 0.5;
  for (int k = 2; k < 82; ++k) m.coords(k, 1) = 0.5;
  const auto binned = search(m, 0.1, false), brute = search(m, 0.1, true);
  EXPECT_EQ(binned.status, MortarStatus::capacity_exceeded);
  expect_identical(binned, brute);
  for (int c = 0; c < max_pair_candidates; ++c) EXPECT_EQ(binned.ids(0, c), c);
}

TEST(CoarseSearch, EmptyAndDegenerateInputs) {
  Mesh m = random_mesh(3, 10, 0, 0.1, 4);
  const auto none = search(m, 0.5, false);
  EXPECT_EQ(none.status, MortarStatus::ok);
  for (int s = 0; s < 10; ++s) EXPECT_EQ(none.count(s), 0);
  Mesh p = random_mesh(2, 10, 5, 0.0, 5);  // point-like faces: boxes of zero size
  for (int k = 20; k < 30; ++k) p.coords(k, 0) = p.coords(k, 1) = 0.25;
  for (int k = 0; k < 20; ++k) p.coords(k, 0) = p.coords(k, 1) = 0.25;
  const auto pts = search(p, 0.5, false);
  expect_identical(pts, search(p, 0.5, true));
  EXPECT_EQ(pts.count(0), 5);
}

namespace {
// Non-matching curved 2D interface: n_s slave segments on y = 0.1 sin(2πx) over [0, 1], and
// 1.3 n_s master segments on the same curve shifted by 1e-3 · h, in opposite orientation.
Mesh wavy_interface_2d(int n_s) {
  const int n_m = (13 * n_s) / 10;
  Mesh mesh{Kokkos::View<double**>("coords", n_s + 1 + n_m + 1, 2),
            Kokkos::View<int**>("slave", n_s, 2), Kokkos::View<int**>("master", n_m, 2)};
  const double pi = 3.14159265358979323846, gap = 1e-3 / n_s;
  for (int i = 0; i <= n_s; ++i) {
    const double x = static_cast<double>(i) / n_s;
    mesh.coords(i, 0) = x, mesh.coords(i, 1) = 0.1 * std::sin(2 * pi * x);
  }
  for (int i = 0; i <= n_m; ++i) {
    const double x = 1.0 - static_cast<double>(i) / n_m;
    mesh.coords(n_s + 1 + i, 0) = x, mesh.coords(n_s + 1 + i, 1) = 0.1 * std::sin(2 * pi * x) + gap;
  }
  for (int e = 0; e < n_s; ++e) mesh.slave(e, 0) = e, mesh.slave(e, 1) = e + 1;
  for (int e = 0; e < n_m; ++e) mesh.master(e, 0) = n_s + 1 + e, mesh.master(e, 1) = n_s + 2 + e;
  return mesh;
}

// Curved 3D interface: n×n slave quads and m×m master quads (m = 1.3 n, split into triangles on
// alternate cells) on z = 0.1 sin(πx) sin(πy) over [0, 1]², master shifted by 1e-3 h.
Mesh wavy_interface_3d(int n) {
  const int m = (13 * n) / 10;
  const int n_nodes = (n + 1) * (n + 1) + (m + 1) * (m + 1);
  Mesh mesh{Kokkos::View<double**>("coords", n_nodes, 3), Kokkos::View<int**>("slave", n * n, 4),
            Kokkos::View<int**>("master", m * m + (m * m + 1) / 2, 4)};
  const double pi = 3.14159265358979323846;
  auto grid = [&](int k, int offset, double dz) {
    for (int j = 0; j <= k; ++j)
      for (int i = 0; i <= k; ++i) {
        const int id = offset + j * (k + 1) + i;
        const double x = static_cast<double>(i) / k, y = static_cast<double>(j) / k;
        mesh.coords(id, 0) = x, mesh.coords(id, 1) = y;
        mesh.coords(id, 2) = 0.1 * std::sin(pi * x) * std::sin(pi * y) + dz;
      }
  };
  grid(n, 0, 0.0);
  const int off = (n + 1) * (n + 1);
  grid(m, off, 1e-3 / n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, f = j * n + i;
      mesh.slave(f, 0) = a, mesh.slave(f, 1) = a + 1, mesh.slave(f, 2) = a + n + 2,
                    mesh.slave(f, 3) = a + n + 1;
    }
  int f = 0;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const int a = off + j * (m + 1) + i, b = a + 1, c = a + m + 2, d = a + m + 1;
      const int quad[4] = {a, d, c, b}, tri1[4] = {a, d, c, -1}, tri2[4] = {a, c, b, -1};
      if ((i + j) % 2) {
        for (int k = 0; k < 4; ++k) mesh.master(f, k) = quad[k];
        ++f;
      } else {
        for (int k = 0; k < 4; ++k) mesh.master(f, k) = tri1[k], mesh.master(f + 1, k) = tri2[k];
        f += 2;
      }
    }
  return mesh;
}

void check_large(const Mesh& mesh, double factor, int max_expected) {
  search(mesh, factor, false);  // warm-up: first touch of the work arrays
  const auto t0 = std::chrono::steady_clock::now();
  const auto c = search(mesh, factor, false);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(c.status, MortarStatus::ok);
  int worst = 0, least = max_pair_candidates;
  for (size_t s = 0; s < c.count.extent(0); ++s) {
    worst = std::max(worst, c.count(s));
    least = std::min(least, c.count(s));
  }
  std::printf("%zu slave, %zu master faces: %.3f s (%.0f ns/slave face), candidates %d..%d\n",
              mesh.slave.extent(0), mesh.master.extent(0), seconds,
              1e9 * seconds / mesh.slave.extent(0), least, worst);
  EXPECT_LE(worst, max_expected);
  EXPECT_GE(least, 1);
  // Spot check against a brute-force scan of every master for a sample of slave faces.
  const auto s_boxes =
      grout::compute_face_boxes(Kokkos::DefaultExecutionSpace(), mesh.slave, mesh.coords, factor);
  const auto m_boxes =
      grout::compute_face_boxes(Kokkos::DefaultExecutionSpace(), mesh.master, mesh.coords, factor);
  const int dim = static_cast<int>(mesh.coords.extent(1));
  for (size_t s = 0; s < c.count.extent(0); s += c.count.extent(0) / 97) {
    int k = 0;
    for (size_t m = 0; m < mesh.master.extent(0); ++m)
      if (grout::boxes_overlap(dim, s_boxes, s, m_boxes, m)) {
        ASSERT_EQ(c.ids(s, k++), int(m));
      }
    ASSERT_EQ(k, c.count(s));
  }
}

}  // namespace

TEST(CoarseSearch, BoundedCandidatesOn1e5Faces2D) {
  check_large(wavy_interface_2d(100000), 0.5, 8);
}

TEST(CoarseSearch, BoundedCandidatesOn1e5Faces3D) {
  check_large(wavy_interface_3d(316), 0.25, 24);
}

// Whole-interface comparison with the brute-force search on grids of many hash blocks (2D:
// ~300 × 30 cells, 64×64-cell blocks; 3D: ~30³ cells, 4×4×4 blocks), every slave face.
TEST(CoarseSearch, IdenticalToBruteForceOnWavyInterfaces) {
  for (const double factor : {0.1, 0.5}) {
    const Mesh m2 = wavy_interface_2d(5000);
    expect_identical(search(m2, factor, false), search(m2, factor, true));
    const Mesh m3 = wavy_interface_3d(48);
    expect_identical(search(m3, factor, false), search(m3, factor, true));
  }
}
