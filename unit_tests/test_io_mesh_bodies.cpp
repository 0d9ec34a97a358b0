// io/mesh_bodies.hpp: the bodies of a mesh are the connected components of its elements.

#include <gtest/gtest.h>

#include <set>

#include "io/contact_meshes.hpp"
#include "io/mesh_bodies.hpp"

namespace grout {
namespace {

// Two stacked blocks that share no node (a contact interface): two bodies, each node's body
// that of its block.
TEST(MeshBodies, StackedBlocksAreTwoBodies) {
  for (const Mesh& mesh :
       {stacked_blocks_2d(StackedBlocks{}), stacked_blocks_3d(StackedBlocks{})}) {
    const std::vector<int> body = node_bodies(mesh);
    ASSERT_EQ(GlobalIndex(body.size()), mesh.num_nodes());
    EXPECT_EQ(std::set<int>(body.begin(), body.end()), (std::set<int>{0, 1}));
    for (const ElementBlock& block : mesh.blocks) {
      std::set<int> of_block;
      for (GlobalIndex n : block.connectivity) of_block.insert(body[n]);
      EXPECT_EQ(of_block.size(), 1u) << block.name;
    }
    EXPECT_EQ(body[mesh.blocks[0].connectivity[0]], 0);  // numbered by their lowest node
  }
}

// Blocks that share nodes are one body; a node of no element is a body of its own; the
// elements of one block can form several bodies.
TEST(MeshBodies, SharedNodesJoinBlocksAndOrphanNodesStandAlone) {
  Mesh mesh;
  mesh.dimension = 2;
  mesh.coordinates.assign(2 * 9, 0.0);
  ElementBlock a, b;
  a.nodes_per_element = b.nodes_per_element = 4;
  a.connectivity = {0, 1, 2, 3, 6, 7, 8, 5};  // two quads apart: nodes 0-3 and 5-8
  b.connectivity = {3, 4, 1, 0};              // joins node 4 to the first quad
  mesh.blocks = {a, b};
  EXPECT_EQ(node_bodies(mesh), (std::vector<int>{0, 0, 0, 0, 0, 1, 1, 1, 1}));
  mesh.blocks = {a};
  EXPECT_EQ(node_bodies(mesh), (std::vector<int>{0, 0, 0, 0, 1, 2, 2, 2, 2}));
}

}  // namespace
}  // namespace grout
