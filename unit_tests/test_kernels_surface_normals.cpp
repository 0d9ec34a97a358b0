// Element normals, averaged nodal normals and tangents (kernels/surface_normals.hpp) against
// hand values, symmetry (regular polygon), axis-aligned cube faces, and finite differences.
#include <gtest/gtest.h>

#include <Sacado.hpp>

#include <array>
#include <cmath>

#include "kernels/surface_normals.hpp"

using grout::MortarStatus;

TEST(SurfaceNormals, ElementNormalsByHand) {
  const double line[2][2] = {{0.0, 0.0}, {2.0, 0.0}};
  double n2[2];
  ASSERT_EQ(grout::line2_normal(line, n2), MortarStatus::ok);
  EXPECT_DOUBLE_EQ(n2[0], 0.0);
  EXPECT_DOUBLE_EQ(n2[1], -1.0);  // (dx, dy) -> (dy, -dx), topology.hpp convention
  const double tri[3][3] = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}};
  double n[3];
  ASSERT_EQ(grout::tri3_normal(tri, n), MortarStatus::ok);
  EXPECT_DOUBLE_EQ(n[2], 1.0);
  // Non-planar quad: the centre normal is ∂x/∂ξ × ∂x/∂η at (0,0), here by central differences
  // of the bilinear map.
  const double quad[4][3] = {{0, 0, 0}, {1.2, -0.1, 0.2}, {1.1, 1.3, -0.1}, {-0.2, 0.9, 0.3}};
  auto x = [&](double xi, double eta, int d) {
    const double N[4] = {(1 - xi) * (1 - eta) / 4, (1 + xi) * (1 - eta) / 4,
                         (1 + xi) * (1 + eta) / 4, (1 - xi) * (1 + eta) / 4};
    return N[0] * quad[0][d] + N[1] * quad[1][d] + N[2] * quad[2][d] + N[3] * quad[3][d];
  };
  double a[3], b[3], ref[3];
  for (int d = 0; d < 3; ++d)
    a[d] = (x(1e-3, 0, d) - x(-1e-3, 0, d)), b[d] = (x(0, 1e-3, d) - x(0, -1e-3, d));
  grout::cross_product(a, b, ref);
  grout::normalize_vector<3>(ref);
  ASSERT_EQ(grout::quad4_normal(quad, n), MortarStatus::ok);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(n[d], ref[d], 1e-12);
  const double flat[3][3] = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  EXPECT_EQ(grout::tri3_normal(flat, n), MortarStatus::degenerate);
  EXPECT_TRUE(std::isfinite(n[0]));
}

TEST(SurfaceNormals, TangentsAreOrthonormalAndRightHanded) {
  const double n2[2] = {0.6, -0.8};
  double t2[2];
  grout::tangent_2d(n2, t2);
  EXPECT_NEAR(t2[0] * n2[0] + t2[1] * n2[1], 0.0, 1e-15);
  EXPECT_NEAR(n2[0] * t2[1] - n2[1] * t2[0], 1.0, 1e-15);  // e_z = n × τ
  for (const auto& v : {std::array<double, 3>{0, 0, 1}, std::array<double, 3>{1, 2, -2},
                        std::array<double, 3>{-3, 0.1, 0.2}}) {
    double n[3] = {v[0], v[1], v[2]}, t1[3], t2b[3], c[3];
    grout::normalize_vector<3>(n);
    grout::tangents_3d(n, t1, t2b);
    grout::cross_product(t1, t2b, c);
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(c[d], n[d], 1e-14);
    EXPECT_NEAR(t1[0] * n[0] + t1[1] * n[1] + t1[2] * n[2], 0.0, 1e-15);
    EXPECT_NEAR(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2], 1.0, 1e-15);
  }
}

