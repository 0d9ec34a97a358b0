#include "nonlinear/system_layout.hpp"

#include "io/mesh.hpp"
#include "io/mesh_bodies.hpp"
#include "nonlinear/mechanics_problem.hpp"

namespace grout {

SystemLayout system_layout(const MechanicsProblem& problem, const Mesh& mesh) {
  SystemLayout layout;
  layout.multiplier_pairing = problem.multiplier_pairing();
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
