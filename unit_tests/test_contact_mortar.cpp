// Mortar quantities of a whole contact interface (assembly/contact_mortar): the sums and
// patch properties of docs/design.md §3 on non-matching flat interfaces, and the derivatives
// against central finite differences.

#include <gtest/gtest.h>

#include <cmath>

#include "assembly/contact_mortar.hpp"
#include "io/mesh_generators.hpp"

namespace grout {
namespace {

struct InterfaceSetup {
  Mesh mesh;
  Input input;
  ContactSurface surface;
  std::vector<std::array<double, 3>> x;
};

InterfaceSetup two_blocks(int dim, double tilt) {
  InterfaceSetup s;
  s.mesh = dim == 2 ? two_block_mesh_2d(4, 3, 5, 3) : two_block_mesh_3d(3, 3, 2, 4, 5, 2);
  s.input.file = "test.yaml";
  ContactInput ci;
  ci.name = "interface";
  ci.slave = "upper_bottom";
  ci.master = "lower_top";
  s.surface = build_contact_surface(s.mesh, s.input, ci);
  s.x.assign(s.surface.nodes.size(), {0.0, 0.0, 0.0});
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    for (int d = 0; d < dim; ++d) s.x[i][d] = s.mesh.coordinates[s.surface.nodes[i] * dim + d];
    s.x[i][dim - 1] += tilt * s.x[i][0];  // a flat but inclined interface
  }
  return s;
}

double f_linear(const std::array<double, 3>& x) {
  return 0.3 + 1.7 * x[0] - 0.4 * x[1] + 0.9 * x[2];
}

void check_patch_properties(int dim) {
  InterfaceSetup s = two_blocks(dim, 0.1);
  const ContactMortar m = evaluate_contact_mortar(s.surface, s.x, ContactMortarOptions());
  double sum_D = 0.0, sum_M = 0.0;
  const auto pos = [&](GlobalIndex n) {
    return s.x[std::lower_bound(s.surface.nodes.begin(), s.surface.nodes.end(), n) -
               s.surface.nodes.begin()];
  };
  std::vector<double> row_M(s.surface.slave_nodes.size(), 0.0), mapped(row_M.size(), 0.0);
  for (const auto& [key, M] : m.M) {
    sum_M += M.value;
    row_M[key.first] += M.value;
    mapped[key.first] += M.value * f_linear(pos(key.second));
  }
  const double area = std::sqrt(1.0 + 0.01);  // inclined unit length / unit square
  for (std::size_t j = 0; j < m.D.size(); ++j) {
    sum_D += m.D[j].value;
    EXPECT_NEAR(row_M[j], m.D[j].value, 1e-13) << "slave node " << j;
    EXPECT_NEAR(mapped[j], m.D[j].value * f_linear(pos(s.surface.slave_nodes[j])), 1e-13)
        << "slave node " << j;
  }
  EXPECT_NEAR(sum_D, dim == 2 ? area : area, 1e-13);
  EXPECT_NEAR(sum_M, sum_D, 1e-13);
}

TEST(ContactMortar, PatchPropertiesOnNonMatchingInterface2D) {
  check_patch_properties(2);
}
TEST(ContactMortar, PatchPropertiesOnNonMatchingInterface3D) {
  check_patch_properties(3);
}

}  // namespace
}  // namespace grout

namespace grout {
namespace {

// Collocation (element-based integration) is not exact: its M differs from the segment-based
// one where master nodes fall inside slave elements, and the difference shrinks with points.
TEST(ContactMortar, CollocationConvergesToExactButIsNotExact) {
  InterfaceSetup s = two_blocks(2, 0.0);
  const ContactMortar exact = evaluate_contact_mortar(s.surface, s.x, ContactMortarOptions());
  double previous = 1e300;
  for (int points : {10, 40, 160}) {
    ContactMortarOptions options;
    options.mortar = mortar_options(2, MortarIntegration::collocation, points);
    const ContactMortar c = evaluate_contact_mortar(s.surface, s.x, options);
    double difference = 0.0;
    for (const auto& [key, M] : exact.M) {
      const auto it = c.M.find(key);
      difference =
          std::max(difference, std::abs(M.value - (it == c.M.end() ? 0.0 : it->second.value)));
    }
    EXPECT_GT(difference, 1e-8) << points << " points";
    EXPECT_LT(difference, previous) << points << " points";
    previous = difference;
  }
}

}  // namespace
}  // namespace grout

