#pragma once
// Two-body meshes for the contact and mesh-tying verification cases (docs/verification.md #1, #2,
// 4, 5, 6, 8, 10, 21). Every body is its own element block; bodies share no nodes. Side sets
// use Exodus side numbers of outward sides, and every side set has a node set of the same
// name (the nodes of its sides). 2D elements are counter-clockwise.
//
// Names: a body's sets carry the body's block name as prefix ("lower_top", "die_bottom").
//
// Half discs (hertz_cylinders, cylinder_on_plane) are an O-grid of four ruled patches, in
// local coordinates with the centre at the origin, the flat face on y = 0 and the arc below;
// the contact point is (0, -R):
//   - bottom patch: the arc from -45 to +45 degrees (measured from -y) joined by straight
//     lines to the bottom side of an inner rectangle [-aR, aR] x [-aR, 0] (a = 1/2);
//     the angle is phi = (pi/4) sinh(beta s)/sinh(beta), s in [-1, 1] (fine at s = 0);
//     points along each line are graded towards the arc, d(t) = (e^(g t) - 1)/(e^g - 1),
//     with g = g_c at the contact point relaxing to g_side at the ends (g(s) smooth);
//   - two side patches: the arc from 45 to 90 degrees (uniform in angle) joined to the
//     vertical sides of the inner rectangle, graded with g_side;
//   - the inner rectangle, same x distribution as the arc patch, uniform in y.
// Level L multiplies every element count by 2^(L-1) with the same mappings, so each level
// halves every element size (nested refinement of the same grading). Level-1 counts:
// 2 x 12 elements along the arc patch, 4 along each side patch, 6 radially, 24 x 4 in the
// inner rectangle. Element size along the arc at the contact point:
// R (pi/4)(beta/sinh beta)/(12 * 2^(L-1)) = R/72/2^(L-1) for beta = 3.5 (0.111, 0.055,
// 0.028 for R = 8: b/6, b/12, b/25 with the Hertz half-width b = 0.6808 of row 8).

#include <string>

#include "io/mesh.hpp"

