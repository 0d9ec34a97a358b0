// Exodus reader/writer round trips and the geometric properties of the mesh generators.

#include <exodusII.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "io/errors.hpp"
#include "io/exodus.hpp"
#include "io/mesh_generators.hpp"

namespace {

using grout::GlobalIndex;
using grout::Mesh;
using Vec = std::array<double, 3>;

std::string temp_path(const std::string& name) {
  return std::string(GROUT_BINARY_DIR) + "/test_io_exodus_" + name + ".exo";
}

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

void expect_same_mesh(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.dimension, b.dimension);
  EXPECT_EQ(a.coordinates, b.coordinates);  // doubles are stored as doubles: exact
  ASSERT_EQ(a.blocks.size(), b.blocks.size());
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    EXPECT_EQ(a.blocks[i].name, b.blocks[i].name);
    EXPECT_EQ(a.blocks[i].id, b.blocks[i].id);
    EXPECT_EQ(a.blocks[i].topology, b.blocks[i].topology);
    EXPECT_EQ(a.blocks[i].nodes_per_element, b.blocks[i].nodes_per_element);
    EXPECT_EQ(a.blocks[i].first_element, b.blocks[i].first_element);
    EXPECT_EQ(a.blocks[i].connectivity, b.blocks[i].connectivity);
  }
  ASSERT_EQ(a.side_sets.size(), b.side_sets.size());
  for (std::size_t i = 0; i < a.side_sets.size(); ++i) {
    EXPECT_EQ(a.side_sets[i].name, b.side_sets[i].name);
    EXPECT_EQ(a.side_sets[i].id, b.side_sets[i].id);
    EXPECT_EQ(a.side_sets[i].elements, b.side_sets[i].elements);
    EXPECT_EQ(a.side_sets[i].sides, b.side_sets[i].sides);
  }
  ASSERT_EQ(a.node_sets.size(), b.node_sets.size());
  for (std::size_t i = 0; i < a.node_sets.size(); ++i) {
    EXPECT_EQ(a.node_sets[i].name, b.node_sets[i].name);
    EXPECT_EQ(a.node_sets[i].id, b.node_sets[i].id);
    EXPECT_EQ(a.node_sets[i].nodes, b.node_sets[i].nodes);
  }
}

/// The generated meshes every property test runs on, by name.
std::map<std::string, Mesh> generated_meshes() {
  std::map<std::string, Mesh> m;
  m["quad"] = grout::rectangle_mesh(5, 3, 0.0, 2.0, -1.0, 0.5, false, 0.3, 7);
  m["tri"] = grout::rectangle_mesh(4, 4, 0.0, 2.0, -1.0, 0.5, true, 0.3, 8);
  m["hex"] = grout::box_mesh(3, 4, 2, {0.0, 2.0, -1.0, 0.5, 1.0, 4.0}, false, 0.3, 9);
  m["tet"] = grout::box_mesh(3, 2, 4, {0.0, 2.0, -1.0, 0.5, 1.0, 4.0}, true, 0.3, 10);
  m["annulus"] = grout::quarter_annulus_mesh(3, 6, 1.0, 2.5);
  m["two_2d"] = grout::two_block_mesh_2d(3, 2, 4, 3, false, 0.1);
  m["two_2d_tri"] = grout::two_block_mesh_2d(3, 2, 4, 3, true);
  m["two_3d"] = grout::two_block_mesh_3d(2, 2, 2, 3, 3, 1, false);
  m["two_3d_tet"] = grout::two_block_mesh_3d(2, 2, 2, 3, 3, 1, true, 0.2);
  return m;
}

