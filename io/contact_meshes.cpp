// Two-body meshes for contact and mesh-tying cases (see contact_meshes.hpp).

#include "io/contact_meshes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include "io/mesh_generators.hpp"

namespace grout {

namespace {

using Point = std::array<double, 3>;
using SidePredicate = std::function<bool(const std::vector<Point>&)>;

Point node_point(const Mesh& mesh, GlobalIndex node) {
  Point p{0.0, 0.0, 0.0};
  for (int d = 0; d < mesh.dimension; ++d) p[d] = mesh.coordinates[mesh.dimension * node + d];
  return p;
}

int block_index(const Mesh& mesh, const std::string& name) {
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b)
    if (mesh.blocks[b].name == name) return int(b);
  throw std::logic_error("contact_meshes: no block " + name);
}

/// Sides of block `b` that belong to no other element of the block, with their nodes.
struct BoundarySide {
  GlobalIndex element;  ///< global 0-based element index
  int side;             ///< Exodus side number
  std::vector<GlobalIndex> nodes;
};

std::vector<BoundarySide> boundary_sides(const Mesh& mesh, int b) {
  const ElementBlock& block = mesh.blocks[b];
  const int npe = block.nodes_per_element;
  std::map<std::vector<GlobalIndex>, int> count;
  std::vector<BoundarySide> all;
  for (GlobalIndex e = 0; e < block.num_elements(); ++e)
    for (int side = 1; side <= topology_num_sides(block.topology); ++side) {
      int local[max_side_nodes];
      const int n = side_local_nodes(block.topology, side, local);
      BoundarySide s{block.first_element + e, side, {}};
      for (int m = 0; m < n; ++m) s.nodes.push_back(block.connectivity[e * npe + local[m]]);
      std::vector<GlobalIndex> key = s.nodes;
      std::sort(key.begin(), key.end());
      ++count[key];
      all.push_back(std::move(s));
    }
  std::vector<BoundarySide> result;
  for (auto& s : all) {
    std::vector<GlobalIndex> key = s.nodes;
    std::sort(key.begin(), key.end());
    if (count[key] == 1) result.push_back(std::move(s));
  }
  return result;
}

/// Add a side set and a node set `name`: the boundary sides of block `block` whose node
/// coordinates satisfy `keep`. Throws when nothing matches (a generator bug).
void add_side_set(Mesh& mesh, const std::string& block, const std::string& name,
                  const SidePredicate& keep) {
  SideSet ss;
  ss.name = name;
  ss.id = int(mesh.side_sets.size() + 1);
  std::vector<GlobalIndex> nodes;
  for (const auto& s : boundary_sides(mesh, block_index(mesh, block))) {
    std::vector<Point> x;
    for (GlobalIndex n : s.nodes) x.push_back(node_point(mesh, n));
    if (!keep(x)) continue;
    ss.elements.push_back(s.element);
    ss.sides.push_back(s.side);
    nodes.insert(nodes.end(), s.nodes.begin(), s.nodes.end());
  }
  if (ss.elements.empty()) throw std::logic_error("contact_meshes: empty side set " + name);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  mesh.side_sets.push_back(std::move(ss));
  mesh.node_sets.push_back({name, int(mesh.node_sets.size() + 1), std::move(nodes)});
}

/// Add a node set `name` holding the node of block `block` nearest to `target`.
void add_point_node_set(Mesh& mesh, const std::string& block, const std::string& name,
                        const Point& target) {
  const ElementBlock& b = mesh.blocks[block_index(mesh, block)];
  GlobalIndex best = -1;
  double best_d = HUGE_VAL;
  for (GlobalIndex n : b.connectivity) {
    const Point p = node_point(mesh, n);
    double d = 0.0;
    for (int k = 0; k < mesh.dimension; ++k) d += (p[k] - target[k]) * (p[k] - target[k]);
    if (d < best_d) best_d = d, best = n;
  }
  mesh.node_sets.push_back({name, int(mesh.node_sets.size() + 1), {best}});
}

void add_prefix(Mesh& mesh, const std::string& prefix) {
  for (auto& s : mesh.side_sets) s.name = prefix + s.name;
  for (auto& s : mesh.node_sets) s.name = prefix + s.name;
}

/// box_mesh names the stacking direction zmin/zmax; contact reads better as bottom/top.
void rename_z(Mesh& mesh) {
  auto rename = [](std::string& n) { n = n == "zmin" ? "bottom" : n == "zmax" ? "top" : n; };
  for (auto& s : mesh.side_sets) rename(s.name);
  for (auto& s : mesh.node_sets) rename(s.name);
}

void transform(Mesh& mesh, const std::function<Point(const Point&)>& f) {
  for (GlobalIndex n = 0; n < mesh.num_nodes(); ++n) {
    const Point p = f(node_point(mesh, n));
    for (int d = 0; d < mesh.dimension; ++d) mesh.coordinates[mesh.dimension * n + d] = p[d];
  }
}

/// Make every QUAD4 counter-clockwise (after a reflection, for instance).
void orient_quads(Mesh& mesh) {
  for (auto& block : mesh.blocks) {
    for (GlobalIndex e = 0; e < block.num_elements(); ++e) {
      GlobalIndex* c = &block.connectivity[4 * e];
      double area2 = 0.0;
      for (int a = 0; a < 4; ++a) {
        const Point p = node_point(mesh, c[a]), q = node_point(mesh, c[(a + 1) % 4]);
        area2 += p[0] * q[1] - q[0] * p[1];
      }
      if (area2 < 0.0) std::swap(c[1], c[3]);
    }
  }
}

bool near(double a, double b, double tol) {
  return std::abs(a - b) <= tol;
}

SidePredicate all_nodes(const std::function<bool(const Point&)>& f) {
  return [f](const std::vector<Point>& x) {
    for (const auto& p : x)
      if (!f(p)) return false;
    return true;
  };
}

Point centroid(const std::vector<Point>& x) {
  Point c{0, 0, 0};
  for (const auto& p : x)
    for (int d = 0; d < 3; ++d) c[d] += p[d] / double(x.size());
  return c;
}

Mesh checked(Mesh mesh, const char* generator) {
  if (!(min_corner_jacobian(mesh) > 0.0))
    throw std::invalid_argument(std::string(generator) +
                                ": an element has a non-positive Jacobian");
  return mesh;
}

}  // namespace

