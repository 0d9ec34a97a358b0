// Reading Exodus II meshes and results with the Exodus 6.02 C API.
//
// The file is opened with EX_ALL_INT64_API, so every id, count and index array passed to
// Exodus is 64-bit (GlobalIndex is long long, the same width as int64_t), and with a
// compute word size of 8 so coordinates and variables arrive as double.

#include <exodusII.h>

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
#include "io/netcdf_header.hpp"

namespace grout {

namespace {

static_assert(sizeof(GlobalIndex) == sizeof(int64_t), "grout: GlobalIndex must be 64-bit");

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError(path + ": " + what);
}

/// Throw InputError when an Exodus call failed (negative status; positive is a warning).
void check(int status, const std::string& path, const std::string& what) {
  if (status < 0)
    fail(path, "Exodus error while " + what + " (status " + std::to_string(status) + ")");
}

/// Longest entity name read (netCDF's NC_MAX_NAME is 256 including the terminating zero).
constexpr int64_t max_name_length = 255;

/// How many stored values a file of `bytes` bytes can hold at most, so that a count in a
/// corrupt or hostile header is refused before anything is allocated for it. A classic
/// netCDF file ("CDF" magic) stores every value in full, at least 4 bytes each. An HDF5-based
/// file (netCDF-4) may compress: deflate, the only filter Exodus applies, shrinks data by at
/// most a factor of 1032.
int64_t max_stored_values(const std::string& path) {
  std::error_code error;
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  if (error) return 0;
  char magic[3] = {};
  std::ifstream(path, std::ios::binary).read(magic, sizeof magic);
  const bool classic = magic[0] == 'C' && magic[1] == 'D' && magic[2] == 'F';
  const std::uintmax_t values = classic ? bytes / 4 : bytes / 4 * 1032;
  return int64_t(std::min<std::uintmax_t>(values, std::numeric_limits<int64_t>::max() / 8));
}

/// An Exodus file opened for reading, closed when it goes out of scope.
class ReadOnlyFile {
 public:
  explicit ReadOnlyFile(const std::string& path)
      : path_(path), max_values_(max_stored_values(path)) {
    int comp_ws = sizeof(double), io_ws = 0;
    float version = 0.0f;
    check_netcdf_header(path);  // before netCDF allocates what the header declares
    id_ = ex_open(path.c_str(), EX_READ | EX_ALL_INT64_API, &comp_ws, &io_ws, &version);
    if (id_ < 0) fail(path, "cannot open Exodus file");
    // Names longer than the 32-character default are truncated unless we ask for them.
    const int64_t used = ex_inquire_int(id_, EX_INQ_DB_MAX_USED_NAME_LENGTH);
    name_length_ = int(std::clamp<int64_t>(used, MAX_NAME_LENGTH, max_name_length));
    ex_set_max_name_length(id_, name_length_);
  }
  ~ReadOnlyFile() { ex_close(id_); }
  ReadOnlyFile(const ReadOnlyFile&) = delete;
  ReadOnlyFile& operator=(const ReadOnlyFile&) = delete;

  int id() const { return id_; }
  const std::string& path() const { return path_; }
  void check(int status, const std::string& what) const { grout::check(status, path_, what); }

  /// Refuse `count` entries of `what` (from the header), `values_each` stored values each,
  /// when the file is too small to hold them: the header is corrupt, and allocating for it
  /// could exhaust the memory.
  void check_count(int64_t count, const std::string& what, int64_t values_each = 1) const {
    if (count < 0) fail(path_, what + ": negative count " + std::to_string(count));
    if (count > max_values_ / values_each) {
      fail(path_, what + ": the header declares " + std::to_string(count) + " entries of " +
                      std::to_string(values_each) + " value(s) but the file can hold at most " +
                      std::to_string(max_values_) +
                      " values (limit from the file size; the file is corrupt or truncated)");
    }
  }

  /// The ids of `count` entities of `type`; each must fit in an int (ElementBlock::id and the
  /// sets' ids are int: 2^32 + 1 would otherwise read as 1, a false "same id").
  std::vector<int64_t> ids(ex_entity_type type, int64_t count, const std::string& what) const {
    check_count(count, what);
    std::vector<int64_t> ids(static_cast<std::size_t>(count));
    if (count > 0) check(ex_get_ids(id_, type, ids.data()), "reading entity ids");
    for (std::size_t i = 0; i < ids.size(); ++i) {
      if (ids[i] < std::numeric_limits<int>::min() || ids[i] > std::numeric_limits<int>::max())
        fail(path_, what + ": entry " + std::to_string(i + 1) + " has id " +
                        std::to_string(ids[i]) + ", outside the supported range " +
                        std::to_string(std::numeric_limits<int>::min()) + ".." +
                        std::to_string(std::numeric_limits<int>::max()));
    }
    return ids;
  }

