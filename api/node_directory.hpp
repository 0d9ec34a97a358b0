#pragma once
// A rendezvous of node ids over the ranks of a communicator (not installed), for
// grout::MortarCoupling's sums over ranks: the entries of node id i meet on rank i mod P (its
// "directory" rank), which knows every rank that registered i and names the lowest of them the
// node's owner. Two all-to-all exchanges per sum; serial (MPI_COMM_NULL or one rank): no
// communication, every registered node is owned here.

#include <mpi.h>

#include <map>
#include <unordered_map>
#include <vector>

namespace grout {

class NodeDirectory {
 public:
  NodeDirectory() = default;
  /// Collective: registers this rank's node ids (each once per rank).
  NodeDirectory(MPI_Comm comm, const std::vector<long long>& ids);

  /// Per registered id (in registration order): the owning rank (the lowest that registered it).
  const std::vector<int>& owners() const { return owners_; }

  /// Collective: for each entry (ids[e], values[e·width …]), the sum over all ranks of the
  /// entries with that id; every rank gets the sums of the ids it sent, in its order.
  std::vector<double> sum_to_senders(const std::vector<long long>& ids,
                                     const std::vector<double>& values, int width) const;

  /// Collective: the same sums, delivered to the owners only: out_ids (ascending) are the
  /// registered ids this rank owns that appear in some rank's entries, out_values their sums.
  void sum_to_owners(const std::vector<long long>& ids, const std::vector<double>& values,
                     int width, std::vector<long long>& out_ids,
                     std::vector<double>& out_values) const;

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0, size_ = 1;
  std::vector<int> owners_;
  std::unordered_map<long long, int> owner_of_;  ///< this rank's directory part: id → owner
  int directory_rank(long long id) const { return int(id % size_); }
  /// Sends entries (id, width values) to the given ranks; returns what this rank received.
  void exchange(const std::vector<int>& to, const std::vector<long long>& ids,
                const std::vector<double>& values, int width, std::vector<int>& from,
                std::vector<long long>& in_ids, std::vector<double>& in_values) const;
  /// Sends each entry to its id's directory rank (to[e]) and sums the entries received there
  /// per id; from/in_ids: the received entries' senders and ids, in arrival order.
  std::map<long long, std::vector<double>> sum_at_directory(const std::vector<long long>& ids,
                                                            const std::vector<double>& values,
                                                            int width, std::vector<int>& to,
                                                            std::vector<int>& from,
                                                            std::vector<long long>& in_ids) const;
};

}  // namespace grout