/// Outward unit direction of a named straight boundary, or zero when not axis-aligned.
Vec expected_normal(std::string name, int dimension) {
  for (const char* prefix : {"lower_", "upper_"})
    if (name.rfind(prefix, 0) == 0) name = name.substr(std::string(prefix).size());
  const std::map<std::string, Vec> normals = {
      {"left", {-1, 0, 0}},      {"right", {1, 0, 0}}, {"xmin", {-1, 0, 0}},
      {"xmax", {1, 0, 0}},       {"ymin", {0, -1, 0}}, {"ymax", {0, 1, 0}},
      {"zmin", {0, 0, -1}},      {"zmax", {0, 0, 1}},  {"x_symmetry", {0, -1, 0}},
      {"y_symmetry", {-1, 0, 0}}};
  if (name == "bottom") return dimension == 2 ? Vec{0, -1, 0} : Vec{0, 0, -1};
  if (name == "top") return dimension == 2 ? Vec{0, 1, 0} : Vec{0, 0, 1};
  const auto it = normals.find(name);
  return it == normals.end() ? Vec{0, 0, 0} : it->second;
}

/// \brief Area vector of side `side` of element e (length = side length/area, direction by
/// the right-hand rule of the side_local_nodes ordering), plus side and element centroids.
struct SideGeometry {
  Vec normal, side_centroid, element_centroid;
};
SideGeometry side_geometry(const Mesh& m, GlobalIndex e, int side) {
  for (const auto& b : m.blocks) {
    if (e < b.first_element || e >= b.first_element + b.num_elements()) continue;
    const GlobalIndex* conn = b.connectivity.data() + (e - b.first_element) * b.nodes_per_element;
    SideGeometry g{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    for (int a = 0; a < b.nodes_per_element; ++a)
      for (int d = 0; d < 3; ++d)
        g.element_centroid[d] += point(m, conn[a])[d] / b.nodes_per_element;
    int local[grout::max_side_nodes];
    const int n = grout::side_local_nodes(b.topology, side, local);
    EXPECT_GT(n, 0) << "side " << side;
    Vec x[4];
    for (int a = 0; a < n; ++a) {
      x[a] = point(m, conn[local[a]]);
      for (int d = 0; d < 3; ++d) g.side_centroid[d] += x[a][d] / n;
    }
    if (n == 2) {
      const Vec t = sub(x[1], x[0]);
      g.normal = {t[1], -t[0], 0.0};
    } else if (n == 3) {
      const Vec c = cross(sub(x[1], x[0]), sub(x[2], x[0]));
      g.normal = {c[0] / 2, c[1] / 2, c[2] / 2};
    } else {
      const Vec c = cross(sub(x[2], x[0]), sub(x[3], x[1]));
      g.normal = {c[0] / 2, c[1] / 2, c[2] / 2};
    }
    return g;
  }
  ADD_FAILURE() << "element " << e << " in no block";
  return {};
}

}  // namespace

TEST(ExodusIO, MeshRoundTripOfGeneratedMeshes) {
  for (const auto& [name, mesh] : generated_meshes()) {
    SCOPED_TRACE(name);
    const std::string path = temp_path("roundtrip_" + name);
    grout::write_exodus_mesh(path, mesh);
    const Mesh back = grout::read_exodus(path);
    EXPECT_EQ(back.file, path);
    expect_same_mesh(mesh, back);
    // Overwriting an existing file works (EX_CLOBBER).
    grout::write_exodus_mesh(path, mesh);
    expect_same_mesh(mesh, grout::read_exodus(path));
  }
}

