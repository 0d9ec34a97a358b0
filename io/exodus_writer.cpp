// Writing Exodus II meshes and results with the Exodus 6.02 C API.
//
// Files are classic netCDF (what every ParaView reads), created with EX_CLOBBER and the
// 64-bit integer API (GlobalIndex arrays are passed straight through). Each time step is
// followed by ex_update() so the data is on disk before the next step starts.

#include <exodusII.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <ctime>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "io/errors.hpp"
#include "io/exodus.hpp"
#include "io/output_files.hpp"

namespace grout {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError(output_name(path) + ": " + what);
}

/// After a failed Exodus call: its reason, from the error Exodus recorded (a netCDF code or
/// an errno value, such as "No space left on device" or "Permission denied").
std::string exodus_reason(int status) {
  const char *message = nullptr, *function = nullptr;
  int code = 0;
  ex_get_err(&message, &function, &code);
  if (code > 0) return std::strerror(code);  // netCDF passes system errors on as errno
  if (code == 0 || code == EX_MSG || !message || !*message)
    return "status " + std::to_string(status);
  return std::string(message) + ", netCDF error " + std::to_string(code);
}

const char* exodus_element_type(Topology t) {
  switch (t) {
    case Topology::quad4:
      return "QUAD4";
    case Topology::tri3:
      return "TRI3";
    case Topology::hex8:
      return "HEX8";
    case Topology::tet4:
      return "TETRA4";
    case Topology::line2:
      break;
  }
  return nullptr;
}

/// Use the mesh's ids when they are positive and distinct, else number 1, 2, ...
template <class Entity>
std::vector<int64_t> entity_ids(const std::vector<Entity>& entities) {
  std::vector<int64_t> ids;
  std::set<int64_t> seen;
  bool valid = true;
  for (const auto& e : entities) {
    ids.push_back(e.id);
    valid = valid && e.id > 0 && seen.insert(e.id).second;
  }
  if (!valid)
    for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = int64_t(i + 1);
  return ids;
}

/// An Exodus file being written; closed on destruction unless released.
class WriteFile {
 public:
  WriteFile(const std::string& path, int max_name_length) : path_(path) {
    int comp_ws = sizeof(double), io_ws = sizeof(double);
    id_ = ex_create(path.c_str(), EX_CLOBBER | EX_ALL_INT64_API, &comp_ws, &io_ws);
    if (id_ < 0) fail(path, "cannot create Exodus file (" + exodus_reason(id_) + ")");
    // Names longer than the 32-character default would be truncated.
    ex_set_max_name_length(id_, std::max(max_name_length, int(MAX_NAME_LENGTH)));
  }
  ~WriteFile() {
    if (id_ >= 0) ex_close(id_);
  }
  WriteFile(WriteFile&& other) noexcept
      : path_(std::move(other.path_)), id_(std::exchange(other.id_, -1)) {}
  WriteFile(const WriteFile&) = delete;
  WriteFile& operator=(const WriteFile&) = delete;

  int id() const { return id_; }
  const std::string& path() const { return path_; }
  int release() { return std::exchange(id_, -1); }
  void check(int status, const std::string& what) const {
    if (status < 0)
      fail(path_, "Exodus error while writing " + what + " (" + exodus_reason(status) + ")");
  }
  void put_names(ex_entity_type type, const std::vector<std::string>& names,
                 const std::string& what) const {
    if (names.empty()) return;
    std::vector<char*> pointers;
    for (const auto& n : names) pointers.push_back(const_cast<char*>(n.c_str()));
    check(ex_put_names(id_, type, pointers.data()), what);
  }
  void put_variables(ex_entity_type type, const std::vector<std::string>& names,
                     const std::string& what) const {
    if (names.empty()) return;
    check(ex_put_variable_param(id_, type, int(names.size())), what);
    std::vector<char*> pointers;
    for (const auto& n : names) pointers.push_back(const_cast<char*>(n.c_str()));
    check(ex_put_variable_names(id_, type, int(names.size()), pointers.data()), what);
  }

