#pragma once
// The quasi-static mechanics problem F(u, λ) = 0: the small-strain solid plus the contact
// interfaces of the input, with slave multipliers λ as extra unknowns (docs/design.md §2).
//
// Unknowns: u (node * dim + c, the solid's dofs) then, per interface, λ_j ∈ R^dim for each
// slave node j. Residual rows:
//   u rows:   f_int(u) − f_ext(t) + f_c,   f_c = Σ_j D_jj λ_j on slave node j,
//                                          −Σ_j M_jl λ_j on master node l;
//   λ rows:   frictionless: C_n = λ_n − max(0, λ_n − ĉ g_j) (active: ĉ g_j, inactive: λ_n),
//             with g_j = g̃_j / D_jj the nodal gap, plus τ_j·λ_j = 0;
//             frictional: the same normal row, and Coulomb's NCP on λ_τ with the weighted
//             slip increment since the last converged step (stick: no slip; slip:
//             λ_τ = μ (λ_n − ĉ g) ξ/|ξ|, ξ = λ_τ + c_t ū);
//             tied: ĉ (D_jj u¹_j − Σ_l M_jl u²_l) / D_jj = 0 with D, M of the reference
//             configuration.
// ĉ = E/h (harmonic mean of the two bodies' Young's moduli over the mean slave face size)
// unless the input sets c_n; the solution does not depend on it. Prescribed dofs keep their
// values: F = 0 there and their rows/columns of J are eliminated.
//
// Distributed contact: a rank owns the multipliers of the slave nodes it owns and evaluates
// only the slave faces around them, so that D_jj, M_jl and the frames of its slave nodes are
// complete; a parallel coarse search (assembly/contact_distribution.hpp) brings it the master
// faces those can touch. The master-row terms −M_jl λ_j and their Jacobian triplets go to the
// rows' owners, and the active-set counts and the round-off floor are summed over the ranks.
// Pair sums run in face-id order and every contact term carries its slave node, so that the
// owner adds the terms of a row in one order (by interface, slave node, emission): D, M, the
// frames, F and J are then bitwise the same on any number of ranks.

#include <mpi.h>

#include <memory>
#include <vector>

#include "assembly/solid_problem.hpp"
#include "nonlinear/contact_interface.hpp"
#include "nonlinear/free_rotation_limit.hpp"
#include "nonlinear/nonlinear_problem.hpp"
#include "nonlinear/prescribed_values.hpp"

namespace grout {

/// Nodal contact results of the last residual evaluation at the slave nodes this rank owns
/// (each slave node is reported by the owner of its displacement dofs), one entry per node.
struct ContactFields {
  std::vector<GlobalIndex> nodes;         ///< global node of each entry
  std::vector<double> pressure;           ///< λ_n = n·λ, > 0 in compression
  std::vector<double> gap;                ///< g̃_j / D_jj
  std::vector<double> status;             ///< 0 open, 1 stick (tied), 2 slip (frictionless active)
  std::vector<std::vector<double>> lm;    ///< λ components [d][entry]
  std::vector<std::vector<double>> slip;  ///< accumulated weighted slip Σ ū τ (frictional)
  int active_nodes = 0;                   ///< over all ranks
};

/// The energy the contact forces of the last residual evaluation put into the bodies over the
/// step from the last converged state (commit_step) to that evaluation (MechanicsProblem::
/// contact_step_energy): per slave node j, e_j = −½ λ_j·(D_jj Δx_j − Σ_l M_jl Δx_l) with the
/// evaluation's D, M (Σ_j e_j = −½ f_c·Δu, the contact term of a step's energy balance under
/// the stabilised dynamics of DynamicProblem), summed over the nodes that close in the step
/// (active now, not at the last converged state) and over the others. closing_sliding: the
/// part of `closing` on interfaces that had active slave nodes at the last converged state
/// (the contact moves on to new slave nodes, as when a body slides over a curved, faceted
/// surface), the rest is new impacts.
struct ContactStepEnergy {
  double closing = 0.0;
  double other = 0.0;
  double closing_sliding = 0.0;
};

class MechanicsProblem : public NonlinearProblem {
 public:
  /// `mesh`: the replicated mesh, or this rank's part of the distributed mesh (the solid's
  /// `part.local`) with `part` its global numbers and bodies (assembly/contact_mesh.hpp).
  /// Collective.
  MechanicsProblem(const SolidProblem& solid, const Mesh& mesh, const Input& input,
                   const ContactMeshPart* part = nullptr);
  ~MechanicsProblem() override;

  Teuchos::RCP<const Map> map() const override { return map_; }
  bool residual(const Vector& x, Vector& F) override;
  bool jacobian(const Vector& x, Teuchos::RCP<Matrix>& J) override;
  int active_set_size() const override { return active_size_; }
  int active_set_changes() const override { return active_changes_; }
  /// Round-off estimate of ‖F‖₂: ε ‖f_int‖₂ for the force rows and ε · max(ĉ, ĉ_t) · |X_j| for
  /// each multiplier row of an active or tied slave node j (ĉ times a gap or slip computed from
  /// coordinates of size |X_j|, known to ε|X_j|; X the reference coordinates, so that a wild
  /// iterate cannot raise the estimate), combined in quadrature; ε = 2.2e-16. Inactive rows
  /// (λ = 0) are exact.
  double residual_floor() const override { return residual_floor_; }
  /// The Newton iterate of the step that the next residual() evaluates (0: the initial guess,
  /// k: after k updates, line-search trials included): the active-set start rules depend on
  /// it (ActiveSetPolicy). begin_step() resets it to 0.
  void set_newton_iterate(int k) override { iterate_ = k; }
  /// The owned multiplier rows' kinds at the last residual() (every interface's), or nullptr
  /// without contact.
  const MultiplierRows* multiplier_rows() const override {
    return interfaces_.empty() ? nullptr : &rows_;
  }
  /// A free rigid rotation of a frictionless pair's slave body slides its contact nodes by at
  /// most a tenth of the mean slave face size per step (nonlinear/free_rotation_limit.hpp).
  void limit_step(const Vector& x, Vector& step) override;
  /// The largest slide of the last limit_step over the mean slave face size (0: none).
  double last_rotation_slide() const { return last_rotation_slide_; }