Mesh stacked_blocks_2d(const StackedBlocks& s) {
  const double y1 = s.height_lower + s.gap;
  Mesh lower = rectangle_mesh(s.nx_lower, s.ny_lower, 0.0, s.width, 0.0, s.height_lower,
                              s.simplex_lower, s.distortion, s.seed, "lower");
  Mesh upper = rectangle_mesh(s.nx_upper, s.ny_upper, 0.0, s.width, y1, y1 + s.height_upper,
                              s.simplex_upper, s.distortion, s.seed + 1, "upper");
  add_prefix(lower, "lower_");
  add_prefix(upper, "upper_");
  return append_mesh(lower, upper);
}

Mesh stacked_blocks_3d(const StackedBlocks& s) {
  const double z1 = s.height_lower + s.gap;
  Mesh lower = box_mesh(s.nx_lower, s.ny_lower, s.nz_lower,
                        {0.0, s.width, 0.0, s.width, 0.0, s.height_lower}, s.simplex_lower,
                        s.distortion, s.seed, "lower");
  Mesh upper = box_mesh(s.nx_upper, s.ny_upper, s.nz_upper,
                        {0.0, s.width, 0.0, s.width, z1, z1 + s.height_upper}, s.simplex_upper,
                        s.distortion, s.seed + 1, "upper");
  rename_z(lower);
  rename_z(upper);
  add_prefix(lower, "lower_");
  add_prefix(upper, "upper_");
  return append_mesh(lower, upper);
}