TEST(SurfaceNormals, RegularPolygonNodalNormalsAreRadial) {
  const int n = 12;
  Kokkos::View<double**> coords("coords", n + 1, 2), normals("normals", n + 1, 2);
  Kokkos::View<int**> faces("faces", n, 2);
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i) {
    coords(i, 0) = 1.0 + 2.0 * std::cos(2 * pi * i / n);  // counter-clockwise, outward normals
    coords(i, 1) = -0.5 + 2.0 * std::sin(2 * pi * i / n);
    faces(i, 0) = i, faces(i, 1) = (i + 1) % n;
  }
  coords(n, 0) = 7.0;  // a node on no face keeps n = 0
  ASSERT_EQ(grout::compute_nodal_normals(faces, coords, normals), MortarStatus::ok);
  for (int i = 0; i < n; ++i) {
    EXPECT_NEAR(normals(i, 0), std::cos(2 * pi * i / n), 1e-14);
    EXPECT_NEAR(normals(i, 1), std::sin(2 * pi * i / n), 1e-14);
  }
  EXPECT_EQ(normals(n, 0), 0.0);
  Kokkos::View<double***> tangents("tangents", n + 1, 1, 2);
  grout::compute_nodal_tangents(normals, tangents);
  for (int i = 0; i < n; ++i) {
    EXPECT_NEAR(tangents(i, 0, 0), -std::sin(2 * pi * i / n), 1e-14);
    EXPECT_NEAR(tangents(i, 0, 1), std::cos(2 * pi * i / n), 1e-14);
  }
}

TEST(SurfaceNormals, CubeSurfaceMixedTriQuad) {
  // Unit cube, 8 corner nodes; faces outward (right-hand rule), x-faces split into triangles.
  // Reference: normalised sum over the faces containing a node of the known axis normal.
  Kokkos::View<double**> coords("coords", 8, 3), normals("normals", 8, 3);
  for (int i = 0; i < 8; ++i)
    for (int d = 0; d < 3; ++d) coords(i, d) = (i >> d) & 1;
  const int quads[4][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}};  // -z +z -y +y
  const double quad_n[4][3] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}};
  const int tris[4][3] = {{0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};  // -x, -x, +x, +x
  const double tri_n[4][3] = {{-1, 0, 0}, {-1, 0, 0}, {1, 0, 0}, {1, 0, 0}};
  Kokkos::View<int**> faces("faces", 8, 4);
  double ref[8][3] = {};
  for (int f = 0; f < 4; ++f)
    for (int k = 0; k < 4; ++k) {
      faces(f, k) = quads[f][k];
      for (int d = 0; d < 3; ++d) ref[quads[f][k]][d] += quad_n[f][d];
    }
  for (int f = 0; f < 4; ++f) {
    for (int k = 0; k < 3; ++k) {
      faces(4 + f, k) = tris[f][k];
      for (int d = 0; d < 3; ++d) ref[tris[f][k]][d] += tri_n[f][d];
    }
    faces(4 + f, 3) = -1;
  }
  ASSERT_EQ(grout::compute_nodal_normals(faces, coords, normals), MortarStatus::ok);
  for (int i = 0; i < 8; ++i) {
    grout::normalize_vector<3>(ref[i]);
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(normals(i, d), ref[i][d], 1e-14) << i;
  }
  Kokkos::View<double***> tangents("tangents", 8, 2, 3);
  grout::compute_nodal_tangents(normals, tangents);
  for (int i = 0; i < 8; ++i) {
    double t1[3] = {tangents(i, 0, 0), tangents(i, 0, 1), tangents(i, 0, 2)};
    double t2[3] = {tangents(i, 1, 0), tangents(i, 1, 1), tangents(i, 1, 2)}, c[3];
    grout::cross_product(t1, t2, c);
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(c[d], normals(i, d), 1e-14);
  }
}

TEST(SurfaceNormals, FadDerivativeOfQuadNormalMatchesFiniteDifferences) {
  using Fad = Sacado::Fad::SFad<double, 12>;
  const double x0[4][3] = {{0, 0, 0}, {1.2, -0.1, 0.2}, {1.1, 1.3, -0.1}, {-0.2, 0.9, 0.3}};
  Fad x[4][3], n[3];
  for (int k = 0; k < 4; ++k)
    for (int d = 0; d < 3; ++d) x[k][d] = Fad(12, 3 * k + d, x0[k][d]);
  ASSERT_EQ(grout::quad4_normal(x, n), MortarStatus::ok);
  const double h = 1e-6;
  for (int i = 0; i < 12; ++i) {
    double xp[4][3], xm[4][3], np[3], nm[3];
    for (int k = 0; k < 4; ++k)
      for (int d = 0; d < 3; ++d) xp[k][d] = xm[k][d] = x0[k][d];
    xp[i / 3][i % 3] += h;
    xm[i / 3][i % 3] -= h;
    grout::quad4_normal(xp, np);
    grout::quad4_normal(xm, nm);
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(n[d].dx(i), (np[d] - nm[d]) / (2 * h), 1e-8);
  }
}
