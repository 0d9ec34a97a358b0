// The rows of one contact interface at a Newton iterate: the closure candidates of the
// active-set policy, then per owned slave node its force terms and multiplier rows
// (contact_interface.hpp).

#include <cmath>
#include <limits>

#include "kernels/contact_laws.hpp"
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
  // g_j = −n_j·(D_jj x_j − Σ_l M_jl x_l) / D_jj at the given positions (owned node q).
  const auto nodal_gap = [&](int q, const auto& at) {
    const int j = owned_[q];
    const SlaveFrame& fr = m.frames[j];
    double g = 0.0;
    for (int a = 0; a < dim; ++a) {
      double v = m.D[j].value * at(slave_pos_[q], a);
      for (std::size_t e = stencil_begin_[q]; e < stencil_begin_[q + 1]; ++e)
        v -= stencil_[e].M->value * at(stencil_[e].pos, a);
      g -= fr.n[a] * v;
    }
    return g / m.D[j].value;
  };
  for (int q = 0; q < n_owned; ++q) {
    const int j = owned_[q];
    ClosureCandidate& node = candidates_[q];
    node = ClosureCandidate();
    node.paired = m.D[j].value > D_tol_;
    if (!node.paired) continue;
    node.was_active = active_[q] != 0;
    node.gap = nodal_gap(q, position);
    // The base of the update: the last evaluation's gap; at the first update a node that
    // had no master then is measured from its last converged position.
    node.gap_old = gap_known_[q]                        ? iterate_gap_[q]
                   : phase == NewtonPhase::first_update ? nodal_gap(q, old_position)
                                                        : 0.0;
    double lambda_n = 0.0;
    for (int a = 0; a < dim; ++a) lambda_n += m.frames[j].n[a] * lambda_[q][a];
    node.closing = !node.was_active && lambda_n - c_hat_ * node.gap >= -active_tolerance_;
  }
  return count_closures(candidates_);
}