Mesh sloped_blocks_2d(const SlopedBlocks& s) {
  if (!(s.width > 0.0 && s.y_left > 0.0 && s.y_right > 0.0 && s.height > s.y_left &&
        s.height > s.y_right))
    throw std::invalid_argument("sloped_blocks_2d: need 0 < y_left, y_right < height, width > 0");
  // Both bodies evaluate the interface with the same expression: identical coordinates.
  auto interface_y = [&](double u) { return s.y_left + (s.y_right - s.y_left) * u; };
  Mesh lower = rectangle_mesh(s.nx_lower, s.ny_lower, 0, 1, 0, 1, s.triangles_lower, 0, 1, "lower");
  Mesh upper = rectangle_mesh(s.nx_upper, s.ny_upper, 0, 1, 0, 1, s.triangles_upper, 0, 1, "upper");
  transform(lower, [&](const Point& p) {
    return Point{s.width * p[0], p[1] == 1.0 ? interface_y(p[0]) : p[1] * interface_y(p[0]), 0};
  });
  transform(upper, [&](const Point& p) {
    const double yb = interface_y(p[0]);
    return Point{s.width * p[0],
                 p[1] == 0.0   ? yb
                 : p[1] == 1.0 ? s.height
                               : yb + p[1] * (s.height - yb),
                 0};
  });
  add_prefix(lower, "lower_");
  add_prefix(upper, "upper_");
  return checked(append_mesh(lower, upper), "sloped_blocks_2d");
}

Mesh taylor_patch_2d(const TaylorPatch& s) {
  if (s.nx_block % 4 != 0)
    throw std::invalid_argument("taylor_patch_2d: nx_block must be a multiple of 4");
  if (!(std::abs(s.die_stretch) < 1.0))
    throw std::invalid_argument("taylor_patch_2d: |die_stretch| must be < 1");
  Mesh block = rectangle_mesh(s.nx_block, s.ny_block, 0, 8, 0, 5, s.simplex_block, 0, 1, "block");
  Mesh die = rectangle_mesh(s.nx_die, s.ny_die, 4, 6, 5, 7, s.simplex_die, 0, 1, "die");
  transform(die, [&](const Point& p) {
    const double u = (p[0] - 4.0) / 2.0;
    return Point{4.0 + 2.0 * (u + s.die_stretch * u * (1.0 - u)), p[1], 0};
  });
  add_prefix(block, "block_");
  add_prefix(die, "die_");
  Mesh m = append_mesh(block, die);
  const double tol = 1e-12;
  add_side_set(m, "block", "block_top_free", [&](const std::vector<Point>& x) {
    const Point c = centroid(x);
    return all_nodes([&](const Point& p) { return near(p[1], 5.0, tol); })(x) &&
           (c[0] < 4.0 || c[0] > 6.0);
  });
  add_point_node_set(m, "block", "block_origin", {0, 0, 0});
  add_point_node_set(m, "die", "die_anchor", {4, 7, 0});
  return checked(std::move(m), "taylor_patch_2d");
}

Mesh taylor_patch_3d(const TaylorPatch& s) {
  if (s.nx_block % 4 != 0 || s.ny_block % 4 != 0)
    throw std::invalid_argument("taylor_patch_3d: nx_block and ny_block must be multiples of 4");
  Mesh block = box_mesh(s.nx_block, s.ny_block, s.nz_block, {0, 8, 0, 8, 0, 4}, s.simplex_block, 0,
                        1, "block");
  Mesh die = box_mesh(s.nx_die, s.ny_die, s.nz_die, {4, 6, 4, 6, 4, 6}, s.simplex_die, 0, 1, "die");
  rename_z(block);
  rename_z(die);
  add_prefix(block, "block_");
  add_prefix(die, "die_");
  Mesh m = append_mesh(block, die);
  const double tol = 1e-12;
  add_side_set(m, "block", "block_top_free", [&](const std::vector<Point>& x) {
    const Point c = centroid(x);
    return all_nodes([&](const Point& p) { return near(p[2], 4.0, tol); })(x) &&
           (c[0] < 4.0 || c[0] > 6.0 || c[1] < 4.0 || c[1] > 6.0);
  });
  add_point_node_set(m, "block", "block_origin", {0, 0, 0});
  add_point_node_set(m, "block", "block_x_end", {8, 0, 0});
  add_point_node_set(m, "die", "die_anchor", {4, 4, 6});
  add_point_node_set(m, "die", "die_x_end", {6, 4, 6});
  return checked(std::move(m), "taylor_patch_3d");
}

