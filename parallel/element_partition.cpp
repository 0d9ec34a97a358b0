// Zoltan2 RCB (Zoltan's RCB underneath in Trilinos 13.2) over element centroids
// (parallel/element_partition.hpp). The only translation unit that includes Zoltan2's headers.

#include "parallel/element_partition.hpp"

#include <Teuchos_ParameterList.hpp>
#include <Zoltan2_BasicVectorAdapter.hpp>
#include <Zoltan2_PartitioningProblem.hpp>

namespace grout {

std::vector<int> partition_elements_rcb(const Comm& comm, int dimension,
                                        const std::vector<GlobalIndex>& ids,
                                        const std::vector<double>& centroids,
                                        const std::vector<double>& weights, int num_parts) {
  std::vector<int> part(ids.size(), 0);
  if (num_parts <= 1) return part;
  using Types = Zoltan2::BasicUserTypes<double, int, long long>;
  using Adapter = Zoltan2::BasicVectorAdapter<Types>;
  std::vector<const double*> entries, weight_entries{weights.data()};
  std::vector<int> strides, weight_strides{1};
  for (int d = 0; d < dimension; ++d) {
    entries.push_back(centroids.data() + d);
    strides.push_back(3);
  }
  Adapter adapter(int(ids.size()), ids.data(), entries, strides, weight_entries, weight_strides);
  Teuchos::ParameterList parameters("grout element partition");
  parameters.set("algorithm", "rcb");
  parameters.set("num_global_parts", num_parts);
  parameters.set("imbalance_tolerance", 1.01);
  // Zoltan2's "rcb" runs Zoltan's RCB, whose default debug level prints its parameters.
  parameters.sublist("zoltan_parameters").set("debug_level", "0");
  Zoltan2::PartitioningProblem<Adapter> problem(&adapter, &parameters, Teuchos::rcpFromRef(comm));
  problem.solve();
  const auto* parts = problem.getSolution().getPartListView();
  for (std::size_t i = 0; i < part.size(); ++i) part[i] = int(parts[i]);
  return part;
}

}  // namespace grout
