// Structured mesh generators (see mesh_generators.hpp).
//
// All of them go through one builder on a logical (i, j, k) lattice: the lattice index of a
// node says which boundary lines/planes it lies on, which gives the side sets, the node sets
// and which coordinates a distortion may move, uniformly for QUAD4/TRI3/HEX8/TET4.

#include "io/mesh_generators.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace grout {

namespace {

using Point = std::array<double, 3>;
using LatticeIndex = std::array<int, 3>;

/// A boundary of the lattice: all nodes with index[direction] == (high ? n : 0).
struct LatticeFace {
  std::string name;
  int direction;
  bool high;
};

struct StructuredMesh {
  Mesh mesh;
  std::vector<LatticeIndex> index;  ///< lattice index of every node
  std::array<int, 3> n{};           ///< cells per direction
};

/// Local node of the corner with bits (a, b, c) in the Exodus QUAD4/HEX8 numbering.
int corner(int a, int b, int c = 0) {
  return 4 * c + (b == 0 ? a : 3 - a);
}

double triple(const Point& a, const Point& b, const Point& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}

Point node_point(const Mesh& mesh, GlobalIndex node) {
  Point p{0.0, 0.0, 0.0};
  for (int k = 0; k < mesh.dimension; ++k) p[k] = mesh.coordinates[mesh.dimension * node + k];
  return p;
}

/// a + u (b - a), exact at both ends so boundary nodes lie exactly on the boundary planes.
double lerp(double a, double b, double u) {
  return u == 1.0 ? b : a + u * (b - a);
}

Point minus(const Point& a, const Point& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

/// \brief Lay out nodes by `map` (lattice parameters in [0,1]^dim -> point), cut each cell into
/// elements of `topology`, and collect the side sets and node sets of `faces`.
StructuredMesh build_structured(int dimension, std::array<int, 3> n, Topology topology,
                                const std::function<Point(double, double, double)>& map,
                                const std::vector<LatticeFace>& faces,
                                const std::string& block_name) {
  for (int d = 0; d < dimension; ++d)
    if (n[d] < 1)
      throw std::invalid_argument("mesh generator: need at least one cell per direction");
  if (dimension == 2) n[2] = 0;
  StructuredMesh s;
  s.n = n;
  Mesh& mesh = s.mesh;
  mesh.dimension = dimension;
  auto node_id = [&](int i, int j, int k) {
    return (GlobalIndex(k) * (n[1] + 1) + j) * (n[0] + 1) + i;
  };
  for (int k = 0; k <= n[2]; ++k)
    for (int j = 0; j <= n[1]; ++j)
      for (int i = 0; i <= n[0]; ++i) {
        const Point p =
            map(double(i) / n[0], double(j) / n[1], dimension == 3 ? double(k) / n[2] : 0.0);
        for (int d = 0; d < dimension; ++d) mesh.coordinates.push_back(p[d]);
        s.index.push_back({i, j, k});
      }

  ElementBlock block;
  block.name = block_name;
  block.id = 1;
  block.topology = topology;
  block.nodes_per_element = topology_num_nodes(topology);
  auto add = [&](std::initializer_list<GlobalIndex> nodes) {
    block.connectivity.insert(block.connectivity.end(), nodes);
  };
  for (int k = 0; k < std::max(n[2], 1); ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        // Cell corners in QUAD4/HEX8 local order.
        GlobalIndex c[8] = {};
        for (int cc = 0; cc < (dimension == 3 ? 2 : 1); ++cc)
          for (int b = 0; b < 2; ++b)
            for (int a = 0; a < 2; ++a) c[corner(a, b, cc)] = node_id(i + a, j + b, k + cc);
        if (topology == Topology::quad4) add({c[0], c[1], c[2], c[3]});
        if (topology == Topology::tri3) {
          add({c[0], c[1], c[2]});
          add({c[0], c[2], c[3]});
        }
        if (topology == Topology::hex8) add({c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]});
        if (topology == Topology::tet4) {
          // Kuhn: one tet per path 000 -> e_p -> e_p + e_q -> 111 along the cell's axes.
          constexpr int paths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                       {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
          for (const auto& path : paths) {
            int bits[3] = {0, 0, 0};
            GlobalIndex tet[4];
            tet[0] = c[corner(0, 0, 0)];
            for (int step = 0; step < 3; ++step) {
              bits[path[step]] = 1;
              tet[step + 1] = c[corner(bits[0], bits[1], bits[2])];
            }
            const Point p0 = node_point(mesh, tet[0]);
            if (triple(minus(node_point(mesh, tet[1]), p0), minus(node_point(mesh, tet[2]), p0),
                       minus(node_point(mesh, tet[3]), p0)) < 0.0)
              std::swap(tet[2], tet[3]);
            add({tet[0], tet[1], tet[2], tet[3]});
          }
        }
      }

  // Side sets: a side lies on a lattice face when all of its nodes do.
  const int npe = block.nodes_per_element;
  const GlobalIndex num_elements = block.num_elements();
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const LatticeFace& face = faces[f];
    const int target = face.high ? n[face.direction] : 0;
    SideSet ss;
    ss.name = face.name;
    ss.id = int(f + 1);
    for (GlobalIndex e = 0; e < num_elements; ++e)
      for (int side = 1; side <= topology_num_sides(topology); ++side) {
        int local[max_side_nodes];
        const int count = side_local_nodes(topology, side, local);
        bool on_face = true;
        for (int m = 0; m < count && on_face; ++m)
          on_face = s.index[block.connectivity[e * npe + local[m]]][face.direction] == target;
        if (on_face) {
          ss.elements.push_back(e);
          ss.sides.push_back(side);
        }
      }
    NodeSet ns;
    ns.name = face.name;
    ns.id = int(f + 1);
    for (GlobalIndex node = 0; node < GlobalIndex(s.index.size()); ++node)
      if (s.index[node][face.direction] == target) ns.nodes.push_back(node);
    mesh.side_sets.push_back(std::move(ss));
    mesh.node_sets.push_back(std::move(ns));
  }
  mesh.blocks.push_back(std::move(block));
  return s;
}

/// Uniform double in [0, 1) from splitmix64: the same sequence on every platform.
class Random {
 public:
  explicit Random(unsigned long long seed) : state_(seed) {}
  double uniform() {
    unsigned long long z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return double(z >> 11) * 0x1.0p-53;
  }

