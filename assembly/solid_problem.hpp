#pragma once
// The small-strain solid on Tpetra: dof maps, the matrix graph, element assembly of the
// internal force and tangent, surface loads, prescribed displacements and element stresses.
//
// Distribution ("owner computes"): a rank owns the nodes of the partition and assembles, for
// its owned rows only, every element touching an owned node (its own elements plus a layer of
// ghost elements). No assembly communication is needed, and each row sums its element
// contributions in global element order, so the matrix and residual are the same on any number
// of ranks and from either mesh: the replicated one (partitioned here, assembly/partition.hpp)
// or one rank's part of the distributed one (assembly/mesh_part.hpp).

#include <Kokkos_Core.hpp>
#include <Teuchos_RCP.hpp>
#include <string>
#include <vector>

#include "assembly/mesh_part.hpp"
#include "assembly/partition.hpp"
#include "assembly/tpetra_types.hpp"
#include "io/input.hpp"
#include "kernels/axisymmetric_elastic.hpp"
#include "kernels/linear_elastic.hpp"
#include "kernels/total_lagrangian.hpp"

namespace grout {

/// The elements of one block that this rank assembles (its own plus ghosts).
struct LocalBlock {
  std::string name;
  Topology topology = Topology::quad4;
  int nodes_per_element = 0;
  ElasticConstants constants{};
  double poissons_ratio = 0.0;
  double density = 0.0;
  bool finite_strain = false;  ///< total-Lagrangian element with `law` (else small strain)
  /// model/plane: axisymmetric (x = r; kernels/axisymmetric_elastic.hpp)
  bool axisymmetric = false;
  HyperelasticLaw law = HyperelasticLaw::saint_venant_kirchhoff;
  Kokkos::View<int**> nodes;          ///< [element][a] column-map node index
  Kokkos::View<GlobalIndex*> global;  ///< global element index
  Kokkos::View<bool*> owned;          ///< element belongs to this rank's partition
};

/// A loaded element side whose nodes include an owned node.
struct LoadedFace {
  Topology topology = Topology::line2;
  int num_nodes = 0;
  int nodes[max_side_nodes] = {};  ///< column-map node indices
  std::size_t load = 0;            ///< index into Input::loads
};

class SolidProblem {
 public:
  /// From the replicated mesh (every rank holds all of it): partitioned here by
  /// partition_mesh, contact slave faces' elements steering the cuts.
  SolidProblem(const Mesh& mesh, const Input& input, Teuchos::RCP<const Comm> comm);
  /// From this rank's part of a mesh, partitioned already (the owners of `part`). The same
  /// global numbering (dof n*dim + c of global node n) and the same per-row sums as the
  /// replicated path; `part.local` must outlive the problem (the vectors need not).
  SolidProblem(const MeshPart& part, const Input& input, Teuchos::RCP<const Comm> comm);

  int dimension() const { return dim_; }
  const Teuchos::RCP<const Comm>& comm() const { return comm_; }
  /// Owned dofs (row, domain and range map); dof of node n, component c is n*dim + c.
  const Teuchos::RCP<const Map>& owned_map() const { return owned_map_; }
  /// Dofs of every node of the local elements, owned first (column map).
  const Teuchos::RCP<const Map>& column_map() const { return column_map_; }
  Teuchos::RCP<const Graph> graph() const { return graph_; }
  Teuchos::RCP<Matrix> create_matrix() const;
  Teuchos::RCP<Vector> create_vector() const;
  /// u on the column map (owned values plus ghosts).
  void import_to_column(const Vector& u, Vector& u_column) const;

  /// f_int(u) = ∫ Bᵀσ(u) dV (small strain) or ∫ P(F) ∇N dV (strain: finite, total
  /// Lagrangian) on the owned rows and, if K is non-null, the tangent K (on the fixed graph,
  /// fill-completed on return). Throws InputError on an element inverted in the mesh.
  /// Returns false (on this rank) if u collapses an element (det F <= 0, finite strain):
  /// the iterate is inadmissible and the caller backs off.
  /// With u_start (the displacement at the start of a time step, scheme: energy_momentum),
  /// the finite-strain blocks give f = 2 f_algo(u_start, u) − f_int(u_start) and its tangent
  /// d f/d u instead (kernels/energy_momentum.hpp); small-strain blocks are unchanged (for a
  /// linear f_int the two agree).
  bool assemble(const Vector& u, Vector& f_int, Matrix* K, const Vector* u_start = nullptr) const;
  /// True when K does not depend on u: every block is small strain (linear elasticity,
  /// K = ∫ Bᵀ C B dV). A caller may then assemble K once and pass K = nullptr afterwards;
  /// f_int is computed by the same element loop either way, so it is the same bit for bit.
  bool tangent_is_constant() const;
  /// Round-off estimate of ‖f_int‖₂ from the last assemble() with a tangent under strain:
  /// finite (sqrt of Σ_rows (ε Σ_k |K_rk u_k|)²), 0 under small strain. Collective.
  double round_off_estimate() const;

