#pragma once
// One time step of implicit dynamics as a NonlinearProblem (docs/design.md §4, "Implicit
// dynamics"): the quasi-static MechanicsProblem F_s(u, λ; t) = f_int(u) − f_ext(t) + f_c(u, λ)
// wrapped in the effective residual and tangent of a TimeIntegrator (time_integrator.hpp):
//
//   u rows:  M a_{n+1−αm}(u) + (1 − αf) F_s(u_{n+1}, λ_{n+1}; t_{n+1}) + αf F_s(u_n, λ_n; t_n)
//            − M g = 0   (g the gravity acceleration; prescribed dofs stay eliminated),
//   λ rows:  MechanicsProblem's contact conditions at t_{n+1}, unchanged.
//
// The contact treatment (io/contact_treatment.hpp) decides what the step's contact
// force does afterwards: carried into the next step (standard), or acting on its own step only
// (stabilized: it is taken out of a_{n+1} and F_s(n), Deuflhard, Krause & Ertel, IJNME 73
// (2008) 1274), and with a velocity update (Laursen & Love, IJNME 53 (2002) 245) the energy
// that closing contacts lose is given back as a rigid velocity jump of each body (a connected
// component of the mesh, io/mesh_bodies.hpp): along the contact impulse, or along the sliding.
// The energies and momentum of the state are measured every step (EnergyBalance).

#include <array>
#include <memory>
#include <vector>

#include "io/contact_treatment.hpp"
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
  /// M on the solid's owned map (assemble_mass_matrix); v0 the initial velocity there;
  /// body_of_owned_node the body of each owned node of the solid, in its owned order
  /// (io/mesh_bodies.hpp; on a distributed mesh parallel/distributed_bodies.hpp).
  DynamicProblem(MechanicsProblem& problem, int dimension, Teuchos::RCP<const Matrix> mass,
                 std::unique_ptr<const TimeIntegrator> integrator,
                 const std::array<double, 3>& gravity, const Vector& v0, ContactTreatment contact,
                 const std::vector<int>& body_of_owned_node);
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
  const TimeIntegrator& integrator() const { return *integrator_; }

 private:
  void acceleration_of(const Vector& u, Vector& a_next) const;
  /// Full static u-row force at the last evaluation: F_s on free rows, the reaction on
  /// prescribed rows (MechanicsProblem zeroes those rows in F).
  void static_force(Vector& out) const;
  /// The velocity jump of the velocity update (docs/design.md §4) for the contact force f_c on
  /// the free dofs (0 elsewhere) that gives the bodies back `loss`; returns the energy given
  /// back. Collective.
  double give_back(const Vector& f_contact, double loss, bool sliding);
  /// Kinetic and strain energy, momentum and total of the state (u, v); collective.
  void measure_state(const Vector& u, const Vector& v);

  MechanicsProblem& problem_;
  Teuchos::RCP<const Matrix> mass_;
  std::unique_ptr<const TimeIntegrator> integrator_;
  ContactTreatment contact_ = ContactTreatment::stabilized;
  double t_ = 0.0, t_next_ = 0.0, dt_ = 0.0;
  int dim_ = 2;
  int num_owned_u_ = 0;
  std::vector<char> free_;            ///< per owned u dof, at the current step
  std::vector<char> mass_col_fixed_;  ///< per column of M: a prescribed dof
  std::vector<int> body_;             ///< per owned u dof: its body (io/mesh_bodies.hpp)
  int num_bodies_ = 0;
  Teuchos::RCP<Vector> u_, v_, a_;   ///< state at t_n (owned u map)
  Teuchos::RCP<Vector> f_static_n_;  ///< static u-row force at t_n (static_force)
  Teuchos::RCP<Vector> f_ext_n_, f_contact_n_;
  Teuchos::RCP<Vector> f_gravity_;      ///< M g
  Teuchos::RCP<Vector> f_static_last_;  ///< F_s u rows of the last residual evaluation
  Teuchos::RCP<Vector> work_, work2_;
  Teuchos::RCP<Matrix> mass_free_;  ///< M with the prescribed rows/columns eliminated
  LinearSolver* solver_ = nullptr;
  double residual_floor_ = 0.0;
  EnergyBalance balance_;
};

}  // namespace grout
