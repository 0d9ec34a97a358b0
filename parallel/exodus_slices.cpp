// Reading an Exodus mesh in slices (parallel/exodus_slices.hpp): the header on rank 0, the
// per-entity arrays with ex_get_partial_coord / ex_get_partial_conn /
// ex_get_partial_side_set / ex_get_partial_node_set (Exodus 6.02 C API), each rank its own
// contiguous slice (parallel/slices.hpp).

#include "parallel/exodus_slices.hpp"

#include <Teuchos_CommHelpers.hpp>

#include "assembly/agree_on_errors.hpp"
#include "assembly/distribute_mesh.hpp"
#include "io/errors.hpp"
#include "io/exodus_read_file.hpp"
#include "parallel/slices.hpp"

namespace grout {

using namespace exodus_read;

namespace {

std::string set_label(const char* kind, const std::string& name, int id) {
  return std::string(kind) + " '" + name + "' (id " + std::to_string(id) + ")";
}

/// Exodus's 1-based numbers of `what` (node, element) in [first, last), each in [1, n], made
/// 0-based; a number out of range is the file's error, naming `label`.
void to_zero_based(GlobalIndex* first, GlobalIndex* last, GlobalIndex n, const char* what,
                   const std::string& file, const std::string& label) {
  for (GlobalIndex* v = first; v != last; ++v) {
    if (*v < 1 || *v > n)
      fail(file,
           label + " refers to " + what + " " + std::to_string(*v) + " of " + std::to_string(n));
    --*v;
  }
}

/// This rank's slice [begin, begin + count) of a set of `size` entries, its begin recorded.
struct SetSlice {
  GlobalIndex begin, count;
};
SetSlice set_slice(GlobalIndex size, int rank, int ranks, std::vector<GlobalIndex>& begins) {
  const GlobalIndex begin = slice_begin(size, rank, ranks);
  begins.push_back(begin);
  return {begin, slice_begin(size, rank + 1, ranks) - begin};
}

/// Rank 0's part of read_mesh_header: the header as a Mesh without per-entity arrays, and the
/// sizes [nodes, elements, blocks..., side sets..., node sets...].
Mesh read_header(const std::string& path, std::vector<long long>& sizes) {
  const ReadOnlyFile file(path);
  const Counts c = read_counts(file);
  Mesh mesh;
  mesh.file = path;
  mesh.dimension = int(c.dimension);
  sizes = {c.nodes, c.elements};
  const auto block_ids = file.ids(EX_ELEM_BLOCK, c.blocks, "the element blocks");
  const auto block_names = file.names(EX_ELEM_BLOCK, block_ids);
  GlobalIndex first = 0;
  for (std::size_t b = 0; b < block_ids.size(); ++b) {
    int64_t count = 0;
    mesh.blocks.push_back(read_block_header(file, c, block_ids[b], block_names[b], first, count));
    sizes.push_back(count);
    first += count;
  }
  if (first != c.elements)
    fail(path, "the element blocks hold " + std::to_string(first) +
                   " elements but the header says " + std::to_string(c.elements));
  const auto read_sets = [&](ex_entity_type type, int64_t n, const char* what, const char* kind,
                             int values_each, auto& sets) {
    const auto ids = file.ids(type, n, what);
    const auto names = file.names(type, ids);
    for (std::size_t s = 0; s < ids.size(); ++s) {
      const std::string set = set_label(kind, names[s], int(ids[s]));
      int64_t count = 0, num_df = 0;
      file.check(ex_get_set_param(file.id(), type, ids[s], &count, &num_df), "reading " + set);
      file.check_count(count, set, values_each);
      sets.emplace_back();
      sets.back().name = names[s];
      sets.back().id = int(ids[s]);
      sizes.push_back(count);
    }
  };
  read_sets(EX_SIDE_SET, c.side_sets, "the side sets", "side set", 2, mesh.side_sets);
  read_sets(EX_NODE_SET, c.node_sets, "the node sets", "node set", 1, mesh.node_sets);
  check_mesh(mesh);  // names and ids unique (no per-entity arrays yet)
  return mesh;
}

void read_coordinates(const ReadOnlyFile& file, const MeshHeader& h, MeshSlices& s,
                      GlobalIndex count) {
  const auto n = std::size_t(count);
  const int d = h.dimension;
  std::vector<double> x(n), y(n), z(d == 3 ? n : 0);
  if (n > 0)
    file.check(ex_get_partial_coord(file.id(), s.node_begin + 1, count, x.data(), y.data(),
                                    d == 3 ? z.data() : nullptr),
               "reading coordinates");
  s.coordinates.resize(n * d);
  for (std::size_t i = 0; i < n; ++i) {
    s.coordinates[d * i] = x[i];
    s.coordinates[d * i + 1] = y[i];
    if (d == 3) s.coordinates[d * i + 2] = z[i];
  }
}

/// Elements [begin, end) of the global order, block by block.
void read_connectivity(const ReadOnlyFile& file, const MeshHeader& h, MeshSlices& s,
                       GlobalIndex end) {
  s.element_nodes_offset.assign(1, 0);
  for (std::size_t b = 0; b < h.blocks.size(); ++b) {
    const ElementBlock& block = h.blocks[b];
    const GlobalIndex lo = std::max(s.element_begin, block.first_element);
    const GlobalIndex hi = std::min(end, block.first_element + h.block_size[b]);
    if (lo >= hi) continue;
    const int npe = block.nodes_per_element;
    const std::size_t at = s.element_nodes.size();
    s.element_nodes.resize(at + std::size_t((hi - lo) * npe));
    const std::string label = block_label(block.name, block.id);
    file.check(ex_get_partial_conn(file.id(), EX_ELEM_BLOCK, block.id, lo - block.first_element + 1,
                                   hi - lo, s.element_nodes.data() + at, nullptr, nullptr),
               "reading the connectivity of " + label);
    to_zero_based(s.element_nodes.data() + at, s.element_nodes.data() + s.element_nodes.size(),
                  h.num_nodes, "node", h.file, label);
    for (GlobalIndex e = lo; e < hi; ++e) {
      s.element_block.push_back(int(b));
      s.element_nodes_offset.push_back(s.element_nodes_offset.back() + npe);
    }
  }
}

/// This rank's slice of one set (`kind`: "side set" or "node set"): its label, its begin
/// recorded in `begins`, and its ids (elements or nodes, `what`) read by
/// `read(first, count, ids)` (Exodus's partial read, `first` 1-based) and made 0-based against
/// their count n.
template <class Set, class Read>
std::vector<GlobalIndex> read_set_slice(const Set& set, const char* kind, GlobalIndex size,
                                        int rank, int ranks, std::vector<GlobalIndex>& begins,
                                        GlobalIndex n, const char* what, const std::string& file,
                                        std::string& label, const Read& read) {
  label = set_label(kind, set.name, set.id);
  const auto [begin, count] = set_slice(size, rank, ranks, begins);
  std::vector<GlobalIndex> ids(static_cast<std::size_t>(count));
  if (count > 0) read(begin + 1, count, ids.data());
  to_zero_based(ids.data(), ids.data() + ids.size(), n, what, file, label);
  return ids;
}

void read_side_sets(const ReadOnlyFile& file, const MeshHeader& h, MeshSlices& s, int rank,
                    int ranks) {
  for (std::size_t k = 0; k < h.side_sets.size(); ++k) {
    const SideSet& set = h.side_sets[k];
    std::string label;
    std::vector<GlobalIndex> sides;
    // Element numbers in a side set are 1-based positions in the global element order.
    std::vector<GlobalIndex> elements = read_set_slice(
        set, "side set", h.side_set_size[k], rank, ranks, s.side_set_begin, h.num_elements,
        "element", h.file, label, [&](GlobalIndex first, GlobalIndex count, GlobalIndex* ids) {
          sides.resize(static_cast<std::size_t>(count));
          file.check(ex_get_partial_side_set(file.id(), set.id, first, count, ids, sides.data()),
                     "reading " + label);
        });
    std::vector<int> side(sides.size());
    for (std::size_t i = 0; i < sides.size(); ++i) {
      const ElementBlock& block = h.blocks[std::size_t(h.block_of(elements[i]))];
      side[i] = int(sides[i]);
      if (sides[i] < 1 || sides[i] > topology_num_sides(block.topology))
        fail(h.file, label + " has side " + std::to_string(side[i]) + " on element " +
                         std::to_string(elements[i] + 1) + " of block '" + block.name + "'");
    }
    s.side_set_elements.push_back(std::move(elements));
    s.side_set_sides.push_back(std::move(side));
  }
}

void read_node_sets(const ReadOnlyFile& file, const MeshHeader& h, MeshSlices& s, int rank,
                    int ranks) {
  for (std::size_t k = 0; k < h.node_sets.size(); ++k) {
    const NodeSet& set = h.node_sets[k];
    std::string label;
    s.node_set_nodes.push_back(read_set_slice(
        set, "node set", h.node_set_size[k], rank, ranks, s.node_set_begin, h.num_nodes, "node",
        h.file, label, [&](GlobalIndex first, GlobalIndex count, GlobalIndex* ids) {
          file.check(ex_get_partial_node_set(file.id(), set.id, first, count, ids),
                     "reading " + label);
        }));
  }
}

}  // namespace

int MeshHeader::block_of(GlobalIndex e) const {
  for (std::size_t b = 0; b < blocks.size(); ++b)
    if (e >= blocks[b].first_element && e < blocks[b].first_element + block_size[b]) return int(b);
  return -1;
}

MeshHeader read_mesh_header(const Comm& comm, const std::string& path) {
  std::vector<long long> sizes;
  Mesh mesh = read_and_broadcast_mesh(comm, [&] { return read_header(path, sizes); });
  long long n = static_cast<long long>(sizes.size());
  Teuchos::broadcast(comm, 0, &n);
  sizes.resize(static_cast<std::size_t>(n));
  if (n > 0) Teuchos::broadcast(comm, 0, int(n), sizes.data());
  MeshHeader h;
  h.file = mesh.file;
  h.dimension = mesh.dimension;
  h.num_nodes = sizes[0];
  h.num_elements = sizes[1];
  std::size_t at = 2;
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) h.block_size.push_back(sizes[at++]);
  for (std::size_t k = 0; k < mesh.side_sets.size(); ++k) h.side_set_size.push_back(sizes[at++]);
  for (std::size_t k = 0; k < mesh.node_sets.size(); ++k) h.node_set_size.push_back(sizes[at++]);
  h.blocks = std::move(mesh.blocks);
  h.side_sets = std::move(mesh.side_sets);
  h.node_sets = std::move(mesh.node_sets);
  return h;
}

MeshSlices read_mesh_slices(const Comm& comm, const MeshHeader& h) {
  const int rank = comm.getRank(), ranks = comm.getSize();
  MeshSlices s;
  s.dimension = h.dimension;
  agree_on_errors(comm, [&] {
    const ReadOnlyFile file(h.file);
    s.node_begin = slice_begin(h.num_nodes, rank, ranks);
    read_coordinates(file, h, s, slice_begin(h.num_nodes, rank + 1, ranks) - s.node_begin);
    s.element_begin = slice_begin(h.num_elements, rank, ranks);
    read_connectivity(file, h, s, slice_begin(h.num_elements, rank + 1, ranks));
    read_side_sets(file, h, s, rank, ranks);
    read_node_sets(file, h, s, rank, ranks);
  });
  return s;
}

}  // namespace grout
