// Reading Exodus II meshes and results with the Exodus 6.02 C API.
//
// The file is opened with EX_ALL_INT64_API, so every id, count and index array passed to
// Exodus is 64-bit (GlobalIndex is long long, the same width as int64_t), and with a
// compute word size of 8 so coordinates and variables arrive as double.

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "io/errors.hpp"
#include "io/exodus.hpp"
#include "io/exodus_read_file.hpp"

namespace grout {

namespace {

static_assert(sizeof(GlobalIndex) == sizeof(int64_t), "grout: GlobalIndex must be 64-bit");

using namespace exodus_read;

void read_coordinates(const ReadOnlyFile& file, const Counts& c, Mesh& mesh) {
  const auto n = std::size_t(c.nodes);
  std::vector<double> x(n), y(n), z(c.dimension == 3 ? n : 0);
  if (n > 0)
    file.check(ex_get_coord(file.id(), x.data(), y.data(), c.dimension == 3 ? z.data() : nullptr),
               "reading coordinates");
  const int d = mesh.dimension;
  mesh.coordinates.resize(n * d);
  for (std::size_t i = 0; i < n; ++i) {
    mesh.coordinates[d * i] = x[i];
    mesh.coordinates[d * i + 1] = y[i];
    if (d == 3) mesh.coordinates[d * i + 2] = z[i];
  }
}

void read_blocks(const ReadOnlyFile& file, const Counts& c, Mesh& mesh) {
  const auto ids = file.ids(EX_ELEM_BLOCK, c.blocks, "the element blocks");
  const auto names = file.names(EX_ELEM_BLOCK, ids);
  GlobalIndex first = 0;
  for (std::size_t b = 0; b < ids.size(); ++b) {
    const std::string block = block_label(names[b], ids[b]);
    int64_t num_elements = 0;
    ElementBlock eb = read_block_header(file, c, ids[b], names[b], first, num_elements);
    const int64_t nodes_per_element = eb.nodes_per_element;
    eb.connectivity.resize(std::size_t(num_elements * nodes_per_element));
    if (num_elements > 0)
      file.check(
          ex_get_conn(file.id(), EX_ELEM_BLOCK, ids[b], eb.connectivity.data(), nullptr, nullptr),
          "reading the connectivity of " + block);
    for (auto& node : eb.connectivity) {
      if (node < 1 || node > c.nodes)
        fail(file.path(),
             block + " refers to node " + std::to_string(node) + " of " + std::to_string(c.nodes));
      --node;  // Exodus is 1-based
    }
    first += num_elements;
    mesh.blocks.push_back(std::move(eb));
  }
  if (first != c.elements)
    fail(file.path(), "the element blocks hold " + std::to_string(first) +
                          " elements but the header says " + std::to_string(c.elements));
}

void read_side_sets(const ReadOnlyFile& file, const Counts& c, Mesh& mesh) {
  const auto ids = file.ids(EX_SIDE_SET, c.side_sets, "the side sets");
  const auto names = file.names(EX_SIDE_SET, ids);
  for (std::size_t s = 0; s < ids.size(); ++s) {
    const std::string set = "side set '" + names[s] + "' (id " + std::to_string(ids[s]) + ")";
    int64_t count = 0, num_df = 0;
    file.check(ex_get_set_param(file.id(), EX_SIDE_SET, ids[s], &count, &num_df), "reading " + set);
    file.check_count(count, set, 2);  // element and side of each face
    SideSet ss;
    ss.name = names[s];
    ss.id = int(ids[s]);
    ss.elements.resize(std::size_t(count));
    std::vector<int64_t> sides(static_cast<std::size_t>(count));
    if (count > 0)
      file.check(ex_get_set(file.id(), EX_SIDE_SET, ids[s], ss.elements.data(), sides.data()),
                 "reading " + set);
    // Element numbers in a side set are 1-based positions in the global element order.
    ss.sides.resize(sides.size());
    for (std::size_t i = 0; i < sides.size(); ++i) {
      const GlobalIndex e = ss.elements[i] - 1;
      if (e < 0 || e >= c.elements)
        fail(file.path(), set + " refers to element " + std::to_string(e + 1) + " of " +
                              std::to_string(c.elements));
      ss.elements[i] = e;
      ss.sides[i] = int(sides[i]);
    }
    // Validate side numbers against the owning block's topology.
    for (std::size_t i = 0; i < sides.size(); ++i) {
      const GlobalIndex e = ss.elements[i];
      const ElementBlock* b = mesh.block_of(e);
      if (b && (ss.sides[i] < 1 || ss.sides[i] > topology_num_sides(b->topology)))
        fail(file.path(), set + " has side " + std::to_string(ss.sides[i]) + " on element " +
                              std::to_string(e + 1) + " of block '" + b->name + "'");
    }
    mesh.side_sets.push_back(std::move(ss));
  }
}

void read_node_sets(const ReadOnlyFile& file, const Counts& c, Mesh& mesh) {
  const auto ids = file.ids(EX_NODE_SET, c.node_sets, "the node sets");
  const auto names = file.names(EX_NODE_SET, ids);
  for (std::size_t s = 0; s < ids.size(); ++s) {
    const std::string set = "node set '" + names[s] + "' (id " + std::to_string(ids[s]) + ")";
    int64_t count = 0, num_df = 0;
    file.check(ex_get_set_param(file.id(), EX_NODE_SET, ids[s], &count, &num_df), "reading " + set);
    file.check_count(count, set);
    NodeSet ns;
    ns.name = names[s];
    ns.id = int(ids[s]);
    ns.nodes.resize(std::size_t(count));
    if (count > 0)
      file.check(ex_get_set(file.id(), EX_NODE_SET, ids[s], ns.nodes.data(), nullptr),
                 "reading " + set);
    for (auto& node : ns.nodes) {
      if (node < 1 || node > c.nodes)
        fail(file.path(),
             set + " refers to node " + std::to_string(node) + " of " + std::to_string(c.nodes));
      --node;
    }
    mesh.node_sets.push_back(std::move(ns));
  }
}

/// 1-based index of variable `name` among `names`, or a thrown InputError.
int variable_index(const ReadOnlyFile& file, const std::vector<std::string>& names,
                   const std::string& name, const char* kind) {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) fail(file.path(), std::string("no ") + kind + " variable '" + name + "'");
  return int(it - names.begin()) + 1;
}

void check_step(const ReadOnlyFile& file, int step) {
  const int64_t steps = ex_inquire_int(file.id(), EX_INQ_TIME);
  if (step < 1 || step > steps)
    fail(file.path(),
         "time step " + std::to_string(step) + " out of range 1.." + std::to_string(steps));
}

}  // namespace

