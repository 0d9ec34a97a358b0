#pragma once
// Exodus II input and output (C API of Exodus 6.02, see docs/design.md, "Toolchain notes").
//
// read_exodus      mesh file -> plain-data Mesh (coordinates, blocks, side sets, node sets)
// ExodusWriter     mesh once, then one flushed time step per write_step() call
// write_exodus_mesh  mesh only (for the mesh generator)
// read_exodus_results / read_*_variable  small results reader (tests, scripts)
//
// All failures of the file or its content throw grout::InputError naming the path.

#include <string>
#include <vector>

#include "io/mesh.hpp"

namespace grout {

/// \brief Read an Exodus II mesh: QUAD4/TRI3 blocks in 2D, HEX8/TET4 blocks in 3D.
/// Element types are matched case-insensitively ("QUAD", "QUAD4", "TRI", "TRI3",
/// "TRIANGLE", "HEX", "HEX8", "TET", "TET4", "TETRA", "TETRA4"). Unnamed blocks and sets
/// get the name "id_<n>". Side-set elements become 0-based global element indices.
/// \throw InputError naming the path and the problem.
Mesh read_exodus(const std::string& path);

/// Write the mesh alone (no results), overwriting an existing file.
void write_exodus_mesh(const std::string& path, const Mesh& mesh);

/// Where a results file comes from: the Exodus QA record (code name, version, and the date
/// mm/dd/yy and time hh:mm:ss (UTC) of writing) and the info records (free text lines; longer
/// than 80 characters are continued on the next record).
struct ExodusProvenance {
  std::string code;  ///< empty: no QA record
  std::string version;
  std::vector<std::string> info;
};

/// \brief What makes a mesh one file of a file-per-rank set (Nemesis I, as SEACAS's decomp
/// writes it): the piece's place in the whole mesh. Indices are 0-based; local nodes and
/// elements are those of the piece's Mesh (elements in block order).
struct ExodusPiece {
  int processor = 0;       ///< the rank that wrote this file
  int num_processors = 1;  ///< files in the set
  GlobalIndex num_global_nodes = 0, num_global_elements = 0;
  std::vector<GlobalIndex> node_ids;     ///< global node of each local node (node id map)
  std::vector<GlobalIndex> element_ids;  ///< global element of each local element
  /// Whole-mesh counts per block, node set and side set (in the piece's order).
  std::vector<GlobalIndex> global_block_sizes, global_node_set_sizes, global_side_set_sizes;
  std::vector<char> border_node;     ///< per local node: also in another processor's file
  std::vector<char> border_element;  ///< per local element: uses a border node
  struct NodeCommMap {
    int processor = 0;               ///< the neighbour
    std::vector<GlobalIndex> nodes;  ///< local nodes also in the neighbour's file
  };
  std::vector<NodeCommMap> node_maps;
};

/// \brief The mesh of a file without its arrays: what ExodusWriter defines before any
/// coordinate, connectivity or set entry is written. `blocks` (names, ids, topologies, nodes
/// per element, first elements) and the sets (names, ids) carry no entries; their sizes are
/// `block_sizes`, `side_set_sizes`, `node_set_sizes`. A writer made from an outline takes the
/// arrays one at a time (put_coordinates, put_connectivity, put_side_set, put_node_set), as
/// rank 0 receives them from the ranks of a distributed mesh.
struct MeshOutline {
  std::string file;
  int dimension = 2;
  GlobalIndex num_nodes = 0;
  std::vector<ElementBlock> blocks;
  std::vector<GlobalIndex> block_sizes;
  std::vector<SideSet> side_sets;
  std::vector<GlobalIndex> side_set_sizes;
  std::vector<NodeSet> node_sets;
  std::vector<GlobalIndex> node_set_sizes;
  GlobalIndex num_elements() const;
};

/// The outline of `mesh` (names, ids and sizes; no arrays copied).
MeshOutline mesh_outline(const Mesh& mesh);

/// \brief Writes a results file: the mesh at construction, then one time step per call
/// of write_step() (or begin_step(), put_nodal() and put_element() once per variable,
/// put_globals(), end_step()), flushed to disk at the end of each step so that a later
/// failure loses nothing. Nodal variables named "displ_x", "displ_y"[, "displ_z"] are what
/// ParaView applies as the deformation. With a piece, the file is one of a file-per-rank set:
/// it also holds the node and element id maps (global ids, 1-based) and the Nemesis I global
/// and load-balance data. Move-only; the destructor closes the file.
class ExodusWriter {
 public:
  ExodusWriter(const std::string& path, const Mesh& mesh, std::vector<std::string> nodal_vars,
               std::vector<std::string> element_vars, std::vector<std::string> global_vars,
               const ExodusProvenance& provenance = {}, const ExodusPiece* piece = nullptr);
  ~ExodusWriter();
  /// The file defined from `outline`; its coordinates, connectivity and set entries follow
  /// through the put_* calls below, each once, before the first step.
  ExodusWriter(const std::string& path, const MeshOutline& outline,
               std::vector<std::string> nodal_vars, std::vector<std::string> element_vars,
               std::vector<std::string> global_vars, const ExodusProvenance& provenance = {});
  ExodusWriter(ExodusWriter&& other) noexcept;
  ExodusWriter& operator=(ExodusWriter&& other) noexcept;
  ExodusWriter(const ExodusWriter&) = delete;
  ExodusWriter& operator=(const ExodusWriter&) = delete;

