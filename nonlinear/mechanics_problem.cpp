#include "nonlinear/mechanics_problem.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
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

MechanicsProblem::MechanicsProblem(const SolidProblem& solid, const Mesh& mesh, const Input& input,
                                   const ContactMeshPart* part)
    : solid_(solid), input_(input), dim_(mesh.dimension) {
  // From the solid, not the mesh: `mesh` may be one rank's part of a distributed mesh.
  num_u_ = GO(solid.num_global_nodes()) * dim_;
  const auto& owned_u = *solid.owned_map();
  const auto comm = solid.comm();
  raw_comm_ = raw_mpi_comm(*comm);
  const ContactMesh contact_mesh = part ? ContactMesh(mesh, *part, raw_comm_) : ContactMesh(mesh);
  num_owned_u_ = int(owned_u.getNodeNumElements());
  std::vector<GO> owned;
  for (int i = 0; i < num_owned_u_; ++i) owned.push_back(owned_u.getGlobalElement(i));
  const auto owns = [&](GlobalIndex node) { return owned_u.isNodeGlobalElement(node * dim_); };

  // Interfaces: this rank's part of the surfaces, multipliers (numbered by slave node, as
  // on one rank: the sorted slave nodes of the side set) after the displacements.
  GO next_lambda = num_u_;
  std::vector<GO> base;  // displacement dofs of the nodes of local faces
  for (const ContactInput& ci : input.contact) {
    auto c = std::make_unique<ContactInterface>(contact_mesh, input, ci, int(interfaces_.size()),
                                                next_lambda, owns, comm);
    next_lambda += c->num_multipliers();
    c->append_owned_multipliers(owned);
    c->append_base_dofs(base);
    interfaces_.push_back(std::move(c));
  }
  // A slave node carries one multiplier: two pairs must not share slave nodes. Each rank checks
  // the slave nodes it owns; every rank agrees on the outcome.
  agree_on_errors(*comm, [&] {
    std::map<GlobalIndex, const ContactInterface*> slave_pair;
    for (const auto& c : interfaces_) {
      for (GlobalIndex n : c->owned_slave_nodes()) {
        const auto [it, fresh] = slave_pair.emplace(n, c.get());
        if (!fresh) {
          throw InputError(input.file + ": grout/contact/" + c->input().name +
                           "/slave: side set '" + c->input().slave + "' shares node " +
                           std::to_string(n + 1) + " with the slave side of grout/contact/" +
                           it->second->input().name +
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
  for (auto& c : interfaces_) c->set_base_map(base_map_);  // reference geometry: D, M once
  x_last_ = Teuchos::rcp(new Vector(map_));
  x_old_ = Teuchos::rcp(new Vector(map_));
  u_ = solid.create_vector();
  f_int_ = solid.create_vector();
  f_ext_ = solid.create_vector();
  reaction_ = solid.create_vector();
  K_solid_ = solid.create_matrix();
  prescribed_ = std::make_unique<PrescribedValues>(solid.owned_map(), solid.column_map());
  owned_fixed_.assign(num_owned_u_, 0);
  // Only a contact pair's slave body can turn freely.
  if (!input.contact.empty()) {
    std::vector<double> slave_face_size;
    for (const auto& c : interfaces_) slave_face_size.push_back(c->mean_slave_face_size());
    rotation_limit_ =
        std::make_unique<FreeRotationLimit>(contact_mesh, input, map_, slave_face_size);
  }
  if (rotation_limit_ && rotation_limit_->num_bodies() == 0) rotation_limit_.reset();
}

void MechanicsProblem::limit_step(const Vector& /*x*/, Vector& step) {
  if (!rotation_limit_) return;
  std::vector<std::vector<ContactNode>> active(input_.contact.size()), slave(active.size());
  for (std::size_t i = 0; i < interfaces_.size(); ++i)
    for (const ContactInterface::NodeResult& r : interfaces_[i]->node_results()) {
      const ContactNode node{
          r.node, {r.normal[0], r.normal[1], r.normal[2]}, {r.X[0], r.X[1], r.X[2]}};
      slave[i].push_back(node);
      if (r.status != 0.0) active[i].push_back(node);
    }
  last_rotation_slide_ = rotation_limit_->limit(active, slave, step);
}

MechanicsProblem::~MechanicsProblem() = default;

void MechanicsProblem::begin_step(double t, Vector& x) {
  iterate_ = 0;
  for (auto& c : interfaces_) c->begin_step();
  // The load expressions are evaluated on each rank's own faces: a value that is not finite
  // on one rank stops every rank.
  std::vector<double> column_values;  // the solid's column map: owned and ghost dofs
  agree_on_errors(*solid_.comm(), [&] {
    column_values = solid_.prescribed_displacements(t);
    solid_.external_force(t, *f_ext_);
  });
  // The dofs held beyond the column map (contact nodes) get their owners' values.
  prescribed_->set(column_values);
  auto xv = x.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (int i = 0; i < num_owned_u_; ++i) {
    const double value = prescribed_->value(map_->getGlobalElement(i));
    owned_fixed_[i] = !std::isnan(value);
    if (owned_fixed_[i]) xv(i, 0) = value;
  }
}

void MechanicsProblem::displacement(const Vector& x, Vector& u) const {
  const auto xv = x.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto uv = u.getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (int i = 0; i < num_owned_u_; ++i) uv(i, 0) = xv(i, 0);
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
  terms_.clear();
  x_last_->assign(x);
  double contact_sums[4] = {0.0, 0.0, 0.0, 0.0};  // active, changes, Σ floor², newly fixed
  if (!interfaces_.empty()) {
    Teuchos::TimeMonitor timer(
        *Teuchos::TimeMonitor::getNewTimer("grout: contact (search, integration, assembly)"));
    const auto& comm = *solid_.comm();
    Vector u_base(base_map_), u_old_base(base_map_);
    u_base.doImport(x, *base_import_, Tpetra::INSERT);
    u_old_base.doImport(*x_old_, *base_import_, Tpetra::INSERT);
    // The stages of contact_interface.hpp, each over all interfaces: geometry, pairing
    // tolerance, closure counts, then the rows (local).
    const int n = int(interfaces_.size());
    const NewtonPhase phase = newton_phase(iterate_);
    for (auto& c : interfaces_) c->update_geometry(u_base, u_old_base);
    std::vector<double> D_max(n), D_max_all(n);
    for (int i = 0; i < n; ++i) D_max[i] = interfaces_[i]->local_max_D();
    Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, n, D_max.data(), D_max_all.data());
    std::vector<double> counts(2 * n), counts_all(2 * n, 0.0);
    bool holds_back = false;
    for (int i = 0; i < n; ++i) {
      interfaces_[i]->set_pairing_tolerance(D_max_all[i]);
      const ClosureCounts k = interfaces_[i]->prepare_active_set(x, phase);
      counts[2 * i] = k.active_before, counts[2 * i + 1] = k.closing;
      holds_back = holds_back || interfaces_[i]->holds_back(phase);
    }
    if (holds_back)  // the same on every rank: the same input and phase
      Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 2 * n, counts.data(), counts_all.data());
    // The rows read the prescribed flags of the surfaces' nodes: master nodes beyond the ghost
    // layer are brought in (collective; only when the search found new ones).
    std::vector<GO> surface_dofs;
    for (auto& c : interfaces_) c->append_surface_dofs(surface_dofs);
    prescribed_->cover(std::move(surface_dofs));
    ContactRowSums sums;
    for (int i = 0; i < n; ++i) {
      const ContactRowSums s = interfaces_[i]->write_rows(
          iterate_, {counts_all[2 * i], counts_all[2 * i + 1]}, *prescribed_, terms_, F);
      sums.active += s.active, sums.changes += s.changes, sums.floor2 += s.floor2;
      sums.newly_fixed += s.newly_fixed;
      if (s.fixed.violation > sums.fixed.violation) sums.fixed = s.fixed;
      sums.lambda_n_max = std::max(sums.lambda_n_max, s.lambda_n_max);
    }
    terms_.sum_forces_to_owners(*map_, raw_comm_, F);
    MultiplierRows rows;  // ascending by GID
    for (auto& c : interfaces_) c->append_rows(rows);
    std::vector<std::size_t> order(rows.gids.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return rows.gids[a] < rows.gids[b]; });
    rows_.gids.clear(), rows_.kinds.clear();
    for (std::size_t k : order)
      rows_.gids.push_back(rows.gids[k]), rows_.kinds.push_back(rows.kinds[k]);
    const double local[4] = {sums.active, sums.changes, sums.floor2, sums.newly_fixed};
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 4, local, contact_sums);
    if (contact_sums[3] > 0.0) report_fixed_nodes(int(contact_sums[3]), sums);  // on every rank
  }
  active_size_ = int(contact_sums[0]);
  active_changes_ = int(contact_sums[1]);
  {
    const double eps = std::numeric_limits<double>::epsilon();
    const double f_floor = eps * f_int_->norm2();            // collective
    const double solid_floor = solid_.round_off_estimate();  // collective; 0 for small strain
    residual_floor_ = std::sqrt(f_floor * f_floor + solid_floor * solid_floor + contact_sums[2]);
  }
  // Reactions, then the prescribed rows drop out.
  {
    auto Fv = F.getLocalViewHost(Tpetra::Access::ReadWrite);
    auto rv = reaction_->getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (int i = 0; i < num_owned_u_; ++i) {
      const bool fixed = owned_fixed_[i] != 0;
      rv(i, 0) = fixed ? Fv(i, 0) : 0.0;
      if (fixed) Fv(i, 0) = 0.0;
    }
  }
  return std::isfinite(F.norm2());
}

// The cycle rule of the active-set policy (active_set_cycles.hpp) fixed `count` nodes at this
// evaluation: said on rank 0, with the violations of both states of the node whose fixed state
// violated the contact conditions most in the cycle (collective).
void MechanicsProblem::report_fixed_nodes(int count, const ContactRowSums& local) const {
  const auto& comm = *solid_.comm();
  const double mine[2] = {local.fixed.violation, local.lambda_n_max};
  double most[2] = {0.0, 0.0};
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 2, mine, most);
  // That node (the lowest id among equals), its state and its other state's violation.
  const long long none = std::numeric_limits<long long>::max();
  const bool mine_most = local.fixed.violation == most[0] && local.fixed.node >= 0;
  const long long key =
      mine_most ? 2 * (long long)local.fixed.node + (local.fixed.closed ? 1 : 0) : none;
  long long first = none;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, 1, &key, &first);
  const double other_here = key == first ? local.fixed.other : -1.0;
  double other = 0.0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 1, &other_here, &other);
  if (comm.getRank() != 0) return;
  const bool closed = first % 2 != 0;
  const double open_off = closed ? other : most[0], closed_off = closed ? most[0] : other;
  std::printf(
      "  contact: %d slave node(s) cycling between open and closed, fixed for the rest of "
      "the step; node %lld fixed %s: in the cycle, open was off by c |g| = %.3g, closed "
      "by |lambda_n| = %.3g (the largest lambda_n: %.3g)\n",
      count, first / 2 + 1, closed ? "closed" : "open", open_off, closed_off, most[1]);
  std::fflush(stdout);
}