Mesh half_disc_mesh(int level, double radius, double beta, const std::string& block_name) {
  if (level < 1 || level > 6) throw std::invalid_argument("half_disc_mesh: level must be 1..6");
  if (!(radius > 0.0 && beta > 0.0))
    throw std::invalid_argument("half_disc_mesh: need radius > 0 and beta > 0");
  const int m = 1 << (level - 1);
  const int n_half = 12 * m, n_side = 4 * m, n_radial = 6 * m;
  const double R = radius, aR = 0.5 * radius, quarter = M_PI / 4.0;
  const double gamma_contact = 3.0, gamma_side = 0.5;

  auto g = [&](double s) { return std::sinh(beta * s) / std::sinh(beta); };
  auto arc = [&](double phi, bool on_diameter) {
    return Point{R * std::sin(phi), on_diameter ? 0.0 : -R * std::cos(phi), 0.0};
  };
  // Point at t in [0,1] on the segment from `a` (arc) to `b` (inner), graded towards `a`.
  auto graded = [&](const Point& a, const Point& b, double t, double gamma, bool at_b) {
    if (at_b) return b;
    const double d = std::expm1(gamma * t) / std::expm1(gamma);
    return Point{a[0] + d * (b[0] - a[0]), a[1] + d * (b[1] - a[1]), 0.0};
  };

  std::map<std::pair<double, double>, GlobalIndex> index;
  std::vector<double> xy;
  std::vector<GlobalIndex> conn;
  auto node = [&](const Point& p) {
    const auto key = std::make_pair(p[0], p[1]);
    const auto it = index.find(key);
    if (it != index.end()) return it->second;
    const GlobalIndex id = GlobalIndex(xy.size() / 2);
    xy.push_back(p[0]);
    xy.push_back(p[1]);
    index.emplace(key, id);
    return id;
  };
  auto patch = [&](int ni, int nj, const std::function<Point(int, int)>& at) {
    std::vector<GlobalIndex> ids;
    for (int j = 0; j <= nj; ++j)
      for (int i = 0; i <= ni; ++i) ids.push_back(node(at(i, j)));
    for (int j = 0; j < nj; ++j)
      for (int i = 0; i < ni; ++i) {
        const int c = j * (ni + 1) + i;
        conn.insert(conn.end(), {ids[c], ids[c + 1], ids[c + ni + 2], ids[c + ni + 1]});
      }
  };

  // Bottom patch: i along the arc (s = -1 .. 1), j from the arc (t = 0) to the rectangle.
  patch(2 * n_half, n_radial, [&](int i, int j) {
    const double s = double(i - n_half) / n_half, w = 1.0 - s * s;
    const double gamma = gamma_side + (gamma_contact - gamma_side) * w * w;
    const Point a = arc(quarter * g(s), false), b{aR * g(s), -aR, 0.0};
    return graded(a, b, double(j) / n_radial, gamma, j == n_radial);
  });
  // Side patches: i from the diagonal (u = 0) to the diameter (u = 1).
  for (const double side : {1.0, -1.0})
    patch(n_side, n_radial, [&](int i, int j) {
      const double u = double(i) / n_side;
      const Point a = arc(side * (quarter + quarter * u), i == n_side);
      const Point b{side * aR, -aR + aR * u, 0.0};
      return graded(a, b, double(j) / n_radial, gamma_side, j == n_radial);
    });
  // Inner rectangle.
  patch(2 * n_half, n_side, [&](int i, int j) {
    const double s = double(i - n_half) / n_half;
    return Point{aR * g(s), -aR + aR * (double(j) / n_side), 0.0};
  });

  Mesh mesh;
  mesh.dimension = 2;
  mesh.coordinates = std::move(xy);
  ElementBlock block;
  block.name = block_name;
  block.id = 1;
  block.topology = Topology::quad4;
  block.nodes_per_element = 4;
  block.connectivity = std::move(conn);
  mesh.blocks.push_back(std::move(block));
  orient_quads(mesh);
  return checked(std::move(mesh), "half_disc_mesh");
}

