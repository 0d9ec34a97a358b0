// read_and_broadcast_mesh: the mesh rank 0 reads arrives whole on every rank, and whatever
// rank 0's reader throws (not only an InputError) ends every rank instead of leaving the
// others in the broadcast. Runs on 1 and 2 ranks.

#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <new>
#include <stdexcept>
#include <string>

#include "assembly/distribute_mesh.hpp"
#include "io/errors.hpp"

namespace grout {
namespace {

Mesh two_triangles() {
  Mesh mesh;
  mesh.file = "two.exo";
  mesh.dimension = 2;
  mesh.coordinates = {0, 0, 1, 0, 1, 1, 0, 1};
  ElementBlock block;
  block.name = "body";
  block.id = 7;
  block.topology = Topology::tri3;
  block.nodes_per_element = 3;
  block.connectivity = {0, 1, 2, 0, 2, 3};
  mesh.blocks.push_back(block);
  mesh.side_sets.push_back({"bottom", 3, {0}, {1}});
  mesh.node_sets.push_back({"left_nodes", 4, {0, 3}});
  return mesh;
}

TEST(ReadAndBroadcastMesh, EveryRankGetsTheMesh) {
  const auto comm = Tpetra::getDefaultComm();
  int reads = 0;
  const Mesh mesh = read_and_broadcast_mesh(*comm, [&] {
    ++reads;
    return two_triangles();
  });
  EXPECT_EQ(reads, comm->getRank() == 0 ? 1 : 0);
  const Mesh expected = two_triangles();
  EXPECT_EQ(mesh.file, expected.file);
  EXPECT_EQ(mesh.coordinates, expected.coordinates);
  ASSERT_EQ(mesh.blocks.size(), 1u);
  EXPECT_EQ(mesh.blocks[0].connectivity, expected.blocks[0].connectivity);
  EXPECT_EQ(mesh.blocks[0].id, 7);
  ASSERT_EQ(mesh.node_sets.size(), 1u);
  EXPECT_EQ(mesh.node_sets[0].nodes, expected.node_sets[0].nodes);
}

/// What read_and_broadcast_mesh throws on this rank when rank 0's reader throws `error`:
/// the message on rank 0, "other rank" elsewhere; `code` gets the exit code.
template <class Error>
std::string outcome(const Error& error, int& code) {
  const auto comm = Tpetra::getDefaultComm();
  try {
    read_and_broadcast_mesh(*comm, [&]() -> Mesh { throw error; });
    return "";
  } catch (const ErrorOnOtherRank& e) {
    code = e.exit_code();
    return "other rank";
  } catch (...) {
    code = exit_code_of(std::current_exception());
    return message_of(std::current_exception());
  }
}

TEST(ReadAndBroadcastMesh, AnyErrorOfTheReaderEndsEveryRank) {
  // The netCDF-4 mesh declaring 120 M nodes: rank 0 ran out of memory, rank 1 waited in the
  // broadcast for ever (only InputError was passed on).
  const bool root = Tpetra::getDefaultComm()->getRank() == 0;
  int code = 0;
  EXPECT_EQ(outcome(std::bad_alloc(), code), root ? "std::bad_alloc" : "other rank");
  EXPECT_EQ(code, 1);
  EXPECT_EQ(outcome(std::runtime_error("library failure"), code),
            root ? "library failure" : "other rank");
  EXPECT_EQ(code, 1);
  EXPECT_EQ(outcome(InputError("mesh.exo: corrupt"), code),
            root ? "mesh.exo: corrupt" : "other rank");
  EXPECT_EQ(code, 2);
}

}  // namespace
}  // namespace grout