 private:
  std::string path_;
  int id_ = -1;
};

template <class Entity>
std::vector<std::string> entity_names(const std::vector<Entity>& entities) {
  std::vector<std::string> names;
  for (const auto& e : entities) names.push_back(e.name);
  return names;
}

void write_coordinates(const WriteFile& file, const Mesh& mesh) {
  const auto n = std::size_t(mesh.num_nodes());
  const int d = mesh.dimension;
  std::vector<double> xyz[3];
  for (int k = 0; k < d; ++k) xyz[k].resize(n);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < d; ++k) xyz[k][i] = mesh.coordinates[d * i + k];
  if (n > 0)
    file.check(
        ex_put_coord(file.id(), xyz[0].data(), xyz[1].data(), d == 3 ? xyz[2].data() : nullptr),
        "coordinates");
}

void write_coordinate_names(const WriteFile& file) {
  const char* names[3] = {"x", "y", "z"};
  file.check(ex_put_coord_names(file.id(), const_cast<char**>(names)), "coordinate names");
}

/// 0-based entity indices as Exodus's 1-based ones.
std::vector<int64_t> one_based(const std::vector<GlobalIndex>& indices) {
  std::vector<int64_t> out(indices.begin(), indices.end());
  for (auto& i : out) ++i;
  return out;
}

/// Writes one array of the mesh into the open file `id` (`path` for the message).
void check_mesh_array(int status, const std::string& path, const std::string& what) {
  if (status < 0)
    fail(path, "Exodus error while writing " + what + " (" + exodus_reason(status) + ")");
}

void write_connectivity(int id, const std::string& path, int64_t block_id, const std::string& name,
                        const std::vector<GlobalIndex>& nodes) {
  if (nodes.empty()) return;
  check_mesh_array(
      ex_put_conn(id, EX_ELEM_BLOCK, block_id, one_based(nodes).data(), nullptr, nullptr), path,
      "connectivity of element block '" + name + "'");
}

void write_side_set(int id, const std::string& path, int64_t set_id, const std::string& name,
                    const std::vector<GlobalIndex>& elements, const std::vector<int>& sides) {
  if (elements.empty()) return;
  std::vector<int64_t> sides64(sides.begin(), sides.end());
  check_mesh_array(ex_put_set(id, EX_SIDE_SET, set_id, one_based(elements).data(), sides64.data()),
                   path, "side set '" + name + "'");
}

void write_node_set(int id, const std::string& path, int64_t set_id, const std::string& name,
                    const std::vector<GlobalIndex>& nodes) {
  if (nodes.empty()) return;
  check_mesh_array(ex_put_set(id, EX_NODE_SET, set_id, one_based(nodes).data(), nullptr), path,
                   "node set '" + name + "'");
}

/// The blocks of `outline`, and with `mesh` their connectivity.
void write_blocks(const WriteFile& file, const MeshOutline& outline,
                  const std::vector<int64_t>& ids, const Mesh* mesh) {
  for (std::size_t b = 0; b < outline.blocks.size(); ++b) {
    const ElementBlock& block = outline.blocks[b];
    const char* type = exodus_element_type(block.topology);
    if (!type) fail(outline.file, "element block '" + block.name + "' has no Exodus element type");
    file.check(ex_put_block(file.id(), EX_ELEM_BLOCK, ids[b], type, outline.block_sizes[b],
                            block.nodes_per_element, 0, 0, 0),
               "element block '" + block.name + "'");
    if (mesh)
      write_connectivity(file.id(), file.path(), ids[b], block.name, mesh->blocks[b].connectivity);
  }
  file.put_names(EX_ELEM_BLOCK, entity_names(outline.blocks), "element block names");
}

void write_side_sets(const WriteFile& file, const MeshOutline& outline,
                     const std::vector<int64_t>& ids, const Mesh* mesh) {
  for (std::size_t s = 0; s < outline.side_sets.size(); ++s) {
    const std::string& name = outline.side_sets[s].name;
    file.check(ex_put_set_param(file.id(), EX_SIDE_SET, ids[s], outline.side_set_sizes[s], 0),
               "side set '" + name + "'");
    if (mesh)
      write_side_set(file.id(), file.path(), ids[s], name, mesh->side_sets[s].elements,
                     mesh->side_sets[s].sides);
  }
  file.put_names(EX_SIDE_SET, entity_names(outline.side_sets), "side set names");
}

