#include "nonlinear/mechanics_problem.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <cmath>
#include <limits>
#include <map>

#include "assembly/agree_on_errors.hpp"
#include "assembly/contact_distribution.hpp"
#include "assembly/raw_mpi_comm.hpp"
#include "assembly/weighted_slip.hpp"
#include "io/errors.hpp"
#include "nonlinear/dirichlet.hpp"
#include "nonlinear/first_update_closures.hpp"
#include "nonlinear/jacobian_matrix.hpp"

namespace grout {

struct MechanicsProblem::Interface {
  ContactSurface surface;     ///< this rank's slave faces; master faces of the last search
  SurfaceFaces owned_master;  ///< master faces this rank owns (sent in the parallel search)
  ContactInput input;
  int index = 0;                 ///< in the input's contact list
  std::vector<int> owned;        ///< indices in surface.slave_nodes of the owned slave nodes
  GO lambda_offset = 0;          ///< GID of the interface's first multiplier
  std::vector<GO> lambda_index;  ///< per owned slave node: its index among all slave nodes
  int dim = 2;
  double c_hat = 1.0;
  double active_tolerance = 0.0;  ///< on λ_n − ĉ g: 1e-10 E
  std::vector<double> proximity;  ///< per owned slave node: ContactInput::start_gap × face size
  double c_t_hat = 1.0;           ///< c_t: like ĉ unless the input sets it
  double hold = 0.0;              ///< Newton step's tangential hold per unit D_jj: κ E/h
  ContactMortarOptions options;
  bool current_geometry = false;  ///< normals, D, M on the current configuration
  ContactMortar reference;        ///< D, M and normals of the reference configuration
  /// The (slave face, master face) pairs `reference` was integrated over.
  std::vector<std::pair<GlobalIndex, GlobalIndex>> reference_pairs;
  // Per node of surface.nodes at the last evaluation: reference coordinates, displacement,
  // displacement of the last converged step.
  std::vector<std::array<double, 3>> X, u, u_old;
  // Per owned slave node: results of the last evaluation and the slip history.
  std::vector<double> pressure, gap;
  std::vector<double> iterate_gap;  ///< g_j at the last evaluation (if gap_known)
  std::vector<char> gap_known;      ///< node j had a master at the last evaluation
  std::vector<char> held_in_step;   ///< held back (inactive) once in this step already
  std::vector<std::array<double, 3>> lambda;
  std::vector<char> active, previous_active;
  std::vector<char> committed_active;  ///< active at the last converged state (commit_step)
  std::vector<double> step_energy;     ///< e_j of ContactStepEnergy at the last evaluation
  std::vector<char> closing;           ///< active at the last evaluation, not committed_active
  std::vector<std::array<double, 3>> slip_increment;           ///< ū_k of the step
  std::vector<std::array<double, 3>> slip_accumulated;         ///< Σ ū_k τ_k (vector)
  std::vector<std::array<std::array<double, 3>, 2>> tangents;  ///< τ_k
  // Current geometry, per owned slave node: D_jj and M_jl of the last converged step (the
  // objective slip's D_n, M_n) and of the last evaluation; set at the first evaluation.
  std::vector<MortarRowHistory> history, last_rows;
  bool history_set = false;