 private:
  unsigned long long state_;
};

/// Move every coordinate of a node that no boundary plane fixes (see rectangle_mesh).
void distort(StructuredMesh& s, const std::array<double, 3>& h, double distortion,
             unsigned long long seed) {
  if (!(distortion >= 0.0 && distortion < 0.4))
    throw std::invalid_argument("mesh generator: distortion " + std::to_string(distortion) +
                                " outside [0, 0.4)");
  if (distortion == 0.0) return;
  Random random(seed);
  const int dim = s.mesh.dimension;
  for (std::size_t node = 0; node < s.index.size(); ++node)
    for (int d = 0; d < dim; ++d) {
      const double shift = (2.0 * random.uniform() - 1.0) * distortion * h[d];
      if (s.index[node][d] > 0 && s.index[node][d] < s.n[d])
        s.mesh.coordinates[dim * node + d] += shift;
    }
}

Mesh checked(Mesh mesh, const char* generator) {
  if (!(min_corner_jacobian(mesh) > 0.0))
    throw std::invalid_argument(std::string(generator) +
                                ": an element has a non-positive Jacobian");
  return mesh;
}

void add_prefix(Mesh& mesh, const std::string& prefix) {
  for (auto& s : mesh.side_sets) s.name = prefix + s.name;
  for (auto& s : mesh.node_sets) s.name = prefix + s.name;
}

}  // namespace

