// Directory exchanges (parallel/directory.hpp) over the all-to-all of
// assembly/contact_distribution.hpp.

#include "parallel/directory.hpp"

#include "assembly/contact_distribution.hpp"
#include "assembly/raw_mpi_comm.hpp"
#include "parallel/slices.hpp"

namespace grout {

std::vector<long long> send_to_ranks(const Comm& comm,
                                     const std::vector<std::vector<long long>>& messages,
                                     std::vector<int>* counts) {
  return exchange_with_ranks(messages, raw_mpi_comm(comm), counts);
}

DirectoryQuestions ask_homes(const Comm& comm, GlobalIndex n, const std::vector<GlobalIndex>& ids) {
  const int ranks = comm.getSize();
  std::vector<std::vector<long long>> questions(static_cast<std::size_t>(ranks));
  for (GlobalIndex id : ids) questions[std::size_t(slice_rank(n, id, ranks))].push_back(id);
  DirectoryQuestions received;
  received.ids = send_to_ranks(comm, questions, &received.counts);
  return received;
}

std::vector<double> answer(const Comm& comm, const std::vector<std::vector<double>>& answers) {
  return exchange_with_ranks(answers, raw_mpi_comm(comm));
}

std::vector<long long> answer(const Comm& comm,
                              const std::vector<std::vector<long long>>& answers) {
  return exchange_with_ranks(answers, raw_mpi_comm(comm));
}

}  // namespace grout