namespace grout {
namespace {

// The partly covered node rule (dual_covered): a slave face of length h covered by a master only
// over its far part (ξ from a to 1, a = 0.24, counted from the node) with the gap rising
// steeply across that part. The 1D dual function of the node, 2 N₁ − N₂ = 2 − 3s, changes sign
// at s = 2/3, so D_jj = ∫_a^1 (2 − 3s) ds · (h/2 per unit of the other direction) is small
// (0.106 h instead of h/2) and g̃ / D_jj extrapolates the gap: with gap(s) = δ + k h (s − a)
// it is δ + k h ∫_a^1 (2 − 3s)(s − a) ds / ∫_a^1 (2 − 3s) ds = δ − 0.651 k h < 0 for
// k h > δ / 0.651, a false penetration of a node whose true gap is δ or more everywhere. The
// rule drops such a node (D_jj < 0.5 w_j); fully covered nodes keep g̃ / D_jj, the exact
// nodal gap of a linear gap field.
TEST(ContactMortar, PartlyCoveredNodeWithFalsePenetrationHasNoMaster) {
  // Lower block [0,1]³ (1 × 1 faces on top, the master), upper block (2 × 1 faces at its
  // bottom z = 1, the slave): the master face moved to x ∈ [0.12, 1.12] and tilted.
  InterfaceSetup s;
  s.mesh = two_block_mesh_3d(1, 1, 1, 2, 1, 1);
  s.input.file = "test.yaml";
  ContactInput ci;
  ci.name = "interface";
  ci.slave = "upper_bottom";
  ci.master = "lower_top";
  s.surface = build_contact_surface(s.mesh, s.input, ci);
  const double delta = 0.01, slope = 0.5;  // gap δ at the master's left edge, rising 0.5 / unit x
  s.x.assign(s.surface.nodes.size(), {0.0, 0.0, 0.0});
  const auto is_slave = [&](GlobalIndex n) {
    return std::binary_search(s.surface.slave_nodes.begin(), s.surface.slave_nodes.end(), n);
  };
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const GlobalIndex n = s.surface.nodes[i];
    for (int d = 0; d < 3; ++d) s.x[i][d] = s.mesh.coordinates[n * 3 + d];
    if (!is_slave(n)) {
      s.x[i][0] += 0.12;
      s.x[i][2] = 1.0 - delta - slope * (s.x[i][0] - 0.12);
    }
  }
  const ContactMortar m = evaluate_contact_mortar(s.surface, s.x, ContactMortarOptions());
  double D_max = 0.0;
  for (const auto& D : m.D) D_max = std::max(D_max, D.value);
  const double D_tol = 1e-8 * D_max;  // the driver's "no master" tolerance
  int dropped = 0, kept = 0;
  for (std::size_t j = 0; j < s.surface.slave_nodes.size(); ++j) {
    const GlobalIndex node = s.surface.slave_nodes[j];
    const auto& x = s.x[std::lower_bound(s.surface.nodes.begin(), s.surface.nodes.end(), node) -
                        s.surface.nodes.begin()];
    // g̃_j = −n_j · (D_jj x_j − Σ_l M_jl x_l)
    double v[3];
    for (int d = 0; d < 3; ++d) v[d] = m.D[j].value * x[d];
    for (auto it = m.M.lower_bound({int(j), 0}); it != m.M.end() && it->first.first == int(j);
         ++it) {
      const auto& y =
          s.x[std::lower_bound(s.surface.nodes.begin(), s.surface.nodes.end(), it->first.second) -
              s.surface.nodes.begin()];
      for (int d = 0; d < 3; ++d) v[d] -= it->second.value * y[d];
    }
    const double g =
        -(m.frames[j].n[0] * v[0] + m.frames[j].n[1] * v[1] + m.frames[j].n[2] * v[2]) /
        m.D[j].value;
    if (x[0] == 0.0) {
      // Covered over s ∈ [a, 1] of its face (h = 0.5): D_jj / w_j = 2 I₁ = 0.2128 and
      // g = δ + slope h I₂ / I₁ = −0.1529, I₁ = ∫_a^1 (2 − 3s) ds, I₂ = ∫_a^1 (2 − 3s)(s − a) ds.
      const double a = 0.24, h = 0.5;
      const double I1 = 2.0 * (1.0 - a) - 1.5 * (1.0 - a * a);
      const double I2 = (a * a * a - a * a) - a * I1;
      EXPECT_NEAR(m.D[j].value / m.W[j], 2.0 * I1, 1e-12) << "slave node " << node;
      EXPECT_NEAR(g, delta + slope * h * I2 / I1, 1e-12) << "slave node " << node;
      EXPECT_LT(g, -0.1) << "slave node " << node << ": the false penetration";
      EXPECT_GT(m.D[j].value, D_tol);
      EXPECT_FALSE(dual_covered(m, int(j))) << "slave node " << node;
      ++dropped;
    } else if (x[0] == 1.0) {
      // Fully covered: D_jj = w_j and g the gap of the plane at x = 1.
      EXPECT_NEAR(m.D[j].value, m.W[j], 1e-13) << "slave node " << node;
      EXPECT_NEAR(g, delta + slope * (1.0 - 0.12), 1e-12) << "slave node " << node;
      EXPECT_TRUE(dual_covered(m, int(j))) << "slave node " << node;
      ++kept;
    }
  }
  EXPECT_EQ(dropped, 2);
  EXPECT_EQ(kept, 2);
}

}  // namespace
}  // namespace grout

