// The rows of one contact interface at a Newton iterate: the closure candidates of the
// active-set policy, then per owned slave node its force terms and multiplier rows
// (contact_interface.hpp).

#include <cmath>
#include <limits>

#include "kernels/contact_laws.hpp"
#include "kernels/weighted_gap.hpp"
#include "nonlinear/contact_interface.hpp"

namespace grout {

// The declared kind of row r of a node (multiplier_rows.hpp) from the law's: an identity row
// of its own component, or of another one (a held tangent: pure-λ); a frictionless tangent row
// τ_k·λ carries ∂τ_k·λ on the displacements where the frame moves with them (the current
// geometry) and λ ≠ 0.
LambdaRow ContactInterface::declared_kind(const ContactLawResult& law, int r) const {
  switch (law.kind[r]) {
    case row_identity:
      return law.component[r] == r ? LambdaRow::identity : LambdaRow::pure_lambda;
    case row_constraint:
      return LambdaRow::constraint;
    case row_tangent: {
      bool moving_frame = false;
      for (int k = 0; k < dim_ - 1; ++k)
        for (int a = 0; a < dim_; ++a)
          moving_frame = moving_frame || law.dC[r][ContactLawLayout::tangent(k, a)] != 0.0;
      return current_geometry_ && moving_frame ? LambdaRow::mixed : LambdaRow::pure_lambda;
    }
    default:
      return LambdaRow::mixed;
  }
}

ClosureCounts ContactInterface::prepare_active_set(const Vector& x, NewtonPhase phase) {
  const int dim = dim_;
  const ContactMortar& m = current_geometry_ ? current_ : reference_;
  const int n_owned = int(owned_.size());
  {
    const auto xv = x.getLocalViewHost(Tpetra::Access::ReadOnly);
    const Map& map = *x.getMap();
    for (int q = 0; q < n_owned; ++q)
      for (int d = 0; d < dim; ++d) lambda_[q][d] = xv(map.getLocalElement(lambda_gid(q, d)), 0);
  }
  if (input_.type == ContactKind::tied) return {};
  // Positions by index in surface_.nodes: current, and of the last converged step.
  const auto position = [&](std::size_t i, int d) { return positions_[i][d]; };
  const auto old_position = [&](std::size_t i, int d) { return X_[i][d] + u_old_[i][d]; };
  // g_j = g̃_j / D_jj with g̃_j = −n_j·v_j, v_j = D_jj x_j − Σ_l M_jl x_l, at the given positions
  // (owned node q; kernels/weighted_gap.hpp), v_j into v.
  const auto nodal_gap = [&](int q, const auto& at, double* v) {
    const int j = owned_[q];
    double xs[3];
    for (int a = 0; a < dim; ++a) xs[a] = at(slave_pos_[q], a);
    const MasterTerm* t = stencil_.data() + stencil_begin_[q];
    mortar_row_weighted_vector(
        dim, m.D[j].value, xs, int(stencil_begin_[q + 1] - stencil_begin_[q]),
        [&](int l) { return t[l].M->value; }, [&](int l, int a) { return at(t[l].pos, a); }, v);
    return weighted_gap_of_row(dim, m.frames[j].n, v) / m.D[j].value;
  };
  for (int q = 0; q < n_owned; ++q) {
    const int j = owned_[q];
    ClosureCandidate& node = candidates_[q];
    node = ClosureCandidate();
    node.paired = paired(q, m);  // with the step's rule for partly covered nodes
    if (!node.paired) continue;
    node.was_active = active_[q] != 0;
    double v_old[3];
    node.gap = nodal_gap(q, position, weighted_[q].data());
    // The base of the update: the last evaluation's gap; at the first update a node that
    // had no master then is measured from its last converged position.
    node.gap_old = gap_known_[q]                        ? iterate_gap_[q]
                   : phase == NewtonPhase::first_update ? nodal_gap(q, old_position, v_old)
                                                        : 0.0;
    double lambda_n = 0.0;
    for (int a = 0; a < dim; ++a) lambda_n += m.frames[j].n[a] * lambda_[q][a];
    node.closing = !node.was_active && lambda_n - c_hat_ * node.gap >= -active_tolerance_;
  }
  return count_closures(candidates_);
}

ContactRowSums ContactInterface::write_rows(int iterate, const ClosureCounts& global,
                                            const PrescribedValues& prescribed, ContactTerms& terms,
                                            Vector& F) {
  const int dim = dim_;
  const int n_owned = int(owned_.size());
  const bool tied = input_.type == ContactKind::tied;
  const bool coulomb = input_.type == ContactKind::frictional;
  ContactRowSums sums;

  // After the step's start: the late-closing nodes held back (first_update_closures.hpp),
  // measured from the last evaluation's gaps.
  std::fill(held_back_.begin(), held_back_.end(), 0);
  if (!tied) {
    held_back_ = policy_.held_back(candidates_, global, newton_phase(iterate));
    for (int q = 0; q < n_owned; ++q) {
      gap_known_[q] = candidates_[q].paired;
      iterate_gap_[q] = candidates_[q].gap;
    }
  }

  // Multiplier rows of the owned slave nodes (q: owned index): the law's inputs per node, the
  // law's launch (kernels/contact_laws.hpp: rows, status, ∂C/∂v over the local variables v),
  // then the chain rule to the global dofs through ∂v/∂x.
  ContactLawParameters law;
  law.dim = dim;
  law.kind = tied ? tied_law : coulomb ? coulomb_law : frictionless_law;
  law.c_hat = c_hat_, law.c_t_hat = c_t_hat_;
  law.mu = input_.friction_coefficient, law.active_tolerance = active_tolerance_;
  if (int(law_nodes_.extent(0)) != n_owned) {
    law_nodes_ =
        LawNodes(Kokkos::ViewAllocateWithoutInitializing("grout::contact_law_nodes"), n_owned);
    law_results_ =
        LawResults(Kokkos::ViewAllocateWithoutInitializing("grout::contact_law_results"), n_owned);
  }
  auto nodes_host = Kokkos::create_mirror_view(law_nodes_);
  std::vector<double> slip_value(n_owned * 2, 0.0);
  std::vector<std::array<SparseGradient, 2>> dslip(coulomb ? n_owned : 0);
  for (int q = 0; q < n_owned; ++q)
    law_inputs(q, iterate, prescribed, nodes_host(q), &slip_value[2 * q],
               coulomb ? dslip[q].data() : nullptr);
  Kokkos::deep_copy(law_nodes_, nodes_host);
  evaluate_contact_law(LawSpace(), law, Kokkos::View<const ContactLawNode*, LawMemory>(law_nodes_),
                       true, law_results_);
  auto results = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), law_results_);

  auto Fv = F.getLocalViewHost(Tpetra::Access::ReadWrite);
  const Map& map = *F.getMap();
  for (int q = 0; q < n_owned; ++q) {
    const ContactLawNode& in = nodes_host(q);
    const ContactLawResult& r = results(q);
    // One tag per node: its forces, rows and hold, keys unique per row.
    terms.begin_node(GO(index_) * GO(num_global_nodes_) + surface_.slave_nodes[owned_[q]]);
    add_contact_forces(q, terms);
    record_node(q, in, r, &slip_value[2 * q]);
    if (r.status != node_open) {  // round-off of rows that carry ĉ × (a gap or a slip)
      double x_max = 0.0;
      for (int a = 0; a < dim; ++a) x_max = std::max(x_max, std::abs(X_[slave_pos_[q]][a]));
      const double row =
          std::numeric_limits<double>::epsilon() * std::max(c_hat_, c_t_hat_) * x_max;
      sums.floor2 += dim * row * row;
    }
    for (int row = 0; row < dim; ++row) {  // F = C_r on the owned multiplier rows, set once
      row_kinds_[q][row] = declared_kind(r, row);
      Fv(map.getLocalElement(lambda_gid(q, row)), 0) += r.C[row];
    }
    add_law_jacobian(q, r, coulomb ? dslip[q].data() : nullptr, terms);
    if (law.kind == frictionless_law && r.status != node_open) add_tangential_hold(q, terms);
  }
  for (int q = 0; q < n_owned; ++q) {
    if (newly_fixed_[q]) {
      sums.newly_fixed += 1.0;
      const bool closed = policy_.fixed_state(q) == 1;
      if (policy_.violation(q, closed) >= sums.fixed.violation)
        sums.fixed = {policy_.violation(q, closed), policy_.violation(q, !closed),
                      surface_.slave_nodes[owned_[q]], closed};
    }
    sums.lambda_n_max = std::max(sums.lambda_n_max, pressure_[q]);
    closing_[q] = active_[q] && !committed_active_[q];
    sums.active += active_[q] != 0;
    // A held-back node is a pending change: the iterate cannot be the converged one.
    sums.changes += active_[q] != previous_active_[q] || held_back_[q];
  }
  return sums;
}