void write_node_sets(const WriteFile& file, const MeshOutline& outline,
                     const std::vector<int64_t>& ids, const Mesh* mesh) {
  for (std::size_t s = 0; s < outline.node_sets.size(); ++s) {
    const std::string& name = outline.node_sets[s].name;
    file.check(ex_put_set_param(file.id(), EX_NODE_SET, ids[s], outline.node_set_sizes[s], 0),
               "node set '" + name + "'");
    if (mesh) write_node_set(file.id(), file.path(), ids[s], name, mesh->node_sets[s].nodes);
  }
  file.put_names(EX_NODE_SET, entity_names(outline.node_sets), "node set names");
}

int longest_name(const MeshOutline& mesh, const std::vector<std::vector<std::string>>& variables) {
  std::size_t n = 0;
  for (const auto& b : mesh.blocks) n = std::max(n, b.name.size());
  for (const auto& s : mesh.side_sets) n = std::max(n, s.name.size());
  for (const auto& s : mesh.node_sets) n = std::max(n, s.name.size());
  for (const auto& list : variables)
    for (const auto& v : list) n = std::max(n, v.size());
  return int(n);
}

/// QA record (code, version, date, time of writing) and info lines of 80 characters at most.
void write_provenance(const WriteFile& file, const ExodusProvenance& provenance) {
  if (!provenance.code.empty()) {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char date[16], clock[16];
    std::strftime(date, sizeof date, "%m/%d/%y", &utc);
    std::strftime(clock, sizeof clock, "%H:%M:%S", &utc);
    std::string fields[4] = {provenance.code, provenance.version, date, clock};
    char* record[1][4];
    for (int k = 0; k < 4; ++k) {
      fields[k].resize(std::min(fields[k].size(), std::size_t(MAX_STR_LENGTH)));
      record[0][k] = const_cast<char*>(fields[k].c_str());
    }
    file.check(ex_put_qa(file.id(), 1, record), "the QA record");
  }
  std::vector<std::string> lines;
  for (const auto& text : provenance.info)
    for (std::size_t at = 0; at == 0 || at < text.size(); at += MAX_LINE_LENGTH)
      lines.push_back(text.substr(at, MAX_LINE_LENGTH));
  if (lines.empty()) return;
  std::vector<char*> pointers;
  for (auto& line : lines) pointers.push_back(const_cast<char*>(line.c_str()));
  file.check(ex_put_info(file.id(), int(pointers.size()), pointers.data()), "the info records");
}

/// 1-based local indices of the entries of `flags` equal to `value`.
std::vector<int64_t> local_ids_where(const std::vector<char>& flags, char value) {
  std::vector<int64_t> ids;
  for (std::size_t i = 0; i < flags.size(); ++i)
    if (flags[i] == value) ids.push_back(int64_t(i + 1));
  return ids;
}

/// \brief The Nemesis I header of one file of a file-per-rank set (what must be defined
/// before ex_put_init): file type "p" with one processor in the file, the global counts,
/// the load-balance parameters (internal and border nodes and elements, no external nodes)
/// and the sizes of the nodal communication maps (no elemental ones).
void write_piece_header(const WriteFile& file, const MeshOutline& mesh, const ExodusPiece& piece) {
  const GlobalIndex num_border_nodes =
      std::count(piece.border_node.begin(), piece.border_node.end(), 1);
  const GlobalIndex num_border_elements =
      std::count(piece.border_element.begin(), piece.border_element.end(), 1);
  char type[] = "p";
  file.check(ex_put_init_info(file.id(), piece.num_processors, 1, type), "the Nemesis header");
  file.check(ex_put_init_global(file.id(), piece.num_global_nodes, piece.num_global_elements,
                                int64_t(mesh.blocks.size()), int64_t(mesh.node_sets.size()),
                                int64_t(mesh.side_sets.size())),
             "the Nemesis global counts");
  file.check(ex_put_loadbal_param(file.id(), mesh.num_nodes - num_border_nodes, num_border_nodes, 0,
                                  mesh.num_elements() - num_border_elements, num_border_elements,
                                  int64_t(piece.node_maps.size()), 0, piece.processor),
             "the Nemesis load-balance parameters");
  if (piece.node_maps.empty()) return;
  std::vector<int64_t> ids, counts;
  for (const auto& m : piece.node_maps) {
    ids.push_back(m.processor);
    counts.push_back(int64_t(m.nodes.size()));
  }
  file.check(
      ex_put_cmap_params(file.id(), ids.data(), counts.data(), nullptr, nullptr, piece.processor),
      "the Nemesis communication map sizes");
}

