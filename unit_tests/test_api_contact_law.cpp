// grout::contact_law_at_nodes (api/grout/contact_law.hpp) against the kernel it wraps:
//   1. on 2D and 3D frictionless, tied and Coulomb stick/slip nodes (and open, unpaired, near,
//      held-back nodes, held tie components and held Coulomb tangents), the API's rows, ∂C/∂v,
//      state, kinds and held axes equal bitwise the per-node kernel contact_law
//      (kernels/contact_law.hpp) on the same values, with and without derivatives; each case
//      also states the branch it must take, so that every branch is met;
//   2. the API runs the driver's launch: Kokkos' profiling hook sees one parallel_for labelled
//      "grout::contact_law" per call, and no other launch but Kokkos' own (View destruction);
//   3. bad settings and non-finite node values throw ContactLawError naming the field.
// The rows themselves are checked against the law's formulas and central differences in
// test_kernels_contact_law, and from a host program in examples/embed_mortar.

#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "grout/contact_law.hpp"
#include "kernels/contact_law.hpp"

namespace {

using grout::ContactLawInput;
using grout::ContactLawRows;
using grout::ContactLawSettings;
using grout::ContactLawType;
using grout::ContactNodeState;
using grout::ContactRowKind;

struct Case {
  std::string name;
  ContactLawSettings settings;
  ContactLawInput node;
  ContactNodeState state;  ///< the branch the case must take
  ContactRowKind kind[3];  ///< rows < dim
};

/// The kernel's node from the host's values (the test's own conversion, field by field).
grout::ContactLawNode kernel_node(const ContactLawInput& in) {
  grout::ContactLawNode x = grout::ContactLawNode();
  for (int a = 0; a < 3; ++a) {
    x.lambda[a] = in.lambda[a], x.n[a] = in.n[a], x.tied[a] = in.tied[a];
    x.t[0][a] = in.t[0][a], x.t[1][a] = in.t[1][a];
    x.prescribed[a] = in.prescribed[a], x.free_share[a] = in.free_share[a];
  }
  x.gap = in.gap, x.slip[0] = in.slip[0], x.slip[1] = in.slip[1];
  x.paired = in.paired, x.near = in.near, x.held_back = in.held_back;
  return x;
}

ContactLawSettings settings(int dim, ContactLawType law, double mu = 0.0) {
  ContactLawSettings s;
  s.dim = dim, s.law = law, s.c_hat = 2.5e3, s.c_t_hat = 1.5e3, s.mu = mu;
  s.active_tolerance = 1e-10;
  return s;
}

/// A node with a slightly tilted frame (n, τ_0, τ_1 orthonormal), multiplier λ, gap g.
ContactLawInput node(int dim, double lambda_n, double lambda_t, double g, double slip = 0.0) {
  ContactLawInput x;
  const double c = std::cos(0.3), s = std::sin(0.3);
  const double n[3] = {dim == 2 ? s : 0.0, c, dim == 2 ? 0.0 : s};
  const double t0[3] = {dim == 2 ? c : 1.0, dim == 2 ? -s : 0.0, 0.0};
  const double t1[3] = {0.0, -s, c};
  for (int a = 0; a < 3; ++a) {
    x.n[a] = n[a], x.t[0][a] = t0[a], x.t[1][a] = t1[a];
    x.lambda[a] = lambda_n * n[a] + lambda_t * t0[a] + (dim == 3 ? 0.4 * lambda_t * t1[a] : 0.0);
    x.tied[a] = 1e-4 * (a + 1) - 2e-4;
    x.free_share[a] = 0.6;
  }
  x.gap = g;
  x.slip[0] = slip, x.slip[1] = dim == 3 ? -0.5 * slip : 0.0;
  return x;
}

std::vector<Case> cases() {
  using K = ContactRowKind;
  using S = ContactNodeState;
  const K I = K::identity, N = K::constraint, P = K::slip, T = K::tangent;
  std::vector<Case> out;
  for (int dim = 2; dim <= 3; ++dim) {
    const std::string d = std::to_string(dim) + "D ";
    const auto fl = settings(dim, ContactLawType::frictionless);
    const auto co = settings(dim, ContactLawType::coulomb, 0.3);
    const auto ti = settings(dim, ContactLawType::tied);
    out.push_back({d + "frictionless active", fl, node(dim, 5.0, 0.7, -1e-4), S::slip, {N, T, T}});
    out.push_back({d + "frictionless open", fl, node(dim, -1.0, 0.2, 1e-3), S::open, {I, I, I}});
    Case near{d + "frictionless near", fl, node(dim, -1.0, 0.2, 1e-3), S::slip, {N, T, T}};
    near.node.near = true;
    out.push_back(near);
    Case back{d + "frictionless held back", fl, node(dim, 5.0, 0.7, -1e-4), S::open, {I, I, I}};
    back.node.held_back = true;
    out.push_back(back);
    Case lone{d + "frictionless unpaired", fl, node(dim, 5.0, 0.7, -1e-4), S::open, {I, I, I}};
    lone.node.paired = false;
    out.push_back(lone);
    out.push_back({d + "tied", ti, node(dim, 5.0, 0.7, 0.0), S::stick, {N, N, N}});
    Case held_tie{d + "tied, component 0 held", ti, node(dim, 5.0, 0.7, 0.0), S::stick, {I, N, N}};
    held_tie.node.prescribed[0] = true, held_tie.node.free_share[0] = 0.0;
    out.push_back(held_tie);
    // Stick: |ξ| = |λ_τ + c_t ū| well below μ s; slip: a tangential multiplier above μ λ_n.
    out.push_back({d + "Coulomb stick", co, node(dim, 5.0, 0.1, -1e-4, 1e-5), S::stick, {N, N, N}});
    out.push_back({d + "Coulomb slip", co, node(dim, 5.0, 3.0, -1e-4, 2e-3), S::slip, {N, P, P}});
    out.push_back({d + "Coulomb open", co, node(dim, -1.0, 0.2, 1e-3), S::open, {I, I, I}});
    if (dim == 3) {  // τ_0 = e_x, x prescribed, masters' share 0.1: tangent 0 held along x
      // ξ = (0, τ_1·λ + c_t ū_1): 1.2 − 1.5 sticks, 1.2 + 1.5 slips (μ s = 1.575).
      Case stick{d + "Coulomb stick, tangent 0 held",
                 co,
                 node(dim, 5.0, 3.0, -1e-4, 2e-3),
                 S::stick,
                 {N, I, N}};
      Case slip{d + "Coulomb slip, tangent 0 held",
                co,
                node(dim, 5.0, 3.0, -1e-4, -2e-3),
                S::slip,
                {N, I, P}};
      for (Case* c : {&stick, &slip}) {
        c->node.prescribed[0] = true, c->node.free_share[0] = 0.1;
        out.push_back(*c);
      }
    }
  }
  return out;
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

/// Every field of two results equal, the doubles bit for bit.
bool same_rows(const ContactLawRows& a, const ContactLawRows& b) {
  bool same =
      a.state == b.state && a.held_axis[0] == b.held_axis[0] && a.held_axis[1] == b.held_axis[1];
  for (int i = 0; i < 3; ++i) {
    same = same && a.kind[i] == b.kind[i] && a.component[i] == b.component[i] &&
           same_bits(a.C[i], b.C[i]);
    for (int q = 0; q < grout::ContactLawColumn::count; ++q)
      same = same && same_bits(a.dC[i][q], b.dC[i][q]);
  }
  return same;
}

TEST(ApiContactLaw, EqualsTheKernelBitwise) {
  const std::vector<Case> all = cases();
  for (const bool derivatives : {true, false}) {
    for (const Case& c : all) {
      SCOPED_TRACE(c.name + (derivatives ? ", with derivatives" : ", values"));
      const std::vector<ContactLawRows> api =
          grout::contact_law_at_nodes(c.settings, {c.node}, derivatives);
      ASSERT_EQ(api.size(), 1u);
      grout::ContactLawParameters p;
      p.dim = c.settings.dim, p.kind = int(c.settings.law);
      p.c_hat = c.settings.c_hat, p.c_t_hat = c.settings.c_t_hat, p.mu = c.settings.mu;
      p.active_tolerance = c.settings.active_tolerance;
      grout::ContactLawResult k;
      grout::contact_law(p, kernel_node(c.node), derivatives, k);
      const ContactLawRows& r = api[0];
      EXPECT_EQ(int(r.state), int(c.state));
      EXPECT_EQ(int(r.state), k.status);
      double nonzero = 0.0;
      for (int i = 0; i < 3; ++i) {
        if (i < c.settings.dim) {
          EXPECT_EQ(int(r.kind[i]), int(c.kind[i])) << "row " << i;
        }
        EXPECT_EQ(int(r.kind[i]), int(k.kind[i])) << "row " << i;
        EXPECT_EQ(r.component[i], k.component[i]) << "row " << i;
        EXPECT_TRUE(same_bits(r.C[i], k.C[i])) << "row " << i << ": " << r.C[i] << " " << k.C[i];
        for (int q = 0; q < grout::ContactLawColumn::count; ++q) {
          EXPECT_TRUE(same_bits(r.dC[i][q], k.dC[i][q])) << "row " << i << " column " << q;
          nonzero += std::abs(r.dC[i][q]);
        }
      }
      EXPECT_EQ(nonzero > 0.0, derivatives);  // the derivatives were asked for, or not
      EXPECT_EQ(r.held_axis[0], k.held_axis[0]);
      EXPECT_EQ(r.held_axis[1], k.held_axis[1]);
    }
  }
  // All cases in one call (one launch over many nodes) give the same bits as one at a time.
  for (int dim = 2; dim <= 3; ++dim) {
    std::vector<ContactLawInput> nodes;
    for (const Case& c : all)
      if (c.settings.dim == dim && c.settings.law == ContactLawType::coulomb)
        nodes.push_back(c.node);
    const auto s = settings(dim, ContactLawType::coulomb, 0.3);
    const auto together = grout::contact_law_at_nodes(s, nodes);
    ASSERT_EQ(together.size(), nodes.size());
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const auto alone = grout::contact_law_at_nodes(s, {nodes[i]});
      EXPECT_TRUE(same_rows(together[i], alone[0])) << "node " << i;
    }
  }
}

std::vector<std::string> launches;
/// Grout's launches (Kokkos' own, "Kokkos::View::destruction" and the like, left out).
void record_launch(const char* name, std::uint32_t, std::uint64_t*) {
  if (std::string(name).rfind("Kokkos::", 0) != 0) launches.emplace_back(name);
}

TEST(ApiContactLaw, RunsTheDriversLaunch) {
  launches.clear();
  Kokkos::Tools::Experimental::set_begin_parallel_for_callback(record_launch);
  const std::vector<Case> all = cases();
  std::vector<ContactLawInput> nodes = {all[0].node, all[1].node, all[2].node};
  grout::contact_law_at_nodes(all[0].settings, nodes, true);
  grout::contact_law_at_nodes(all[0].settings, nodes, false);
  Kokkos::Tools::Experimental::set_begin_parallel_for_callback(nullptr);
  ASSERT_EQ(launches.size(), 2u);
  EXPECT_EQ(launches[0], "grout::contact_law");
  EXPECT_EQ(launches[1], "grout::contact_law");
}

void expect_error(const ContactLawSettings& s, const ContactLawInput& x, const std::string& what) {
  try {
    grout::contact_law_at_nodes(s, std::vector<ContactLawInput>{ContactLawInput(), x});
    ADD_FAILURE() << "no error for " << what;
  } catch (const grout::ContactLawError& e) {
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

TEST(ApiContactLaw, BadValuesAreReported) {
  const ContactLawSettings good = settings(3, ContactLawType::coulomb, 0.3);
  const ContactLawInput fine = node(3, 1.0, 0.1, 0.0);
  ContactLawSettings s = good;
  s.dim = 4;
  expect_error(s, fine, "settings.dim = 4");
  s = good, s.c_hat = 0.0;
  expect_error(s, fine, "settings.c_hat");
  s = good, s.mu = -0.1;
  expect_error(s, fine, "settings.mu");
  s = good, s.law = ContactLawType(7);
  expect_error(s, fine, "settings.law = 7");
  ContactLawInput x = fine;
  x.gap = std::nan("");
  expect_error(good, x, "node 1: gap");
  x = fine, x.lambda[2] = INFINITY;
  expect_error(good, x, "node 1: lambda[2]");
  x = fine, x.free_share[1] = -1.0;
  expect_error(good, x, "node 1: free_share[1] < 0");
  // 2D reads no third component: a NaN there is not an error.
  x = node(2, 1.0, 0.1, 0.0), x.lambda[2] = std::nan("");
  EXPECT_NO_THROW(grout::contact_law_at_nodes(settings(2, ContactLawType::coulomb, 0.3), {x}));
}

}  // namespace
