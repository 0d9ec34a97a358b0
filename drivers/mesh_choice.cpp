#include "drivers/mesh_choice.hpp"

#include <cstdlib>

#include "io/errors.hpp"
#include "nonlinear/linear_solver.hpp"

namespace grout {

MeshChoice choose_mesh(const Input& input, const std::function<long long()>& num_nodes,
                       bool forced_replicated) {
  const auto replicated = [](std::string reason) { return MeshChoice{false, std::move(reason)}; };
  if (forced_replicated) return replicated("GROUT_MESH=replicated");
  if (input.dynamics.enabled && !input.contact.empty()) return replicated("dynamics with contact");
  for (const ContactInput& c : input.contact) {
    if (c.self) return replicated("self-contact");
    if (c.type == ContactKind::tied) return replicated("tied contact");
  }
  // With contact, the iterative path's layout still takes every node's coordinates and body.
  // The unknowns: the displacements, num_nodes * dim; the multipliers come on top, which the
  // driver counts on the distributed mesh (iterative_for_unknowns).
  if (!input.contact.empty() && iterative_solver_chosen(input, num_nodes()))
    return replicated("contact on the iterative linear solver");
  return {true, ""};
}

bool iterative_solver_chosen(const Input& input, long long num_nodes) {
  return input.solver.linear.type == LinearSolverType::belos ||
         iterative_for_unknowns(input, num_nodes * input.model.dimension);
}

bool iterative_for_unknowns(const Input& input, long long unknowns) {
  return input.solver.linear.type == LinearSolverType::automatic &&
         auto_linear_solver_type(unknowns, input.model.dimension) == "belos";
}

bool replicated_mesh_forced() {
  const char* value = std::getenv("GROUT_MESH");
  if (!value || std::string(value).empty() || std::string(value) == "distributed") return false;
  if (std::string(value) == "replicated") return true;
  throw InputError(std::string("GROUT_MESH=") + value +
                   ": expected replicated or distributed (the default)");
}

}  // namespace grout