/// The rest of the Nemesis I data (after the mesh): global block and set sizes, the
/// internal/border node and element maps, the nodal communication maps, and the node and
/// element id maps (global numbers, 1-based) that readers show as global ids.
void write_piece_maps(const WriteFile& file, const MeshOutline& mesh, const ExodusPiece& piece) {
  std::vector<int64_t> ids = entity_ids(mesh.blocks);
  std::vector<int64_t> counts(piece.global_block_sizes.begin(), piece.global_block_sizes.end());
  if (!ids.empty())
    file.check(ex_put_eb_info_global(file.id(), ids.data(), counts.data()),
               "the Nemesis block sizes");
  const auto put_sets = [&](auto put, std::vector<int64_t> set_ids,
                            const std::vector<GlobalIndex>& sizes, const char* what) {
    if (set_ids.empty()) return;
    std::vector<int64_t> n(sizes.begin(), sizes.end()), factors(sizes.size(), 0);
    file.check(put(file.id(), set_ids.data(), n.data(), factors.data()), what);
  };
  put_sets(ex_put_ns_param_global, entity_ids(mesh.node_sets), piece.global_node_set_sizes,
           "the Nemesis node set sizes");
  put_sets(ex_put_ss_param_global, entity_ids(mesh.side_sets), piece.global_side_set_sizes,
           "the Nemesis side set sizes");
  std::vector<int64_t> internal = local_ids_where(piece.border_node, 0),
                       border = local_ids_where(piece.border_node, 1), external;
  file.check(ex_put_processor_node_maps(file.id(), internal.data(), border.data(), external.data(),
                                        piece.processor),
             "the Nemesis node maps");
  internal = local_ids_where(piece.border_element, 0);
  border = local_ids_where(piece.border_element, 1);
  file.check(ex_put_processor_elem_maps(file.id(), internal.data(), border.data(), piece.processor),
             "the Nemesis element maps");
  for (const auto& m : piece.node_maps) {
    std::vector<int64_t> nodes(m.nodes.begin(), m.nodes.end()), procs(m.nodes.size(), m.processor);
    for (auto& n : nodes) ++n;
    file.check(
        ex_put_node_cmap(file.id(), m.processor, nodes.data(), procs.data(), piece.processor),
        "the Nemesis communication map to processor " + std::to_string(m.processor));
  }
  std::vector<int64_t> node_map(piece.node_ids.begin(), piece.node_ids.end());
  for (auto& n : node_map) ++n;
  if (!node_map.empty())
    file.check(ex_put_id_map(file.id(), EX_NODE_MAP, node_map.data()), "the node id map");
  std::vector<int64_t> element_map(piece.element_ids.begin(), piece.element_ids.end());
  for (auto& e : element_map) ++e;
  if (!element_map.empty())
    file.check(ex_put_id_map(file.id(), EX_ELEM_MAP, element_map.data()), "the element id map");
}

