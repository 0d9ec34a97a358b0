#pragma once
// The mesh as plain data, as read from an Exodus II file (replicated on every rank).

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "kernels/topology.hpp"

namespace grout {

using GlobalIndex = long long;

struct ElementBlock {
  std::string name;  ///< Exodus name, or "id_<n>" when the file has none
  int id = 0;        ///< Exodus block id
  Topology topology = Topology::quad4;
  int nodes_per_element = 0;
  GlobalIndex first_element = 0;          ///< global 0-based index of the block's first element
  std::vector<GlobalIndex> connectivity;  ///< 0-based node indices, element-major
  GlobalIndex num_elements() const {
    return nodes_per_element ? GlobalIndex(connectivity.size()) / nodes_per_element : 0;
  }
  bool contains(GlobalIndex element) const {
    return element >= first_element && element < first_element + num_elements();
  }
  /// True if `key` refers to this block: its Exodus name or "id_<n>".
  bool named(std::string_view key) const;
};

struct SideSet {
  std::string name;
  int id = 0;
  std::vector<GlobalIndex> elements;  ///< 0-based global element indices
  std::vector<int> sides;             ///< Exodus side numbers (1-based), same length
};

struct NodeSet {
  std::string name;
  int id = 0;
  std::vector<GlobalIndex> nodes;  ///< 0-based node indices
};

struct Mesh {
  std::string file;  ///< where it was read from (for error messages)
  int dimension = 2;
  std::vector<double> coordinates;  ///< node-major: x0 y0 [z0] x1 y1 ...
  std::vector<ElementBlock> blocks;
  std::vector<SideSet> side_sets;
  std::vector<NodeSet> node_sets;

  GlobalIndex num_nodes() const { return GlobalIndex(coordinates.size()) / dimension; }
  GlobalIndex num_elements() const {
    GlobalIndex n = 0;
    for (const auto& b : blocks) n += b.num_elements();
    return n;
  }
  /// Look-up by Exodus name or by "id_<n>"; nullptr when absent.
  const ElementBlock* find_block(std::string_view name) const;
  const SideSet* find_side_set(std::string_view name) const;
  /// A node set `name` that the mesh lacks resolves to `name`_nodes when that exists
  /// (grout_mesh's naming since 2026-11-24), so inputs written for older meshes still run.
  const NodeSet* find_node_set(std::string_view name) const;
  /// The block holding global element `element`; nullptr if out of range.
  const ElementBlock* block_of(GlobalIndex element) const;
};

/// \brief Checks what every solve relies on; throws InputError naming the mesh file and the
/// entity: ids and names unique among blocks, among side sets and among node sets; no node
/// twice in a node set and no (element, side) twice in a side set; every element with
/// finite coordinates and det J > 0 at each point of its quadrature rule (not inverted,
/// not degenerate).
void check_mesh(const Mesh& mesh);

/// \brief check_mesh's test of one element of `topology`: its coordinates `X` (node-major,
/// `dimension` each) finite and at most 1e100 in magnitude, det J > 0 at each point of the
/// stiffness and mass quadrature rules (degenerate when |det J| <= 1e-10 h^dim, h its longest
/// extent). `nodes`: its 0-based global node indices, for the message; `where()`: the
/// message's prefix naming the mesh and the element. Throws InputError.
void check_element_geometry(Topology topology, int dimension, const double* X,
                            const GlobalIndex* nodes, const std::function<std::string()>& where);

}  // namespace grout
