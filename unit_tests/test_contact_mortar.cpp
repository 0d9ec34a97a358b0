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