  GO lambda_gid(int q, int c) const { return lambda_offset + lambda_index[q] * dim + c; }
  std::size_t position_of(GlobalIndex node) const {
    return std::size_t(std::lower_bound(surface.nodes.begin(), surface.nodes.end(), node) -
                       surface.nodes.begin());
  }
};

namespace {

// Young's modulus of the material of the block of the side set's first face.
double youngs_modulus_of(const Input& input, const Mesh& mesh, const std::string& set_name,
                         const ContactInput& contact) {
  const SideSet* set = mesh.find_side_set(set_name);  // checked by build_local_contact_surface
  const ElementBlock& block = *mesh.block_of(set->elements.front());
  if (const MaterialInput* m = find_material(input, block)) return m->youngs_modulus;
  throw InputError(input.file + ": grout/contact/" + contact.name + ": no material on block '" +
                   block.name + "'");
}

}  // namespace

MechanicsProblem::MechanicsProblem(const SolidProblem& solid, const Mesh& mesh, const Input& input)
    : solid_(solid), mesh_(mesh), input_(input), dim_(mesh.dimension) {
  num_u_ = GO(mesh.num_nodes()) * dim_;
  const auto& owned_u = *solid.owned_map();
  const auto comm = solid.comm();
  raw_comm_ = raw_mpi_comm(*comm);
  num_owned_u_ = int(owned_u.getNodeNumElements());
  std::vector<GO> owned;
  for (int i = 0; i < num_owned_u_; ++i) owned.push_back(owned_u.getGlobalElement(i));
  const auto owns = [&](GlobalIndex node) { return owned_u.isNodeGlobalElement(node * dim_); };

  // Interfaces: this rank's part of the surfaces, multipliers (numbered by slave node, as
  // on one rank: the sorted slave nodes of the side set), penalty-like scaling ĉ.
  GO next_lambda = num_u_;
  std::vector<GO> base;  // displacement dofs of the nodes of local faces
  for (const ContactInput& ci : input.contact) {
    auto c = std::make_unique<Interface>();
    LocalContactFaces local = build_local_contact_surface(mesh, input, ci, owns);
    GlobalIndex shared =
        local.shared_node < 0 ? std::numeric_limits<GlobalIndex>::max() : local.shared_node;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, 1, &shared, &local.shared_node);
    if (local.shared_node != std::numeric_limits<GlobalIndex>::max())
      throw InputError(shared_node_message(input, ci, local.shared_node));
    c->surface = std::move(local.surface);
    c->owned_master = std::move(local.owned_master);
    c->input = ci;
    c->index = int(interfaces_.size());
    c->dim = dim_;
    const ContactSurface& s = c->surface;
    const std::vector<GlobalIndex> all_slave = side_set_nodes(mesh, ci.slave);
    for (std::size_t j = 0; j < s.slave_nodes.size(); ++j) {
      if (!owns(s.slave_nodes[j])) continue;
      c->owned.push_back(int(j));
      c->lambda_index.push_back(
          std::lower_bound(all_slave.begin(), all_slave.end(), s.slave_nodes[j]) -
          all_slave.begin());
    }
    const int n_owned = int(c->owned.size());
    c->lambda_offset = next_lambda;
    next_lambda += GO(all_slave.size()) * dim_;
    for (int q = 0; q < n_owned; ++q)
      for (int d = 0; d < dim_; ++d) owned.push_back(c->lambda_gid(q, d));

    const double E1 = youngs_modulus_of(input, mesh, ci.slave, ci);
    const double E2 = youngs_modulus_of(input, mesh, ci.master, ci);
    c->c_hat = ci.c_n > 0.0 ? ci.c_n : 2.0 / (1.0 / E1 + 1.0 / E2) / mean_face_size(mesh, ci.slave);
    c->active_tolerance = 1e-10 * 2.0 / (1.0 / E1 + 1.0 / E2);
    c->proximity.assign(n_owned, 0.0);  // start_gap × the mean size of the node's faces
    for (int q = 0; q < n_owned; ++q) {
      const auto& faces = s.slave_node_faces[c->owned[q]];
      for (int f : faces)
        c->proximity[q] += face_size(mesh, s.slave.nodes[f].data(), s.slave.num_nodes[f]);
      if (!faces.empty()) c->proximity[q] *= ci.start_gap / double(faces.size());
    }
    c->c_t_hat = ci.c_t > 0.0 ? ci.c_t : c->c_hat;
    // κ = 1e-11 of the default ĉ (not of an input c_n: the iterates must not depend on it).
    c->hold = 1e-11 * 2.0 / (1.0 / E1 + 1.0 / E2) / mean_face_size(mesh, ci.slave);
    // Collocation points: per slave element (2D) or per direction (3D); 20 unless the input
    // sets them.
    c->options.mortar = mortar_options(dim_,
                                       ci.integration == ContactIntegration::collocation
                                           ? MortarIntegration::collocation
                                           : MortarIntegration::exact,
                                       ci.collocation_points > 0 ? ci.collocation_points : 20);
    const ContactGeometry geometry = ci.geometry != ContactGeometry::automatic ? ci.geometry
                                     : input.model.strain == StrainKind::small
                                         ? ContactGeometry::reference
                                         : ContactGeometry::current;
    c->current_geometry = geometry == ContactGeometry::current && ci.type != ContactKind::tied;

    c->pressure.assign(n_owned, 0.0);
    c->gap.assign(n_owned, 0.0);
    c->iterate_gap.assign(n_owned, 0.0);
    c->gap_known.assign(n_owned, 0);
    c->held_in_step.assign(n_owned, 0);
    c->lambda.assign(n_owned, {0.0, 0.0, 0.0});
    c->active.assign(n_owned, 0);
    c->previous_active.assign(n_owned, 0);
    c->committed_active.assign(n_owned, 0);
    c->step_energy.assign(n_owned, 0.0);
    c->closing.assign(n_owned, 0);
    c->slip_increment.assign(n_owned, {0.0, 0.0, 0.0});
    c->slip_accumulated.assign(n_owned, {0.0, 0.0, 0.0});
    c->tangents.assign(n_owned, {});
    c->history.assign(n_owned, {});
    c->last_rows.assign(n_owned, {});
    for (GlobalIndex n : s.slave_nodes)
      for (int d = 0; d < dim_; ++d) base.push_back(n * dim_ + d);
    for (std::size_t f = 0; f < c->owned_master.size(); ++f)
      for (int a = 0; a < c->owned_master.num_nodes[f]; ++a)
        for (int d = 0; d < dim_; ++d) base.push_back(c->owned_master.nodes[f][a] * dim_ + d);

    if (!c->current_geometry) {  // D, M and normals once, at zero displacement
      ghost_master_faces_of(*c, nullptr, nullptr);
      std::vector<std::array<double, 3>> X = c->X;
      ContactMortarOptions reference_options = c->options;
      reference_options.derivatives = false;
      c->reference = evaluate_contact_mortar(c->surface, X, reference_options);
      c->reference_pairs = contact_pairs(c->surface, X, reference_options);
    }
    interfaces_.push_back(std::move(c));
  }
  // A slave node carries one multiplier: two pairs must not share slave nodes. Each rank checks
  // the slave nodes it owns; every rank agrees on the outcome.
  agree_on_errors(*comm, [&] {
    std::map<GlobalIndex, const Interface*> slave_pair;
    for (const auto& c : interfaces_) {
      for (int j : c->owned) {
        const GlobalIndex n = c->surface.slave_nodes[j];
        const auto [it, fresh] = slave_pair.emplace(n, c.get());
        if (!fresh) {
          throw InputError(input.file + ": grout/contact/" + c->input.name + "/slave: side set '" +
                           c->input.slave + "' shares node " + std::to_string(n + 1) +
                           " with the slave side of grout/contact/" + it->second->input.name +
                           " (a slave node belongs to one contact pair)");
        }
      }
    }
  });
  map_ = Teuchos::rcp(new Map(next_lambda, owned.data(), owned.size(), 0, comm));
  std::sort(base.begin(), base.end());
  base.erase(std::unique(base.begin(), base.end()), base.end());
  base_map_ = Teuchos::rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                   base.data(), base.size(), 0, comm));
  base_import_ = Teuchos::rcp(new Import(map_, base_map_));
  x_last_ = Teuchos::rcp(new Vector(map_));
  x_old_ = Teuchos::rcp(new Vector(map_));
  u_ = solid.create_vector();
  f_int_ = solid.create_vector();
  f_ext_ = solid.create_vector();
  reaction_ = solid.create_vector();
  K_solid_ = solid.create_matrix();
  prescribed_.assign(num_u_, std::numeric_limits<double>::quiet_NaN());
}

