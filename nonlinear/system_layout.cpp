#include "nonlinear/system_layout.hpp"

#include <utility>

#include "io/mesh.hpp"
#include "io/mesh_bodies.hpp"
#include "nonlinear/mechanics_problem.hpp"

namespace grout {

SystemLayout system_layout(const MechanicsProblem& problem, const Mesh& mesh) {
  return system_layout(problem.multiplier_pairing(), mesh);
}

SystemLayout system_layout(std::vector<std::pair<GO, GO>> multiplier_pairing, const Mesh& mesh) {
  SystemLayout layout;
  layout.multiplier_pairing = std::move(multiplier_pairing);
  layout.dofs_per_node = mesh.dimension;
  layout.coordinates = mesh.coordinates;
  layout.dim = mesh.dimension;
  layout.node_bodies = node_bodies(mesh);
  return layout;
}

SystemLayout mass_matrix_layout(const Mesh& mesh) {
  SystemLayout layout;
  layout.coordinates = mesh.coordinates;
  layout.dim = mesh.dimension;
  return layout;
}

}  // namespace grout