  /// Set the load and prescribed displacements of time t, and put the prescribed values
  /// into x (the initial guess of the step).
  void begin_step(double t, Vector& x);
  /// Accept the state of the last residual evaluation as converged: slip increments are
  /// measured from it from now on (path dependence of friction).
  void commit_step();
  /// Evaluate the solid's force over a time step from u_n (SolidProblem::assemble with
  /// u_start: the energy-momentum scheme of DynamicProblem), or f_int(u) again (nullptr).
  /// u_n (on the solid's owned map) must outlive its use.
  void set_solid_step_start(const Vector* u_n) { solid_step_start_ = u_n; }
  /// The displacement part of x, on the solid's owned map.
  void displacement(const Vector& x, Vector& u) const;
  /// f_int − f_ext + f_c on the prescribed dofs at the last residual evaluation, 0 elsewhere.
  const Vector& reactions() const { return *reaction_; }
  /// The solid (dof maps, element assembly, stored energy).
  const SolidProblem& solid() const { return solid_; }
  /// f_int and f_ext (owned rows) at the last residual evaluation / begin_step (with
  /// set_solid_step_start: the solid's step force 2 f_algo − f_int(u_n) in place of f_int).
  const Vector& internal_force() const { return *f_int_; }
  const Vector& external_force() const { return *f_ext_; }
  /// Prescribed values at the current step of the displacement dofs this rank reaches (owned,
  /// ghost, and the contact nodes of the last residual evaluation and Jacobian columns beyond
  /// the ghost layer; NaN where free).
  const PrescribedValues& prescribed() const { return *prescribed_; }
  /// Global displacement dofs (the u part of the map: GIDs 0 .. num_u − 1, owned first locally).
  GO num_displacement_dofs() const { return num_u_; }
  /// Contact results at the last residual evaluation at this rank's slave nodes (empty
  /// without contact); active_nodes is summed over the ranks. Collective.
  ContactFields contact_fields() const;
  bool has_contact() const { return !interfaces_.empty(); }
  /// ContactStepEnergy of the last residual evaluation, summed over the ranks. Collective.
  ContactStepEnergy contact_step_energy() const;
  /// (λ dof, slave displacement dof) pairs of every interface, all ranks' pairs in λ order,
  /// for the condensed solve (SystemLayout::pairing, system_layout.hpp). Collective.
  std::vector<std::pair<GO, GO>> multiplier_pairing() const;
  /// Collective: on rank 0 one line per interface and rank, what the rank holds of it
  /// (ContactInterface::Holdings); empty on the other ranks and without contact.
  std::string describe_contact_holdings() const;
  /// Collective: on rank 0 one line per rank, the prescribed values it holds (PrescribedValues:
  /// its solid's column map, and the contact nodes beyond it the run reached so far); empty on
  /// the other ranks.
  std::string describe_prescribed_holdings() const;

 private:
  void report_fixed_nodes(int count, const ContactRowSums& local) const;

  const SolidProblem& solid_;
  const Input& input_;
  int dim_ = 2;
  GO num_u_ = 0;  ///< global displacement dofs
  int num_owned_u_ = 0;
  Teuchos::RCP<const Map> map_;
  std::vector<std::unique_ptr<ContactInterface>> interfaces_;
  std::unique_ptr<FreeRotationLimit> rotation_limit_;  ///< null: no body to limit
  double last_rotation_slide_ = 0.0;
  MPI_Comm raw_comm_ = MPI_COMM_SELF;
  /// Displacement dofs of the nodes of this rank's slave faces and owned master faces.
  Teuchos::RCP<const Map> base_map_;
  Teuchos::RCP<Import> base_import_;
  Teuchos::RCP<Vector> x_last_;  ///< x of the last residual evaluation
  Teuchos::RCP<Vector> x_old_;   ///< x of the last converged step (slip increments)
  ContactTerms terms_;           ///< contact terms of the last residual evaluation
  MultiplierRows rows_;          ///< multiplier row kinds of the last residual evaluation
  Teuchos::RCP<Vector> u_, f_int_, f_ext_, reaction_;
  Teuchos::RCP<Matrix> K_solid_;
  const Vector* solid_step_start_ = nullptr;  ///< set_solid_step_start
  bool K_solid_constant_ = false;  ///< K_solid_ assembled and independent of u (small strain)
  std::unique_ptr<PrescribedValues> prescribed_;  ///< of the dofs this rank reaches
  std::vector<char> owned_fixed_;                 ///< per owned u dof: prescribed
  int active_size_ = 0, active_changes_ = 0;
  double residual_floor_ = 0.0;
  int iterate_ = 0;  ///< the Newton iterate of the next residual evaluation (newton_phase)
};

}  // namespace grout
