#include "assembly/folded_elements.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <cstdio>

#include "kernels/corner_jacobian.hpp"

namespace grout {

FoldedElement most_folded_element(const SolidProblem& solid, const Vector& u) {
  const int dim = solid.dimension();
  Vector u_column(solid.column_map());
  solid.import_to_column(u, u_column);
  const auto u_view =
      Kokkos::subview(u_column.getLocalViewHost(Tpetra::Access::ReadOnly), Kokkos::ALL(), 0);
  const auto X_all = solid.column_coordinates();
  FoldedElement local;
  for (const LocalBlock& block : solid.local_blocks()) {
    if (!block.finite_strain) continue;
    for (std::size_t e = 0; e < block.nodes.extent(0); ++e) {
      if (!block.owned(e)) continue;
      double X[max_element_dofs], x[max_element_dofs];
      for (int a = 0; a < block.nodes_per_element; ++a) {
        for (int d = 0; d < dim; ++d) {
          X[a * dim + d] = X_all(block.nodes(e, a), d);
          x[a * dim + d] = X[a * dim + d] + u_view(block.nodes(e, a) * dim + d);
        }
      }
      int corner = -1;
      const double det_F = min_corner_det_F(block.topology, dim, X, x, corner);
      if (corner >= 0 && det_F < local.det_F)
        local = FoldedElement{det_F, block.name, GlobalIndex(block.global(e)), corner};
    }
  }
  // The smallest det F, then the lowest rank that holds it sends its element.
  const Comm& comm = *solid.comm();
  double det_F = local.det_F;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, 1, &local.det_F, &det_F);
  const int rank = comm.getRank(), none = comm.getSize();
  int holder = local.element >= 0 && local.det_F == det_F ? rank : none, first = none;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, 1, &holder, &first);
  if (first == none) return FoldedElement{};
  long long element = local.element;
  int corner = local.corner;
  Teuchos::broadcast(comm, first, &element);
  Teuchos::broadcast(comm, first, &corner);
  int length = int(local.block.size());
  Teuchos::broadcast(comm, first, &length);
  std::string block = rank == first ? local.block : std::string(std::size_t(length), ' ');
  if (length > 0) Teuchos::broadcast(comm, first, length, &block[0]);
  return FoldedElement{det_F, block, GlobalIndex(element), corner};
}

void warn_of_folded_elements(const SolidProblem& solid, const Vector& u, int step, double time) {
  const FoldedElement folded = most_folded_element(solid, u);
  if (folded.element < 0 || folded.det_F > 0.0 || solid.comm()->getRank() != 0) return;
  std::fprintf(
      stderr,
      "grout: warning: step %d (t = %g): global element %lld of block '%s' is folded: det F = "
      "%.3g at its local node %d (det F > 0 at its Gauss points); its corner is "
      "inside out: refine the mesh there or reduce the load (docs/robustness.md)\n",
      step, time, static_cast<long long>(folded.element + 1), folded.block.c_str(), folded.det_F,
      folded.corner + 1);
  std::fflush(stderr);
}

}  // namespace grout
