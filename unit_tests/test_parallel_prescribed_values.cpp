// The prescribed values one rank holds (nonlinear/prescribed_values.hpp), on 1, 2 and 3 ranks:
// - PrescribedValues alone: dofs covered beyond the column map get their owners' values, and
//   the held dofs keep theirs;
// - MechanicsProblem on the distributed two-block mesh with contact, after a step's start, a
//   residual and a Jacobian: each rank holds the dofs of its column map and those of its
//   contact nodes beyond it, not the whole mesh's (the held count is at most its solid column
//   map plus the contact side sets' dofs, and below the mesh's dof count on 2 or more ranks),
//   every u column of the Jacobian is held, and every held value is the Dirichlet expression
//   at the node (bit for bit: the owner evaluates it) or NaN where the dof is free.

#include <gtest/gtest.h>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <algorithm>
#include <cmath>
#include <set>

#include "assembly/contact_mesh.hpp"
#include "assembly/solid_problem.hpp"
#include "io/exodus.hpp"
#include "io/mesh_generators.hpp"
#include "nonlinear/mechanics_problem.hpp"
#include "nonlinear/prescribed_values.hpp"
#include "parallel/distributed_bodies.hpp"
#include "parallel/distributed_mesh.hpp"
#include "unit_tests/two_block_contact_input.hpp"

