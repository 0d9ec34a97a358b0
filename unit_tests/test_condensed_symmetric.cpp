// Symmetric (null-space) reduction of the dual-mortar (u, λ) system
// (nonlinear/symmetric_condensation.hpp) on 1 and 2 ranks, on the Jacobians of MechanicsProblem
// for two-block contact meshes in 2D and 3D: for frictionless and tied contact on the
// reference geometry it applies, K̃ is symmetric, MUMPS's LDLᵀ of K̃ takes about half the
// flops of the LU, and the expanded solution (u and λ) equals the full direct solve of J x = b;
// on frictional (slipping) and frictionless contact on the current geometry, on a deliberately
// non-symmetric K and on multiplier columns that are not the constraints' gradients it
// declines, and LinearSolver then takes the (non-symmetric) condensation with the same answer.
// K̃, built without a general triple product, equals Tpetra's product Tᵀ J T entry by entry.

#include <gtest/gtest.h>

#include <TpetraExt_TripleMatrixMultiply.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_RowMatrixTransposer.hpp>
#include <cmath>
#include <random>
#include <set>

#include "assembly/solid_problem.hpp"
#include "io/mesh_generators.hpp"
#include "nonlinear/linear_solver.hpp"
#include "nonlinear/mechanics_problem.hpp"
#include "nonlinear/mumps_solver.hpp"
#include "nonlinear/symmetric_condensation.hpp"
#include "unit_tests/two_block_contact_input.hpp"

