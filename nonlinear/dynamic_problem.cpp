#include "nonlinear/dynamic_problem.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <algorithm>
#include <cmath>
#include <limits>

#include "nonlinear/dirichlet.hpp"
#include "nonlinear/linear_solver.hpp"

namespace grout {

namespace {

// What each ContactTreatment (io/contact_treatment.hpp) does.
bool stabilized(ContactTreatment c) {
  return c != ContactTreatment::standard;
}
bool velocity_update(ContactTreatment c) {
  return c == ContactTreatment::velocity_update_impact ||
         c == ContactTreatment::velocity_update_tangential ||
         c == ContactTreatment::velocity_update_balanced;
}
bool sliding_update(ContactTreatment c) {
  return c == ContactTreatment::velocity_update_tangential ||
         c == ContactTreatment::velocity_update_balanced;
}
bool sliding_balance(ContactTreatment c) {
  return c == ContactTreatment::velocity_update_balanced;
}

}  // namespace

DynamicProblem::DynamicProblem(MechanicsProblem& problem, int dimension,
                               Teuchos::RCP<const Matrix> mass,
                               std::unique_ptr<const TimeIntegrator> integrator,
                               const std::array<double, 3>& gravity, const Vector& v0,
                               ContactTreatment contact, const std::vector<int>& body_of_owned_node)
    : problem_(problem),
      mass_(std::move(mass)),
      integrator_(std::move(integrator)),
      contact_(contact),
      dim_(dimension) {
  const auto u_map = mass_->getRowMap();
  num_owned_u_ = int(u_map->getNodeNumElements());
  auto make = [&] { return Teuchos::rcp(new Vector(u_map)); };
  u_ = make(), v_ = make(), a_ = make();
  f_static_n_ = make(), f_ext_n_ = make(), f_contact_n_ = make(), f_gravity_ = make();
  f_static_last_ = make(), work_ = make(), work2_ = make();
  v_->assign(v0);
  Vector g(u_map);
  {
    auto gv = g.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (int i = 0; i < num_owned_u_; ++i) gv(i, 0) = gravity[u_map->getGlobalElement(i) % dim_];
  }
  mass_->apply(g, *f_gravity_);
  free_.assign(num_owned_u_, 1);
  // Bodies: the connected components of the mesh (io/mesh_bodies.hpp); owned u dof i is
  // component i % dim of owned node i / dim (the solid's owned map).
  body_.assign(num_owned_u_, -1);
  int local_bodies = 0;
  for (int i = 0; i < num_owned_u_; ++i) {
    const std::size_t node = std::size_t(i / dim_);
    if (node < body_of_owned_node.size()) body_[i] = body_of_owned_node[node];
    local_bodies = std::max(local_bodies, body_[i] + 1);
  }
  Teuchos::reduceAll(*u_map->getComm(), Teuchos::REDUCE_MAX, local_bodies,
                     Teuchos::outArg(num_bodies_));
}

DynamicProblem::~DynamicProblem() {
  problem_.set_solid_step_start(nullptr);
}

void DynamicProblem::acceleration_of(const Vector& u, Vector& a_next) const {
  integrator_->acceleration(u, *u_, *v_, *a_, dt_, a_next);
}

void DynamicProblem::static_force(Vector& out) const {
  const auto fs = f_static_last_->getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto r = problem_.reactions().getLocalViewHost(Tpetra::Access::ReadOnly);
  auto o = out.getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (int i = 0; i < num_owned_u_; ++i) o(i, 0) = free_[i] ? fs(i, 0) : r(i, 0);
}

bool DynamicProblem::residual(const Vector& x, Vector& F) {
  const bool ok = problem_.residual(x, F);
  {
    const auto Fv = F.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto fs = f_static_last_->getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (int i = 0; i < num_owned_u_; ++i) fs(i, 0) = Fv(i, 0);
  }
  // M a_{n+1−αm}(u_{n+1}).
  problem_.displacement(x, *work_);
  acceleration_of(*work_, *work2_);
  const double am = integrator_->alpha_m(), af = integrator_->alpha_f();
  work2_->update(am, *a_, 1.0 - am);
  mass_->apply(*work2_, *work_);
  {
    auto Fv = F.getLocalViewHost(Tpetra::Access::ReadWrite);
    const auto fn = f_static_n_->getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto ma = work_->getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto fg = f_gravity_->getLocalViewHost(Tpetra::Access::ReadOnly);
    for (int i = 0; i < num_owned_u_; ++i)
      if (free_[i]) Fv(i, 0) = (1.0 - af) * Fv(i, 0) + af * fn(i, 0) + ma(i, 0) - fg(i, 0);
  }
  const double inertia_floor = std::numeric_limits<double>::epsilon() * work_->norm2();
  residual_floor_ = std::hypot(problem_.residual_floor(), inertia_floor);
  const double norm = F.norm2();  // collective
  return ok && std::isfinite(norm);
}

bool DynamicProblem::jacobian(const Vector& x, Teuchos::RCP<Matrix>& J) {
  if (!problem_.jacobian(x, J)) return false;
  const double c = integrator_->mass_factor(dt_), scale = 1.0 - integrator_->alpha_f();
  const auto& row_map = *J->getRowMap();
  J->resumeFill();
  {
    const auto local = J->getLocalMatrixHost();
    for (int i = 0; i < num_owned_u_; ++i) {
      if (!free_[i]) continue;
      for (auto p = local.graph.row_map(i); p < local.graph.row_map(i + 1); ++p)
        local.values(p) *= scale;
    }
  }
  const auto& mass_cols = *mass_->getColMap();
  std::vector<GO> cols;
  std::vector<double> vals;
  for (int i = 0; i < num_owned_u_; ++i) {
    if (!free_[i]) continue;
    typename Matrix::local_inds_host_view_type indices;
    typename Matrix::values_host_view_type values;
    mass_->getLocalRowView(i, indices, values);
    cols.clear(), vals.clear();
    for (std::size_t k = 0; k < indices.extent(0); ++k) {
      const GO col = mass_cols.getGlobalElement(indices(k));
      if (mass_col_fixed_[std::size_t(indices(k))] || values(k) == 0.0) continue;
      cols.push_back(col);
      vals.push_back(c * values(k));
    }
    J->sumIntoGlobalValues(row_map.getGlobalElement(i), Teuchos::ArrayView<const GO>(cols),
                           Teuchos::ArrayView<const double>(vals));
  }
  J->fillComplete(J->getDomainMap(), J->getRangeMap());
  return true;
}

void DynamicProblem::begin_step(double t, Vector& x) {
  t_next_ = t;
  dt_ = t - t_;
  problem_.begin_step(t, x);
  // The mass matrix's columns are the solid's (owned and ghost dofs): all held.
  const auto& prescribed = problem_.prescribed();
  const auto& u_map = *mass_->getRowMap();
  for (int i = 0; i < num_owned_u_; ++i)
    free_[i] = prescribed.fixed(u_map.getGlobalElement(i)) ? 0 : 1;
  const auto& mass_cols = *mass_->getColMap();
  mass_col_fixed_.resize(mass_cols.getNodeNumElements());
  for (std::size_t k = 0; k < mass_col_fixed_.size(); ++k)
    mass_col_fixed_[k] = prescribed.fixed(mass_cols.getGlobalElement(LO(k))) ? 1 : 0;
}

void DynamicProblem::start(Vector& x0, LinearSolver& linear) {
  solver_ = &linear;
  begin_step(0.0, x0);
  dt_ = 0.0;
  Vector F(problem_.map());
  problem_.residual(x0, F);
  {
    const auto Fv = F.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto fs = f_static_last_->getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (int i = 0; i < num_owned_u_; ++i) fs(i, 0) = Fv(i, 0);
  }
  static_force(*f_static_n_);
  f_ext_n_->assign(problem_.external_force());
  problem_.displacement(x0, *u_);
  // M a_0 = M g − F_s(x0) on the free dofs, a_0 = 0 on the prescribed ones.
  Vector rhs(mass_->getRowMap());
  {
    auto b = rhs.getLocalViewHost(Tpetra::Access::OverwriteAll);
    const auto fg = f_gravity_->getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto fs = f_static_n_->getLocalViewHost(Tpetra::Access::ReadOnly);
    for (int i = 0; i < num_owned_u_; ++i) b(i, 0) = free_[i] ? fg(i, 0) - fs(i, 0) : 0.0;
  }
  a_->putScalar(0.0);
  mass_free_ = Teuchos::rcp(new Matrix(*mass_, Teuchos::Copy));
  {
    const auto& cols = *mass_free_->getColMap();
    std::vector<double> delta(cols.getNodeNumElements(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t k = 0; k < delta.size(); ++k)
      if (problem_.prescribed().fixed(cols.getGlobalElement(LO(k)))) delta[k] = 0.0;
    apply_dirichlet(*mass_free_, rhs, delta);
  }
  if (rhs.normInf() > 0.0) linear.solve(mass_free_, rhs, *a_);
  // f_c = F_s − f_int + f_ext, and the energies of the initial state.
  f_contact_n_->update(1.0, *f_static_n_, -1.0, problem_.internal_force(), 0.0);
  f_contact_n_->update(1.0, *f_ext_n_, 1.0);
  balance_ = EnergyBalance();
  measure_state(*u_, *v_);
  // Energy-momentum: from now on the solid's force of a step is taken from u_n
  // (EnergyMomentumScheme, generalized_alpha_family.hpp).
  if (integrator_->discrete_gradient_force()) problem_.set_solid_step_start(u_.get());
}

double DynamicProblem::give_back(const Vector& f_contact, double loss, bool sliding) {
  // Per body: the resultant F_b of f_c, the mass m_b = Σ (M 1) over its x dofs, per direction
  // whether it has a prescribed dof, and its momentum P_b = Σ (M v); summed over the ranks.
  const int stride = 3 * dim_ + 1, mass_at = dim_, held_at = dim_ + 1, p_at = 2 * dim_ + 1;
  std::vector<double> local(std::size_t(num_bodies_) * stride, 0.0), sums(local.size(), 0.0);
  work2_->putScalar(1.0);
  mass_->apply(*work2_, *work_);
  Vector momentum(mass_->getRowMap());
  mass_->apply(*v_, momentum);
  const auto& u_map = *mass_->getRowMap();
  {
    const auto f = f_contact.getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto m1 = work_->getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto mv = momentum.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (int i = 0; i < num_owned_u_; ++i) {
      if (body_[i] < 0) continue;
      double* row = &local[std::size_t(body_[i]) * stride];
      const int d = int(u_map.getGlobalElement(i) % dim_);
      row[d] += f(i, 0);
      row[p_at + d] += mv(i, 0);
      if (d == 0) row[mass_at] += m1(i, 0);
      if (!free_[i]) row[held_at + d] = 1.0;
    }
  }
  Teuchos::reduceAll(*u_map.getComm(), Teuchos::REDUCE_SUM, int(local.size()), local.data(),
                     sums.data());
  // The rigid translation w_b of each body, in the directions in which none of its dofs is
  // prescribed (its admissible translations): −F_b/m_b (impact), or the part of its mean
  // velocity P_b/m_b normal to F_b (sliding; none without a contact force on it), F_b and P_b
  // restricted to those directions. A body whose prescribed directions carry more than 1 % of
  // |F_b|² gets none (a die driven in y is not kicked sideways); a body held in z only, as the
  // plane-strain-like 3D cases with u_z = 0 on their faces, gets its in-plane jump.
  std::vector<double> w_body(std::size_t(num_bodies_) * dim_, 0.0);
  for (int b = 0; b < num_bodies_; ++b) {
    const double* row = &sums[std::size_t(b) * stride];
    double* w = &w_body[std::size_t(b) * dim_];
    if (!(row[mass_at] > 0.0)) continue;  // massless
    double f_all = 0.0, f_held = 0.0;
    double F[3] = {0.0, 0.0, 0.0}, P[3] = {0.0, 0.0, 0.0};
    for (int d = 0; d < dim_; ++d) {
      f_all += row[d] * row[d];
      if (row[held_at + d] > 0.0) {
        f_held += row[d] * row[d];
      } else {
        F[d] = row[d];
        P[d] = row[p_at + d];
      }
    }
    if (f_held > 1e-2 * f_all) continue;  // held along the impulse
    if (!sliding) {
      for (int d = 0; d < dim_; ++d) w[d] = -F[d] / row[mass_at];
      continue;
    }
    double ff = 0.0, fv = 0.0;
    for (int d = 0; d < dim_; ++d) ff += F[d] * F[d], fv += F[d] * P[d];
    if (!(ff > 0.0)) continue;
    for (int d = 0; d < dim_; ++d) w[d] = (P[d] - fv / ff * F[d]) / row[mass_at];
  }
  {
    auto w = work2_->getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (int i = 0; i < num_owned_u_; ++i)
      w(i, 0) = body_[i] < 0 ? 0.0
                             : w_body[std::size_t(body_[i]) * dim_ +
                                      std::size_t(u_map.getGlobalElement(i) % dim_)];
  }
  // ½ s² wᵀMw + s vᵀMw = loss: a s² + b s − loss = 0 with a > 0, loss > 0, so one root is
  // positive (impact: the jump along the impulse, the contact opens as after an elastic
  // impact; sliding: the tangential speed grows); the stable form of that root.
  mass_->apply(*work2_, *work_);
  const double a = 0.5 * work2_->dot(*work_), b = v_->dot(*work_);  // collective
  if (!(a > 0.0)) return 0.0;
  if (loss < 0.0) {
    // A gain to take out (balanced sliding, b = 2a): the root of a s² + b s − loss = 0
    // nearest 0, s ∈ [−b/(2a), 0); at most the energy of the motion along w, b²/(4a).
    const double taken = std::max(loss, -b * b / (4.0 * a));
    const double root = std::sqrt(std::max(b * b + 4.0 * a * taken, 0.0));
    v_->update(2.0 * taken / (root + b), *work2_, 1.0);
    return taken;
  }
  const double root = std::sqrt(b * b + 4.0 * a * loss);
  const double s = b <= 0.0 ? (root - b) / (2.0 * a) : 2.0 * loss / (root + b);
  v_->update(s, *work2_, 1.0);
  return loss;
}

void DynamicProblem::measure_state(const Vector& u, const Vector& v) {
  mass_->apply(v, *work_);
  balance_.kinetic = 0.5 * v.dot(*work_);
  balance_.strain = problem_.solid().stored_energy(u);
  balance_.total = balance_.kinetic + balance_.strain - balance_.external_work;
  double p_local[3] = {0.0, 0.0, 0.0};
  {
    const auto mv = work_->getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto& u_map = *mass_->getRowMap();
    for (int i = 0; i < num_owned_u_; ++i) p_local[u_map.getGlobalElement(i) % dim_] += mv(i, 0);
  }
  Teuchos::reduceAll(*mass_->getRowMap()->getComm(), Teuchos::REDUCE_SUM, 3, p_local,
                     balance_.momentum.data());
}

void DynamicProblem::commit_step(const Vector& x) {
  const auto u_map = mass_->getRowMap();
  Vector u_next(u_map), a_next(u_map), v_next(u_map), f_static(u_map), f_contact(u_map);
  problem_.displacement(x, u_next);
  acceleration_of(u_next, a_next);
  integrator_->velocity(*v_, *a_, a_next, dt_, v_next);
  static_force(f_static);
  const Vector& f_ext = problem_.external_force();
  f_contact.update(1.0, f_static, -1.0, problem_.internal_force(), 0.0);
  f_contact.update(1.0, f_ext, 1.0);

  // Work over the step by the trapezoidal rule, Δu = u_{n+1} − u_n:
  //   loads and gravity  ½ (f_ext,n + f_ext,n+1)·Δu + (M g)·Δu,
  //   supports           ½ (R_n + R_{n+1})·Δu on prescribed dofs, R = M a + F_s − M g,
  //   contact            −½ (f_c,n + f_c,n+1)·Δu (f_c enters F_s with a plus sign).
  Vector du(u_map), reaction(u_map), reaction_n(u_map);
  du.update(1.0, u_next, -1.0, *u_, 0.0);
  mass_->apply(a_next, reaction);
  reaction.update(1.0, f_static, -1.0, *f_gravity_, 1.0);
  mass_->apply(*a_, reaction_n);
  reaction_n.update(1.0, *f_static_n_, -1.0, *f_gravity_, 1.0);
  {
    auto r = reaction.getLocalViewHost(Tpetra::Access::ReadWrite);
    auto rn = reaction_n.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (int i = 0; i < num_owned_u_; ++i)
      if (free_[i]) r(i, 0) = rn(i, 0) = 0.0;
  }
  balance_.external_work += 0.5 * (f_ext_n_->dot(du) + f_ext.dot(du)) + f_gravity_->dot(du) +
                            0.5 * (reaction_n.dot(du) + reaction.dot(du));
  balance_.contact_work -= 0.5 * (f_contact_n_->dot(du) + f_contact.dot(du));

  u_->assign(u_next);
  v_->assign(v_next);
  a_->assign(a_next);
  f_static_n_->assign(f_static);
  if (integrator_->discrete_gradient_force()) {
    // The step's solid force was 2 f_algo − f_int(u_n); the next step starts from f_int(u_{n+1})
    // (the work terms above use the step's force: ½ (R_n + R_{n+1}) holds f_algo).
    Vector f_int(u_map);
    problem_.solid().assemble(u_next, f_int, nullptr);  // a converged state: no collapse
    f_static_n_->update(1.0, f_int, -1.0, problem_.internal_force(), 1.0);
  }
  f_ext_n_->assign(f_ext);
  f_contact_n_->assign(f_contact);
  if (stabilized(contact_) && problem_.has_contact()) {
    // The contact force acted on this step only: a*_{n+1} = a_{n+1} + M⁻¹ f_c,n+1, and
    // neither it nor f_c,n+1 is carried into the next step (docs/design.md §4).
    ContactStepEnergy step_energy;
    if (velocity_update(contact_)) step_energy = problem_.contact_step_energy();  // collective
    // Sliding contacts: their closing loss is given back along the sliding.
    const double sliding_loss = sliding_update(contact_) ? -step_energy.closing_sliding : 0.0;
    const double impact_loss = -step_energy.closing - sliding_loss;
    // Balanced: also the energy of the nodes that stay closed (of either sign; all on
    // interfaces in contact at the last step), so that the step's contact work is zero.
    const double balanced_loss = sliding_balance(contact_) ? sliding_loss - step_energy.other : 0.0;
    Vector rhs(u_map), da(u_map);
    rhs.assign(f_contact);
    {
      auto r = rhs.getLocalViewHost(Tpetra::Access::ReadWrite);
      for (int i = 0; i < num_owned_u_; ++i)
        if (!free_[i]) r(i, 0) = 0.0;
    }
    if (rhs.normInf() > 0.0) {
      solver_->solve(mass_free_, rhs, da);
      a_->update(1.0, da, 1.0);
      // A loss at round-off level (a contact that closes with no gap to close: touching
      // bodies) is no impact: no jump (it would reverse the bodies' approach).
      const double scale = balance_.kinetic + balance_.strain;
      if (impact_loss > 1e-12 * scale) balance_.contact_work += give_back(rhs, impact_loss, false);
      if (sliding_balance(contact_)) {
        if (std::abs(balanced_loss) > 1e-12 * scale)
          balance_.contact_work += give_back(rhs, balanced_loss, true);
      } else if (sliding_loss > 1e-12 * scale) {
        balance_.contact_work += give_back(rhs, sliding_loss, true);
      }
    }
    f_static_n_->update(-1.0, f_contact, 1.0);
    f_contact_n_->putScalar(0.0);
  }
  t_ = t_next_;
  measure_state(*u_, *v_);
}

}  // namespace grout