namespace {

/// Arc sides with |x| <= width of the disc (centre (0, cy), radius R) in block `block`.
SidePredicate on_arc(double cy, double R, double width) {
  const double tol = 1e-9 * R;
  return all_nodes([=](const Point& p) {
    return near(std::hypot(p[0], p[1] - cy), R, tol) && std::abs(p[0]) <= width + tol;
  });
}

SidePredicate on_line_y(double y, double tol) {
  return all_nodes([=](const Point& p) { return near(p[1], y, tol); });
}

SidePredicate on_line_x(double x, double tol) {
  return all_nodes([=](const Point& p) { return near(p[0], x, tol); });
}

/// The elements of a one-block 2D mesh without sets whose centroid lies at x > 0, their nodes
/// renumbered in the order of first use (the half disc's mid line x = 0 is a mesh line with
/// exact zeros: sinh(0) = 0).
Mesh right_half(const Mesh& mesh) {
  const ElementBlock& in = mesh.blocks.at(0);
  std::vector<GlobalIndex> renumber(mesh.num_nodes(), -1);
  Mesh out;
  out.dimension = 2;
  ElementBlock block;
  block.name = in.name;
  block.id = 1;
  block.topology = in.topology;
  block.nodes_per_element = in.nodes_per_element;
  const int npe = in.nodes_per_element;
  for (GlobalIndex e = 0; e < in.num_elements(); ++e) {
    double cx = 0.0;
    for (int a = 0; a < npe; ++a) cx += node_point(mesh, in.connectivity[e * npe + a])[0];
    if (!(cx > 0.0)) continue;
    for (int a = 0; a < npe; ++a) {
      const GlobalIndex n = in.connectivity[e * npe + a];
      if (renumber[n] < 0) {
        renumber[n] = GlobalIndex(out.coordinates.size() / 2);
        out.coordinates.push_back(mesh.coordinates[2 * n]);
        out.coordinates.push_back(mesh.coordinates[2 * n + 1]);
      }
      block.connectivity.push_back(renumber[n]);
    }
  }
  out.blocks.push_back(std::move(block));
  return out;
}

}  // namespace

Mesh quarter_disc_mesh(int level, double radius) {
  const double R = radius, tol = 1e-9 * R;
  Mesh m = right_half(half_disc_mesh(level, R, 3.5, "sphere"));
  add_side_set(m, "sphere", "sphere_surface", on_arc(0.0, R, R));
  add_side_set(m, "sphere", "sphere_equator", on_line_y(0.0, tol));
  add_side_set(m, "sphere", "sphere_axis", on_line_x(0.0, tol));
  return checked(std::move(m), "quarter_disc_mesh");
}

namespace {

// The plane of the *_on_plane meshes: its sets prefixed "plane_", and a node set "plane" of all
// its nodes (to hold it, or to make it rigid).
void name_rigid_plane(Mesh& plane) {
  add_prefix(plane, "plane_");
  NodeSet all{"plane", 0, {}};
  for (GlobalIndex n = 0; n < plane.num_nodes(); ++n) all.nodes.push_back(n);
  plane.node_sets.push_back(std::move(all));
}

}  // namespace

