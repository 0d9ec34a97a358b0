// Sacado forward-AD derivatives of the exact 3D mortar integrals D, M and of the weighted gap
// g̃_j = −n₀ · (D_jj x¹_j − Σ_l M_jl x²_l) with respect to all slave and master coordinates,
// against central finite differences of the double evaluation, on random 3D configurations
// (fixed seed), across a clip-polygon topology change, and on degenerate overlaps (finite).
#include <gtest/gtest.h>

#include <Sacado.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "kernels/mortar_3d.hpp"

namespace {

using grout::max_face_nodes;
using grout::MortarStatus;

constexpr int n_dof = 2 * max_face_nodes * 3;  // slave then master coordinates
using Fad = Sacado::Fad::SFad<double, n_dof>;
using Fad1 = Sacado::Fad::SFad<double, 1>;

struct Config {
  int ns = 4, nm = 4;
  double x[2 * max_face_nodes][3] = {};  // slave nodes 0..3, master nodes 4..7
};

/// overlap, D_j, M_jl, g̃_j (as a flat list) of the pair in the scalar type.
template <class Scalar>
MortarStatus outputs(int ns, const Scalar xs[max_face_nodes][3], int nm,
                     const Scalar xm[max_face_nodes][3], std::vector<Scalar>& out) {
  grout::MortarPairResult<Scalar> r;
  const MortarStatus st = grout::integrate_mortar_3d(ns, xs, xs, nm, xm, r);
  Scalar c[3], n0[3];
  grout::face_centre_normal(ns, xs, c, n0);
  out.clear();
  out.push_back(r.overlap);
  for (int j = 0; j < ns; ++j) out.push_back(r.D[j]);
  for (int j = 0; j < ns; ++j)
    for (int l = 0; l < nm; ++l) out.push_back(r.M[j][l]);
  for (int j = 0; j < ns; ++j) {
    Scalar g = 0.0;
    for (int d = 0; d < 3; ++d) {
      Scalar v = r.D[j] * xs[j][d];
      for (int l = 0; l < nm; ++l) v -= r.M[j][l] * xm[l][d];
      g -= n0[d] * v;
    }
    out.push_back(g);
  }
  return st;
}

MortarStatus evaluate(const Config& c, std::vector<double>& out) {
  double xs[max_face_nodes][3], xm[max_face_nodes][3];
  for (int i = 0; i < max_face_nodes; ++i)
    for (int d = 0; d < 3; ++d) xs[i][d] = c.x[i][d], xm[i][d] = c.x[i + max_face_nodes][d];
  return outputs(c.ns, xs, c.nm, xm, out);
}

/// Fad derivatives: jac[q][k] = ∂out_q/∂x_k (k = 3 node + d).
MortarStatus evaluate_fad(const Config& c, std::vector<double>& val,
                          std::vector<std::vector<double>>& jac) {
  Fad xs[max_face_nodes][3], xm[max_face_nodes][3];
  for (int i = 0; i < max_face_nodes; ++i)
    for (int d = 0; d < 3; ++d) {
      xs[i][d] = Fad(n_dof, 3 * i + d, c.x[i][d]);
      xm[i][d] = Fad(n_dof, 3 * (i + max_face_nodes) + d, c.x[i + max_face_nodes][d]);
    }
  std::vector<Fad> out;
  const MortarStatus st = outputs(c.ns, xs, c.nm, xm, out);
  val.assign(out.size(), 0.0);
  jac.assign(out.size(), std::vector<double>(n_dof, 0.0));
  for (std::size_t q = 0; q < out.size(); ++q) {
    val[q] = out[q].val();
    for (int k = 0; k < n_dof; ++k) jac[q][k] = out[q].dx(k);
  }
  return st;
}

Config random_config(std::mt19937& rng, int ns, int nm) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Config c;
  c.ns = ns, c.nm = nm;
  const double sq[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 0; i < 4; ++i)
    c.x[i][0] = sq[i][0] + 0.15 * u(rng), c.x[i][1] = sq[i][1] + 0.15 * u(rng),
    c.x[i][2] = 0.1 * u(rng);
  // master: rotated, shifted unit square below, facing the slave (reversed order)
  const double a = 0.5 * u(rng), ox = 0.5 * u(rng), oy = 0.5 * u(rng);
  for (int l = 0; l < 4; ++l) {
    const double px = sq[3 - l][0] - 0.5, py = sq[3 - l][1] - 0.5;
    double* x = c.x[max_face_nodes + l];
    x[0] = 0.5 + ox + std::cos(a) * px - std::sin(a) * py + 0.1 * u(rng);
    x[1] = 0.5 + oy + std::sin(a) * px + std::cos(a) * py + 0.1 * u(rng);
    x[2] = -0.05 + 0.02 * u(rng);
  }
  return c;
}

TEST(Mortar3DAD, FadMatchesCentralDifferencesOnRandomPairs) {
  std::mt19937 rng(2024);
  const double h = 1e-6;
  int tested = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Config c = random_config(rng, trial % 2 ? 3 : 4, trial % 4 < 2 ? 4 : 3);
    std::vector<double> val, v0, vp, vm;
    std::vector<std::vector<double>> jac;
    const MortarStatus st = evaluate_fad(c, val, jac);
    ASSERT_EQ(evaluate(c, v0), st);
    if (st != MortarStatus::ok) continue;
    ++tested;
    for (std::size_t q = 0; q < val.size(); ++q) EXPECT_NEAR(val[q], v0[q], 1e-14);
    for (int k = 0; k < n_dof; ++k) {
      const int node = k / 3;
      if ((node < 4 && node >= c.ns) || (node >= 4 && node - 4 >= c.nm)) continue;
      Config p = c, m = c;
      p.x[node][k % 3] += h;
      m.x[node][k % 3] -= h;
      ASSERT_EQ(evaluate(p, vp), MortarStatus::ok);
      ASSERT_EQ(evaluate(m, vm), MortarStatus::ok);
      for (std::size_t q = 0; q < val.size(); ++q) {
        const double fd = (vp[q] - vm[q]) / (2 * h);
        EXPECT_NEAR(jac[q][k], fd, 1e-7 * (1.0 + std::abs(fd)))
            << "trial " << trial << " output " << q << " dof " << k;
      }
    }
  }
  EXPECT_GE(tested, 30);
}