Mesh read_exodus(const std::string& path) {
  const ReadOnlyFile file(path);
  const Counts counts = read_counts(file);
  Mesh mesh;
  mesh.file = path;
  mesh.dimension = int(counts.dimension);
  read_coordinates(file, counts, mesh);
  read_blocks(file, counts, mesh);
  read_side_sets(file, counts, mesh);
  read_node_sets(file, counts, mesh);
  return mesh;
}

ExodusResults read_exodus_results(const std::string& path) {
  const ReadOnlyFile file(path);
  ExodusResults r;
  const int64_t steps = std::max<int64_t>(ex_inquire_int(file.id(), EX_INQ_TIME), 0);
  file.check_count(steps, "the time steps");
  r.times.resize(std::size_t(steps));
  if (!r.times.empty()) file.check(ex_get_all_times(file.id(), r.times.data()), "reading times");
  r.nodal_names = file.variable_names(EX_NODAL);
  r.element_names = file.variable_names(EX_ELEM_BLOCK);
  r.global_names = file.variable_names(EX_GLOBAL);
  return r;
}

std::vector<double> read_nodal_variable(const std::string& path, const std::string& name,
                                        int step) {
  const ReadOnlyFile file(path);
  const int index = variable_index(file, file.variable_names(EX_NODAL), name, "nodal");
  check_step(file, step);
  const int64_t nodes = ex_inquire_int(file.id(), EX_INQ_NODES);
  file.check_count(nodes, "the nodes");
  std::vector<double> values(static_cast<std::size_t>(nodes));
  file.check(ex_get_var(file.id(), step, EX_NODAL, index, 1, int64_t(values.size()), values.data()),
             "reading nodal variable '" + name + "'");
  return values;
}

std::vector<double> read_element_variable(const std::string& path, const std::string& name,
                                          int step) {
  const ReadOnlyFile file(path);
  const int index = variable_index(file, file.variable_names(EX_ELEM_BLOCK), name, "element");
  check_step(file, step);
  const Counts counts = read_counts(file);
  std::vector<double> values(static_cast<std::size_t>(counts.elements));
  // Blocks are stored one after the other in the global element order.
  std::size_t offset = 0;
  for (const int64_t id : file.ids(EX_ELEM_BLOCK, counts.blocks, "the element blocks")) {
    char type[MAX_STR_LENGTH + 1] = {};
    int64_t num_elements = 0, npe = 0, edges = 0, faces = 0, attributes = 0;
    file.check(ex_get_block(file.id(), EX_ELEM_BLOCK, id, type, &num_elements, &npe, &edges, &faces,
                            &attributes),
               "reading element block " + std::to_string(id));
    if (num_elements < 0 || std::size_t(num_elements) > values.size() - offset)
      fail(file.path(), "element block " + std::to_string(id) + " holds " +
                            std::to_string(num_elements) + " elements, more than the header's " +
                            std::to_string(counts.elements) + " in all");
    if (num_elements > 0)
      file.check(ex_get_var(file.id(), step, EX_ELEM_BLOCK, index, id, num_elements,
                            values.data() + offset),
                 "reading element variable '" + name + "'");
    offset += std::size_t(num_elements);
  }
  return values;
}

std::vector<double> read_global_variables(const std::string& path, int step) {
  const ReadOnlyFile file(path);
  const auto names = file.variable_names(EX_GLOBAL);
  check_step(file, step);
  std::vector<double> values(names.size());
  if (!values.empty())
    file.check(ex_get_var(file.id(), step, EX_GLOBAL, 1, 1, int64_t(values.size()), values.data()),
               "reading global variables");
  return values;
}

}  // namespace grout
