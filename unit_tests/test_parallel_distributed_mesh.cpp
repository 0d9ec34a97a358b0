// The distributed mesh (parallel/distributed_mesh.hpp) against the replicated Mesh read on
// every rank by io/exodus_reader.cpp, by brute force: owned entities partition the file's,
// ghosts are exactly the one-layer definition, nodes are owned by the lowest part among their
// (contact) elements, coordinates, connectivity and sets are the file's; the memory bound on 2
// ranks; bad meshes throw on every rank with the replicated reader's message.

#include <gtest/gtest.h>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>

#include "io/errors.hpp"
#include "io/exodus.hpp"
#include "io/mesh_generators.hpp"
#include "parallel/contact_bands.hpp"
#include "parallel/distributed_mesh.hpp"

namespace grout {
namespace {

using CommPtr = Teuchos::RCP<const Teuchos::Comm<int>>;

CommPtr world() {
  return Tpetra::getDefaultComm();
}

/// Writes `mesh` (rank 0) to a file of the build tree named after the test and the rank
/// count; every rank gets the path.
std::string write_mesh(const Mesh& mesh, const std::string& name) {
  const auto comm = world();
  const std::string path = std::string(GROUT_BINARY_DIR) + "/unit_tests/distmesh_" + name + "_np" +
                           std::to_string(comm->getSize()) + ".exo";
  if (comm->getRank() == 0) write_exodus_mesh(path, mesh);
  comm->barrier();
  return path;
}

/// Element-wise sum over ranks.
std::vector<long long> sum_over_ranks(const std::vector<long long>& v) {
  std::vector<long long> total(v.size());
  Teuchos::reduceAll(*world(), Teuchos::REDUCE_SUM, int(v.size()), v.data(), total.data());
  return total;
}

/// Every check of the file comment, for the mesh at `path`.
void check_against_replicated(const std::string& path, const DistributionOptions& options = {}) {
  const auto comm = world();
  const int me = comm->getRank();
  const Mesh file = read_exodus(path);
  const DistributedMesh m = read_distributed_mesh(*comm, path, options);
  const GlobalIndex N = file.num_nodes(), E = file.num_elements();
  ASSERT_EQ(m.global_num_nodes, N);
  ASSERT_EQ(m.global_num_elements, E);
  ASSERT_EQ(m.local.file, file.file);
  ASSERT_EQ(m.local.dimension, file.dimension);
  ASSERT_EQ(m.local.blocks.size(), file.blocks.size());
  const int dim = file.dimension;

  // Owned entities: each of the file's exactly once over the ranks.
  std::vector<long long> element_owner(std::size_t(E), 0), element_count(std::size_t(E), 0);
  for (GlobalIndex e = 0; e < m.num_local_elements(); ++e) {
    ASSERT_GE(m.element_owner[e], 0);
    ASSERT_LT(m.element_owner[e], comm->getSize());
    if (m.owns_element(e)) {
      element_owner[std::size_t(m.element_gid[e])] = me;
      ++element_count[std::size_t(m.element_gid[e])];
    }
  }
  element_owner = sum_over_ranks(element_owner);
  element_count = sum_over_ranks(element_count);
  for (GlobalIndex e = 0; e < E; ++e) ASSERT_EQ(element_count[e], 1) << "element " << e;
  std::vector<long long> node_count(std::size_t(N), 0);
  for (GlobalIndex n = 0; n < m.num_owned_nodes; ++n) {
    ASSERT_TRUE(m.owns_node(n));
    ++node_count[std::size_t(m.node_gid[n])];
  }
  node_count = sum_over_ranks(node_count);
  for (GlobalIndex n = 0; n < N; ++n) ASSERT_EQ(node_count[n], 1) << "node " << n;

  // Brute force: node owner = lowest part among its contact elements (with a face on one of
  // the options' contact side sets, when the options use them), else among its elements (0
  // without elements); ghosts = elements owned elsewhere sharing a node with an element owned
  // here.
  std::set<GlobalIndex> contact_elements;
  if (options.contact_weight != 0.0 || options.balance_contact || options.separate_contact)
    for (const std::string& name : options.contact_side_sets)
      for (GlobalIndex e : file.find_side_set(name)->elements) contact_elements.insert(e);
  if (options.separate_contact)  // the master elements are contact elements too
    for (const std::string& name : options.master_side_sets)
      for (GlobalIndex e : file.find_side_set(name)->elements) contact_elements.insert(e);
  std::vector<int> node_owner(std::size_t(N), comm->getSize());
  std::vector<int> contact_owner(std::size_t(N), comm->getSize());
  std::vector<char> touches_mine(std::size_t(N), 0);
  for (const auto& b : file.blocks)
    for (GlobalIndex e = 0; e < b.num_elements(); ++e)
      for (int a = 0; a < b.nodes_per_element; ++a) {
        const GlobalIndex n = b.connectivity[e * b.nodes_per_element + a];
        const int p = int(element_owner[b.first_element + e]);
        node_owner[n] = std::min(node_owner[n], p);
        if (contact_elements.count(b.first_element + e))
          contact_owner[n] = std::min(contact_owner[n], p);
        if (p == me) touches_mine[n] = 1;
      }
  for (GlobalIndex n = 0; n < N; ++n)
    if (contact_owner[n] < comm->getSize()) node_owner[n] = contact_owner[n];
  for (auto& p : node_owner)
    if (p == comm->getSize()) p = 0;
  std::set<GlobalIndex> expected_elements, expected_nodes;
  for (const auto& b : file.blocks)
    for (GlobalIndex e = 0; e < b.num_elements(); ++e) {
      bool local = element_owner[b.first_element + e] == me;
      for (int a = 0; a < b.nodes_per_element; ++a)
        local = local || touches_mine[b.connectivity[e * b.nodes_per_element + a]];
      if (!local) continue;
      expected_elements.insert(b.first_element + e);
      for (int a = 0; a < b.nodes_per_element; ++a)
        expected_nodes.insert(b.connectivity[e * b.nodes_per_element + a]);
    }
  for (GlobalIndex n = 0; n < N; ++n)
    if (me == 0 && node_owner[n] == 0 && !touches_mine[n]) expected_nodes.insert(n);  // no element
  EXPECT_EQ(std::set<GlobalIndex>(m.element_gid.begin(), m.element_gid.end()), expected_elements);
  EXPECT_EQ(GlobalIndex(expected_elements.size()), m.num_local_elements());
  EXPECT_EQ(std::set<GlobalIndex>(m.node_gid.begin(), m.node_gid.end()), expected_nodes);
  EXPECT_EQ(GlobalIndex(expected_nodes.size()), m.num_local_nodes());

  // Nodes: owners, order (owned, then ghosts, each ascending), coordinates, look-up.
  for (GlobalIndex n = 0; n < m.num_local_nodes(); ++n) {
    const GlobalIndex g = m.node_gid[n];
    ASSERT_EQ(m.node_owner[n], node_owner[g]) << "node " << g;
    ASSERT_EQ(m.owns_node(n), n < m.num_owned_nodes);
    if (n > 0 && n != m.num_owned_nodes) {
      ASSERT_LT(m.node_gid[n - 1], g);
    }
    for (int d = 0; d < dim; ++d)
      ASSERT_EQ(m.local.coordinates[n * dim + d], file.coordinates[g * dim + d]);
    ASSERT_EQ(m.local_node(g), n);
  }
  // Elements: block, order, owner, connectivity, look-up.
  for (std::size_t b = 0; b < file.blocks.size(); ++b) {
    const ElementBlock &mine = m.local.blocks[b], &theirs = file.blocks[b];
    ASSERT_EQ(mine.name, theirs.name);
    ASSERT_EQ(mine.id, theirs.id);
    ASSERT_EQ(mine.topology, theirs.topology);
    ASSERT_EQ(m.block_global_first[b], theirs.first_element);
    ASSERT_EQ(m.block_global_size[b], theirs.num_elements());
    const int npe = theirs.nodes_per_element;
    for (GlobalIndex k = 0; k < mine.num_elements(); ++k) {
      const GlobalIndex e = mine.first_element + k, g = m.element_gid[e];
      ASSERT_TRUE(theirs.contains(g));
      ASSERT_EQ(m.element_owner[e], element_owner[g]);
      ASSERT_EQ(m.owns_element(e), k < m.num_owned_in_block[b]);
      if (k > 0 && k != m.num_owned_in_block[b]) {
        ASSERT_LT(m.element_gid[e - 1], g);
      }
      for (int a = 0; a < npe; ++a)
        ASSERT_EQ(m.node_gid[mine.connectivity[k * npe + a]],
                  theirs.connectivity[(g - theirs.first_element) * npe + a]);
      ASSERT_EQ(m.local_element(g), e);
    }
  }
  // Sets: the file's entries on local entities, in the file's order, with their positions.
  ASSERT_EQ(m.local.side_sets.size(), file.side_sets.size());
  for (std::size_t k = 0; k < file.side_sets.size(); ++k) {
    const SideSet &mine = m.local.side_sets[k], &theirs = file.side_sets[k];
    ASSERT_EQ(mine.name, theirs.name);
    ASSERT_EQ(mine.id, theirs.id);
    ASSERT_EQ(m.side_set_global_size[k], GlobalIndex(theirs.elements.size()));
    std::vector<GlobalIndex> expected;
    for (std::size_t i = 0; i < theirs.elements.size(); ++i)
      if (expected_elements.count(theirs.elements[i])) expected.push_back(GlobalIndex(i));
    ASSERT_EQ(m.side_set_position[k], expected) << theirs.name;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      ASSERT_EQ(m.element_gid[mine.elements[i]], theirs.elements[expected[i]]);
      ASSERT_EQ(mine.sides[i], theirs.sides[expected[i]]);
    }
  }
  ASSERT_EQ(m.local.node_sets.size(), file.node_sets.size());
  for (std::size_t k = 0; k < file.node_sets.size(); ++k) {
    const NodeSet &mine = m.local.node_sets[k], &theirs = file.node_sets[k];
    ASSERT_EQ(mine.name, theirs.name);
    ASSERT_EQ(mine.id, theirs.id);
    std::vector<GlobalIndex> expected;
    for (std::size_t i = 0; i < theirs.nodes.size(); ++i)
      if (expected_nodes.count(theirs.nodes[i])) expected.push_back(GlobalIndex(i));
    ASSERT_EQ(m.node_set_position[k], expected) << theirs.name;
    for (std::size_t i = 0; i < expected.size(); ++i)
      ASSERT_EQ(m.node_gid[mine.nodes[i]], theirs.nodes[expected[i]]);
  }
  // The local part is a valid Mesh in its own right.
  EXPECT_NO_THROW(check_mesh(m.local));
  // The holdings report names every rank on rank 0.
  const std::string text = describe_holdings(*comm, m);
  if (me == 0)
    EXPECT_NE(text.find("mesh on rank " + std::to_string(comm->getSize() - 1)), std::string::npos);
  else
    EXPECT_TRUE(text.empty());
}

TEST(DistributedMesh, QuadRectangleMatchesReplicated) {
  check_against_replicated(write_mesh(rectangle_mesh(13, 7, 0, 2, 0, 1, false, 0.2), "quad"));
}

TEST(DistributedMesh, TriangleRectangleMatchesReplicated) {
  check_against_replicated(write_mesh(rectangle_mesh(9, 11, 0, 1, 0, 1, true, 0.1, 3), "tri"));
}

TEST(DistributedMesh, TwoBodyHexMatchesReplicated) {
  check_against_replicated(write_mesh(two_block_mesh_3d(4, 4, 3, 3, 3, 2, false, 0.01), "hex2"));
}

TEST(DistributedMesh, TetBoxWithContactWeightMatchesReplicated) {
  DistributionOptions options;
  options.contact_side_sets = {"zmax"};
  options.contact_weight = 10.0;
  check_against_replicated(write_mesh(box_mesh(4, 3, 5, {}, true, 0.1), "tet"), options);
}

TEST(DistributedMesh, NodeOfNoElementBelongsToRankZero) {
  Mesh mesh = rectangle_mesh(4, 3);
  mesh.coordinates.insert(mesh.coordinates.end(), {5.0, 5.0});
  mesh.node_sets[0].nodes.push_back(mesh.num_nodes() - 1);
  check_against_replicated(write_mesh(mesh, "orphan"));
}

/// A gmsh mesh from the ctest fixture gmsh_hertz_meshes (inputs/gmsh_hertz).
std::string gmsh_mesh(const char* name) {
  const std::string path = std::string(GROUT_BINARY_DIR) + "/inputs/gmsh_hertz/" + name;
  EXPECT_TRUE(std::filesystem::exists(path)) << path << " (ctest fixture gmsh_hertz_meshes)";
  return path;
}

TEST(DistributedMesh, GmshHalfDiscsMatchReplicated) {
  check_against_replicated(gmsh_mesh("point_contact.exo"));
}

TEST(DistributedMesh, GmshHemispheresMatchReplicated) {
  check_against_replicated(gmsh_mesh("hemispheres.exo"));
}

/// Owned elements and owned faces of side set `set` on this rank.
std::pair<long long, long long> owned_elements_and_faces(const DistributedMesh& m,
                                                         const std::string& set) {
  long long faces = 0;
  for (GlobalIndex e : m.local.find_side_set(set)->elements) faces += m.owns_element(e);
  return {m.num_owned_elements(), faces};
}

TEST(DistributedMesh, GmshHemispheresWithSeparateContactMatchReplicated) {
  DistributionOptions options;
  options.contact_side_sets = {"lower_contact"};
  options.separate_contact = true;
  check_against_replicated(gmsh_mesh("hemispheres.exo"), options);
}

TEST(DistributedMesh, SeparateContactSharesElementsAndContactFaces) {
  // Two hemispheres one above the other: weights 1 cut between them, so one part holds the
  // whole slave surface; partitioned apart, the slave faces' elements and the others are each
  // split evenly, within RCB's 1 % (a face or element more for rounding).
  const auto comm = world();
  const std::string path = gmsh_mesh("hemispheres.exo");
  const Mesh file = read_exodus(path);
  const double parts = comm->getSize();
  const double elements = double(file.num_elements()),
               faces = double(file.find_side_set("lower_contact")->elements.size());
  DistributionOptions options;
  options.contact_side_sets = {"lower_contact"};
  options.separate_contact = true;
  const auto [mine_elements, mine_faces] =
      owned_elements_and_faces(read_distributed_mesh(*comm, path, options), "lower_contact");
  EXPECT_LE(std::abs(double(mine_elements) - elements / parts), 0.01 * elements / parts + 1.0);
  EXPECT_LE(std::abs(double(mine_faces) - faces / parts), 0.01 * faces / parts + 1.0);
}

TEST(DistributedMesh, GmshHemispheresWithGapBandsMatchReplicated) {
  DistributionOptions options;
  options.contact_side_sets = {"upper_contact"};
  options.master_side_sets = {"lower_contact"};
  options.separate_contact = true;
  check_against_replicated(gmsh_mesh("hemispheres.exo"), options);
}

/// Element centroids of `file` (the mean of the nodes), 3 per element.
std::vector<double> element_centroids(const Mesh& file) {
  std::vector<double> c(std::size_t(3 * file.num_elements()), 0.0);
  for (const auto& b : file.blocks)
    for (GlobalIndex e = 0; e < b.num_elements(); ++e)
      for (int a = 0; a < b.nodes_per_element; ++a)
        for (int d = 0; d < file.dimension; ++d)
          c[std::size_t(3 * (b.first_element + e) + d)] +=
              file.coordinates[std::size_t(
                  b.connectivity[std::size_t(e * b.nodes_per_element + a)] * file.dimension + d)] /
              b.nodes_per_element;
  return c;
}

TEST(DistributedMesh, GapBandsShareTheContactZoneOnBothSurfaces) {
  // The gmsh hemispheres touch at one point. A contact zone is, near enough, the faces within
  // some distance of the other surface. Brute force: every slave element's distance to the
  // nearest master element (centroids) and every master element's to the nearest slave
  // element; the nearest k/K of them (k = 1 .. K-1, K the bands) are a zone of growing size.
  // Each rank owns its share of each zone, within RCB's 1 % per band (an element more per band
  // for rounding). The cut by position alone (no master sets: the slave elements apart, the
  // master elements with the solid) does not share them on 2 ranks.
  const auto comm = world();
  const int parts = comm->getSize();
  const std::string path = gmsh_mesh("hemispheres.exo");
  const Mesh file = read_exodus(path);
  const std::vector<double> c = element_centroids(file);
  const auto elements_of = [&](const char* set) {
    const auto& e = file.find_side_set(set)->elements;
    return std::set<GlobalIndex>(e.begin(), e.end());
  };
  const std::set<GlobalIndex> slave = elements_of("upper_contact"),
                              master = elements_of("lower_contact");
  const auto distance_to = [&](GlobalIndex e, const std::set<GlobalIndex>& other) {
    double best = std::numeric_limits<double>::infinity();
    for (GlobalIndex o : other) {
      double r2 = 0.0;
      for (int d = 0; d < 3; ++d)
        r2 += std::pow(c[std::size_t(3 * e + d)] - c[std::size_t(3 * o + d)], 2);
      if (o != e) best = std::min(best, r2);
    }
    return std::sqrt(best);
  };
  std::vector<std::pair<double, GlobalIndex>> by_distance;
  for (GlobalIndex e : slave) by_distance.emplace_back(distance_to(e, master), e);
  for (GlobalIndex e : master) by_distance.emplace_back(distance_to(e, slave), e);
  std::sort(by_distance.begin(), by_distance.end());
  const std::size_t C = by_distance.size();
  const int K = num_gap_bands(GlobalIndex(C), parts);
  ASSERT_GE(K, parts > 1 ? 2 : 1) << C << " contact elements";

  const auto owned_share = [&](const DistributedMesh& m, std::size_t count) {
    std::set<GlobalIndex> mine;
    for (GlobalIndex e = 0; e < m.num_local_elements(); ++e)
      if (m.owns_element(e)) mine.insert(m.element_gid[e]);
    long long n = 0;
    for (std::size_t k = 0; k < count; ++k) n += mine.count(by_distance[k].second);
    return double(n);
  };
  // The largest excess over the tolerance of any rank's share of any zone (≤ 0: shared).
  const auto worst_excess = [&](const DistributedMesh& m) {
    double worst = -std::numeric_limits<double>::infinity();
    for (int k = 1; k <= K; ++k) {
      const std::size_t zone = C * std::size_t(k) / std::size_t(K);
      const double off = std::abs(owned_share(m, zone) - double(zone) / parts);
      worst = std::max(worst, off - (0.01 * double(zone) / parts + k + 1));
    }
    double most = 0.0;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, worst, Teuchos::outArg(most));
    return most;
  };
  DistributionOptions options;
  options.contact_side_sets = {"upper_contact"};
  options.master_side_sets = {"lower_contact"};
  options.separate_contact = true;
  EXPECT_LE(worst_excess(read_distributed_mesh(*comm, path, options)), 0.0);
  if (parts == 2) {  // the cut by position alone (the slave elements apart) does not share them
    options.master_side_sets.clear();
    EXPECT_GT(worst_excess(read_distributed_mesh(*comm, path, options)), 0.0);
  }
}