  /// \brief Append time step number num_steps()+1.
  /// \pre nodal[v].size() == num_nodes for each nodal variable v (same order as given to
  ///      the constructor); element[v].size() == num_elements (global element order, blocks
  ///      in mesh order); globals.size() == number of global variables.
  void write_step(double time, const std::vector<std::vector<double>>& nodal,
                  const std::vector<std::vector<double>>& element,
                  const std::vector<double>& globals);

  /// Step num_steps()+1 at `time`; then every variable once, then end_step().
  void begin_step(double time);
  /// Nodal variable `v` (0-based, constructor order): one value per node.
  void put_nodal(std::size_t v, const std::vector<double>& values);
  /// Element variable `v`: one value per element (blocks in mesh order).
  void put_element(std::size_t v, const std::vector<double>& values);
  void put_globals(const std::vector<double>& values);
  /// Flushes the step to disk and counts it.
  void end_step();

  /// Coordinate `component` (0 x, 1 y, 2 z) of every node.
  void put_coordinates(int component, const std::vector<double>& values);
  /// Block `b`'s connectivity: 0-based nodes, element-major, block_sizes[b] elements.
  void put_connectivity(std::size_t b, const std::vector<GlobalIndex>& nodes);
  /// Side set `s`'s entries: 0-based elements and 1-based Exodus sides, in the set's order.
  void put_side_set(std::size_t s, const std::vector<GlobalIndex>& elements,
                    const std::vector<int>& sides);
  /// Node set `s`'s entries: 0-based nodes, in the set's order.
  void put_node_set(std::size_t s, const std::vector<GlobalIndex>& nodes);

  int num_steps() const { return num_steps_; }
  const std::string& path() const { return path_; }

 private:
  struct BlockSlice {
    long long id;
    GlobalIndex first_element;
    GlobalIndex num_elements;
    int nodes_per_element;
    std::string name;
  };
  struct SetSlot {
    long long id;
    std::string name;
    GlobalIndex size;
  };
  void keep_outline(const MeshOutline& outline);
  void close() noexcept;
  void check_step(int status, const std::string& what) const;

  std::string path_;
  int exoid_ = -1;
  GlobalIndex num_nodes_ = 0;
  GlobalIndex num_elements_ = 0;
  std::vector<BlockSlice> blocks_;
  std::vector<SetSlot> side_sets_, node_sets_;  ///< for the put_* calls
  std::size_t num_nodal_ = 0, num_element_ = 0, num_global_ = 0;
  int num_steps_ = 0;
  int step_ = 0;  ///< the step being written (begin_step)
};

/// What a results file holds: the time values and the variable names.
struct ExodusResults {
  std::vector<double> times;  ///< one per step; step s (1-based) is times[s-1]
  std::vector<std::string> nodal_names, element_names, global_names;
  int num_steps() const { return int(times.size()); }
};

/// \throw InputError when the file cannot be opened.
ExodusResults read_exodus_results(const std::string& path);

/// \brief Values of nodal variable `name` at time step `step` (1-based), one per node.
/// \throw InputError when the file, the variable or the step does not exist.
std::vector<double> read_nodal_variable(const std::string& path, const std::string& name, int step);

/// Element variable over all elements (blocks in file order), at step `step` (1-based).
std::vector<double> read_element_variable(const std::string& path, const std::string& name,
                                          int step);

/// All global variables at step `step` (1-based), in the order of global_names.
std::vector<double> read_global_variables(const std::string& path, int step);

}  // namespace grout