namespace grout {
namespace {

struct Case {
  Mesh mesh;
  Input input;
  std::unique_ptr<SolidProblem> solid;
  std::unique_ptr<MechanicsProblem> problem;
  Teuchos::RCP<Matrix> J;
  Teuchos::RCP<Vector> b;
  MultiplierPairing pairing;
  GO n_u = 0;
  int active = 0;
};

// The layout of `pairing` alone (system_layout.hpp), `dim` dofs per slave node.
SystemLayout pairing_layout(const MultiplierPairing& pairing, int dim) {
  SystemLayout layout;
  layout.multiplier_pairing = pairing, layout.dofs_per_node = dim;
  return layout;
}

// pairing_layout plus the mesh's coordinates: the iterative path's elasticity defaults
// (near-null space, aggregation on the nodes, the Jacobi smoother).
SystemLayout elastic_layout(const MultiplierPairing& pairing, const Mesh& mesh) {
  SystemLayout layout = pairing_layout(pairing, mesh.dimension);
  layout.coordinates = mesh.coordinates, layout.dim = mesh.dimension;
  return layout;
}

// J and −F at a perturbed state with a mix of active and inactive slave nodes.
void build(Case& mc, int dim, ContactKind type, double mu, ContactGeometry geometry, int k = 1,
           unsigned seed = 5u) {
  const auto comm = Tpetra::getDefaultComm();
  mc.mesh = dim == 2 ? two_block_mesh_2d(3 * k, 2 * k, 4 * k, 2 * k)
                     : two_block_mesh_3d(2 * k, 2 * k, k, 3 * k, 2 * k, k);
  mc.input = two_block_input(dim, type, mu, geometry);
  mc.solid = std::make_unique<SolidProblem>(mc.mesh, mc.input, comm);
  mc.problem = std::make_unique<MechanicsProblem>(*mc.solid, mc.mesh, mc.input);
  MechanicsProblem& problem = *mc.problem;
  Vector x(problem.map()), F(problem.map());
  mc.n_u = GO(mc.mesh.num_nodes()) * dim;
  {
    auto xv = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
    std::uniform_real_distribution<double> r(-1.0, 1.0);
    for (std::size_t i = 0; i < problem.map()->getNodeNumElements(); ++i) {
      const GO g = problem.map()->getGlobalElement(LO(i));
      std::mt19937 local(unsigned(g) * 7919u + seed);  // same value on any rank count
      const double v = r(local);
      xv(i, 0) = g < mc.n_u ? 1e-3 * v : (g - mc.n_u) % dim == dim - 1 ? -2.0 * v - 0.5 : v;
    }
  }
  problem.begin_step(1.0, x);
  EXPECT_TRUE(problem.residual(x, F));
  mc.active = problem.active_set_size();
  EXPECT_TRUE(problem.jacobian(x, mc.J));
  mc.b = Teuchos::rcp(new Vector(problem.map()));
  mc.b->update(-1.0, F, 0.0);
  mc.pairing = problem.multiplier_pairing();
}

// |a − b| / |b| over the displacements (lambda = false) or the multipliers.
double relative_difference(const Vector& a, const Vector& b, GO n_u, bool lambda) {
  const auto av = a.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto bv = b.getLocalViewHost(Tpetra::Access::ReadOnly);
  double d[2] = {0.0, 0.0}, all[2] = {0.0, 0.0};
  for (std::size_t i = 0; i < a.getLocalLength(); ++i) {
    if ((a.getMap()->getGlobalElement(LO(i)) >= n_u) != lambda) continue;
    d[0] += (av(i, 0) - bv(i, 0)) * (av(i, 0) - bv(i, 0));
    d[1] += bv(i, 0) * bv(i, 0);
  }
  Teuchos::reduceAll(*a.getMap()->getComm(), Teuchos::REDUCE_SUM, 2, d, all);
  return std::sqrt(all[0] / all[1]);
}

// max |A − Aᵀ| / max |A|.
double asymmetry(const Teuchos::RCP<const Matrix>& A) {
  const auto At =
      Tpetra::RowMatrixTransposer<double, LO, GO, Node>(Teuchos::rcp_const_cast<Matrix>(A))
          .createTranspose();
  double local[2] = {0.0, 0.0}, all[2] = {0.0, 0.0};
  const auto& rows = *A->getRowMap();
  for (LO i = 0; i < LO(rows.getNodeNumElements()); ++i) {
    const GO g = rows.getGlobalElement(i);
    typename Matrix::nonconst_global_inds_host_view_type ca("c", A->getNumEntriesInGlobalRow(g)),
        ct("c", At->getNumEntriesInGlobalRow(g));
    typename Matrix::nonconst_values_host_view_type va("v", ca.extent(0)), vt("v", ct.extent(0));
    std::size_t na = 0, nt = 0;
    A->getGlobalRowCopy(g, ca, va, na);
    At->getGlobalRowCopy(g, ct, vt, nt);
    std::map<GO, double> diff;
    for (std::size_t e = 0; e < na; ++e) {
      diff[ca(e)] += va(e);
      local[1] = std::max(local[1], std::abs(va(e)));
    }
    for (std::size_t e = 0; e < nt; ++e) diff[ct(e)] -= vt(e);
    for (const auto& [c, v] : diff) local[0] = std::max(local[0], std::abs(v));
  }
  Teuchos::reduceAll(*A->getRowMap()->getComm(), Teuchos::REDUCE_MAX, 2, local, all);
  return all[0] / all[1];
}

Teuchos::ParameterList params(const std::string& type, bool condense) {
  Teuchos::ParameterList p;
  p.set("type", type);
  p.set("condense_multipliers", condense);
  return p;
}

// The symmetric reduction applies; K̃ is symmetric; LDLᵀ of K̃ takes ≤ 0.6 of the LU's
// flops; u and λ equal the full direct solve's; LinearSolver (mumps) takes this path.
void check_applies(int dim, ContactKind type, const std::string& label, int k = 1) {
  Case mc;
  build(mc, dim, type, 0.0, ContactGeometry::reference, k);
  EXPECT_GT(mc.active, 0) << label;
  const auto map = mc.J->getRowMap();
  Vector x_full(map), x(map), x_solver(map);
  LinearSolver full(params("amesos2", false), "test", {});
  full.solve(mc.J, *mc.b, x_full);

  SymmetricCondensation reduction(mc.pairing, dim);
  ASSERT_TRUE(reduction.condense(*mc.J, *mc.b)) << label << ": " << reduction.reason();
  EXPECT_GT(reduction.statistics().eliminated, 0) << label;
  EXPECT_LT(asymmetry(reduction.matrix()), 1e-13) << label;
  MumpsOptions symmetric, general;
  symmetric.symmetric = true;
  MumpsSolver ldlt(symmetric), lu(general);
  Vector y(reduction.matrix()->getRowMap()), y_lu(reduction.matrix()->getRowMap());
  ldlt.solve(reduction.matrix(), reduction.rhs(), y);
  lu.solve(reduction.matrix(), reduction.rhs(), y_lu);
  EXPECT_LT(ldlt.statistics().flops, 0.6 * lu.statistics().flops) << label;
  reduction.expand(y, x);
  EXPECT_LT(relative_difference(x, x_full, mc.n_u, false), 1e-10) << label << " (u)";
  EXPECT_LT(relative_difference(x, x_full, mc.n_u, true), 1e-10) << label << " (lambda)";

  LinearSolver solver(params("mumps", true), "test", pairing_layout(mc.pairing, dim));
  solver.solve(mc.J, *mc.b, x_solver);
  EXPECT_TRUE(solver.last_solve_symmetric()) << label;
  EXPECT_LT(relative_difference(x_solver, x_full, mc.n_u, false), 1e-10) << label << " (u)";
  EXPECT_LT(relative_difference(x_solver, x_full, mc.n_u, true), 1e-10) << label << " (lambda)";

  // The iterative path takes it too (CG on K̃), and the condensation (GMRES) when told not to;
  // both to Belos's tolerance 1e-12 of the direct solve's answer.
  for (const bool reduce : {true, false}) {
    Teuchos::ParameterList belos = params("belos", true);
    belos.set("symmetric_reduction", reduce);
    LinearSolver iterative(belos, "test", pairing_layout(mc.pairing, dim));
    Vector x_belos(map);
    iterative.solve(mc.J, *mc.b, x_belos);
    EXPECT_EQ(iterative.last_solve_symmetric(), reduce) << label;
    EXPECT_LT(relative_difference(x_belos, x_full, mc.n_u, false), 1e-9) << label << " (u, belos)";
    EXPECT_LT(relative_difference(x_belos, x_full, mc.n_u, true), 1e-9)
        << label << " (lambda, belos)";
  }
  if (map->getComm()->getRank() == 0)
    std::printf(
        "[symmetric] %s: active %d, %d slave nodes, %d eliminated dofs, LDLt %.3g flops, LU "
        "%.3g\n",
        label.c_str(), mc.active, reduction.statistics().nodes, reduction.statistics().eliminated,
        ldlt.statistics().flops, lu.statistics().flops);
}

// The reduction declines (on every rank alike); LinearSolver falls back to the condensation
// and still gives the full direct solve's answer.
void check_declines(Case& mc, int dim, const std::string& label) {
  SymmetricCondensation reduction(mc.pairing, dim);
  EXPECT_FALSE(reduction.condense(*mc.J, *mc.b)) << label;
  EXPECT_FALSE(reduction.reason().empty()) << label;
  const auto map = mc.J->getRowMap();
  Vector x_full(map), x(map);
  LinearSolver full(params("amesos2", false), "test", {});
  full.solve(mc.J, *mc.b, x_full);
  LinearSolver solver(params("mumps", true), "test", pairing_layout(mc.pairing, dim));
  solver.solve(mc.J, *mc.b, x);
  EXPECT_FALSE(solver.last_solve_symmetric()) << label;
  EXPECT_LT(relative_difference(x, x_full, mc.n_u, false), 1e-8) << label;
  if (map->getComm()->getRank() == 0)
    std::printf("[symmetric] %s declines: %s\n", label.c_str(), reduction.reason().c_str());
}

// The row `g` of A as (column GID, value), without exact zeros unless `zeros`.
std::map<GO, double> global_row(const Matrix& A, GO g, bool zeros) {
  typename Matrix::nonconst_global_inds_host_view_type c("c", A.getNumEntriesInGlobalRow(g));
  typename Matrix::nonconst_values_host_view_type v("v", c.extent(0));
  std::size_t n = 0;
  A.getGlobalRowCopy(g, c, v, n);
  std::map<GO, double> out;
  for (std::size_t e = 0; e < n; ++e) out[c(e)] += v(e);
  if (!zeros)
    for (auto it = out.begin(); it != out.end();) it = it->second == 0.0 ? out.erase(it) : ++it;
  return out;
}

// K̃ entry by entry against the reference product Tᵀ J T (Tpetra's MultiplyRAP, T from the
// reduction): on the kept rows the same values to round-off (an entry missing in one of them
// counts as 0: the two sums differ in order, and an entry that is 0 in exact arithmetic may
// be an exact zero, dropped, in one and 1e-18 of the largest in the other); the product's
// rows of the eliminated dofs are empty, K̃'s hold a nonzero diagonal and explicit zeros.
void check_against_product(int dim, ContactKind type, const std::string& label) {
  Case mc;
  build(mc, dim, type, 0.0, ContactGeometry::reference);
  SymmetricCondensation reduction(mc.pairing, dim);
  ASSERT_TRUE(reduction.condense(*mc.J, *mc.b)) << label << ": " << reduction.reason();
  const auto T = reduction.transformation();
  const auto A = reduction.matrix();
  Matrix product(A->getRowMap(), 0);
  Tpetra::TripleMatrixMultiply::MultiplyRAP(*T, true, *mc.J, false, *T, false, product);
  // difference, largest |product|; entries in one pattern only, eliminated rows, their bad
  // entries
  double local[2] = {0.0, 0.0}, all[2] = {0.0, 0.0};
  int counts[3] = {0, 0, 0}, counts_all[3] = {0, 0, 0};
  const auto& rows = *A->getRowMap();
  for (LO i = 0; i < LO(rows.getNodeNumElements()); ++i) {
    const GO g = rows.getGlobalElement(i);
    const auto p = global_row(product, g, false);
    const auto a = global_row(*A, g, true);
    if (p.empty()) {
      ++counts[1];
      for (const auto& [c, v] : a) counts[2] += c == g ? v == 0.0 : v != 0.0;
      counts[2] += a.count(g) == 0;
      continue;
    }
    for (const auto& [c, v] : p) {
      local[1] = std::max(local[1], std::abs(v));
      const auto it = a.find(c);
      counts[0] += it == a.end();
      local[0] = std::max(local[0], std::abs((it == a.end() ? 0.0 : it->second) - v));
    }
    for (const auto& [c, v] : a)
      if (p.count(c) == 0) ++counts[0], local[0] = std::max(local[0], std::abs(v));
  }
  const auto& comm = *rows.getComm();
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 2, local, all);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 3, counts, counts_all);
  EXPECT_GT(all[1], 0.0) << label;
  EXPECT_LE(all[0], 1e-14 * all[1]) << label;
  EXPECT_EQ(counts_all[1], reduction.statistics().eliminated) << label;
  EXPECT_EQ(counts_all[2], 0) << label << ": eliminated rows";
  if (rows.getComm()->getRank() == 0)
    std::printf(
        "[symmetric] %s: K~ vs T^T J T: max |difference| %.3g of max %.3g, %d entries in one "
        "pattern only, %d eliminated\n",
        label.c_str(), all[0], all[1], counts_all[0], counts_all[1]);
}

