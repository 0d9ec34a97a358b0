#pragma once
// One contact interface of the quasi-static or dynamic problem (docs/design.md §2): its
// surfaces and their parallel search, its multipliers λ_j (one per owned slave node), its
// mortar geometry (D, M, frames), its state (active set, slip history, energy) and its rows of
// F and J. The Newton problem (MechanicsProblem) only lays out the unknowns and sums the
// interfaces; the contact law at a node is the kernel's, the active-set start rules are
// ActiveSetPolicy's, and the exchange of terms between ranks is ContactTerms'.
//
// Rows of one owned slave node j (multiplier rows lambda_gid(q, 0 .. dim−1)):
//   forces:      D_jj λ_j on slave node j, −M_jl λ_j on master node l;
//   frictionless: C_n = ĉ g_j (active) or λ_j = 0 (open), and τ_k·λ_j = 0;
//   frictional:  the same normal row, and Coulomb's NCP on λ_τ with the weighted slip
//                increment since the last converged step (assembly/weighted_slip.hpp);
//   tied:        ĉ (D u¹_j − Σ_l M_jl u²_l) / D = 0 with D, M of the reference configuration.
// Evaluation runs in stages, each a collective of all interfaces at once, so that no stage
// makes MPI calls in the middle of a node loop: update_geometry (parallel search and
// integration), then the pairing tolerance (max D over the ranks), then the closure counts of
// the active-set policy (summed over the ranks), then write_rows (local).

#include <mpi.h>

#include <array>
#include <unordered_map>
#include <vector>

#include "assembly/contact_mesh.hpp"
#include "assembly/contact_mortar.hpp"
#include "assembly/contact_terms.hpp"
#include "assembly/weighted_slip.hpp"
#include "io/input.hpp"
#include "io/mesh.hpp"
#include "kernels/contact_law.hpp"
#include "nonlinear/active_set_policy.hpp"
#include "nonlinear/multiplier_rows.hpp"
#include "nonlinear/prescribed_values.hpp"

namespace grout {

/// Counts and round-off of one evaluation (summed over interfaces and ranks by the caller).
struct ContactRowSums {
  double active = 0.0;       ///< nodes not open
  double changes = 0.0;      ///< nodes whose status changed, plus held-back nodes
  double floor2 = 0.0;       ///< Σ of the squared round-off of the multiplier rows
  double newly_fixed = 0.0;  ///< nodes whose status the cycle rule fixed at this evaluation
  /// Of those, the one whose fixed state violates the contact conditions most (max).
  struct FixedNode {
    double violation = -1.0;  ///< |λ_n − ĉ g| where the law left its fixed state
    double other = 0.0;       ///< ... and where it left the other state
    GlobalIndex node = -1;
    bool closed = false;  ///< fixed closed
  } fixed;
  double lambda_n_max = 0.0;  ///< the largest λ_n (max)
};

class ContactInterface {
 public:
  /// The interface `index` of the input's contact list: this rank's part of the surfaces
  /// (slave faces around the slave nodes `owns` says it owns), multipliers numbered from
  /// `lambda_offset` by the sorted slave nodes of the side set, ĉ = E/h unless c_n is set.
  /// Collective (a slave side set may not share a node with its master side).
  /// `mesh`: the replicated mesh or this rank's part of the distributed one.
  ContactInterface(const ContactMesh& mesh, const Input& input, const ContactInput& contact,
                   int index, GO lambda_offset, const std::function<bool(GlobalIndex)>& owns,
                   const Teuchos::RCP<const Teuchos::Comm<int>>& comm);

