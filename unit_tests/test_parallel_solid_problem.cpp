// SolidProblem built from this rank's part of the distributed mesh (parallel/distributed_mesh.hpp,
// Zoltan2's partition) against SolidProblem built from the replicated mesh (partition_mesh's
// partition), on 1, 2 and 3 ranks: both number dof c of global node n as n*dim + c, so after
// moving one's owned rows onto the other's map the internal force, the tangent (entry by
// entry, same pattern), the surface loads, the prescribed displacements, the stored energy and
// the element stresses must agree to round-off. Each row sums its elements in global element
// order on both paths, so in practice they agree bit for bit.

#include <gtest/gtest.h>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_Import.hpp>
#include <algorithm>
#include <cmath>
#include <map>

#include "assembly/solid_problem.hpp"
#include "io/exodus.hpp"
#include "io/mesh_generators.hpp"
#include "parallel/distributed_mesh.hpp"

namespace grout {
namespace {

Teuchos::RCP<const Comm> world() {
  return Tpetra::getDefaultComm();
}

/// Writes `mesh` (rank 0) to the build tree; every rank gets the path.
std::string write_mesh(const Mesh& mesh, const std::string& name) {
  const auto comm = world();
  const std::string path = std::string(GROUT_BINARY_DIR) + "/unit_tests/distsolid_" + name + "_np" +
                           std::to_string(comm->getSize()) + ".exo";
  if (comm->getRank() == 0) write_exodus_mesh(path, mesh);
  comm->barrier();
  return path;
}

/// One material per block of `mesh` (Young's modulus differing from block to block).
Input make_input(const Mesh& mesh, StrainKind strain, const std::string& load_set,
                 const std::string& fixed_set) {
  const int dim = mesh.dimension;
  Input input;
  input.file = "test.yaml";
  input.model.dimension = dim;
  input.model.strain = strain;
  for (const ElementBlock& block : mesh.blocks) {
    MaterialInput m;
    m.name = m.block = block.name;
    m.law = strain == StrainKind::finite ? MaterialLaw::neo_hookean : MaterialLaw::linear_elastic;
    m.youngs_modulus = 1000.0 * double(input.materials.size() + 1);
    m.poissons_ratio = 0.3;
    input.materials.push_back(m);
  }
  LoadInput load;
  load.name = "push";
  load.side_set = load_set;
  load.value = Expression("10 + 3*x - 2*y + t", "test.yaml: push");
  input.loads.push_back(load);
  for (int c = 0; c < dim; ++c) {
    DirichletInput d;
    d.name = "fix_" + std::to_string(c);
    d.node_set = fixed_set;
    d.component = c;
    d.value = Expression(c == 0 ? "0.01*t*y" : "-0.02*t", "test.yaml: fix");
    input.dirichlet.push_back(d);
  }
  return input;
}

/// u(X) smooth and nonlinear, from the global node's coordinates (held by both problems).
void fill_displacement(const SolidProblem& solid, Vector& u) {
  const int dim = solid.dimension();
  const auto X = solid.column_coordinates();
  const auto& map = *solid.owned_map();
  auto uv = u.getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (std::size_t i = 0; i < map.getNodeNumElements(); ++i) {
    const int k = int(i) / dim, c = int(i) % dim;  // owned node k is column node k
    double s = 0.0;
    for (int d = 0; d < dim; ++d) s += (d + 1) * X(k, d);
    uv(i, 0) = 0.05 * std::sin(s + c) + 0.02 * X(k, c);
  }
}

/// `v` (on another partition's map) moved onto `map`.
Teuchos::RCP<Vector> on_map(const Vector& v, const Teuchos::RCP<const Map>& map) {
  auto out = Teuchos::rcp(new Vector(map));
  const Import import(v.getMap(), map);
  out->doImport(v, import, Tpetra::INSERT);
  return out;
}

double max_abs(const Vector& v) {
  return v.normInf();
}

void expect_vectors_agree(const Vector& a, const Vector& b_other, const char* what) {
  const auto b = on_map(b_other, a.getMap());
  const auto av = a.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto bv = b->getLocalViewHost(Tpetra::Access::ReadOnly);
  const double scale = std::max(max_abs(a), 1e-300);
  for (std::size_t i = 0; i < av.extent(0); ++i)
    ASSERT_NEAR(av(i, 0), bv(i, 0), 1e-14 * scale)
        << what << " at dof " << a.getMap()->getGlobalElement(LO(i));
}

/// Row g of a fill-complete matrix as (global column, value).
std::map<GO, double> row_of(const Matrix& K, GO g) {
  std::map<GO, double> row;
  const LO i = K.getRowMap()->getLocalElement(g);
  const auto local = K.getLocalMatrixHost();
  for (auto p = local.graph.row_map(i); p < local.graph.row_map(i + 1); ++p)
    row[K.getColMap()->getGlobalElement(local.graph.entries(p))] += local.values(p);
  return row;
}

void check(const Mesh& generated, const std::string& name, StrainKind strain,
           const std::string& load_set, const std::string& fixed_set) {
  const auto comm = world();
  const std::string path = write_mesh(generated, name);
  const Mesh mesh = read_exodus(path);
  const DistributedMesh part = read_distributed_mesh(*comm, path);
  const Input input = make_input(mesh, strain, load_set, fixed_set);
  const SolidProblem replicated(mesh, input, comm);
  const SolidProblem distributed(mesh_part(part), input, comm);
  ASSERT_EQ(distributed.num_global_nodes(), replicated.num_global_nodes());
  ASSERT_EQ(distributed.num_global_elements(), replicated.num_global_elements());
  ASSERT_EQ(distributed.owned_map()->getGlobalNumElements(),
            replicated.owned_map()->getGlobalNumElements());

  Vector u_r(replicated.owned_map()), u_d(distributed.owned_map());
  fill_displacement(replicated, u_r);
  fill_displacement(distributed, u_d);
  expect_vectors_agree(u_r, u_d, "u (both from the nodes' coordinates)");

  // F (internal force) and J (tangent).
  Vector f_r(replicated.owned_map()), f_d(distributed.owned_map());
  const auto K_r = replicated.create_matrix(), K_d = distributed.create_matrix();
  ASSERT_TRUE(replicated.assemble(u_r, f_r, K_r.get()));
  ASSERT_TRUE(distributed.assemble(u_d, f_d, K_d.get()));
  expect_vectors_agree(f_r, f_d, "f_int");
  const Import rows(distributed.owned_map(), replicated.owned_map());
  const auto K_moved = Tpetra::importAndFillCompleteCrsMatrix<Matrix>(
      K_d, rows, replicated.owned_map(), replicated.owned_map());
  ASSERT_EQ(K_moved->getGlobalNumEntries(), K_r->getGlobalNumEntries());
  const double scale = K_r->getFrobeniusNorm();
  for (std::size_t i = 0; i < replicated.owned_map()->getNodeNumElements(); ++i) {
    const GO g = replicated.owned_map()->getGlobalElement(LO(i));
    const auto a = row_of(*K_r, g), b = row_of(*K_moved, g);
    ASSERT_EQ(a.size(), b.size()) << "row " << g;
    for (const auto& [column, value] : a) {
      ASSERT_EQ(b.count(column), 1u) << "row " << g << " column " << column;
      ASSERT_NEAR(value, b.at(column), 1e-14 * scale) << "row " << g << " column " << column;
    }
  }

  // Loads and prescribed displacements at t = 1.
  Vector p_r(replicated.owned_map()), p_d(distributed.owned_map());
  replicated.external_force(1.0, p_r);
  distributed.external_force(1.0, p_d);
  ASSERT_GT(max_abs(p_r), 0.0);
  expect_vectors_agree(p_r, p_d, "f_ext");
  // Prescribed displacements (per column dof): the owned values agree between the two
  // partitions, and on each the ghost values are their owners'.
  const auto owned_part = [](const SolidProblem& s, const std::vector<double>& column) {
    Vector v(s.owned_map());
    auto view = v.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t i = 0; i < view.extent(0); ++i) view(i, 0) = column.at(i);
    return v;
  };
  const auto same = [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); };
  const std::vector<double> g_r = replicated.prescribed_displacements(1.0);
  const std::vector<double> g_d = distributed.prescribed_displacements(1.0);
  ASSERT_EQ(g_r.size(), replicated.column_map()->getNodeNumElements());
  ASSERT_EQ(g_d.size(), distributed.column_map()->getNodeNumElements());
  const Vector pv_r = owned_part(replicated, g_r), pv_d = owned_part(distributed, g_d);
  int prescribed = 0;
  {
    const auto moved = on_map(pv_d, replicated.owned_map());
    const auto a = pv_r.getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto b = moved->getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t i = 0; i < a.extent(0); ++i) {
      EXPECT_TRUE(same(a(i, 0), b(i, 0)))
          << "dof " << replicated.owned_map()->getGlobalElement(LO(i)) << ": " << a(i, 0)
          << " replicated, " << b(i, 0) << " distributed";
      prescribed += !std::isnan(a(i, 0));
    }
  }
  for (const auto* p : {&replicated, &distributed}) {
    const std::vector<double>& g = p == &replicated ? g_r : g_d;
    const auto ghosts = on_map(p == &replicated ? pv_r : pv_d, p->column_map());
    const auto v = ghosts->getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t k = 0; k < g.size(); ++k)
      EXPECT_TRUE(same(g[k], v(k, 0))) << "column dof " << p->column_map()->getGlobalElement(LO(k));
  }
  int prescribed_all = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, prescribed, Teuchos::outArg(prescribed_all));
  EXPECT_GT(prescribed_all, 0);

  // Stored energy and element stresses (each element once, by its owner).
  const double W_r = replicated.stored_energy(u_r), W_d = distributed.stored_energy(u_d);
  EXPECT_NEAR(W_r, W_d, 1e-14 * std::abs(W_r));
  const auto owned_r = replicated.owned_elements(), owned_d = distributed.owned_elements();
  EXPECT_TRUE(std::is_sorted(owned_d.begin(), owned_d.end()));  // blocks in global order
  const auto s_r = replicated.element_stresses(u_r), s_d = distributed.element_stresses(u_d);
  const std::size_t E = std::size_t(mesh.num_elements());
  for (std::size_t c = 0; c < s_r.size(); ++c) {
    std::vector<double> whole_r(E, 0.0), whole_d(E, 0.0), sum_r(E), sum_d(E);
    for (std::size_t k = 0; k < owned_r.size(); ++k) whole_r[owned_r[k]] = s_r[c][k];
    for (std::size_t k = 0; k < owned_d.size(); ++k) whole_d[owned_d[k]] = s_d[c][k];
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, int(E), whole_r.data(), sum_r.data());
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, int(E), whole_d.data(), sum_d.data());
    const double s_scale = *std::max_element(
        sum_r.begin(), sum_r.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
    for (std::size_t e = 0; e < E; ++e)
      ASSERT_NEAR(sum_r[e], sum_d[e], 1e-14 * std::abs(s_scale)) << "element " << e;
  }
}

