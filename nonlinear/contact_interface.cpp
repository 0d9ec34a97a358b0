#include "nonlinear/contact_interface.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <algorithm>
#include <limits>

#include "assembly/contact_distribution.hpp"
#include "assembly/contact_sides.hpp"
#include "assembly/raw_mpi_comm.hpp"
#include "io/errors.hpp"

namespace grout {

namespace {

// Young's modulus of the material of `block` (a side's first face's).
double youngs_modulus_of(const Input& input, const ElementBlock& block,
                         const ContactInput& contact) {
  if (const MaterialInput* m = find_material(input, block)) return m->youngs_modulus;
  throw InputError(input.file + ": grout/contact/" + contact.name + ": no material on block '" +
                   block.name + "'");
}

}  // namespace

ContactInterface::ContactInterface(const ContactMesh& mesh, const Input& input,
                                   const ContactInput& ci, int index, GO lambda_offset,
                                   const std::function<bool(GlobalIndex)>& owns,
                                   const Teuchos::RCP<const Teuchos::Comm<int>>& comm)
    : num_global_nodes_(mesh.num_global_nodes()),
      input_(ci),
      index_(index),
      dim_(mesh.dimension()),
      lambda_offset_(lambda_offset) {
  raw_comm_ = raw_mpi_comm(*comm);
  ContactSides sides = read_contact_sides(mesh, input, ci, owns);
  LocalContactFaces& local = sides.local;
  X_ref_ = std::move(sides.X);
  GlobalIndex shared =
      local.shared_node < 0 ? std::numeric_limits<GlobalIndex>::max() : local.shared_node;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, 1, &shared, &local.shared_node);
  if (local.shared_node != std::numeric_limits<GlobalIndex>::max())
    throw InputError(shared_node_message(input, ci, local.shared_node));
  surface_ = std::move(local.surface);
  owned_master_ = std::move(local.owned_master);
  const ContactSurface& s = surface_;
  const std::vector<GlobalIndex>& all_slave = sides.all_slave_nodes;
  for (std::size_t j = 0; j < s.slave_nodes.size(); ++j) {
    if (!owns(s.slave_nodes[j])) continue;
    owned_.push_back(int(j));
    lambda_index_.push_back(std::lower_bound(all_slave.begin(), all_slave.end(), s.slave_nodes[j]) -
                            all_slave.begin());
  }
  const int n_owned = int(owned_.size());
  num_multipliers_ = GO(all_slave.size()) * dim_;
  if (ci.self) self_faces_ = sides.num_slave_faces;  // ids 0 .. self_faces_ - 1

  const double E1 = youngs_modulus_of(input, *sides.slave_block, ci);
  const double E2 = youngs_modulus_of(input, *sides.master_block, ci);
  const double h = mean_slave_face_size_ = sides.mean_slave_face_size;
  c_hat_ = ci.c_n > 0.0 ? ci.c_n : 2.0 / (1.0 / E1 + 1.0 / E2) / h;
  active_tolerance_ = 1e-10 * 2.0 / (1.0 / E1 + 1.0 / E2);
  std::vector<double> proximity(n_owned, 0.0);  // start_gap × the mean size of the node's faces
  for (int q = 0; q < n_owned; ++q) {
    const auto& faces = s.slave_node_faces[owned_[q]];
    for (int f : faces) {
      std::array<double, 3> x[max_face_nodes];
      for (int a = 0; a < s.slave.num_nodes[f]; ++a) x[a] = X_ref_.at(s.slave.nodes[f][a]);
      proximity[q] += face_size_of(dim_, x, s.slave.num_nodes[f]);
    }
    if (!faces.empty()) proximity[q] *= ci.start_gap / double(faces.size());
  }
  policy_ = ActiveSetPolicy(std::move(proximity), ci.start_closure);
  c_t_hat_ = ci.c_t > 0.0 ? ci.c_t : c_hat_;
  // κ = 1e-11 of the default ĉ (not of an input c_n: the iterates must not depend on it).
  hold_ = 1e-11 * 2.0 / (1.0 / E1 + 1.0 / E2) / h;
  // Collocation points: per slave element (2D) or per direction (3D); 20 unless the input
  // sets them.
  options_.mortar = mortar_options(dim_,
                                   ci.integration == ContactIntegration::collocation
                                       ? MortarIntegration::collocation
                                       : MortarIntegration::exact,
                                   ci.collocation_points > 0 ? ci.collocation_points : 20);
  options_.mortar.axisymmetric = input.model.plane == PlaneKind::axisymmetric;  // 2π r weights
  const ContactGeometry geometry = ci.geometry != ContactGeometry::automatic ? ci.geometry
                                   : input.model.strain == StrainKind::small
                                       ? ContactGeometry::reference
                                       : ContactGeometry::current;
  current_geometry_ = geometry == ContactGeometry::current && ci.type != ContactKind::tied;