/// Create `path` and define the mesh of `outline` (and the variable names); with `mesh`, its
/// arrays are written too, else they follow through ExodusWriter's put_* calls. The file stays
/// open.
WriteFile create_mesh_file(const std::string& path, const MeshOutline& outline, const Mesh* mesh,
                           const std::vector<std::string>& nodal_vars,
                           const std::vector<std::string>& element_vars,
                           const std::vector<std::string>& global_vars,
                           const ExodusProvenance& provenance, const ExodusPiece* piece) {
  if (outline.dimension != 2 && outline.dimension != 3)
    fail(path, "cannot write a mesh of dimension " + std::to_string(outline.dimension));
  WriteFile file(path, longest_name(outline, {nodal_vars, element_vars, global_vars}));
  const auto block_ids = entity_ids(outline.blocks);
  if (piece) write_piece_header(file, outline, *piece);
  file.check(ex_put_init(file.id(), "Grout", outline.dimension, outline.num_nodes,
                         outline.num_elements(), int64_t(outline.blocks.size()),
                         int64_t(outline.node_sets.size()), int64_t(outline.side_sets.size())),
             "the header");
  if (mesh) write_coordinates(file, *mesh);
  write_coordinate_names(file);
  write_blocks(file, outline, block_ids, mesh);
  write_side_sets(file, outline, entity_ids(outline.side_sets), mesh);
  write_node_sets(file, outline, entity_ids(outline.node_sets), mesh);
  if (piece) write_piece_maps(file, outline, *piece);

  file.put_variables(EX_GLOBAL, global_vars, "global variable names");
  file.put_variables(EX_NODAL, nodal_vars, "nodal variable names");
  file.put_variables(EX_ELEM_BLOCK, element_vars, "element variable names");
  if (!element_vars.empty() && !outline.blocks.empty()) {
    // Every element variable exists on every block.
    std::vector<int> truth(outline.blocks.size() * element_vars.size(), 1);
    file.check(ex_put_truth_table(file.id(), EX_ELEM_BLOCK, int(outline.blocks.size()),
                                  int(element_vars.size()), truth.data()),
               "the element variable truth table");
  }
  write_provenance(file, provenance);
  file.check(ex_update(file.id()), "the mesh");
  return file;
}

}  // namespace

GlobalIndex MeshOutline::num_elements() const {
  GlobalIndex n = 0;
  for (GlobalIndex size : block_sizes) n += size;
  return n;
}

MeshOutline mesh_outline(const Mesh& mesh) {
  MeshOutline outline;
  outline.file = mesh.file;
  outline.dimension = mesh.dimension;
  outline.num_nodes = mesh.num_nodes();
  for (const ElementBlock& b : mesh.blocks) {
    ElementBlock block;
    block.name = b.name, block.id = b.id, block.topology = b.topology;
    block.nodes_per_element = b.nodes_per_element, block.first_element = b.first_element;
    outline.blocks.push_back(std::move(block));
    outline.block_sizes.push_back(b.num_elements());
  }
  for (const SideSet& s : mesh.side_sets) {
    outline.side_sets.push_back({s.name, s.id, {}, {}});
    outline.side_set_sizes.push_back(GlobalIndex(s.elements.size()));
  }
  for (const NodeSet& s : mesh.node_sets) {
    outline.node_sets.push_back({s.name, s.id, {}});
    outline.node_set_sizes.push_back(GlobalIndex(s.nodes.size()));
  }
  return outline;
}

void write_exodus_mesh(const std::string& path, const Mesh& mesh) {
  create_mesh_file(path, mesh_outline(mesh), &mesh, {}, {}, {}, {}, nullptr);
}

ExodusWriter::ExodusWriter(const std::string& path, const Mesh& mesh,
                           std::vector<std::string> nodal_vars,
                           std::vector<std::string> element_vars,
                           std::vector<std::string> global_vars, const ExodusProvenance& provenance,
                           const ExodusPiece* piece)
    : path_(path),
      num_nodal_(nodal_vars.size()),
      num_element_(element_vars.size()),
      num_global_(global_vars.size()) {
  const MeshOutline outline = mesh_outline(mesh);
  WriteFile file = create_mesh_file(path, outline, &mesh, nodal_vars, element_vars, global_vars,
                                    provenance, piece);
  keep_outline(outline);
  exoid_ = file.release();
}

