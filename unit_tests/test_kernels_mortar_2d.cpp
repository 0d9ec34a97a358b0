// 2D mortar pair kernel (kernels/mortar_2d.hpp), dual basis, Gauss rule and weighted gap,
// each against an independent reference: hand/closed-form integrals, polynomial
// antiderivatives, Simpson's rule, very fine collocation, rigid motions, Kratos' expectations.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "kernels/coarse_search.hpp"
#include "kernels/dual_basis.hpp"
#include "kernels/gauss_line.hpp"
#include "kernels/mortar_2d.hpp"
#include "kernels/mortar_integrate.hpp"
#include "kernels/surface_normals.hpp"
#include "kernels/weighted_gap.hpp"

namespace {

using grout::MortarPairResult;
using grout::MortarStatus;
using P = std::array<double, 2>;

struct Pair2D {
  double xs[2][2], ns[2][2], xm[2][2];
};

// Slave a→b, master c→d, both slave nodal normals = element normal of the slave.
Pair2D flat_pair(P a, P b, P c, P d) {
  Pair2D p{{{a[0], a[1]}, {b[0], b[1]}}, {}, {{c[0], c[1]}, {d[0], d[1]}}};
  double n[2];
  grout::line2_normal(p.xs, n);
  for (int j = 0; j < 2; ++j) p.ns[j][0] = n[0], p.ns[j][1] = n[1];
  return p;
}

MortarPairResult<double> integrate(const Pair2D& p, MortarStatus expect = MortarStatus::ok) {
  MortarPairResult<double> r;
  EXPECT_EQ(grout::integrate_mortar_2d(p.xs, p.ns, p.xm, r), expect);
  return r;
}

// ∫_a^b (p0 + p1 x)(q0 + q1 x) dx by antiderivatives.
double int_lin_lin(double p0, double p1, double q0, double q1, double a, double b) {
  return p0 * q0 * (b - a) + (p0 * q1 + p1 * q0) * (b * b - a * a) / 2 +
         p1 * q1 * (b * b * b - a * a * a) / 3;
}

bool all_finite(const MortarPairResult<double>& r) {
  bool ok = std::isfinite(r.overlap);
  for (int j = 0; j < 2; ++j) {
    ok = ok && std::isfinite(r.D[j]);
    for (int l = 0; l < 2; ++l) ok = ok && std::isfinite(r.M[j][l]);
  }
  return ok;
}

// Averaged nodal normals of a polyline (LINE2 chain x[0]→x[1]→…).
std::vector<P> chain_normals(const std::vector<P>& x) {
  std::vector<P> n(x.size(), P{0, 0});
  for (size_t e = 0; e + 1 < x.size(); ++e) {
    const double xe[2][2] = {{x[e][0], x[e][1]}, {x[e + 1][0], x[e + 1][1]}};
    double ne[2];
    grout::line2_normal(xe, ne);
    for (int d = 0; d < 2; ++d) n[e][d] += ne[d], n[e + 1][d] += ne[d];
  }
  for (auto& v : n) {
    const double len = std::hypot(v[0], v[1]);
    v[0] /= len, v[1] /= len;
  }
  return n;
}

Pair2D chain_pair(const std::vector<P>& s, const std::vector<P>& ns, size_t e,
                  const std::vector<P>& m, size_t f) {
  Pair2D p;
  for (int k = 0; k < 2; ++k)
    for (int d = 0; d < 2; ++d) {
      p.xs[k][d] = s[e + k][d];
      p.ns[k][d] = ns[e + k][d];
      p.xm[k][d] = m[f + k][d];
    }
  return p;
}

// Arc of radius r through the given angles.
std::vector<P> arc(double r, const std::vector<double>& theta) {
  std::vector<P> x;
  for (double t : theta) x.push_back({r * std::cos(t), r * std::sin(t)});
  return x;
}

}  // namespace