bool MechanicsProblem::jacobian(const Vector&, Teuchos::RCP<Matrix>& J) {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("grout: jacobian (u, lambda)"));
  // Contact triplets: this rank's rows, then those other ranks computed for its rows (master
  // rows), in rank order.
  std::vector<JacobianTerm> entries;
  if (!interfaces_.empty()) entries = terms_.owned_entries(*map_, raw_comm_);
  // Each row's terms are summed in key = (slave node, emission) order: one order on any
  // number of ranks.
  J = jacobian_matrix(*K_solid_, map_, entries);

  // Prescribed dofs: rows and columns eliminated, diagonal kept (their update is zero). The
  // contact entries' columns (other ranks' slave and master nodes in this rank's master rows)
  // may lie beyond the held dofs: brought in (collective).
  const auto& jc = *J->getColMap();
  std::vector<GO> u_columns;
  for (std::size_t c = 0; c < jc.getNodeNumElements(); ++c) {
    const GO g = jc.getGlobalElement(LO(c));
    if (g < num_u_) u_columns.push_back(g);
  }
  prescribed_->cover(u_columns);
  std::vector<double> delta(jc.getNodeNumElements(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t c = 0; c < delta.size(); ++c) {
    const GO g = jc.getGlobalElement(LO(c));
    if (g < num_u_ && prescribed_->fixed(g)) delta[c] = 0.0;
  }
  Vector rhs(map_);
  apply_dirichlet(*J, rhs, delta);
  return true;
}