ExodusWriter::ExodusWriter(const std::string& path, const MeshOutline& outline,
                           std::vector<std::string> nodal_vars,
                           std::vector<std::string> element_vars,
                           std::vector<std::string> global_vars, const ExodusProvenance& provenance)
    : path_(path),
      num_nodal_(nodal_vars.size()),
      num_element_(element_vars.size()),
      num_global_(global_vars.size()) {
  WriteFile file = create_mesh_file(path, outline, nullptr, nodal_vars, element_vars, global_vars,
                                    provenance, nullptr);
  keep_outline(outline);
  exoid_ = file.release();
}

void ExodusWriter::keep_outline(const MeshOutline& outline) {
  num_nodes_ = outline.num_nodes;
  num_elements_ = outline.num_elements();
  const auto ids = entity_ids(outline.blocks);
  for (std::size_t b = 0; b < outline.blocks.size(); ++b)
    blocks_.push_back({ids[b], outline.blocks[b].first_element, outline.block_sizes[b],
                       outline.blocks[b].nodes_per_element, outline.blocks[b].name});
  const auto side_ids = entity_ids(outline.side_sets), node_ids = entity_ids(outline.node_sets);
  for (std::size_t s = 0; s < outline.side_sets.size(); ++s)
    side_sets_.push_back({side_ids[s], outline.side_sets[s].name, outline.side_set_sizes[s]});
  for (std::size_t s = 0; s < outline.node_sets.size(); ++s)
    node_sets_.push_back({node_ids[s], outline.node_sets[s].name, outline.node_set_sizes[s]});
}

void ExodusWriter::put_coordinates(int component, const std::vector<double>& values) {
  if (GlobalIndex(values.size()) != num_nodes_ || component < 0 || component > 2)
    throw std::invalid_argument(path_ + ": put_coordinates: component or size");
  if (values.empty()) return;
  const double* xyz[3] = {nullptr, nullptr, nullptr};  // a null component is left alone
  xyz[component] = values.data();
  check_mesh_array(ex_put_coord(exoid_, xyz[0], xyz[1], xyz[2]), path_, "coordinates");
}

void ExodusWriter::put_connectivity(std::size_t b, const std::vector<GlobalIndex>& nodes) {
  if (b >= blocks_.size() ||
      GlobalIndex(nodes.size()) != blocks_[b].num_elements * blocks_[b].nodes_per_element)
    throw std::invalid_argument(path_ + ": put_connectivity: block or size");
  write_connectivity(exoid_, path_, blocks_[b].id, blocks_[b].name, nodes);
}

void ExodusWriter::put_side_set(std::size_t s, const std::vector<GlobalIndex>& elements,
                                const std::vector<int>& sides) {
  if (s >= side_sets_.size() || GlobalIndex(elements.size()) != side_sets_[s].size ||
      sides.size() != elements.size())
    throw std::invalid_argument(path_ + ": put_side_set: set or size");
  write_side_set(exoid_, path_, side_sets_[s].id, side_sets_[s].name, elements, sides);
}

void ExodusWriter::put_node_set(std::size_t s, const std::vector<GlobalIndex>& nodes) {
  if (s >= node_sets_.size() || GlobalIndex(nodes.size()) != node_sets_[s].size)
    throw std::invalid_argument(path_ + ": put_node_set: set or size");
  write_node_set(exoid_, path_, node_sets_[s].id, node_sets_[s].name, nodes);
}

ExodusWriter::~ExodusWriter() {
  close();
}

ExodusWriter::ExodusWriter(ExodusWriter&& other) noexcept
    : path_(std::move(other.path_)),
      exoid_(std::exchange(other.exoid_, -1)),
      num_nodes_(other.num_nodes_),
      num_elements_(other.num_elements_),
      blocks_(std::move(other.blocks_)),
      side_sets_(std::move(other.side_sets_)),
      node_sets_(std::move(other.node_sets_)),
      num_nodal_(other.num_nodal_),
      num_element_(other.num_element_),
      num_global_(other.num_global_),
      num_steps_(other.num_steps_),
      step_(other.step_) {}