namespace grout {

/// Two stacked blocks: "lower" = [0,w] x [0,h_l] (x [0,w] in 3D), "upper" on top of it
/// after a gap. Each body can be simplicial (TRI3/TET4) or not (QUAD4/HEX8) on its own, and
/// distorted (interior nodes move freely, boundary nodes slide in their boundary line/plane,
/// so the interface stays flat). Sets per body (prefix "lower_"/"upper_"):
///   2D: bottom right top left        3D: xmin xmax ymin ymax bottom top
struct StackedBlocks {
  int nx_lower = 4, ny_lower = 4, nz_lower = 4;
  int nx_upper = 5, ny_upper = 5, nz_upper = 5;
  double width = 1.0, height_lower = 1.0, height_upper = 1.0, gap = 0.0;
  bool simplex_lower = false, simplex_upper = false;
  double distortion = 0.0;  ///< in [0, 0.4), as for rectangle_mesh
  unsigned long long seed = 1;
};
Mesh stacked_blocks_2d(const StackedBlocks& spec);
Mesh stacked_blocks_3d(const StackedBlocks& spec);

/// Two quadrilateral regions meeting on the sloped line from (0, y_left) to (width, y_right):
/// "lower" (0,0) (w,0) (w,y_right) (0,y_left) and "upper" (0,y_left) (w,y_right) (w,h) (0,h).
/// Each is a structured mesh of its quadrilateral (straight columns, rows interpolated between
/// the bottom and top edges). Sets per body: bottom right top left ("lower_top" and
/// "upper_bottom" are the sloped interface).
struct SlopedBlocks {
  int nx_lower = 4, ny_lower = 3, nx_upper = 5, ny_upper = 3;
  double width = 1.0, y_left = 0.9, y_right = 1.1, height = 2.0;
  bool triangles_lower = false, triangles_upper = false;
};
Mesh sloped_blocks_2d(const SlopedBlocks& spec);

/// Taylor patch test (Kratos taylor_patch_test geometry): foundation "block" = [0,8] x [0,5]
/// (3D: [0,8]^2 x [0,4]), die "die" = [4,6] x [5,7] (3D: [4,6]^2 x [4,6]) resting on it.
/// nx_block (and ny_block in 3D) must be a multiple of 4 so the die's edges lie on element
/// edges of the foundation. die_stretch (2D, |.| < 1) moves the die's columns to
/// x = 4 + 2 (u + die_stretch u (1 - u)), u uniform in [0,1] (non-symmetric non-matching).
/// Sets: the rectangle/box sets of each body with prefix "block_"/"die_" (3D: xmin xmax ymin
/// ymax bottom top), plus "block_top_free" (the foundation top not under the die; side set
/// and node set) and single-node node sets "block_origin" (0,0[,0]), "die_anchor" (the die's
/// top corner with least x [and y]); 3D also "block_x_end" (8,0,0) and "die_x_end" (6,4,6).
struct TaylorPatch {
  int nx_block = 8, ny_block = 4, nz_block = 4;  ///< 2D: nx, ny; 3D: nx, ny (in-plane), nz
  int nx_die = 3, ny_die = 2, nz_die = 2;        ///< 2D: nx, ny; 3D: nx, ny, nz
  double die_stretch = 0.0;
  bool simplex_block = false, simplex_die = false;
};
Mesh taylor_patch_2d(const TaylorPatch& spec);
Mesh taylor_patch_3d(const TaylorPatch& spec);

/// Hertz cylinder-cylinder (docs/verification.md #8): block "upper" = lower half of the disc of
/// radius R centred at (0, R + gap), block "lower" = upper half of the disc centred at
/// (0, -R); they touch at the origin. The lower body uses a slightly different tangential
/// grading (beta = 3.0 instead of 3.5), so the interface meshes do not match.
/// Sets: "upper_contact", "lower_contact" (arc sides with |x| <= contact_width),
/// "upper_top" (flat face y = R + gap), "lower_bottom" (flat face y = -R).
Mesh hertz_cylinders_mesh(int level, double radius = 8.0, double gap = 0.0,
                          double contact_width = 2.5);

/// Hertz cylinder on a plane (docs/verification.md #10): block "cylinder" = lower half of the disc
/// of radius R centred at (0, R) (touching the plane at the origin), block "plane" =
/// [-2R, 2R] x [-2R, 0] (8 x 4 QUAD4 times 2^(level-1) per direction).
/// Sets: "cylinder_contact" (arc sides with |x| <= contact_width), "cylinder_top" (the flat face y
/// = R), "plane_top", "plane_bottom", "plane_left", "plane_right"; node set "plane" (all nodes of
/// the plane, to hold it rigid).
Mesh cylinder_on_plane_mesh(int level, double radius = 6.1237, double contact_width = 2.5);

/// Axisymmetric sphere on a rigid plane (docs/verification.md #10, model/plane: axisymmetric,
/// x = r): block "sphere" = the quarter of the disc of radius R centred at (0, R) with x >= 0
/// and y <= R (the right half of cylinder_on_plane's half disc: the cross-section of a
/// hemisphere), block "plane" = [0, 2R] x [-2R, 0] (8 x 4 QUAD4 times 2^(level-1), graded
/// towards the contact point: x = 2R sinh(5 t)/sinh(5), -y likewise, t uniform; the plane's
/// element at the contact point is R/60/2^(level-1) wide, the sphere's R/72/2^(level-1)). Sets:
/// "sphere_contact" (arc sides with x <= contact_width), "sphere_top" (the flat face y = R),
/// "sphere_axis" (the sides on x = 0), the plane's rectangle sets with prefix "plane_"; node set
/// "plane" (all plane nodes).
Mesh sphere_on_plane_axisymmetric_mesh(int level, double radius = 6.1237,
                                       double contact_width = 2.5);

/// Solid sphere, axisymmetric: block "sphere" = the quarter disc x >= 0, y <= 0 of radius R
/// centred at the origin (the right half of half_disc_mesh). Sets: "sphere_surface" (the arc),
/// "sphere_equator" (y = 0), "sphere_axis" (x = 0).
Mesh quarter_disc_mesh(int level, double radius = 1.0);

/// Half-disc building block (see the file comment): centre at the origin, flat face y = 0,
/// arc below, QUAD4, no sets. Element counts: the level-1 counts times 2^(level-1).
Mesh half_disc_mesh(int level, double radius, double beta, const std::string& block_name);

}  // namespace grout