std::vector<std::pair<GO, GO>> MechanicsProblem::multiplier_pairing() const {
  std::vector<long long> mine;
  for (const auto& c : interfaces_) c->append_pairing(mine);
  const int n_ranks = map_->getComm()->getSize();
  const std::vector<long long> all =
      exchange_with_ranks(std::vector<std::vector<long long>>(n_ranks, mine), raw_comm_);
  std::vector<std::pair<GO, GO>> pairs;
  for (std::size_t k = 0; k + 1 < all.size(); k += 2) pairs.emplace_back(all[k], all[k + 1]);
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

ContactStepEnergy MechanicsProblem::contact_step_energy() const {
  // Per interface: the closing and other energies, and its number of slave nodes active at
  // the last converged state (> 0: the closing nodes of the step are a sliding contact's).
  const std::size_t n = interfaces_.size();
  std::vector<double> local(3 * n, 0.0), global(3 * n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    interfaces_[i]->add_step_energy(local[3 * i], local[3 * i + 1], local[3 * i + 2]);
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
  for (auto& c : interfaces_) c->commit_step();
  x_old_->assign(*x_last_);
}

ContactFields MechanicsProblem::contact_fields() const {
  ContactFields out;
  out.lm.resize(dim_);
  out.slip.resize(dim_);
  int active = 0;
  for (const auto& c : interfaces_) {
    for (const ContactInterface::NodeResult& r : c->node_results()) {
      out.nodes.push_back(r.node);
      out.pressure.push_back(r.pressure);
      out.gap.push_back(r.gap);
      out.status.push_back(r.status);
      for (int d = 0; d < dim_; ++d) {
        out.lm[d].push_back(r.lambda[d]);
        out.slip[d].push_back(r.slip[d]);
      }
      active += r.status != 0.0;
    }
  }
  if (!interfaces_.empty())  // the same on every rank: all call the reduction or none
    Teuchos::reduceAll(*map_->getComm(), Teuchos::REDUCE_SUM, 1, &active, &out.active_nodes);
  return out;
}

}  // namespace grout