ExodusWriter& ExodusWriter::operator=(ExodusWriter&& other) noexcept {
  if (this != &other) {
    close();
    path_ = std::move(other.path_);
    exoid_ = std::exchange(other.exoid_, -1);
    num_nodes_ = other.num_nodes_;
    num_elements_ = other.num_elements_;
    blocks_ = std::move(other.blocks_);
    side_sets_ = std::move(other.side_sets_);
    node_sets_ = std::move(other.node_sets_);
    num_nodal_ = other.num_nodal_;
    num_element_ = other.num_element_;
    num_global_ = other.num_global_;
    num_steps_ = other.num_steps_;
    step_ = other.step_;
  }
  return *this;
}

void ExodusWriter::close() noexcept {
  if (exoid_ >= 0) ex_close(exoid_);
  exoid_ = -1;
}

void ExodusWriter::write_step(double time, const std::vector<std::vector<double>>& nodal,
                              const std::vector<std::vector<double>>& element,
                              const std::vector<double>& globals) {
  if (exoid_ < 0) fail(path_, "write_step on a closed Exodus writer");
  // Sizes are the caller's contract, not user input: a mismatch is a programming error.
  auto require = [&](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument(path_ + ": write_step: " + what);
  };
  require(nodal.size() == num_nodal_,
          "expected " + std::to_string(num_nodal_) + " nodal variables");
  require(element.size() == num_element_,
          "expected " + std::to_string(num_element_) + " element variables");
  require(globals.size() == num_global_,
          "expected " + std::to_string(num_global_) + " global variables");
  for (const auto& v : nodal) require(GlobalIndex(v.size()) == num_nodes_, "nodal variable size");
  for (const auto& v : element)
    require(GlobalIndex(v.size()) == num_elements_, "element variable size");

  begin_step(time);
  for (std::size_t v = 0; v < nodal.size(); ++v) put_nodal(v, nodal[v]);
  for (std::size_t v = 0; v < element.size(); ++v) put_element(v, element[v]);
  put_globals(globals);
  end_step();
}

void ExodusWriter::check_step(int status, const std::string& what) const {
  if (status < 0)
    fail(path_, "Exodus error while writing " + what + " at step " + std::to_string(step_) + " (" +
                    exodus_reason(status) + ")");
}

void ExodusWriter::begin_step(double time) {
  if (exoid_ < 0) fail(path_, "write_step on a closed Exodus writer");
  step_ = num_steps_ + 1;
  check_step(ex_put_time(exoid_, step_, &time), "the time value");
}

void ExodusWriter::put_nodal(std::size_t v, const std::vector<double>& values) {
  if (GlobalIndex(values.size()) != num_nodes_ || v >= num_nodal_)
    throw std::invalid_argument(path_ + ": put_nodal: variable or size");
  check_step(ex_put_var(exoid_, step_, EX_NODAL, int(v + 1), 1, num_nodes_, values.data()),
             "nodal variable " + std::to_string(v + 1));
}

void ExodusWriter::put_element(std::size_t v, const std::vector<double>& values) {
  if (GlobalIndex(values.size()) != num_elements_ || v >= num_element_)
    throw std::invalid_argument(path_ + ": put_element: variable or size");
  for (const auto& b : blocks_) {
    if (b.num_elements == 0) continue;
    check_step(ex_put_var(exoid_, step_, EX_ELEM_BLOCK, int(v + 1), b.id, b.num_elements,
                          values.data() + b.first_element),
               "element variable " + std::to_string(v + 1));
  }
}

void ExodusWriter::put_globals(const std::vector<double>& values) {
  if (values.size() != num_global_) throw std::invalid_argument(path_ + ": put_globals: size");
  if (!values.empty())
    check_step(ex_put_var(exoid_, step_, EX_GLOBAL, 1, 1, int64_t(values.size()), values.data()),
               "global variables");
}

void ExodusWriter::end_step() {
  check_step(ex_update(exoid_), "(flushing)");
  num_steps_ = step_;
}

}  // namespace grout
