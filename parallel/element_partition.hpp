#pragma once
// The element partition of the distributed mesh: Zoltan2's recursive coordinate bisection
// (its "rcb", multi-jagged with one cut per level) on element centroids, each element
// weighted, over elements that the ranks hold in any distribution (here the reading slices).

#include <vector>

#include "assembly/tpetra_types.hpp"
#include "io/mesh.hpp"

namespace grout {

/// \brief Collective. The part (0 .. num_parts-1) of each of this rank's elements: ids[i]
/// its global id, centroids[3 i .. 3 i + dimension) its centroid, weights[num_weights i + w]
/// >= 0 its weight w (num_weights 1 or 2, the same on every rank). Zoltan2 RCB balances the sum
/// of each weight per part within 1 % (imbalance_tolerance 1.01; two weights: Zoltan's
/// multi-criteria RCB, which balances both as well as it can).
/// With one part every element gets 0 and Zoltan2 is not called.
std::vector<int> partition_elements_rcb(const Comm& comm, int dimension,
                                        const std::vector<GlobalIndex>& ids,
                                        const std::vector<double>& centroids,
                                        const std::vector<double>& weights, int num_weights,
                                        int num_parts);

}  // namespace grout