MechanicsProblem::~MechanicsProblem() = default;

void MechanicsProblem::begin_step(double t, Vector& x) {
  step_start_ = true;
  first_update_ = false;
  for (auto& c : interfaces_) std::fill(c->held_in_step.begin(), c->held_in_step.end(), 0);
  // The load expressions are evaluated on each rank's own faces: a value that is not finite
  // on one rank stops every rank.
  agree_on_errors(*solid_.comm(), [&] {
    prescribed_ = solid_.prescribed_displacements(t);
    solid_.external_force(t, *f_ext_);
  });
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
  constexpr long long seq_bits = 24;
  const long long seq = entry_seq_++;
  if (seq >= (1LL << seq_bits))
    throw std::logic_error("MechanicsProblem: too many Jacobian entries for one slave node");
  if (value == 0.0) return;
  entry_rows_.push_back(row);  // rows other ranks own are sent to them by jacobian()
  entry_cols_.push_back(col);
  entry_keys_.push_back((entry_tag_ << seq_bits) + seq);
  entry_values_.push_back(value);
}

bool MechanicsProblem::residual(const Vector& x, Vector& F) {
  displacement(x, *u_);
  {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("grout: solid assembly"));
    // Under small strain K_solid is assembled once: later residuals compute f_int alone
    // (the same element loop, so the same f_int bit for bit) and jacobian() reuses K_solid.
    // On the 2D Hertz level-3 case the tangent was 0.4 G of 3.6 G instructions of the run.
    Matrix* const K = K_solid_constant_ ? nullptr : K_solid_.get();
    // A collapsed element (finite strain) on any rank: every rank backs off together.
    const int ok_here = solid_.assemble(*u_, *f_int_, K, solid_step_start_) ? 1 : 0;
    int ok_all = 0;
    Teuchos::reduceAll(*solid_.comm(), Teuchos::REDUCE_MIN, ok_here, Teuchos::outArg(ok_all));
    if (!ok_all) return false;
    if (K) K_solid_constant_ = solid_.tangent_is_constant();
  }
  {
    auto Fv = F.getLocalViewHost(Tpetra::Access::OverwriteAll);
    const auto fi = f_int_->getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto fe = f_ext_->getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t i = 0; i < Fv.extent(0); ++i)
      Fv(i, 0) = int(i) < num_owned_u_ ? fi(i, 0) - fe(i, 0) : 0.0;
  }
  entry_rows_.clear(), entry_cols_.clear(), entry_keys_.clear(), entry_values_.clear();
  force_rows_.clear(), force_tags_.clear(), force_values_.clear();
  x_last_->assign(x);
  double contact_sums[3] = {0.0, 0.0, 0.0};  // active, changes, Σ floor²
  if (!interfaces_.empty()) {
    Teuchos::TimeMonitor timer(
        *Teuchos::TimeMonitor::getNewTimer("grout: contact (search, integration, assembly)"));
    Vector u_base(base_map_), u_old_base(base_map_);
    u_base.doImport(x, *base_import_, Tpetra::INSERT);
    u_old_base.doImport(*x_old_, *base_import_, Tpetra::INSERT);
    active_size_ = active_changes_ = 0;
    contact_floor2_ = 0.0;
    for (auto& c : interfaces_) evaluate_interface(*c, x, u_base, u_old_base, F);
    assemble_contact_forces(F);
    const double local[3] = {double(active_size_), double(active_changes_), contact_floor2_};
    Teuchos::reduceAll(*solid_.comm(), Teuchos::REDUCE_SUM, 3, local, contact_sums);
  }
  active_size_ = int(contact_sums[0]);
  active_changes_ = int(contact_sums[1]);
  contact_floor2_ = contact_sums[2];
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

// The contact terms of the displacement rows: those of other ranks' rows are sent to their
// owners; each owner sums the terms of a row in tag order, then adds the sum to F (one order
// on any number of ranks). Also records the owners for jacobian().
void MechanicsProblem::assemble_contact_forces(Vector& F) {
  std::vector<GO> remote;
  for (GO row : force_rows_)
    if (!map_->isNodeGlobalElement(row)) remote.push_back(row);
  std::sort(remote.begin(), remote.end());
  remote.erase(std::unique(remote.begin(), remote.end()), remote.end());
  std::vector<int> owners(remote.size(), -1);
  map_->getRemoteIndexList(Teuchos::ArrayView<const GO>(remote), Teuchos::ArrayView<int>(owners));
  remote_owner_.clear();
  for (std::size_t k = 0; k < remote.size(); ++k) remote_owner_[remote[k]] = owners[k];

  const int n_ranks = map_->getComm()->getSize();
  std::vector<std::vector<long long>> send_ids(n_ranks);
  std::vector<std::vector<double>> send_values(n_ranks);
  struct Term {
    GO row;
    long long tag;
    double value;
  };
  std::vector<Term> terms;
  for (std::size_t t = 0; t < force_rows_.size(); ++t) {
    if (map_->isNodeGlobalElement(force_rows_[t])) {
      terms.push_back({force_rows_[t], force_tags_[t], force_values_[t]});
      continue;
    }
    const int owner = remote_owner_.at(force_rows_[t]);
    send_ids[owner].push_back(force_rows_[t]);
    send_ids[owner].push_back(force_tags_[t]);
    send_values[owner].push_back(force_values_[t]);
  }
  const std::vector<long long> ids = exchange_with_ranks(send_ids, raw_comm_);
  const std::vector<double> values = exchange_with_ranks(send_values, raw_comm_);
  for (std::size_t t = 0; t < values.size(); ++t)
    terms.push_back({ids[2 * t], ids[2 * t + 1], values[t]});
  std::sort(terms.begin(), terms.end(), [](const Term& a, const Term& b) {
    return a.row < b.row || (a.row == b.row && a.tag < b.tag);
  });
  auto Fv = F.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (std::size_t t = 0; t < terms.size();) {
    const GO row = terms[t].row;
    double sum = 0.0;
    for (; t < terms.size() && terms[t].row == row; ++t) sum += terms[t].value;
    Fv(map_->getLocalElement(row), 0) += sum;
  }
}