Mesh rectangle_mesh(int nx, int ny, double x0, double x1, double y0, double y1, bool triangles,
                    double distortion, unsigned long long seed, const std::string& block_name) {
  if (!(x1 > x0 && y1 > y0)) throw std::invalid_argument("rectangle_mesh: empty rectangle");
  const std::vector<LatticeFace> faces = {
      {"bottom", 1, false}, {"right", 0, true}, {"top", 1, true}, {"left", 0, false}};
  auto map = [&](double u, double v, double) {
    return Point{lerp(x0, x1, u), lerp(y0, y1, v), 0.0};
  };
  StructuredMesh s = build_structured(2, {nx, ny, 0}, triangles ? Topology::tri3 : Topology::quad4,
                                      map, faces, block_name);
  distort(s, {(x1 - x0) / nx, (y1 - y0) / ny, 0.0}, distortion, seed);
  return checked(std::move(s.mesh), "rectangle_mesh");
}

Mesh box_mesh(int nx, int ny, int nz, const BoxBounds& b, bool tetrahedra, double distortion,
              unsigned long long seed, const std::string& block_name) {
  if (!(b.x1 > b.x0 && b.y1 > b.y0 && b.z1 > b.z0))
    throw std::invalid_argument("box_mesh: empty box");
  const std::vector<LatticeFace> faces = {{"xmin", 0, false}, {"xmax", 0, true},
                                          {"ymin", 1, false}, {"ymax", 1, true},
                                          {"zmin", 2, false}, {"zmax", 2, true}};
  auto map = [&](double u, double v, double w) {
    return Point{lerp(b.x0, b.x1, u), lerp(b.y0, b.y1, v), lerp(b.z0, b.z1, w)};
  };
  StructuredMesh s = build_structured(3, {nx, ny, nz}, tetrahedra ? Topology::tet4 : Topology::hex8,
                                      map, faces, block_name);
  distort(s, {(b.x1 - b.x0) / nx, (b.y1 - b.y0) / ny, (b.z1 - b.z0) / nz}, distortion, seed);
  return checked(std::move(s.mesh), "box_mesh");
}

Mesh quarter_annulus_mesh(int n_radial, int n_circ, double r_inner, double r_outer,
                          const std::string& block_name) {
  if (!(r_inner > 0.0 && r_outer > r_inner))
    throw std::invalid_argument("quarter_annulus_mesh: need 0 < r_inner < r_outer");
  const std::vector<LatticeFace> faces = {
      {"inner", 0, false}, {"outer", 0, true}, {"x_symmetry", 1, false}, {"y_symmetry", 1, true}};
  // u runs outwards, v counter-clockwise from the x axis: (e_r, e_theta) is right-handed.
  auto map = [&](double u, double v, double) {
    const double r = lerp(r_inner, r_outer, u);
    const double theta = v * M_PI / 2.0;
    // Exact zeros on the symmetry edges (cos(pi/2) is 6e-17, not 0).
    const double x = v == 1.0 ? 0.0 : r * std::cos(theta);
    const double y = v == 0.0 ? 0.0 : r * std::sin(theta);
    return Point{x, y, 0.0};
  };
  StructuredMesh s =
      build_structured(2, {n_radial, n_circ, 0}, Topology::quad4, map, faces, block_name);
  return checked(std::move(s.mesh), "quarter_annulus_mesh");
}

Mesh append_mesh(const Mesh& a, const Mesh& b) {
  if (a.dimension != b.dimension) throw std::invalid_argument("append_mesh: dimensions differ");
  Mesh m = a;
  const GlobalIndex node_offset = a.num_nodes(), element_offset = a.num_elements();
  m.coordinates.insert(m.coordinates.end(), b.coordinates.begin(), b.coordinates.end());
  for (ElementBlock block : b.blocks) {
    for (auto& node : block.connectivity) node += node_offset;
    block.first_element += element_offset;
    m.blocks.push_back(std::move(block));
  }
  for (SideSet set : b.side_sets) {
    for (auto& e : set.elements) e += element_offset;
    m.side_sets.push_back(std::move(set));
  }
  for (NodeSet set : b.node_sets) {
    for (auto& node : set.nodes) node += node_offset;
    m.node_sets.push_back(std::move(set));
  }
  for (std::size_t i = 0; i < m.blocks.size(); ++i) m.blocks[i].id = int(i + 1);
  for (std::size_t i = 0; i < m.side_sets.size(); ++i) m.side_sets[i].id = int(i + 1);
  for (std::size_t i = 0; i < m.node_sets.size(); ++i) m.node_sets[i].id = int(i + 1);
  return m;
}