TEST(DistributedSolid, DistortedQuadsSmallStrainMatchReplicated) {
  check(rectangle_mesh(13, 7, 0, 2, 0, 1, false, 0.2), "quad", StrainKind::small, "right", "left");
}

TEST(DistributedSolid, TrianglesFiniteStrainMatchReplicated) {
  check(rectangle_mesh(9, 11, 0, 1, 0, 1, true, 0.1, 3), "tri", StrainKind::finite, "top",
        "bottom");
}

TEST(DistributedSolid, TetBoxFiniteStrainMatchReplicated) {
  check(box_mesh(4, 3, 5, {}, true, 0.1), "tet", StrainKind::finite, "zmax", "zmin");
}

TEST(DistributedSolid, HexBoxSmallStrainMatchReplicated) {
  check(box_mesh(5, 4, 3, {}, false, 0.15), "hex", StrainKind::small, "xmax", "xmin");
}

TEST(DistributedSolid, TwoBlocksMatchReplicated) {
  check(two_block_mesh_3d(4, 4, 3, 3, 3, 2, false, 0.01), "hex2", StrainKind::finite, "upper_top",
        "lower_bottom");
}

TEST(DistributedSolid, NodeOfNoElementMatchesReplicated) {
  Mesh mesh = rectangle_mesh(6, 5);
  mesh.coordinates.insert(mesh.coordinates.end(), {5.0, 5.0});  // owned by rank 0
  mesh.node_sets[0].nodes.push_back(mesh.num_nodes() - 1);
  check(mesh, "orphan", StrainKind::small, "top", mesh.node_sets[0].name);
}

}  // namespace
}  // namespace grout