TEST(ExodusIO, ResultsRoundTrip) {
  const Mesh mesh = grout::two_block_mesh_2d(2, 2, 3, 1);  // 2 blocks: per-block slicing
  const std::string path = temp_path("results");
  const auto nn = std::size_t(mesh.num_nodes()), ne = std::size_t(mesh.num_elements());
  std::vector<std::vector<double>> nodal[2], element[2];
  std::vector<double> globals[2];
  {
    grout::ExodusWriter writer(path, mesh, {"displ_x", "displ_y"}, {"stress_xx"},
                               {"newton_iterations", "a_rather_long_global_variable_name_over_32"});
    grout::ExodusWriter moved = std::move(writer);  // move-only, the file stays open
    for (int s = 0; s < 2; ++s) {
      nodal[s].assign(2, std::vector<double>(nn));
      element[s].assign(1, std::vector<double>(ne));
      for (std::size_t i = 0; i < nn; ++i) {
        nodal[s][0][i] = 0.1 * i + s;
        nodal[s][1][i] = -1.0 / (i + 1) - s;
      }
      for (std::size_t e = 0; e < ne; ++e) element[s][0][e] = 1000.0 * e + s + 0.25;
      globals[s] = {3.0 + s, 1.0 / 3.0};
      moved.write_step(0.5 * (s + 1), nodal[s], element[s], globals[s]);
      // Flushed: another reader sees the step at once.
      EXPECT_EQ(grout::read_exodus_results(path).num_steps(), s + 1);
    }
    EXPECT_EQ(moved.num_steps(), 2);
    EXPECT_THROW(moved.write_step(2.0, {{1.0}}, element[0], globals[0]), std::invalid_argument);
  }
  const grout::ExodusResults r = grout::read_exodus_results(path);
  EXPECT_EQ(r.times, (std::vector<double>{0.5, 1.0}));
  EXPECT_EQ(r.nodal_names, (std::vector<std::string>{"displ_x", "displ_y"}));
  EXPECT_EQ(r.element_names, (std::vector<std::string>{"stress_xx"}));
  EXPECT_EQ(r.global_names,
            (std::vector<std::string>{"newton_iterations",
                                      "a_rather_long_global_variable_name_over_32"}));
  for (int s = 0; s < 2; ++s) {
    EXPECT_EQ(grout::read_nodal_variable(path, "displ_x", s + 1), nodal[s][0]);
    EXPECT_EQ(grout::read_nodal_variable(path, "displ_y", s + 1), nodal[s][1]);
    EXPECT_EQ(grout::read_element_variable(path, "stress_xx", s + 1), element[s][0]);
    EXPECT_EQ(grout::read_global_variables(path, s + 1), globals[s]);
  }
  expect_same_mesh(mesh, grout::read_exodus(path));
  EXPECT_THROW(grout::read_nodal_variable(path, "displ_z", 1), grout::InputError);
  EXPECT_THROW(grout::read_nodal_variable(path, "displ_x", 3), grout::InputError);
}

TEST(ExodusIO, MissingOrInvalidFileNamesThePath) {
  const std::string missing = temp_path("does_not_exist");
  std::remove(missing.c_str());
  try {
    grout::read_exodus(missing);
    FAIL() << "no exception";
  } catch (const grout::InputError& e) {
    EXPECT_EQ(std::string(e.what()), missing + ": cannot open Exodus file");
  }
  const std::string text = temp_path("not_exodus");
  std::ofstream(text) << "this is not a netCDF file\n";
  EXPECT_THROW(grout::read_exodus(text), grout::InputError);
  EXPECT_THROW(grout::read_exodus_results(missing), grout::InputError);
  EXPECT_THROW(grout::write_exodus_mesh("/nonexistent_dir/x.exo", grout::rectangle_mesh(1, 1)),
               grout::InputError);
}

/// Write a one-element 2D file with the raw C API: element type `type`, `npe` nodes.
void write_raw_file(const std::string& path, const char* type, int npe) {
  int comp_ws = 8, io_ws = 8;
  const int id = ex_create(path.c_str(), EX_CLOBBER, &comp_ws, &io_ws);
  ASSERT_GE(id, 0);
  ASSERT_GE(ex_put_init(id, "raw", 2, npe, 1, 1, 1, 1), 0);
  std::vector<double> x(npe), y(npe);
  for (int i = 0; i < npe; ++i) x[i] = std::cos(6.28 * i / npe), y[i] = std::sin(6.28 * i / npe);
  ASSERT_GE(ex_put_coord(id, x.data(), y.data(), nullptr), 0);
  ASSERT_GE(ex_put_block(id, EX_ELEM_BLOCK, 10, type, 1, npe, 0, 0, 0), 0);
  std::vector<int> conn(npe);
  for (int i = 0; i < npe; ++i) conn[i] = i + 1;
  ASSERT_GE(ex_put_conn(id, EX_ELEM_BLOCK, 10, conn.data(), nullptr, nullptr), 0);
  const int elem = 1, side = 1, node = 2;
  ASSERT_GE(ex_put_set_param(id, EX_SIDE_SET, 20, 1, 0), 0);
  ASSERT_GE(ex_put_set(id, EX_SIDE_SET, 20, &elem, &side), 0);
  ASSERT_GE(ex_put_set_param(id, EX_NODE_SET, 30, 1, 0), 0);
  ASSERT_GE(ex_put_set(id, EX_NODE_SET, 30, &node, nullptr), 0);
  ex_close(id);
}

