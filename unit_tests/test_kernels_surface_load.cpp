// Consistent nodal forces of pressure and traction loads, against closed-form resultants.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <tuple>
#include <utility>
#include <vector>

#include "kernels/surface_load.hpp"

namespace {

using grout::ElementStatus;
using grout::Topology;
using Vec3 = std::array<double, 3>;

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Vec3 point(const std::vector<double>& X, int a) {
  return {X[3 * a], X[3 * a + 1], X[3 * a + 2]};
}

Vec3 sub(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

/// Vector area of a 3D side: (1/2)(x1 - x0) x (x2 - x0) for a triangle, (1/2)(x2 - x0) x
/// (x3 - x1) (half the cross product of the diagonals) for a quad, which is exact for a bilinear
/// patch even when warped.
Vec3 vector_area(Topology t, const std::vector<double>& X) {
  const Vec3 c = t == Topology::tri3
                     ? cross(sub(point(X, 1), point(X, 0)), sub(point(X, 2), point(X, 0)))
                     : cross(sub(point(X, 2), point(X, 0)), sub(point(X, 3), point(X, 1)));
  return {0.5 * c[0], 0.5 * c[1], 0.5 * c[2]};
}

/// int_T g dA over the triangle (a, b, c) for g quadratic: area/3 * sum of g at the edge
/// midpoints (exact for degree 2; Strang & Fix table 4.1).
template <class G>
Vec3 integrate_triangle(const Vec3& a, const Vec3& b, const Vec3& c, G g) {
  const Vec3 n = cross(sub(b, a), sub(c, a));
  const double area = 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  Vec3 sum{0, 0, 0};
  for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
    const Vec3 mid{0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2])};
    const Vec3 v = g(mid);
    for (int i = 0; i < 3; ++i) sum[i] += area / 3.0 * v[i];
  }
  return sum;
}

}  // namespace

TEST(SurfaceLoad, UniformPressureOnEdgeFollowsOrientation) {
  // Edge (0,0) -> (2,0) of a body lying above it: outward normal -y, pressure pushes +y.
  const double p = 3.0, X[4] = {0, 0, 2, 0}, p_nodal[2] = {p, p};
  double f[4];
  ASSERT_EQ(grout::surface_load(Topology::line2, 2, X, p_nodal, nullptr, f), ElementStatus::ok);
  const double expected[4] = {0, p, 0, p};  // -p n L / 2 per node
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(f[k], expected[k], 1e-14);
  // Reversed node order: outward normal +y, force -y.
  const double X_reversed[4] = {2, 0, 0, 0};
  ASSERT_EQ(grout::surface_load(Topology::line2, 2, X_reversed, p_nodal, nullptr, f),
            ElementStatus::ok);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(f[k], -expected[k], 1e-14);
  // Inclined edge: total force -p n L with n L = (dy, -dx).
  const double Xi[4] = {1, 2, 4, 6};
  ASSERT_EQ(grout::surface_load(Topology::line2, 2, Xi, p_nodal, nullptr, f), ElementStatus::ok);
  EXPECT_NEAR(f[0] + f[2], -p * 4.0, 1e-13);
  EXPECT_NEAR(f[1] + f[3], p * 3.0, 1e-13);
}

TEST(SurfaceLoad, PositivePressureOnUpwardFaceActsDownward) {
  // Counter-clockwise seen from +z: outward normal +z, so positive pressure pushes along -z.
  const double p = 2.0, p_nodal[4] = {p, p, p, p};
  const std::vector<double> tri = {0, 0, 1, 2, 0, 1, 0, 3, 1};            // area 3
  const std::vector<double> quad = {0, 0, 0, 2, 0, 0, 3, 1, 0, 0, 1, 0};  // trapezoid, area 2.5
  for (const auto& [t, X, area] :
       {std::tuple{Topology::tri3, tri, 3.0}, std::tuple{Topology::quad4, quad, 2.5}}) {
    const int nodes = grout::topology_num_nodes(t);
    double f[12];
    ASSERT_EQ(grout::surface_load(t, 3, X.data(), p_nodal, nullptr, f), ElementStatus::ok);
    double total[3] = {0, 0, 0};
    for (int a = 0; a < nodes; ++a)
      for (int i = 0; i < 3; ++i) total[i] += f[3 * a + i];
    EXPECT_NEAR(total[0], 0.0, 1e-14);
    EXPECT_NEAR(total[1], 0.0, 1e-14);
    EXPECT_NEAR(total[2], -p * area, 1e-13);
    for (int a = 0; a < nodes; ++a) EXPECT_LT(f[3 * a + 2], 0.0);
  }
}