TEST(GaussLine, ExactForDegree2nMinus1) {
  for (int n = 1; n <= grout::max_gauss_line_points; ++n)
    for (int k = 0; k <= 2 * n - 1; ++k) {
      double sum = 0.0, xi, w;
      for (int i = 0; i < n; ++i) {
        ASSERT_TRUE(grout::gauss_line_point(n, i, xi, w));
        sum += w * std::pow(xi, k);
      }
      EXPECT_NEAR(sum, k % 2 ? 0.0 : 2.0 / (k + 1), 1e-14) << "n=" << n << " k=" << k;
    }
  double xi, w;
  EXPECT_FALSE(grout::gauss_line_point(9, 0, xi, w));
}

TEST(DualBasis, Line2BiorthogonalBySimpson) {
  // Simpson's rule is exact for the quadratic Φ_j N_k; the element length is arbitrary.
  const double len = 2.7, det_j = len / 2;
  for (int j = 0; j < 2; ++j)
    for (int k = 0; k < 2; ++k) {
      double f[3], nj[3];
      for (int q = 0; q < 3; ++q) {
        const double xi = -1.0 + q;
        double Phi[2], N[2];
        grout::line2_dual_shape(xi, Phi);
        grout::line2_shape(xi, N);
        f[q] = Phi[j] * N[k];
        nj[q] = N[j];
      }
      const double lhs = det_j * (f[0] + 4 * f[1] + f[2]) / 3;
      const double rhs = j == k ? det_j * (nj[0] + 4 * nj[1] + nj[2]) / 3 : 0.0;
      EXPECT_NEAR(lhs, rhs, 1e-15);
    }
}

TEST(DualBasis, GeneralCoefficientsMatchClosedForm) {
  const double x[2][2] = {{0.3, -1.2}, {2.1, 0.4}};
  double A[2][2];
  ASSERT_EQ(grout::dual_basis_coefficients_line2(x, A), MortarStatus::ok);
  EXPECT_NEAR(A[0][0], 2.0, 1e-14);
  EXPECT_NEAR(A[0][1], -1.0, 1e-14);
  EXPECT_NEAR(A[1][0], -1.0, 1e-14);
  EXPECT_NEAR(A[1][1], 2.0, 1e-14);
  const double pt[2][2] = {{1.0, 1.0}, {1.0, 1.0}};
  EXPECT_EQ(grout::dual_basis_coefficients_line2(pt, A), MortarStatus::degenerate);
}

TEST(DualBasis, InvertSmallMatrix) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double A[4][4], Ai[4][4];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) A[i][j] = u(rng) + (i == j ? 3.0 : 0.0);
  ASSERT_EQ((grout::invert_small_matrix<double, 4>(A, Ai)), MortarStatus::ok);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = 0.0;
      for (int k = 0; k < 4; ++k) s += A[i][k] * Ai[k][j];
      EXPECT_NEAR(s, i == j ? 1.0 : 0.0, 1e-14);
    }
  const double S[2][2] = {{1.0, 2.0}, {2.0, 4.0}};
  double Si[2][2];
  EXPECT_EQ((grout::invert_small_matrix<double, 2>(S, Si)), MortarStatus::degenerate);
}

TEST(Mortar2D, HandComputedShiftedMaster) {
  // Slave [0,1] × {0}, master [0.25,1.5] at y = 0.2 (parallel, so χ is a vertical shift).
  // By hand in x: Φ₁ = 2 − 3x, Φ₂ = 3x − 1, N²₁ = (1.5 − x)/1.25, N²₂ = (x − 0.25)/1.25 on [0.25,
  // 1].
  const auto r = integrate(flat_pair({0, 0}, {1, 0}, {0.25, 0.2}, {1.5, 0.2}));
  EXPECT_NEAR(r.overlap, 0.75, 1e-15);
  EXPECT_NEAR(r.D[0], 0.09375, 1e-15);
  EXPECT_NEAR(r.D[1], 0.65625, 1e-15);
  EXPECT_NEAR(r.M[0][0], 0.15, 1e-15);
  EXPECT_NEAR(r.M[0][1], -0.05625, 1e-15);
  EXPECT_NEAR(r.M[1][0], 0.375, 1e-15);
  EXPECT_NEAR(r.M[1][1], 0.28125, 1e-15);
  // Reversed master orientation swaps the master columns.
  const auto q = integrate(flat_pair({0, 0}, {1, 0}, {1.5, -0.2}, {0.25, -0.2}));
  EXPECT_NEAR(q.M[0][1], 0.15, 1e-15);
  EXPECT_NEAR(q.M[1][0], 0.28125, 1e-15);
}

