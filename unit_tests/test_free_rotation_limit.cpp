// The Newton step's limit on a free rigid rotation (nonlinear/free_rotation_limit.hpp) on
// two stacked blocks (upper [0,1] x [1,2], slave = its bottom edge, held in x on its top edge,
// so that it turns freely about any point of the top edge). A step that turns the upper block
// by θ about (0.3, 2) and moves it down keeps, at the contact nodes x ∈ [0.25, 0.75], its mean
// motion and turns by θ' = (h/10) / √(1 + 0.25²) instead (w = θ e_z × (X − (0.5, 2)) slides the
// contact nodes by θ √(1 + (x − 0.5)²), h = 1/8 the slave face size); a step that slides them by
// less than h/10, a block held in y on its top edge too, and a frictional pair are left alone;
// the lower block and every prescribed dof never move. 1 and 2 ranks.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <cmath>
#include <limits>

#include "io/mesh_generators.hpp"
#include "nonlinear/free_rotation_limit.hpp"
#include "unit_tests/two_block_contact_input.hpp"

namespace {

using namespace grout;

struct Blocks {
  Mesh mesh = two_block_mesh_2d(4, 2, 8, 4);
  Teuchos::RCP<const Map> map;
  std::vector<double> prescribed;
  std::vector<std::vector<ContactNode>> active{1}, slave{1};

  bool hold_top_y = false;

  explicit Blocks(bool hold_top_y_) : hold_top_y(hold_top_y_) {
    const auto comm = Tpetra::getDefaultComm();
    const GO nodes = mesh.num_nodes();
    std::vector<GO> owned;
    for (GO n = 0; n < nodes; ++n)  // nodes split in two halves on 2 ranks
      if (n * comm->getSize() / nodes == comm->getRank())
        for (int c = 0; c < 2; ++c) owned.push_back(2 * n + c);
    map = Teuchos::rcp(new Map(2 * nodes, owned.data(), owned.size(), 0, comm));
    prescribed.assign(2 * nodes, std::numeric_limits<double>::quiet_NaN());
    for (GlobalIndex n : mesh.find_node_set("lower_bottom")->nodes)
      prescribed[2 * n] = prescribed[2 * n + 1] = 0.0;
    for (GlobalIndex n : mesh.find_node_set("upper_top")->nodes) {
      prescribed[2 * n] = 0.0;
      if (hold_top_y) prescribed[2 * n + 1] = 0.0;
    }
    for (GlobalIndex n : mesh.find_node_set("upper_bottom")->nodes) {
      if (!map->isNodeGlobalElement(2 * n)) continue;
      const double x = mesh.coordinates[2 * n];
      // the slave body's outward normal
      const ContactNode node{n, {0.0, -1.0, 0.0}, {x, mesh.coordinates[2 * n + 1], 0.0}};
      slave[0].push_back(node);
      if (x > 0.2 && x < 0.8) active[0].push_back(node);
    }
  }
  /// The pair, with the Dirichlet sets of `prescribed` (the limit's prescribed dofs).
  Input input(ContactKind type, double mu) const {
    Input in = two_block_bodies(2, type, mu, ContactGeometry::reference);
    add_dirichlet(in, "lower_bottom", 0, "0");
    add_dirichlet(in, "lower_bottom", 1, "0");
    add_dirichlet(in, "upper_top", 0, "0");
    if (hold_top_y) add_dirichlet(in, "upper_top", 1, "0");
    return in;
  }
  bool is_upper_node(GlobalIndex n) const {
    for (GlobalIndex m : mesh.find_block("upper")->connectivity)
      if (m == n) return true;
    return false;
  }
  // θ e_z × (X − (0.3, 2)) − 0.01 e_y on the upper block's free dofs, 0 elsewhere.
  Vector turn(double theta) const {
    Vector v(map);
    auto s = v.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t i = 0; i < s.extent(0); ++i) {
      const GO gid = map->getGlobalElement(LO(i));
      const GlobalIndex n = gid / 2;
      const int c = int(gid % 2);
      const double x = mesh.coordinates[2 * n], y = mesh.coordinates[2 * n + 1];
      double value = 0.0;
      if (is_upper_node(n) && std::isnan(prescribed[gid]))
        value = c == 0 ? -theta * (y - 2.0) : theta * (x - 0.3) - 0.01;
      s(i, 0) = value;
    }
    return v;
  }
};

double max_difference(const Vector& a, const Vector& b) {
  Vector d(a.getMap());
  d.update(1.0, a, -1.0, b, 0.0);
  return d.normInf();
}

TEST(FreeRotationLimit, TurnBeyondOneFaceIsCutToOneFace) {
  Blocks s(false);
  const FreeRotationLimit limit(s.mesh, s.input(ContactKind::frictionless, 0.0), s.map);
  ASSERT_EQ(limit.num_bodies(), 1);
  const double theta = 0.5, h = 0.125;
  Vector step = s.turn(theta);
  const double slide = limit.limit(s.active, s.slave, step);
  EXPECT_NEAR(slide, theta * std::sqrt(1.0 + 0.0625) / h, 1e-12);
  // The limited step is θ' e_z × (X − (0.5, 2)) plus what the cut left: at every upper node
  // u = θ e_z × (X − (0.3, 2)) − 0.01 e_y − (θ − θ') e_z × (X − (0.5, 2)).
  const double theta_new = 0.1 * h / std::sqrt(1.0 + 0.0625);
  Vector expected = s.turn(theta);
  {
    auto e = expected.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (std::size_t i = 0; i < e.extent(0); ++i) {
      const GO gid = s.map->getGlobalElement(LO(i));
      const GlobalIndex n = gid / 2;
      if (!s.is_upper_node(n) || !std::isnan(s.prescribed[gid])) continue;
      const double x = s.mesh.coordinates[2 * n], y = s.mesh.coordinates[2 * n + 1];
      e(i, 0) -= (theta - theta_new) * (gid % 2 == 0 ? -(y - 2.0) : x - 0.5);
    }
  }
  EXPECT_LT(max_difference(step, expected), 1e-12);
}

TEST(FreeRotationLimit, SmallTurnHeldBodyAndFrictionAreLeftAlone) {
  {
    Blocks s(false);
    const FreeRotationLimit limit(s.mesh, s.input(ContactKind::frictionless, 0.0), s.map);
    Vector step = s.turn(0.01), before = s.turn(0.01);  // slides by 0.0103 < h/10 = 0.0125
    EXPECT_LT(limit.limit(s.active, s.slave, step), 0.1);
    EXPECT_EQ(max_difference(step, before), 0.0);
    // No active node: the slave nodes stand for the contact (mean x = 0.5 again).
    std::vector<std::vector<ContactNode>> none(1);
    Vector big = s.turn(0.5);
    EXPECT_NEAR(limit.limit(none, s.slave, big), 0.5 * std::sqrt(1.25) / 0.125, 1e-12);
  }
  {
    Blocks s(true);  // held in x and y on the top edge: no free rotation
    const FreeRotationLimit limit(s.mesh, s.input(ContactKind::frictionless, 0.0), s.map);
    Vector step = s.turn(0.5), before = s.turn(0.5);
    EXPECT_EQ(limit.limit(s.active, s.slave, step), 0.0);
    EXPECT_EQ(max_difference(step, before), 0.0);
  }
  Blocks s(false);
  const FreeRotationLimit frictional(s.mesh, s.input(ContactKind::frictional, 0.3), s.map);
  EXPECT_EQ(frictional.num_bodies(), 0);
}

}  // namespace
