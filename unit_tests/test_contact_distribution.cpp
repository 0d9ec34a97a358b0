// The parallel coarse search of assembly/contact_distribution: on any number of ranks, the
// master faces a rank receives are exactly those whose enlarged box overlaps the region of
// its slave faces (checked against a brute force over the whole replicated master surface),
// they cover every (slave, master) pair with overlapping boxes, and they arrive with the
// owner's nodes, coordinates and payload. On 2 ranks no rank receives the whole surface.

#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <random>
#include <set>

#include "assembly/contact_distribution.hpp"
#include "assembly/contact_surface.hpp"
#include "io/mesh_generators.hpp"
#include "kernels/coarse_search.hpp"

namespace grout {
namespace {

int comm_rank(MPI_Comm comm) {
  int r = 0;
  MPI_Comm_rank(comm, &r);
  return r;
}
int comm_size(MPI_Comm comm) {
  int s = 1;
  MPI_Comm_size(comm, &s);
  return s;
}

// Node positions: the mesh coordinates moved by a random field (the same on every rank).
std::vector<std::array<double, 3>> moved_positions(const Mesh& mesh) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> r(-0.02, 0.02);
  std::vector<std::array<double, 3>> x(mesh.num_nodes(), {0.0, 0.0, 0.0});
  for (GlobalIndex n = 0; n < mesh.num_nodes(); ++n)
    for (int d = 0; d < mesh.dimension; ++d)
      x[n][d] = mesh.coordinates[n * mesh.dimension + d] + r(rng);
  return x;
}

// Faces [begin, end) of `faces` as a FaceSet with a 2-value payload per node (n, −n).
FaceSet face_set(const SurfaceFaces& faces, const std::vector<std::array<double, 3>>& x, int dim,
                 std::size_t begin, std::size_t end, std::size_t stride = 1) {
  FaceSet out;
  out.dimension = dim;
  out.payload_size = 2;
  for (std::size_t f = begin; f < end; f += stride) {
    double xs[max_face_nodes][3] = {}, payload[2 * max_face_nodes] = {};
    for (int a = 0; a < faces.num_nodes[f]; ++a) {
      const GlobalIndex n = faces.nodes[f][a];
      for (int d = 0; d < 3; ++d) xs[a][d] = x[n][d];
      payload[2 * a] = double(n);
      payload[2 * a + 1] = -double(n);
    }
    out.add(GlobalIndex(f), faces.num_nodes[f], faces.nodes[f].data(), xs, payload);
  }
  return out;
}

void box(const FaceSet& faces, std::size_t f, double factor, double lo[3], double hi[3]) {
  double x[max_face_nodes][3] = {};
  for (int a = 0; a < faces.num_nodes[f]; ++a)
    for (int d = 0; d < 3; ++d) x[a][d] = faces.coordinates[f][3 * a + d];
  face_bounding_box(faces.dimension, faces.num_nodes[f], x, factor, lo, hi);
}

bool boxes_meet(int dim, const double alo[3], const double ahi[3], const double blo[3],
                const double bhi[3]) {
  for (int d = 0; d < dim; ++d)
    if (alo[d] > bhi[d] || blo[d] > ahi[d]) return false;
  return true;
}

void check_ghosting(const Mesh& mesh) {
  const MPI_Comm comm = MPI_COMM_WORLD;
  const int rank = comm_rank(comm), size = comm_size(comm), dim = mesh.dimension;
  Input input;
  input.file = "test.yaml";
  ContactInput ci;
  ci.name = "interface";
  ci.slave = "upper_bottom";
  ci.master = "lower_top";
  const ContactSurface whole = build_contact_surface(mesh, input, ci);
  const auto x = moved_positions(mesh);
  const double factor = 0.3;

  // Slave faces: a contiguous chunk per rank (side-set order); master faces: every size-th.
  const std::size_t n_slave = whole.slave.size(), n_master = whole.master.size();
  const FaceSet slave =
      face_set(whole.slave, x, dim, n_slave * rank / size, n_slave * (rank + 1) / size);
  const FaceSet owned = face_set(whole.master, x, dim, rank, n_master, size);
  const FaceSet all_master = face_set(whole.master, x, dim, 0, n_master);
  const SearchRegion region = search_region(slave, factor);
  const FaceSet ghost = ghost_master_faces(owned, region, factor, comm);

  // Exactly the master faces whose box overlaps the region, in id order, with their data.
  std::vector<GlobalIndex> expected;
  for (std::size_t m = 0; m < n_master; ++m) {
    double lo[3], hi[3];
    box(all_master, m, factor, lo, hi);
    if (!region.empty && boxes_meet(dim, lo, hi, region.lo, region.hi))
      expected.push_back(GlobalIndex(m));
  }
  EXPECT_EQ(ghost.ids, expected);
  ASSERT_EQ(ghost.payload.size(), ghost.size() * max_face_nodes * 2);
  for (std::size_t k = 0; k < ghost.size(); ++k) {
    const std::size_t m = std::size_t(ghost.ids[k]);
    EXPECT_EQ(ghost.num_nodes[k], all_master.num_nodes[m]);
    EXPECT_EQ(ghost.nodes[k], all_master.nodes[m]);
    EXPECT_EQ(ghost.coordinates[k], all_master.coordinates[m]);
    for (int a = 0; a < ghost.num_nodes[k]; ++a) {
      EXPECT_EQ(ghost.payload[(k * max_face_nodes + a) * 2], double(ghost.nodes[k][a]));
      EXPECT_EQ(ghost.payload[(k * max_face_nodes + a) * 2 + 1], -double(ghost.nodes[k][a]));
    }
  }

  // Every pair with overlapping boxes has its master received.
  const std::set<GlobalIndex> received(ghost.ids.begin(), ghost.ids.end());
  int pairs = 0;
  for (std::size_t s = 0; s < slave.size(); ++s) {
    double slo[3], shi[3];
    box(slave, s, factor, slo, shi);
    for (std::size_t m = 0; m < n_master; ++m) {
      double lo[3], hi[3];
      box(all_master, m, factor, lo, hi);
      if (!boxes_meet(dim, slo, shi, lo, hi)) continue;
      ++pairs;
      EXPECT_TRUE(received.count(GlobalIndex(m))) << "slave " << slave.ids[s] << " master " << m;
    }
  }
  if (slave.size() > 0) {
    EXPECT_GT(pairs, 0);
  }
  // With the slave surface split, no rank needs the whole master surface.
  if (size > 1) {
    EXPECT_LT(ghost.size(), n_master);
  }
}

TEST(ContactDistribution, GhostsExactlyTheMasterFacesOverlappingTheRegion2D) {
  check_ghosting(two_block_mesh_2d(16, 2, 21, 2));
}

TEST(ContactDistribution, GhostsExactlyTheMasterFacesOverlappingTheRegion3D) {
  check_ghosting(two_block_mesh_3d(8, 6, 1, 7, 9, 1));
  check_ghosting(two_block_mesh_3d(4, 4, 1, 5, 5, 1, true));
}

TEST(ContactDistribution, EmptyRegionReceivesNothing) {
  const Mesh mesh = two_block_mesh_2d(4, 1, 5, 1);
  Input input;
  input.file = "test.yaml";
  ContactInput ci;
  ci.name = "interface";
  ci.slave = "upper_bottom";
  ci.master = "lower_top";
  const ContactSurface whole = build_contact_surface(mesh, input, ci);
  const auto x = moved_positions(mesh);
  const FaceSet owned = face_set(whole.master, x, 2, 0, whole.master.size());
  EXPECT_EQ(ghost_master_faces(owned, SearchRegion(), 0.5, MPI_COMM_WORLD).size(), 0u);
}

TEST(ContactDistribution, ExchangeDeliversEachMessageInRankOrder) {
  const MPI_Comm comm = MPI_COMM_WORLD;
  const int rank = comm_rank(comm), size = comm_size(comm);
  std::vector<std::vector<double>> send(size);
  std::vector<std::vector<long long>> send_ids(size);
  for (int q = 0; q < size; ++q) {
    send[q].assign(std::size_t(q + rank + 1), 10.0 * rank + q);  // rank → q: q + rank + 1 values
    send_ids[q].assign(std::size_t(rank), 100LL * rank + q);
  }
  std::vector<int> counts;
  const std::vector<double> got = exchange_with_ranks(send, comm, &counts);
  std::vector<double> expected;
  for (int r = 0; r < size; ++r) {
    EXPECT_EQ(counts[r], rank + r + 1);
    expected.insert(expected.end(), std::size_t(rank + r + 1), 10.0 * r + rank);
  }
  EXPECT_EQ(got, expected);
  std::vector<long long> expected_ids;
  for (int r = 0; r < size; ++r)
    expected_ids.insert(expected_ids.end(), std::size_t(r), 100LL * r + rank);
  EXPECT_EQ(exchange_with_ranks(send_ids, comm), expected_ids);
}

}  // namespace
}  // namespace grout
