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

/// \brief Writes a results file: the mesh at construction, then one time step per call
/// of write_step(), flushed to disk immediately so that a later failure loses nothing.
/// Nodal variables named "displ_x", "displ_y"[, "displ_z"] are what ParaView applies as
/// the deformation. Move-only; the destructor closes the file.
class ExodusWriter {
 public:
  ExodusWriter(const std::string& path, const Mesh& mesh, std::vector<std::string> nodal_vars,
               std::vector<std::string> element_vars, std::vector<std::string> global_vars,
               const ExodusProvenance& provenance = {});
  ~ExodusWriter();
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

  int num_steps() const { return num_steps_; }
  const std::string& path() const { return path_; }

 private:
  struct BlockSlice {
    long long id;
    GlobalIndex first_element;
    GlobalIndex num_elements;
  };
  void close() noexcept;

  std::string path_;
  int exoid_ = -1;
  GlobalIndex num_nodes_ = 0;
  GlobalIndex num_elements_ = 0;
  std::vector<BlockSlice> blocks_;
  std::size_t num_nodal_ = 0, num_element_ = 0, num_global_ = 0;
  int num_steps_ = 0;
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