ContactInterface::SlaveRow ContactInterface::slave_row(int q) const {
  const ContactMortar& m = current_geometry_ ? current_ : reference_;
  const int j = owned_[q];
  return {j,
          surface_.slave_nodes[j],
          slave_pos_[q],
          m.D[j],
          m.frames[j],
          stencil_.data() + stencil_begin_[q],
          stencil_.data() + stencil_begin_[q + 1]};
}

// The law's inputs of owned node q (j: its index in surface_.slave_nodes): λ and the frame;
// for a paired node the held components, then the tied jump t = (D u¹_j − Σ_l M_jl u²_l) / D,
// or the gap as prepare_active_set measured it at these positions and, with Coulomb, the
// weighted slip ū_k (objective on the current geometry, assembly/weighted_slip.hpp) and its
// gradient.
void ContactInterface::law_inputs(int q, int iterate, const PrescribedValues& prescribed,
                                  ContactLawNode& in, double* slip, SparseGradient* dslip) {
  const SlaveRow sr = slave_row(q);
  const double D = sr.D.value;
  const int dim = dim_;
  in = ContactLawNode();
  for (int a = 0; a < dim; ++a) {
    in.lambda[a] = lambda_[q][a];
    in.n[a] = sr.frame.n[a];
    for (int k = 0; k < dim - 1; ++k) in.t[k][a] = sr.frame.t[k][a];
  }
  in.paired = paired(q, current_geometry_ ? current_ : reference_);
  double lambda_n = 0.0;
  for (int a = 0; a < dim; ++a) lambda_n += sr.frame.n[a] * lambda_[q][a];
  // The cycle rule (active_set_cycles.hpp) on the status the law gives the node with the start
  // rules applied: a node without a master is open, its row λ_j = 0 off by |λ_n|.
  const auto cycle_rule = [&](bool closed, double s) {
    const bool was_fixed = policy_.fixed(q);
    const int fixed = policy_.fixed_status(q, iterate, closed, s);
    newly_fixed_[q] = fixed >= 0 && !was_fixed;
    return fixed;
  };
  newly_fixed_[q] = 0;
  const bool tied = input_.type == ContactKind::tied;
  if (!in.paired) {
    if (!tied) cycle_rule(false, lambda_n);
    return;
  }
  in.held_back = held_back_[q];
  for (int a = 0; a < dim; ++a) {  // held components: prescribed slave dof, free masters' share
    in.prescribed[a] = prescribed.fixed(GO(sr.node) * dim + a);
    double free_sum = 0.0;
    for (const MasterTerm* t = sr.begin; t != sr.end; ++t)
      if (!prescribed.fixed(GO(t->node) * dim + a)) free_sum += std::abs(t->M->value);
    in.free_share[a] = free_sum / D;
  }
  if (tied) {
    double v[3];
    mortar_row_weighted_vector(
        dim, D, u_[slave_pos_[q]].data(), int(sr.end - sr.begin),
        [&](int l) { return sr.begin[l].M->value; },
        [&](int l, int a) { return u_[sr.begin[l].pos][a]; }, v);
    for (int a = 0; a < dim; ++a) in.tied[a] = v[a] / D;
    return;
  }
  in.gap = candidates_[q].gap;
  in.near = policy_.near(q, lambda_n, in.gap, newton_phase(iterate));
  const double s = lambda_n - c_hat_ * in.gap;
  const int fixed = cycle_rule(!in.held_back && (s >= -active_tolerance_ || in.near), s);
  if (fixed == 1) in.near = 1, in.held_back = 0;  // closed although s < −tol
  if (fixed == 0) in.held_back = 1;               // open although s ≥ −tol
  if (dslip) {
    // Positions by global node (the weighted slip's interface).
    const auto position = [&](GlobalIndex n, int d) { return positions_[position_of(n)][d]; };
    const auto old_position = [&](GlobalIndex n, int d) {
      const std::size_t k = position_of(n);
      return X_[k][d] + u_old_[k][d];
    };
    std::vector<MortarRowEntry> m_row;
    for (const MasterTerm* t = sr.begin; t != sr.end; ++t) m_row.emplace_back(t->node, t->M);
    const bool objective = current_geometry_ && history_[q].D > D_tol_;
    weighted_slip_increment(dim, sr.node, sr.frame, sr.D, m_row, objective ? &history_[q] : nullptr,
                            position, old_position, slip, dslip);
    for (int k = 0; k < dim - 1; ++k) in.slip[k] = slip[k];
  }
}

