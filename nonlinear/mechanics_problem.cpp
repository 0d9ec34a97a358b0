#include "nonlinear/mechanics_problem.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <cmath>
#include <limits>

#include "io/errors.hpp"
#include "nonlinear/dirichlet.hpp"

namespace grout {

struct MechanicsProblem::Interface {
  ContactSurface surface;
  ContactInput input;
  GO lambda_offset = 0;  ///< GID of λ_0, component 0
  double c_hat = 1.0;
  double active_tolerance = 0.0;                        ///< on λ_n − ĉ g: 1e-10 E
  double c_t_hat = 1.0;                                 ///< c_t: like ĉ unless the input sets it
  std::vector<std::array<double, 3>> old_positions;     ///< of surface.nodes, last converged step
  std::vector<std::array<double, 3>> positions;         ///< of surface.nodes, last evaluation
  std::vector<std::array<double, 3>> slip_increment;    ///< per slave node, ū_k of the step
  std::vector<std::array<double, 3>> slip_accumulated;  ///< per slave node, Σ ū_k τ_k (vector)
  std::vector<std::array<std::array<double, 3>, 2>> tangents;  ///< τ_k per slave node

  double old_position(GlobalIndex node, int d) const {
    return old_positions[std::lower_bound(surface.nodes.begin(), surface.nodes.end(), node) -
                         surface.nodes.begin()][d];
  }
  ContactMortarOptions options;
  bool current_geometry = false;  ///< normals, D, M on the current configuration
  ContactMortar reference;        ///< D, M and normals of the reference configuration
  // Results of the last evaluation, per slave node.
  std::vector<double> pressure, gap;
  std::vector<std::array<double, 3>> lambda;
  std::vector<char> active, previous_active;

  GO lambda_gid(int j, int c) const { return lambda_offset + GO(j) * surface.dimension + c; }
};

namespace {

// Young's modulus of the material of the block the surface's first face belongs to.
double youngs_modulus_of(const Input& input, const SurfaceFaces& faces, const ContactSurface& s) {
  if (const MaterialInput* m = find_material(input, *faces.blocks.front()))
    return m->youngs_modulus;
  throw InputError(input.file + ": grout/contact/" + s.name + ": no material on block '" +
                   faces.blocks.front()->name + "'");
}

double mean_face_size(const Mesh& mesh, const SurfaceFaces& faces) {
  const int dim = mesh.dimension;
  double sum = 0.0;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    double extent = 0.0;  // longest edge
    for (int a = 0; a < faces.num_nodes[f]; ++a) {
      const GlobalIndex p = faces.nodes[f][a], q = faces.nodes[f][(a + 1) % faces.num_nodes[f]];
      double d2 = 0.0;
      for (int d = 0; d < dim; ++d) {
        const double dx = mesh.coordinates[p * dim + d] - mesh.coordinates[q * dim + d];
        d2 += dx * dx;
      }
      extent = std::max(extent, std::sqrt(d2));
    }
    sum += extent;
  }
  return sum / double(faces.size());
}

}  // namespace

