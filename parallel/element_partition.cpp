// Zoltan2 RCB (Zoltan's RCB underneath in Trilinos 13.2) over element centroids
// (parallel/element_partition.hpp). The only translation unit that includes Zoltan2's headers.

#include "parallel/element_partition.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Zoltan2_BasicVectorAdapter.hpp>
#include <Zoltan2_PartitioningProblem.hpp>
#include <algorithm>

namespace grout {

std::vector<int> partition_elements_rcb(const Comm& comm, int dimension,
                                        const std::vector<GlobalIndex>& ids,
                                        const std::vector<double>& centroids,
                                        const std::vector<double>& weights, int num_weights,
                                        int num_parts) {
  std::vector<int> part(ids.size(), 0);
  if (num_parts <= 1) return part;
  // Zoltan's RCB fails ("Zoltan LB_Partition") on fewer elements than parts: each element then
  // stays on the rank whose slice holds it.
  long long local_count = (long long)ids.size(), global_count = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, local_count, Teuchos::outArg(global_count));
  if (global_count < num_parts)
    return std::vector<int>(ids.size(), std::min(comm.getRank(), num_parts - 1));
  using Types = Zoltan2::BasicUserTypes<double, int, long long>;
  using Adapter = Zoltan2::BasicVectorAdapter<Types>;
  // One weight per element, or two (the element's weight and whether it lies on the contact
  // surface): Zoltan's multi-criteria RCB then balances both, each part its share of the
  // contact surface.
  std::vector<const double*> weight_entries;
  std::vector<int> weight_strides;
  for (int w = 0; w < num_weights; ++w) {
    weight_entries.push_back(weights.data() + w);
    weight_strides.push_back(num_weights);
  }
  std::vector<const double*> entries;
  std::vector<int> strides;
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