// Contact forces f¹_k = D_kk λ_k, f²_l = −Σ_j M_jl λ_j of owned slave node q, and their
// derivatives in λ and (through D and M) in the displacements.
void ContactInterface::add_contact_forces(int q, ContactTerms& terms) const {
  const SlaveRow sr = slave_row(q);
  const MortarValue& D = sr.D;
  const int dim = dim_;
  for (int a = 0; a < dim; ++a) {
    const GO row = sr.node * dim + a;
    terms.add_force(row, D.value * lambda_[q][a]);
    terms.add_entry(row, lambda_gid(q, a), D.value);
    for (const auto& [dof, dv] : D.gradient) terms.add_entry(row, dof, lambda_[q][a] * dv);
  }
  for (std::size_t e = stencil_begin_[q]; e < stencil_begin_[q + 1]; ++e) {
    const MasterTerm& t = stencil_[e];
    const MortarValue& M = *t.M;
    for (int a = 0; a < dim; ++a) {
      const GO row = t.node * dim + a;
      terms.add_force(row, -M.value * lambda_[q][a]);
      terms.add_entry(row, lambda_gid(q, a), -M.value);
      for (const auto& [dof, dv] : M.gradient) terms.add_entry(row, dof, -lambda_[q][a] * dv);
    }
  }
}

