#pragma once
// The time-discrete problem of one step of implicit dynamics, wrapped around the quasi-static
// MechanicsProblem F_s(u, λ; t) = f_int(u) − f_ext(t) + f_c(u, λ) (its u rows) and its contact
// rows, with the generalised-α coefficients of TimeIntegrator (Chung & Hulbert 1993):
//
//   u rows:  M a_{n+1−αm}(u) + (1 − αf) F_s(u_{n+1}, λ_{n+1}; t_{n+1}) + αf F_s(u_n, λ_n; t_n)
//            − M g = 0,
//            a_{n+1−αm} = (1 − αm) a_{n+1}(u) + αm a_n,  a_{n+1}(u) from TimeIntegrator;
//   λ rows:  the contact conditions of MechanicsProblem at t_{n+1}, unchanged (dual-mortar
//            semi-smooth Newton: the active set is decided at the end of the step).
//
// For a linear f_int, (1 − αf) F_s(n+1) + αf F_s(n) is F_s at u_{n+1−αf} exactly.
//
// Stabilised contact (the default): the contact force of a step acts on that step only. It
// enters a_{n+1} and v_{n+1} through the step's equation, but the acceleration carried into
// the next step is a*_{n+1} = a_{n+1} + M⁻¹ f_c,n+1 (without it), and F_s(n) above excludes
// f_c,n. For the average-acceleration rule the step's energy balance is then (Δ over the step)
//   Δ(½ vᵀMv + ½ uᵀKu) = W_ext − ½ f_c,n+1·Δu = W_ext + ½ λ_{n+1}·Δg̃,
// and λ_{n+1} > 0 only where g̃_{n+1} = 0, so Δg̃ = −g̃_n ≤ 0: contact never adds energy, and
// removes ½ λ_{n+1} g̃_n at a closing step (none while a contact stays closed). A contact force
// carried into the next step (contact_treatment: standard) adds ½ λ_n Δg̃ > 0 at every
// release instead, and impacts chatter. This keeps contact forces out of the next step's
// predictor, the idea of the contact-stabilised Newmark method (Deuflhard, Krause & Ertel,
// IJNME 73 (2008) 1274). A closed contact's multiplier is then the force of its step alone:
// for the average-acceleration rule twice the mean force over the step.
//
// Velocity update (optional, with the stabilised treatment), after Laursen & Love (IJNME 53
// (2002) 245: an admissible position update followed by a velocity update along the contact
// normals that closes the step's energy balance). The closing steps' loss ½ λ g̃_n is an
// artefact of the time discretisation of an impact that lasts less than a step (an elastic
// impact loses nothing); it is given back to the bodies as a velocity jump along the step's
// contact impulse acting on each body as a whole, v_{n+1} ← v_{n+1} + s w, s > 0 the root of
//   ½ s² wᵀMw + s v_{n+1}ᵀMw = L,   L = −Σ_{j closing} e_j ≥ 0
// (ContactStepEnergy: the contact energy of the slave nodes that closed in this step). w is
// the rigid translation each body (element block) would get from the contact impulse, in the
// directions in which none of its dofs is prescribed: w = −F_b/m_b on the nodes of body b
// (F_b the resultant of f_c,n+1 on it restricted to those directions, m_b its mass). A body
// whose prescribed directions carry more than 1 % of |F_b|² gets none (a die driven along the
// impulse); one held across it only (u_z = 0 on the faces of a 3D slice) gets its in-plane
// jump, as the same body in plane strain. Measured on the cylinder in a
// ring (inputs/ring_pendulum/README.md): the jump along the impulse itself, w = −M⁻¹ f_c, puts
// the energy into vibrations of the slave body near the contact node instead of its motion.
// The impact then acts with a restitution of one, and momentum is kept (two free bodies get
// opposite impulses); contacts that stay closed are left alone (their energy term is zero
// for a fixed geometry, and of either sign on a curved, faceted one).
// Sliding (sliding_update, the default): a node that closes on an interface that had active
// nodes at the last converged step is a sliding contact moving on to the next node, not a new
// impact (ContactStepEnergy::closing_sliding). Its loss goes back along the sliding instead:
// w_b = v̄_b − (v̄_b·F̂_b) F̂_b, the part of body b's mean velocity v̄_b = P_b/m_b normal to the
// contact resultant (none without contact force), so the normal approach is not reversed and
// the body stays on the track (persistency λ ġ = 0 of a sliding contact, Laursen & Chawla,
// IJNME 40 (1997) 863; this split is Grout's own). Measured on the ring over 4 s
// (inputs/ring_pendulum/README.md): the jump along the impulse at every kink bounces the
// cylinder by up to 25 mm and pumps 22 % of m g h into its vibrations; along the sliding,
// 0.6 %. Balanced sliding (sliding_balance): also the energy of the nodes that stay closed
// (ContactStepEnergy::other, of either sign; a closed node that passes to the next master
// facet meets its kink like a closing node) goes back along the sliding, a gain taken out by
// a jump s < 0 (at most stopping the motion along w): the step's contact work is then zero,
// as for a frictionless contact in continuous time.
// Energy-momentum (TimeScheme::energy_momentum, αm = αf = ½, β = ¼, γ = ½): the solid's force
// in F_s(u_{n+1}) is f = 2 f_algo(u_n, u_{n+1}) − f_int(u_n) (MechanicsProblem::
// set_solid_step_start, kernels/energy_momentum.hpp), and F_s(u_n) carries f_int(u_n) (commit
// replaces the step's f by it), so that the u rows read
//   M (v_{n+1} − v_n)/Δt + f_algo(u_n, u_{n+1}) − ½ (f_ext,n + f_ext,n+1) + ½ f_c,n+1 − M g = 0
// with u_{n+1} − u_n = Δt/2 (v_n + v_{n+1}): the discrete energy-momentum method of Simo &
// Tarnow (ZAMP 43 (1992) 757) with Gonzalez's discrete gradient (CMAME 190 (2000) 1763). A free
// hyperelastic body keeps its energy and angular momentum exactly (the average-acceleration
// rule keeps neither under finite strain); the contact terms are those of the other schemes.
// Jacobian: the u rows of J_s scaled by (1 − αf), plus (1 − αm)/(β Δt²) M on the free dofs.
// Prescribed dofs stay eliminated (MechanicsProblem); g is the gravity acceleration.

