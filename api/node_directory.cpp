// NodeDirectory: sums of per-node entries over the ranks through a directory rank per id
// (node_directory.hpp).

#include "node_directory.hpp"

#include <algorithm>
#include <map>
#include <numeric>

namespace grout {

namespace {
bool distributed(MPI_Comm comm) {
  if (comm == MPI_COMM_NULL) return false;
  int size = 1;
  MPI_Comm_size(comm, &size);
  return size > 1;
}

/// total[id] += v[0 .. width) (an id met first starts at 0).
template <class Map>
void accumulate(Map& total, long long id, const double* v, int width) {
  auto& t = total[id];
  t.resize(width, 0.0);
  for (int c = 0; c < width; ++c) t[c] += v[c];
}
}  // namespace

void NodeDirectory::exchange(const std::vector<int>& to, const std::vector<long long>& ids,
                             const std::vector<double>& values, int width, std::vector<int>& from,
                             std::vector<long long>& in_ids, std::vector<double>& in_values) const {
  // Entries grouped by destination (stable), counts exchanged first.
  std::vector<int> order(ids.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return to[a] < to[b]; });
  std::vector<int> send_counts(size_, 0), recv_counts(size_);
  for (int r : to) ++send_counts[r];
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, comm_);
  std::vector<int> send_offsets(size_, 0), recv_offsets(size_, 0);
  std::partial_sum(send_counts.begin(), send_counts.end() - 1, send_offsets.begin() + 1);
  std::partial_sum(recv_counts.begin(), recv_counts.end() - 1, recv_offsets.begin() + 1);
  const int n_in = recv_offsets.back() + recv_counts.back();
  std::vector<long long> out_ids(ids.size());
  std::vector<double> out_values(ids.size() * width);
  for (std::size_t e = 0; e < order.size(); ++e) {
    out_ids[e] = ids[order[e]];
    for (int c = 0; c < width; ++c) out_values[e * width + c] = values[order[e] * width + c];
  }
  in_ids.resize(n_in);
  MPI_Alltoallv(out_ids.data(), send_counts.data(), send_offsets.data(), MPI_LONG_LONG,
                in_ids.data(), recv_counts.data(), recv_offsets.data(), MPI_LONG_LONG, comm_);
  if (width > 0) {
    std::vector<int> sc(size_), so(size_), rc(size_), ro(size_);
    for (int r = 0; r < size_; ++r) {
      sc[r] = send_counts[r] * width, so[r] = send_offsets[r] * width;
      rc[r] = recv_counts[r] * width, ro[r] = recv_offsets[r] * width;
    }
    in_values.resize(std::size_t(n_in) * width);
    MPI_Alltoallv(out_values.data(), sc.data(), so.data(), MPI_DOUBLE, in_values.data(), rc.data(),
                  ro.data(), MPI_DOUBLE, comm_);
  }
  from.resize(n_in);
  for (int r = 0; r < size_; ++r)
    std::fill(from.begin() + recv_offsets[r], from.begin() + recv_offsets[r] + recv_counts[r], r);
}

NodeDirectory::NodeDirectory(MPI_Comm comm, const std::vector<long long>& ids) {
  owners_.assign(ids.size(), 0);
  if (!distributed(comm)) return;
  comm_ = comm;
  MPI_Comm_rank(comm, &rank_);
  MPI_Comm_size(comm, &size_);
  std::vector<int> to(ids.size()), from;
  for (std::size_t e = 0; e < ids.size(); ++e) to[e] = directory_rank(ids[e]);
  std::vector<long long> in_ids;
  std::vector<double> none;
  exchange(to, ids, {}, 0, from, in_ids, none);
  for (std::size_t e = 0; e < in_ids.size(); ++e) {  // owner: the lowest registering rank
    const auto [it, added] = owner_of_.emplace(in_ids[e], from[e]);
    if (!added) it->second = std::min(it->second, from[e]);
  }
  // Each registering rank learns the owner of its ids: the answers, as doubles (ranks are exact).
  std::vector<double> answers(in_ids.size());
  for (std::size_t e = 0; e < in_ids.size(); ++e) answers[e] = owner_of_.at(in_ids[e]);
  std::vector<int> back;
  std::vector<long long> echo_ids;
  std::vector<double> echo;
  exchange(from, in_ids, answers, 1, back, echo_ids, echo);
  std::unordered_map<long long, int> mine;
  for (std::size_t e = 0; e < echo_ids.size(); ++e) mine[echo_ids[e]] = int(echo[e]);
  for (std::size_t e = 0; e < ids.size(); ++e) owners_[e] = mine.at(ids[e]);
}