// What the evaluation leaves of owned node q for the output, the step's bookkeeping and the
// next iterate: its status, λ_n = n·λ, the gap, the contact work e_j and the slip increment.
void ContactInterface::record_node(int q, const ContactLawNode& in, const ContactLawResult& r,
                                   const double* slip) {
  const SlaveRow sr = slave_row(q);
  const double D = sr.D.value;
  const int dim = dim_;
  const bool tied = input_.type == ContactKind::tied;
  const auto x_at = [&](std::size_t k, int d) { return positions_[k][d]; };
  const auto x_old_at = [&](std::size_t k, int d) { return X_[k][d] + u_old_[k][d]; };
  previous_active_[q] = active_[q];
  active_[q] = char(r.status);
  pressure_[q] = gap_[q] = 0.0;
  {  // e_j = −½ λ_j·(D Δx_j − Σ_l M_jl Δx_l), Δ since the last converged state
    double dx[3], w[3];
    for (int a = 0; a < dim; ++a) dx[a] = x_at(sr.i, a) - x_old_at(sr.i, a);
    mortar_row_weighted_vector(
        dim, D, dx, int(sr.end - sr.begin), [&](int l) { return sr.begin[l].M->value; },
        [&](int l, int a) { return x_at(sr.begin[l].pos, a) - x_old_at(sr.begin[l].pos, a); }, w);
    double e = 0.0;
    for (int a = 0; a < dim; ++a) e += lambda_[q][a] * w[a];
    step_energy_[q] = -0.5 * e;
  }
  if (!in.paired) return;
  for (int a = 0; a < dim; ++a) pressure_[q] += sr.frame.n[a] * lambda_[q][a];  // λ_n = n·λ
  if (tied) return;
  gap_[q] = in.gap;
  if (r.status == node_open) slip_increment_[q] = {0.0, 0.0, 0.0};
  if (input_.type == ContactKind::frictional && r.status != node_open)
    for (int k = 0; k < dim - 1; ++k) slip_increment_[q][k] = r.held_axis[k] >= 0 ? 0.0 : slip[k];
}

