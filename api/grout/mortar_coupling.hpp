#pragma once
// grout::MortarCoupling: Grout's mortar terms for a host code's own contact surfaces, from
// plain arrays or host Kokkos Views (docs/embedding.md is the tutorial). Installed as
// <grout/mortar_coupling.hpp>, target Grout::mortar.
//
// For a slave surface Γ¹ and a master surface Γ² (LINE2 in 2D, TRI3/QUAD4 in 3D), with the
// multiplier basis Φ_j (Popp et al. 2010, eqs. 9-10, 30; docs/design.md §2):
//   D_jk = ∫ Φ_j N¹_k dA             slave nodes j, k (CRS); diagonal for the dual basis:
//                                    D_jj = ∫ Φ_j dA per slave node (D())
//   M_jl = ∫ Φ_j (N²_l ∘ χ) dA       slave node j → master node l (CRS)
//   g̃_j  = −n_j · (Σ_k D_jk x¹_k − Σ_l M_jl x²_l)   weighted gap, > 0 open, < 0 penetrating
//   f¹_k = +Σ_j D_jk λ_j,  f²_l = −Σ_j M_jl λ_j      nodal contact forces for a multiplier λ
// Dual basis (default, Grout's driver): Φ_j biorthogonal to N¹_k, D diagonal. Standard basis:
// Φ_j = N¹_j, D_jk = ∫ N¹_j N¹_k dA a full sparse slave × slave matrix.
// n_j is the averaged unit normal at slave node j, outward from the slave body (towards the
// master). λ_j follows Grout's driver (docs/input.md): the traction on the slave is −λ_j and
// the normal pressure λ_n = n_j · λ_j is > 0 in compression; f¹, f² are the contact terms of the
// residual r = f_int − f_ext + f_c (the force on slave node j is −f¹_j). Σ f¹ + Σ f² = 0 for
// any λ (Σ_l M_jl = Σ_k D_jk pair by pair). Exact derivatives: dual basis only.
//
// Serial when no communicator is given. With one, each rank passes the faces it owns (every
// face owned by exactly one rank, nodes numbered by global ids shared by both surfaces); the
// master faces a rank needs, and the slave faces around its nodes (for the nodal normals), come
// through Grout's parallel coarse search (assembly/contact_distribution). D, M, gaps and
// forces are then this rank's contributions: the host sums them over the ranks by node id, as
// it assembles element contributions. Normals and tangents are complete on every rank.
//
// Lifetime of the results: every const reference returned (D, the CRS arrays, gaps, normals,
// tangents, row_status, the derivative triplets) refers to a std::vector owned by the coupling,
// the same object for the coupling's life; each update() overwrites its contents (per-row
// arrays keep their size; M's CRS arrays and the triplets may change size, so their data()
// pointers may move). Copy what must outlive the next update. contact_forces returns a value
// the host owns.
//
// Errors: every check of the host's data throws MortarCouplingError with the offending value
// (with a communicator, on every rank: an error one rank finds is agreed on collectively).
// The constructor also checks that the two surfaces face each other (a surface whose faces are
// ordered into its body flips its normals; for the slave, the sign of every gap): over the
// overlapping face pairs, the overlap-weighted mean of n_slave · n_master must be negative;
// with inside_points, every face's normal must point away from its point. Nothing returned is
// NaN. Rows a master covers only in part: row_status().

#include <mpi.h>
#include <Kokkos_Core.hpp>

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <vector>

// The two option enums. Installed, this header includes nothing of Grout's internals (a host
// sees only <grout/...> names); inside Grout's own build, or for a host that also uses Grout's
// internal headers (Grout::grout puts them on the include path), they come from
// kernels/mortar_types.hpp, whose definitions these repeat token for token (one type either way).
#if __has_include(<kernels/mortar_types.hpp>)
#include <kernels/mortar_types.hpp>
#else
namespace grout {
enum class MortarIntegration : int { exact = 0, collocation = 1 };
enum class MultiplierBasis : int { dual = 0, standard = 1 };
}  // namespace grout
#endif