TEST(ContactBands, NearestDistancesAreTheBruteForceOnes) {
  // Points on a wavy surface, queries around it; a query never finds its own id.
  std::vector<double> points, queries;
  std::vector<GlobalIndex> point_ids, query_ids;
  unsigned seed = 7;
  const auto next = [&] { return (seed = seed * 1103515245u + 12345u) / 4294967296.0; };
  for (int i = 0; i < 400; ++i) {
    const double x = next(), y = next();
    points.insert(points.end(), {x, y, 0.1 * std::sin(6.0 * x) * std::cos(5.0 * y)});
    point_ids.push_back(i);
  }
  for (int i = 0; i < 300; ++i) {
    queries.insert(queries.end(), {1.4 * next() - 0.2, 1.4 * next() - 0.2, 0.6 * next() - 0.3});
    query_ids.push_back(i < 100 ? i : 1000 + i);  // the first 100 are points' ids
  }
  const std::vector<double> d = nearest_distances(points, point_ids, queries, query_ids);
  for (std::size_t q = 0; q < query_ids.size(); ++q) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t p = 0; p < point_ids.size(); ++p) {
      if (point_ids[p] == query_ids[q]) continue;
      double r2 = 0.0;
      for (int k = 0; k < 3; ++k) r2 += std::pow(queries[3 * q + k] - points[3 * p + k], 2);
      best = std::min(best, r2);
    }
    EXPECT_EQ(d[q], std::sqrt(best)) << "query " << q;
  }
  EXPECT_TRUE(std::isinf(nearest_distances({}, {}, {0.0, 0.0, 0.0}, {0})[0]));
  EXPECT_EQ(num_gap_bands(0, 2), 1);
  EXPECT_EQ(num_gap_bands(400, 2), 3);
  EXPECT_EQ(num_gap_bands(100000, 2), 8);
}