// ∂g of owned node q: ∂g = (∂g̃ − g ∂D) / D, ∂g̃ = −Σ_a v_a ∂n_a − Σ_a n_a ∂v_a,
// ∂v_a = x_ja ∂D + D e_ja − Σ_l (x_la ∂M_jl + M_jl e_la), v_j and g as prepare_active_set
// measured them.
SparseGradient ContactInterface::gap_gradient(int q) const {
  const SlaveRow sr = slave_row(q);
  const double D = sr.D.value;
  const int dim = dim_;
  const double rD = 1.0 / D;
  const double* v = weighted_[q].data();
  SparseGradient dg;
  double n_dot_x = 0.0;
  for (int a = 0; a < dim; ++a) {
    n_dot_x += sr.frame.n[a] * positions_[sr.i][a];
    for (const auto& [dof, dn] : sr.frame.dn[a]) dg.emplace_back(dof, -rD * v[a] * dn);
    dg.emplace_back(sr.node * dim + a, -rD * sr.frame.n[a] * D);
  }
  for (const auto& [dof, dD] : sr.D.gradient)
    dg.emplace_back(dof, -rD * (n_dot_x + candidates_[q].gap) * dD);
  for (std::size_t e = stencil_begin_[q]; e < stencil_begin_[q + 1]; ++e) {
    const MasterTerm& t = stencil_[e];
    double n_dot_xl = 0.0;
    for (int a = 0; a < dim; ++a) {
      n_dot_xl += sr.frame.n[a] * positions_[t.pos][a];
      dg.emplace_back(t.node * dim + a, rD * sr.frame.n[a] * t.M->value);
    }
    for (const auto& [dof, dM] : t.M->gradient) dg.emplace_back(dof, rD * n_dot_xl * dM);
  }
  compress_gradient(dg);
  return dg;
}

// The Jacobian of owned node q's multiplier rows: row r, J = Σ_v ∂C_r/∂v ∂v/∂x (λ: the
// multiplier dofs; n, τ: the frame's gradients; g: gap_gradient, only where a row uses g;
// ū: the weighted slip's, dslip; t: e_j − Σ_l M_jl/D e_l).
void ContactInterface::add_law_jacobian(int q, const ContactLawResult& r,
                                        const SparseGradient* dslip, ContactTerms& terms) const {
  const SlaveRow sr = slave_row(q);
  const double D = sr.D.value;
  using L = ContactLawLayout;
  const int dim = dim_;
  bool uses_gap = false;
  for (int row = 0; row < dim; ++row) uses_gap = uses_gap || r.dC[row][L::gap()] != 0.0;
  const SparseGradient dg = uses_gap ? gap_gradient(q) : SparseGradient();
  for (int row = 0; row < dim; ++row) {
    const GO gid = lambda_gid(q, row);
    const double* dC = r.dC[row];
    SparseGradient J;
    const auto chain = [&](const SparseGradient& grad, double scale) {
      if (scale != 0.0)
        for (const auto& [dof, value] : grad) J.emplace_back(dof, scale * value);
    };
    for (int a = 0; a < dim; ++a) {
      if (dC[L::lambda(a)] != 0.0) J.emplace_back(lambda_gid(q, a), dC[L::lambda(a)]);
      chain(sr.frame.dn[a], dC[L::normal(a)]);
      for (int k = 0; k < dim - 1; ++k) chain(sr.frame.dt[k][a], dC[L::tangent(k, a)]);
      if (dC[L::tied(a)] != 0.0) {
        J.emplace_back(sr.node * dim + a, dC[L::tied(a)]);
        for (const MasterTerm* t = sr.begin; t != sr.end; ++t)
          J.emplace_back(t->node * dim + a, -dC[L::tied(a)] * t->M->value / D);
      }
    }
    chain(dg, dC[L::gap()]);
    for (int k = 0; k < dim - 1 && dslip; ++k) chain(dslip[k], dC[L::slip(k)]);
    compress_gradient(J);
    for (const auto& [dof, value] : J) terms.add_entry(gid, dof, value);
  }
}