TEST(SymmetricCondensation, EqualsTheTripleProduct) {
  for (int dim : {2, 3}) {
    check_against_product(dim, ContactKind::frictionless, std::to_string(dim) + "D frictionless");
    check_against_product(dim, ContactKind::tied, std::to_string(dim) + "D tied");
  }
}

// reuse_preconditioner on the iterative path: a Jacobian equal to the last one value for value
// (small strain, an unchanged active set: the next Newton iteration, the next load step's
// first) keeps the whole MueLu hierarchy, no set-up, and gives the same answer bit for bit;
// one with other values (the symmetric reduction declines a scaled, non-symmetric J: the
// condensation, other unknowns) builds a new one.
TEST(SymmetricCondensation, IterativePathKeepsTheHierarchyForTheSameSystem) {
  Case mc;
  build(mc, 3, ContactKind::frictionless, 0.0, ContactGeometry::reference, 2);
  const auto map = mc.J->getRowMap();
  Teuchos::ParameterList p = params("belos", true);
  p.set("reuse_preconditioner", true);
  p.sublist("MueLu").set("coarse: max size", 50);  // a multilevel hierarchy
  LinearSolver solver(p, "test", pairing_layout(mc.pairing, 3));
  Vector x1(map), x2(map), x_full(map);
  LinearSolver full(params("amesos2", false), "test", {});
  full.solve(mc.J, *mc.b, x_full);
  const int first = solver.solve(mc.J, *mc.b, x1);
  EXPECT_TRUE(solver.last_solve_symmetric());
  EXPECT_EQ(solver.kept_hierarchies(), 0);
  const auto J_copy = Teuchos::rcp(new Matrix(*mc.J, Teuchos::Copy));
  const int second = solver.solve(J_copy, *mc.b, x2);
  EXPECT_EQ(solver.reused_hierarchies(), 1);
  EXPECT_EQ(solver.kept_hierarchies(), 1);
  EXPECT_EQ(first, second);
  Vector d(map);
  d.update(1.0, x1, -1.0, x2, 0.0);
  EXPECT_EQ(d.normInf(), 0.0);
  EXPECT_LT(relative_difference(x2, x_full, mc.n_u, false), 1e-9);
  EXPECT_LT(relative_difference(x2, x_full, mc.n_u, true), 1e-9);
}

