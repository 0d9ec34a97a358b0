// check_mesh: set integrity and element validity (det J at the quadrature points), and the
// kernel min_jacobian_determinant against hand-computed determinants.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "io/errors.hpp"
#include "io/mesh.hpp"
#include "kernels/element_jacobian.hpp"
#include "kernels/linear_elastic.hpp"

namespace grout {
namespace {

/// Two unit QUAD4 elements side by side, [0,2]x[0,1]: nodes 0-2 at y = 0, 3-5 at y = 1.
Mesh two_quads() {
  Mesh mesh;
  mesh.file = "two.exo";
  mesh.dimension = 2;
  mesh.coordinates = {0, 0, 1, 0, 2, 0, 0, 1, 1, 1, 2, 1};
  ElementBlock block;
  block.name = "body";
  block.id = 1;
  block.topology = Topology::quad4;
  block.nodes_per_element = 4;
  block.connectivity = {0, 1, 4, 3, 1, 2, 5, 4};
  mesh.blocks.push_back(block);
  mesh.node_sets.push_back({"left", 1, {0, 3}});
  mesh.node_sets.push_back({"right", 2, {2, 5}});
  mesh.side_sets.push_back({"bottom", 1, {0, 1}, {1, 1}});
  mesh.side_sets.push_back({"top", 2, {0, 1}, {3, 3}});
  return mesh;
}

void expect_mesh_error(const Mesh& mesh, const std::string& expected) {
  try {
    check_mesh(mesh);
    ADD_FAILURE() << "expected InputError: " << expected;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos)
        << "message: " << e.what() << "\nlacks:   " << expected;
  }
}

TEST(MeshCheck, ValidMeshPasses) {
  EXPECT_NO_THROW(check_mesh(two_quads()));
}

TEST(MeshCheck, DuplicateNodeInANodeSet) {
  Mesh mesh = two_quads();
  mesh.node_sets[1].nodes.push_back(2);
  expect_mesh_error(mesh, "mesh 'two.exo': node set 'right' lists node 3 twice");
}

TEST(MeshCheck, DuplicateFaceInASideSet) {
  Mesh mesh = two_quads();
  mesh.side_sets[1].elements.push_back(1);
  mesh.side_sets[1].sides.push_back(3);
  expect_mesh_error(mesh, "mesh 'two.exo': side set 'top' lists side 3 of element 2 twice");
  // The same element with another side is another face: fine.
  Mesh other = two_quads();
  other.side_sets[1].elements.push_back(1);
  other.side_sets[1].sides.push_back(2);
  EXPECT_NO_THROW(check_mesh(other));
}

TEST(MeshCheck, DuplicateIdsAndNames) {
  Mesh mesh = two_quads();
  mesh.node_sets[1].name = "left";
  expect_mesh_error(mesh, "node sets with ids 1 and 2 are both named 'left'");
  mesh = two_quads();
  mesh.side_sets[1].id = 1;
  expect_mesh_error(mesh, "side sets 'bottom' and 'top' have the same id 1");
  mesh = two_quads();
  mesh.side_sets[1].name = "id_1";  // the look-up name of the set with id 1
  expect_mesh_error(mesh, "side sets with ids 1 and 2 are both named 'id_1'");
  // A node set and a side set may share a name (looked up separately).
  mesh = two_quads();
  mesh.node_sets[0].name = "bottom";
  EXPECT_NO_THROW(check_mesh(mesh));
}

TEST(MeshCheck, InvertedDegenerateAndNonFiniteElementsNameBlockAndElement) {
  Mesh mesh = two_quads();
  std::swap(mesh.blocks[0].connectivity[5], mesh.blocks[0].connectivity[7]);  // clockwise
  expect_mesh_error(mesh, "mesh 'two.exo': block 'body', element 2 (global element 2): inverted");
  mesh = two_quads();
  mesh.coordinates[2 * 5 + 1] = 0.0;  // node 5 onto node 2: a triangle, det J > 0 at the points
  EXPECT_NO_THROW(check_mesh(mesh));
  mesh.coordinates[2 * 4 + 1] = 0.0;  // node 4 onto node 1: zero area
  expect_mesh_error(mesh, "block 'body', element 2 (global element 2): degenerate");
  mesh = two_quads();
  mesh.coordinates[0] = std::numeric_limits<double>::quiet_NaN();
  expect_mesh_error(mesh, "element 1 (global element 1): a node coordinate is not a finite number");
}

TEST(ElementJacobian, MinimumDeterminantAtTheQuadraturePoints) {
  // QUAD4 [0,2]x[0,1]: J = diag(1, 1/2), det J = 1/2 at every point.
  const double rectangle[8] = {0, 0, 2, 0, 2, 1, 0, 1};
  double det = 0.0;
  ASSERT_TRUE(min_jacobian_determinant(Topology::quad4, 2, rectangle,
                                       full_integration_degree(Topology::quad4), det));
  EXPECT_DOUBLE_EQ(det, 0.5);
  // TRI3 with legs 2 and 3: det J = 2 A = 6.
  const double triangle[6] = {0, 0, 2, 0, 0, 3};
  ASSERT_TRUE(min_jacobian_determinant(Topology::tri3, 2, triangle, 1, det));
  EXPECT_DOUBLE_EQ(det, 6.0);
  // TET4 with unit legs, nodes 1 and 2 swapped: det J = -6 V = -1.
  const double tet[12] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1};
  ASSERT_TRUE(min_jacobian_determinant(Topology::tet4, 3, tet, 1, det));
  EXPECT_DOUBLE_EQ(det, -1.0);
  // A trapezoid QUAD4 (0,0) (4,0) (3,1) (1,1): ∂x/∂ξ = (3 - η)/2, ∂y/∂η = 1/2, ∂y/∂ξ = 0, so
  // det J = (3 - η)/4, smallest at the upper Gauss point η = 1/√3.
  const double trapezoid[8] = {0, 0, 4, 0, 3, 1, 1, 1};
  ASSERT_TRUE(min_jacobian_determinant(Topology::quad4, 2, trapezoid, 3, det));
  EXPECT_NEAR(det, (3.0 - 1.0 / std::sqrt(3.0)) / 4.0, 1e-15);
  const double nan_node[8] = {0, 0, 2, 0, 2, std::numeric_limits<double>::infinity(), 0, 1};
  EXPECT_FALSE(min_jacobian_determinant(Topology::quad4, 2, nan_node, 3, det));
}

}  // namespace
}  // namespace grout