// The master faces the slave faces of `c` can touch (parallel coarse search, on the current
// configuration or the reference one), and the reference coordinates, displacements and
// last converged displacements of every node of the local surface. u_base / u_old_base:
// displacements on base_map_ (nullptr: zero).
void MechanicsProblem::ghost_master_faces_of(Interface& c, const Vector* u_base,
                                             const Vector* u_old_base) {
  const int dim = dim_;
  using HostView =
      decltype(std::declval<const Vector&>().getLocalViewHost(Tpetra::Access::ReadOnly));
  HostView ub, uob;
  if (u_base) ub = u_base->getLocalViewHost(Tpetra::Access::ReadOnly);
  if (u_old_base) uob = u_old_base->getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto node_values = [&](GlobalIndex n, double X[3], double u[3], double u_old[3]) {
    for (int d = 0; d < 3; ++d) X[d] = u[d] = u_old[d] = 0.0;
    for (int d = 0; d < dim; ++d) {
      X[d] = mesh_.coordinates[n * dim + d];
      if (!u_base) continue;
      const LO lid = base_map_->getLocalElement(n * dim + d);
      u[d] = ub(lid, 0);
      u_old[d] = uob(lid, 0);
    }
  };
  // Positions to search on: current (X + u) or reference (X).
  const auto search_coordinates = [](bool current, const double X[3], const double u[3],
                                     double x[3]) {
    for (int d = 0; d < 3; ++d) x[d] = current ? X[d] + u[d] : X[d];
  };
  constexpr int payload = 9;  // X, u, u_old per node
  // Owned master faces, and the region of the evaluated slave faces; the master faces that
  // overlap the region, from every rank, searched on the current or the reference positions.
  const auto ghost_faces = [&](bool current) {
    FaceSet owned;
    owned.dimension = dim;
    owned.payload_size = payload;
    for (std::size_t f = 0; f < c.owned_master.size(); ++f) {
      double x[max_face_nodes][3], values[max_face_nodes * payload];
      for (int a = 0; a < c.owned_master.num_nodes[f]; ++a) {
        double* v = values + a * payload;
        node_values(c.owned_master.nodes[f][a], v, v + 3, v + 6);
        search_coordinates(current, v, v + 3, x[a]);
      }
      owned.add(c.owned_master.ids[f], c.owned_master.num_nodes[f], c.owned_master.nodes[f].data(),
                x, values);
    }
    const SurfaceFaces& slave = c.surface.slave;
    FaceSet slave_set;
    slave_set.dimension = dim;
    for (std::size_t f = 0; f < slave.size(); ++f) {
      double x[max_face_nodes][3], X[3], u[3], u_old[3];
      for (int a = 0; a < slave.num_nodes[f]; ++a) {
        node_values(slave.nodes[f][a], X, u, u_old);
        search_coordinates(current, X, u, x[a]);
      }
      slave_set.add(slave.ids[f], slave.num_nodes[f], slave.nodes[f].data(), x);
    }
    return ghost_master_faces(
        owned, search_region(slave_set, c.options.search_factor, c.surface.integrate),
        c.options.search_factor, raw_comm_);
  };
  // The current geometry searches on the current positions. The reference geometry searches
  // on the reference positions and, once there is a displacement, on the current ones too:
  // faces that the load brings together must be paired even if they lie far apart in the
  // reference configuration (evaluate_contact_mortar's search_x).
  FaceSet ghost = ghost_faces(c.current_geometry);
  if (!c.current_geometry && u_base) ghost = merge_face_sets(ghost, ghost_faces(true));

  SurfaceFaces master;
  master.ids = ghost.ids;
  master.nodes = ghost.nodes;
  master.num_nodes = ghost.num_nodes;
  master.blocks.assign(ghost.size(), nullptr);
  set_master_faces(c.surface, std::move(master));
  const std::size_t n = c.surface.nodes.size();
  c.X.assign(n, {0.0, 0.0, 0.0});
  c.u.assign(n, {0.0, 0.0, 0.0});
  c.u_old.assign(n, {0.0, 0.0, 0.0});
  for (GlobalIndex node : c.surface.slave_nodes) {
    const std::size_t i = c.position_of(node);
    node_values(node, c.X[i].data(), c.u[i].data(), c.u_old[i].data());
  }
  for (std::size_t f = 0; f < ghost.size(); ++f) {
    for (int a = 0; a < ghost.num_nodes[f]; ++a) {
      const std::size_t i = c.position_of(ghost.nodes[f][a]);
      const double* v = &ghost.payload[(f * max_face_nodes + a) * payload];
      for (int d = 0; d < 3; ++d) c.X[i][d] = v[d], c.u[i][d] = v[3 + d], c.u_old[i][d] = v[6 + d];
    }
  }
}