// The default (reuse_preconditioner not given) on the symmetric reduction: the next system,
// from another state (other multipliers, so other contact rows in K~: the pattern may change
// too, which RAP reuse allows), keeps the last hierarchy's coarse levels (MueLu `reuse: type:
// RAP`) and rebuilds the fine smoother only. CG still solves it to its tolerance: the answer
// is the direct solver's. The 33 k-node hemispheres' Newton iterations, whose active sets
// grow from 145 to 519 nodes, are measured in docs/performance.md ("Iterative solver").
TEST(SymmetricCondensation, IterativePathKeepsTheCoarseLevelsForAnotherActiveSet) {
  Case mc, next;
  build(mc, 3, ContactKind::frictionless, 0.0, ContactGeometry::reference, 2);
  build(next, 3, ContactKind::frictionless, 0.0, ContactGeometry::reference, 2, 11u);
  Teuchos::ParameterList p = params("belos", true);
  p.sublist("MueLu").set("coarse: max size", 50);  // a multilevel hierarchy
  LinearSolver solver(p, "test", elastic_layout(mc.pairing, mc.mesh));
  Vector x1(mc.J->getRowMap()), x2(next.J->getRowMap()), x_full(next.J->getRowMap());
  const int first = solver.solve(mc.J, *mc.b, x1);
  ASSERT_TRUE(solver.last_solve_symmetric());
  EXPECT_EQ(solver.reused_hierarchies(), 0);
  // The default smoother on K~ (no multipliers): damped Jacobi (nonlinear/jacobi_smoother.hpp).
  EXPECT_GT(solver.jacobi_damping(), 0.0);
  EXPECT_LT(solver.jacobi_damping(), 1.0);
  const int second = solver.solve(next.J, *next.b, x2);
  ASSERT_TRUE(solver.last_solve_symmetric());
  EXPECT_EQ(solver.reused_hierarchies(), 1);
  EXPECT_EQ(solver.kept_hierarchies(), 0);  // other values: the fine smoother rebuilt
  EXPECT_LE(second, 2 * first + 10);        // within the rebuild rule (iterative_plugin.cpp)
  LinearSolver full(params("amesos2", false), "test", {});
  full.solve(next.J, *next.b, x_full);
  EXPECT_LT(relative_difference(x2, x_full, next.n_u, false), 1e-9);
  EXPECT_LT(relative_difference(x2, x_full, next.n_u, true), 1e-9);
  // reuse_preconditioner: false builds a new hierarchy every solve.
  p.set("reuse_preconditioner", false);
  LinearSolver fresh(p, "test", elastic_layout(mc.pairing, mc.mesh));
  fresh.solve(mc.J, *mc.b, x1);
  const int fresh_second = fresh.solve(next.J, *next.b, x2);
  EXPECT_EQ(fresh.reused_hierarchies(), 0);
  // A smoother of the user's replaces the Jacobi default; the answer stays the direct one.
  p.sublist("MueLu").set("smoother: type", "RELAXATION");
  p.sublist("MueLu").sublist("smoother: params").set("relaxation: type", "Symmetric Gauss-Seidel");
  LinearSolver chosen(p, "test", elastic_layout(mc.pairing, mc.mesh));
  chosen.solve(next.J, *next.b, x2);
  EXPECT_EQ(chosen.jacobi_damping(), 0.0);
  EXPECT_LT(relative_difference(x2, x_full, next.n_u, false), 1e-9);
  if (Tpetra::getDefaultComm()->getRank() == 0)
    std::printf(
        "[iterations] active sets %d, %d; CG %d, then %d with the coarse levels kept, "
        "%d fresh\n",
        int(mc.active), int(next.active), first, second, fresh_second);
}

