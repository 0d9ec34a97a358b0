// parallel/distributed_bodies.hpp: the bodies labelled across the ranks of the distributed mesh
// against io/mesh_bodies.hpp's node_bodies on the replicated mesh, on 1, 2 and 3 ranks: every
// owned node the same body index, and the same number of bodies. The meshes make the labels
// travel: two interleaved combs (each body crosses the partition's cuts many times, and nodes of
// no element are bodies of their own), blocks that touch without sharing nodes, one box.

#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <algorithm>
#include <cmath>

#include "io/contact_meshes.hpp"
#include "io/exodus.hpp"
#include "io/mesh_bodies.hpp"
#include "io/mesh_generators.hpp"
#include "parallel/distributed_bodies.hpp"

namespace grout {
namespace {

Teuchos::RCP<const Comm> world() {
  return Tpetra::getDefaultComm();
}

/// Writes `mesh` (rank 0) to the build tree; every rank gets the path.
std::string write_mesh(const Mesh& mesh, const std::string& name) {
  const auto comm = world();
  const std::string path = std::string(GROUT_BINARY_DIR) + "/unit_tests/distbodies_" + name +
                           "_np" + std::to_string(comm->getSize()) + ".exo";
  if (comm->getRank() == 0) write_exodus_mesh(path, mesh);
  comm->barrier();
  return path;
}

/// Two combs on an nx × ny grid of unit-square cells: comb A has the rows j ≡ 0 (mod 4) from
/// column 2 on and the spine column nx − 1; comb B the rows j ≡ 2 (mod 4) up to column nx − 3
/// and the spine column 0 from row 2. They share no node; the nodes of the cells left out that
/// no kept cell touches are nodes of no element.
Mesh two_combs(int nx, int ny) {
  Mesh mesh = rectangle_mesh(nx, ny, 0.0, double(nx), 0.0, double(ny));
  ElementBlock& block = mesh.blocks.front();
  const int k = block.nodes_per_element;
  std::vector<GlobalIndex> kept;
  for (std::size_t e = 0; e + k <= block.connectivity.size(); e += k) {
    double cx = 0.0, cy = 0.0;
    for (int a = 0; a < k; ++a) {
      cx += mesh.coordinates[2 * block.connectivity[e + a]] / k;
      cy += mesh.coordinates[2 * block.connectivity[e + a] + 1] / k;
    }
    const int i = int(std::floor(cx)), j = int(std::floor(cy));
    const bool a = (j % 4 == 0 && i >= 2) || i == nx - 1;
    const bool b = (j % 4 == 2 && i <= nx - 3) || (i == 0 && j >= 2);
    if (a || b) kept.insert(kept.end(), &block.connectivity[e], &block.connectivity[e] + k);
  }
  block.connectivity = kept;
  mesh.side_sets.clear();  // their entries name cells left out
  return mesh;
}

void check(const Mesh& generated, const std::string& name, int expected_bodies) {
  const auto comm = world();
  const std::string path = write_mesh(generated, name);
  const std::vector<int> expected = node_bodies(read_exodus(path));
  const DistributedMesh part = read_distributed_mesh(*comm, path);
  const DistributedBodies bodies = distributed_node_bodies(*comm, part);
  EXPECT_EQ(*std::max_element(expected.begin(), expected.end()) + 1, expected_bodies) << name;
  EXPECT_EQ(bodies.num_bodies, expected_bodies) << name;
  ASSERT_EQ(GlobalIndex(bodies.owned_node_body.size()), part.num_owned_nodes) << name;
  for (GlobalIndex n = 0; n < part.num_owned_nodes; ++n)
    ASSERT_EQ(bodies.owned_node_body[n], expected[part.node_gid[n]])
        << name << ": node " << part.node_gid[n] << " on rank " << comm->getRank();
}

TEST(DistributedBodies, InterleavedCombsAndLooseNodes) {
  // The two combs and one body per node of no element.
  const Mesh mesh = two_combs(12, 13);
  std::vector<bool> used(std::size_t(mesh.num_nodes()), false);
  for (GlobalIndex n : mesh.blocks.front().connectivity) used[std::size_t(n)] = true;
  const int loose = int(std::count(used.begin(), used.end(), false));
  ASSERT_GT(loose, 0);
  check(mesh, "combs", 2 + loose);
}

TEST(DistributedBodies, BlocksThatTouchWithoutSharingNodes) {
  check(stacked_blocks_3d(StackedBlocks{}), "stacked", 2);
}

TEST(DistributedBodies, OneBox) {
  check(box_mesh(5, 4, 6), "box", 1);
}

}  // namespace
}  // namespace grout
