// Two-body meshes for the frictional verification cases (see friction_meshes.hpp).

#include "io/friction_meshes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/contact_meshes.hpp"
#include "io/mesh_generators.hpp"

namespace grout {

namespace {

void add_prefix(Mesh& mesh, const std::string& prefix) {
  for (auto& s : mesh.side_sets) s.name = prefix + s.name;
  for (auto& s : mesh.node_sets) s.name = prefix + s.name;
}

/// A side set (and node set of the same name) with the sides of side set `from` whose
/// nodes all satisfy x in [x0, x1] (tolerance tol).
void add_x_subset(Mesh& mesh, const std::string& from, const std::string& name, double x0,
                  double x1, double tol) {
  const SideSet* src = nullptr;
  for (const auto& s : mesh.side_sets)
    if (s.name == from) src = &s;
  if (!src) throw std::logic_error("friction_meshes: no side set " + from);
  SideSet ss;
  ss.name = name;
  ss.id = int(mesh.side_sets.size() + 1);
  std::vector<GlobalIndex> nodes;
  for (std::size_t k = 0; k < src->elements.size(); ++k) {
    const GlobalIndex e = src->elements[k];
    const int side = src->sides[k];
    for (const auto& block : mesh.blocks) {
      if (e < block.first_element || e >= block.first_element + block.num_elements()) continue;
      int local[max_side_nodes];
      const int n = side_local_nodes(block.topology, side, local);
      std::vector<GlobalIndex> side_nodes;
      bool inside = true;
      for (int m = 0; m < n; ++m) {
        const GlobalIndex node =
            block.connectivity[(e - block.first_element) * block.nodes_per_element + local[m]];
        const double x = mesh.coordinates[mesh.dimension * node];
        inside = inside && x >= x0 - tol && x <= x1 + tol;
        side_nodes.push_back(node);
      }
      if (inside) {
        ss.elements.push_back(e);
        ss.sides.push_back(side);
        nodes.insert(nodes.end(), side_nodes.begin(), side_nodes.end());
      }
    }
  }
  if (ss.elements.empty()) throw std::logic_error("friction_meshes: empty side set " + name);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  const SideSet copy = ss;  // src may dangle after push_back
  mesh.side_sets.push_back(copy);
  mesh.node_sets.push_back({name, int(mesh.node_sets.size() + 1), std::move(nodes)});
}

/// Add a node set `name` holding the node of block `block` nearest to (x, y).
void add_nearest_node_set(Mesh& mesh, const std::string& block, const std::string& name, double x,
                          double y) {
  const ElementBlock* b = nullptr;
  for (const auto& blk : mesh.blocks)
    if (blk.name == block) b = &blk;
  if (!b) throw std::logic_error("friction_meshes: no block " + block);
  GlobalIndex best = -1;
  double best_d = HUGE_VAL;
  for (GlobalIndex n : b->connectivity) {
    const double dx = mesh.coordinates[2 * n] - x, dy = mesh.coordinates[2 * n + 1] - y;
    if (dx * dx + dy * dy < best_d) best_d = dx * dx + dy * dy, best = n;
  }
  mesh.node_sets.push_back({name, int(mesh.node_sets.size() + 1), {best}});
}

}  // namespace

Mesh hertz_cylinders_pinned(int level, double radius, double gap, double contact_width) {
  Mesh m = hertz_cylinders_mesh(level, radius, gap, contact_width);
  add_nearest_node_set(m, "upper", "upper_top_centre", 0.0, radius + gap);
  add_nearest_node_set(m, "upper", "upper_top_end", radius, radius + gap);
  add_nearest_node_set(m, "lower", "lower_bottom_centre", 0.0, -radius);
  add_nearest_node_set(m, "lower", "lower_bottom_end", radius, -radius);
  return m;
}

Mesh dong_blocks_2d(const DongBlocks& s) {
  if (!(s.width_lower > 0.0 && s.height_lower > 0.0 && s.width_upper > 0.0 &&
        s.height_upper > 0.0 && s.gap >= 0.0))
    throw std::invalid_argument("dong_blocks: widths and heights must be > 0, gap >= 0");
  if (!(s.x_upper >= 0.0 && s.x_upper + s.width_upper <= s.width_lower * (1.0 + 1e-12)))
    throw std::invalid_argument(
        "dong_blocks: block I must lie over block II (0 <= x_upper, "
        "x_upper + width_upper <= width_lower)");
  const double y1 = s.height_lower + s.gap;
  Mesh lower = rectangle_mesh(s.nx_lower, s.ny_lower, 0.0, s.width_lower, 0.0, s.height_lower,
                              s.triangles_lower, 0.0, 1, "lower");
  Mesh upper = rectangle_mesh(s.nx_upper, s.ny_upper, s.x_upper, s.x_upper + s.width_upper, y1,
                              y1 + s.height_upper, s.triangles_upper, 0.0, 1, "upper");
  add_prefix(lower, "lower_");
  add_prefix(upper, "upper_");
  Mesh m = append_mesh(lower, upper);
  add_x_subset(m, "lower_top", "lower_top_contact", s.x_upper, s.x_upper + s.width_upper,
               1e-12 * s.width_lower);
  if (!(min_corner_jacobian(m) > 0.0))
    throw std::invalid_argument("dong_blocks: an element has a non-positive Jacobian");
  return m;
}

}  // namespace grout
