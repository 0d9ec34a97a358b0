#include "assembly/initial_conditions.hpp"

#include <cmath>

#include "io/errors.hpp"

namespace grout {

Teuchos::RCP<Vector> initial_velocity(const SolidProblem& solid, const Mesh& mesh,
                                      const Input& input) {
  const int dim = mesh.dimension;
  std::vector<double> value(mesh.num_nodes() * dim, 0.0);
  for (const InitialVelocityInput& entry : input.initial_velocity) {
    const ElementBlock* block = mesh.find_block(entry.block);
    if (!block) {
      throw InputError(input.file + ": grout/initial_velocity/" + entry.name +
                       "/block: no block '" + entry.block + "' in mesh '" + mesh.file + "'");
    }
    for (GlobalIndex node : block->connectivity) {
      const double* X = &mesh.coordinates[node * dim];
      for (int d = 0; d < dim; ++d) {
        const double v = entry.components[d](0.0, X[0], X[1], dim == 3 ? X[2] : 0.0);
        if (!std::isfinite(v)) {
          throw InputError(input.file + ": grout/initial_velocity/" + entry.name + "/" + "xyz"[d] +
                           ": not finite at node " + std::to_string(node + 1));
        }
        value[node * dim + d] = v;
      }
    }
  }
  auto v0 = solid.create_vector();
  const auto& map = *v0->getMap();
  auto view = v0->getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (std::size_t i = 0; i < view.extent(0); ++i) view(i, 0) = value[map.getGlobalElement(LO(i))];
  return v0;
}

}  // namespace grout