  const ContactInput& input() const { return input_; }
  /// Global multipliers of the interface (dim per slave node of the side set).
  GO num_multipliers() const { return num_multipliers_; }
  /// The multiplier GIDs this rank owns.
  void append_owned_multipliers(std::vector<GO>& gids) const;
  /// The displacement dofs of the nodes of this rank's slave faces and owned master faces.
  void append_base_dofs(std::vector<GO>& dofs) const;
  /// The displacement dofs of every node of the local surface (slave faces and the master
  /// faces of the last search): those the rows of write_rows read.
  void append_surface_dofs(std::vector<GO>& dofs) const;
  /// Slave nodes this rank owns (global node indices).
  std::vector<GlobalIndex> owned_slave_nodes() const;
  /// Mean size of the slave side's faces (longest edges, summed in side-set order).
  double mean_slave_face_size() const { return mean_slave_face_size_; }
  /// Called once the base map is known: D, M and normals of the reference configuration
  /// (reference geometry only; collective).
  void set_base_map(const Teuchos::RCP<const Map>& base_map);

  /// A new step: the active-set policy's per-step memory is reset; self-contact chooses its
  /// slave and master faces, and contact its covered nodes, afresh at the next update_geometry.
  void begin_step() {
    policy_.begin_step();
    choose_sides_ = true;
    coverage_set_ = false;
  }
  /// Stage 1 (collective): the master faces the slave faces can touch, and D, M, frames at
  /// the displacements u_base (and u_old_base, the last converged step) on the base map.
  void update_geometry(const Vector& u_base, const Vector& u_old_base);
  /// Stage 2: the largest D_jj of the owned slave nodes; set_pairing_tolerance(max over ranks).
  double local_max_D() const;
  void set_pairing_tolerance(double max_D) { D_tol_ = 1e-8 * max_D; }
  /// Stage 3: λ from x, the closure candidates of the active-set policy, and their local
  /// counts (summed over the ranks by the caller when the policy holds_back(phase)).
  ClosureCounts prepare_active_set(const Vector& x, NewtonPhase phase);
  bool holds_back(NewtonPhase phase) const {
    return input_.type != ContactKind::tied && policy_.holds_back(phase);
  }
  /// Stage 4 (local), at Newton iterate `iterate` of the step (its phase: newton_phase): the
  /// rows of the owned slave nodes: force terms and Jacobian entries in `terms`, multiplier
  /// rows added to F (owned rows of F's map). `global` are the summed closure counts (ignored
  /// unless holds_back(phase)); `prescribed` must hold every dof of append_surface_dofs.
  ContactRowSums write_rows(int iterate, const ClosureCounts& global,
                            const PrescribedValues& prescribed, ContactTerms& terms, Vector& F);

  /// Accept the last evaluation as the converged state (slip history, committed active set).
  void commit_step();
  /// The kinds of the owned multiplier rows at the last write_rows (unsorted).
  void append_rows(MultiplierRows& rows) const;
  /// (λ GID, slave displacement GID) of the owned multipliers.
  void append_pairing(std::vector<long long>& pairs) const;

  /// What this rank holds of the interface after the last search (`grout --timers`): its
  /// slave faces (those with an owned node, which it evaluates, and their neighbours for the
  /// nodal normals), the master faces it owns and sends to the ranks whose search region
  /// they overlap, the master faces it received (its own included), and the surface's nodes.
  struct Holdings {
    long long slave_faces = 0, evaluated_slave_faces = 0, owned_master_faces = 0,
              searched_master_faces = 0, surface_nodes = 0;
  };
  Holdings holdings() const;

  /// Per owned slave node: results of the last evaluation.
  struct NodeResult {
    GlobalIndex node;
    double pressure, gap, status;
    double lambda[3], slip[3];
    double normal[3];  ///< the unit normal n_j of the geometry in use (reference or current)
    double X[3];       ///< reference coordinates
  };
  std::vector<NodeResult> node_results() const;
  /// Per owned slave node's e_j of ContactStepEnergy: (closing part, other part), and whether
  /// the node was active at the last converged state.
  void add_step_energy(double& closing, double& other, double& committed_active) const;