std::map<long long, std::vector<double>> NodeDirectory::sum_at_directory(
    const std::vector<long long>& ids, const std::vector<double>& values, int width,
    std::vector<int>& to, std::vector<int>& from, std::vector<long long>& in_ids) const {
  to.resize(ids.size());
  for (std::size_t e = 0; e < ids.size(); ++e) to[e] = directory_rank(ids[e]);
  std::vector<double> in_values;
  exchange(to, ids, values, width, from, in_ids, in_values);
  // Sums in a fixed order (by sending rank, then entry): the same on every run.
  std::map<long long, std::vector<double>> total;
  for (std::size_t e = 0; e < in_ids.size(); ++e)
    accumulate(total, in_ids[e], in_values.data() + e * width, width);
  return total;
}

std::vector<double> NodeDirectory::sum_to_senders(const std::vector<long long>& ids,
                                                  const std::vector<double>& values,
                                                  int width) const {
  if (comm_ == MPI_COMM_NULL) {  // serial: sum repeated ids
    std::unordered_map<long long, std::vector<double>> total;
    for (std::size_t e = 0; e < ids.size(); ++e)
      accumulate(total, ids[e], values.data() + e * width, width);
    std::vector<double> out(values.size());
    for (std::size_t e = 0; e < ids.size(); ++e)
      std::copy(total[ids[e]].begin(), total[ids[e]].end(), out.begin() + e * width);
    return out;
  }
  std::vector<int> to, from;
  std::vector<long long> in_ids;
  auto total = sum_at_directory(ids, values, width, to, from, in_ids);
  std::vector<double> answers(in_ids.size() * width);
  for (std::size_t e = 0; e < in_ids.size(); ++e)
    std::copy(total[in_ids[e]].begin(), total[in_ids[e]].end(), answers.begin() + e * width);
  // Back to the senders; each rank's entries return grouped by directory rank, in their order.
  std::vector<int> back;
  std::vector<long long> echo_ids;
  std::vector<double> echo;
  exchange(from, in_ids, answers, width, back, echo_ids, echo);
  std::vector<int> order(ids.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return to[a] < to[b]; });
  std::vector<double> out(values.size());
  for (std::size_t e = 0; e < order.size(); ++e)
    std::copy(echo.begin() + e * width, echo.begin() + (e + 1) * width,
              out.begin() + std::size_t(order[e]) * width);
  return out;
}

void NodeDirectory::sum_to_owners(const std::vector<long long>& ids,
                                  const std::vector<double>& values, int width,
                                  std::vector<long long>& out_ids,
                                  std::vector<double>& out_values) const {
  std::map<long long, std::vector<double>> total;
  if (comm_ == MPI_COMM_NULL) {
    for (std::size_t e = 0; e < ids.size(); ++e)
      accumulate(total, ids[e], values.data() + e * width, width);
  } else {
    std::vector<int> to, from;
    std::vector<long long> in_ids;
    const auto at_directory = sum_at_directory(ids, values, width, to, from, in_ids);
    std::vector<int> owner_rank;
    std::vector<long long> sum_ids;
    std::vector<double> sums, in_values;
    for (const auto& [id, t] : at_directory) {
      const auto it = owner_of_.find(id);
      owner_rank.push_back(it != owner_of_.end() ? it->second : rank_);  // unregistered: keep
      sum_ids.push_back(id);
      sums.insert(sums.end(), t.begin(), t.end());
    }
    exchange(owner_rank, sum_ids, sums, width, from, in_ids, in_values);
    for (std::size_t e = 0; e < in_ids.size(); ++e)
      accumulate(total, in_ids[e], in_values.data() + e * width, width);
  }
  out_ids.clear();
  out_values.clear();
  for (const auto& [id, t] : total) {
    out_ids.push_back(id);
    out_values.insert(out_values.end(), t.begin(), t.end());
  }
}

}  // namespace grout
