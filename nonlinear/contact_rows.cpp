// The rows of one contact interface at a Newton iterate: the closure candidates of the
// active-set policy, then per owned slave node its force terms and multiplier rows
// (contact_interface.hpp).

#include <cmath>
#include <limits>

#include "nonlinear/contact_interface.hpp"

namespace grout {

ClosureCounts ContactInterface::prepare_active_set(const Vector& x, NewtonPhase phase) {
  const int dim = dim_;
  const ContactMortar& m = current_geometry_ ? current_ : reference_;
  const ContactSurface& s = surface_;
  const int n_owned = int(owned_.size());
  {
    const auto xv = x.getLocalViewHost(Tpetra::Access::ReadOnly);
    const Map& map = *x.getMap();
    for (int q = 0; q < n_owned; ++q)
      for (int d = 0; d < dim; ++d) lambda_[q][d] = xv(map.getLocalElement(lambda_gid(q, d)), 0);
  }
  if (input_.type == ContactKind::tied) return {};
  const auto m_range = [&](int j) {
    return m.M.lower_bound({j, std::numeric_limits<GlobalIndex>::min()});
  };
  const auto position = [&](GlobalIndex node, int d) { return positions_[position_of(node)][d]; };
  const auto old_position = [&](GlobalIndex node, int d) {
    const std::size_t i = position_of(node);
    return X_[i][d] + u_old_[i][d];
  };
  // g_j = −n_j·(D_jj x_j − Σ_l M_jl x_l) / D_jj at the given positions.
  const auto nodal_gap = [&](int j, const auto& at) {
    const SlaveFrame& fr = m.frames[j];
    double g = 0.0;
    for (int a = 0; a < dim; ++a) {
      double v = m.D[j].value * at(s.slave_nodes[j], a);
      for (auto it = m_range(j); it != m_range(j + 1); ++it)
        v -= it->second.value * at(it->first.second, a);
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
    node.gap = nodal_gap(j, position);
    // The base of the update: the last evaluation's gap; at the first update a node that
    // had no master then is measured from its last converged position.
    node.gap_old = gap_known_[q]                        ? iterate_gap_[q]
                   : phase == NewtonPhase::first_update ? nodal_gap(j, old_position)
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
  const auto pos = [&](GlobalIndex node) { return position_of(node); };
  const auto position = [&](GlobalIndex node, int d) { return positions_[pos(node)][d]; };
  const auto old_position = [&](GlobalIndex node, int d) {
    const std::size_t i = pos(node);
    return X_[i][d] + u_old_[i][d];
  };
  const auto m_range = [&](int j) {
    return m.M.lower_bound({j, std::numeric_limits<GlobalIndex>::min()});
  };
  const double D_tol = D_tol_;

  // Contact forces f¹_k = D_kk λ_k, f²_l = −Σ_j M_jl λ_j (j owned).
  for (int q = 0; q < n_owned; ++q) {
    const int j = owned_[q];
    const GlobalIndex node = s.slave_nodes[j];
    begin_node(node);
    const MortarValue& D = m.D[j];
    for (int a = 0; a < dim; ++a) {
      const GO row = node * dim + a;
      add_F_(row, D.value * lambda_[q][a]);
      add_entry(row, lambda_gid(q, a), D.value);
      for (const auto& [dof, dv] : D.gradient) add_entry(row, dof, lambda_[q][a] * dv);
    }
    for (auto it = m_range(j); it != m_range(j + 1); ++it) {
      const GlobalIndex master = it->first.second;
      const MortarValue& M = it->second;
      for (int a = 0; a < dim; ++a) {
        const GO row = master * dim + a;
        add_F_(row, -M.value * lambda_[q][a]);
        add_entry(row, lambda_gid(q, a), -M.value);
        for (const auto& [dof, dv] : M.gradient) add_entry(row, dof, -lambda_[q][a] * dv);
      }
    }
  }

  // Multiplier rows of the owned slave nodes (q: owned index, j: index in s.slave_nodes).
  for (int q = 0; q < n_owned; ++q) {
    const int j = owned_[q];
    const GlobalIndex node = s.slave_nodes[j];
    begin_node(node);
    const double D = m.D[j].value;
    const auto m_begin = m_range(j), m_end = m_range(j + 1);
    previous_active_[q] = active_[q];
    active_[q] = 0;
    pressure_[q] = gap_[q] = 0.0;
    {  // e_j = −½ λ_j·(D Δx_j − Σ_l M_jl Δx_l), Δ since the last converged state
      double w = 0.0;
      for (int a = 0; a < dim; ++a) {
        double wa = D * (position(node, a) - old_position(node, a));
        for (auto it = m_begin; it != m_end; ++it)
          wa -= it->second.value *
                (position(it->first.second, a) - old_position(it->first.second, a));
        w += lambda_[q][a] * wa;
      }
      step_energy_[q] = -0.5 * w;
    }
    if (D <= D_tol) {  // no master facing this node: λ_j = 0
      for (int a = 0; a < dim; ++a) {
        add_F_(lambda_gid(q, a), lambda_[q][a]);
        add_entry(lambda_gid(q, a), lambda_gid(q, a), 1.0);
      }
      continue;
    }
    // Round-off of node j's rows where they carry ĉ × (a gap or a slip): ε ĉ |X_j| each.
    const auto add_floor = [&] {
      double x_max = 0.0;
      for (int a = 0; a < dim; ++a) x_max = std::max(x_max, std::abs(X_[pos(node)][a]));
      const double row =
          std::numeric_limits<double>::epsilon() * std::max(c_hat_, c_t_hat_) * x_max;
      sums.floor2 += dim * row * row;
    };
    // True when component a of the slave dof is prescribed and the master dofs node j is
    // tied to carry a share of Σ_l |M_jl| at most `free_share` D where component a is free:
    // D u¹_ja − Σ_l M_jl u²_la then (nearly) involves prescribed values only, and λ_ja acts
    // (nearly) on prescribed rows only, which leaves it undetermined (or determined only
    // through that small share: λ ~ force / share, the update of an ill-conditioned row).
    const auto component_held = [&](int a, double free_share) {
      if (std::isnan(prescribed[node * dim + a])) return false;
      double free_sum = 0.0;
      for (auto it = m_begin; it != m_end; ++it)
        if (std::isnan(prescribed[it->first.second * dim + a]))
          free_sum += std::abs(it->second.value);
      return free_sum <= free_share * D;
    };
    if (tied) {  // ĉ (D u¹_j − Σ_l M_jl u²_l) / D = 0, per component
      active_[q] = 1;
      add_floor();
      for (int a = 0; a < dim; ++a)  // reported only: λ_n = n·λ as for frictional contact
        pressure_[q] += m.frames[j].n[a] * lambda_[q][a];
      for (int a = 0; a < dim; ++a) {
        const GO row = lambda_gid(q, a);
        // A held component (free share at the round-off 1e-12 D that the integration leaves
        // where M_jl vanishes): the tie constrains prescribed values only, and λ is not
        // determined; λ = 0 as for a node without master (else the round-off row pins a free
        // master dof and λ ~ 1e17; condensed_solve.hpp, kind R).
        if (component_held(a, 1e-12)) {
          add_F_(row, lambda_[q][a]);
          add_entry(row, row, 1.0);
          continue;
        }
        double v = D * u_[pos(node)][a];
        add_entry(row, node * dim + a, c_hat_);
        for (auto it = m_begin; it != m_end; ++it) {
          const GlobalIndex l = it->first.second;
          v -= it->second.value * u_[pos(l)][a];
          add_entry(row, l * dim + a, -c_hat_ * it->second.value / D);
        }
        add_F_(row, c_hat_ * v / D);
      }
      continue;
    }
    // Normal contact: v = D x¹_j − Σ_l M_jl x²_l, g̃ = −n·v, g = g̃ / D.
    const SlaveFrame& fr = m.frames[j];
    double v[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < dim; ++a) v[a] = D * position(node, a);
    for (auto it = m_begin; it != m_end; ++it)
      for (int a = 0; a < dim; ++a) v[a] -= it->second.value * position(it->first.second, a);
    double g_tilde = 0.0, lambda_n = 0.0;
    for (int a = 0; a < dim; ++a) {
      g_tilde -= fr.n[a] * v[a];
      lambda_n += fr.n[a] * lambda_[q][a];
    }
    const double gap = g_tilde / D;
    gap_[q] = gap;
    pressure_[q] = lambda_n;
    // Active if λ_n − ĉ g > 0; a closed gap with no pressure yet (λ_n = g = 0, the usual
    // start) counts as active, within round-off of ĉ g, so that touching bodies are supported.
    // Until the first Newton update of a step, a node with no pressure and a gap below
    // start_gap × its face size (contact input, default 0.05) also counts as active, as
    // Kratos' active check does: a body held only by contact then has its rigid motion fixed
    // by several contact rows from the first solve (with none, K is singular; with one, the
    // first update is a huge rigid motion). From the next iterate on only λ_n − ĉ g decides,
    // so the converged state satisfies the contact conditions exactly.
    const double augmented = lambda_n - c_hat_ * gap;
    const bool near = policy_.near(q, lambda_n, gap, phase);
    if ((augmented < -active_tolerance_ && !near) || held_back_[q]) {  // inactive: λ_j = 0
      for (int a = 0; a < dim; ++a) {
        add_F_(lambda_gid(q, a), lambda_[q][a]);
        add_entry(lambda_gid(q, a), lambda_gid(q, a), 1.0);
      }
      slip_increment_[q] = {0.0, 0.0, 0.0};
      continue;
    }
    add_floor();
    // dg = (dg̃ − g dD) / D,  dg̃ = −Σ_a v_a dn_a − Σ_a n_a dv_a,
    // dv_a = x_ja dD + D e_ja − Σ_l (x_la dM_jl + M_jl e_la).
    SparseGradient dg;
    {
      const double r = 1.0 / D;
      double n_dot_x = 0.0;
      for (int a = 0; a < dim; ++a) {
        n_dot_x += fr.n[a] * position(node, a);
        for (const auto& [dof, dn] : fr.dn[a]) dg.emplace_back(dof, -r * v[a] * dn);
        dg.emplace_back(node * dim + a, -r * fr.n[a] * D);
      }
      for (const auto& [dof, dD] : m.D[j].gradient) dg.emplace_back(dof, -r * (n_dot_x + gap) * dD);
      for (auto it = m_begin; it != m_end; ++it) {
        const GlobalIndex l = it->first.second;
        double n_dot_xl = 0.0;
        for (int a = 0; a < dim; ++a) {
          n_dot_xl += fr.n[a] * position(l, a);
          dg.emplace_back(l * dim + a, r * fr.n[a] * it->second.value);
        }
        for (const auto& [dof, dM] : it->second.gradient) dg.emplace_back(dof, r * n_dot_xl * dM);
      }
      compress_gradient(dg);
    }
    const auto emit = [&](GO row, const SparseGradient& g, double scale) {
      for (const auto& [dof, value] : g) add_entry(row, dof, scale * value);
    };
    // Normal row: ĉ g = 0.
    const GO row = lambda_gid(q, 0);
    add_F_(row, c_hat_ * gap);
    emit(row, dg, c_hat_);

    // Tangential multipliers λ_τk = τ_k·λ and their gradients (λ dofs and dτ_k).
    double lambda_t[2] = {0.0, 0.0};
    SparseGradient dlambda_t[2];
    for (int k = 0; k < dim - 1; ++k) {
      for (int a = 0; a < dim; ++a) {
        lambda_t[k] += fr.t[k][a] * lambda_[q][a];
        dlambda_t[k].emplace_back(lambda_gid(q, a), fr.t[k][a]);
        for (const auto& [dof, dt] : fr.dt[k][a])
          dlambda_t[k].emplace_back(dof, lambda_[q][a] * dt);
      }
      compress_gradient(dlambda_t[k]);
    }
    if (input_.type == ContactKind::frictionless) {  // τ_k·λ = 0
      active_[q] = 2;
      for (int k = 0; k < dim - 1; ++k) {
        add_F_(lambda_gid(q, k + 1), lambda_t[k]);
        emit(lambda_gid(q, k + 1), dlambda_t[k], 1.0);
      }
      // The Newton step's tangential hold (Jacobian only: F stays exact, so a converged state
      // satisfies the contact conditions exactly and does not depend on it): a spring of
      // stiffness κ (E/h) D_jj along each tangent between the slave node and its master
      // points, κ (E/h) D_jj w_k w_kᵀ on the displacement rows, w_k = ∂ū_k/∂u the gradient of
      // the weighted tangential relative displacement ū_k = τ_k·(D_jj x¹_j − Σ_l M_jl x²_l) /
      // D_jj (τ_k on the slave node, −τ_k M_jl / D_jj on master node l). Frictionless
      // contact resists no motion along the slave surface, and where that surface is an arc,
      // no rotation about the arc's centre either: the slave nodes then move along their
      // tangents, normal to their own (radial) normals, and no gap row sees it. A body held
      // otherwise only on a line through that centre (two half discs, the upper one pressed
      // by a load on its flat edge, held in x) has a rotation that J does not determine:
      // exactly singular where the slave normals are radial (KLU2 status 1, MUMPS INFOG(1) =
      // −10), determined only through the normals' tilt by the mesh grading elsewhere, and
      // the step carried an arbitrary rotation: inputs/gmsh_hertz/point_contact.yaml came out
      // rotated by 2.2 rad (|u_x| = 17 at the contact point of R = 8), its pressures
      // unchanged (inputs/start_family/README.md). With the hold J is regular and a step
      // turns the body only as far as the residual's moment pushes it (point_contact.yaml:
      // 9e-4 rad). Symmetric and positive semidefinite in u, and the multiplier rows stay
      // pure-λ, so the symmetric reduction still applies (symmetric_condensation.hpp).
      // κ = 1e-11: a step of a problem without such a mode leaves a residual of about
      // κ (E/p) (ū/h) of the step's, below the Newton tolerance (κ = 1e-8 added an iteration
      // to hertz_cylinders' hertz_2). The same spring in F as well (a drag on the slip since
      // the last converged step) holds the rotation for good, but moves the patch tests by
      // 1e-8..2e-7 and breaks ring_pendulum's angular momentum balance: not kept.
      for (int k = 0; k < dim - 1; ++k) {
        SparseGradient w;
        for (int a = 0; a < dim; ++a) {
          w.emplace_back(node * dim + a, fr.t[k][a]);
          for (auto it = m_begin; it != m_end; ++it)
            w.emplace_back(it->first.second * dim + a, -fr.t[k][a] * it->second.value / D);
        }
        compress_gradient(w);
        const double spring = hold_ * D;
        for (const auto& [r, wr] : w)
          for (const auto& [col, wc] : w) add_entry(r, col, spring * wr * wc);
      }
      continue;
    }

    // Coulomb friction (Hüeber, Stadler, Wohlmuth 2008; docs/design.md §2), per unit D_jj:
    // ū_k the weighted slip increment since the last converged step (weighted_slip.hpp:
    // objective on the current geometry, standard on the reference one), ξ = λ_τ + c_t ū,
    // s = λ_n − ĉ g.
    //   stick (|ξ| < μ s):  c_t ū = 0;
    //   slip:               λ_τ − μ s ξ/|ξ| = 0   (the NCP divided by |ξ| > 0).
    // A node with no master at the last converged step (D_jj,n = 0) measures its first slip
    // with the standard increment.
    std::vector<MortarRowEntry> m_row;
    for (auto it = m_begin; it != m_end; ++it) m_row.emplace_back(it->first.second, &it->second);
    const bool objective = current_geometry_ && history_[q].D > D_tol;
    double slip[2] = {0.0, 0.0}, xi[2] = {0.0, 0.0}, xi_norm = 0.0;
    SparseGradient dslip[2];
    weighted_slip_increment(dim, node, fr, m.D[j], m_row, objective ? &history_[q] : nullptr,
                            position, old_position, slip, dslip);
    // A tangent along a held Cartesian direction: a symmetry plane that cuts the contact
    // surface, prescribed on both bodies. The slave node cannot move along it, and the
    // master dofs it is tied to are (nearly) all prescribed along it too: the stick row
    // c_t ū_k then constrains prescribed dofs only (a zero row: J singular), or, once the
    // surfaces tilt off the plane by deformation, pins the few free master dofs through
    // their small share of M_jl (λ_τk ~ force / share: updates of 1e12 and no convergence).
    // The friction along it acts on the supports, not on the bodies, and is not determined:
    // e_a·λ = 0 in τ_k's row, the traction the full model's mirror symmetry gives on its
    // mid-plane, and Coulomb's law holds for the other tangent. (τ_k·λ = 0 instead leaves
    // λ_a = −tan θ λ·τ' where the one-sided normal tilts by θ; that λ_a acts on the free
    // master nodes off the plane: twice the difference to the full model while sliding,
    // docs/verification.md.) Held: τ_k within 0.1 rad of e_a (|τ_k·e_a|² ≥ 0.99), and
    // the free master dofs' share of Σ|M_jl| at most 0.25 of D. Both are 0 on a plane of
    // symmetry at rest, and both grow there with the deformation alone: the plane's nodal
    // normals average the faces of one side (they tilt as the bodies bulge), and faces that
    // no longer line up across the plane give the dual basis a share of the free master
    // nodes off the plane. A die pressed 0.8 of its face size into a one-layer slab
    // (inputs/shallow_ironing/slab_ci_frictional.yaml) tilts them by 0.011 rad and shares
    // 0.07 of D; with the former limits (0.01 rad, 0.01) its plane nodes switched to stick
    // rows and no step size converged (docs/verification.md, "Friction on the slab's plane").
    // A master free along e_a, a real frictional contact, has a share near 1 (Σ_l M_jl = D).
    constexpr double held_tangent = 0.99, held_free_share = 0.25;
    int held_axis[2] = {-1, -1};  // the Cartesian axis a of a held tangent τ_k, or −1
    for (int k = 0; k < dim - 1; ++k)
      for (int a = 0; a < dim && held_axis[k] < 0; ++a)
        if (fr.t[k][a] * fr.t[k][a] >= held_tangent && component_held(a, held_free_share))
          held_axis[k] = a;
    const bool held[2] = {held_axis[0] >= 0, held_axis[1] >= 0};
    const auto emit_held = [&](int k) {  // e_a·λ = 0 in τ_k's row
      const GO row = lambda_gid(q, k + 1);
      add_F_(row, lambda_[q][held_axis[k]]);
      add_entry(row, lambda_gid(q, held_axis[k]), 1.0);
    };
    for (int k = 0; k < dim - 1; ++k) {
      if (held[k]) slip[k] = 0.0;
      xi[k] = held[k] ? 0.0 : lambda_t[k] + c_t_hat_ * slip[k];
      xi_norm += xi[k] * xi[k];
    }
    xi_norm = std::sqrt(xi_norm);
    for (int k = 0; k < dim - 1; ++k) slip_increment_[q][k] = slip[k];
    const double mu = input_.friction_coefficient;
    // Stick includes |ξ| = μ s: at the start of a step (λ = 0, no slip) every node starts
    // stuck, the usual initial guess; starting in slip leaves a body held by friction alone
    // without tangential stiffness (a singular Jacobian). μ = 0 always slips (frictionless).
    if (mu > 0.0 && xi_norm <= mu * (augmented + active_tolerance_)) {  // stick
      active_[q] = 1;
      for (int k = 0; k < dim - 1; ++k) {
        if (held[k]) {
          emit_held(k);
          continue;
        }
        add_F_(lambda_gid(q, k + 1), c_t_hat_ * slip[k]);
        emit(lambda_gid(q, k + 1), dslip[k], c_t_hat_);
      }
    } else {  // slip: λ_τ − μ s ξ̂, d = dλ_τ − μ ξ̂ ds − μ s (I − ξ̂ξ̂ᵀ)/|ξ| dξ
      active_[q] = 2;
      SparseGradient ds = dg;  // ds = dλ_n − ĉ dg
      for (auto& [dof, value] : ds) value *= -c_hat_;
      for (int a = 0; a < dim; ++a) {
        ds.emplace_back(lambda_gid(q, a), fr.n[a]);
        for (const auto& [dof, dn] : fr.dn[a]) ds.emplace_back(dof, lambda_[q][a] * dn);
      }
      compress_gradient(ds);
      double xi_hat[2] = {0.0, 0.0};
      if (xi_norm > 0.0)
        for (int k = 0; k < dim - 1; ++k) xi_hat[k] = xi[k] / xi_norm;
      for (int k = 0; k < dim - 1; ++k) {
        if (held[k]) {  // ξ̂_k = 0, so the other row's P has no term of this tangent
          emit_held(k);
          continue;
        }
        const GO trow = lambda_gid(q, k + 1);
        add_F_(trow, lambda_t[k] - mu * augmented * xi_hat[k]);
        emit(trow, dlambda_t[k], 1.0);
        emit(trow, ds, -mu * xi_hat[k]);
        if (xi_norm > 0.0 && dim == 3) {  // the direction's derivative (none in 2D)
          for (int m2 = 0; m2 < dim - 1; ++m2) {
            if (held[m2]) continue;  // P = 0
            const double P = ((k == m2 ? 1.0 : 0.0) - xi_hat[k] * xi_hat[m2]) / xi_norm;
            emit(trow, dlambda_t[m2], -mu * augmented * P);
            emit(trow, dslip[m2], -mu * augmented * P * c_t_hat_);
          }
        }
      }
    }
  }
  for (int q = 0; q < n_owned; ++q) {
    closing_[q] = active_[q] && !committed_active_[q];
    sums.active += active_[q] != 0;
    // A held-back node is a pending change: the iterate cannot be the converged one.
    sums.changes += active_[q] != previous_active_[q] || held_back_[q];
  }
  return sums;
}

}  // namespace grout