/// Master triangle (0.4, 0.2), (1 + t, 0.5), (0.4, 0.8) under the unit-square slave: at t = 0
/// the vertex crosses the slave edge x = 1 and the clip polygon changes from the triangle
/// (t < 0) to a quadrilateral (t > 0). The integrals stay C¹ (the cut-off part is O(t²)):
/// away from t = 0 the directional Fad derivative matches central differences; at t = 0 it
/// matches both one-sided differences to O(h).
TEST(Mortar3DAD, DerivativesAcrossClipTopologyChange) {
  auto eval = [](double t, std::vector<double>& val, std::vector<double>& dval) {
    Fad1 xs[max_face_nodes][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    Fad1 xm[max_face_nodes][3] = {{0.4, 0.2, -0.1}, {0.4, 0.8, -0.1}, {0, 0.5, -0.1}, {0, 0, 0}};
    xm[2][0] = Fad1(1, 0, 1.0 + t);  // seed d/dt
    xm[2][1] = 0.5;
    std::vector<Fad1> out;
    const MortarStatus st = outputs(4, xs, 3, xm, out);
    val.clear(), dval.clear();
    for (const Fad1& o : out) val.push_back(o.val()), dval.push_back(o.dx(0));
    return st;
  };
  std::vector<double> v, dv, vp, dp, vm, dm;
  const double h = 1e-6;
  for (double t : {-1e-2, -1e-3, 1e-3, 1e-2}) {
    ASSERT_EQ(eval(t, v, dv), MortarStatus::ok);
    eval(t + h, vp, dp);
    eval(t - h, vm, dm);
    for (std::size_t q = 0; q < v.size(); ++q)
      EXPECT_NEAR(dv[q], (vp[q] - vm[q]) / (2 * h), 1e-7) << "t=" << t << " output " << q;
  }
  const double h1 = 1e-5;
  ASSERT_EQ(eval(0.0, v, dv), MortarStatus::ok);
  eval(h1, vp, dp);
  eval(-h1, vm, dm);
  for (std::size_t q = 0; q < v.size(); ++q) {
    EXPECT_TRUE(std::isfinite(dv[q]));
    EXPECT_NEAR(dv[q], (vp[q] - v[q]) / h1, 1e-4) << "right, output " << q;
    EXPECT_NEAR(dv[q], (v[q] - vm[q]) / h1, 1e-4) << "left, output " << q;
  }
  // and the overlap really changes shape: the triangle loses an O(t²) tip for t > 0
  eval(-1e-2, vm, dm);
  eval(1e-2, vp, dp);
  EXPECT_NEAR(vm[0], 0.5 * 0.6 * (0.6 - 1e-2), 1e-14);  // whole master triangle
  EXPECT_LT(vp[0], 0.5 * 0.6 * (0.6 + 1e-2));
}

/// Degenerate overlaps (identical faces, shared edges and vertices, touching, disjoint, a
/// master vertex exactly on a slave edge, edge-on master): values and derivatives finite.
TEST(Mortar3DAD, DerivativesFiniteOnDegenerateOverlaps) {
  const std::vector<std::vector<std::array<double, 3>>> masters = {
      {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}},                  // identical (reversed)
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},                  // identical (same order)
      {{0, 0, -0.1}, {0, 1, -0.1}, {0.5, 1, -0.1}, {0.5, 0, -0.1}},  // shared edges
      {{0, 0, 0}, {1, 1, 0}, {1, 0, 0}},                             // shared vertices
      {{1, 0, 0}, {1, 1, 0}, {2, 1, 0}, {2, 0, 0}},                  // touching along an edge
      {{1, 1, 0}, {1, 2, 0}, {2, 2, 0}, {2, 1, 0}},                  // touching at a vertex
      {{3, 0, 0}, {3, 1, 0}, {4, 1, 0}, {4, 0, 0}},                  // disjoint
      {{0.2, 0.2, 0}, {1, 0.5, 0}, {0.2, 0.8, 0}},                   // vertex on the edge x = 1
      {{0.5, 0, -1}, {0.5, 1, -1}, {0.5, 1, 1}, {0.5, 0, 1}}};       // edge-on
  for (std::size_t k = 0; k < masters.size(); ++k) {
    Config c;
    c.ns = 4;
    c.nm = static_cast<int>(masters[k].size());
    const double sq[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    for (int i = 0; i < 4; ++i)
      for (int d = 0; d < 3; ++d) c.x[i][d] = sq[i][d];
    for (int l = 0; l < c.nm; ++l)
      for (int d = 0; d < 3; ++d) c.x[4 + l][d] = masters[k][l][d];
    std::vector<double> val;
    std::vector<std::vector<double>> jac;
    const MortarStatus st = evaluate_fad(c, val, jac);
    EXPECT_TRUE(st == MortarStatus::ok || st == MortarStatus::no_overlap) << "case " << k;
    for (std::size_t q = 0; q < val.size(); ++q) {
      EXPECT_TRUE(std::isfinite(val[q])) << "case " << k;
      for (int i = 0; i < n_dof; ++i) EXPECT_TRUE(std::isfinite(jac[q][i])) << "case " << k;
    }
  }
}

}  // namespace
