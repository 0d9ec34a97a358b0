// The slave frames launch (kernels/slave_frames.hpp): its values against the nodal normals and
// tangents launches (surface_normals.hpp), and its derivatives against central differences of
// those values, on a curved 2D polyline and on a curved 3D patch of QUAD4 and TRI3 faces.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "kernels/slave_frames.hpp"
#include "kernels/surface_normals.hpp"

namespace grout {
namespace {

struct Surface {
  int dim;
  std::vector<std::vector<int>> faces;  // node lists
  std::vector<double> x;                // n_nodes × dim
};

// Five LINE2 faces on an arc y = 0.3 x², nodes unevenly spaced.
Surface arc_2d() {
  Surface s{2, {}, {}};
  const double xs[] = {-1.0, -0.55, -0.1, 0.2, 0.7, 1.05};
  for (double x : xs) s.x.insert(s.x.end(), {x, 0.3 * x * x});
  for (int f = 0; f < 5; ++f) s.faces.push_back({f, f + 1});
  return s;
}

// A 3 × 3 grid of nodes on z = 0.2 x² + 0.1 x y − 0.15 y², jittered, with two QUAD4 faces and
// four TRI3 faces (the other two quadrants split), all oriented alike.
Surface patch_3d() {
  Surface s{3, {}, {}};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const double x = i - 1.0 + 0.07 * ((i * 7 + j * 3) % 5 - 2);
      const double y = j - 1.0 + 0.05 * ((i * 2 + j * 5) % 4 - 1.5);
      s.x.insert(s.x.end(), {x, y, 0.2 * x * x + 0.1 * x * y - 0.15 * y * y});
    }
  const auto n = [](int i, int j) { return j * 3 + i; };
  s.faces.push_back({n(0, 0), n(1, 0), n(1, 1), n(0, 1)});
  s.faces.push_back({n(1, 1), n(2, 1), n(2, 2), n(1, 2)});
  s.faces.push_back({n(1, 0), n(2, 0), n(2, 1)});
  s.faces.push_back({n(1, 0), n(2, 1), n(1, 1)});
  s.faces.push_back({n(0, 1), n(1, 1), n(1, 2)});
  s.faces.push_back({n(0, 1), n(1, 2), n(0, 2)});
  return s;
}

struct Frames {
  Kokkos::View<int*> offsets, node_faces;
  Kokkos::View<double**> values;
  Kokkos::View<double***> gradients;
};

template <int Dim>
Frames frames_of(const Surface& s, bool derivatives) {
  const int n_nodes = int(s.x.size()) / Dim;
  Kokkos::View<int**> faces("faces", s.faces.size(), max_face_nodes);
  Kokkos::deep_copy(faces, -1);
  for (std::size_t f = 0; f < s.faces.size(); ++f)
    for (std::size_t a = 0; a < s.faces[f].size(); ++a) faces(f, a) = s.faces[f][a];
  Kokkos::View<double**> coords("coords", n_nodes, Dim);
  for (int i = 0; i < n_nodes; ++i)
    for (int d = 0; d < Dim; ++d) coords(i, d) = s.x[i * Dim + d];
  Frames r;
  r.offsets = Kokkos::View<int*>("offsets", n_nodes + 1);
  std::vector<int> list;
  for (int i = 0; i < n_nodes; ++i) {
    for (std::size_t f = 0; f < s.faces.size(); ++f)
      for (int node : s.faces[f])
        if (node == i) list.push_back(int(f));
    r.offsets(i + 1) = int(list.size());
  }
  r.node_faces = Kokkos::View<int*>("node_faces", list.size());
  for (std::size_t q = 0; q < list.size(); ++q) r.node_faces(q) = list[q];
  r.values = Kokkos::View<double**>("frames", n_nodes, Dim * Dim);
  r.gradients = Kokkos::View<double***>("gradients", list.size(), Dim * Dim, max_face_nodes * Dim);
  const MortarStatus st =
      compute_slave_frames<Dim>(Kokkos::DefaultExecutionSpace(), faces, coords, r.offsets,
                                r.node_faces, derivatives, r.values, r.gradients);
  EXPECT_EQ(st, MortarStatus::ok);
  return r;
}

template <int Dim>
void check_values(const Surface& s) {
  const int n_nodes = int(s.x.size()) / Dim;
  const Frames f = frames_of<Dim>(s, true);
  const Frames plain = frames_of<Dim>(s, false);
  Kokkos::View<int**> faces("faces", s.faces.size(), max_face_nodes);
  Kokkos::deep_copy(faces, -1);
  for (std::size_t e = 0; e < s.faces.size(); ++e)
    for (std::size_t a = 0; a < s.faces[e].size(); ++a) faces(e, a) = s.faces[e][a];
  Kokkos::View<double**> coords("coords", n_nodes, Dim), normals("normals", n_nodes, Dim);
  Kokkos::View<double***> tangents("tangents", n_nodes, Dim - 1, Dim);
  for (int i = 0; i < n_nodes; ++i)
    for (int d = 0; d < Dim; ++d) coords(i, d) = s.x[i * Dim + d];
  ASSERT_EQ(compute_nodal_normals(faces, coords, normals), MortarStatus::ok);
  compute_nodal_tangents(normals, tangents);
  using L = SlaveFrameLayout<Dim>;
  for (int i = 0; i < n_nodes; ++i)
    for (int d = 0; d < Dim; ++d) {
      EXPECT_NEAR(f.values(i, L::normal(d)), normals(i, d), 1e-15) << i << " " << d;
      EXPECT_EQ(f.values(i, L::normal(d)), plain.values(i, L::normal(d)));
      for (int k = 0; k < Dim - 1; ++k)
        EXPECT_NEAR(f.values(i, L::tangent(k, d)), tangents(i, k, d), 1e-15) << i << " " << k;
    }
}

// ∂frame/∂x summed over the node's faces (a node in several faces has a column in each)
// against (frame(x + h e) − frame(x − h e)) / 2h for every coordinate of the surface.
template <int Dim>
void check_derivatives(const Surface& s) {
  using L = SlaveFrameLayout<Dim>;
  const int n_nodes = int(s.x.size()) / Dim;
  const Frames f = frames_of<Dim>(s, true);
  const double h = 1e-6;
  double worst = 0.0;
  for (int m = 0; m < n_nodes; ++m)
    for (int c = 0; c < Dim; ++c) {
      Surface plus = s, minus = s;
      plus.x[m * Dim + c] += h;
      minus.x[m * Dim + c] -= h;
      const Frames fp = frames_of<Dim>(plus, false), fm = frames_of<Dim>(minus, false);
      for (int i = 0; i < n_nodes; ++i)
        for (int r = 0; r < L::rows; ++r) {
          double exact = 0.0;
          for (int q = f.offsets(i); q < f.offsets(i + 1); ++q) {
            const auto& face = s.faces[f.node_faces(q)];
            for (std::size_t a = 0; a < face.size(); ++a)
              if (face[a] == m) exact += f.gradients(q, r, int(a) * Dim + c);
          }
          const double fd = (fp.values(i, r) - fm.values(i, r)) / (2 * h);
          EXPECT_NEAR(exact, fd, 1e-8) << "node " << i << " row " << r << " by x_" << m << "," << c;
          worst = std::max(worst, std::abs(exact - fd));
        }
    }
  ::testing::Test::RecordProperty("worst_difference", std::to_string(worst));
}

TEST(SlaveFrames, ValuesEqualTheNodalNormalsAndTangents2D) {
  check_values<2>(arc_2d());
}
TEST(SlaveFrames, ValuesEqualTheNodalNormalsAndTangents3D) {
  check_values<3>(patch_3d());
}
TEST(SlaveFrames, DerivativesMatchCentralDifferences2D) {
  check_derivatives<2>(arc_2d());
}
TEST(SlaveFrames, DerivativesMatchCentralDifferences3D) {
  check_derivatives<3>(patch_3d());
}

}  // namespace
}  // namespace grout