TEST(Mortar2D, RandomParallelPairsAgainstAntiderivatives) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 2.0);
  for (int t = 0; t < 200; ++t) {
    const double x0 = u(rng), x1 = x0 + 0.1 + std::abs(u(rng)), c = u(rng), d = u(rng);
    const double gap = 0.1 * u(rng);
    MortarPairResult<double> r;
    const Pair2D p = flat_pair({x0, 0}, {x1, 0}, {c, gap}, {d, gap});
    const MortarStatus s = grout::integrate_mortar_2d(p.xs, p.ns, p.xm, r);
    const double a = std::max(x0, std::min(c, d)), b = std::min(x1, std::max(c, d));
    if (b - a <= 1e-9 * (x1 - x0)) {
      EXPECT_TRUE(s == MortarStatus::no_overlap || std::abs(r.overlap) < 1e-8);
      continue;
    }
    ASSERT_EQ(s, MortarStatus::ok);
    const double L = x1 - x0;
    const double phi[2][2] = {{(2 * x1 + x0) / L, -3 / L}, {-(x1 + 2 * x0) / L, 3 / L}};
    const double nm[2][2] = {{d / (d - c), -1 / (d - c)}, {-c / (d - c), 1 / (d - c)}};
    EXPECT_NEAR(r.overlap, b - a, 1e-12);
    for (int j = 0; j < 2; ++j) {
      EXPECT_NEAR(r.D[j], int_lin_lin(phi[j][0], phi[j][1], 1, 0, a, b), 1e-11);
      for (int l = 0; l < 2; ++l)
        EXPECT_NEAR(r.M[j][l], int_lin_lin(phi[j][0], phi[j][1], nm[l][0], nm[l][1], a, b), 1e-10);
    }
  }
}

TEST(Mortar2D, CoverageCases) {
  // Fully covered: Σ D = slave length, Σ M = overlap, D = ∫N_j (biorthogonality).
  const double L = std::hypot(0.8, 0.6);
  auto full = integrate(flat_pair({0, 0}, {0.8, 0.6}, {1.6, 1.2 + 1e-3}, {-0.8, -0.6 + 1e-3}));
  EXPECT_NEAR(full.D[0] + full.D[1], L, 1e-14);
  EXPECT_NEAR(full.D[0], L / 2, 1e-14);
  EXPECT_NEAR(full.M[0][0] + full.M[0][1] + full.M[1][0] + full.M[1][1], L, 1e-14);
  // Partially covered: Σ_jl M = Σ_j D = overlap.
  auto part = integrate(flat_pair({0, 0}, {1, 0}, {0.6, 0.1}, {2, 0.1}));
  EXPECT_NEAR(part.overlap, 0.4, 1e-15);
  EXPECT_NEAR(part.D[0] + part.D[1], 0.4, 1e-15);
  EXPECT_NEAR(part.M[0][0] + part.M[0][1] + part.M[1][0] + part.M[1][1], 0.4, 1e-15);
  // Disjoint.
  auto none = integrate(flat_pair({0, 0}, {1, 0}, {1.5, 0.1}, {2, 0.1}), MortarStatus::no_overlap);
  EXPECT_EQ(none.overlap, 0.0);
  EXPECT_EQ(none.D[0], 0.0);
  EXPECT_EQ(none.M[1][1], 0.0);
}

