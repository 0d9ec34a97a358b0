#pragma once
// Structured mesh generators for tests, verification cases and benchmarks.
//
// Every generator returns a Mesh whose elements have positive Jacobians at all corners
// (checked; std::invalid_argument otherwise), counter-clockwise 2D elements, and side sets
// with correct Exodus side numbers plus node sets of the same names:
//   2D rectangle:  "bottom", "right", "top", "left"        (ids 1-4 in that order)
//   3D box:        "xmin", "xmax", "ymin", "ymax", "zmin", "zmax"   (ids 1-6)
// Side sets list elements in ascending order; node sets list nodes in ascending order.

#include <string>

#include "io/mesh.hpp"

namespace grout {

struct BoxBounds {
  double x0 = 0.0, x1 = 1.0, y0 = 0.0, y1 = 1.0, z0 = 0.0, z1 = 1.0;
};

/// \brief nx x ny QUAD4 mesh of [x0,x1] x [y0,y1], or 2 TRI3 per quad (diagonal from the
/// cell's lower-left to its upper-right corner).
/// \param distortion  each node coordinate that is not fixed by a boundary line moves by a
///   uniform random amount in [-distortion*h, distortion*h] (h = cell size in that
///   direction): interior nodes move freely, edge nodes slide along their edge, corners stay.
///   Must lie in [0, 0.4).
/// \param seed  seed of the (platform-independent) random generator.
Mesh rectangle_mesh(int nx, int ny, double x0 = 0.0, double x1 = 1.0, double y0 = 0.0,
                    double y1 = 1.0, bool triangles = false, double distortion = 0.0,
                    unsigned long long seed = 1, const std::string& block_name = "block");

/// \brief nx x ny x nz HEX8 mesh of a box, or 6 TET4 per hex (Kuhn subdivision around the
/// cell's main diagonal: the face diagonals of neighbouring cells match, so it conforms).
/// Distortion as for rectangle_mesh (face nodes slide in their face, edge nodes along their edge).
Mesh box_mesh(int nx, int ny, int nz, const BoxBounds& bounds = {}, bool tetrahedra = false,
              double distortion = 0.0, unsigned long long seed = 1,
              const std::string& block_name = "block");

/// \brief QUAD4 mesh of the quarter annulus r_inner <= r <= r_outer, 0 <= theta <= pi/2
/// (thick-walled cylinder, Lame problem). Nodes on the arcs lie exactly on the circles.
/// Side sets and node sets: "inner", "outer", "x_symmetry" (the edge on y = 0),
/// "y_symmetry" (the edge on x = 0).
Mesh quarter_annulus_mesh(int n_radial, int n_circ, double r_inner, double r_outer,
                          const std::string& block_name = "block");

/// \brief Two stacked 2D blocks for contact tests: "lower" = [0,1] x [0,1] (nx_lower x
/// ny_lower) and "upper" = [0,1] x [1+gap, 2+gap] (nx_upper x ny_upper). The blocks share no
/// nodes; the interface meshes do not match when nx_lower != nx_upper. Side sets and node
/// sets: "lower_bottom", "lower_right", "lower_top", "lower_left", then the same with "upper_".
Mesh two_block_mesh_2d(int nx_lower, int ny_lower, int nx_upper, int ny_upper,
                       bool triangles = false, double gap = 0.0);

/// \brief The 3D analogue: "lower" = [0,1]^3, "upper" = [0,1]^2 x [1+gap, 2+gap], HEX8 or
/// TET4. Sets per block (prefix "lower_" / "upper_"): "xmin", "xmax", "ymin", "ymax",
/// "bottom" (z min), "top" (z max).
Mesh two_block_mesh_3d(int nx_lower, int ny_lower, int nz_lower, int nx_upper, int ny_upper,
                       int nz_upper, bool tetrahedra = false, double gap = 0.0);

/// \brief Concatenate two meshes of the same dimension without merging nodes. Block, side-set
/// and node-set names of b keep their names; ids are renumbered 1, 2, ... Use to build
/// multi-body contact meshes.
Mesh append_mesh(const Mesh& a, const Mesh& b);

/// \brief Smallest corner Jacobian determinant over all elements (det of the edge vectors
/// at each corner: positive for a valid, counter-clockwise / right-handed element).
double min_corner_jacobian(const Mesh& mesh);

/// \brief Rename every node set that shares its name with a side set to "<name>_nodes"
/// (the generators give a side set and the node set of its nodes one name). Files that use
/// one name for both make ParaView's IOSS reader put side-set data on the wrong points;
/// grout_mesh writes its meshes through this. Throws std::invalid_argument when a new name
/// is taken already.
void name_node_sets_apart(Mesh& mesh);

}  // namespace grout