namespace grout {

/// Wrong sizes, face types, node ids or options, non-finite coordinates, degenerate faces.
class MortarCouplingError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// MultiplierBasis (kernels/mortar_types.hpp): `dual` (D diagonal) or `standard` (Φ_j = N¹_j,
// D a full sparse matrix: read it with D_offsets/D_columns/D_values; D() throws).

struct MortarCouplingOptions {
  MortarIntegration integration = MortarIntegration::exact;  ///< or collocation
  MultiplierBasis multipliers = MultiplierBasis::dual;
  int collocation_points = 20;  ///< collocation: per slave element (2D) or per direction (3D)
  double search_factor = 0.5;   ///< face boxes grown by this fraction of the face size
  /// Also compute ∂D, ∂M, ∂g̃ / ∂coordinates (Sacado AD). Dual multipliers only: with
  /// `standard` the constructor throws MortarCouplingError.
  bool derivatives = false;
};

/// One surface (this rank's part) as plain arrays, not owned: MortarCoupling copies them.
struct SurfaceArrays {
  /// 2: LINE2 (2D); 3: TRI3; 4: QUAD4, or a mix of QUAD4 and TRI3 rows padded with −1.
  int nodes_per_face = 2;
  const int* faces = nullptr;  ///< n_faces × nodes_per_face, row indices into `coordinates`
  std::size_t n_faces = 0;
  const double* coordinates = nullptr;  ///< n_nodes × dim, row-major (any consistent length unit)
  std::size_t n_nodes = 0;
  /// Optional: a global id per coordinate row, from one numbering shared by both surfaces
  /// (required with a communicator of more than one rank). Default: slave rows 0 … n_s − 1,
  /// master rows n_s … n_s + n_m − 1.
  const long long* node_ids = nullptr;
  /// Optional: per face, dim coordinates of a point inside the body the face bounds (e.g. its
  /// element's centroid). Given, the constructor checks that every face normal points away
  /// from it and names the first face that does not (a surface oriented into its body).
  const double* inside_points = nullptr;
};

/// Helper: SurfaceArrays over std::vectors (they must outlive the constructor call).
SurfaceArrays surface_arrays(int nodes_per_face, const std::vector<int>& faces,
                             const std::vector<double>& coordinates, int dim,
                             const std::vector<long long>& node_ids = {});

/// Host-space Kokkos Views of a surface (any layout: LayoutRight, LayoutLeft, strided; a
/// View<double**> or View<const double**> on a host space converts implicitly).
using HostCoordinates = Kokkos::View<const double**, Kokkos::LayoutStride, Kokkos::HostSpace>;
using HostFaces = Kokkos::View<const int**, Kokkos::LayoutStride, Kokkos::HostSpace>;
using HostNodeIds = Kokkos::View<const long long*, Kokkos::LayoutStride, Kokkos::HostSpace>;

/// One surface as Kokkos Views: faces (n_faces × nodes_per_face, row indices into
/// coordinates, −1 pads a TRI3 row of a QUAD4 table), coordinates (n_nodes × dim), optional
/// node ids (n_nodes; an empty View: the default numbering of SurfaceArrays::node_ids).
struct SurfaceViews {
  HostFaces faces;
  HostCoordinates coordinates;
  HostNodeIds node_ids;
  /// Optional (n_faces × dim, or empty): SurfaceArrays::inside_points.
  HostCoordinates inside_points = {};
};

/// How a slave row is covered by the master surface at the last update (row_status()).
/// With the dual basis a node whose faces are only partly covered gets a D_jj that can be small
/// or negative, and a weighted gap g̃_j that can be negative where the bodies are apart: it is
/// not a penetration. Grout's driver takes D_jj ≤ 1e-8 max_k D_kk as "no master" (λ_j = 0).
enum class RowStatus : int {
  /// No master under the node: c_j ≤ 1e-8 max_k c_k (c_j = D_jj, standard: Σ_k D_jk; the
  /// driver's threshold), or no faces. Its D, M and g̃ are not to be used; set λ_j = 0.
  uncovered = 0,
  /// Some face around the node is only partly covered: c_j differs from w_j = ∫ N¹_j dA over
  /// the node's faces by more than 1e-6 w_j. D_jj (dual) may be small or negative and g̃_j < 0
  /// need not mean penetration.
  partial = 1,
  full = 2  ///< Every face around the node is covered: c_j = w_j (within 1e-6 w_j).
};

/// contact_forces: each rank's own contributions (the default), or summed over the ranks and
/// delivered to the owner of each node (the lowest rank that passes it as a row).
enum class ForceSum : int { contributions = 0, owners = 1 };

/// The slave row and the master node of one entry of M_values (MortarCoupling::M_entry).
struct MEntry {
  std::size_t row;
  long long master_node;
};
/// A derivative column as a node id and a coordinate component (MortarCoupling::dof).
struct Dof {
  long long node;
  int component;
};

/// One entry of a sparse derivative: ∂(quantity `row`) / ∂(coordinate `column`), with
/// column = node id · dim + component (node ids as in SurfaceArrays::node_ids). Each
/// (row, column) appears once.
struct DerivativeTriplet {
  int row;
  long long column;
  double value;
};

/// Nodal contact forces of one multiplier field (see the file comment for the signs).
struct ContactForces {
  std::vector<double> slave;  ///< per slave row, dim components: +Σ_j D_jk λ_j (dual: D_kk λ_k)
  std::vector<long long> master_nodes;  ///< ids of the master nodes with an M entry (ascending)
  std::vector<double> master;           ///< per master_nodes entry, dim: −Σ_j M_jl λ_j
};

class MortarCoupling {
 public:
  /// Copies the surfaces and checks them (sizes, face types, ids), then update()s with their
  /// coordinates. \pre Kokkos is initialised (e.g. Kokkos::ScopeGuard) for the object's life.
  /// comm: MPI_COMM_NULL for serial use; otherwise collective over comm (the constructor and
  /// update()).
  MortarCoupling(int dim, const SurfaceArrays& slave, const SurfaceArrays& master,
                 const MortarCouplingOptions& options = {}, MPI_Comm comm = MPI_COMM_NULL);
  /// The same from Kokkos Views (nodes_per_face = faces.extent(1), dim =
  /// coordinates.extent(1) of both surfaces; copied like the arrays).
  MortarCoupling(const SurfaceViews& slave, const SurfaceViews& master,
                 const MortarCouplingOptions& options = {}, MPI_Comm comm = MPI_COMM_NULL);
  ~MortarCoupling();
  MortarCoupling(MortarCoupling&&) noexcept;
  MortarCoupling& operator=(MortarCoupling&&) noexcept;