Mesh sphere_on_plane_axisymmetric_mesh(int level, double radius, double contact_width) {
  if (!(contact_width > 0.0 && contact_width < radius))
    throw std::invalid_argument("sphere_on_plane_axisymmetric_mesh: need 0 < contact_width < R");
  const double R = radius, tol = 1e-9 * R;
  Mesh sphere = right_half(half_disc_mesh(level, R, 3.5, "sphere"));
  transform(sphere, [&](const Point& p) { return Point{p[0], p[1] + R, 0.0}; });
  // The plane is graded towards the contact point (x = sinh(5 t)/sinh(5), t uniform, in both
  // directions: 0.067 of the uniform size there), so that it can be the slave side.
  const int m = 1 << (level - 1);
  Mesh plane = rectangle_mesh(8 * m, 4 * m, 0.0, 1.0, 0.0, 1.0, false, 0, 1, "plane");
  const auto grade = [](double t) { return std::sinh(5.0 * t) / std::sinh(5.0); };
  transform(plane, [&](const Point& p) {
    return Point{2 * R * grade(p[0]), -2 * R * grade(1.0 - p[1]), 0.0};
  });
  name_rigid_plane(plane);
  Mesh mesh = append_mesh(sphere, plane);
  add_side_set(mesh, "sphere", "sphere_contact", on_arc(R, R, contact_width));
  add_side_set(mesh, "sphere", "sphere_top", on_line_y(R, tol));
  add_side_set(mesh, "sphere", "sphere_axis", on_line_x(0.0, tol));
  return checked(std::move(mesh), "sphere_on_plane_axisymmetric_mesh");
}

Mesh hertz_cylinders_mesh(int level, double radius, double gap, double contact_width) {
  if (!(gap >= 0.0 && contact_width > 0.0 && contact_width < radius))
    throw std::invalid_argument("hertz_cylinders_mesh: need gap >= 0, 0 < contact_width < R");
  const double R = radius, cy = R + gap, tol = 1e-9 * R;
  Mesh upper = half_disc_mesh(level, R, 3.5, "upper");
  transform(upper, [&](const Point& p) { return Point{p[0], p[1] + cy, 0.0}; });
  Mesh lower = half_disc_mesh(level, R, 3.0, "lower");
  transform(lower, [&](const Point& p) { return Point{p[0], -p[1] - R, 0.0}; });
  orient_quads(lower);
  Mesh m = append_mesh(upper, lower);
  add_side_set(m, "upper", "upper_contact", on_arc(cy, R, contact_width));
  add_side_set(m, "lower", "lower_contact", on_arc(-R, R, contact_width));
  add_side_set(m, "upper", "upper_top", on_line_y(cy, tol));
  add_side_set(m, "lower", "lower_bottom", on_line_y(-R, tol));
  return checked(std::move(m), "hertz_cylinders_mesh");
}

Mesh cylinder_on_plane_mesh(int level, double radius, double contact_width) {
  if (!(contact_width > 0.0 && contact_width < radius))
    throw std::invalid_argument("cylinder_on_plane_mesh: need 0 < contact_width < R");
  const double R = radius, tol = 1e-9 * R;
  Mesh cylinder = half_disc_mesh(level, R, 3.5, "cylinder");
  transform(cylinder, [&](const Point& p) { return Point{p[0], p[1] + R, 0.0}; });
  const int m = 1 << (level - 1);
  Mesh plane = rectangle_mesh(8 * m, 4 * m, -2 * R, 2 * R, -2 * R, 0.0, false, 0, 1, "plane");
  name_rigid_plane(plane);
  Mesh mesh = append_mesh(cylinder, plane);
  add_side_set(mesh, "cylinder", "cylinder_contact", on_arc(R, R, contact_width));
  add_side_set(mesh, "cylinder", "cylinder_top", on_line_y(R, tol));
  return checked(std::move(mesh), "cylinder_on_plane_mesh");
}

}  // namespace grout