// `near_null_space: translations`: MueLu's aggregates carry the three translations only (half
// the prolongator's columns in 3D); CG on K~ still reaches the direct answer, in another number
// of iterations than with the rotations (the option reaches the module).
TEST(SymmetricCondensation, IterativePathWithTranslationsOnly) {
  Case mc;
  build(mc, 3, ContactKind::frictionless, 0.0, ContactGeometry::reference, 2);
  Teuchos::ParameterList p = params("belos", true);
  p.sublist("MueLu").set("coarse: max size", 50);  // a multilevel hierarchy
  const auto map = mc.J->getRowMap();
  Vector x_rigid(map), x_translations(map), x_full(map);
  LinearSolver rigid(p, "test", elastic_layout(mc.pairing, mc.mesh));
  const int with_rotations = rigid.solve(mc.J, *mc.b, x_rigid);
  p.set("near_null_space", "translations");
  LinearSolver translations(p, "test", elastic_layout(mc.pairing, mc.mesh));
  const int without = translations.solve(mc.J, *mc.b, x_translations);
  ASSERT_TRUE(translations.last_solve_symmetric());
  EXPECT_NE(without, with_rotations);
  LinearSolver full(params("amesos2", false), "test", {});
  full.solve(mc.J, *mc.b, x_full);
  EXPECT_LT(relative_difference(x_translations, x_full, mc.n_u, false), 1e-9);
  EXPECT_LT(relative_difference(x_translations, x_full, mc.n_u, true), 1e-9);
  if (Tpetra::getDefaultComm()->getRank() == 0)
    std::printf("[iterations] CG %d with the rotations, %d with the translations only\n",
                with_rotations, without);
}