// Contact contributions of one interface to F and the Jacobian entries, for the slave nodes
// this rank owns: their multiplier rows (added to F here), their slave and master rows (the
// master rows may belong to other ranks: terms for assemble_contact_forces).
void MechanicsProblem::evaluate_interface(Interface& c, const Vector& x, const Vector& u_base,
                                          const Vector& u_old_base, Vector& F) {
  const int dim = dim_;
  ghost_master_faces_of(c, &u_base, &u_old_base);
  const ContactSurface& s = c.surface;
  const std::size_t n_nodes = s.nodes.size();
  std::vector<std::array<double, 3>> positions(n_nodes, {0.0, 0.0, 0.0});
  for (std::size_t i = 0; i < n_nodes; ++i)
    for (int d = 0; d < dim; ++d) positions[i][d] = c.X[i][d] + c.u[i][d];
  const bool tied = c.input.type == ContactKind::tied;
  if (!c.current_geometry) {
    // Integrated on the reference positions, paired on the reference and current ones: the
    // integration again only when the pairing changed.
    ContactMortarOptions reference_options = c.options;
    reference_options.derivatives = false;
    auto pairs = contact_pairs(s, c.X, reference_options, &positions);
    if (pairs != c.reference_pairs) {
      c.reference = evaluate_contact_mortar(s, c.X, reference_options, &positions);
      c.reference_pairs = std::move(pairs);
    }
  }
  const ContactMortar mortar =
      c.current_geometry ? evaluate_contact_mortar(s, positions, c.options) : ContactMortar();
  const ContactMortar& m = c.current_geometry ? mortar : c.reference;
  const int n_owned = int(c.owned.size());
  for (int q = 0; q < n_owned; ++q)
    for (int k = 0; k < dim - 1; ++k)
      for (int a = 0; a < 3; ++a) c.tangents[q][k][a] = m.frames[c.owned[q]].t[k][a];
  // The rows D_jj, M_jl of the owned slave nodes (objective slip): of this evaluation, and at
  // the first evaluation those of the last converged positions (commit_step moves them on).
  const auto rows_of = [&](const ContactMortar& mm, std::vector<MortarRowHistory>& rows) {
    for (int q = 0; q < n_owned; ++q) {
      const int j = c.owned[q];
      rows[q].D = mm.D[j].value;
      rows[q].M.clear();
      for (auto it = mm.M.lower_bound({j, std::numeric_limits<GlobalIndex>::min()});
           it != mm.M.end() && it->first.first == j; ++it)
        rows[q].M.emplace_back(it->first.second, it->second.value);
    }
  };
  if (c.current_geometry && c.input.type == ContactKind::frictional) {
    if (!c.history_set) {
      std::vector<std::array<double, 3>> old_positions(n_nodes, {0.0, 0.0, 0.0});
      for (std::size_t i = 0; i < n_nodes; ++i)
        for (int d = 0; d < dim; ++d) old_positions[i][d] = c.X[i][d] + c.u_old[i][d];
      ContactMortarOptions old_options = c.options;
      old_options.derivatives = false;
      rows_of(evaluate_contact_mortar(s, old_positions, old_options), c.history);
      c.history_set = true;
    }
    rows_of(m, c.last_rows);
  }

  const auto xv = x.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto Fv = F.getLocalViewHost(Tpetra::Access::ReadWrite);
  const auto add_F_ = [&](GO row, double v) {
    if (row < num_u_) {  // a slave or master row: a term tagged by the slave node
      force_rows_.push_back(row);
      force_tags_.push_back(entry_tag_);
      force_values_.push_back(v);
    } else {  // an owned multiplier row, set once
      Fv(map_->getLocalElement(row), 0) += v;
    }
  };
  const auto begin_node = [&](GlobalIndex node) {
    entry_tag_ = GO(c.index) * GO(mesh_.num_nodes()) + node;
    entry_seq_ = 0;
  };
  const auto pos = [&](GlobalIndex node) { return c.position_of(node); };
  const auto position = [&](GlobalIndex node, int d) { return positions[pos(node)][d]; };
  const auto old_position = [&](GlobalIndex node, int d) {
    const std::size_t i = pos(node);
    return c.X[i][d] + c.u_old[i][d];
  };
  const auto m_range = [&](int j) {
    return m.M.lower_bound({j, std::numeric_limits<GlobalIndex>::min()});
  };
  double D_max = 0.0, D_max_local = 0.0;
  for (int j : c.owned) D_max_local = std::max(D_max_local, m.D[j].value);
  Teuchos::reduceAll(*solid_.comm(), Teuchos::REDUCE_MAX, 1, &D_max_local, &D_max);
  const double D_tol = 1e-8 * D_max;

  for (int q = 0; q < n_owned; ++q)
    for (int d = 0; d < dim; ++d) c.lambda[q][d] = xv(map_->getLocalElement(c.lambda_gid(q, d)), 0);
  // After the step's start: the late-closing nodes held back (first_update_closures.hpp),
  // measured from the last evaluation's gaps.
  std::vector<char> held_back(n_owned, 0);
  if (!tied) {
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
    std::vector<ClosureCandidate> nodes(n_owned);
    for (int q = 0; q < n_owned; ++q) {
      const int j = c.owned[q];
      ClosureCandidate& node = nodes[q];
      node.paired = m.D[j].value > D_tol;
      if (!node.paired) continue;
      node.was_active = c.active[q] != 0;
      node.gap = nodal_gap(j, position);
      // The base of the update: the last evaluation's gap; at the first update a node that
      // had no master then is measured from its last converged position.
      node.gap_old = c.gap_known[q]  ? c.iterate_gap[q]
                     : first_update_ ? nodal_gap(j, old_position)
                                     : 0.0;
      double lambda_n = 0.0;
      for (int a = 0; a < dim; ++a) lambda_n += m.frames[j].n[a] * c.lambda[q][a];
      node.closing = !node.was_active && lambda_n - c.c_hat * node.gap >= -c.active_tolerance;
    }
    if (!step_start_ && c.input.start_closure < 1.0) {
      const ClosureCounts local = count_closures(nodes);
      double sums[2] = {local.active_before, local.closing}, global[2] = {0.0, 0.0};
      Teuchos::reduceAll(*solid_.comm(), Teuchos::REDUCE_SUM, 2, sums, global);
      held_back = held_back_closures(nodes, {global[0], global[1]}, c.input.start_closure);
    }
    // Once per node and step (a held node closes at the next iterate at the latest).
    for (int q = 0; q < n_owned; ++q) {
      if (c.held_in_step[q]) held_back[q] = 0;
      if (held_back[q]) c.held_in_step[q] = 1;
    }
    for (int q = 0; q < n_owned; ++q) {
      c.gap_known[q] = nodes[q].paired;
      c.iterate_gap[q] = nodes[q].gap;
    }
  }

  // Contact forces f¹_k = D_kk λ_k, f²_l = −Σ_j M_jl λ_j (j owned).
  for (int q = 0; q < n_owned; ++q) {
    const int j = c.owned[q];
    const GlobalIndex node = s.slave_nodes[j];
    begin_node(node);
    const MortarValue& D = m.D[j];
    for (int a = 0; a < dim; ++a) {
      const GO row = node * dim + a;
      add_F_(row, D.value * c.lambda[q][a]);
      add_entry(row, c.lambda_gid(q, a), D.value);
      for (const auto& [dof, dv] : D.gradient) add_entry(row, dof, c.lambda[q][a] * dv);
    }
    for (auto it = m_range(j); it != m_range(j + 1); ++it) {
      const GlobalIndex master = it->first.second;
      const MortarValue& M = it->second;
      for (int a = 0; a < dim; ++a) {
        const GO row = master * dim + a;
        add_F_(row, -M.value * c.lambda[q][a]);
        add_entry(row, c.lambda_gid(q, a), -M.value);
        for (const auto& [dof, dv] : M.gradient) add_entry(row, dof, -c.lambda[q][a] * dv);
      }
    }
  }

  // Multiplier rows of the owned slave nodes (q: owned index, j: index in s.slave_nodes).
  for (int q = 0; q < n_owned; ++q) {
    const int j = c.owned[q];
    const GlobalIndex node = s.slave_nodes[j];
    begin_node(node);
    const double D = m.D[j].value;
    const auto m_begin = m_range(j), m_end = m_range(j + 1);
    c.previous_active[q] = c.active[q];
    c.active[q] = 0;
    c.pressure[q] = c.gap[q] = 0.0;
    {  // e_j = −½ λ_j·(D Δx_j − Σ_l M_jl Δx_l), Δ since the last converged state
      double w = 0.0;
      for (int a = 0; a < dim; ++a) {
        double wa = D * (position(node, a) - old_position(node, a));
        for (auto it = m_begin; it != m_end; ++it)
          wa -= it->second.value *
                (position(it->first.second, a) - old_position(it->first.second, a));
        w += c.lambda[q][a] * wa;
      }
      c.step_energy[q] = -0.5 * w;
    }
    if (D <= D_tol) {  // no master facing this node: λ_j = 0
      for (int a = 0; a < dim; ++a) {
        add_F_(c.lambda_gid(q, a), c.lambda[q][a]);
        add_entry(c.lambda_gid(q, a), c.lambda_gid(q, a), 1.0);
      }
      continue;
    }
    // Round-off of node j's rows where they carry ĉ × (a gap or a slip): ε ĉ |X_j| each.
    const auto add_floor = [&] {
      double x_max = 0.0;
      for (int a = 0; a < dim; ++a) x_max = std::max(x_max, std::abs(c.X[pos(node)][a]));
      const double row =
          std::numeric_limits<double>::epsilon() * std::max(c.c_hat, c.c_t_hat) * x_max;
      contact_floor2_ += dim * row * row;
    };
    // True when component a of the slave dof is prescribed and the master dofs node j is
    // tied to carry a share of Σ_l |M_jl| at most `free_share` D where component a is free:
    // D u¹_ja − Σ_l M_jl u²_la then (nearly) involves prescribed values only, and λ_ja acts
    // (nearly) on prescribed rows only, which leaves it undetermined (or determined only
    // through that small share: λ ~ force / share, the update of an ill-conditioned row).
    const auto component_held = [&](int a, double free_share) {
      if (std::isnan(prescribed_[node * dim + a])) return false;
      double free_sum = 0.0;
      for (auto it = m_begin; it != m_end; ++it)
        if (std::isnan(prescribed_[it->first.second * dim + a]))
          free_sum += std::abs(it->second.value);
      return free_sum <= free_share * D;
    };
    if (tied) {  // ĉ (D u¹_j − Σ_l M_jl u²_l) / D = 0, per component
      c.active[q] = 1;
      add_floor();
      for (int a = 0; a < dim; ++a)  // reported only: λ_n = n·λ as for frictional contact
        c.pressure[q] += m.frames[j].n[a] * c.lambda[q][a];
      for (int a = 0; a < dim; ++a) {
        const GO row = c.lambda_gid(q, a);
        // A held component (free share at the round-off 1e-12 D that the integration leaves
        // where M_jl vanishes): the tie constrains prescribed values only, and λ is not
        // determined; λ = 0 as for a node without master (else the round-off row pins a free
        // master dof and λ ~ 1e17; condensed_solve.hpp, kind R).
        if (component_held(a, 1e-12)) {
          add_F_(row, c.lambda[q][a]);
          add_entry(row, row, 1.0);
          continue;
        }
        double v = D * c.u[pos(node)][a];
        add_entry(row, node * dim + a, c.c_hat);
        for (auto it = m_begin; it != m_end; ++it) {
          const GlobalIndex l = it->first.second;
          v -= it->second.value * c.u[pos(l)][a];
          add_entry(row, l * dim + a, -c.c_hat * it->second.value / D);
        }
        add_F_(row, c.c_hat * v / D);
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
      lambda_n += fr.n[a] * c.lambda[q][a];
    }
    const double gap = g_tilde / D;
    c.gap[q] = gap;
    c.pressure[q] = lambda_n;
    // Active if λ_n − ĉ g > 0; a closed gap with no pressure yet (λ_n = g = 0, the usual
    // start) counts as active, within round-off of ĉ g, so that touching bodies are supported.
    // Until the first Newton update of a step, a node with no pressure and a gap below
    // start_gap × its face size (contact input, default 0.05) also counts as active, as
    // Kratos' active check does: a body held only by contact then has its rigid motion fixed
    // by several contact rows from the first solve (with none, K is singular; with one, the
    // first update is a huge rigid motion). From the next iterate on only λ_n − ĉ g decides,
    // so the converged state satisfies the contact conditions exactly.
    const double augmented = lambda_n - c.c_hat * gap;
    const bool near = step_start_ && lambda_n <= 0.0 && gap <= c.proximity[q];
    if ((augmented < -c.active_tolerance && !near) || held_back[q]) {  // inactive: λ_j = 0
      for (int a = 0; a < dim; ++a) {
        add_F_(c.lambda_gid(q, a), c.lambda[q][a]);
        add_entry(c.lambda_gid(q, a), c.lambda_gid(q, a), 1.0);
      }
      c.slip_increment[q] = {0.0, 0.0, 0.0};
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
    const GO row = c.lambda_gid(q, 0);
    add_F_(row, c.c_hat * gap);
    emit(row, dg, c.c_hat);

    // Tangential multipliers λ_τk = τ_k·λ and their gradients (λ dofs and dτ_k).
    double lambda_t[2] = {0.0, 0.0};
    SparseGradient dlambda_t[2];
    for (int k = 0; k < dim - 1; ++k) {
      for (int a = 0; a < dim; ++a) {
        lambda_t[k] += fr.t[k][a] * c.lambda[q][a];
        dlambda_t[k].emplace_back(c.lambda_gid(q, a), fr.t[k][a]);
        for (const auto& [dof, dt] : fr.dt[k][a])
          dlambda_t[k].emplace_back(dof, c.lambda[q][a] * dt);
      }
      compress_gradient(dlambda_t[k]);
    }
    if (c.input.type == ContactKind::frictionless) {  // τ_k·λ = 0
      c.active[q] = 2;
      for (int k = 0; k < dim - 1; ++k) {
        add_F_(c.lambda_gid(q, k + 1), lambda_t[k]);
        emit(c.lambda_gid(q, k + 1), dlambda_t[k], 1.0);
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
        const double spring = c.hold * D;
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
    const bool objective = c.current_geometry && c.history[q].D > D_tol;
    double slip[2] = {0.0, 0.0}, xi[2] = {0.0, 0.0}, xi_norm = 0.0;
    SparseGradient dslip[2];
    weighted_slip_increment(dim, node, fr, m.D[j], m_row, objective ? &c.history[q] : nullptr,
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
      const GO row = c.lambda_gid(q, k + 1);
      add_F_(row, c.lambda[q][held_axis[k]]);
      add_entry(row, c.lambda_gid(q, held_axis[k]), 1.0);
    };
    for (int k = 0; k < dim - 1; ++k) {
      if (held[k]) slip[k] = 0.0;
      xi[k] = held[k] ? 0.0 : lambda_t[k] + c.c_t_hat * slip[k];
      xi_norm += xi[k] * xi[k];
    }
    xi_norm = std::sqrt(xi_norm);
    for (int k = 0; k < dim - 1; ++k) c.slip_increment[q][k] = slip[k];
    const double mu = c.input.friction_coefficient;
    // Stick includes |ξ| = μ s: at the start of a step (λ = 0, no slip) every node starts
    // stuck, the usual initial guess; starting in slip leaves a body held by friction alone
    // without tangential stiffness (a singular Jacobian). μ = 0 always slips (frictionless).
    if (mu > 0.0 && xi_norm <= mu * (augmented + c.active_tolerance)) {  // stick
      c.active[q] = 1;
      for (int k = 0; k < dim - 1; ++k) {
        if (held[k]) {
          emit_held(k);
          continue;
        }
        add_F_(c.lambda_gid(q, k + 1), c.c_t_hat * slip[k]);
        emit(c.lambda_gid(q, k + 1), dslip[k], c.c_t_hat);
      }
    } else {  // slip: λ_τ − μ s ξ̂, d = dλ_τ − μ ξ̂ ds − μ s (I − ξ̂ξ̂ᵀ)/|ξ| dξ
      c.active[q] = 2;
      SparseGradient ds = dg;  // ds = dλ_n − ĉ dg
      for (auto& [dof, value] : ds) value *= -c.c_hat;
      for (int a = 0; a < dim; ++a) {
        ds.emplace_back(c.lambda_gid(q, a), fr.n[a]);
        for (const auto& [dof, dn] : fr.dn[a]) ds.emplace_back(dof, c.lambda[q][a] * dn);
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
        const GO trow = c.lambda_gid(q, k + 1);
        add_F_(trow, lambda_t[k] - mu * augmented * xi_hat[k]);
        emit(trow, dlambda_t[k], 1.0);
        emit(trow, ds, -mu * xi_hat[k]);
        if (xi_norm > 0.0 && dim == 3) {  // the direction's derivative (none in 2D)
          for (int m2 = 0; m2 < dim - 1; ++m2) {
            if (held[m2]) continue;  // P = 0
            const double P = ((k == m2 ? 1.0 : 0.0) - xi_hat[k] * xi_hat[m2]) / xi_norm;
            emit(trow, dlambda_t[m2], -mu * augmented * P);
            emit(trow, dslip[m2], -mu * augmented * P * c.c_t_hat);
          }
        }
      }
    }
  }
  for (int q = 0; q < n_owned; ++q) {
    c.closing[q] = c.active[q] && !c.committed_active[q];
    active_size_ += c.active[q] != 0;
    // A held-back node is a pending change: the iterate cannot be the converged one.
    active_changes_ += c.active[q] != c.previous_active[q] || held_back[q];
  }
}

bool MechanicsProblem::jacobian(const Vector&, Teuchos::RCP<Matrix>& J) {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("grout: jacobian (u, lambda)"));
  // Contact triplets: this rank's rows, then those other ranks computed for its rows (master
  // rows), in rank order.
  std::vector<JacobianTerm> entries;
  if (!interfaces_.empty()) {
    const int n_ranks = map_->getComm()->getSize();
    std::vector<std::vector<long long>> send_ids(n_ranks);
    std::vector<std::vector<double>> send_values(n_ranks);
    for (std::size_t e = 0; e < entry_rows_.size(); ++e) {
      if (map_->isNodeGlobalElement(entry_rows_[e])) {
        entries.push_back({entry_rows_[e], entry_cols_[e], entry_keys_[e], entry_values_[e]});
        continue;
      }
      const int owner = remote_owner_.at(entry_rows_[e]);
      send_ids[owner].insert(send_ids[owner].end(),
                             {entry_rows_[e], entry_cols_[e], entry_keys_[e]});
      send_values[owner].push_back(entry_values_[e]);
    }
    const std::vector<long long> ids = exchange_with_ranks(send_ids, raw_comm_);
    const std::vector<double> received = exchange_with_ranks(send_values, raw_comm_);
    for (std::size_t e = 0; e < received.size(); ++e)
      entries.push_back({ids[3 * e], ids[3 * e + 1], ids[3 * e + 2], received[e]});
  }
  // Each row's terms are summed in key = (slave node, emission) order: one order on any
  // number of ranks.
  J = jacobian_matrix(*K_solid_, map_, entries);

  // Prescribed dofs: rows and columns eliminated, diagonal kept (their update is zero).
  const auto& jc = *J->getColMap();
  std::vector<double> delta(jc.getNodeNumElements(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t c = 0; c < delta.size(); ++c) {
    const GO g = jc.getGlobalElement(LO(c));
    if (g < num_u_ && !std::isnan(prescribed_[g])) delta[c] = 0.0;
  }
  Vector rhs(map_);
  apply_dirichlet(*J, rhs, delta);
  first_update_ = step_start_;  // the next residual is at the first Newton update
  step_start_ = false;
  return true;
}

std::vector<std::pair<GO, GO>> MechanicsProblem::multiplier_pairing() const {
  std::vector<long long> mine;
  for (const auto& c : interfaces_)
    for (std::size_t q = 0; q < c->owned.size(); ++q)
      for (int d = 0; d < dim_; ++d) {
        mine.push_back(c->lambda_gid(int(q), d));
        mine.push_back(GO(c->surface.slave_nodes[c->owned[q]]) * dim_ + d);
      }
  const int n_ranks = map_->getComm()->getSize();
  const std::vector<long long> all =
      exchange_with_ranks(std::vector<std::vector<long long>>(n_ranks, mine), raw_comm_);
  std::vector<std::pair<GO, GO>> pairs;
  for (std::size_t k = 0; k + 1 < all.size(); k += 2) pairs.emplace_back(all[k], all[k + 1]);
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::vector<GlobalIndex> MechanicsProblem::slave_nodes() const {
  std::vector<GlobalIndex> nodes;
  for (const auto& c : interfaces_) {
    const std::vector<GlobalIndex> set = side_set_nodes(mesh_, c->input.slave);
    nodes.insert(nodes.end(), set.begin(), set.end());
  }
  return nodes;
}

ContactStepEnergy MechanicsProblem::contact_step_energy() const {
  // Per interface: the closing and other energies, and its number of slave nodes active at
  // the last converged state (> 0: the closing nodes of the step are a sliding contact's).
  const std::size_t n = interfaces_.size();
  std::vector<double> local(3 * n, 0.0), global(3 * n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& c = *interfaces_[i];
    for (std::size_t q = 0; q < c.owned.size(); ++q) {
      local[3 * i + (c.closing[q] ? 0 : 1)] += c.step_energy[q];
      local[3 * i + 2] += c.committed_active[q] ? 1.0 : 0.0;
    }
  }
  if (n > 0)
    Teuchos::reduceAll(*map_->getComm(), Teuchos::REDUCE_SUM, int(3 * n), local.data(),
                       global.data());
  ContactStepEnergy out;
  for (std::size_t i = 0; i < n; ++i) {
    out.closing += global[3 * i];
    out.other += global[3 * i + 1];
    if (global[3 * i + 2] > 0.0) out.closing_sliding += global[3 * i];
  }
  return out;
}

void MechanicsProblem::commit_step() {
  for (auto& c : interfaces_) {
    c->committed_active = c->active;
    for (std::size_t q = 0; q < c->slip_accumulated.size(); ++q)
      for (int k = 0; k < dim_ - 1; ++k)
        for (int a = 0; a < dim_; ++a)
          c->slip_accumulated[q][a] += c->slip_increment[q][k] * c->tangents[q][k][a];
    for (auto& increment : c->slip_increment) increment = {0.0, 0.0, 0.0};
    if (c->history_set) c->history = c->last_rows;
  }
  x_old_->assign(*x_last_);
}

ContactFields MechanicsProblem::contact_fields() const {
  ContactFields out;
  const std::size_t n = mesh_.num_nodes();
  // Rows: pressure, gap, status, λ (dim), slip (dim); each node set by its owner only.
  const std::size_t n_fields = 3 + 2 * std::size_t(dim_);
  std::vector<double> local(n_fields * n, 0.0), global(local.size(), 0.0);
  int active = 0;
  for (const auto& c : interfaces_) {
    for (std::size_t q = 0; q < c->owned.size(); ++q) {
      const GlobalIndex node = c->surface.slave_nodes[c->owned[q]];
      local[0 * n + node] = c->pressure[q];
      local[1 * n + node] = c->gap[q];
      local[2 * n + node] = c->active[q];
      for (int d = 0; d < dim_; ++d) {
        local[(3 + d) * n + node] = c->lambda[q][d];
        double slip = c->slip_accumulated[q][d];
        for (int k = 0; k < dim_ - 1; ++k)  // this step's increment, not yet committed
          slip += c->slip_increment[q][k] * c->tangents[q][k][d];
        local[(3 + dim_ + d) * n + node] = slip;
      }
      active += c->active[q] != 0;
    }
  }
  if (!interfaces_.empty()) {  // the same on every rank: all call the reductions or none
    const auto& comm = *map_->getComm();
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, int(local.size()), local.data(), global.data());
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 1, &active, &out.active_nodes);
  }
  const auto field = [&](std::size_t i) {
    return std::vector<double>(global.begin() + i * n, global.begin() + (i + 1) * n);
  };
  out.pressure = field(0);
  out.gap = field(1);
  out.status = field(2);
  for (int d = 0; d < dim_; ++d) {
    out.lm.push_back(field(3 + d));
    out.slip.push_back(field(3 + dim_ + d));
  }
  return out;
}

}  // namespace grout