TEST(DistributedMesh, EachRankHoldsAtMost55PercentOnTwoOrMoreRanks) {
  const auto comm = world();
  if (comm->getSize() < 2) GTEST_SKIP() << "needs 2 ranks";
  // A cube of n^3 hexes cut in two holds, with its ghost layer, n/2 + 2 of the n + 1 node
  // layers and n/2 + 1 of the n element layers on a rank: 54.5 % and 53.1 % for n = 32 (the
  // ghost layer's share falls as 1/n: a 22^3 cube, 1e4 elements, would hold 56.5 % nodes).
  const std::string path = write_mesh(box_mesh(32, 32, 32), "memory");
  const DistributedMesh m = read_distributed_mesh(*comm, path);
  ASSERT_GE(m.global_num_elements, 10000);
  EXPECT_LE(double(m.num_local_nodes()), 0.55 * double(m.global_num_nodes));
  EXPECT_LE(double(m.num_local_elements()), 0.55 * double(m.global_num_elements));
}

/// The replicated reader's message for the bad mesh at `path` (read_exodus + check_mesh).
std::string replicated_error(const std::string& path) {
  try {
    check_mesh(read_exodus(path));
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

/// Every rank throws: the reporting rank InputError with the replicated reader's message,
/// the others ErrorOnOtherRank with exit code 2.
void expect_error_on_every_rank(const std::string& path) {
  const auto comm = world();
  const std::string expected = replicated_error(path);
  ASSERT_NE(expected, "no error");
  int reporters = 0;
  try {
    read_distributed_mesh(*comm, path);
    ADD_FAILURE() << "no error for " << path;
  } catch (const ErrorOnOtherRank& e) {
    EXPECT_EQ(e.exit_code(), 2);
  } catch (const InputError& e) {
    reporters = 1;
    EXPECT_EQ(std::string(e.what()), expected);
  }
  int total = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 1, &reporters, &total);
  EXPECT_EQ(total, 1);
}

TEST(DistributedMesh, InvertedElementThrowsOnEveryRank) {
  Mesh mesh = rectangle_mesh(6, 5);
  auto& c = mesh.blocks[0].connectivity;
  std::swap(c[4 * 17 + 1], c[4 * 17 + 3]);  // element 18: a node order of negative area
  expect_error_on_every_rank(write_mesh(mesh, "inverted"));
}

TEST(DistributedMesh, DuplicateNodeInNodeSetThrowsOnEveryRank) {
  Mesh mesh = rectangle_mesh(6, 5);
  mesh.node_sets[1].nodes.push_back(mesh.node_sets[1].nodes.front());
  expect_error_on_every_rank(write_mesh(mesh, "duplicate_node"));
}

TEST(DistributedMesh, DuplicateFaceInSideSetThrowsOnEveryRank) {
  Mesh mesh = rectangle_mesh(6, 5);
  mesh.side_sets[2].elements.push_back(mesh.side_sets[2].elements.front());
  mesh.side_sets[2].sides.push_back(mesh.side_sets[2].sides.front());
  expect_error_on_every_rank(write_mesh(mesh, "duplicate_face"));
}

TEST(DistributedMesh, BadSideNumberThrowsOnEveryRank) {
  Mesh mesh = rectangle_mesh(6, 5);
  mesh.side_sets[3].sides.back() = 5;  // QUAD4 has sides 1-4
  expect_error_on_every_rank(write_mesh(mesh, "bad_side"));
}

TEST(DistributedMesh, DuplicateSetNameThrowsOnEveryRank) {
  Mesh mesh = rectangle_mesh(6, 5);
  mesh.node_sets[1].name = mesh.node_sets[0].name;
  expect_error_on_every_rank(write_mesh(mesh, "duplicate_name"));
}

TEST(DistributedMesh, MissingFileThrowsOnEveryRank) {
  expect_error_on_every_rank(std::string(GROUT_BINARY_DIR) + "/unit_tests/no_such_mesh.exo");
}

}  // namespace
}  // namespace grout
