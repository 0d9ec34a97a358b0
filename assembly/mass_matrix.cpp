#include "assembly/mass_matrix.hpp"

#include "assembly/agree_on_errors.hpp"
#include "assembly/crs_row_search.hpp"
#include "io/errors.hpp"
#include "kernels/mass_matrix.hpp"

namespace grout {

Teuchos::RCP<Matrix> assemble_mass_matrix(const SolidProblem& solid, bool lumped) {
  Teuchos::RCP<Matrix> M = solid.create_matrix();
  M->resumeFill();
  M->setAllToScalar(0.0);
  const int dim = solid.dimension();
  const int n_owned = solid.num_owned_nodes();
  const auto X_all = solid.column_coordinates();
  const auto local = M->getLocalMatrixHost();
  const auto row_map = local.graph.row_map;
  const auto entries = local.graph.entries;
  const auto values = local.values;
  // An element only one rank assembles may fail: every rank learns it before the collective
  // fillComplete (a throw on one rank alone left the other in MPI_Allreduce).
  agree_on_errors(*solid.comm(), [&] {
    for (const LocalBlock& block : solid.local_blocks()) {
      const int npe = block.nodes_per_element;
      for (std::size_t e = 0; e < block.nodes.extent(0); ++e) {
        double X[max_element_dofs], Me[max_element_nodes * max_element_nodes];
        for (int a = 0; a < npe; ++a)
          for (int d = 0; d < dim; ++d) X[a * dim + d] = X_all(block.nodes(e, a), d);
        if (element_mass(block.topology, dim, X, block.density, lumped, Me) != ElementStatus::ok) {
          throw InputError("element " + std::to_string(block.global(e) + 1) + " of block '" +
                           block.name +
                           "' is inverted (det J <= 0 at a point of the mass matrix's Gauss rule) "
                           "or of an unsupported type");
        }
        // Scatter M_ab δ_ij into the owned rows (the graph's columns of a node row are sorted).
        for (int a = 0; a < npe; ++a) {
          const int k = block.nodes(e, a);
          if (k >= n_owned) continue;
          for (int i = 0; i < dim; ++i) {
            const auto begin = row_map(k * dim + i), end = row_map(k * dim + i + 1);
            for (int b = 0; b < npe; ++b) {
              if (Me[a * npe + b] == 0.0) continue;
              const int column = block.nodes(e, b) * dim + i;
              values(lower_bound_in_row(entries, begin, end, column)) += Me[a * npe + b];
            }
          }
        }
      }
    }
  });
  M->fillComplete(solid.owned_map(), solid.owned_map());
  return M;
}

}  // namespace grout
