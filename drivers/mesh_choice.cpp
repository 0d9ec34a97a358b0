#include "drivers/mesh_choice.hpp"

#include <cstdlib>

#include "io/errors.hpp"
#include "nonlinear/linear_solver.hpp"

namespace grout {

MeshChoice choose_mesh(const Input& input, bool forced_replicated) {
  const auto replicated = [](std::string reason) { return MeshChoice{false, std::move(reason)}; };
  if (forced_replicated) return replicated("GROUT_MESH=replicated");
  if (!input.contact.empty()) return replicated("contact");
  if (input.dynamics.enabled) return replicated("dynamics");
  if (input.output.parallel == OutputParallel::per_rank)
    return replicated("output/parallel: per_rank");
  return {true, ""};
}

bool iterative_solver_chosen(const Input& input, long long num_nodes) {
  const LinearSolverType type = input.solver.linear.type;
  return type == LinearSolverType::belos ||
         (type == LinearSolverType::automatic &&
          auto_linear_solver_type(num_nodes * input.model.dimension, input.model.dimension) ==
              "belos");
}

bool replicated_mesh_forced() {
  const char* value = std::getenv("GROUT_MESH");
  if (!value || std::string(value).empty() || std::string(value) == "distributed") return false;
  if (std::string(value) == "replicated") return true;
  throw InputError(std::string("GROUT_MESH=") + value +
                   ": expected replicated or distributed (the default)");
}

}  // namespace grout