TEST(Mortar2D, DegenerateConfigurationsGiveNoNaN) {
  // Coincident edge, same orientation: M = diag(D) = diag(L/2).
  auto same = integrate(flat_pair({0, 0}, {2, 0}, {0, 0}, {2, 0}));
  EXPECT_NEAR(same.M[0][0], 1.0, 1e-15);
  EXPECT_NEAR(same.M[0][1], 0.0, 1e-15);
  EXPECT_NEAR(same.D[1], 1.0, 1e-15);
  // Coincident node only (zero-length overlap), master collapsed to a point, master
  // perpendicular, slave of zero length: statuses, but every output finite and zero.
  integrate(flat_pair({0, 0}, {1, 0}, {1, 0}, {2, 0}), MortarStatus::no_overlap);
  integrate(flat_pair({0, 0}, {1, 0}, {0.5, 0.1}, {0.5, 0.1}), MortarStatus::no_overlap);
  integrate(flat_pair({0, 0}, {1, 0}, {0.5, 0.0}, {0.5, 1.0}), MortarStatus::no_overlap);
  Pair2D zero{{{1, 1}, {1, 1}}, {{0, 1}, {0, 1}}, {{0, 1.1}, {2, 1.1}}};
  MortarPairResult<double> r;
  EXPECT_EQ(grout::integrate_mortar_2d(zero.xs, zero.ns, zero.xm, r), MortarStatus::degenerate);
  EXPECT_TRUE(all_finite(r));
  EXPECT_EQ(grout::integrate_mortar_2d_collocation(zero.xs, zero.ns, zero.xm, 10, r),
            MortarStatus::degenerate);
  EXPECT_TRUE(all_finite(r));
  for (const auto& q : {flat_pair({0, 0}, {1, 0}, {1, 0}, {2, 0}),
                        flat_pair({0, 0}, {1, 0}, {0.5, 0.1}, {0.5, 0.1}),
                        flat_pair({0, 0}, {1, 0}, {0.5, 0.0}, {0.5, 1.0})}) {
    grout::integrate_mortar_2d(q.xs, q.ns, q.xm, r);
    EXPECT_TRUE(all_finite(r));
    EXPECT_EQ(r.overlap, 0.0);
  }
}

TEST(Mortar2D, KratosExactIntegrationLines) {
  // Kratos test_exact_integration.py line_1..3 (order 2): slave parameters of the Gauss points;
  // Kratos' weights are twice ours (its w = ŵ Δξ/2 · L, ours ŵ Δξ/2 · L/2 = physical weight).
  struct Case {
    Pair2D p;
    double xi[2], w;
  };
  const double r3 = 0.57735026918962576;
  const Case cases[3] = {{flat_pair({0, 0}, {1, 0}, {0, 0.001}, {1, 0.001}), {-r3, r3}, 1.0},
                         {flat_pair({0, 0}, {1, 0}, {0.5, 0.001}, {1.5, 0.001}),
                          {0.21132486540517492, 0.7886751345947951},
                          0.5},
                         {flat_pair({0, -0.5}, {1, 0.5}, {0, 0.5}, {1, 0.5}),
                          {0.21132486540517847, 0.7886751345948},
                          1 / std::sqrt(2.0)}};
  for (const auto& c : cases) {
    double xi[8], eta[8], w[8];
    ASSERT_EQ(grout::mortar_integration_points_2d(c.p.xs, c.p.ns, c.p.xm, 2, xi, eta, w),
              MortarStatus::ok);
    for (int g = 0; g < 2; ++g) {
      EXPECT_NEAR(xi[g], c.xi[g], 1e-7);
      EXPECT_NEAR(2 * w[g], c.w, 1e-7);
    }
  }
}