MechanicsProblem::MechanicsProblem(const SolidProblem& solid, const Mesh& mesh, const Input& input)
    : solid_(solid), mesh_(mesh), input_(input), dim_(mesh.dimension) {
  num_u_ = GO(mesh.num_nodes()) * dim_;
  const auto& owned_u = *solid.owned_map();
  num_owned_u_ = int(owned_u.getNodeNumElements());
  std::vector<GO> owned;
  for (int i = 0; i < num_owned_u_; ++i) owned.push_back(owned_u.getGlobalElement(i));

  // Interfaces: surfaces, multiplier numbering, penalty-like scaling ĉ.
  GO next_lambda = num_u_;
  std::vector<GO> gathered;
  for (const ContactInput& ci : input.contact) {
    auto c = std::make_unique<Interface>();
    c->surface = build_contact_surface(mesh, input, ci);
    c->input = ci;
    c->lambda_offset = next_lambda;
    const int n_slave = int(c->surface.slave_nodes.size());
    next_lambda += GO(n_slave) * dim_;
    const double E1 = youngs_modulus_of(input, c->surface.slave, c->surface);
    const double E2 = youngs_modulus_of(input, c->surface.master, c->surface);
    c->c_hat = ci.c_n > 0.0 ? ci.c_n
                            : 2.0 / (1.0 / E1 + 1.0 / E2) / mean_face_size(mesh, c->surface.slave);
    c->active_tolerance = 1e-10 * 2.0 / (1.0 / E1 + 1.0 / E2);
    c->options.scheme = ci.integration == ContactIntegration::collocation
                            ? MortarIntegration::collocation
                            : MortarIntegration::exact;
    if (ci.collocation_points > 0) c->options.collocation_points = ci.collocation_points;
    c->pressure.assign(n_slave, 0.0);
    c->gap.assign(n_slave, 0.0);
    c->lambda.assign(n_slave, {0.0, 0.0, 0.0});
    c->active.assign(n_slave, 0);
    c->previous_active.assign(n_slave, 0);
    for (int j = 0; j < n_slave; ++j) {
      if (owned_u.isNodeGlobalElement(c->surface.slave_nodes[j] * dim_))
        for (int d = 0; d < dim_; ++d) owned.push_back(c->lambda_gid(j, d));
      for (int d = 0; d < dim_; ++d) gathered.push_back(c->lambda_gid(j, d));
    }
    for (GlobalIndex n : c->surface.nodes)
      for (int d = 0; d < dim_; ++d) gathered.push_back(n * dim_ + d);
    const ContactGeometry geometry = ci.geometry != ContactGeometry::automatic ? ci.geometry
                                     : input.model.strain == StrainKind::small
                                         ? ContactGeometry::reference
                                         : ContactGeometry::current;
    c->current_geometry = geometry == ContactGeometry::current && ci.type != ContactKind::tied;
    if (!c->current_geometry) {
      std::vector<std::array<double, 3>> X(c->surface.nodes.size(), {0.0, 0.0, 0.0});
      for (std::size_t i = 0; i < X.size(); ++i)
        for (int d = 0; d < dim_; ++d) X[i][d] = mesh.coordinates[c->surface.nodes[i] * dim_ + d];
      ContactMortarOptions reference_options = c->options;
      reference_options.derivatives = false;
      c->reference = evaluate_contact_mortar(c->surface, X, reference_options);
    }
    c->c_t_hat = ci.c_t > 0.0 ? ci.c_t : c->c_hat;
    c->old_positions.assign(c->surface.nodes.size(), {0.0, 0.0, 0.0});
    for (std::size_t i = 0; i < c->surface.nodes.size(); ++i)
      for (int d = 0; d < dim_; ++d)
        c->old_positions[i][d] = mesh.coordinates[c->surface.nodes[i] * dim_ + d];
    c->positions = c->old_positions;
    c->slip_increment.assign(n_slave, {0.0, 0.0, 0.0});
    c->slip_accumulated.assign(n_slave, {0.0, 0.0, 0.0});
    c->tangents.assign(n_slave, {});
    interfaces_.push_back(std::move(c));
  }
  const auto comm = solid.comm();
  map_ = Teuchos::rcp(new Map(next_lambda, owned.data(), owned.size(), 0, comm));
  std::sort(gathered.begin(), gathered.end());
  gathered.erase(std::unique(gathered.begin(), gathered.end()), gathered.end());
  gathered_map_ = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                       gathered.data(), gathered.size(), 0, comm));
  gather_ = Teuchos::rcp(new Import(map_, gathered_map_));
  u_ = solid.create_vector();
  f_int_ = solid.create_vector();
  f_ext_ = solid.create_vector();
  reaction_ = solid.create_vector();
  K_solid_ = solid.create_matrix();
  prescribed_.assign(num_u_, std::numeric_limits<double>::quiet_NaN());
}

MechanicsProblem::~MechanicsProblem() = default;

void MechanicsProblem::begin_step(double t, Vector& x) {
  prescribed_ = solid_.prescribed_displacements(t);
  solid_.external_force(t, *f_ext_);
  auto xv = x.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (int i = 0; i < num_owned_u_; ++i) {
    const double value = prescribed_[map_->getGlobalElement(i)];
    if (!std::isnan(value)) xv(i, 0) = value;
  }
}