TEST(SymmetricCondensation, Frictionless2D) {
  check_applies(2, ContactKind::frictionless, "2D frictionless");
}
TEST(SymmetricCondensation, Frictionless3D) {
  check_applies(3, ContactKind::frictionless, "3D frictionless");
  check_applies(3, ContactKind::frictionless, "3D frictionless, refined x2", 2);
}
TEST(SymmetricCondensation, Tied2D) {
  check_applies(2, ContactKind::tied, "2D tied");
}
TEST(SymmetricCondensation, Tied3D) {
  check_applies(3, ContactKind::tied, "3D tied");
}

TEST(SymmetricCondensation, DeclinesOnFrictionAndCurrentGeometry) {
  for (int dim : {2, 3}) {
    Case frictional, current;
    build(frictional, dim, ContactKind::frictional, 0.3, ContactGeometry::current);
    check_declines(frictional, dim, std::to_string(dim) + "D frictional, current geometry");
    build(current, dim, ContactKind::frictionless, 0.0, ContactGeometry::current);
    check_declines(current, dim, std::to_string(dim) + "D frictionless, current geometry");
  }
}

// One off-diagonal stiffness entry K(i, j) of a free dof scaled by 1 + 1e-6: not symmetric.
TEST(SymmetricCondensation, DeclinesOnANonSymmetricStiffness) {
  Case mc;
  build(mc, 3, ContactKind::frictionless, 0.0, ContactGeometry::reference);
  const GO row = mc.n_u / 2;  // a dof in the middle of the mesh
  mc.J->resumeFill();
  if (mc.J->getRowMap()->isNodeGlobalElement(row)) {
    typename Matrix::nonconst_global_inds_host_view_type cols("c",
                                                              mc.J->getNumEntriesInGlobalRow(row));
    typename Matrix::nonconst_values_host_view_type vals("v", cols.extent(0));
    std::size_t n = 0;
    mc.J->getGlobalRowCopy(row, cols, vals, n);
    for (std::size_t e = 0; e < n; ++e)
      if (cols(e) != row && vals(e) != 0.0 && cols(e) < mc.n_u) {
        const GO c = cols(e);
        const double v = vals(e) * (1.0 + 1e-6);
        mc.J->replaceGlobalValues(row, Teuchos::ArrayView<const GO>(&c, 1),
                                  Teuchos::ArrayView<const double>(&v, 1));
        break;
      }
  }
  mc.J->fillComplete(mc.J->getDomainMap(), mc.J->getRangeMap());
  check_declines(mc, 3, "3D frictionless with one K entry off by 1e-6");
}

