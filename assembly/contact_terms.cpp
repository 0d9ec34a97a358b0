#include "assembly/contact_terms.hpp"

#include <algorithm>
#include <stdexcept>

#include "assembly/contact_distribution.hpp"

namespace grout {

void ContactTerms::clear() {
  force_rows_.clear(), force_tags_.clear(), force_values_.clear();
  entry_rows_.clear(), entry_cols_.clear(), entry_keys_.clear(), entry_values_.clear();
}

void ContactTerms::begin_node(long long tag) {
  tag_ = tag;
  seq_ = 0;
}

void ContactTerms::add_force(GO row, double value) {
  force_rows_.push_back(row);
  force_tags_.push_back(tag_);
  force_values_.push_back(value);
}

void ContactTerms::add_entry(GO row, GO col, double value) {
  constexpr long long seq_bits = 24;
  const long long seq = seq_++;
  if (seq >= (1LL << seq_bits))
    throw std::logic_error("ContactTerms: too many Jacobian entries for one slave node");
  if (value == 0.0) return;
  entry_rows_.push_back(row);
  entry_cols_.push_back(col);
  entry_keys_.push_back((tag_ << seq_bits) + seq);
  entry_values_.push_back(value);
}

void ContactTerms::sum_forces_to_owners(const Map& map, MPI_Comm comm, Vector& F) {
  std::vector<GO> remote;
  for (GO row : force_rows_)
    if (!map.isNodeGlobalElement(row)) remote.push_back(row);
  std::sort(remote.begin(), remote.end());
  remote.erase(std::unique(remote.begin(), remote.end()), remote.end());
  std::vector<int> owners(remote.size(), -1);
  map.getRemoteIndexList(Teuchos::ArrayView<const GO>(remote), Teuchos::ArrayView<int>(owners));
  remote_owner_.clear();
  for (std::size_t k = 0; k < remote.size(); ++k) remote_owner_[remote[k]] = owners[k];

  const int n_ranks = map.getComm()->getSize();
  std::vector<std::vector<long long>> send_ids(n_ranks);
  std::vector<std::vector<double>> send_values(n_ranks);
  struct Term {
    GO row;
    long long tag;
    double value;
  };
  std::vector<Term> terms;
  for (std::size_t t = 0; t < force_rows_.size(); ++t) {
    if (map.isNodeGlobalElement(force_rows_[t])) {
      terms.push_back({force_rows_[t], force_tags_[t], force_values_[t]});
      continue;
    }
    const int owner = remote_owner_.at(force_rows_[t]);
    send_ids[owner].push_back(force_rows_[t]);
    send_ids[owner].push_back(force_tags_[t]);
    send_values[owner].push_back(force_values_[t]);
  }
  const std::vector<long long> ids = exchange_with_ranks(send_ids, comm);
  const std::vector<double> values = exchange_with_ranks(send_values, comm);
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
    Fv(map.getLocalElement(row), 0) += sum;
  }
}

std::vector<JacobianTerm> ContactTerms::owned_entries(const Map& map, MPI_Comm comm) const {
  std::vector<JacobianTerm> entries;
  entries.reserve(entry_rows_.size());
  const int n_ranks = map.getComm()->getSize();
  std::vector<std::vector<long long>> send_ids(n_ranks);
  std::vector<std::vector<double>> send_values(n_ranks);
  for (std::size_t e = 0; e < entry_rows_.size(); ++e) {
    if (map.isNodeGlobalElement(entry_rows_[e])) {
      entries.push_back({entry_rows_[e], entry_cols_[e], entry_keys_[e], entry_values_[e]});
      continue;
    }
    const int owner = remote_owner_.at(entry_rows_[e]);
    send_ids[owner].insert(send_ids[owner].end(), {entry_rows_[e], entry_cols_[e], entry_keys_[e]});
    send_values[owner].push_back(entry_values_[e]);
  }
  const std::vector<long long> ids = exchange_with_ranks(send_ids, comm);
  const std::vector<double> received = exchange_with_ranks(send_values, comm);
  entries.reserve(entries.size() + received.size());
  for (std::size_t e = 0; e < received.size(); ++e)
    entries.push_back({ids[3 * e], ids[3 * e + 1], ids[3 * e + 2], received[e]});
  return entries;
}

}  // namespace grout