namespace grout {
namespace {

Teuchos::RCP<const Comm> world() {
  return Tpetra::getDefaultComm();
}

bool same(double a, double b) {
  return a == b || (std::isnan(a) && std::isnan(b));
}

// Dofs 0 .. 10 R − 1 on R ranks, 10 per rank; the column map adds the next rank's first dof.
// A dof's value is 0.5 g for even g, free for odd g.
TEST(PrescribedValues, CoveredDofsGetTheirOwnersValues) {
  const auto comm = world();
  const int rank = comm->getRank(), ranks = comm->getSize();
  const GO n = 10 * GO(ranks);
  std::vector<GO> owned, column;
  for (GO g = 10 * rank; g < 10 * (rank + 1); ++g) owned.push_back(g);
  column = owned;
  if (rank + 1 < ranks) column.push_back(10 * (rank + 1));
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  const auto owned_map = Teuchos::rcp(new Map(n, owned.data(), owned.size(), 0, comm));
  const auto column_map = Teuchos::rcp(new Map(invalid, column.data(), column.size(), 0, comm));
  PrescribedValues p(owned_map, column_map);
  EXPECT_EQ(p.size(), column.size());
  const auto value_of = [](GO g) { return g % 2 == 0 ? 0.5 * double(g) : std::nan(""); };
  std::vector<double> column_values;
  for (GO g : column) column_values.push_back(g % 2 == 0 ? value_of(g) : std::nan(""));
  if (rank + 1 < ranks) column_values.back() = 1e9;  // a ghost's value is its owner's
  p.set(column_values);
  for (GO g : column) EXPECT_TRUE(same(p.value(g), value_of(g))) << "dof " << g;
  // Every rank covers the last rank's dofs and dof 3 (repeated, some held already).
  std::vector<GO> more{3, 3};
  for (GO g = n - 10; g < n; ++g) more.push_back(g);
  p.cover(more);
  std::set<GO> held(column.begin(), column.end());
  held.insert(more.begin(), more.end());
  EXPECT_EQ(p.size(), held.size());
  for (GO g : held) EXPECT_TRUE(same(p.value(g), value_of(g))) << "dof " << g;
  for (std::size_t i = 0; i < column.size(); ++i)  // held dofs keep their local index
    EXPECT_EQ(p.held_map()->getGlobalElement(LO(i)), column[i]);
  if (ranks >= 3 && rank == 0) EXPECT_FALSE(p.holds(15));  // rank 1's, not covered here
  EXPECT_THROW(p.value(n), std::logic_error);
  // A new time: the covered dofs are imported again.
  for (double& v : column_values) v = std::isnan(v) ? v : 2.0 * v;
  p.set(column_values);
  for (GO g : held)
    EXPECT_TRUE(same(p.value(g), g % 2 == 0 ? double(g) : std::nan(""))) << "dof " << g;
}

/// What contact reads of a distributed mesh, with its bodies (as the driver builds it).
ContactMeshPart contact_part(const Comm& comm, const DistributedMesh& mesh) {
  ContactMeshPart part;
  part.global_num_nodes = mesh.global_num_nodes;
  part.rank = mesh.rank;
  part.node_gid = &mesh.node_gid;
  part.element_owner = &mesh.element_owner;
  part.element_gid = &mesh.element_gid;
  part.side_set_position = &mesh.side_set_position;
  part.side_set_global_size = &mesh.side_set_global_size;
  part.node_body = distributed_node_body_labels(comm, mesh);
  return part;
}

TEST(PrescribedValues, ContactProblemHoldsItsPartOnly) {
  const auto comm = world();
  const int dim = 2;
  // Non-matching blocks, the upper one pressed down and sheared (current geometry).
  const std::string path = std::string(GROUT_BINARY_DIR) + "/unit_tests/prescribed_values_np" +
                           std::to_string(comm->getSize()) + ".exo";
  if (comm->getRank() == 0) write_exodus_mesh(path, two_block_mesh_2d(16, 4, 12, 4));
  comm->barrier();
  const Mesh whole = read_exodus(path);  // the reference values (this test only)
  Input input = two_block_bodies(dim, ContactKind::frictionless, 0.0, ContactGeometry::current);
  add_dirichlet(input, "lower_bottom", 0, "0");
  add_dirichlet(input, "lower_bottom", 1, "0");
  add_dirichlet(input, "upper_top", 0, "0.003*t*x");
  add_dirichlet(input, "upper_top", 1, "-0.01*t*(1 + x*x)");
  add_dirichlet(input, "lower_left", 0, "0");

  const DistributedMesh part = read_distributed_mesh(*comm, path);
  const ContactMeshPart cpart = contact_part(*comm, part);
  const SolidProblem solid(mesh_part(part), input, comm);
  MechanicsProblem problem(solid, part.local, input, &cpart);
  Vector x(problem.map()), F(problem.map());
  x.putScalar(0.0);
  const double t = 0.7;
  problem.begin_step(t, x);
  ASSERT_TRUE(problem.residual(x, F));
  Teuchos::RCP<Matrix> J;
  ASSERT_TRUE(problem.jacobian(x, J));
  const PrescribedValues& p = problem.prescribed();

  // Size: the solid's column map plus contact nodes, never the whole mesh.
  const std::size_t column = solid.column_map()->getNodeNumElements();
  std::set<GlobalIndex> surface;
  for (const char* set : {"upper_bottom", "lower_top"})
    for (GlobalIndex k : whole.find_node_set(set)->nodes) surface.insert(k);
  const GO num_u = GO(whole.num_nodes()) * dim;
  EXPECT_GE(p.size(), column);
  EXPECT_LE(p.size(), column + dim * surface.size());
  if (comm->getSize() > 1) EXPECT_LT(GO(p.size()), num_u);

  // Coverage: every u column of the Jacobian.
  const Map& cols = *J->getColMap();
  for (std::size_t c = 0; c < cols.getNodeNumElements(); ++c) {
    const GO g = cols.getGlobalElement(LO(c));
    if (g < num_u) EXPECT_TRUE(p.holds(g)) << "Jacobian column " << g;
  }

  // Values: the Dirichlet expressions at the nodes, NaN elsewhere.
  std::vector<const DirichletInput*> bc_of(std::size_t(num_u), nullptr);
  for (const DirichletInput& bc : input.dirichlet)
    for (GlobalIndex n : whole.find_node_set(bc.node_set)->nodes)
      bc_of[n * dim + bc.component] = &bc;
  const Map& held = *p.held_map();
  long long beyond = 0, fixed = 0;
  for (std::size_t i = 0; i < held.getNodeNumElements(); ++i) {
    const GO g = held.getGlobalElement(LO(i));
    const GlobalIndex n = g / dim;
    const DirichletInput* bc = bc_of[std::size_t(g)];
    const double expected =
        bc ? bc->value(t, whole.coordinates[n * dim], whole.coordinates[n * dim + 1], 0.0)
           : std::nan("");
    EXPECT_TRUE(same(p.value(g), expected))
        << "dof " << g << ": " << p.value(g) << ", expected " << expected;
    beyond += !solid.column_map()->isNodeGlobalElement(g);
    fixed += bc != nullptr;
  }
  long long beyond_all = 0, fixed_all = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, beyond, Teuchos::outArg(beyond_all));
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, fixed, Teuchos::outArg(fixed_all));
  EXPECT_GT(fixed_all, 0);
  if (comm->getRank() == 0)
    std::printf(
        "rank 0 holds %zu prescribed values (column map %zu, mesh %lld dofs); "
        "%lld held beyond the column maps on all ranks\n",
        p.size(), column, num_u, beyond_all);
}

}  // namespace
}  // namespace grout