Mesh two_block_mesh_2d(int nx_lower, int ny_lower, int nx_upper, int ny_upper, bool triangles,
                       double gap) {
  Mesh lower = rectangle_mesh(nx_lower, ny_lower, 0.0, 1.0, 0.0, 1.0, triangles, 0.0, 1, "lower");
  Mesh upper = rectangle_mesh(nx_upper, ny_upper, 0.0, 1.0, 1.0 + gap, 2.0 + gap, triangles, 0.0, 1,
                              "upper");
  add_prefix(lower, "lower_");
  add_prefix(upper, "upper_");
  return append_mesh(lower, upper);
}

Mesh two_block_mesh_3d(int nx_lower, int ny_lower, int nz_lower, int nx_upper, int ny_upper,
                       int nz_upper, bool tetrahedra, double gap) {
  Mesh lower =
      box_mesh(nx_lower, ny_lower, nz_lower, {0, 1, 0, 1, 0, 1}, tetrahedra, 0.0, 1, "lower");
  Mesh upper = box_mesh(nx_upper, ny_upper, nz_upper, {0, 1, 0, 1, 1 + gap, 2 + gap}, tetrahedra,
                        0.0, 1, "upper");
  for (Mesh* m : {&lower, &upper}) {
    // Contact reads better with "top"/"bottom" for the stacking direction.
    for (auto& s : m->side_sets)
      s.name = s.name == "zmin" ? "bottom" : s.name == "zmax" ? "top" : s.name;
    for (auto& s : m->node_sets)
      s.name = s.name == "zmin" ? "bottom" : s.name == "zmax" ? "top" : s.name;
  }
  add_prefix(lower, "lower_");
  add_prefix(upper, "upper_");
  return append_mesh(lower, upper);
}

double min_corner_jacobian(const Mesh& mesh) {
  double result = HUGE_VAL;
  for (const auto& block : mesh.blocks) {
    const int npe = block.nodes_per_element;
    for (GlobalIndex e = 0; e < block.num_elements(); ++e) {
      Point x[max_element_nodes];
      for (int a = 0; a < npe; ++a) x[a] = node_point(mesh, block.connectivity[e * npe + a]);
      auto det2 = [](const Point& u, const Point& v) { return u[0] * v[1] - u[1] * v[0]; };
      switch (block.topology) {
        case Topology::tri3:
          result = std::min(result, det2(minus(x[1], x[0]), minus(x[2], x[0])));
          break;
        case Topology::tet4:
          result =
              std::min(result, triple(minus(x[1], x[0]), minus(x[2], x[0]), minus(x[3], x[0])));
          break;
        case Topology::quad4:
          // At corner (a, b): d/dxi along the cell row b, d/deta along the column a.
          for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 2; ++b)
              result = std::min(result, det2(minus(x[corner(1, b)], x[corner(0, b)]),
                                             minus(x[corner(a, 1)], x[corner(a, 0)])));
          break;
        case Topology::hex8:
          for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 2; ++b)
              for (int c = 0; c < 2; ++c)
                result = std::min(result, triple(minus(x[corner(1, b, c)], x[corner(0, b, c)]),
                                                 minus(x[corner(a, 1, c)], x[corner(a, 0, c)]),
                                                 minus(x[corner(a, b, 1)], x[corner(a, b, 0)])));
          break;
        case Topology::line2:
          break;
      }
    }
  }
  return result;
}

void name_node_sets_apart(Mesh& mesh) {
  for (auto& node_set : mesh.node_sets) {
    if (!mesh.find_side_set(node_set.name)) continue;
    const std::string name = node_set.name + "_nodes";
    if (mesh.find_side_set(name) || mesh.find_node_set(name))
      throw std::invalid_argument("mesh generator: cannot rename node set '" + node_set.name +
                                  "': '" + name + "' exists already");
    node_set.name = name;
  }
}

}  // namespace grout