#include <array>
#include <vector>

#include "nonlinear/linear_solver.hpp"
#include "nonlinear/mechanics_problem.hpp"
#include "nonlinear/time_integrator.hpp"

namespace grout {

/// Energies and momentum of the state (DynamicProblem::balance): totals over all ranks.
struct EnergyBalance {
  double kinetic = 0.0;        ///< ½ vᵀ M v
  double strain = 0.0;         ///< stored energy ∫ W dV (SolidProblem::stored_energy)
  double external_work = 0.0;  ///< Σ_steps ½ (f_n + f_{n+1})·Δu: loads, gravity, supports
  double contact_work = 0.0;   ///< Σ_steps ½ (f_c,n + f_c,n+1)·Δu done by the contact forces
  double total = 0.0;          ///< kinetic + strain − external_work
  std::array<double, 3> momentum = {0.0, 0.0, 0.0};  ///< Σ (M v) per axis
};

class DynamicProblem : public NonlinearProblem {
 public:
  /// M on the solid's owned map (assemble_mass_matrix); v0 the initial velocity there.
  /// stabilized_contact: contact forces act on their own step only; velocity_update: and the
  /// closing steps' loss is given back as a velocity jump (file comment).
  DynamicProblem(MechanicsProblem& problem, int dimension, Teuchos::RCP<const Matrix> mass,
                 const TimeIntegrator& integrator, const std::array<double, 3>& gravity,
                 const Vector& v0, bool stabilized_contact = true, bool velocity_update = false,
                 bool sliding_update = true, bool sliding_balance = false);
  ~DynamicProblem() override;
  DynamicProblem(const DynamicProblem&) = delete;
  DynamicProblem& operator=(const DynamicProblem&) = delete;