 private:
  void ghost_master_faces(const Vector* u_base, const Vector* u_old_base);
  /// Self-contact (collective): the slave and master faces (surface_.self_side) from the
  /// candidate pairs of all ranks at positions x (and search_x), docs/input.md "Self-contact";
  /// afresh if choose_sides_, else keeping the sides chosen so far.
  void choose_self_sides(const std::vector<std::array<double, 3>>& x,
                         const std::vector<std::array<double, 3>>* search_x);
  GO lambda_gid(int q, int c) const { return lambda_offset_ + lambda_index_[q] * dim_ + c; }
  std::size_t position_of(GlobalIndex node) const;
  /// The owned slave nodes' mortar rows at positions in surface_.nodes (update_geometry).
  void build_stencil(const ContactMortar& m);
  LambdaRow declared_kind(const ContactLawResult& law, int r) const;
  // The pieces of write_rows per owned slave node q (contact_rows.cpp).
  void law_inputs(int q, int iterate, const PrescribedValues& prescribed, ContactLawNode& in,
                  double* slip, SparseGradient* dslip);
  void add_contact_forces(int q, ContactTerms& terms) const;
  void record_node(int q, const ContactLawNode& in, const ContactLawResult& r, const double* slip);
  SparseGradient gap_gradient(int q) const;
  void add_law_jacobian(int q, const ContactLawResult& r, const SparseGradient* dslip,
                        ContactTerms& terms) const;
  /// The Newton step's tangential hold of owned node q (frictionless, active): Jacobian only.
  void add_tangential_hold(int q, ContactTerms& terms) const;

