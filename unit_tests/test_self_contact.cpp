// Self-contact (docs/input.md "Self-contact"): the search's self filters (no pair of faces that
// share a node, element normals facing each other) and the choice of slave and master sides
// (assembly/contact_surface.hpp, self_contact_sides), on a hand-made fold.

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>

#include "assembly/contact_mortar.hpp"

namespace grout {
namespace {

// Four unit quads of one block: two below y = 1 (elements 0, 1) and two above it (2, 3),
// joined at (0, 1) only (node 3 is shared by elements 0 and 2; (1, 1) and (2, 1) are doubled):
// a slit along y = 1 from x = 0 to 2 whose tip is (0, 1). Side set `fold`: face 0 = top of
// element 0, 1 = top of 1, 2 = bottom of 2, 3 = bottom of 3.
Mesh fold_mesh() {
  Mesh m;
  m.file = "fold.exo";
  m.dimension = 2;
  m.coordinates = {0, 0, 1, 0, 1, 1, 0, 1, 1, 1, 1, 2, 0, 2, 2, 0, 2, 1, 2, 1, 2, 2};
  ElementBlock b;
  b.name = "strip";
  b.id = 1;
  b.topology = Topology::quad4;
  b.nodes_per_element = 4;
  b.connectivity = {0, 1, 2, 3, 1, 7, 8, 2, 3, 4, 5, 6, 4, 9, 10, 5};
  m.blocks.push_back(b);
  SideSet s;
  s.name = "fold";
  s.id = 1;
  s.elements = {0, 1, 2, 3};
  s.sides = {3, 3, 1, 1};
  m.side_sets.push_back(s);
  return m;
}

struct Fold {
  Mesh mesh = fold_mesh();
  Input input;
  ContactSurface surface;
  std::vector<std::array<double, 3>> x;
  Fold() {
    input.file = "test.yaml";
    ContactInput ci;
    ci.name = "fold";
    ci.self = true;
    ci.slave = ci.master = "fold";
    surface = build_contact_surface(mesh, input, ci);
    for (GlobalIndex n : surface.nodes)
      x.push_back({mesh.coordinates[2 * n], mesh.coordinates[2 * n + 1], 0.0});
  }
  std::set<std::pair<GlobalIndex, GlobalIndex>> pairs() const {
    const auto p = contact_pairs(surface, x, ContactMortarOptions());
    return {p.begin(), p.end()};
  }
};

TEST(SelfContact, SearchDropsNeighboursAndKeepsFacingFlanks) {
  Fold f;
  ASSERT_TRUE(f.surface.self);
  // 0-2 face each other but share the tip node 3; 0-1 and 2-3 are neighbours on one flank.
  const std::set<std::pair<GlobalIndex, GlobalIndex>> expected = {{0, 3}, {1, 2}, {1, 3},
                                                                  {2, 1}, {3, 0}, {3, 1}};
  EXPECT_EQ(f.pairs(), expected);
}

TEST(SelfContact, SearchDropsFacesWhoseNormalsDoNotFaceEachOther) {
  Fold f;
  // Face 3 reversed (its nodes 4 and 9 swap places): its normal points up like the lower
  // flank's, so it pairs with no lower face; 1-2 still face each other.
  const auto at = [&](GlobalIndex n) {
    return std::size_t(std::lower_bound(f.surface.nodes.begin(), f.surface.nodes.end(), n) -
                       f.surface.nodes.begin());
  };
  std::swap(f.x[at(4)], f.x[at(9)]);
  const std::set<std::pair<GlobalIndex, GlobalIndex>> expected = {{1, 2}, {2, 1}};
  EXPECT_EQ(f.pairs(), expected);
}

TEST(SelfContact, SidesColourEachComponentFromItsLowestFace) {
  // The fold: one component {0, 1, 2, 3}; face 0 (lowest) is a slave face.
  std::vector<long long> pairs = {0, 3, 1, 2, 1, 3, 2, 1, 3, 0, 3, 1};
  const std::vector<signed char> fold = {1, 1, 0, 0};
  EXPECT_EQ(self_contact_sides(4, pairs), fold);
  // The same pairs in another order (as gathered from other ranks): the same sides.
  std::vector<long long> reordered = {3, 1, 2, 1, 1, 3, 0, 3, 3, 0, 1, 2};
  EXPECT_EQ(self_contact_sides(4, reordered), fold);
  // Two components and a face of no pair: {5, 8} from 5, {2, 4, 7} from 2 (4 and 7 master);
  // an odd cycle {0, 1, 6}: 0 slave, 1 and 6 master (the pair 1-6 is left on one side).
  const std::vector<long long> mixed = {8, 5, 4, 2, 7, 2, 6, 0, 1, 0, 1, 6};
  const std::vector<signed char> sides = {1, 0, 1, -1, 0, 1, 0, 0, 0};
  EXPECT_EQ(self_contact_sides(9, mixed), sides);
}

TEST(SelfContact, SidesKeptWithinAStepSpreadToNewPartners) {
  // Faces 1 (master) and 2 (slave) were chosen earlier in the step; faces 0 and 3 come into
  // reach. A fresh choice would make 0 a slave face and flip 1 and 2; kept, 2's new partner
  // 0 is a master face and 3, in no pair with a kept face, starts a component of its own.
  const std::vector<long long> pairs = {0, 2, 1, 2, 3, 4};
  const std::vector<signed char> fresh = {1, 1, 0, 1, 0};
  EXPECT_EQ(self_contact_sides(5, pairs), fresh);
  const std::vector<signed char> keep = {-1, 0, 1, -1, -1};
  const std::vector<signed char> kept = {0, 0, 1, 1, 0};
  EXPECT_EQ(self_contact_sides(5, pairs, keep), kept);
}

}  // namespace
}  // namespace grout