TEST(ExodusIO, ElementTypesAndUnnamedEntities) {
  const std::string path = temp_path("raw");
  write_raw_file(path, "triangle", 3);  // lower case, long name: accepted
  const Mesh m = grout::read_exodus(path);
  EXPECT_EQ(m.dimension, 2);
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_EQ(m.blocks[0].topology, grout::Topology::tri3);
  EXPECT_EQ(m.blocks[0].name, "id_10");  // no names in the file
  EXPECT_EQ(m.side_sets.at(0).name, "id_20");
  EXPECT_EQ(m.side_sets[0].elements, std::vector<GlobalIndex>{0});
  EXPECT_EQ(m.side_sets[0].sides, std::vector<int>{1});
  EXPECT_EQ(m.node_sets.at(0).name, "id_30");
  EXPECT_EQ(m.node_sets[0].nodes, std::vector<GlobalIndex>{1});
  EXPECT_NE(m.find_side_set("id_20"), nullptr);

  write_raw_file(path, "Quad", 4);
  EXPECT_EQ(grout::read_exodus(path).blocks[0].topology, grout::Topology::quad4);

  write_raw_file(path, "QUAD8", 8);
  try {
    grout::read_exodus(path);
    FAIL() << "no exception";
  } catch (const grout::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path), std::string::npos) << what;
    EXPECT_NE(what.find("id_10"), std::string::npos) << what;
    EXPECT_NE(what.find("QUAD8"), std::string::npos) << what;
  }
  write_raw_file(path, "QUAD4", 5);  // wrong node count for the type
  EXPECT_THROW(grout::read_exodus(path), grout::InputError);
}

TEST(MeshGenerators, PositiveElementJacobians) {
  for (const auto& [name, mesh] : generated_meshes()) {
    SCOPED_TRACE(name);
    EXPECT_GT(grout::min_corner_jacobian(mesh), 0.0);
    // Independent check: the signed measure of every element (shoelace / divergence
    // theorem over its sides) is positive, and they add up to the domain measure.
    double total = 0.0;
    for (const auto& b : mesh.blocks)
      for (GlobalIndex e = b.first_element; e < b.first_element + b.num_elements(); ++e) {
        double measure = 0.0;  // (1/dim) sum over sides of x_side . area_vector
        for (int s = 1; s <= grout::topology_num_sides(b.topology); ++s) {
          const SideGeometry g = side_geometry(mesh, e, s);
          measure += dot(g.side_centroid, g.normal) / mesh.dimension;
        }
        EXPECT_GT(measure, 0.0) << "element " << e;
        total += measure;
      }
    const std::map<std::string, double> domain = {
        {"quad", 3.0},   {"tri", 3.0},        {"hex", 9.0},    {"tet", 9.0},
        {"two_2d", 2.0}, {"two_2d_tri", 2.0}, {"two_3d", 2.0}, {"two_3d_tet", 2.0}};
    const auto it = domain.find(name);
    if (it != domain.end()) {
      EXPECT_NEAR(total, it->second, 1e-12);
    }
  }
}

