#pragma once
// What each rank holds of a mesh, as one line per rank for `grout --timers` and
// grout_mesh_probe (the distributed mesh's and the solid's holdings).

#include <string>

#include "assembly/tpetra_types.hpp"

namespace grout {

/// This rank's counts: owned and ghost nodes and elements; side_set_faces < 0: not reported.
struct RankHoldings {
  long long owned_nodes = 0, ghost_nodes = 0, owned_elements = 0, ghost_elements = 0;
  long long side_set_faces = -1;
};

/// \brief Collective: on rank 0 one line per rank, "<what> on rank r: nodes a owned + b ghost
/// (p % of N), elements c owned + d ghost (q % of E)[, side-set faces f owned]"; empty on the
/// other ranks.
std::string describe_rank_holdings(const Comm& comm, const char* what, const RankHoldings& mine,
                                   long long global_nodes, long long global_elements);

}  // namespace grout