TEST(WeightedGap, KratosTwoMastersGapAndSlip) {
  // Kratos test_weighted_gap.cpp (2D): slave (0,1e-3)-(1,1e-3) over masters (0,0)-(1,0),
  // (1,0)-(2,0). g̃_j / ∫N_j = 1e-3; after the slave moves by δ = 0.5 in x, the weighted slip
  // divided by 0.5 is δ in magnitude (Kratos prints −δ: opposite sign convention).
  const double delta = 0.5;
  const double xm[3][2] = {{0, 0}, {1, 0}, {2, 0}};
  double g[2] = {0, 0}, slip[2] = {0, 0}, slip_obj[2] = {0, 0};
  for (int m = 0; m < 2; ++m) {
    const Pair2D p0 = flat_pair({0, 1e-3}, {1, 1e-3}, {xm[m][0], 0}, {xm[m + 1][0], 0});
    const Pair2D p1 = flat_pair({delta, 1e-3}, {1 + delta, 1e-3}, {xm[m][0], 0}, {xm[m + 1][0], 0});
    MortarPairResult<double> r0, r1;
    grout::integrate_mortar_2d(p0.xs, p0.ns, p0.xm, r0);
    grout::integrate_mortar_2d(p1.xs, p1.ns, p1.xm, r1);
    double gp[4], sp[4], so[4];
    grout::weighted_gap_pair<2>(r0, p0.xs, p0.ns, p0.xm, gp);
    double tau[2][2], dxs[2][2] = {{delta, 0}, {delta, 0}}, dxm[2][2] = {{0, 0}, {0, 0}};
    for (int j = 0; j < 2; ++j) grout::tangent_2d(p1.ns[j], tau[j]);
    grout::weighted_slip_increment_pair<2>(r1, dxs, tau, dxm, sp);
    grout::weighted_slip_increment_objective_pair<2>(r1, r0, p1.xs, tau, p1.xm, so);
    for (int j = 0; j < 2; ++j) g[j] += gp[j], slip[j] += sp[j], slip_obj[j] += so[j];
  }
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(g[j] / 0.5, 1e-3, 1e-3 * 1e-4);
    EXPECT_NEAR(slip[j] / 0.5, delta, delta * 1e-4);
    EXPECT_NEAR(slip_obj[j] / 0.5, delta, delta * 1e-4);
  }
}

TEST(Mortar2D, PatchTestNonMatchingFlatInterface) {
  // Σ_pairs Σ_l M_jl f(x²_l) = D_jj f(x¹_j) for linear f (biorthogonality, docs/design.md §3), on a
  // tilted flat interface; coincident lines for a general f, a gap for a tangential f.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double c = std::cos(0.4), s = std::sin(0.4);
  auto line = [&](std::vector<double> t, double off) {
    std::sort(t.begin(), t.end());
    std::vector<P> x;
    for (double v : t) x.push_back({c * v + s * off, s * v - c * off});
    return x;
  };
  std::vector<double> ts = {0.0, 1.0}, tm = {-0.2, 1.2};
  for (int i = 0; i < 6; ++i) ts.push_back(u(rng));
  for (int i = 0; i < 8; ++i) tm.push_back(1.4 * u(rng) - 0.2);
  std::sort(ts.begin(), ts.end());
  for (double off : {0.0, 0.05}) {
    const auto xs = line(ts, 0.0);
    auto xm = line(tm, off);
    std::reverse(xm.begin(), xm.end());  // master oriented against the slave, as in contact
    const auto ns = chain_normals(xs);
    auto f = [&](const P& x) {
      return off == 0.0 ? 1.0 + 2 * x[0] - 3 * x[1] : 0.5 + c * x[0] + s * x[1];
    };
    std::vector<double> D(xs.size(), 0.0), Mf(xs.size(), 0.0);
    for (size_t e = 0; e + 1 < xs.size(); ++e)
      for (size_t m = 0; m + 1 < xm.size(); ++m) {
        const Pair2D p = chain_pair(xs, ns, e, xm, m);
        MortarPairResult<double> r;
        const MortarStatus st = grout::integrate_mortar_2d(p.xs, p.ns, p.xm, r);
        ASSERT_TRUE(st == MortarStatus::ok || st == MortarStatus::no_overlap);
        for (int j = 0; j < 2; ++j) {
          D[e + j] += r.D[j];
          for (int l = 0; l < 2; ++l) Mf[e + j] += r.M[j][l] * f(xm[m + l]);
        }
      }
    for (size_t j = 0; j < xs.size(); ++j) {
      const double lo = j > 0 ? ts[j] - ts[j - 1] : 0.0;
      const double hi = j + 1 < xs.size() ? ts[j + 1] - ts[j] : 0.0;
      EXPECT_NEAR(D[j], 0.5 * (lo + hi), 1e-14);
      EXPECT_NEAR(Mf[j], D[j] * f(xs[j]), 1e-14);
    }
  }
}