void MechanicsProblem::displacement(const Vector& x, Vector& u) const {
  const auto xv = x.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto uv = u.getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (int i = 0; i < num_owned_u_; ++i) uv(i, 0) = xv(i, 0);
}

void MechanicsProblem::add_entry(GO row, GO col, double value) {
  if (value == 0.0 || map_->getLocalElement(row) == Teuchos::OrdinalTraits<LO>::invalid()) return;
  entry_rows_.push_back(row);
  entry_cols_.push_back(col);
  entry_values_.push_back(value);
}

bool MechanicsProblem::residual(const Vector& x, Vector& F) {
  displacement(x, *u_);
  {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("grout: solid assembly"));
    // A collapsed element (finite strain) on any rank: every rank backs off together.
    const int ok_here = solid_.assemble(*u_, *f_int_, K_solid_.get()) ? 1 : 0;
    int ok_all = 0;
    Teuchos::reduceAll(*solid_.comm(), Teuchos::REDUCE_MIN, ok_here, Teuchos::outArg(ok_all));
    if (!ok_all) return false;
  }
  {
    auto Fv = F.getLocalViewHost(Tpetra::Access::OverwriteAll);
    const auto fi = f_int_->getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto fe = f_ext_->getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t i = 0; i < Fv.extent(0); ++i)
      Fv(i, 0) = int(i) < num_owned_u_ ? fi(i, 0) - fe(i, 0) : 0.0;
  }
  entry_rows_.clear(), entry_cols_.clear(), entry_values_.clear();
  if (!interfaces_.empty()) {
    Teuchos::TimeMonitor timer(
        *Teuchos::TimeMonitor::getNewTimer("grout: contact (search, integration, assembly)"));
    Vector x_gathered(gathered_map_);
    x_gathered.doImport(x, *gather_, Tpetra::INSERT);
    active_size_ = active_changes_ = 0;
    contact_floor2_ = 0.0;
    for (auto& c : interfaces_) evaluate_interface(*c, x_gathered, F);
  }
  {
    const double eps = std::numeric_limits<double>::epsilon();
    const double f_floor = eps * f_int_->norm2();            // collective
    const double solid_floor = solid_.round_off_estimate();  // collective; 0 for small strain
    residual_floor_ = std::sqrt(f_floor * f_floor + solid_floor * solid_floor + contact_floor2_);
  }
  // Reactions, then the prescribed rows drop out.
  {
    auto Fv = F.getLocalViewHost(Tpetra::Access::ReadWrite);
    auto rv = reaction_->getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (int i = 0; i < num_owned_u_; ++i) {
      const bool fixed = !std::isnan(prescribed_[map_->getGlobalElement(i)]);
      rv(i, 0) = fixed ? Fv(i, 0) : 0.0;
      if (fixed) Fv(i, 0) = 0.0;
    }
  }
  return std::isfinite(F.norm2());
}