  /// Names of all entities of one type; an empty name becomes "id_<n>".
  std::vector<std::string> names(ex_entity_type type, const std::vector<int64_t>& ids) const {
    std::vector<std::string> result(ids.size());
    if (ids.empty()) return result;
    std::vector<std::vector<char>> buffers(ids.size(), std::vector<char>(name_length_ + 1, '\0'));
    std::vector<char*> pointers;
    for (auto& b : buffers) pointers.push_back(b.data());
    check(ex_get_names(id_, type, pointers.data()), "reading names");
    for (std::size_t i = 0; i < ids.size(); ++i) {
      result[i] = buffers[i].data();
      if (result[i].empty()) result[i] = "id_" + std::to_string(ids[i]);
    }
    return result;
  }

  std::vector<std::string> variable_names(ex_entity_type type) const {
    int count = 0;
    check(ex_get_variable_param(id_, type, &count), "reading the number of variables");
    check_count(count, "the number of variables");
    std::vector<std::string> result(std::size_t(std::max(count, 0)));
    if (count <= 0) return result;
    std::vector<std::vector<char>> buffers(result.size(),
                                           std::vector<char>(name_length_ + 1, '\0'));
    std::vector<char*> pointers;
    for (auto& b : buffers) pointers.push_back(b.data());
    check(ex_get_variable_names(id_, type, count, pointers.data()), "reading variable names");
    for (std::size_t i = 0; i < result.size(); ++i) result[i] = buffers[i].data();
    return result;
  }

 private:
  std::string path_;
  int64_t max_values_ = 0;
  int id_ = -1;
  int name_length_ = MAX_NAME_LENGTH;
};

std::string upper_case(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

/// Map an Exodus element type string to a Topology; false when unsupported.
bool parse_topology(const std::string& exodus_type, Topology& topology) {
  const std::string t = upper_case(exodus_type);
  if (t == "QUAD" || t == "QUAD4")
    topology = Topology::quad4;
  else if (t == "TRI" || t == "TRI3" || t == "TRIANGLE")
    topology = Topology::tri3;
  else if (t == "HEX" || t == "HEX8")
    topology = Topology::hex8;
  else if (t == "TET" || t == "TET4" || t == "TETRA" || t == "TETRA4")
    topology = Topology::tet4;
  else
    return false;
  return true;
}

struct Counts {
  int64_t dimension = 0, nodes = 0, elements = 0, blocks = 0, node_sets = 0, side_sets = 0;
};

Counts read_counts(const ReadOnlyFile& file) {
  Counts c;
  char title[MAX_LINE_LENGTH + 1] = {};
  file.check(ex_get_init(file.id(), title, &c.dimension, &c.nodes, &c.elements, &c.blocks,
                         &c.node_sets, &c.side_sets),
             "reading the header");
  if (c.dimension != 2 && c.dimension != 3)
    fail(file.path(), "unsupported spatial dimension " + std::to_string(c.dimension));
  file.check_count(c.nodes, "the node coordinates", c.dimension);
  file.check_count(c.elements, "the elements");
  file.check_count(c.blocks, "the element blocks");
  file.check_count(c.node_sets, "the node sets");
  file.check_count(c.side_sets, "the side sets");
  return c;
}

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
    const std::string block =
        "element block '" + names[b] + "' (id " + std::to_string(ids[b]) + ")";
    char type[MAX_STR_LENGTH + 1] = {};
    int64_t num_elements = 0, nodes_per_element = 0, edges = 0, faces = 0, attributes = 0;
    file.check(ex_get_block(file.id(), EX_ELEM_BLOCK, ids[b], type, &num_elements,
                            &nodes_per_element, &edges, &faces, &attributes),
               "reading " + block);
    ElementBlock eb;
    eb.name = names[b];
    eb.id = int(ids[b]);
    eb.first_element = first;
    // Exodus writes an element block without elements with the type "NULL".
    if (num_elements == 0)
      fail(file.path(), block + " is empty (0 elements, element type '" + std::string(type) +
                            "'): every block needs elements; remove it from the mesh");
    if (!parse_topology(type, eb.topology))
      fail(file.path(), block + " has unsupported element type '" + std::string(type) +
                            "' (supported: QUAD4, TRI3, HEX8, TET4)");
    if (topology_dimension(eb.topology) != mesh.dimension)
      fail(file.path(), block + " has element type '" + std::string(type) + "' in a " +
                            std::to_string(mesh.dimension) + "D mesh");
    if (nodes_per_element != topology_num_nodes(eb.topology))
      fail(file.path(), block + " of type '" + std::string(type) + "' has " +
                            std::to_string(nodes_per_element) + " nodes per element, expected " +
                            std::to_string(topology_num_nodes(eb.topology)));
    eb.nodes_per_element = int(nodes_per_element);
    file.check_count(num_elements, "the connectivity of " + block, nodes_per_element);
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