TEST(MeshGenerators, SideSetsPointOutwardAndCoverTheBoundary) {
  // Exact boundary measures: rectangle/box [0,2] x [-1,0.5] (x [1,4]); two blocks unit.
  const std::map<std::string, double> rectangle = {
      {"bottom", 2.0}, {"top", 2.0}, {"left", 1.5}, {"right", 1.5}};
  const std::map<std::string, double> box = {{"xmin", 1.5 * 3},   {"xmax", 1.5 * 3},
                                             {"ymin", 2.0 * 3},   {"ymax", 2.0 * 3},
                                             {"zmin", 2.0 * 1.5}, {"zmax", 2.0 * 1.5}};
  for (const auto& [name, mesh] : generated_meshes()) {
    SCOPED_TRACE(name);
    for (const auto& set : mesh.side_sets) {
      SCOPED_TRACE(set.name);
      ASSERT_FALSE(set.elements.empty());
      ASSERT_EQ(set.elements.size(), set.sides.size());
      double measure = 0.0;
      const Vec n = expected_normal(set.name, mesh.dimension);
      for (std::size_t i = 0; i < set.elements.size(); ++i) {
        const SideGeometry g = side_geometry(mesh, set.elements[i], set.sides[i]);
        const double area = std::sqrt(dot(g.normal, g.normal));
        measure += area;
        EXPECT_GT(dot(g.normal, sub(g.side_centroid, g.element_centroid)), 0.0);
        if (dot(n, n) > 0) {
          EXPECT_NEAR(dot(g.normal, n), area, 1e-12 * area);
        }
        if (set.name == "inner" || set.name == "outer") {  // radial: -r inner, +r outer
          const Vec c = g.side_centroid;
          const double radial = dot(g.normal, c) / std::sqrt(dot(c, c));
          EXPECT_GT(set.name == "outer" ? radial : -radial, 0.99 * area);
        }
      }
      double expected = 1.0;  // two-block meshes: unit squares and cubes
      if (name == "quad" || name == "tri") expected = rectangle.at(set.name);
      if (name == "hex" || name == "tet") expected = box.at(set.name);
      if (name == "annulus") {
        const double r = set.name == "inner" ? 1.0 : 2.5;  // 6 chords of a quarter circle
        expected =
            set.name.find("symmetry") != std::string::npos ? 1.5 : 6 * 2 * r * std::sin(M_PI / 24);
      }
      EXPECT_NEAR(measure, expected, 1e-12);
    }
  }
}

TEST(MeshGenerators, NodeSetsAreTheBoundaryNodes) {
  for (const auto& [name, mesh] : generated_meshes()) {
    SCOPED_TRACE(name);
    ASSERT_EQ(mesh.node_sets.size(), mesh.side_sets.size());
    for (std::size_t s = 0; s < mesh.node_sets.size(); ++s) {
      // A node set holds exactly the nodes of the side set of the same name.
      EXPECT_EQ(mesh.node_sets[s].name, mesh.side_sets[s].name);
      std::vector<GlobalIndex> from_sides;
      const auto& set = mesh.side_sets[s];
      for (std::size_t i = 0; i < set.elements.size(); ++i)
        for (const auto& b : mesh.blocks) {
          if (set.elements[i] < b.first_element ||
              set.elements[i] >= b.first_element + b.num_elements())
            continue;
          int local[grout::max_side_nodes];
          const int n = grout::side_local_nodes(b.topology, set.sides[i], local);
          for (int a = 0; a < n; ++a)
            from_sides.push_back(
                b.connectivity[(set.elements[i] - b.first_element) * b.nodes_per_element +
                               local[a]]);
        }
      std::sort(from_sides.begin(), from_sides.end());
      from_sides.erase(std::unique(from_sides.begin(), from_sides.end()), from_sides.end());
      EXPECT_EQ(mesh.node_sets[s].nodes, from_sides) << mesh.node_sets[s].name;
    }
  }
}