// The Newton step's tangential hold (Jacobian only: F stays exact, so a converged state
// satisfies the contact conditions exactly and does not depend on it): a spring of stiffness
// κ (E/h) D_jj along each tangent between the slave node and its master points, κ (E/h) D_jj
// w_k w_kᵀ on the displacement rows, w_k = ∂ū_k/∂u the gradient of the weighted tangential
// relative displacement ū_k = τ_k·(D_jj x¹_j − Σ_l M_jl x²_l) / D_jj (τ_k on the slave node,
// −τ_k M_jl / D_jj on master node l). Frictionless contact resists no motion along the slave
// surface, and where that surface is an arc, no rotation about the arc's centre either: the
// slave nodes then move along their tangents, normal to their own (radial) normals, and no gap
// row sees it. A body held otherwise only on a line through that centre (two half discs, the
// upper one pressed by a load on its flat edge, held in x) has a rotation that J does not
// determine: exactly singular where the slave normals are radial (KLU2 status 1, MUMPS
// INFOG(1) = −10), determined only through the normals' tilt by the mesh grading elsewhere,
// and the step carried an arbitrary rotation: inputs/gmsh_hertz/point_contact.yaml came out
// rotated by 2.2 rad (|u_x| = 17 at the contact point of R = 8), its pressures unchanged
// (inputs/start_family/README.md). With the hold J is regular and a step turns the body only
// as far as the residual's moment pushes it (point_contact.yaml: 9e-4 rad). Symmetric and
// positive semidefinite in u, and the multiplier rows stay pure-λ, so the symmetric reduction
// still applies (symmetric_condensation.hpp). κ = 1e-11: a step of a problem without such a
// mode leaves a residual of about κ (E/p) (ū/h) of the step's, below the Newton tolerance
// (κ = 1e-8 added an iteration to hertz_cylinders' hertz_2). The same spring in F as well (a
// drag on the slip since the last converged step) holds the rotation for good, but moves the
// patch tests by 1e-8..2e-7 and breaks ring_pendulum's angular momentum balance: not kept.
void ContactInterface::add_tangential_hold(int q, ContactTerms& terms) const {
  const SlaveRow sr = slave_row(q);
  const double D = sr.D.value;
  const int dim = dim_;
  for (int k = 0; k < dim - 1; ++k) {
    SparseGradient w;
    for (int a = 0; a < dim; ++a) {
      w.emplace_back(sr.node * dim + a, sr.frame.t[k][a]);
      for (const MasterTerm* t = sr.begin; t != sr.end; ++t)
        w.emplace_back(t->node * dim + a, -sr.frame.t[k][a] * t->M->value / D);
    }
    compress_gradient(w);
    const double spring = hold_ * D;
    for (const auto& [r, wr] : w)
      for (const auto& [col, wc] : w) terms.add_entry(r, col, spring * wr * wc);
  }
}

}  // namespace grout