  GlobalIndex num_global_nodes_ = 0;
  /// Reference coordinates of the nodes of this rank's slave faces and owned master faces.
  std::unordered_map<GlobalIndex, std::array<double, 3>> X_ref_;
  ContactInput input_;
  int index_ = 0;  ///< in the input's contact list
  int dim_ = 2;
  MPI_Comm raw_comm_ = MPI_COMM_SELF;
  Teuchos::RCP<const Map> base_map_;
  ContactSurface surface_;     ///< this rank's slave faces; master faces of the last search
  SurfaceFaces owned_master_;  ///< master faces this rank owns (sent in the parallel search)
  std::vector<int> owned_;     ///< indices in surface_.slave_nodes of the owned slave nodes
  GO lambda_offset_ = 0;       ///< GID of the interface's first multiplier
  GO num_multipliers_ = 0;
  std::vector<GO> lambda_index_;  ///< per owned slave node: its index among all slave nodes
  double c_hat_ = 1.0;
  double mean_slave_face_size_ = 0.0;
  double active_tolerance_ = 0.0;  ///< on λ_n − ĉ g: 1e-10 E
  double c_t_hat_ = 1.0;           ///< c_t: like ĉ unless the input sets it
  double hold_ = 0.0;              ///< Newton step's tangential hold per unit D_jj: κ E/h
  double D_tol_ = 0.0;             ///< D_jj at most this: the node has no master
  bool choose_sides_ = true;       ///< self-contact: choose the sides afresh at the next evaluation
  /// Per owned slave node: its faces covered by at least min_dual_coverage (dual_covered) at
  /// some evaluation of this step (see update_geometry); tied rows keep 1 throughout.
  std::vector<char> covered_;
  bool coverage_set_ = false;   ///< covered_ holds this step's evaluations
  GlobalIndex self_faces_ = 0;  ///< self-contact: faces of the side set
  ActiveSetPolicy policy_;
  ContactMortarOptions options_;
  bool current_geometry_ = false;  ///< normals, D, M on the current configuration
  ContactMortar reference_;        ///< D, M and normals of the reference configuration
  /// The (slave face, master face) pairs `reference_` was integrated over.
  std::vector<std::pair<GlobalIndex, GlobalIndex>> reference_pairs_;
  ContactMortar current_;  ///< D, M and normals of the last evaluation (current geometry)
  // Per node of surface_.nodes at the last evaluation: reference coordinates, displacement,
  // displacement of the last converged step; positions X + u.
  std::vector<std::array<double, 3>> X_, u_, u_old_, positions_;
  // The mortar rows of the owned slave nodes with the nodes' positions in surface_.nodes, set
  // by update_geometry: slave_pos_[q], and master terms stencil_[stencil_begin_[q] ..
  // stencil_begin_[q + 1]) in M's order (a row read without a search per term).
  struct MasterTerm {
    GlobalIndex node;      ///< master node l
    std::size_t pos;       ///< its index in surface_.nodes
    const MortarValue* M;  ///< M_jl in the ContactMortar in use
  };
  std::vector<std::size_t> slave_pos_, stencil_begin_;
  std::vector<MasterTerm> stencil_;
  /// Owned slave node q's mortar row in the ContactMortar in use, as build_stencil laid it out.
  struct SlaveRow {
    int j;                    ///< index in surface_.slave_nodes
    GlobalIndex node;         ///< the slave node
    std::size_t i;            ///< its index in surface_.nodes (positions_, X_, u_)
    const MortarValue& D;     ///< D_jj
    const SlaveFrame& frame;  ///< n_j, τ_j and their derivatives
    const MasterTerm* begin;  ///< its master terms [begin, end)
    const MasterTerm* end;
  };
  SlaveRow slave_row(int q) const;
  /// Whether owned slave node q has a master for its rows in the ContactMortar m in use: D_jj
  /// above the "no master" tolerance, and its faces covered (covered_; always for tied rows).
  bool paired(int q, const ContactMortar& m) const {
    return m.D[owned_[q]].value > D_tol_ && covered_[q];
  }
  // Per owned slave node: results of the last evaluation and the slip history.
  std::vector<double> pressure_, gap_;
  std::vector<double> iterate_gap_;  ///< g_j at the last evaluation (if gap_known_)
  std::vector<char> gap_known_;      ///< node j had a master at the last evaluation
  std::vector<char> held_back_;      ///< held open at this iterate (policy)
  std::vector<char> newly_fixed_;    ///< status fixed by the cycle rule at this evaluation
  std::vector<std::array<double, 3>> lambda_;
  std::vector<char> active_, previous_active_;
  std::vector<char> committed_active_;  ///< active at the last converged state (commit_step)
  std::vector<double> step_energy_;     ///< e_j of ContactStepEnergy at the last evaluation
  std::vector<char> closing_;           ///< active at the last evaluation, not committed
  std::vector<std::array<LambdaRow, 3>> row_kinds_;  ///< per owned node, of its rows
  // The contact law's launch: inputs and results per owned slave node (write_rows), kept
  // between residuals while their size holds.
  using LawSpace = Kokkos::DefaultExecutionSpace;
  using LawMemory = LawSpace::memory_space;
  using LawNodes = Kokkos::View<ContactLawNode*, LawMemory>;
  using LawResults = Kokkos::View<ContactLawResult*, LawMemory>;
  LawNodes law_nodes_;
  LawResults law_results_;
  std::vector<ClosureCandidate> candidates_;     ///< of prepare_active_set
  std::vector<std::array<double, 3>> weighted_;  ///< v_j = D x¹_j − Σ M x², of prepare_active_set
  std::vector<std::array<double, 3>> slip_increment_;           ///< ū_k of the step
  std::vector<std::array<double, 3>> slip_accumulated_;         ///< Σ ū_k τ_k (vector)
  std::vector<std::array<std::array<double, 3>, 2>> tangents_;  ///< τ_k
  // Current geometry, per owned slave node: D_jj and M_jl of the last converged step (the
  // objective slip's D_n, M_n) and of the last evaluation; set at the first evaluation.
  std::vector<MortarRowHistory> history_, last_rows_;
  bool history_set_ = false;
};

}  // namespace grout
