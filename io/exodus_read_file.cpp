// The Exodus file opened read-only and the header checks shared by the mesh readers
// (io/exodus_read_file.hpp).

#include "io/exodus_read_file.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <limits>

#include "io/errors.hpp"
#include "io/netcdf_header.hpp"

namespace grout::exodus_read {

namespace {

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

std::string upper_case(std::string s) {
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

void fail(const std::string& path, const std::string& what) {
  throw InputError(path + ": " + what);
}

void check(int status, const std::string& path, const std::string& what) {
  if (status < 0)
    fail(path, "Exodus error while " + what + " (status " + std::to_string(status) + ")");
}

ReadOnlyFile::ReadOnlyFile(const std::string& path)
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

ReadOnlyFile::~ReadOnlyFile() {
  ex_close(id_);
}

void ReadOnlyFile::check_count(int64_t count, const std::string& what, int64_t values_each) const {
  if (count < 0) fail(path_, what + ": negative count " + std::to_string(count));
  if (count > max_values_ / values_each) {
    fail(path_, what + ": the header declares " + std::to_string(count) + " entries of " +
                    std::to_string(values_each) + " value(s) but the file can hold at most " +
                    std::to_string(max_values_) +
                    " values (limit from the file size; the file is corrupt or truncated)");
  }
}

std::vector<int64_t> ReadOnlyFile::ids(ex_entity_type type, int64_t count,
                                       const std::string& what) const {
  check_count(count, what);
  std::vector<int64_t> ids(static_cast<std::size_t>(count));
  if (count > 0) check(ex_get_ids(id_, type, ids.data()), "reading entity ids");
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (ids[i] < std::numeric_limits<int>::min() || ids[i] > std::numeric_limits<int>::max())
      fail(path_, what + ": entry " + std::to_string(i + 1) + " has id " + std::to_string(ids[i]) +
                      ", outside the supported range " +
                      std::to_string(std::numeric_limits<int>::min()) + ".." +
                      std::to_string(std::numeric_limits<int>::max()));
  }
  return ids;
}

std::vector<std::string> ReadOnlyFile::names(ex_entity_type type,
                                             const std::vector<int64_t>& ids) const {
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

std::vector<std::string> ReadOnlyFile::variable_names(ex_entity_type type) const {
  int count = 0;
  check(ex_get_variable_param(id_, type, &count), "reading the number of variables");
  check_count(count, "the number of variables");
  std::vector<std::string> result(std::size_t(std::max(count, 0)));
  if (count <= 0) return result;
  std::vector<std::vector<char>> buffers(result.size(), std::vector<char>(name_length_ + 1, '\0'));
  std::vector<char*> pointers;
  for (auto& b : buffers) pointers.push_back(b.data());
  check(ex_get_variable_names(id_, type, count, pointers.data()), "reading variable names");
  for (std::size_t i = 0; i < result.size(); ++i) result[i] = buffers[i].data();
  return result;
}

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

std::string block_label(const std::string& name, int64_t id) {
  return "element block '" + name + "' (id " + std::to_string(id) + ")";
}

ElementBlock read_block_header(const ReadOnlyFile& file, const Counts& counts, int64_t id,
                               const std::string& name, GlobalIndex first, int64_t& num_elements) {
  const std::string block = block_label(name, id);
  char type[MAX_STR_LENGTH + 1] = {};
  int64_t nodes_per_element = 0, edges = 0, faces = 0, attributes = 0;
  num_elements = 0;
  file.check(ex_get_block(file.id(), EX_ELEM_BLOCK, id, type, &num_elements, &nodes_per_element,
                          &edges, &faces, &attributes),
             "reading " + block);
  ElementBlock eb;
  eb.name = name;
  eb.id = int(id);
  eb.first_element = first;
  // Exodus writes an element block without elements with the type "NULL".
  if (num_elements == 0)
    fail(file.path(), block + " is empty (0 elements, element type '" + std::string(type) +
                          "'): every block needs elements; remove it from the mesh");
  if (!parse_topology(type, eb.topology))
    fail(file.path(), block + " has unsupported element type '" + std::string(type) +
                          "' (supported: QUAD4, TRI3, HEX8, TET4)");
  if (topology_dimension(eb.topology) != counts.dimension)
    fail(file.path(), block + " has element type '" + std::string(type) + "' in a " +
                          std::to_string(counts.dimension) + "D mesh");
  if (nodes_per_element != topology_num_nodes(eb.topology))
    fail(file.path(), block + " of type '" + std::string(type) + "' has " +
                          std::to_string(nodes_per_element) + " nodes per element, expected " +
                          std::to_string(topology_num_nodes(eb.topology)));
  eb.nodes_per_element = int(nodes_per_element);
  file.check_count(num_elements, "the connectivity of " + block, nodes_per_element);
  return eb;
}

}  // namespace grout::exodus_read
