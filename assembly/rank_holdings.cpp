#include "assembly/rank_holdings.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <cstdio>
#include <vector>

namespace grout {

std::string describe_rank_holdings(const Comm& comm, const char* what, const RankHoldings& mine,
                                   long long global_nodes, long long global_elements) {
  const long long local[5] = {mine.owned_nodes, mine.ghost_nodes, mine.owned_elements,
                              mine.ghost_elements, mine.side_set_faces};
  std::vector<long long> all(std::size_t(5 * comm.getSize()));
  Teuchos::gatherAll(comm, 5, local, int(all.size()), all.data());
  if (comm.getRank() != 0) return {};
  const auto percent = [](long long a, long long b) {
    return b > 0 ? 100.0 * double(a) / double(b) : 0.0;
  };
  std::string text;
  for (int r = 0; r < comm.getSize(); ++r) {
    const long long* c = all.data() + 5 * r;
    char line[320];
    int n =
        std::snprintf(line, sizeof line,
                      "%s on rank %d: nodes %lld owned + %lld ghost (%.1f %% of %lld), elements "
                      "%lld owned + %lld ghost (%.1f %% of %lld)",
                      what, r, c[0], c[1], percent(c[0] + c[1], global_nodes), global_nodes, c[2],
                      c[3], percent(c[2] + c[3], global_elements), global_elements);
    if (c[4] >= 0 && n > 0 && n < int(sizeof line))
      std::snprintf(line + n, sizeof line - std::size_t(n), ", side-set faces %lld owned", c[4]);
    text += line;
    text += '\n';
  }
  return text;
}

}  // namespace grout
