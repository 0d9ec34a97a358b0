#include "drivers/mesh_choice.hpp"

#include <cstdlib>

#include "io/errors.hpp"
#include "nonlinear/linear_solver.hpp"

namespace grout {

MeshChoice choose_mesh(const Input& input, const std::function<long long()>& num_nodes,
                       bool forced_replicated) {
  const auto replicated = [](std::string reason) { return MeshChoice{false, std::move(reason)}; };
  if (forced_replicated) return replicated("GROUT_MESH=replicated");
  if (input.dynamics.enabled) return replicated("dynamics");
  for (const ContactInput& c : input.contact) {
    if (c.self) return replicated("self-contact");
    if (c.type == ContactKind::tied) return replicated("tied contact");
  }
  if (input.output.parallel == OutputParallel::per_rank)
    return replicated("output/parallel: per_rank");
  // The unknowns: the displacements, num_nodes * dim, and with contact the multipliers, dim
  // per slave node (at most as many again): `auto` must pick a direct solver for the most.
  const LinearSolverType type = input.solver.linear.type;
  const long long most_unknowns =
      num_nodes() * input.model.dimension * (input.contact.empty() ? 1 : 2);
  const bool iterative = type == LinearSolverType::belos ||
                         (type == LinearSolverType::automatic &&
                          auto_linear_solver_type(most_unknowns, input.model.dimension) == "belos");
  if (iterative) return replicated("the iterative linear solver");
  return {true, ""};
}

bool replicated_mesh_forced() {
  const char* value = std::getenv("GROUT_MESH");
  if (!value || std::string(value).empty() || std::string(value) == "distributed") return false;
  if (std::string(value) == "replicated") return true;
  throw InputError(std::string("GROUT_MESH=") + value +
                   ": expected replicated or distributed (the default)");
}

}  // namespace grout
