#pragma once
// Gap bands of the contact elements, for the separate partition of the distributed mesh
// (DistributionOptions::master_side_sets).
//
// A contact zone grows from the closest points of the two surfaces: at any load it is, near
// enough, the slave faces whose initial distance to the master surface is below some value.
// One RCB over all contact elements cuts them by position only, and where the surface is much
// larger than the zone (Hertz spheres: the zone round the pole, a fifth of the slave nodes) one
// part gets all of the zone: on 2 ranks the other evaluated slave faces that found no master
// face, and waited (docs/performance.md, "Two ranks against one in 3D"). Sorted by their
// distance to the nearest master element and cut into bands of equal count, each band
// partitioned by its own RCB (all across one axis, so that the cuts of neighbouring bands nearly
// meet: parallel/distributed_mesh.cpp), the contact elements of every zone that is a union of
// bands are shared evenly, whatever the zone's final size. The master elements are cut the same
// way, by their distance to the slave surface (the contact terms of master rows are summed and
// assembled by the master nodes' owners), each band's slave and master elements apart.

#include <vector>

#include "assembly/tpetra_types.hpp"
#include "io/mesh.hpp"

namespace grout {

/// Distances from each query point to the nearest of `points` whose id differs from the
/// query's (3 coordinates per point, unused ones 0; +inf when there is none): a k-d tree,
/// O(log n) per query for points spread over a surface.
std::vector<double> nearest_distances(const std::vector<double>& points,
                                      const std::vector<GlobalIndex>& point_ids,
                                      const std::vector<double>& queries,
                                      const std::vector<GlobalIndex>& query_ids);

/// How many bands `num_contact` contact elements (over all ranks) are cut into for
/// `num_parts` parts: at least 64 elements per part in a band, at most 8 bands, at least 1.
int num_gap_bands(GlobalIndex num_contact, int num_parts);

/// \brief Collective. Per element of this rank (ids[i], centroid centroids[3 i .. 3 i + 3)):
/// -1 unless slave[i] or master[i] (a contact element, with a face on a slave or a master side
/// set); for a contact element 2 b for a slave element, 2 b + 1 for a master one, b its band in
/// [0, num_gap_bands): the contact elements of all ranks sorted by their distance to the other
/// surface (a slave element's centroid to the nearest master element's, a master element's to
/// the nearest slave element's, on any rank; the smaller for an element on both, which counts
/// as a slave one), cut into bands of equal count (equal distances in one band). Without slave
/// or without master elements every contact element is in band 0.
std::vector<int> contact_gap_bands(const Comm& comm, const std::vector<GlobalIndex>& ids,
                                   const std::vector<double>& centroids,
                                   const std::vector<char>& slave, const std::vector<char>& master);

}  // namespace grout
