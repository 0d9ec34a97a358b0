// Two-body contact meshes (io/contact_meshes.hpp): Exodus round trip, valid elements, bodies
// without shared nodes, side sets on the boundary with outward normals in the expected
// direction, node sets = side-set nodes, and the geometry each verification case relies on.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "io/contact_meshes.hpp"
#include "io/exodus.hpp"
#include "io/mesh_generators.hpp"

namespace {

using grout::GlobalIndex;
using grout::Mesh;
using Vec = std::array<double, 3>;

Vec point(const Mesh& m, GlobalIndex node) {
  Vec p{0, 0, 0};
  for (int d = 0; d < m.dimension; ++d) p[d] = m.coordinates[m.dimension * node + d];
  return p;
}
Vec sub(const Vec& a, const Vec& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
double norm(const Vec& a) {
  return std::sqrt(dot(a, a));
}

const grout::ElementBlock& block_of(const Mesh& m, GlobalIndex e) {
  for (const auto& b : m.blocks)
    if (e >= b.first_element && e < b.first_element + b.num_elements()) return b;
  throw std::logic_error("element in no block");
}

/// Nodes of side `side` of element e, in side_local_nodes order.
std::vector<GlobalIndex> side_nodes(const Mesh& m, GlobalIndex e, int side) {
  const auto& b = block_of(m, e);
  int local[grout::max_side_nodes];
  const int n = grout::side_local_nodes(b.topology, side, local);
  std::vector<GlobalIndex> nodes;
  for (int a = 0; a < n; ++a)
    nodes.push_back(b.connectivity[(e - b.first_element) * b.nodes_per_element + local[a]]);
  return nodes;
}

/// Unit outward normal of a side (right-hand rule of the Exodus side ordering).
Vec side_normal(const Mesh& m, const std::vector<GlobalIndex>& nodes) {
  Vec n;
  if (nodes.size() == 2) {
    const Vec t = sub(point(m, nodes[1]), point(m, nodes[0]));
    n = {t[1], -t[0], 0.0};
  } else if (nodes.size() == 3) {
    n = cross(sub(point(m, nodes[1]), point(m, nodes[0])),
              sub(point(m, nodes[2]), point(m, nodes[0])));
  } else {
    n = cross(sub(point(m, nodes[2]), point(m, nodes[0])),
              sub(point(m, nodes[3]), point(m, nodes[1])));
  }
  const double l = norm(n);
  return {n[0] / l, n[1] / l, n[2] / l};
}

Vec centroid(const Mesh& m, const std::vector<GlobalIndex>& nodes) {
  Vec c{0, 0, 0};
  for (GlobalIndex n : nodes)
    for (int d = 0; d < 3; ++d) c[d] += point(m, n)[d] / double(nodes.size());
  return c;
}

/// Expected outward unit normal at point x of side set `name` (zero vector: not checked).
using NormalRule = std::function<Vec(const Vec&)>;

NormalRule constant(Vec n) {
  return [n](const Vec&) { return n; };
}

/// Properties every generated two-body mesh must have; `rules` gives the expected outward
/// normal of side sets (every side set must have a rule).
void check_two_body_mesh(const Mesh& m, const std::map<std::string, NormalRule>& rules,
                         const std::string& tag) {
  SCOPED_TRACE(tag);
  EXPECT_GT(grout::min_corner_jacobian(m), 0.0);
  // Bodies share no nodes; every node belongs to an element.
  std::vector<int> owner(std::size_t(m.num_nodes()), -1);
  for (std::size_t b = 0; b < m.blocks.size(); ++b)
    for (GlobalIndex n : m.blocks[b].connectivity) {
      EXPECT_TRUE(owner[n] == -1 || owner[n] == int(b)) << "node " << n << " shared";
      owner[n] = int(b);
    }
  EXPECT_EQ(std::count(owner.begin(), owner.end(), -1), 0);
  // Element first indices are consecutive.
  GlobalIndex first = 0;
  for (const auto& b : m.blocks) {
    EXPECT_EQ(b.first_element, first);
    first += b.num_elements();
  }
  // Every side of a side set is a boundary side of its block, with the expected normal.
  std::map<std::vector<GlobalIndex>, int> uses;
  for (const auto& b : m.blocks)
    for (GlobalIndex e = 0; e < b.num_elements(); ++e)
      for (int s = 1; s <= grout::topology_num_sides(b.topology); ++s) {
        auto key = side_nodes(m, b.first_element + e, s);
        std::sort(key.begin(), key.end());
        ++uses[key];
      }
  for (const auto& set : m.side_sets) {
    SCOPED_TRACE(set.name);
    ASSERT_FALSE(set.elements.empty());
    ASSERT_EQ(set.elements.size(), set.sides.size());
    ASSERT_TRUE(rules.count(set.name)) << "no normal rule for side set " << set.name;
    std::set<GlobalIndex> nodes;
    for (std::size_t i = 0; i < set.elements.size(); ++i) {
      const auto sn = side_nodes(m, set.elements[i], set.sides[i]);
      auto key = sn;
      std::sort(key.begin(), key.end());
      EXPECT_EQ(uses[key], 1) << "side is not on the boundary";
      const Vec n = side_normal(m, sn), c = centroid(m, sn);
      // Outward: away from the element's centroid.
      const auto& b = block_of(m, set.elements[i]);
      std::vector<GlobalIndex> all(
          b.connectivity.begin() + (set.elements[i] - b.first_element) * b.nodes_per_element,
          b.connectivity.begin() + (set.elements[i] - b.first_element + 1) * b.nodes_per_element);
      EXPECT_GT(dot(n, sub(c, centroid(m, all))), 0.0);
      const Vec expected = rules.at(set.name)(c);
      EXPECT_GT(dot(n, expected), 0.99) << "normal (" << n[0] << ", " << n[1] << ", " << n[2]
                                        << ") at (" << c[0] << ", " << c[1] << ", " << c[2] << ")";
      nodes.insert(sn.begin(), sn.end());
    }
    const auto* ns = m.find_node_set(set.name);
    ASSERT_NE(ns, nullptr) << "no node set " << set.name;
    EXPECT_EQ(std::vector<GlobalIndex>(nodes.begin(), nodes.end()), ns->nodes);
  }
  // Exodus round trip.
  const std::string path =
      std::string(GROUT_BINARY_DIR) + "/test_io_contact_meshes_" + tag + ".exo";
  grout::write_exodus_mesh(path, m);
  const Mesh r = grout::read_exodus(path);
  EXPECT_EQ(r.coordinates, m.coordinates);
  ASSERT_EQ(r.blocks.size(), m.blocks.size());
  for (std::size_t b = 0; b < m.blocks.size(); ++b) {
    EXPECT_EQ(r.blocks[b].name, m.blocks[b].name);
    EXPECT_EQ(r.blocks[b].topology, m.blocks[b].topology);
    EXPECT_EQ(r.blocks[b].connectivity, m.blocks[b].connectivity);
  }
  ASSERT_EQ(r.side_sets.size(), m.side_sets.size());
  for (std::size_t s = 0; s < m.side_sets.size(); ++s) {
    EXPECT_EQ(r.side_sets[s].name, m.side_sets[s].name);
    EXPECT_EQ(r.side_sets[s].elements, m.side_sets[s].elements);
    EXPECT_EQ(r.side_sets[s].sides, m.side_sets[s].sides);
  }
  ASSERT_EQ(r.node_sets.size(), m.node_sets.size());
  for (std::size_t s = 0; s < m.node_sets.size(); ++s) {
    EXPECT_EQ(r.node_sets[s].name, m.node_sets[s].name);
    EXPECT_EQ(r.node_sets[s].nodes, m.node_sets[s].nodes);
  }
  std::remove(path.c_str());
}

std::map<std::string, NormalRule> box_rules(const std::vector<std::string>& prefixes, int dim) {
  std::map<std::string, NormalRule> r;
  for (const auto& p : prefixes) {
    if (dim == 2) {
      r[p + "bottom"] = constant({0, -1, 0});
      r[p + "top"] = constant({0, 1, 0});
      r[p + "left"] = constant({-1, 0, 0});
      r[p + "right"] = constant({1, 0, 0});
    } else {
      r[p + "bottom"] = constant({0, 0, -1});
      r[p + "top"] = constant({0, 0, 1});
      r[p + "xmin"] = constant({-1, 0, 0});
      r[p + "xmax"] = constant({1, 0, 0});
      r[p + "ymin"] = constant({0, -1, 0});
      r[p + "ymax"] = constant({0, 1, 0});
    }
  }
  return r;
}

const grout::NodeSet& node_set(const Mesh& m, const std::string& name) {
  const auto* s = m.find_node_set(name);
  if (!s) throw std::logic_error("no node set " + name);
  return *s;
}

TEST(ContactMeshes, StackedBlocks) {
  grout::StackedBlocks s;
  s.simplex_lower = true;
  s.distortion = 0.25;
  s.seed = 3;
  const Mesh m2 = grout::stacked_blocks_2d(s);
  EXPECT_EQ(m2.blocks[0].topology, grout::Topology::tri3);
  EXPECT_EQ(m2.blocks[1].topology, grout::Topology::quad4);
  check_two_body_mesh(m2, box_rules({"lower_", "upper_"}, 2), "stacked_2d");
  // The interface stays flat under distortion: both sides on y = 1.
  for (const char* name : {"lower_top", "upper_bottom"})
    for (GlobalIndex n : node_set(m2, name).nodes) EXPECT_EQ(point(m2, n)[1], 1.0);

  s.nx_lower = 3, s.ny_lower = 4, s.nx_upper = 4, s.ny_upper = 3, s.nz_upper = 2;
  s.simplex_lower = false;
  s.simplex_upper = true;
  const Mesh m3 = grout::stacked_blocks_3d(s);
  EXPECT_EQ(m3.blocks[0].topology, grout::Topology::hex8);
  EXPECT_EQ(m3.blocks[1].topology, grout::Topology::tet4);
  check_two_body_mesh(m3, box_rules({"lower_", "upper_"}, 3), "stacked_3d");
  for (const char* name : {"lower_top", "upper_bottom"})
    for (GlobalIndex n : node_set(m3, name).nodes) EXPECT_EQ(point(m3, n)[2], 1.0);
}

TEST(ContactMeshes, SlopedBlocks) {
  grout::SlopedBlocks s;
  const Mesh m = grout::sloped_blocks_2d(s);
  auto rules = box_rules({"lower_", "upper_"}, 2);
  const double dy = s.y_right - s.y_left, l = std::hypot(s.width, dy);
  rules["lower_top"] = constant({-dy / l, s.width / l, 0});
  rules["upper_bottom"] = constant({dy / l, -s.width / l, 0});
  check_two_body_mesh(m, rules, "sloped");
  // Interface nodes of both bodies on the line from (0, 0.9) to (1, 1.1).
  for (const char* name : {"lower_top", "upper_bottom"}) {
    const auto& nodes = node_set(m, name).nodes;
    EXPECT_EQ(nodes.size(), std::string(name) == "lower_top" ? 5u : 6u);
    for (GlobalIndex n : nodes) {
      const Vec p = point(m, n);
      EXPECT_NEAR(p[1], s.y_left + dy * p[0] / s.width, 1e-15);
    }
  }
  grout::SlopedBlocks tri = s;
  tri.triangles_upper = true;
  check_two_body_mesh(grout::sloped_blocks_2d(tri), rules, "sloped_tri");
}

TEST(ContactMeshes, TaylorPatch2d) {
  grout::TaylorPatch s;
  s.die_stretch = 0.3;
  s.simplex_die = true;
  const Mesh m = grout::taylor_patch_2d(s);
  auto rules = box_rules({"block_", "die_"}, 2);
  rules["block_top_free"] = constant({0, 1, 0});
  check_two_body_mesh(m, rules, "taylor_2d");
  // Free top = the 6 of 8 top edges outside [4, 6]; the die's edges lie on foundation nodes.
  const auto* free = m.find_side_set("block_top_free");
  EXPECT_EQ(free->elements.size(), 6u);
  for (GlobalIndex n : node_set(m, "block_top_free").nodes) {
    const double x = point(m, n)[0];
    EXPECT_TRUE(x <= 4.0 || x >= 6.0) << x;
  }
  EXPECT_EQ(point(m, node_set(m, "block_origin").nodes.at(0)), (Vec{0, 0, 0}));
  EXPECT_EQ(point(m, node_set(m, "die_anchor").nodes.at(0)), (Vec{4, 7, 0}));
  // Stretched die columns: x = 4 + 2 (u + 0.3 u (1 - u)).
  std::set<double> xs;
  for (GlobalIndex n : node_set(m, "die_bottom").nodes) xs.insert(point(m, n)[0]);
  const std::vector<double> expected = {4.0, 4.0 + 2.0 * (1.0 / 3 + 0.3 * 2.0 / 9),
                                        4.0 + 2.0 * (2.0 / 3 + 0.3 * 2.0 / 9), 6.0};
  ASSERT_EQ(xs.size(), 4u);
  std::size_t i = 0;
  for (double x : xs) EXPECT_NEAR(x, expected[i++], 1e-14);
  EXPECT_THROW(grout::taylor_patch_2d({6}), std::invalid_argument);
}

TEST(ContactMeshes, TaylorPatch3d) {
  for (bool tets : {false, true}) {
    grout::TaylorPatch s;
    s.ny_block = 8, s.ny_die = 3;
    s.simplex_block = s.simplex_die = tets;
    const Mesh m = grout::taylor_patch_3d(s);
    auto rules = box_rules({"block_", "die_"}, 3);
    rules["block_top_free"] = constant({0, 0, 1});
    check_two_body_mesh(m, rules, tets ? "taylor_3d_tet" : "taylor_3d_hex");
    // Free top = 64 - 4 unit cells (hexes) or twice as many triangles.
    EXPECT_EQ(m.find_side_set("block_top_free")->elements.size(), tets ? 120u : 60u);
    EXPECT_EQ(point(m, node_set(m, "block_x_end").nodes.at(0)), (Vec{8, 0, 0}));
    EXPECT_EQ(point(m, node_set(m, "die_anchor").nodes.at(0)), (Vec{4, 4, 6}));
    EXPECT_EQ(point(m, node_set(m, "die_x_end").nodes.at(0)), (Vec{6, 4, 6}));
  }
}

/// Outward normal of a disc of centre (0, cy) at x: (x - c)/|x - c|.
NormalRule radial(double cy) {
  return [cy](const Vec& x) {
    const double l = std::hypot(x[0], x[1] - cy);
    return Vec{x[0] / l, (x[1] - cy) / l, 0};
  };
}

/// Largest edge length of the elements touching the contact point (0, 0) within |x| < b.
double contact_element_size(const Mesh& m, const std::string& set, double b) {
  double h = 0.0;
  const auto& nodes = node_set(m, set).nodes;
  std::vector<GlobalIndex> sorted;
  for (GlobalIndex n : nodes)
    if (std::abs(point(m, n)[0]) <= b) sorted.push_back(n);
  std::sort(sorted.begin(), sorted.end(),
            [&](GlobalIndex a, GlobalIndex c) { return point(m, a)[0] < point(m, c)[0]; });
  for (std::size_t i = 1; i < sorted.size(); ++i)
    h = std::max(h, norm(sub(point(m, sorted[i]), point(m, sorted[i - 1]))));
  return h;
}

TEST(ContactMeshes, HertzCylinders) {
  const double R = 8.0, b = 0.6808;
  double previous_h = HUGE_VAL;
  for (int level = 1; level <= 3; ++level) {
    const Mesh m = grout::hertz_cylinders_mesh(level, R);
    std::map<std::string, NormalRule> rules = {{"upper_contact", radial(R)},
                                               {"lower_contact", radial(-R)},
                                               {"upper_top", constant({0, 1, 0})},
                                               {"lower_bottom", constant({0, -1, 0})}};
    check_two_body_mesh(m, rules, "hertz_" + std::to_string(level));
    EXPECT_LE(m.num_nodes(), 20000);
    // Arc nodes exactly on their circle, within the contact width, touching at the origin.
    for (const auto& [name, cy] :
         std::map<std::string, double>{{"upper_contact", R}, {"lower_contact", -R}}) {
      bool origin = false;
      for (GlobalIndex n : node_set(m, name).nodes) {
        const Vec p = point(m, n);
        EXPECT_NEAR(std::hypot(p[0], p[1] - cy), R, 1e-13 * R);
        EXPECT_LE(std::abs(p[0]), 2.5);
        origin = origin || (p[0] == 0.0 && p[1] == 0.0);
      }
      EXPECT_TRUE(origin) << name;
    }
    // Flat faces span the full diameter (the load P = 2 R p acts on all of it).
    for (const char* name : {"upper_top", "lower_bottom"}) {
      double lo = HUGE_VAL, hi = -HUGE_VAL;
      for (GlobalIndex n : node_set(m, name).nodes) {
        lo = std::min(lo, point(m, n)[0]);
        hi = std::max(hi, point(m, n)[0]);
      }
      EXPECT_EQ(lo, -R);
      EXPECT_EQ(hi, R);
    }
    // Element size within the contact zone halves per level; finest well below b/10.
    const double h = contact_element_size(m, "upper_contact", b);
    EXPECT_LT(h, 0.6 * previous_h);
    previous_h = h;
    if (level == 3) {
      EXPECT_LT(h, b / 10.0);
    }
    // Non-matching: the lower body's contact nodes differ from the upper body's.
    std::set<double> upper_x, lower_x;
    for (GlobalIndex n : node_set(m, "upper_contact").nodes) upper_x.insert(point(m, n)[0]);
    for (GlobalIndex n : node_set(m, "lower_contact").nodes) lower_x.insert(point(m, n)[0]);
    EXPECT_NE(upper_x, lower_x);
  }
  EXPECT_THROW(grout::hertz_cylinders_mesh(0), std::invalid_argument);
}

TEST(ContactMeshes, CylinderOnPlane) {
  const double R = 6.1237;
  for (int level = 1; level <= 3; ++level) {
    const Mesh m = grout::cylinder_on_plane_mesh(level, R);
    auto rules = box_rules({"plane_"}, 2);
    rules["cylinder_contact"] = radial(R);
    rules["cylinder_top"] = constant({0, 1, 0});
    check_two_body_mesh(m, rules, "cylinder_plane_" + std::to_string(level));
    // The node set "plane" holds every node of the plane block.
    std::set<GlobalIndex> plane(m.blocks[1].connectivity.begin(), m.blocks[1].connectivity.end());
    EXPECT_EQ(std::vector<GlobalIndex>(plane.begin(), plane.end()), node_set(m, "plane").nodes);
    for (GlobalIndex n : node_set(m, "cylinder_top").nodes) EXPECT_EQ(point(m, n)[1], R);
    for (GlobalIndex n : node_set(m, "plane_top").nodes) EXPECT_EQ(point(m, n)[1], 0.0);
  }
}

TEST(ContactMeshes, HalfDiscArea) {
  // The polygon area converges to pi R^2 / 2 at second order (chords of the arc).
  double previous = HUGE_VAL;
  for (int level = 1; level <= 3; ++level) {
    const Mesh m = grout::half_disc_mesh(level, 1.0, 3.5, "disc");
    double area = 0.0;
    const auto& c = m.blocks[0].connectivity;
    for (std::size_t e = 0; e < c.size(); e += 4)
      for (int a = 0; a < 4; ++a) {
        const Vec p = point(m, c[e + a]), q = point(m, c[e + (a + 1) % 4]);
        area += 0.5 * (p[0] * q[1] - q[0] * p[1]);
      }
    const double error = M_PI / 2 - area;
    EXPECT_GT(error, 0.0);
    EXPECT_LT(error, 0.3 * previous);
    previous = error;
  }
}

// grout_mesh writes node set "X_nodes" beside side set "X" (ParaView's IOSS reader needs
// distinct names); node sets without a side set of their name keep it.
TEST(ContactMeshes, NodeSetsNamedApartFromSideSets) {
  Mesh m = grout::taylor_patch_2d({});
  const std::size_t n_sets = m.node_sets.size();
  grout::name_node_sets_apart(m);
  ASSERT_EQ(m.node_sets.size(), n_sets);
  std::set<std::string> side_names;
  for (const auto& s : m.side_sets) side_names.insert(s.name);
  for (const auto& ns : m.node_sets) {
    EXPECT_EQ(side_names.count(ns.name), 0u) << ns.name;
    const bool twin = ns.name.size() > 6 && ns.name.substr(ns.name.size() - 6) == "_nodes";
    EXPECT_TRUE(twin || ns.name == "block_origin" || ns.name == "die_anchor") << ns.name;
  }
  for (const auto& s : m.side_sets)
    EXPECT_NE(m.find_node_set(s.name + "_nodes"), nullptr) << s.name;
  // Idempotent: a second pass finds nothing to rename.
  const Mesh once = m;
  grout::name_node_sets_apart(m);
  for (std::size_t i = 0; i < n_sets; ++i) EXPECT_EQ(m.node_sets[i].name, once.node_sets[i].name);
  // A name that is taken already is an error, not a silent duplicate.
  Mesh clash = grout::rectangle_mesh(1, 1);
  clash.side_sets.push_back(clash.side_sets.front());
  clash.side_sets.back().name = clash.node_sets.front().name + "_nodes";
  EXPECT_THROW(grout::name_node_sets_apart(clash), std::invalid_argument);
}

}  // namespace
