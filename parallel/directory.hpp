#pragma once
// Directory exchanges of the distributed mesh: an entity's home is the rank whose reading
// slice holds its global index (parallel/slices.hpp), so any rank can ask about any node or
// element without a global table.

#include <vector>

#include "assembly/tpetra_types.hpp"
#include "io/mesh.hpp"

namespace grout {

/// Questions received by a home rank: the ids asked of it, concatenated in the askers' rank
/// order, `counts[r]` of them from rank r.
struct DirectoryQuestions {
  std::vector<long long> ids;
  std::vector<int> counts;
};

/// Collective. Sends each of `ids` (sorted ascending) to its home among the slices of
/// [0, n), and returns the questions this rank received.
DirectoryQuestions ask_homes(const Comm& comm, GlobalIndex n, const std::vector<GlobalIndex>& ids);

/// Collective. Sends `answers[r]` to rank r (the answers to rank r's questions, in their
/// order) and returns this rank's answers, concatenated in home rank order: for sorted
/// question ids this is the order of the questions.
std::vector<double> answer(const Comm& comm, const std::vector<std::vector<double>>& answers);
std::vector<long long> answer(const Comm& comm, const std::vector<std::vector<long long>>& answers);

/// Collective. Sends `messages[r]` to rank r; returns what this rank received, in rank
/// order, and (if given) how much from each rank.
std::vector<long long> send_to_ranks(const Comm& comm,
                                     const std::vector<std::vector<long long>>& messages,
                                     std::vector<int>* counts = nullptr);

}  // namespace grout