TEST(SurfaceLoad, UniformPressureResultantOnInclinedAndWarpedFaces) {
  const double p = 1.7, p_nodal[4] = {p, p, p, p};
  const std::vector<double> tri = {0.2, -0.1, 0.4, 1.9, 0.5, -0.3, 0.1, 1.4, 1.1};
  const std::vector<double> warped = {0, 0, 0, 2, 0.1, 0.3, 2.2, 1.7, -0.2, -0.1, 1.5, 0.4};
  for (const auto& [t, X] : {std::pair{Topology::tri3, tri}, std::pair{Topology::quad4, warped}}) {
    const int nodes = grout::topology_num_nodes(t);
    double f[12];
    ASSERT_EQ(grout::surface_load(t, 3, X.data(), p_nodal, nullptr, f), ElementStatus::ok);
    const Vec3 A = vector_area(t, X);
    for (int i = 0; i < 3; ++i) {
      double total = 0.0;
      for (int a = 0; a < nodes; ++a) total += f[3 * a + i];
      EXPECT_NEAR(total, -p * A[i], 1e-13) << "topology " << int(t) << " component " << i;
    }
  }
}

TEST(SurfaceLoad, LinearTractionOnEdgeGivesForceAndMoment) {
  // t = (0, q(x)), q linear from q0 to q1 on [0, L]: resultant (q0 + q1) L / 2, moment about
  // node 0 int x q dx = L^2 (q0 / 6 + q1 / 3).
  const double L = 3.0, q0 = 2.0, q1 = 5.0;
  const double X[4] = {0, 0, L, 0}, t_nodal[4] = {0, q0, 0, q1};
  double f[4];
  ASSERT_EQ(grout::surface_load(Topology::line2, 2, X, nullptr, t_nodal, f), ElementStatus::ok);
  EXPECT_NEAR(f[0], 0.0, 1e-14);
  EXPECT_NEAR(f[2], 0.0, 1e-14);
  EXPECT_NEAR(f[1] + f[3], (q0 + q1) * L / 2, 1e-13);
  EXPECT_NEAR(f[3] * L, L * L * (q0 / 6 + q1 / 3), 1e-13);
}