  /// Recomputes everything at new coordinates (same rows and layout as at construction:
  /// n_nodes × dim each). Collective with a communicator. Without one (values path), while the
  /// candidate pairs of the search and the overlapping pairs are those of the previous update,
  /// the CRS pattern of D and M is kept (offsets and columns unchanged) and only the values are
  /// summed anew, in the same order: the results equal a new coupling's.
  void update(const double* slave_coordinates, const double* master_coordinates);
  /// The same, checking the sizes.
  void update(const std::vector<double>& slave_coordinates,
              const std::vector<double>& master_coordinates);
  /// The same from host Views (n_nodes × dim each, checked; any layout: a contiguous
  /// LayoutRight View is read in place, others are gathered first).
  void update(const HostCoordinates& slave_coordinates, const HostCoordinates& master_coordinates);

  int dim() const;
  std::size_t num_slave_nodes() const;  ///< slave coordinate rows

  MultiplierBasis multipliers() const;

  /// Dual multipliers: D_jj per slave row (0 for rows whose faces overlap no master face).
  /// Standard multipliers: throws MortarCouplingError (D is not diagonal: use the CRS below).
  const std::vector<double>& D() const;
  /// D in CRS, for both bases: row j's entries are [D_offsets[j], D_offsets[j+1]), slave node
  /// ids in D_columns (ascending per row), values D_jk in D_values. Dual: the diagonal, one
  /// entry per row with an overlapping face; standard: D_jk = ∫ N¹_j N¹_k dA.
  const std::vector<std::size_t>& D_offsets() const;
  const std::vector<long long>& D_columns() const;
  const std::vector<double>& D_values() const;
  /// M in CRS: row j's entries are [M_offsets[j], M_offsets[j+1]), master node ids in
  /// M_columns (ascending per row), values in M_values.
  const std::vector<std::size_t>& M_offsets() const;
  const std::vector<long long>& M_columns() const;
  const std::vector<double>& M_values() const;
  /// g̃_j per slave row (0 where D_jj = 0).
  const std::vector<double>& weighted_gaps() const;
  /// Unit averaged nodal normals, per slave row × dim (0 for rows on no slave face).
  const std::vector<double>& normals() const;
  /// Unit tangents per slave row × (dim − 1) × dim: 2D τ = (−n_y, n_x); 3D (τ₁, τ₂, n)
  /// right-handed, τ₁ from the coordinate axis least aligned with n. Computed on the first
  /// read after an update (update itself does not pay for them).
  const std::vector<double>& tangents() const;
  /// (slave face, master face) pairs with a non-empty overlap in the last update.
  int overlapping_pairs() const;

