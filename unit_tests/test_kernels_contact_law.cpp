// The contact law at a slave node (kernels/contact_law.hpp) and its launch (contact_laws.hpp), in
// 2D and 3D, on random but reproducible states of every kind and branch: open (no master,
// inactive, held back), the proximity rule, tied with a held component, frictionless, Coulomb
// stick and slip, a held tangent in stick and in slip, slip at ξ = 0 (μ = 0, and a near node).
//   (a) the rows, status, row kinds and identity components against a direct transcription of
//       the rules (docs/design.md, "Contact conditions") written here, and against the
//       expected branch of each case;
//   (b) every AD derivative column against a central difference of the values (each case is
//       built away from the branch switches, and the test checks that the steps do not cross
//       one), unused variables included (their derivative must be 0);
//   (c) the launch over a View of nodes against the per-node function.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "kernels/contact_laws.hpp"

namespace grout {
namespace {

using L = ContactLawLayout;

// ---- (a) the reference: the rules written out in double, independently of the kernel ----

struct Reference {
  double C[3] = {0.0, 0.0, 0.0};
  int status = 0;
  int kind[3] = {0, 0, 0};
  int component[3] = {-1, -1, -1};
};

Reference reference_law(const ContactLawParameters& p, const ContactLawNode& x) {
  Reference r;
  const int d = p.dim;
  auto all_open = [&] {
    for (int a = 0; a < d; ++a) r.C[a] = x.lambda[a], r.kind[a] = 0, r.component[a] = a;
    r.status = 0;
    return r;
  };
  if (!x.paired) return all_open();
  if (p.kind == tied_law) {
    r.status = 1;
    for (int a = 0; a < d; ++a) {
      const bool held = x.prescribed[a] != 0 && x.free_share[a] <= 1e-12;
      r.C[a] = held ? x.lambda[a] : p.c_hat * x.tied[a];
      r.kind[a] = held ? 0 : 1;
      r.component[a] = held ? a : -1;
    }
    return r;
  }
  double ln = 0.0;
  for (int a = 0; a < d; ++a) ln += x.n[a] * x.lambda[a];
  const double s = ln - p.c_hat * x.gap;
  const bool active = !x.held_back && (s >= -p.active_tolerance || x.near);
  if (!active) return all_open();
  r.C[0] = p.c_hat * x.gap;
  r.kind[0] = 1;
  double lt[2] = {0.0, 0.0};
  for (int k = 0; k + 1 < d; ++k)
    for (int a = 0; a < d; ++a) lt[k] += x.t[k][a] * x.lambda[a];
  if (p.kind == frictionless_law) {
    r.status = 2;
    for (int k = 0; k + 1 < d; ++k) r.C[k + 1] = lt[k], r.kind[k + 1] = 3;
    return r;
  }
  int axis[2] = {-1, -1};
  double xi[2] = {0.0, 0.0};
  for (int k = 0; k + 1 < d; ++k) {
    for (int a = d - 1; a >= 0; --a)  // the first qualifying axis: scanned backwards, last wins
      if (x.t[k][a] * x.t[k][a] >= 0.99 && x.prescribed[a] && x.free_share[a] <= 0.25) axis[k] = a;
    xi[k] = axis[k] >= 0 ? 0.0 : lt[k] + p.c_t_hat * x.slip[k];
  }
  const double norm = std::hypot(xi[0], xi[1]);
  const bool stick = p.mu > 0.0 && norm <= p.mu * (s + p.active_tolerance);
  r.status = stick ? 1 : 2;
  for (int k = 0; k + 1 < d; ++k) {
    if (axis[k] >= 0) {
      r.C[k + 1] = x.lambda[axis[k]], r.kind[k + 1] = 0, r.component[k + 1] = axis[k];
    } else if (stick) {
      r.C[k + 1] = p.c_t_hat * x.slip[k], r.kind[k + 1] = 1;
    } else {
      r.C[k + 1] = lt[k] - (norm > 0.0 ? p.mu * s * xi[k] / norm : 0.0), r.kind[k + 1] = 2;
    }
  }
  return r;
}

// ---- the cases ----

using Rng = std::mt19937;
double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
void normalize(double v[3]) {
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int a = 0; a < 3; ++a) v[a] /= l;
}
void cross(const double a[3], const double b[3], double c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

void frame_once(int dim, Rng& rng, int axis, double tilt, ContactLawNode& x);

// An orthonormal frame; `axis` ≥ 0: τ_0 within about `tilt` rad of e_axis, n along the next
// axis; `axis` < 0: random, every tangent at least 0.2 rad off the axes (|τ_k·e_a|² ≤ 0.95).
void frame(int dim, Rng& rng, int axis, double tilt, ContactLawNode& x) {
  for (;;) {
    frame_once(dim, rng, axis, tilt, x);
    double largest = 0.0;
    for (int k = 0; k + 1 < dim; ++k)
      for (int a = 0; a < dim; ++a) largest = std::max(largest, x.t[k][a] * x.t[k][a]);
    if (axis >= 0 || largest <= 0.95) return;
  }
}

void frame_once(int dim, Rng& rng, int axis, double tilt, ContactLawNode& x) {
  double n[3] = {0.0, 0.0, 0.0}, t0[3] = {0.0, 0.0, 0.0};
  if (axis < 0) {
    for (int a = 0; a < dim; ++a) n[a] = uniform(rng, -1.0, 1.0);
  } else {
    t0[axis] = 1.0;
    n[(axis + 1) % dim] = 1.0;
    for (int a = 0; a < dim; ++a) n[a] += tilt * uniform(rng, -1.0, 1.0);
  }
  normalize(n);
  if (dim == 2) {
    const double t[3] = {-n[1], n[0], 0.0};
    for (int a = 0; a < 2; ++a) x.n[a] = n[a], x.t[0][a] = t[a];
    if (axis >= 0 && x.t[0][axis] < 0.0)  // τ_0 along +e_axis
      for (int a = 0; a < 2; ++a) x.t[0][a] = -x.t[0][a], x.n[a] = -x.n[a];
    return;
  }
  double r[3];
  if (axis < 0) {
    for (int a = 0; a < 3; ++a) r[a] = uniform(rng, -1.0, 1.0);
  } else {
    for (int a = 0; a < 3; ++a) r[a] = t0[a] + tilt * uniform(rng, -1.0, 1.0);
  }
  double t[3], b[3];
  cross(n, r, b);  // b ⟂ n, then τ_0 = b × n ⟂ n, close to r
  normalize(b);
  cross(b, n, t);
  for (int a = 0; a < 3; ++a) x.n[a] = n[a], x.t[0][a] = t[a], x.t[1][a] = b[a];
}

struct Case {
  std::string name;
  ContactLawParameters p;
  ContactLawNode x;
  int status;
  int kind[3];
  int component[3];
  bool direction_at_zero = false;  // slip at ξ = 0 with μ s ≠ 0: ξ/|ξ| jumps under λ, τ, ū
};

// Every field random (components the dimension does not use too: the law must not read them).
ContactLawNode random_node(Rng& rng) {
  ContactLawNode x;
  for (int a = 0; a < 3; ++a) {
    x.lambda[a] = uniform(rng, -2.0, 2.0);
    x.n[a] = uniform(rng, -1.0, 1.0);
    x.t[0][a] = uniform(rng, -1.0, 1.0);
    x.t[1][a] = uniform(rng, -1.0, 1.0);
    x.tied[a] = uniform(rng, -0.01, 0.01);
    x.prescribed[a] = 0;
    x.free_share[a] = uniform(rng, 0.5, 1.0);
  }
  x.gap = uniform(rng, -0.01, 0.01);
  x.slip[0] = uniform(rng, -0.01, 0.01);
  x.slip[1] = uniform(rng, -0.01, 0.01);
  x.paired = 1;
  x.near = 0;
  x.held_back = 0;
  return x;
}

double lambda_n(int dim, const ContactLawNode& x) {
  double l = 0.0;
  for (int a = 0; a < dim; ++a) l += x.n[a] * x.lambda[a];
  return l;
}
double lambda_t(int dim, const ContactLawNode& x, int k) {
  double l = 0.0;
  for (int a = 0; a < dim; ++a) l += x.t[k][a] * x.lambda[a];
  return l;
}
// g with s = λ_n − ĉ g = s_target.
void set_augmented(const ContactLawParameters& p, ContactLawNode& x, double s_target) {
  x.gap = (lambda_n(p.dim, x) - s_target) / p.c_hat;
}
// ū with ξ = λ_τ + c_t ū = xi (tangents not held).
void set_xi(const ContactLawParameters& p, ContactLawNode& x, const double xi[2]) {
  for (int k = 0; k + 1 < p.dim; ++k) x.slip[k] = (xi[k] - lambda_t(p.dim, x, k)) / p.c_t_hat;
}
// A direction of |ξ| = m, both components in 3D away from 0.
void xi_of_size(int dim, Rng& rng, double m, double xi[2]) {
  if (dim == 2) {
    xi[0] = uniform(rng, 0.0, 1.0) < 0.5 ? -m : m, xi[1] = 0.0;
    return;
  }
  const double phi = uniform(rng, 0.2, 1.3) + (uniform(rng, 0.0, 1.0) < 0.5 ? 3.14159 : 0.0);
  xi[0] = m * std::cos(phi), xi[1] = m * std::sin(phi);
}

std::vector<Case> cases(int dim, unsigned seed) {
  Rng rng(seed);
  std::vector<Case> out;
  ContactLawParameters base{dim, coulomb_law, 0.0, 0.0, 0.3, 1e-8};
  base.c_hat = uniform(rng, 50.0, 200.0);
  base.c_t_hat = uniform(rng, 20.0, 80.0);
  const auto add = [&](const std::string& name, ContactLawParameters p, const ContactLawNode& x,
                       int status, std::vector<int> kind, std::vector<int> component,
                       bool at_zero = false) {
    Case c{name + (dim == 2 ? " 2D" : " 3D"), p, x, status, {0, 0, 0}, {-1, -1, -1}, at_zero};
    for (int r = 0; r < dim; ++r) c.kind[r] = kind[r], c.component[r] = component[r];
    out.push_back(c);
  };
  const std::vector<int> open_kind(dim, row_identity);
  std::vector<int> own(dim), none(dim, -1);
  for (int a = 0; a < dim; ++a) own[a] = a;
  ContactLawParameters coulomb = base, frictionless = base, tied = base, mu0 = base;
  frictionless.kind = frictionless_law;
  tied.kind = tied_law;
  mu0.mu = 0.0;
  std::vector<int> fl_kind(dim, row_tangent), stick_kind(dim, row_constraint),
      slip_kind(dim, row_slip);
  fl_kind[0] = slip_kind[0] = row_constraint;

  for (int repeat = 0; repeat < 3; ++repeat) {
    ContactLawNode x = random_node(rng);
    frame(dim, rng, -1, 0.0, x);
    x.paired = 0;
    set_augmented(coulomb, x, 1.0);
    add("no master", coulomb, x, node_open, open_kind, own);

    x = random_node(rng);
    frame(dim, rng, -1, 0.0, x);
    set_augmented(frictionless, x, -uniform(rng, 0.5, 2.0));
    add("inactive", frictionless, x, node_open, open_kind, own);
    x.near = 1;
    add("near (proximity rule)", frictionless, x, node_slip, fl_kind, none);

    x = random_node(rng);
    frame(dim, rng, -1, 0.0, x);
    set_augmented(coulomb, x, uniform(rng, 0.5, 2.0));
    x.held_back = 1;
    add("held back", coulomb, x, node_open, open_kind, own);

    x = random_node(rng);
    frame(dim, rng, -1, 0.0, x);
    x.prescribed[0] = 1, x.free_share[0] = 0.0;  // held: λ_0 = 0
    x.prescribed[1] = 1, x.free_share[1] = 0.3;  // prescribed, but a free master share
    {
      std::vector<int> k = stick_kind, c = none;
      k[0] = row_identity, c[0] = 0;
      add("tied, component 0 held", tied, x, node_stick, k, c);
    }

    x = random_node(rng);
    frame(dim, rng, -1, 0.0, x);
    set_augmented(frictionless, x, uniform(rng, 0.5, 2.0));
    add("frictionless", frictionless, x, node_slip, fl_kind, none);

    double xi[2];
    x = random_node(rng);
    frame(dim, rng, -1, 0.0, x);
    {
      const double s = uniform(rng, 0.5, 2.0);
      set_augmented(coulomb, x, s);
      xi_of_size(dim, rng, uniform(rng, 0.2, 0.8) * coulomb.mu * s, xi);
      set_xi(coulomb, x, xi);
      add("stick", coulomb, x, node_stick, stick_kind, none);
      xi_of_size(dim, rng, uniform(rng, 1.3, 3.0) * coulomb.mu * s, xi);
      set_xi(coulomb, x, xi);
      add("slip", coulomb, x, node_slip, slip_kind, none);
      add("slip, mu = 0", mu0, x, node_slip, slip_kind, none);
      // Prescribed along τ_0's axis but not held: τ_0 is not near an axis here.
      x.prescribed[0] = x.prescribed[1] = 1, x.free_share[0] = x.free_share[1] = 0.0;
      if (dim == 3) x.prescribed[2] = 1, x.free_share[2] = 0.0;
      add("slip, prescribed, no axis tangent", coulomb, x, node_slip, slip_kind, none);
    }

    // A tangent along e_0 (tilt ≤ 0.05 rad): held where the slave dof is prescribed along it
    // and the free master share is at most 0.25 (2D: the only tangent, so |ξ| = 0 sticks).
    x = random_node(rng);
    frame(dim, rng, 0, 0.03, x);
    x.prescribed[0] = 1, x.free_share[0] = uniform(rng, 0.0, 0.2);
    {
      const double s = uniform(rng, 0.5, 2.0);
      set_augmented(coulomb, x, s);
      std::vector<int> k = stick_kind, c = none;
      k[1] = row_identity, c[1] = 0;
      const double sign = uniform(rng, 0.0, 1.0) < 0.5 ? -1.0 : 1.0;
      if (dim == 3) {  // ξ = (0, ξ_1): the held tangent's ū_0 and ξ_0 are 0
        const double xi1 = sign * uniform(rng, 0.2, 0.8) * coulomb.mu * s;
        x.slip[1] = (xi1 - lambda_t(dim, x, 1)) / coulomb.c_t_hat;
      }
      add("held tangent, stick", coulomb, x, node_stick, k, c);
      k = slip_kind, k[1] = row_identity;
      if (dim == 3) {
        const double xi1 = sign * uniform(rng, 1.3, 3.0) * coulomb.mu * s;
        x.slip[1] = (xi1 - lambda_t(dim, x, 1)) / coulomb.c_t_hat;
        add("held tangent, slip", coulomb, x, node_slip, k, c);
      } else {
        add("held tangent, slip (mu = 0)", mu0, x, node_slip, k, c);
      }
      x.free_share[0] = uniform(rng, 0.3, 1.0);  // a free master along e_0: Coulomb holds
      xi_of_size(dim, rng, uniform(rng, 1.3, 3.0) * coulomb.mu * s, xi);
      set_xi(coulomb, x, xi);
      add("axis tangent, free master", coulomb, x, node_slip, slip_kind, none);
    }

    // Slip at ξ = 0 exactly (λ = 0, ū = 0: the start of a step): μ = 0 (any ξ slips), and a
    // near node with s < −tol (μ s < 0).
    x = random_node(rng);
    frame(dim, rng, -1, 0.0, x);
    for (int a = 0; a < 3; ++a) x.lambda[a] = 0.0;
    x.slip[0] = x.slip[1] = 0.0;
    set_augmented(coulomb, x, uniform(rng, 0.5, 2.0));
    add("xi = 0, mu = 0", mu0, x, node_slip, slip_kind, none);
    set_augmented(coulomb, x, -uniform(rng, 0.5, 2.0));
    x.near = 1;
    add("xi = 0, near", coulomb, x, node_slip, slip_kind, none, true);
  }
  return out;
}

ContactLawResult evaluate(const Case& c, const ContactLawNode& x, bool derivatives) {
  ContactLawResult r;
  contact_law(c.p, x, derivatives, r);
  return r;
}

// Whether the reference takes the same branches at x as at the case's state.
bool same_branch(const Case& c, const ContactLawNode& x) {
  const Reference a = reference_law(c.p, c.x), b = reference_law(c.p, x);
  if (a.status != b.status) return false;
  for (int r = 0; r < 3; ++r)
    if (a.kind[r] != b.kind[r] || a.component[r] != b.component[r]) return false;
  return true;
}

void check_values(int dim, unsigned seed) {
  int count = 0;
  for (const Case& c : cases(dim, seed)) {
    SCOPED_TRACE(c.name);
    const Reference ref = reference_law(c.p, c.x);
    EXPECT_EQ(ref.status, c.status);
    for (const bool derivatives : {true, false}) {
      const ContactLawResult r = evaluate(c, c.x, derivatives);
      EXPECT_EQ(r.status, c.status);
      for (int row = 0; row < 3; ++row) {
        const double scale = std::max(1.0, std::abs(ref.C[row]));
        EXPECT_NEAR(r.C[row], ref.C[row], 1e-14 * scale) << "row " << row;
        EXPECT_EQ(int(r.kind[row]), row < dim ? c.kind[row] : 0) << "row " << row;
        EXPECT_EQ(int(r.kind[row]), ref.kind[row]) << "row " << row;
        EXPECT_EQ(r.component[row], row < dim ? c.component[row] : -1) << "row " << row;
        EXPECT_EQ(r.component[row], ref.component[row]) << "row " << row;
        if (!derivatives) {
          for (int v = 0; v < L::count; ++v) EXPECT_EQ(r.dC[row][v], 0.0);
        }
      }
    }
    ++count;
  }
  EXPECT_EQ(count, 3 * 15);
}

// ∂C_r/∂v by AD against (C(x + h e_v) − C(x − h e_v)) / 2h, h = 1e-6 max(0.01, |x_v|), to 1e-7 of
// the row's largest derivative (gaps, slips and ties are ~1e-2: their steps scale with them); a
// step that changes a branch fails the test (the cases keep a margin). At ξ = 0 with μ s ≠ 0 the
// columns of λ, τ and ū (which move ξ off 0 and turn ξ/|ξ| from 0 to a unit vector) are checked
// against the derivative of the convention ξ/|ξ| = 0 instead: ∂C_{k+1} = ∂(τ_k·λ).
void check_derivatives(int dim, unsigned seed) {
  double worst = 0.0;
  for (const Case& c : cases(dim, seed)) {
    SCOPED_TRACE(c.name);
    const ContactLawResult r = evaluate(c, c.x, true);
    for (int v = 0; v < L::count; ++v) {
      ContactLawNode plus = c.x, minus = c.x;
      const double h = 1e-6 * std::max(0.01, std::abs(contact_law_variable(plus, v)));
      contact_law_variable(plus, v) += h;
      contact_law_variable(minus, v) -= h;
      ASSERT_TRUE(same_branch(c, plus) && same_branch(c, minus)) << "variable " << v;
      const ContactLawResult rp = evaluate(c, plus, false), rm = evaluate(c, minus, false);
      const bool moves_xi =
          v < 3 || (v >= L::tangent(0, 0) && v < L::gap()) || v == L::slip(0) || v == L::slip(1);
      for (int row = 0; row < 3; ++row) {
        double expected = (rp.C[row] - rm.C[row]) / (2 * h);
        if (c.direction_at_zero && moves_xi && row >= 1 && row < dim) {
          const int k = row - 1;
          expected = 0.0;
          for (int a = 0; a < dim; ++a) {
            if (v == L::lambda(a)) expected = c.x.t[k][a];
            if (v == L::tangent(k, a)) expected = c.x.lambda[a];
          }
        }
        double scale = 0.0;
        for (int q = 0; q < L::count; ++q) scale = std::max(scale, std::abs(r.dC[row][q]));
        if (row >= dim) {
          EXPECT_EQ(scale, 0.0);
        }
        const double err = std::abs(r.dC[row][v] - expected);
        EXPECT_LE(err, 1e-7 * std::max(scale, std::abs(expected)))
            << "row " << row << " variable " << v << ": AD " << r.dC[row][v] << ", difference "
            << expected;
        if (scale > 0.0) worst = std::max(worst, err / scale);
      }
    }
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", worst);
  ::testing::Test::RecordProperty("worst_relative_difference", text);
}

// The launch over all of a dimension's nodes, under each case's parameters, against the
// per-node function, with and without derivatives.
void check_launch(int dim, unsigned seed) {
  const std::vector<Case> all = cases(dim, seed);
  Kokkos::View<ContactLawNode*> nodes("nodes", all.size());
  for (std::size_t i = 0; i < all.size(); ++i) nodes(i) = all[i].x;
  Kokkos::View<ContactLawResult*> results("results", all.size());
  for (const Case& c : all)
    for (const bool derivatives : {true, false}) {
      SCOPED_TRACE(c.name);
      ASSERT_TRUE(
          evaluate_contact_law(Kokkos::DefaultExecutionSpace(), c.p, nodes, derivatives, results));
      Kokkos::fence();
      for (std::size_t i = 0; i < all.size(); ++i) {
        const ContactLawResult one = evaluate(c, all[i].x, derivatives);
        const ContactLawResult& r = results(i);
        EXPECT_EQ(r.status, one.status);
        for (int row = 0; row < 3; ++row) {
          EXPECT_EQ(r.C[row], one.C[row]);
          EXPECT_EQ(r.kind[row], one.kind[row]);
          EXPECT_EQ(r.component[row], one.component[row]);
          for (int v = 0; v < L::count; ++v) EXPECT_EQ(r.dC[row][v], one.dC[row][v]);
        }
        EXPECT_EQ(r.held_axis[0], one.held_axis[0]);
        EXPECT_EQ(r.held_axis[1], one.held_axis[1]);
      }
    }
  Kokkos::View<ContactLawResult*> short_results("short", all.size() - 1);
  EXPECT_FALSE(
      evaluate_contact_law(Kokkos::DefaultExecutionSpace(), all[0].p, nodes, true, short_results));
}

TEST(ContactLaw, ValuesFollowTheRules2D) {
  check_values(2, 2026u);
}
TEST(ContactLaw, ValuesFollowTheRules3D) {
  check_values(3, 3037u);
}
TEST(ContactLaw, DerivativesMatchCentralDifferences2D) {
  check_derivatives(2, 2026u);
}
TEST(ContactLaw, DerivativesMatchCentralDifferences3D) {
  check_derivatives(3, 3037u);
}
TEST(ContactLaw, LaunchEqualsThePerNodeFunction2D) {
  check_launch(2, 2026u);
}
TEST(ContactLaw, LaunchEqualsThePerNodeFunction3D) {
  check_launch(3, 3037u);
}

// Other seeds: the same checks on fresh random states.
TEST(ContactLaw, OtherSeeds) {
  for (unsigned seed : {1u, 7u, 99u}) {
    check_values(2, seed);
    check_values(3, seed);
    check_derivatives(2, seed);
    check_derivatives(3, seed);
  }
}

}  // namespace
}  // namespace grout