  pressure_.assign(n_owned, 0.0);
  gap_.assign(n_owned, 0.0);
  iterate_gap_.assign(n_owned, 0.0);
  gap_known_.assign(n_owned, 0);
  held_back_.assign(n_owned, 0);
  newly_fixed_.assign(n_owned, 0);
  lambda_.assign(n_owned, {0.0, 0.0, 0.0});
  active_.assign(n_owned, 0);
  previous_active_.assign(n_owned, 0);
  committed_active_.assign(n_owned, 0);
  step_energy_.assign(n_owned, 0.0);
  closing_.assign(n_owned, 0);
  candidates_.assign(n_owned, {});
  covered_.assign(n_owned, 1);
  weighted_.assign(n_owned, {});
  row_kinds_.assign(n_owned, {LambdaRow::identity, LambdaRow::identity, LambdaRow::identity});
  slip_increment_.assign(n_owned, {0.0, 0.0, 0.0});
  slip_accumulated_.assign(n_owned, {0.0, 0.0, 0.0});
  tangents_.assign(n_owned, {});
  history_.assign(n_owned, {});
  last_rows_.assign(n_owned, {});
}

void ContactInterface::append_owned_multipliers(std::vector<GO>& gids) const {
  for (int q = 0; q < int(owned_.size()); ++q)
    for (int d = 0; d < dim_; ++d) gids.push_back(lambda_gid(q, d));
}

void ContactInterface::append_base_dofs(std::vector<GO>& base) const {
  for (GlobalIndex n : surface_.slave_nodes)
    for (int d = 0; d < dim_; ++d) base.push_back(n * dim_ + d);
  for (std::size_t f = 0; f < owned_master_.size(); ++f)
    for (int a = 0; a < owned_master_.num_nodes[f]; ++a)
      for (int d = 0; d < dim_; ++d) base.push_back(owned_master_.nodes[f][a] * dim_ + d);
}

void ContactInterface::append_surface_dofs(std::vector<GO>& dofs) const {
  for (GlobalIndex n : surface_.nodes)
    for (int d = 0; d < dim_; ++d) dofs.push_back(GO(n) * dim_ + d);
}

std::vector<GlobalIndex> ContactInterface::owned_slave_nodes() const {
  std::vector<GlobalIndex> nodes;
  for (int j : owned_) nodes.push_back(surface_.slave_nodes[j]);
  return nodes;
}

void ContactInterface::set_base_map(const Teuchos::RCP<const Map>& base_map) {
  base_map_ = base_map;
  if (current_geometry_) return;
  // D, M and normals once, at zero displacement.
  ghost_master_faces(nullptr, nullptr);
  std::vector<std::array<double, 3>> X = X_;
  if (input_.self) choose_self_sides(X, nullptr);
  ContactMortarOptions reference_options = options_;
  reference_options.derivatives = false;
  reference_ = evaluate_contact_mortar(surface_, X, reference_options);
  reference_pairs_ = contact_pairs(surface_, X, reference_options);
}

std::size_t ContactInterface::position_of(GlobalIndex node) const {
  return std::size_t(std::lower_bound(surface_.nodes.begin(), surface_.nodes.end(), node) -
                     surface_.nodes.begin());
}

