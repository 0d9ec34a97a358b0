// Coarse search (kernels/coarse_search.hpp): the binned search must return exactly the
// brute-force candidate lists (of any length: graded surfaces put many fine master faces in one
// coarse slave box), and keep the candidate count per slave face bounded on 1e5 faces in
// reasonable time.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "kernels/coarse_search.hpp"

namespace {

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
  grout::SearchCandidates<Kokkos::HostSpace> crs;
  MortarStatus status = MortarStatus::ok;
  int count(size_t s) const { return crs.offsets(s + 1) - crs.offsets(s); }
  int id(size_t s, int c) const { return crs.masters(crs.offsets(s) + c); }
  size_t n_slave() const { return crs.offsets.extent(0) - 1; }
};

Candidates search(const Mesh& m, double factor, bool brute) {
  Candidates c;
  c.status = brute ? grout::coarse_search_brute_force(Kokkos::DefaultExecutionSpace(), m.slave,
                                                      m.master, m.coords, factor, c.crs)
                   : grout::coarse_search(m.slave, m.master, m.coords, factor, c.crs);
  return c;
}

void expect_identical(const Candidates& a, const Candidates& b) {
  ASSERT_EQ(a.status, b.status);
  ASSERT_EQ(a.n_slave(), b.n_slave());
  ASSERT_EQ(a.crs.n_pairs, b.crs.n_pairs);
  for (size_t s = 0; s < a.n_slave(); ++s) {
    ASSERT_EQ(a.count(s), b.count(s)) << "slave " << s;
    for (int c = 0; c < a.count(s); ++c) ASSERT_EQ(a.id(s, c), b.id(s, c)) << "slave " << s;
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
      for (size_t s = 0; s < binned.n_slave(); ++s) total += binned.count(s);
      EXPECT_GT(total, 0);
    }
}

TEST(CoarseSearch, LongCandidateListsKeptInFull) {
  // 400 masters inside one slave box: every one of them is a candidate, in ascending order.
  Mesh m = random_mesh(2, 1, 400, 0.0, 9);
  m.coords(0, 0) = 0.0, m.coords(0, 1) = 0.5, m.coords(1, 0) = 1.0, m.coords(1, 1) = 0.5;
  for (int k = 2; k < 802; ++k) m.coords(k, 1) = 0.5;
  const auto binned = search(m, 0.1, false), brute = search(m, 0.1, true);
  EXPECT_EQ(binned.status, MortarStatus::ok);
  expect_identical(binned, brute);
  ASSERT_EQ(binned.count(0), 400);
  for (int c = 0; c < 400; ++c) EXPECT_EQ(binned.id(0, c), c);
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
  int worst = 0, least = INT_MAX;
  for (size_t s = 0; s < c.n_slave(); ++s) {
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
  for (size_t s = 0; s < c.n_slave(); s += c.n_slave() / 97) {
    int k = 0;
    for (size_t m = 0; m < mesh.master.extent(0); ++m)
      if (grout::boxes_overlap(dim, s_boxes, s, m_boxes, m)) {
        ASSERT_EQ(c.id(s, k++), int(m));
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

namespace {
// Graded TRI3 surfaces on z = 0.1 sin(πx) sin(πy) over [0, 1]²: grid lines at t_i = (i/n)^3 in
// each direction (cells shrink as 3 t^(2/3)/n towards the origin), each cell cut into two
// triangles. The slave surface has n_s cells per direction and is graded towards (0, 0); the
// master has n_m per direction and is graded towards (1, 1) (coordinates mirrored), shifted by
// 1e-3 / n_m in z: coarse slave faces cover many fine master faces near (1, 1) and fine slave
// faces lie inside one coarse master face near (0, 0).
Mesh graded_triangle_surfaces(int n_s, int n_m) {
  const int n_nodes = (n_s + 1) * (n_s + 1) + (n_m + 1) * (n_m + 1);
  Mesh mesh{Kokkos::View<double**>("coords", n_nodes, 3),
            Kokkos::View<int**>("slave", 2 * n_s * n_s, 3),
            Kokkos::View<int**>("master", 2 * n_m * n_m, 3)};
  const double pi = 3.14159265358979323846;
  auto surface = [&](int n, int offset, bool mirrored, double dz, Kokkos::View<int**> faces) {
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const int id = offset + j * (n + 1) + i;
        double x = std::pow(static_cast<double>(i) / n, 3.0);
        double y = std::pow(static_cast<double>(j) / n, 3.0);
        if (mirrored) x = 1.0 - x, y = 1.0 - y;
        mesh.coords(id, 0) = x, mesh.coords(id, 1) = y;
        mesh.coords(id, 2) = 0.1 * std::sin(pi * x) * std::sin(pi * y) + dz;
      }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int a = offset + j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
        const int f = 2 * (j * n + i);
        faces(f, 0) = a, faces(f, 1) = b, faces(f, 2) = c;
        faces(f + 1, 0) = a, faces(f + 1, 1) = c, faces(f + 1, 2) = d;
      }
  };
  surface(n_s, 0, false, 0.0, mesh.slave);
  surface(n_m, (n_s + 1) * (n_s + 1), true, 1e-3 / n_m, mesh.master);
  return mesh;
}
}  // namespace

// Graded triangle surfaces (element sizes from ~1e-4 to ~0.2): some slave faces have far more
// than 32 candidates, and every list equals the brute-force one.
TEST(CoarseSearch, IdenticalToBruteForceOnGradedTriangleSurfaces) {
  for (const double factor : {0.1, 0.5}) {
    const Mesh m = graded_triangle_surfaces(24, 40);
    const auto binned = search(m, factor, false), brute = search(m, factor, true);
    expect_identical(binned, brute);
    int worst = 0, least = INT_MAX;
    for (size_t s = 0; s < binned.n_slave(); ++s) {
      worst = std::max(worst, binned.count(s));
      least = std::min(least, binned.count(s));
    }
    std::printf("factor %.1f: candidates per slave face %d..%d\n", factor, least, worst);
    EXPECT_GT(worst, 32);
    EXPECT_GE(least, 1);
  }
}
