#pragma once
// Two-body meshes for the frictional verification cases (docs/verification.md #7; #3 and #9
// use stacked_2d/3d of contact_meshes.hpp).

#include "io/mesh.hpp"

namespace grout {

/// Friction base test (Dong 1999; Kratos pure_friction_test): a short upper block I on a
/// longer lower block II, both QUAD4 (or TRI3), structured, non-matching along the interface
/// when the element sizes differ.
///   "lower" (block II) = [0, width_lower] x [0, height_lower]
///   "upper" (block I)  = [x_upper, x_upper + width_upper] x [y1, y1 + height_upper],
///                        y1 = height_lower + gap
/// Defaults: the Kratos geometry 0.35 x 0.2 (lower 0.35 x 0.075 with 40 x 6 elements, upper
/// 0.1 x 0.125 with 8 x 10 elements, 386 nodes), zero gap.
/// Sets per body (prefix "lower_"/"upper_"): bottom right top left (side set + node set),
/// plus "lower_top_contact": the part of the lower top face under block I (faces with both
/// nodes in [x_upper, x_upper + width_upper]; side set + node set).
struct DongBlocks {
  int nx_lower = 40, ny_lower = 6, nx_upper = 8, ny_upper = 10;
  double width_lower = 0.35, height_lower = 0.075;
  double width_upper = 0.1, height_upper = 0.125, x_upper = 0.0, gap = 0.0;
  bool triangles_lower = false, triangles_upper = false;
};
Mesh dong_blocks_2d(const DongBlocks& spec);

/// Frictional Hertz (Cattaneo-Mindlin, docs/verification.md #9): hertz_cylinders_mesh (see
/// contact_meshes.hpp) plus single-node node sets at the centres and the right ends of the
/// flat faces: "upper_top_centre" (the node nearest (0, R + gap)), "upper_top_end"
/// (R, R + gap), "lower_bottom_centre" (0, -R), "lower_bottom_end" (R, -R). Both flat faces
/// can then be loaded alike (the two bodies deform as mirror images, and no tangential
/// traction arises under the normal load alone for identical materials) with the rigid
/// modes removed by a pin and a roller that carry no force.
Mesh hertz_cylinders_pinned(int level, double radius = 8.0, double gap = 0.0,
                            double contact_width = 2.5);

}  // namespace grout
