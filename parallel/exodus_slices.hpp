#pragma once
// The distributed mesh's reading step: the Exodus header once (rank 0, broadcast), then each
// rank's contiguous slice of the nodes, of the elements (in the file's global element order,
// across blocks) and of each side and node set, with Exodus's partial reads. No rank reads or
// holds a whole-mesh array. Validation as io/exodus_reader.cpp: InputError naming the file
// and the entity, and an error on one rank ends the job (assembly/agree_on_errors.hpp).

#include <string>
#include <vector>

#include "assembly/tpetra_types.hpp"
#include "io/mesh.hpp"

namespace grout {

/// The file's header: names, ids, types and sizes of every entity, no per-entity arrays.
/// `blocks` carry no connectivity; `block_size[b]` is block b's element count and
/// `side_set_size`, `node_set_size` the sets' entry counts.
struct MeshHeader {
  std::string file;
  int dimension = 2;
  GlobalIndex num_nodes = 0, num_elements = 0;
  std::vector<ElementBlock> blocks;
  std::vector<GlobalIndex> block_size;
  std::vector<SideSet> side_sets;  ///< names and ids only
  std::vector<NodeSet> node_sets;  ///< names and ids only
  std::vector<GlobalIndex> side_set_size, node_set_size;
  /// The block holding global element `e` (0-based), or -1.
  int block_of(GlobalIndex e) const;
};

/// One rank's slices: nodes [node_begin, node_begin + n), elements [element_begin, ...),
/// and for each set the entries [set_begin[s], ...) in the file's order.
struct MeshSlices {
  int dimension = 2;
  GlobalIndex node_begin = 0;
  std::vector<double> coordinates;  ///< node-major, header.dimension per node
  GlobalIndex element_begin = 0;
  std::vector<int> element_block;                 ///< block of each slice element
  std::vector<GlobalIndex> element_nodes_offset;  ///< CRS offsets into element_nodes
  std::vector<GlobalIndex> element_nodes;         ///< 0-based global node indices
  std::vector<GlobalIndex> side_set_begin, node_set_begin;
  std::vector<std::vector<GlobalIndex>> side_set_elements;  ///< 0-based global elements
  std::vector<std::vector<int>> side_set_sides;             ///< 1-based Exodus sides
  std::vector<std::vector<GlobalIndex>> node_set_nodes;     ///< 0-based global nodes
  GlobalIndex num_nodes() const { return GlobalIndex(coordinates.size()) / dimension; }
  GlobalIndex num_elements() const { return GlobalIndex(element_block.size()); }
};

/// Collective. Rank 0 reads and checks the header (counts, block types, names and ids unique
/// as check_mesh asks), every rank gets it. Throws on every rank if rank 0 fails.
MeshHeader read_mesh_header(const Comm& comm, const std::string& path);

/// Collective. Each rank reads its slices (parallel/slices.hpp) and checks every index in
/// them against the header (node and element numbers in range, side numbers valid for the
/// element's block). Throws on every rank if any rank fails.
MeshSlices read_mesh_slices(const Comm& comm, const MeshHeader& header);

}  // namespace grout