  /// Per slave row, how the master covers it (RowStatus: uncovered, partial, full). With a
  /// communicator the status is of the node's faces on all ranks (c_j and w_j summed by id),
  /// the same on every rank that has the row.
  const std::vector<RowStatus>& row_status() const;

  /// Forces of the multiplier field lambda (per slave row × dim): f¹_k = Σ_j D_jk λ_j at the
  /// slave rows, f²_l = −Σ_j M_jl λ_j at master_nodes. ForceSum::owners (collective with a
  /// communicator): both summed over the ranks; `slave` holds the total at the rows this rank
  /// owns (0 at the others), `master_nodes` the master nodes it owns that have a force.
  ContactForces contact_forces(const double* lambda, ForceSum sum = ForceSum::contributions) const;
  ContactForces contact_forces(const std::vector<double>& lambda,
                               ForceSum sum = ForceSum::contributions) const;

  /// Index spaces. Slave rows are the host's slave coordinate rows (D, g̃, normals, the CRS
  /// rows, row_status, the rows of the D and gap derivatives); CRS columns and ContactForces::
  /// master_nodes are node ids; derivative columns are node id · dim + component; the rows of
  /// M_derivatives are positions k in M_values. These accessors translate them.
  long long slave_id(std::size_t row) const;  ///< node id of a slave row
  long long slave_row(long long id) const;    ///< slave row of a node id, −1 if none
  /// Slave row and master node id of M_values[k]. M's pattern (and so k) belongs to one update.
  MEntry M_entry(std::size_t k) const;
  Dof dof(long long column) const;  ///< a derivative column as (node id, component)

  /// Exact derivatives (options.derivatives): rows are slave rows for D and the gaps, and
  /// positions in M_values for M. Throw MortarCouplingError if derivatives were not requested.
  const std::vector<DerivativeTriplet>& D_derivatives() const;
  const std::vector<DerivativeTriplet>& M_derivatives() const;
  const std::vector<DerivativeTriplet>& gap_derivatives() const;

  struct Impl;

 private:
  void check_orientation() const;
  std::unique_ptr<Impl> impl_;
};

}  // namespace grout