  MechanicsProblem& quasi_static() { return problem_; }
  Teuchos::RCP<const Map> map() const override { return problem_.map(); }
  bool residual(const Vector& x, Vector& F) override;
  bool jacobian(const Vector& x, Teuchos::RCP<Matrix>& J) override;
  int active_set_size() const override { return problem_.active_set_size(); }
  int active_set_changes() const override { return problem_.active_set_changes(); }
  double residual_floor() const override { return residual_floor_; }
  void set_newton_iterate(int k) override { problem_.set_newton_iterate(k); }
  const MultiplierRows* multiplier_rows() const override { return problem_.multiplier_rows(); }

  /// Initial acceleration from M a_0 = f_ext(0) + M g − F_s(x0) on the free dofs (a_0 = 0 on
  /// prescribed dofs), and the initial energies. Call once; `linear` (kept) solves with M.
  void start(Vector& x0, LinearSolver& linear);
  /// Set t_{n+1} = t, Δt = t − t_n, and the prescribed values into x (the predictor u_n).
  void begin_step(double t, Vector& x);
  /// Accept x (after a residual evaluation at x): u, v, a, energies and work move to n+1.
  void commit_step(const Vector& x);

  const Vector& velocity() const { return *v_; }
  const Vector& acceleration() const { return *a_; }
  const EnergyBalance& balance() const { return balance_; }
  const TimeIntegrator& integrator() const { return integrator_; }

 private:
  void acceleration_of(const Vector& u, Vector& a_next) const;
  /// Full static u-row force at the last evaluation: F_s on free rows, the reaction on
  /// prescribed rows (MechanicsProblem zeroes those rows in F).
  void static_force(Vector& out) const;
  /// The velocity jump of the velocity update (file comment) for the contact force f_c on
  /// the free dofs (0 elsewhere) that gives the bodies back `loss`; returns the energy given
  /// back. Collective.
  double give_back(const Vector& f_contact, double loss, bool sliding);
  /// Kinetic and strain energy, momentum and total of the state (u, v); collective.
  void measure_state(const Vector& u, const Vector& v);

  MechanicsProblem& problem_;
  Teuchos::RCP<const Matrix> mass_;
  TimeIntegrator integrator_;
  double t_ = 0.0, t_next_ = 0.0, dt_ = 0.0;
  int dim_ = 2;
  int num_owned_u_ = 0;
  std::vector<char> free_;  ///< per owned u dof, at the current step
  std::vector<int> body_;   ///< per owned u dof: its element block (−1: none)
  int num_bodies_ = 0;
  Teuchos::RCP<Vector> u_, v_, a_;   ///< state at t_n (owned u map)
  Teuchos::RCP<Vector> f_static_n_;  ///< static u-row force at t_n (static_force)
  Teuchos::RCP<Vector> f_ext_n_, f_contact_n_;
  Teuchos::RCP<Vector> f_gravity_;      ///< M g
  Teuchos::RCP<Vector> f_static_last_;  ///< F_s u rows of the last residual evaluation
  Teuchos::RCP<Vector> work_, work2_;
  Teuchos::RCP<Matrix> mass_free_;  ///< M with the prescribed rows/columns eliminated
  bool stabilized_contact_ = true;
  bool velocity_update_ = false;
  bool sliding_update_ = false;   ///< sliding contacts' loss given back along the sliding
  bool sliding_balance_ = false;  ///< and the energy of nodes that stay closed, either sign
  LinearSolver* solver_ = nullptr;
  double residual_floor_ = 0.0;
  EnergyBalance balance_;
};

}  // namespace grout