TEST(SurfaceLoad, LinearTractionAndPressureOnFacesGiveForceAndMoment) {
  // t(x) = t0 + G x and p(x) = p0 + g . x are reproduced by the isoparametric interpolation, so
  // sum_a f_a = int (t - p n) dA and sum_a x_a x f_a = int x x (t - p n) dA exactly (planar
  // sides). Reference: split into triangles, integrate with the edge-midpoint rule.
  const Vec3 t0{0.3, -1.2, 0.7}, g{0.4, -0.2, 0.9};
  const double G[3][3] = {{0.5, -0.3, 0.2}, {0.1, 0.8, -0.6}, {-0.4, 0.2, 0.3}};
  const double p0 = 1.5;
  const Vec3 e1{1.0, 0.2, 0.3}, e2{-0.1, 0.9, 0.4}, origin{0.3, -0.2, 0.5};  // an inclined plane
  auto in_plane = [&](double s, double r) {
    return Vec3{origin[0] + s * e1[0] + r * e2[0], origin[1] + s * e1[1] + r * e2[1],
                origin[2] + s * e1[2] + r * e2[2]};
  };
  const Vec3 nA = cross(e1, e2);
  const double nA_norm = std::sqrt(nA[0] * nA[0] + nA[1] * nA[1] + nA[2] * nA[2]);
  const Vec3 n{nA[0] / nA_norm, nA[1] / nA_norm, nA[2] / nA_norm};
  auto load = [&](const Vec3& x) {
    const double p = p0 + g[0] * x[0] + g[1] * x[1] + g[2] * x[2];
    Vec3 v;
    for (int i = 0; i < 3; ++i)
      v[i] = t0[i] + G[i][0] * x[0] + G[i][1] * x[1] + G[i][2] * x[2] - p * n[i];
    return v;
  };
  auto moment = [&](const Vec3& x) { return cross(x, load(x)); };

  const std::vector<std::vector<std::array<double, 2>>> sides = {
      {{0, 0}, {2, 0.3}, {0.4, 1.5}},                // tri3
      {{0, 0}, {2, 0.2}, {2.4, 1.7}, {-0.3, 1.2}}};  // quad4, a general planar quadrilateral
  for (const auto& params : sides) {
    const int nodes = static_cast<int>(params.size());
    const Topology t = nodes == 3 ? Topology::tri3 : Topology::quad4;
    std::vector<double> X, p_nodal, t_nodal;
    std::vector<Vec3> x;
    for (const auto& sr : params) {
      x.push_back(in_plane(sr[0], sr[1]));
      const Vec3& xa = x.back();
      X.insert(X.end(), xa.begin(), xa.end());
      p_nodal.push_back(p0 + g[0] * xa[0] + g[1] * xa[1] + g[2] * xa[2]);
      for (int i = 0; i < 3; ++i)
        t_nodal.push_back(t0[i] + G[i][0] * xa[0] + G[i][1] * xa[1] + G[i][2] * xa[2]);
    }
    double f[12];
    ASSERT_EQ(grout::surface_load(t, 3, X.data(), p_nodal.data(), t_nodal.data(), f),
              ElementStatus::ok);

    Vec3 force_ref{0, 0, 0}, moment_ref{0, 0, 0};
    for (int k = 1; k + 1 < nodes; ++k) {  // fan triangulation (0, k, k+1)
      const Vec3 fk = integrate_triangle(x[0], x[k], x[k + 1], load);
      const Vec3 mk = integrate_triangle(x[0], x[k], x[k + 1], moment);
      for (int i = 0; i < 3; ++i) force_ref[i] += fk[i], moment_ref[i] += mk[i];
    }
    Vec3 force{0, 0, 0}, moment_sum{0, 0, 0};
    for (int a = 0; a < nodes; ++a) {
      const Vec3 fa{f[3 * a], f[3 * a + 1], f[3 * a + 2]};
      const Vec3 ma = cross(x[a], fa);
      for (int i = 0; i < 3; ++i) force[i] += fa[i], moment_sum[i] += ma[i];
    }
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(force[i], force_ref[i], 1e-12) << "nodes " << nodes << " component " << i;
      EXPECT_NEAR(moment_sum[i], moment_ref[i], 1e-12) << "nodes " << nodes << " component " << i;
    }
  }
}

TEST(SurfaceLoad, NoLoadAndUnsupportedSides) {
  const double X[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  double f[12];
  for (double& v : f) v = 99.0;
  ASSERT_EQ(grout::surface_load(Topology::quad4, 3, X, nullptr, nullptr, f), ElementStatus::ok);
  for (double v : f) EXPECT_EQ(v, 0.0);
  const double p[4] = {1, 1, 1, 1};
  EXPECT_EQ(grout::surface_load(Topology::quad4, 2, X, p, nullptr, f), ElementStatus::unsupported);
  EXPECT_EQ(grout::surface_load(Topology::line2, 3, X, p, nullptr, f), ElementStatus::unsupported);
  EXPECT_EQ(grout::surface_load(Topology::hex8, 3, X, p, nullptr, f), ElementStatus::unsupported);
}