// grout_mesh writes a side set's node set as "<name>_nodes" (name_node_sets_apart); an input
// written before that names the node set "<name>" and must still find it, and an exact name
// always wins over the fallback.
TEST(MeshLookup, NodeSetNamedWithoutSuffixFindsTheNodesSet) {
  grout::Mesh m;
  m.node_sets.push_back({"top_nodes", 1, {4, 5}});
  m.node_sets.push_back({"left", 2, {0}});
  m.node_sets.push_back({"left_nodes", 3, {0, 1}});
  ASSERT_NE(m.find_node_set("top"), nullptr);
  EXPECT_EQ(m.find_node_set("top"), m.find_node_set("top_nodes"));
  EXPECT_EQ(m.find_node_set("left")->id, 2);  // exact name first
  EXPECT_EQ(m.find_node_set("id_3")->name, "left_nodes");
  EXPECT_EQ(m.find_node_set("bottom"), nullptr);
  EXPECT_EQ(m.find_node_set("top_node"), nullptr);
}

TEST(MeshGenerators, SimplexMeshesConformAndArcsAreExact) {
  // Every face of a conforming mesh is shared by two elements or lies on the boundary;
  // the boundary faces are exactly the side-set faces (each once per boundary patch).
  for (const char* name : {"tri", "tet", "two_3d_tet"}) {
    SCOPED_TRACE(name);
    const Mesh mesh = generated_meshes().at(name);
    std::map<std::vector<GlobalIndex>, int> faces;
    for (const auto& b : mesh.blocks)
      for (GlobalIndex e = 0; e < b.num_elements(); ++e)
        for (int s = 1; s <= grout::topology_num_sides(b.topology); ++s) {
          int local[grout::max_side_nodes];
          const int n = grout::side_local_nodes(b.topology, s, local);
          std::vector<GlobalIndex> key;
          for (int a = 0; a < n; ++a)
            key.push_back(b.connectivity[e * b.nodes_per_element + local[a]]);
          std::sort(key.begin(), key.end());
          ++faces[key];
        }
    std::size_t boundary = 0, side_set_faces = 0;
    for (const auto& [key, count] : faces) {
      EXPECT_LE(count, 2);
      boundary += count == 1;
    }
    for (const auto& set : mesh.side_sets) side_set_faces += set.elements.size();
    EXPECT_EQ(boundary, side_set_faces);
  }
  const Mesh annulus = grout::quarter_annulus_mesh(3, 6, 1.0, 2.5);
  for (const char* set : {"inner", "outer"})
    for (GlobalIndex node : annulus.find_node_set(set)->nodes) {
      const Vec p = point(annulus, node);
      EXPECT_NEAR(std::hypot(p[0], p[1]), std::string(set) == "inner" ? 1.0 : 2.5, 1e-15);
    }
  for (GlobalIndex node : annulus.find_node_set("x_symmetry")->nodes)
    EXPECT_EQ(point(annulus, node)[1], 0.0);
  for (GlobalIndex node : annulus.find_node_set("y_symmetry")->nodes)
    EXPECT_EQ(point(annulus, node)[0], 0.0);
}

TEST(MeshGenerators, DistortionIsSeededAndKeepsBoundaryNodesOnTheBoundary) {
  const Mesh a = grout::rectangle_mesh(6, 5, 0.0, 1.0, 0.0, 1.0, false, 0.3, 42);
  const Mesh b = grout::rectangle_mesh(6, 5, 0.0, 1.0, 0.0, 1.0, false, 0.3, 42);
  const Mesh c = grout::rectangle_mesh(6, 5, 0.0, 1.0, 0.0, 1.0, false, 0.3, 43);
  const Mesh regular = grout::rectangle_mesh(6, 5);
  EXPECT_EQ(a.coordinates, b.coordinates);
  EXPECT_NE(a.coordinates, c.coordinates);
  EXPECT_NE(a.coordinates, regular.coordinates);
  for (const auto& [set, d, value] : std::vector<std::tuple<std::string, int, double>>{
           {"bottom", 1, 0.0}, {"top", 1, 1.0}, {"left", 0, 0.0}, {"right", 0, 1.0}})
    for (GlobalIndex node : a.find_node_set(set)->nodes) EXPECT_EQ(point(a, node)[d], value);
  EXPECT_THROW(grout::rectangle_mesh(2, 2, 0, 1, 0, 1, false, 0.45), std::invalid_argument);
  EXPECT_THROW(grout::box_mesh(0, 2, 2), std::invalid_argument);
}
