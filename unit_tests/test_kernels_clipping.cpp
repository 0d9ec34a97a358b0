// clip_polygons (kernels/polygon_clipping.hpp) against hand-built overlaps with analytic
// polygons and areas, including the degenerate cases (coincident edges and vertices,
// identical polygons, touching at a point or along an edge) and a random symmetry test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "kernels/polygon_clipping.hpp"

namespace {

using grout::max_clip_vertices;
using grout::MortarStatus;

struct Poly {
  int n = 0;
  double p[max_clip_vertices][2];
};

Poly make(std::vector<std::pair<double, double>> v) {
  Poly q;
  q.n = static_cast<int>(v.size());
  for (int i = 0; i < q.n; ++i) q.p[i][0] = v[i].first, q.p[i][1] = v[i].second;
  return q;
}

Poly rect(double x0, double y0, double x1, double y1) {
  return make({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}

Poly reversed(const Poly& a) {
  Poly r = a;
  for (int i = 0; i < a.n; ++i) r.p[i][0] = a.p[a.n - 1 - i][0], r.p[i][1] = a.p[a.n - 1 - i][1];
  return r;
}

struct Clip {
  MortarStatus status;
  Poly poly;
  double area;
};

Clip clip(const Poly& a, const Poly& b) {
  Clip c;
  c.status = grout::clip_polygons(a.n, a.p, b.n, b.p, c.poly.p, c.poly.n);
  c.area = grout::polygon_signed_area(c.poly.n, c.poly.p);
  for (int i = 0; i < c.poly.n; ++i) {
    EXPECT_TRUE(std::isfinite(c.poly.p[i][0]) && std::isfinite(c.poly.p[i][1]));
  }
  return c;
}

/// The result equals `expected` as a cyclic, counter-clockwise vertex list.
void expect_polygon(const Poly& result, const Poly& expected, double tol = 1e-14) {
  ASSERT_EQ(result.n, expected.n);
  int shift = -1;
  for (int s = 0; s < result.n && shift < 0; ++s)
    if (std::abs(result.p[s][0] - expected.p[0][0]) < tol &&
        std::abs(result.p[s][1] - expected.p[0][1]) < tol)
      shift = s;
  ASSERT_GE(shift, 0) << "first expected vertex not found";
  for (int i = 0; i < expected.n; ++i) {
    const int k = (i + shift) % result.n;
    EXPECT_NEAR(result.p[k][0], expected.p[i][0], tol) << "vertex " << i;
    EXPECT_NEAR(result.p[k][1], expected.p[i][1], tol) << "vertex " << i;
  }
}

TEST(PolygonClipping, FullyInside) {
  const Clip c = clip(rect(0, 0, 1, 1), rect(0.25, 0.3, 0.5, 0.7));
  EXPECT_EQ(c.status, MortarStatus::ok);
  expect_polygon(c.poly, rect(0.25, 0.3, 0.5, 0.7));
  EXPECT_NEAR(c.area, 0.25 * 0.4, 1e-15);
  const Clip d = clip(rect(0.25, 0.3, 0.5, 0.7), rect(0, 0, 1, 1));
  expect_polygon(d.poly, rect(0.25, 0.3, 0.5, 0.7));
}

TEST(PolygonClipping, PartialSquares) {
  const Clip c = clip(rect(0, 0, 1, 1), rect(0.5, 0.25, 1.5, 1.25));
  EXPECT_EQ(c.status, MortarStatus::ok);
  expect_polygon(c.poly, rect(0.5, 0.25, 1, 1));
  EXPECT_NEAR(c.area, 0.375, 1e-15);
}

TEST(PolygonClipping, TriangleTriangle) {
  // x, y ≥ 0, x + y ≤ 1  ∩  y ≥ 0, x ≤ 1, y ≤ x  =  triangle (0,0), (1,0), (0.5,0.5)
  const Clip c = clip(make({{0, 0}, {1, 0}, {0, 1}}), make({{0, 0}, {1, 0}, {1, 1}}));
  EXPECT_EQ(c.status, MortarStatus::ok);
  expect_polygon(c.poly, make({{0, 0}, {1, 0}, {0.5, 0.5}}));
  EXPECT_NEAR(c.area, 0.25, 1e-15);
}

TEST(PolygonClipping, HexagonAndOctagon) {
  // equilateral triangle and its point reflection through the centroid: hexagon, 2/3 area
  const double s3 = std::sqrt(3.0);
  const Poly t = make({{-1, -1 / s3}, {1, -1 / s3}, {0, 2 / s3}});
  const Poly u = make({{1, 1 / s3}, {-1, 1 / s3}, {0, -2 / s3}});
  const Clip c = clip(t, u);
  EXPECT_EQ(c.status, MortarStatus::ok);
  EXPECT_EQ(c.poly.n, 6);
  EXPECT_NEAR(c.area, 2.0 / 3.0 * s3, 1e-14);
  // square [-1,1]² and the square rotated by 45° with the same centre and inradius √2/... :
  // vertices (±√2, 0), (0, ±√2) -> regular octagon of inradius 1, area 8 tan(π/8)
  const double r2 = std::sqrt(2.0);
  const Clip o = clip(rect(-1, -1, 1, 1), make({{r2, 0}, {0, r2}, {-r2, 0}, {0, -r2}}));
  EXPECT_EQ(o.status, MortarStatus::ok);
  EXPECT_EQ(o.poly.n, 8);  // = max_clip_vertices
  EXPECT_NEAR(o.area, 8.0 * std::tan(M_PI / 8.0), 1e-14);
}

TEST(PolygonClipping, Disjoint) {
  const Clip c = clip(rect(0, 0, 1, 1), rect(2, 0, 3, 1));
  EXPECT_EQ(c.status, MortarStatus::no_overlap);
  EXPECT_EQ(c.poly.n, 0);
  const Clip d = clip(make({{0, 0}, {1, 0}, {0, 1}}), rect(0.6, 0.6, 2, 2));  // beyond the
  EXPECT_EQ(d.status, MortarStatus::no_overlap);                              // hypotenuse
}

TEST(PolygonClipping, CoincidentEdges) {
  // shared vertical edges x = 0 and x = 1
  const Clip c = clip(rect(0, 0, 1, 1), rect(0, 0.5, 1, 1.5));
  EXPECT_EQ(c.status, MortarStatus::ok);
  expect_polygon(c.poly, rect(0, 0.5, 1, 1));
  EXPECT_NEAR(c.area, 0.5, 1e-15);
  // one shared edge, the clip polygon inside
  const Clip d = clip(rect(0, 0, 1, 1), rect(0, 0, 0.5, 0.5));
  expect_polygon(d.poly, rect(0, 0, 0.5, 0.5));
  // a shifted grid of edges slightly off by round-off: 0.1 + 0.2 != 0.3
  const Clip e = clip(rect(0.3, 0, 1, 1), rect(0.1 + 0.2, 0, 2, 0.5));
  EXPECT_EQ(e.status, MortarStatus::ok);
  EXPECT_EQ(e.poly.n, 4);
  EXPECT_NEAR(e.area, 0.35, 1e-15);
}

TEST(PolygonClipping, CoincidentVertices) {
  // the triangle's vertices are the square's vertices
  const Poly t = make({{0, 0}, {1, 0}, {0, 1}});
  const Clip c = clip(rect(0, 0, 1, 1), t);
  EXPECT_EQ(c.status, MortarStatus::ok);
  expect_polygon(c.poly, t);
  EXPECT_NEAR(c.area, 0.5, 1e-15);
  // diagonal quad through the square's corners: (0,0) and (1,1) shared
  const Clip d = clip(rect(0, 0, 1, 1), make({{0, 0}, {2, 1}, {1, 1}, {-1, 0}}));
  EXPECT_EQ(d.status, MortarStatus::ok);
  EXPECT_NEAR(d.area, 0.5, 1e-15);  // band x/2 ≤ y ≤ (x + 1)/2 of the square
}

TEST(PolygonClipping, IdenticalPolygons) {
  for (const Poly& a : {rect(0, 0, 1, 1), make({{0.1, 0.2}, {1.3, -0.1}, {0.4, 0.9}}),
                        make({{0, 0}, {1.2, 0.1}, {1.0, 1.1}, {-0.2, 0.8}})}) {
    const Clip c = clip(a, a);
    EXPECT_EQ(c.status, MortarStatus::ok);
    expect_polygon(c.poly, a);
    EXPECT_NEAR(c.area, grout::polygon_signed_area(a.n, a.p), 1e-15);
    // opposite orientation of one input (a master facing the slave): same polygon, CCW
    const Clip d = clip(a, reversed(a));
    expect_polygon(d.poly, a);
    const Clip e = clip(reversed(a), reversed(a));
    expect_polygon(e.poly, a);
  }
}

TEST(PolygonClipping, TouchingIsEmpty) {
  const Poly sq = rect(0, 0, 1, 1);
  // along an edge, at a point, at a point of an edge, at a vertex of a triangle
  for (const Poly& b :
       {rect(1, 0, 2, 1), rect(1, 1, 2, 2), rect(1, -0.5, 2, 0.5), rect(0.2, 1, 0.7, 3),
        make({{1, 0.5}, {2, 0}, {2, 1}}), make({{1, 1}, {2, 1}, {1, 2}})}) {
    const Clip c = clip(sq, b);
    EXPECT_EQ(c.status, MortarStatus::no_overlap);
    EXPECT_EQ(c.poly.n, 0);
    const Clip d = clip(b, sq);
    EXPECT_EQ(d.status, MortarStatus::no_overlap);
  }
}

TEST(PolygonClipping, SliverRemoved) {
  const Clip c = clip(rect(0, 0, 1, 1), rect(1 - 1e-14, 0, 2, 1));
  EXPECT_EQ(c.status, MortarStatus::no_overlap);
  const Clip d = clip(rect(0, 0, 1, 1), rect(1 - 1e-9, 0, 2, 1));  // thin but kept
  EXPECT_EQ(d.status, MortarStatus::ok);
  EXPECT_NEAR(d.area, 1e-9, 1e-16);  // 1 - (1 - 1e-9) in double
}

TEST(PolygonClipping, DegenerateInput) {
  const Poly line = make({{0, 0}, {1, 0}, {2, 0}});
  Poly out;
  EXPECT_EQ(grout::clip_polygons(line.n, line.p, 4, rect(0, 0, 1, 1).p, out.p, out.n),
            MortarStatus::degenerate);
  EXPECT_EQ(out.n, 0);
}

/// Random convex quads and triangles: area(A ∩ B) = area(B ∩ A); every result vertex lies in
/// both polygons; the result is convex and counter-clockwise; area ≤ min(area A, area B).
TEST(PolygonClipping, RandomSymmetryAndContainment) {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<double> u(-0.25, 0.25);
  auto inside = [](const Poly& q, const double p[2]) {
    const double s = grout::polygon_signed_area(q.n, q.p) > 0 ? 1.0 : -1.0;
    for (int i = 0; i < q.n; ++i) {
      const double* a = q.p[i];
      const double* b = q.p[(i + 1) % q.n];
      if (s * ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])) < -1e-12)
        return false;
    }
    return true;
  };
  int n_overlaps = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const double ox = 1.5 * u(rng), oy = 1.5 * u(rng);
    const Poly a = make(
        {{u(rng), u(rng)}, {1 + u(rng), u(rng)}, {1 + u(rng), 1 + u(rng)}, {u(rng), 1 + u(rng)}});
    const Poly b = trial % 2 ? make({{ox + u(rng), oy + u(rng)},
                                     {ox + 1 + u(rng), oy + u(rng)},
                                     {ox + u(rng), oy + 1 + u(rng)}})
                             : reversed(rect(ox, oy, ox + 0.8, oy + 0.9));
    const Clip ab = clip(a, b), ba = clip(b, a);
    ASSERT_EQ(ab.status == MortarStatus::ok, ba.status == MortarStatus::ok);
    if (ab.status != MortarStatus::ok) continue;
    ++n_overlaps;
    EXPECT_NEAR(ab.area, ba.area, 1e-14);
    EXPECT_LE(ab.area, std::min(std::abs(grout::polygon_signed_area(a.n, a.p)),
                                std::abs(grout::polygon_signed_area(b.n, b.p))) +
                           1e-14);
    for (int i = 0; i < ab.poly.n; ++i) {
      EXPECT_TRUE(inside(a, ab.poly.p[i]) && inside(b, ab.poly.p[i]));
      const double* p0 = ab.poly.p[i];
      const double* p1 = ab.poly.p[(i + 1) % ab.poly.n];
      const double* p2 = ab.poly.p[(i + 2) % ab.poly.n];
      EXPECT_GE((p1[0] - p0[0]) * (p2[1] - p0[1]) - (p1[1] - p0[1]) * (p2[0] - p0[0]), -1e-14);
    }
  }
  EXPECT_GT(n_overlaps, 300);
}

}  // namespace