// The master faces the slave faces can touch (parallel coarse search, on the current
// configuration or the reference one), and the reference coordinates, displacements and
// last converged displacements of every node of the local surface. u_base / u_old_base:
// displacements on base_map_ (nullptr: zero).
void ContactInterface::ghost_master_faces(const Vector* u_base, const Vector* u_old_base) {
  const int dim = dim_;
  using HostView =
      decltype(std::declval<const Vector&>().getLocalViewHost(Tpetra::Access::ReadOnly));
  HostView ub, uob;
  if (u_base) ub = u_base->getLocalViewHost(Tpetra::Access::ReadOnly);
  if (u_old_base) uob = u_old_base->getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto node_values = [&](GlobalIndex n, double X[3], double u[3], double u_old[3]) {
    for (int d = 0; d < 3; ++d) X[d] = u[d] = u_old[d] = 0.0;
    const std::array<double, 3>& Xn = X_ref_.at(n);
    for (int d = 0; d < dim; ++d) {
      X[d] = Xn[d];
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
    for (std::size_t f = 0; f < owned_master_.size(); ++f) {
      double x[max_face_nodes][3], values[max_face_nodes * payload];
      for (int a = 0; a < owned_master_.num_nodes[f]; ++a) {
        double* v = values + a * payload;
        node_values(owned_master_.nodes[f][a], v, v + 3, v + 6);
        search_coordinates(current, v, v + 3, x[a]);
      }
      owned.add(owned_master_.ids[f], owned_master_.num_nodes[f], owned_master_.nodes[f].data(), x,
                values);
    }
    const SurfaceFaces& slave = surface_.slave;
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
    return grout::ghost_master_faces(
        owned, search_region(slave_set, options_.search_factor, surface_.integrate),
        options_.search_factor, raw_comm_);
  };
  // The current geometry searches on the current positions. The reference geometry searches
  // on the reference positions and, once there is a displacement, on the current ones too:
  // faces that the load brings together must be paired even if they lie far apart in the
  // reference configuration (evaluate_contact_mortar's search_x).
  FaceSet ghost = ghost_faces(current_geometry_);
  if (!current_geometry_ && u_base) ghost = merge_face_sets(ghost, ghost_faces(true));

  SurfaceFaces master;
  master.ids = ghost.ids;
  master.nodes = ghost.nodes;
  master.num_nodes = ghost.num_nodes;
  master.blocks.assign(ghost.size(), nullptr);
  set_master_faces(surface_, std::move(master));
  const std::size_t n = surface_.nodes.size();
  X_.assign(n, {0.0, 0.0, 0.0});
  u_.assign(n, {0.0, 0.0, 0.0});
  u_old_.assign(n, {0.0, 0.0, 0.0});
  for (GlobalIndex node : surface_.slave_nodes) {
    const std::size_t i = position_of(node);
    node_values(node, X_[i].data(), u_[i].data(), u_old_[i].data());
  }
  for (std::size_t f = 0; f < ghost.size(); ++f) {
    for (int a = 0; a < ghost.num_nodes[f]; ++a) {
      const std::size_t i = position_of(ghost.nodes[f][a]);
      const double* v = &ghost.payload[(f * max_face_nodes + a) * payload];
      for (int d = 0; d < 3; ++d) X_[i][d] = v[d], u_[i][d] = v[3 + d], u_old_[i][d] = v[6 + d];
    }
  }
}

ContactInterface::Holdings ContactInterface::holdings() const {
  Holdings h;
  h.slave_faces = (long long)surface_.slave.size();
  h.evaluated_slave_faces =
      surface_.integrate.empty()
          ? h.slave_faces
          : (long long)std::count(surface_.integrate.begin(), surface_.integrate.end(), char(1));
  h.owned_master_faces = (long long)owned_master_.size();
  h.searched_master_faces = (long long)surface_.master.size();
  h.surface_nodes = (long long)surface_.nodes.size();
  return h;
}

void ContactInterface::update_geometry(const Vector& u_base, const Vector& u_old_base) {
  const int dim = dim_;
  ghost_master_faces(&u_base, &u_old_base);
  const ContactSurface& s = surface_;
  const std::size_t n_nodes = s.nodes.size();
  positions_.assign(n_nodes, {0.0, 0.0, 0.0});
  for (std::size_t i = 0; i < n_nodes; ++i)
    for (int d = 0; d < dim; ++d) positions_[i][d] = X_[i][d] + u_[i][d];
  if (input_.self) {
    if (current_geometry_)
      choose_self_sides(positions_, nullptr);
    else
      choose_self_sides(X_, &positions_);
    choose_sides_ = false;
  }
  if (!current_geometry_) {
    // Integrated on the reference positions, paired on the reference and current ones: the
    // integration again only when the pairing changed.
    ContactMortarOptions reference_options = options_;
    reference_options.derivatives = false;
    auto pairs = contact_pairs(s, X_, reference_options, &positions_);
    if (pairs != reference_pairs_) {
      reference_ = evaluate_contact_mortar(s, X_, reference_options, &positions_);
      reference_pairs_ = std::move(pairs);
    }
  }
  current_ = current_geometry_ ? evaluate_contact_mortar(s, positions_, options_) : ContactMortar();
  const ContactMortar& m = current_geometry_ ? current_ : reference_;
  build_stencil(m);
  // The partly covered node rule within a step: a node counts as covered from the step's first
  // evaluation at which its faces are (dual_covered) to the step's end. Re-decided at each
  // iterate, a node whose coverage hovers about min_dual_coverage switches its row between the
  // contact law and λ_j = 0 from one iterate to the next (the 3D press fit's leading nodes
  // sliding onto the channel's edge stalled at any step size so); decided only at the step's
  // start, a node that a master reaches within the step would get no row (the Hertz spheres).
  if (input_.type != ContactKind::tied) {
    for (int q = 0; q < int(owned_.size()); ++q)
      covered_[q] = (coverage_set_ && covered_[q]) || dual_covered(m, owned_[q]);
    coverage_set_ = true;
  }
  const int n_owned = int(owned_.size());
  for (int q = 0; q < n_owned; ++q)
    for (int k = 0; k < dim - 1; ++k)
      for (int a = 0; a < 3; ++a) tangents_[q][k][a] = m.frames[owned_[q]].t[k][a];
  // The rows D_jj, M_jl of the owned slave nodes (objective slip): of this evaluation, and at
  // the first evaluation those of the last converged positions (commit_step moves them on).
  const auto rows_of = [&](const ContactMortar& mm, std::vector<MortarRowHistory>& rows) {
    for (int q = 0; q < n_owned; ++q) {
      const int j = owned_[q];
      rows[q].D = mm.D[j].value;
      rows[q].M.clear();
      for (auto it = mm.M.lower_bound({j, std::numeric_limits<GlobalIndex>::min()});
           it != mm.M.end() && it->first.first == j; ++it)
        rows[q].M.emplace_back(it->first.second, it->second.value);
    }
  };
  if (current_geometry_ && input_.type == ContactKind::frictional) {
    if (!history_set_) {
      std::vector<std::array<double, 3>> old_positions(n_nodes, {0.0, 0.0, 0.0});
      for (std::size_t i = 0; i < n_nodes; ++i)
        for (int d = 0; d < dim; ++d) old_positions[i][d] = X_[i][d] + u_old_[i][d];
      ContactMortarOptions old_options = options_;
      old_options.derivatives = false;
      rows_of(evaluate_contact_mortar(s, old_positions, old_options), history_);
      history_set_ = true;
    }
    rows_of(m, last_rows_);
  }
}

void ContactInterface::build_stencil(const ContactMortar& m) {
  const int n_owned = int(owned_.size());
  slave_pos_.resize(n_owned);
  stencil_begin_.assign(n_owned + 1, 0);
  stencil_.clear();
  for (int q = 0; q < n_owned; ++q) {
    const int j = owned_[q];
    slave_pos_[q] = position_of(surface_.slave_nodes[j]);
    for (auto it = m.M.lower_bound({j, std::numeric_limits<GlobalIndex>::min()});
         it != m.M.end() && it->first.first == j; ++it)
      stencil_.push_back({it->first.second, position_of(it->first.second), &it->second});
    stencil_begin_[q + 1] = stencil_.size();
  }
}

// Self-contact sides (docs/input.md "Self-contact"): the candidate pairs of every rank (the
// search's self filters: no shared node, facing normals) gathered, then 2-coloured in face-id
// order (self_contact_sides), so the choice is the same on any number of ranks. Afresh at the
// first evaluation of a step; at the others the step's sides are kept and only faces newly in
// reach get theirs.
void ContactInterface::choose_self_sides(const std::vector<std::array<double, 3>>& x,
                                         const std::vector<std::array<double, 3>>* search_x) {
  ContactMortarOptions search_options = options_;
  search_options.derivatives = false;
  std::vector<signed char> keep;  // within a step: the sides chosen so far
  if (!choose_sides_) keep = std::move(surface_.self_side);
  surface_.self_side.clear();  // every facing, non-neighbouring pair
  std::vector<long long> mine;
  for (const auto& [f, g] : contact_pairs(surface_, x, search_options, search_x)) {
    mine.push_back(f);
    mine.push_back(g);
  }
  int n_ranks = 1;
  MPI_Comm_size(raw_comm_, &n_ranks);
  const std::vector<long long> all =
      exchange_with_ranks(std::vector<std::vector<long long>>(n_ranks, mine), raw_comm_);
  surface_.self_side = self_contact_sides(self_faces_, all, keep);
}

double ContactInterface::local_max_D() const {
  const ContactMortar& m = current_geometry_ ? current_ : reference_;
  double D_max = 0.0;
  for (int j : owned_) D_max = std::max(D_max, m.D[j].value);
  return D_max;
}

void ContactInterface::commit_step() {
  committed_active_ = active_;
  for (std::size_t q = 0; q < slip_accumulated_.size(); ++q)
    for (int k = 0; k < dim_ - 1; ++k)
      for (int a = 0; a < dim_; ++a)
        slip_accumulated_[q][a] += slip_increment_[q][k] * tangents_[q][k][a];
  for (auto& increment : slip_increment_) increment = {0.0, 0.0, 0.0};
  if (history_set_) history_ = last_rows_;
}

void ContactInterface::append_rows(MultiplierRows& rows) const {
  for (std::size_t q = 0; q < owned_.size(); ++q)
    for (int d = 0; d < dim_; ++d) {
      rows.gids.push_back(lambda_gid(int(q), d));
      rows.kinds.push_back(row_kinds_[q][d]);
    }
}

void ContactInterface::append_pairing(std::vector<long long>& pairs) const {
  for (std::size_t q = 0; q < owned_.size(); ++q)
    for (int d = 0; d < dim_; ++d) {
      pairs.push_back(lambda_gid(int(q), d));
      pairs.push_back(GO(surface_.slave_nodes[owned_[q]]) * dim_ + d);
    }
}

std::vector<ContactInterface::NodeResult> ContactInterface::node_results() const {
  std::vector<NodeResult> out;
  for (std::size_t q = 0; q < owned_.size(); ++q) {
    const GlobalIndex node = surface_.slave_nodes[owned_[q]];
    NodeResult r{node, pressure_[q], gap_[q], double(active_[q]), {}, {}, {}, {}};
    const std::array<double, 3>& X = X_ref_.at(node);
    for (int d = 0; d < 3; ++d) r.X[d] = X[d];
    const ContactMortar& m = current_geometry_ ? current_ : reference_;
    for (int d = 0; d < dim_; ++d) {
      r.normal[d] = m.frames.size() > std::size_t(owned_[q]) ? m.frames[owned_[q]].n[d] : 0.0;
      r.lambda[d] = lambda_[q][d];
      double slip = slip_accumulated_[q][d];
      for (int k = 0; k < dim_ - 1; ++k)  // this step's increment, not yet committed
        slip += slip_increment_[q][k] * tangents_[q][k][d];
      r.slip[d] = slip;
    }
    out.push_back(r);
  }
  return out;
}

void ContactInterface::add_step_energy(double& closing, double& other,
                                       double& committed_active) const {
  for (std::size_t q = 0; q < owned_.size(); ++q) {
    (closing_[q] ? closing : other) += step_energy_[q];
    committed_active += committed_active_[q] ? 1.0 : 0.0;
  }
}

}  // namespace grout