  /// Stored elastic energy Π_int(u) = ∫ W dV of the whole mesh, summed over the ranks
  /// (collective; each element counted once, by its owner): under strain: finite the
  /// hyperelastic law's W(F) at the element's quadrature points (total_lagrangian_element);
  /// under small strain ½ u_eᵀ K_e u_e = ½ ∫ ε:C:ε dV, exact for the linear element.
  double stored_energy(const Vector& u) const;

  /// Consistent nodal forces of the pressure/traction loads at time t (owned rows).
  void external_force(double t, Vector& f_ext) const;

  /// Prescribed displacement at time t of each dof of the column map (owned and ghost: every
  /// column of the solid's rows), by its local index; NaN where free.
  std::vector<double> prescribed_displacements(double t) const;

  /// Volume-averaged stress of this rank's own elements in the order of stress_names() (the
  /// Cauchy stress averaged over the deformed element under strain: finite,
  /// total_lagrangian_cauchy_stress): `[component][k]` of owned_elements()[k].
  std::vector<std::vector<double>> element_stresses(const Vector& u) const;
  /// The global elements this rank owns: blocks in mesh order, ascending within a block.
  std::vector<GlobalIndex> owned_elements() const;
  /// Output names of the stress components, in the order in which IOSS (ParaView's Exodus
  /// reader) groups them into one symmetric tensor: 2D xx yy zz xy; 3D xx yy zz xy yz zx.
  std::vector<std::string> stress_names() const;

  GlobalIndex num_global_nodes() const { return num_nodes_; }
  GlobalIndex num_global_elements() const { return num_elements_; }
  /// The element blocks this rank assembles (own elements plus a ghost layer), column-map
  /// node indices, and the reference coordinates of the column-map nodes.
  const std::vector<LocalBlock>& local_blocks() const { return blocks_; }
  Kokkos::View<const double**> column_coordinates() const { return column_coordinates_; }
  /// Global node of a column-map node.
  GlobalIndex column_node(int k) const { return column_nodes_[k]; }
  int num_owned_nodes() const { return num_owned_nodes_; }

 private:
  void build(const MeshPart& part);
  void build_maps(const MeshPart& part, const std::vector<char>& assembled);
  void build_blocks(const MeshPart& part, const std::vector<char>& assembled);
  void build_graph();
  void build_loads();
  Kokkos::View<double**> column_coordinates_;  ///< [column node][d]

  const Mesh& mesh_;  ///< the replicated mesh or this rank's part (local numbering)
  const Input& input_;
  Teuchos::RCP<const Comm> comm_;
  int dim_ = 2;
  GlobalIndex num_nodes_ = 0, num_elements_ = 0;
  /// Global node of each node of mesh_; empty for the replicated mesh (the identity).
  std::vector<GlobalIndex> node_gid_;
  std::vector<int> column_of_local_;  ///< mesh_ node -> column-map node, -1; construction only
  int num_owned_nodes_ = 0;
  std::vector<GlobalIndex> column_nodes_;  ///< column-map node -> global node
  Teuchos::RCP<const Map> owned_map_, column_map_;
  Teuchos::RCP<Import> importer_;  ///< owned -> column
  Teuchos::RCP<Graph> graph_;
  std::vector<LocalBlock> blocks_;
  std::vector<LoadedFace> faces_;
  std::vector<const DirichletInput*> dirichlet_;
  mutable double round_off2_ = 0.0;  ///< this rank's part of round_off_estimate()²
};

/// \brief Collective. One line per rank, "solid on rank r: nodes o owned + g ghost (x % of
/// N), elements o owned + g ghost (x % of E)": the nodes of its rows and columns and the
/// elements it assembles, gathered to rank 0 (the text is empty elsewhere).
std::string describe_solid_holdings(const SolidProblem& solid);

}  // namespace grout
