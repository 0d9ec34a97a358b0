// MechanicsProblem::describe_contact_holdings: what each rank holds of each contact interface,
// and describe_prescribed_holdings: how many prescribed values, for `grout --timers`
// (docs/performance.md, "Scale: what a rank holds"). A master face travels to every rank whose
// search region (the box of its evaluated slave faces, widened by the search factor) it overlaps
// (assembly/contact_distribution.hpp), so the received count is the search's communication volume:
// per face its ids and nodes, and per node its coordinates, displacement and last converged
// displacement.

#include <Teuchos_CommHelpers.hpp>
#include <cstdio>
#include <vector>

#include "nonlinear/mechanics_problem.hpp"

namespace grout {

std::string MechanicsProblem::describe_contact_holdings() const {
  const Comm& comm = *solid_.comm();
  constexpr int fields = 5;
  std::string text;
  for (const auto& interface : interfaces_) {
    const ContactInterface::Holdings h = interface->holdings();
    const long long mine[fields] = {h.slave_faces, h.evaluated_slave_faces, h.owned_master_faces,
                                    h.searched_master_faces, h.surface_nodes};
    std::vector<long long> all(std::size_t(fields * comm.getSize()));
    Teuchos::gatherAll(comm, fields, mine, int(all.size()), all.data());
    if (comm.getRank() != 0) continue;
    for (int r = 0; r < comm.getSize(); ++r) {
      const long long* c = all.data() + fields * r;
      char line[320];
      std::snprintf(line, sizeof line,
                    "contact %s on rank %d: slave faces %lld (%lld evaluated), master faces %lld "
                    "owned, %lld after the search, surface nodes %lld\n",
                    interface->input().name.c_str(), r, c[0], c[1], c[2], c[3], c[4]);
      text += line;
    }
  }
  return text;
}

std::string MechanicsProblem::describe_prescribed_holdings() const {
  const Comm& comm = *solid_.comm();
  const long long mine[2] = {(long long)prescribed_->size(),
                             (long long)solid_.column_map()->getNodeNumElements()};
  std::vector<long long> all(std::size_t(2 * comm.getSize()));
  Teuchos::gatherAll(comm, 2, mine, int(all.size()), all.data());
  if (comm.getRank() != 0) return "";
  std::string text;
  for (int r = 0; r < comm.getSize(); ++r) {
    const long long held = all[2 * r], column = all[2 * r + 1];
    char line[240];
    std::snprintf(line, sizeof line,
                  "prescribed values on rank %d: %lld of %lld dofs (%lld owned + ghost, %lld "
                  "contact nodes' beyond)\n",
                  r, held, (long long)num_u_, column, held - column);
    text += line;
  }
  return text;
}

}  // namespace grout