namespace {
// Non-matching concentric arcs: slave r = 1 (outward normals), master r = 1.05 (reversed).
struct CurvedInterface {
  std::vector<P> xs, ns, xm;
  CurvedInterface(double rot = 0.0, P shift = {0, 0}) {
    xs = arc(1.0, {0.0, 0.09, 0.21, 0.3, 0.42, 0.5, 0.6});
    xm = arc(1.05, {0.7, 0.52, 0.37, 0.2, 0.04, -0.1});
    const double c = std::cos(rot), s = std::sin(rot);
    for (auto* v : {&xs, &xm})
      for (auto& x : *v) x = P{c * x[0] - s * x[1] + shift[0], s * x[0] + c * x[1] + shift[1]};
    ns = chain_normals(xs);
  }
};
}  // namespace

TEST(Mortar2D, CurvedExactAgreesWithFineCollocation) {
  const CurvedInterface ci;
  const size_t e = 2;
  auto integrate_all = [&](int scheme_points) {  // 0: exact 5 Gauss, −1: exact 8, N: collocation
    std::vector<double> v;
    for (size_t m = 0; m + 1 < ci.xm.size(); ++m) {
      const Pair2D p = chain_pair(ci.xs, ci.ns, e, ci.xm, m);
      MortarPairResult<double> r;
      if (scheme_points > 0)
        grout::integrate_mortar_2d_collocation(p.xs, p.ns, p.xm, scheme_points, r);
      else
        grout::integrate_mortar_2d(p.xs, p.ns, p.xm, scheme_points == 0 ? 5 : 8, r);
      v.insert(v.end(), {r.D[0], r.D[1], r.M[0][0], r.M[0][1], r.M[1][0], r.M[1][1]});
    }
    return v;
  };
  auto max_diff = [](const std::vector<double>& a, const std::vector<double>& b) {
    double d = 0.0;
    for (size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
    return d;
  };
  const auto exact = integrate_all(0);
  double covered = 0.0;
  for (size_t m = 0; m * 6 < exact.size(); ++m) covered += exact[6 * m] + exact[6 * m + 1];
  EXPECT_NEAR(covered, std::hypot(ci.xs[3][0] - ci.xs[2][0], ci.xs[3][1] - ci.xs[2][1]), 1e-15);
  EXPECT_LT(max_diff(exact, integrate_all(-1)), 1e-12);  // Gauss error of the exact scheme
  double previous = 1.0;
  for (int n : {100, 1000, 10000, 100000}) {
    const double err = max_diff(exact, integrate_all(n));
    EXPECT_LT(err, 0.25 * previous) << n;  // O(1/N): the overlap ends cut collocation cells
    EXPECT_LT(err, 0.12 / n) << n;         // ≤ a cell width times the integrand
    previous = err;
  }
}

TEST(Mortar2D, RigidMotionInvariance) {
  const CurvedInterface a, b(2.3, {3.0, -1.7});
  for (size_t e = 0; e + 1 < a.xs.size(); ++e) {
    double ga[2] = {0, 0}, gb[2] = {0, 0};
    for (size_t m = 0; m + 1 < a.xm.size(); ++m) {
      const Pair2D pa = chain_pair(a.xs, a.ns, e, a.xm, m), pb = chain_pair(b.xs, b.ns, e, b.xm, m);
      MortarPairResult<double> ra, rb;
      EXPECT_EQ(grout::integrate_mortar_2d(pa.xs, pa.ns, pa.xm, ra),
                grout::integrate_mortar_2d(pb.xs, pb.ns, pb.xm, rb));
      for (int j = 0; j < 2; ++j) {
        EXPECT_NEAR(ra.D[j], rb.D[j], 1e-13);
        for (int l = 0; l < 2; ++l) EXPECT_NEAR(ra.M[j][l], rb.M[j][l], 1e-13);
      }
      double g1[4], g2[4];
      grout::weighted_gap_pair<2>(ra, pa.xs, pa.ns, pa.xm, g1);
      grout::weighted_gap_pair<2>(rb, pb.xs, pb.ns, pb.xm, g2);
      for (int j = 0; j < 2; ++j) ga[j] += g1[j], gb[j] += g2[j];
    }
    for (int j = 0; j < 2; ++j) EXPECT_NEAR(ga[j], gb[j], 1e-13);
    EXPECT_GT(ga[0], 0.0);  // open gap
  }
}

TEST(MortarIntegrate, DriverMatchesPairLoopAndWeightedGap) {
  const CurvedInterface ci(0.3);
  const int n_s = static_cast<int>(ci.xs.size()), n_m = static_cast<int>(ci.xm.size());
  Kokkos::View<double**> coords("coords", n_s + n_m, 2);
  Kokkos::View<int**> sf("sf", n_s - 1, 2), mf("mf", n_m - 1, 2);
  for (int i = 0; i < n_s; ++i) coords(i, 0) = ci.xs[i][0], coords(i, 1) = ci.xs[i][1];
  for (int i = 0; i < n_m; ++i) coords(n_s + i, 0) = ci.xm[i][0], coords(n_s + i, 1) = ci.xm[i][1];
  for (int e = 0; e + 1 < n_s; ++e) sf(e, 0) = e, sf(e, 1) = e + 1;
  for (int e = 0; e + 1 < n_m; ++e) mf(e, 0) = n_s + e, mf(e, 1) = n_s + e + 1;
  Kokkos::View<double**> normals("normals", n_s + n_m, 2);
  ASSERT_EQ(grout::compute_nodal_normals(sf, coords, normals), MortarStatus::ok);
  grout::SearchCandidates<Kokkos::HostSpace> cand;
  ASSERT_EQ(grout::coarse_search(sf, mf, coords, 0.5, cand), MortarStatus::ok);
  const auto offsets = cand.offsets;
  EXPECT_EQ(cand.n_pairs, offsets(n_s - 1));
  Kokkos::View<MortarPairResult<double>*> res("res", cand.n_pairs);
  ASSERT_EQ(grout::mortar_integrate_2d(sf, mf, coords, normals, offsets, cand.masters,
                                       grout::MortarOptions{}, res),
            MortarStatus::ok);
  Kokkos::View<double*> g("g", n_s + n_m);
  grout::accumulate_weighted_gaps(sf, mf, coords, normals, offsets, cand.masters, res, g);
  std::vector<double> g_ref(n_s, 0.0);
  for (int e = 0; e + 1 < n_s; ++e) {
    double D[2] = {0, 0}, D_ref[2] = {0, 0};
    for (int p = offsets(e); p < offsets(e + 1); ++p) D[0] += res(p).D[0], D[1] += res(p).D[1];
    for (int m = 0; m + 1 < n_m; ++m) {
      const Pair2D p = chain_pair(ci.xs, ci.ns, e, ci.xm, m);
      MortarPairResult<double> r;
      grout::integrate_mortar_2d(p.xs, p.ns, p.xm, r);
      double gp[4];
      grout::weighted_gap_pair<2>(r, p.xs, p.ns, p.xm, gp);
      for (int j = 0; j < 2; ++j) D_ref[j] += r.D[j], g_ref[e + j] += gp[j];
    }
    for (int j = 0; j < 2; ++j) EXPECT_NEAR(D[j], D_ref[j], 1e-14);
  }
  for (int j = 0; j < n_s; ++j) EXPECT_NEAR(g(j), g_ref[j], 1e-14);
}