namespace grout {
namespace {

// Contact pairs face each other: a master face within the search box whose normal points the
// same way as the slave face's (here the slave's bottom, n = −e_z, and a master face 0.3 inside
// the slave block with n = −e_z: a wall behind the slave face, as the crossed tubes' lower tube
// under the upper tube's flank) is not paired. Integrated, it would give every slave node the
// false penetration g = −0.3.
TEST(ContactMortar, MasterFaceFacingAwayIsNotPaired) {
  InterfaceSetup s;
  s.mesh = two_block_mesh_3d(1, 1, 1, 2, 1, 1);
  s.input.file = "test.yaml";
  ContactInput ci;
  ci.name = "interface";
  ci.slave = "upper_bottom";
  ci.master = "lower_top";
  s.surface = build_contact_surface(s.mesh, s.input, ci);
  s.x.assign(s.surface.nodes.size(), {0.0, 0.0, 0.0});
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const GlobalIndex n = s.surface.nodes[i];
    for (int d = 0; d < 3; ++d) s.x[i][d] = s.mesh.coordinates[n * 3 + d];
    if (!std::binary_search(s.surface.slave_nodes.begin(), s.surface.slave_nodes.end(), n)) {
      s.x[i][1] = 1.0 - s.x[i][1];  // mirrored: the master face's normal becomes −e_z
      s.x[i][2] = 1.3;
    }
  }
  const ContactMortar m = evaluate_contact_mortar(s.surface, s.x, ContactMortarOptions());
  EXPECT_EQ(m.pairs, 0);
  for (std::size_t j = 0; j < m.D.size(); ++j) EXPECT_EQ(m.D[j].value, 0.0) << "slave node " << j;
  EXPECT_TRUE(m.M.empty());
  // The same face turned to face the slave (n = +e_z): paired, every node 0.3 into it.
  for (std::size_t i = 0; i < s.x.size(); ++i)
    if (!std::binary_search(s.surface.slave_nodes.begin(), s.surface.slave_nodes.end(),
                            s.surface.nodes[i]))
      s.x[i][1] = 1.0 - s.x[i][1];
  const ContactMortar facing = evaluate_contact_mortar(s.surface, s.x, ContactMortarOptions());
  EXPECT_EQ(facing.pairs, 2);
  for (std::size_t j = 0; j < facing.D.size(); ++j)
    EXPECT_NEAR(facing.D[j].value, facing.W[j], 1e-14) << "slave node " << j;
}

}  // namespace
}  // namespace grout
