#include "assembly/initial_conditions.hpp"

#include <cmath>
#include <string>

#include "io/errors.hpp"

namespace grout {

Teuchos::RCP<Vector> initial_velocity(const SolidProblem& solid, const Mesh& mesh,
                                      const Input& input) {
  // The owned nodes of each block, from the solid's local blocks: every element around an owned
  // node is local (owned or ghost), so on a distributed mesh's part too.
  const int dim = solid.dimension(), n_owned = solid.num_owned_nodes();
  const auto X = solid.column_coordinates();
  std::vector<double> value(std::size_t(n_owned) * dim, 0.0);  // owned node k, component d
  for (const InitialVelocityInput& entry : input.initial_velocity) {
    if (!mesh.find_block(entry.block)) {
      throw InputError(input.file + ": grout/initial_velocity/" + entry.name +
                       "/block: no block '" + entry.block + "' in mesh '" + mesh.file + "'");
    }
    for (const LocalBlock& block : solid.local_blocks()) {
      if (block.name != entry.block) continue;
      for (std::size_t e = 0; e < block.nodes.extent(0); ++e)
        for (int a = 0; a < block.nodes_per_element; ++a) {
          const int k = block.nodes(e, a);
          if (k >= n_owned) continue;
          const double x[3] = {X(k, 0), X(k, 1), dim == 3 ? X(k, 2) : 0.0};
          for (int d = 0; d < dim; ++d) {
            const double v = entry.components[d](0.0, x[0], x[1], x[2]);
            if (!std::isfinite(v)) {
              throw InputError(input.file + ": grout/initial_velocity/" + entry.name + "/" +
                               "xyz"[d] + ": not finite at node " +
                               std::to_string(solid.column_node(k) + 1));
            }
            value[std::size_t(k) * dim + d] = v;
          }
        }
    }
  }
  auto v0 = solid.create_vector();  // owned dof i: owned node i / dim, component i % dim
  auto view = v0->getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (std::size_t i = 0; i < view.extent(0); ++i) view(i, 0) = value[i];
  return v0;
}

}  // namespace grout