// The same across the ranks (2 ranks): rank 0 scales one entry K(i, j) whose column j is a
// displacement dof another rank owns, so that K(j, i) lies on that rank only. check_symmetric
// sends each rank's ghost-column entries to the column's owner; a mirror lost on the way
// would pass the perturbed K.
TEST(SymmetricCondensation, DeclinesOnAStiffnessNonSymmetricAcrossTheRanks) {
  Case mc;
  build(mc, 3, ContactKind::frictionless, 0.0, ContactGeometry::reference);
  const auto comm = mc.J->getRowMap()->getComm();
  if (comm->getSize() == 1) GTEST_SKIP() << "needs a second rank";
  const auto& row_map = *mc.J->getRowMap();
  // Rank 0's largest such entry (a small one, scaled, could stay within the tolerance, which
  // is relative to its row's largest entry).
  int changed = 0;
  GO best_row = -1, best_col = -1;
  double best = 0.0;
  if (comm->getRank() == 0) {
    for (LO i = 0; i < LO(row_map.getNodeNumElements()); ++i) {
      const GO row = row_map.getGlobalElement(i);
      if (row >= mc.n_u) continue;
      typename Matrix::nonconst_global_inds_host_view_type cols(
          "c", mc.J->getNumEntriesInGlobalRow(row));
      typename Matrix::nonconst_values_host_view_type vals("v", cols.extent(0));
      std::size_t n = 0;
      mc.J->getGlobalRowCopy(row, cols, vals, n);
      for (std::size_t e = 0; e < n; ++e)
        if (cols(e) < mc.n_u && !row_map.isNodeGlobalElement(cols(e)) &&
            std::abs(vals(e)) > std::abs(best))
          best_row = row, best_col = cols(e), best = vals(e);
    }
  }
  mc.J->resumeFill();
  if (best_row >= 0) {
    const double v = best * (1.0 + 1e-6);
    mc.J->replaceGlobalValues(best_row, Teuchos::ArrayView<const GO>(&best_col, 1),
                              Teuchos::ArrayView<const double>(&v, 1));
    changed = 1;
  }
  mc.J->fillComplete(mc.J->getDomainMap(), mc.J->getRangeMap());
  int anywhere = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, changed, Teuchos::outArg(anywhere));
  ASSERT_EQ(anywhere, 1) << "rank 0 has no entry in another rank's displacement column";
  check_declines(mc, 3, "3D frictionless with one K entry across the ranks off by 1e-6");
}

// The multiplier columns of the master rows scaled by 1 + 1e-6: C N is no longer a multiple
// of the constraint rows' Gᵀ (the multiplier would not act along the gap's gradient).
TEST(SymmetricCondensation, DeclinesWhenTheMultiplierColumnsAreNotTheConstraintGradients) {
  Case mc;
  build(mc, 3, ContactKind::frictionless, 0.0, ContactGeometry::reference);
  std::set<GO> slave_dofs;
  for (const auto& [t, s] : mc.pairing) slave_dofs.insert(s);
  mc.J->resumeFill();
  const auto& rows = *mc.J->getRowMap();
  for (LO i = 0; i < LO(rows.getNodeNumElements()); ++i) {
    const GO row = rows.getGlobalElement(i);
    if (row >= mc.n_u || slave_dofs.count(row)) continue;
    typename Matrix::nonconst_global_inds_host_view_type cols("c",
                                                              mc.J->getNumEntriesInGlobalRow(row));
    typename Matrix::nonconst_values_host_view_type vals("v", cols.extent(0));
    std::size_t n = 0;
    mc.J->getGlobalRowCopy(row, cols, vals, n);
    for (std::size_t e = 0; e < n; ++e)
      if (cols(e) >= mc.n_u) {
        const GO c = cols(e);
        const double v = vals(e) * (1.0 + 1e-6);
        mc.J->replaceGlobalValues(row, Teuchos::ArrayView<const GO>(&c, 1),
                                  Teuchos::ArrayView<const double>(&v, 1));
      }
  }
  mc.J->fillComplete(mc.J->getDomainMap(), mc.J->getRangeMap());
  check_declines(mc, 3, "3D frictionless with the master multiplier columns off by 1e-6");
}

}  // namespace
}  // namespace grout