// Contact contributions of one interface to F (owned rows) and to the Jacobian entries.
// Every rank evaluates the whole interface (replicated) and keeps its own rows.
void MechanicsProblem::evaluate_interface(Interface& c, const Vector& x_gathered, Vector& F) {
  const ContactSurface& s = c.surface;
  const int dim = dim_;
  const auto xg = x_gathered.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto value_of = [&](GO gid) { return xg(gathered_map_->getLocalElement(gid), 0); };
  std::vector<std::array<double, 3>> x(s.nodes.size(), {0.0, 0.0, 0.0});
  for (std::size_t i = 0; i < s.nodes.size(); ++i)
    for (int d = 0; d < dim; ++d)
      x[i][d] = mesh_.coordinates[s.nodes[i] * dim + d] + value_of(s.nodes[i] * dim + d);
  const bool tied = c.input.type == ContactKind::tied;
  const ContactMortar mortar =
      c.current_geometry ? evaluate_contact_mortar(s, x, c.options) : ContactMortar();
  const ContactMortar& m = c.current_geometry ? mortar : c.reference;
  c.positions = x;
  for (std::size_t j = 0; j < m.frames.size(); ++j)
    for (int k = 0; k < dim - 1; ++k)
      for (int a = 0; a < 3; ++a) c.tangents[j][k][a] = m.frames[j].t[k][a];

  auto Fv = F.getLocalViewHost(Tpetra::Access::ReadWrite);
  const auto add_F = [&](GO row, double v) {
    const LO lid = map_->getLocalElement(row);
    if (lid != Teuchos::OrdinalTraits<LO>::invalid()) Fv(lid, 0) += v;
  };
  const auto position = [&](GlobalIndex node, int d) {
    return x[std::lower_bound(s.nodes.begin(), s.nodes.end(), node) - s.nodes.begin()][d];
  };
  double D_max = 0.0;
  for (const auto& D : m.D) D_max = std::max(D_max, D.value);
  const double D_tol = 1e-8 * D_max;

  const int n_slave = int(s.slave_nodes.size());
  for (int j = 0; j < n_slave; ++j)
    for (int d = 0; d < dim; ++d) c.lambda[j][d] = value_of(c.lambda_gid(j, d));

  // Contact forces f¹_k = D_kk λ_k, f²_l = −Σ_j M_jl λ_j.
  for (int j = 0; j < n_slave; ++j) {
    const GlobalIndex node = s.slave_nodes[j];
    const MortarValue& D = m.D[j];
    for (int a = 0; a < dim; ++a) {
      const GO row = node * dim + a;
      add_F(row, D.value * c.lambda[j][a]);
      add_entry(row, c.lambda_gid(j, a), D.value);
      for (const auto& [dof, dv] : D.gradient) add_entry(row, dof, c.lambda[j][a] * dv);
    }
  }
  for (const auto& [key, M] : m.M) {
    const auto [j, master] = key;
    for (int a = 0; a < dim; ++a) {
      const GO row = master * dim + a;
      add_F(row, -M.value * c.lambda[j][a]);
      add_entry(row, c.lambda_gid(j, a), -M.value);
      for (const auto& [dof, dv] : M.gradient) add_entry(row, dof, -c.lambda[j][a] * dv);
    }
  }

  // Multiplier rows.
  auto m_begin = m.M.begin();
  for (int j = 0; j < n_slave; ++j) {
    const GlobalIndex node = s.slave_nodes[j];
    const double D = m.D[j].value;
    auto m_end = m_begin;
    while (m_end != m.M.end() && m_end->first.first == j) ++m_end;
    c.previous_active[j] = c.active[j];
    c.active[j] = 0;
    c.pressure[j] = c.gap[j] = 0.0;
    if (D <= D_tol) {  // no master facing this node: λ_j = 0
      for (int a = 0; a < dim; ++a) {
        add_F(c.lambda_gid(j, a), c.lambda[j][a]);
        add_entry(c.lambda_gid(j, a), c.lambda_gid(j, a), 1.0);
      }
      m_begin = m_end;
      continue;
    }
    // Round-off of node j's rows where they carry ĉ × (a gap or a slip): ε ĉ |X_j| each.
    const auto add_floor = [&] {
      double x_max = 0.0;
      for (int a = 0; a < dim; ++a)
        x_max = std::max(x_max, std::abs(mesh_.coordinates[node * dim + a]));
      const double row =
          std::numeric_limits<double>::epsilon() * std::max(c.c_hat, c.c_t_hat) * x_max;
      contact_floor2_ += dim * row * row;
    };
    if (tied) {  // ĉ (D u¹_j − Σ_l M_jl u²_l) / D = 0, per component
      c.active[j] = 1;
      add_floor();
      for (int a = 0; a < dim; ++a) {
        const GO row = c.lambda_gid(j, a);
        double v = D * value_of(node * dim + a);
        add_entry(row, node * dim + a, c.c_hat);
        for (auto it = m_begin; it != m_end; ++it) {
          const GlobalIndex l = it->first.second;
          v -= it->second.value * value_of(l * dim + a);
          add_entry(row, l * dim + a, -c.c_hat * it->second.value / D);
        }
        add_F(row, c.c_hat * v / D);
      }
      m_begin = m_end;
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
      lambda_n += fr.n[a] * c.lambda[j][a];
    }
    const double gap = g_tilde / D;
    c.gap[j] = gap;
    c.pressure[j] = lambda_n;
    // Active if λ_n − ĉ g > 0; a closed gap with no pressure yet (λ_n = g = 0, the usual
    // start) counts as active, within round-off of ĉ g, so that touching bodies are supported.
    const double augmented = lambda_n - c.c_hat * gap;
    if (augmented < -c.active_tolerance) {  // inactive: λ_j = 0
      for (int a = 0; a < dim; ++a) {
        add_F(c.lambda_gid(j, a), c.lambda[j][a]);
        add_entry(c.lambda_gid(j, a), c.lambda_gid(j, a), 1.0);
      }
      c.slip_increment[j] = {0.0, 0.0, 0.0};
      m_begin = m_end;
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
    const GO row = c.lambda_gid(j, 0);
    add_F(row, c.c_hat * gap);
    emit(row, dg, c.c_hat);

    // Tangential multipliers λ_τk = τ_k·λ and their gradients (λ dofs and dτ_k).
    double lambda_t[2] = {0.0, 0.0};
    SparseGradient dlambda_t[2];
    for (int k = 0; k < dim - 1; ++k) {
      for (int a = 0; a < dim; ++a) {
        lambda_t[k] += fr.t[k][a] * c.lambda[j][a];
        dlambda_t[k].emplace_back(c.lambda_gid(j, a), fr.t[k][a]);
        for (const auto& [dof, dt] : fr.dt[k][a])
          dlambda_t[k].emplace_back(dof, c.lambda[j][a] * dt);
      }
      compress_gradient(dlambda_t[k]);
    }
    if (c.input.type == ContactKind::frictionless) {  // τ_k·λ = 0
      c.active[j] = 2;
      for (int k = 0; k < dim - 1; ++k) {
        add_F(c.lambda_gid(j, k + 1), lambda_t[k]);
        emit(c.lambda_gid(j, k + 1), dlambda_t[k], 1.0);
      }
      m_begin = m_end;
      continue;
    }

    // Coulomb friction (Hüeber, Stadler, Wohlmuth 2008; DESIGN.md §2), per unit D_jj:
    // slip increment ū_k = τ_k·w / D, w = D Δx_j − Σ_l M_jl Δx_l (Δ since the last converged
    // step), ξ = λ_τ + c_t ū, s = λ_n − ĉ g.
    //   stick (|ξ| < μ s):  c_t ū = 0;
    //   slip:               λ_τ − μ s ξ/|ξ| = 0   (the NCP divided by |ξ| > 0).
    double w[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < dim; ++a) w[a] = D * (position(node, a) - c.old_position(node, a));
    for (auto it = m_begin; it != m_end; ++it)
      for (int a = 0; a < dim; ++a)
        w[a] -= it->second.value *
                (position(it->first.second, a) - c.old_position(it->first.second, a));
    double slip[2] = {0.0, 0.0}, xi[2] = {0.0, 0.0}, xi_norm = 0.0;
    SparseGradient dslip[2];
    for (int k = 0; k < dim - 1; ++k) {
      const double r = 1.0 / D;
      for (int a = 0; a < dim; ++a) {
        slip[k] += r * fr.t[k][a] * w[a];
        for (const auto& [dof, dt] : fr.dt[k][a]) dslip[k].emplace_back(dof, r * w[a] * dt);
        dslip[k].emplace_back(node * dim + a, fr.t[k][a]);
      }
      double t_dx = 0.0;  // τ_k·Δx_j
      for (int a = 0; a < dim; ++a)
        t_dx += fr.t[k][a] * (position(node, a) - c.old_position(node, a));
      for (const auto& [dof, dD] : m.D[j].gradient)
        dslip[k].emplace_back(dof, r * (t_dx - slip[k]) * dD);
      for (auto it = m_begin; it != m_end; ++it) {
        const GlobalIndex l = it->first.second;
        double t_dxl = 0.0;
        for (int a = 0; a < dim; ++a) {
          t_dxl += fr.t[k][a] * (position(l, a) - c.old_position(l, a));
          dslip[k].emplace_back(l * dim + a, -r * fr.t[k][a] * it->second.value);
        }
        for (const auto& [dof, dM] : it->second.gradient)
          dslip[k].emplace_back(dof, -r * t_dxl * dM);
      }
      compress_gradient(dslip[k]);
      xi[k] = lambda_t[k] + c.c_t_hat * slip[k];
      xi_norm += xi[k] * xi[k];
    }
    xi_norm = std::sqrt(xi_norm);
    for (int k = 0; k < dim - 1; ++k) c.slip_increment[j][k] = slip[k];
    const double mu = c.input.friction_coefficient;
    // Stick includes |ξ| = μ s: at the start of a step (λ = 0, no slip) every node starts
    // stuck, the usual initial guess; starting in slip leaves a body held by friction alone
    // without tangential stiffness (a singular Jacobian). μ = 0 always slips (frictionless).
    if (mu > 0.0 && xi_norm <= mu * (augmented + c.active_tolerance)) {  // stick
      c.active[j] = 1;
      for (int k = 0; k < dim - 1; ++k) {
        add_F(c.lambda_gid(j, k + 1), c.c_t_hat * slip[k]);
        emit(c.lambda_gid(j, k + 1), dslip[k], c.c_t_hat);
      }
    } else {  // slip: λ_τ − μ s ξ̂, d = dλ_τ − μ ξ̂ ds − μ s (I − ξ̂ξ̂ᵀ)/|ξ| dξ
      c.active[j] = 2;
      SparseGradient ds = dg;  // ds = dλ_n − ĉ dg
      for (auto& [dof, value] : ds) value *= -c.c_hat;
      for (int a = 0; a < dim; ++a) {
        ds.emplace_back(c.lambda_gid(j, a), fr.n[a]);
        for (const auto& [dof, dn] : fr.dn[a]) ds.emplace_back(dof, c.lambda[j][a] * dn);
      }
      compress_gradient(ds);
      double xi_hat[2] = {0.0, 0.0};
      if (xi_norm > 0.0)
        for (int k = 0; k < dim - 1; ++k) xi_hat[k] = xi[k] / xi_norm;
      for (int k = 0; k < dim - 1; ++k) {
        const GO trow = c.lambda_gid(j, k + 1);
        add_F(trow, lambda_t[k] - mu * augmented * xi_hat[k]);
        emit(trow, dlambda_t[k], 1.0);
        emit(trow, ds, -mu * xi_hat[k]);
        if (xi_norm > 0.0 && dim == 3) {  // the direction's derivative (none in 2D)
          for (int m2 = 0; m2 < dim - 1; ++m2) {
            const double P = ((k == m2 ? 1.0 : 0.0) - xi_hat[k] * xi_hat[m2]) / xi_norm;
            emit(trow, dlambda_t[m2], -mu * augmented * P);
            emit(trow, dslip[m2], -mu * augmented * P * c.c_t_hat);
          }
        }
      }
    }
    m_begin = m_end;
  }
  for (int j = 0; j < n_slave; ++j) {
    active_size_ += c.active[j] != 0;
    active_changes_ += c.active[j] != c.previous_active[j];
  }
}

bool MechanicsProblem::jacobian(const Vector&, Teuchos::RCP<Matrix>& J) {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("grout: jacobian (u, lambda)"));
  const LO n_rows = LO(map_->getNodeNumElements());
  std::vector<std::size_t> counts(n_rows, 0);
  const auto& K_row_map = *K_solid_->getRowMap();
  for (LO i = 0; i < num_owned_u_; ++i) counts[i] = K_solid_->getNumEntriesInLocalRow(i);
  for (GO row : entry_rows_) ++counts[map_->getLocalElement(row)];
  for (LO i = num_owned_u_; i < n_rows; ++i) ++counts[i];  // the λ diagonal below
  J = Teuchos::rcp(new Matrix(map_, Teuchos::ArrayView<const std::size_t>(counts)));

  const auto& col_map = *K_solid_->getColMap();
  const auto local = K_solid_->getLocalMatrixHost();
  std::vector<GO> cols;
  std::vector<double> vals;
  for (LO i = 0; i < num_owned_u_; ++i) {
    cols.clear(), vals.clear();
    for (auto p = local.graph.row_map(i); p < local.graph.row_map(i + 1); ++p) {
      cols.push_back(col_map.getGlobalElement(local.graph.entries(p)));
      vals.push_back(local.values(p));
    }
    J->insertGlobalValues(K_row_map.getGlobalElement(i), Teuchos::ArrayView<const GO>(cols),
                          Teuchos::ArrayView<const double>(vals));
  }
  for (std::size_t e = 0; e < entry_rows_.size(); ++e)
    J->insertGlobalValues(entry_rows_[e], Teuchos::ArrayView<const GO>(&entry_cols_[e], 1),
                          Teuchos::ArrayView<const double>(&entry_values_[e], 1));
  for (LO i = num_owned_u_; i < n_rows; ++i) {  // keep a diagonal entry in every λ row
    const GO g = map_->getGlobalElement(i);
    const double zero = 0.0;
    J->insertGlobalValues(g, Teuchos::ArrayView<const GO>(&g, 1),
                          Teuchos::ArrayView<const double>(&zero, 1));
  }
  J->fillComplete(map_, map_);

  // Prescribed dofs: rows and columns eliminated, diagonal kept (their update is zero).
  const auto& jc = *J->getColMap();
  std::vector<double> delta(jc.getNodeNumElements(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t c = 0; c < delta.size(); ++c) {
    const GO g = jc.getGlobalElement(LO(c));
    if (g < num_u_ && !std::isnan(prescribed_[g])) delta[c] = 0.0;
  }
  Vector rhs(map_);
  apply_dirichlet(*J, rhs, delta);
  return true;
}

std::vector<std::pair<GO, GO>> MechanicsProblem::multiplier_pairing() const {
  std::vector<std::pair<GO, GO>> pairs;
  for (const auto& c : interfaces_)
    for (std::size_t j = 0; j < c->surface.slave_nodes.size(); ++j)
      for (int d = 0; d < dim_; ++d)
        pairs.emplace_back(c->lambda_gid(int(j), d), GO(c->surface.slave_nodes[j]) * dim_ + d);
  return pairs;
}

std::vector<GlobalIndex> MechanicsProblem::slave_nodes() const {
  std::vector<GlobalIndex> nodes;
  for (const auto& c : interfaces_)
    nodes.insert(nodes.end(), c->surface.slave_nodes.begin(), c->surface.slave_nodes.end());
  return nodes;
}

void MechanicsProblem::commit_step() {
  for (auto& c : interfaces_) {
    for (std::size_t j = 0; j < c->slip_accumulated.size(); ++j)
      for (int k = 0; k < dim_ - 1; ++k)
        for (int a = 0; a < dim_; ++a)
          c->slip_accumulated[j][a] += c->slip_increment[j][k] * c->tangents[j][k][a];
    for (auto& increment : c->slip_increment) increment = {0.0, 0.0, 0.0};
    c->old_positions = c->positions;
  }
}

ContactFields MechanicsProblem::contact_fields() const {
  ContactFields out;
  const std::size_t n = mesh_.num_nodes();
  out.pressure.assign(n, 0.0);
  out.gap.assign(n, 0.0);
  out.status.assign(n, 0.0);
  out.lm.assign(dim_, std::vector<double>(n, 0.0));
  out.slip.assign(dim_, std::vector<double>(n, 0.0));
  for (const auto& c : interfaces_) {
    for (std::size_t j = 0; j < c->surface.slave_nodes.size(); ++j) {
      const GlobalIndex node = c->surface.slave_nodes[j];
      out.pressure[node] = c->pressure[j];
      out.gap[node] = c->gap[j];
      out.status[node] = c->active[j];
      for (int d = 0; d < dim_; ++d) {
        out.lm[d][node] = c->lambda[j][d];
        out.slip[d][node] = c->slip_accumulated[j][d];
        for (int k = 0; k < dim_ - 1; ++k)  // this step's increment, not yet committed
          out.slip[d][node] += c->slip_increment[j][k] * c->tangents[j][k][d];
      }
      out.active_nodes += c->active[j] != 0;
    }
  }
  return out;
}

}  // namespace grout