ContactRowSums ContactInterface::write_rows(NewtonPhase phase, const ClosureCounts& global,
                                            const std::vector<double>& prescribed,
                                            ContactTerms& terms, Vector& F) {
  const int dim = dim_;
  const ContactMortar& m = current_geometry_ ? current_ : reference_;
  const ContactSurface& s = surface_;
  const int n_owned = int(owned_.size());
  const bool tied = input_.type == ContactKind::tied;
  ContactRowSums sums;

  // After the step's start: the late-closing nodes held back (first_update_closures.hpp),
  // measured from the last evaluation's gaps.
  std::fill(held_back_.begin(), held_back_.end(), 0);
  if (!tied) {
    held_back_ = policy_.held_back(candidates_, global, phase);
    for (int q = 0; q < n_owned; ++q) {
      gap_known_[q] = candidates_[q].paired;
      iterate_gap_[q] = candidates_[q].gap;
    }
  }

  auto Fv = F.getLocalViewHost(Tpetra::Access::ReadWrite);
  const Map& map = *F.getMap();
  const GO num_u = GO(mesh_.num_nodes()) * dim;
  const auto add_F_ = [&](GO row, double v) {
    if (row < num_u)  // a slave or master row: a term tagged by the slave node
      terms.add_force(row, v);
    else  // an owned multiplier row, set once
      Fv(map.getLocalElement(row), 0) += v;
  };
  const auto add_entry = [&](GO row, GO col, double v) { terms.add_entry(row, col, v); };
  const auto begin_node = [&](GlobalIndex node) {
    terms.begin_node(GO(index_) * GO(mesh_.num_nodes()) + node);
  };
  // Positions by global node (the weighted slip's interface) and by index in surface_.nodes.
  const auto position = [&](GlobalIndex node, int d) { return positions_[position_of(node)][d]; };
  const auto old_position = [&](GlobalIndex node, int d) {
    const std::size_t i = position_of(node);
    return X_[i][d] + u_old_[i][d];
  };
  const auto x_at = [&](std::size_t i, int d) { return positions_[i][d]; };
  const auto x_old_at = [&](std::size_t i, int d) { return X_[i][d] + u_old_[i][d]; };
  // The master terms of owned node q's row (build_stencil).
  const auto terms_of = [&](int q) {
    return std::make_pair(stencil_.data() + stencil_begin_[q],
                          stencil_.data() + stencil_begin_[q + 1]);
  };
  const double D_tol = D_tol_;

  // Multiplier rows of the owned slave nodes (q: owned index, j: index in s.slave_nodes): the
  // law's inputs per node, the law's launch (kernels/contact_laws.hpp: rows, status, ∂C/∂v over
  // the local variables v), then the chain rule to the global dofs through ∂v/∂x.
  const bool coulomb = input_.type == ContactKind::frictional;
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
  std::vector<std::array<double, 3>> weighted(n_owned);  // D x¹_j − Σ_l M_jl x²_l
  std::vector<std::array<SparseGradient, 2>> dslip(coulomb ? n_owned : 0);
  for (int q = 0; q < n_owned; ++q) {
    const int j = owned_[q];
    const GlobalIndex node = s.slave_nodes[j];
    const double D = m.D[j].value;
    const auto [m_begin, m_end] = terms_of(q);
    const std::size_t i = slave_pos_[q];
    const SlaveFrame& fr = m.frames[j];
    ContactLawNode& in = nodes_host(q);
    in = ContactLawNode();
    for (int a = 0; a < dim; ++a) {
      in.lambda[a] = lambda_[q][a];
      in.n[a] = fr.n[a];
      for (int k = 0; k < dim - 1; ++k) in.t[k][a] = fr.t[k][a];
    }
    in.paired = D > D_tol;
    if (!in.paired) continue;
    in.held_back = held_back_[q];
    for (int a = 0; a < dim; ++a) {  // held components: prescribed slave dof, free masters' share
      in.prescribed[a] = !std::isnan(prescribed[node * dim + a]);
      double free_sum = 0.0;
      for (const MasterTerm* t = m_begin; t != m_end; ++t)
        if (std::isnan(prescribed[t->node * dim + a])) free_sum += std::abs(t->M->value);
      in.free_share[a] = free_sum / D;
    }
    if (tied) {  // t_a = (D u¹_j − Σ_l M_jl u²_l) / D
      for (int a = 0; a < dim; ++a) {
        double v = D * u_[i][a];
        for (const MasterTerm* t = m_begin; t != m_end; ++t) v -= t->M->value * u_[t->pos][a];
        in.tied[a] = v / D;
      }
      continue;
    }
    // g = g̃ / D, g̃ = −n·(D x¹_j − Σ_l M_jl x²_l).
    double g_tilde = 0.0, lambda_n = 0.0;
    for (int a = 0; a < dim; ++a) {
      double& v = weighted[q][a];
      v = D * x_at(i, a);
      for (const MasterTerm* t = m_begin; t != m_end; ++t) v -= t->M->value * x_at(t->pos, a);
      g_tilde -= fr.n[a] * v;
      lambda_n += fr.n[a] * lambda_[q][a];
    }
    in.gap = g_tilde / D;
    in.near = policy_.near(q, lambda_n, in.gap, phase);
    if (coulomb) {  // ū_k, objective on the current geometry (assembly/weighted_slip.hpp)
      std::vector<MortarRowEntry> m_row;
      for (const MasterTerm* t = m_begin; t != m_end; ++t) m_row.emplace_back(t->node, t->M);
      const bool objective = current_geometry_ && history_[q].D > D_tol;
      weighted_slip_increment(dim, node, fr, m.D[j], m_row, objective ? &history_[q] : nullptr,
                              position, old_position, &slip_value[2 * q], dslip[q].data());
      for (int k = 0; k < dim - 1; ++k) in.slip[k] = slip_value[2 * q + k];
    }
  }
  Kokkos::deep_copy(law_nodes_, nodes_host);
  evaluate_contact_law(LawSpace(), law, Kokkos::View<const ContactLawNode*, LawMemory>(law_nodes_),
                       true, law_results_);
  auto results = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), law_results_);

  // Contact forces f¹_k = D_kk λ_k, f²_l = −Σ_j M_jl λ_j of owned slave node q.
  const auto add_forces = [&](int q) {
    const int j = owned_[q];
    const GlobalIndex node = s.slave_nodes[j];
    const MortarValue& D = m.D[j];
    for (int a = 0; a < dim; ++a) {
      const GO row = node * dim + a;
      add_F_(row, D.value * lambda_[q][a]);
      add_entry(row, lambda_gid(q, a), D.value);
      for (const auto& [dof, dv] : D.gradient) add_entry(row, dof, lambda_[q][a] * dv);
    }
    const auto [m_begin, m_end] = terms_of(q);
    for (const MasterTerm* t = m_begin; t != m_end; ++t) {
      const GlobalIndex master = t->node;
      const MortarValue& M = *t->M;
      for (int a = 0; a < dim; ++a) {
        const GO row = master * dim + a;
        add_F_(row, -M.value * lambda_[q][a]);
        add_entry(row, lambda_gid(q, a), -M.value);
        for (const auto& [dof, dv] : M.gradient) add_entry(row, dof, -lambda_[q][a] * dv);
      }
    }
  };
  using L = ContactLawLayout;
  for (int q = 0; q < n_owned; ++q) {
    const int j = owned_[q];
    const GlobalIndex node = s.slave_nodes[j];
    begin_node(node);  // one tag per node: its forces, rows and hold, keys unique per row
    add_forces(q);
    const double D = m.D[j].value;
    const auto [m_begin, m_end] = terms_of(q);
    const std::size_t i = slave_pos_[q];
    const SlaveFrame& fr = m.frames[j];
    const ContactLawNode& in = nodes_host(q);
    const ContactLawResult& r = results(q);
    previous_active_[q] = active_[q];
    active_[q] = char(r.status);
    pressure_[q] = gap_[q] = 0.0;
    {  // e_j = −½ λ_j·(D Δx_j − Σ_l M_jl Δx_l), Δ since the last converged state
      double w = 0.0;
      for (int a = 0; a < dim; ++a) {
        double wa = D * (x_at(i, a) - x_old_at(i, a));
        for (const MasterTerm* t = m_begin; t != m_end; ++t)
          wa -= t->M->value * (x_at(t->pos, a) - x_old_at(t->pos, a));
        w += lambda_[q][a] * wa;
      }
      step_energy_[q] = -0.5 * w;
    }
    if (in.paired) {
      for (int a = 0; a < dim; ++a) pressure_[q] += fr.n[a] * lambda_[q][a];  // λ_n = n·λ
      if (!tied) gap_[q] = in.gap;
      if (!tied && r.status == node_open) slip_increment_[q] = {0.0, 0.0, 0.0};
      if (coulomb && r.status != node_open)
        for (int k = 0; k < dim - 1; ++k)
          slip_increment_[q][k] = r.held_axis[k] >= 0 ? 0.0 : slip_value[2 * q + k];
    }
    if (r.status != node_open) {  // round-off of rows that carry ĉ × (a gap or a slip)
      double x_max = 0.0;
      for (int a = 0; a < dim; ++a) x_max = std::max(x_max, std::abs(X_[i][a]));
      const double row =
          std::numeric_limits<double>::epsilon() * std::max(c_hat_, c_t_hat_) * x_max;
      sums.floor2 += dim * row * row;
    }
    // ∂g = (∂g̃ − g ∂D) / D, ∂g̃ = −Σ_a v_a ∂n_a − Σ_a n_a ∂v_a,
    // ∂v_a = x_ja ∂D + D e_ja − Σ_l (x_la ∂M_jl + M_jl e_la); only where a row uses g.
    SparseGradient dg;
    bool uses_gap = false;
    for (int row = 0; row < dim; ++row) uses_gap = uses_gap || r.dC[row][L::gap()] != 0.0;
    if (uses_gap) {
      const double rD = 1.0 / D;
      const double* v = weighted[q].data();  // of the law's inputs
      double n_dot_x = 0.0;
      for (int a = 0; a < dim; ++a) {
        n_dot_x += fr.n[a] * x_at(i, a);
        for (const auto& [dof, dn] : fr.dn[a]) dg.emplace_back(dof, -rD * v[a] * dn);
        dg.emplace_back(node * dim + a, -rD * fr.n[a] * D);
      }
      for (const auto& [dof, dD] : m.D[j].gradient)
        dg.emplace_back(dof, -rD * (n_dot_x + in.gap) * dD);
      for (const MasterTerm* t = m_begin; t != m_end; ++t) {
        double n_dot_xl = 0.0;
        for (int a = 0; a < dim; ++a) {
          n_dot_xl += fr.n[a] * x_at(t->pos, a);
          dg.emplace_back(t->node * dim + a, rD * fr.n[a] * t->M->value);
        }
        for (const auto& [dof, dM] : t->M->gradient) dg.emplace_back(dof, rD * n_dot_xl * dM);
      }
      compress_gradient(dg);
    }
    // Row r: F = C_r, J = Σ_v ∂C_r/∂v ∂v/∂x (λ: the multiplier dofs; n, τ: the frame's
    // gradients; g: dg; ū: the weighted slip's; t: e_j − Σ_l M_jl/D e_l).
    for (int row = 0; row < dim; ++row) {
      const GO gid = lambda_gid(q, row);
      row_kinds_[q][row] = declared_kind(r, row);
      add_F_(gid, r.C[row]);
      const double* dC = r.dC[row];
      SparseGradient J;
      const auto chain = [&](const SparseGradient& grad, double scale) {
        if (scale != 0.0)
          for (const auto& [dof, value] : grad) J.emplace_back(dof, scale * value);
      };
      for (int a = 0; a < dim; ++a) {
        if (dC[L::lambda(a)] != 0.0) J.emplace_back(lambda_gid(q, a), dC[L::lambda(a)]);
        chain(fr.dn[a], dC[L::normal(a)]);
        for (int k = 0; k < dim - 1; ++k) chain(fr.dt[k][a], dC[L::tangent(k, a)]);
        if (dC[L::tied(a)] != 0.0) {
          J.emplace_back(node * dim + a, dC[L::tied(a)]);
          for (const MasterTerm* t = m_begin; t != m_end; ++t)
            J.emplace_back(t->node * dim + a, -dC[L::tied(a)] * t->M->value / D);
        }
      }
      chain(dg, dC[L::gap()]);
      for (int k = 0; k < dim - 1 && coulomb; ++k) chain(dslip[q][k], dC[L::slip(k)]);
      compress_gradient(J);
      for (const auto& [dof, value] : J) add_entry(gid, dof, value);
    }
    if (law.kind == frictionless_law && r.status != node_open) add_tangential_hold(q, terms);
  }
  for (int q = 0; q < n_owned; ++q) {
    closing_[q] = active_[q] && !committed_active_[q];
    sums.active += active_[q] != 0;
    // A held-back node is a pending change: the iterate cannot be the converged one.
    sums.changes += active_[q] != previous_active_[q] || held_back_[q];
  }
  return sums;
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
  const int dim = dim_;
  const ContactMortar& m = current_geometry_ ? current_ : reference_;
  const int j = owned_[q];
  const GlobalIndex node = surface_.slave_nodes[j];
  const double D = m.D[j].value;
  const MasterTerm* m_begin = stencil_.data() + stencil_begin_[q];
  const MasterTerm* m_end = stencil_.data() + stencil_begin_[q + 1];
  const SlaveFrame& fr = m.frames[j];
  for (int k = 0; k < dim - 1; ++k) {
    SparseGradient w;
    for (int a = 0; a < dim; ++a) {
      w.emplace_back(node * dim + a, fr.t[k][a]);
      for (const MasterTerm* t = m_begin; t != m_end; ++t)
        w.emplace_back(t->node * dim + a, -fr.t[k][a] * t->M->value / D);
    }
    compress_gradient(w);
    const double spring = hold_ * D;
    for (const auto& [r, wr] : w)
      for (const auto& [col, wc] : w) terms.add_entry(r, col, spring * wr * wc);
  }
}

}  // namespace grout
