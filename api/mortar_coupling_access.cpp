// grout::MortarCoupling's read access: the results' getters, row_status, the index
// translations (docs/embedding.md, "Index spaces") and the contact forces of a multiplier field,
// per rank or summed to the owners of the nodes (NodeDirectory).

#include <algorithm>
#include <string>

#include "mortar_coupling_impl.hpp"

namespace grout {

void MortarCoupling::Impl::master_nodes_of_M(std::vector<long long>& nodes,
                                             std::vector<int>& entry_node) const {
  // surface.nodes is sorted by id: marking the positions orders the master nodes by id.
  std::vector<int> index(surface.nodes.size(), -1), entry_position(M_columns.size());
  for (std::size_t k = 0; k < M_columns.size(); ++k)
    index[entry_position[k] = position_of(M_columns[k])] = 0;
  nodes.clear();
  for (std::size_t i = 0; i < index.size(); ++i)
    if (index[i] == 0) {
      index[i] = int(nodes.size());
      nodes.push_back(surface.nodes[i]);
    }
  entry_node.resize(M_columns.size());
  for (std::size_t k = 0; k < M_columns.size(); ++k) entry_node[k] = index[entry_position[k]];
}

int MortarCoupling::dim() const {
  return impl_->dim;
}
std::size_t MortarCoupling::num_slave_nodes() const {
  return impl_->slave.n_nodes;
}
MultiplierBasis MortarCoupling::multipliers() const {
  return impl_->options.multipliers;
}
const std::vector<double>& MortarCoupling::D() const {
  if (impl_->options.multipliers != MultiplierBasis::dual)
    throw MortarCouplingError(
        "grout::MortarCoupling::D: D is not diagonal with standard multipliers (D_jk = ∫ N_j N_k "
        "dA): read D_offsets(), D_columns(), D_values()");
  return impl_->D;
}
const std::vector<std::size_t>& MortarCoupling::D_offsets() const {
  if (!impl_->D_crs_ready) impl_->fill_diagonal_D();
  return impl_->D_offsets;
}
const std::vector<long long>& MortarCoupling::D_columns() const {
  if (!impl_->D_crs_ready) impl_->fill_diagonal_D();
  return impl_->D_columns;
}
const std::vector<double>& MortarCoupling::D_values() const {
  if (!impl_->D_crs_ready) impl_->fill_diagonal_D();
  return impl_->D_values;
}
const std::vector<std::size_t>& MortarCoupling::M_offsets() const {
  return impl_->M_offsets;
}
const std::vector<long long>& MortarCoupling::M_columns() const {
  return impl_->M_columns;
}
const std::vector<double>& MortarCoupling::M_values() const {
  return impl_->M_values;
}
const std::vector<double>& MortarCoupling::weighted_gaps() const {
  return impl_->gaps;
}
const std::vector<double>& MortarCoupling::normals() const {
  return impl_->normals;
}
const std::vector<double>& MortarCoupling::tangents() const {
  if (!impl_->tangents_ready) impl_->fill_tangents();
  return impl_->tangents;
}
int MortarCoupling::overlapping_pairs() const {
  return impl_->pairs;
}

ContactForces MortarCoupling::contact_forces(const std::vector<double>& lambda,
                                             ForceSum sum) const {
  if (lambda.size() != impl_->slave.n_nodes * impl_->dim)
    throw MortarCouplingError(
        "grout::MortarCoupling::contact_forces: " + std::to_string(lambda.size()) +
        " multiplier values, " + std::to_string(impl_->slave.n_nodes * impl_->dim) +
        " expected (slave rows × dim)");
  return contact_forces(lambda.data(), sum);
}

ContactForces MortarCoupling::contact_forces(const double* lambda, ForceSum sum) const {
  const Impl& m = *impl_;
  const int dim = m.dim;
  if (!lambda && m.slave.n_nodes > 0)
    throw MortarCouplingError("grout::MortarCoupling::contact_forces: null multipliers");
  ContactForces f;
  std::vector<int> M_master;  // per M entry: its index in f.master_nodes
  m.master_nodes_of_M(f.master_nodes, M_master);
  f.slave.assign(m.slave.n_nodes * dim, 0.0);
  f.master.assign(f.master_nodes.size() * dim, 0.0);
  const bool dual = m.options.multipliers == MultiplierBasis::dual;
  for (std::size_t j = 0; j < m.slave.n_nodes; ++j) {
    const double* lambda_j = lambda + j * dim;
    if (dual) {
      for (int d = 0; d < dim; ++d) f.slave[j * dim + d] = m.D[j] * lambda_j[d];
    } else {  // f¹_k += D_jk λ_j; the columns are nodes of this rank's faces: host slave rows
      for (std::size_t k = m.D_offsets[j]; k < m.D_offsets[j + 1]; ++k) {
        const std::size_t row = std::size_t(m.host_row[m.position_of(m.D_columns[k])].second);
        for (int d = 0; d < dim; ++d) f.slave[row * dim + d] += m.D_values[k] * lambda_j[d];
      }
    }
    for (std::size_t k = m.M_offsets[j]; k < m.M_offsets[j + 1]; ++k)
      for (int d = 0; d < dim; ++d)
        f.master[std::size_t(M_master[k]) * dim + d] -= m.M_values[k] * lambda_j[d];
  }
  if (sum == ForceSum::owners) {
    // Master: the totals by id at their owners. Slave: the totals at every rank's rows, kept
    // where this rank owns the row.
    std::vector<long long> ids;
    std::vector<double> totals;
    m.directory.sum_to_owners(f.master_nodes, f.master, dim, ids, totals);
    f.master_nodes = std::move(ids);
    f.master = std::move(totals);
    f.slave = m.directory.sum_to_senders(m.slave.ids, f.slave, dim);
    for (std::size_t r = 0; r < m.slave.n_nodes; ++r)
      if (m.slave_owner[r] != m.rank)
        for (int d = 0; d < dim; ++d) f.slave[r * dim + d] = 0.0;
  }
  return f;
}

const std::vector<RowStatus>& MortarCoupling::row_status() const {
  if (!impl_->status_ready) impl_->fill_row_status();  // serial (distributed: in update)
  return impl_->status;
}

long long MortarCoupling::slave_id(std::size_t row) const {
  if (row >= impl_->slave.n_nodes)
    throw MortarCouplingError("grout::MortarCoupling::slave_id: row " + std::to_string(row) +
                              " of " + std::to_string(impl_->slave.n_nodes) + " slave rows");
  return impl_->slave.ids[row];
}

long long MortarCoupling::slave_row(long long id) const {
  const Impl& m = *impl_;
  const int i = m.position_of(id);
  if (std::size_t(i) < m.surface.nodes.size() && m.surface.nodes[i] == id &&
      m.host_row[i].first == 0)
    return m.host_row[i].second;
  for (std::size_t r = 0; r < m.slave.n_nodes; ++r)  // a row on no face
    if (m.slave.ids[r] == id) return (long long)r;
  return -1;
}

MEntry MortarCoupling::M_entry(std::size_t k) const {
  const Impl& m = *impl_;
  if (k >= m.M_values.size())
    throw MortarCouplingError("grout::MortarCoupling::M_entry: " + std::to_string(k) + " of " +
                              std::to_string(m.M_values.size()) + " M entries");
  const std::size_t row = std::size_t(std::upper_bound(m.M_offsets.begin(), m.M_offsets.end(), k) -
                                      m.M_offsets.begin()) -
                          1;
  return {row, m.M_columns[k]};
}

Dof MortarCoupling::dof(long long column) const {
  if (column < 0)
    throw MortarCouplingError("grout::MortarCoupling::dof: column " + std::to_string(column));
  return {column / impl_->dim, int(column % impl_->dim)};
}

namespace {
const std::vector<DerivativeTriplet>& require(const MortarCoupling::Impl& m,
                                              const std::vector<DerivativeTriplet>& v) {
  if (!m.options.derivatives)
    throw MortarCouplingError(
        "grout::MortarCoupling: derivatives were not requested (MortarCouplingOptions::"
        "derivatives = true)");
  return v;
}
}  // namespace

const std::vector<DerivativeTriplet>& MortarCoupling::D_derivatives() const {
  return require(*impl_, impl_->dD);
}
const std::vector<DerivativeTriplet>& MortarCoupling::M_derivatives() const {
  return require(*impl_, impl_->dM);
}
const std::vector<DerivativeTriplet>& MortarCoupling::gap_derivatives() const {
  return require(*impl_, impl_->dg);
}

}  // namespace grout
