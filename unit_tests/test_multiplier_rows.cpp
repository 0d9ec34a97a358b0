// The multiplier rows as the contact interface declares them (nonlinear/multiplier_rows.hpp)
// against the structure of the Jacobian it assembles, on grout_mesh's two-block contact meshes
// in 2D and 3D, frictionless, tied and frictional, reference and current geometry, 1 and 2
// ranks: an identity row holds only its diagonal, a pure-λ row no displacement, a constraint
// row no multiplier, and a mixed row both (Coulomb slip, τ·λ on the current geometry); the
// condensations built from the declarations give the same solution as the ones that read J;
// a declaration J contradicts is refused. Also: the active set's start rules depend on the
// Newton iterate given (MechanicsProblem::set_newton_iterate), not on whether jacobian() was
// called in between.

#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <cmath>
#include <random>

#include "assembly/solid_problem.hpp"
#include "io/mesh_generators.hpp"
#include "nonlinear/condensed_solve.hpp"
#include "nonlinear/mechanics_problem.hpp"
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
  Teuchos::RCP<Vector> x, F, b;
  GO n_u = 0;
};

// J and −F at a perturbed state with open, closed and (frictional) sliding slave nodes.
void build(Case& mc, int dim, ContactKind type, double mu, ContactGeometry geometry) {
  const auto comm = Tpetra::getDefaultComm();
  mc.mesh = dim == 2 ? two_block_mesh_2d(3, 2, 4, 2) : two_block_mesh_3d(2, 2, 1, 3, 2, 1);
  mc.input = two_block_input(dim, type, mu, geometry);
  mc.solid = std::make_unique<SolidProblem>(mc.mesh, mc.input, comm);
  mc.problem = std::make_unique<MechanicsProblem>(*mc.solid, mc.mesh, mc.input);
  MechanicsProblem& problem = *mc.problem;
  mc.x = Teuchos::rcp(new Vector(problem.map()));
  mc.F = Teuchos::rcp(new Vector(problem.map()));
  mc.n_u = GO(mc.mesh.num_nodes()) * dim;
  {
    auto xv = mc.x->getLocalViewHost(Tpetra::Access::OverwriteAll);
    std::uniform_real_distribution<double> r(-1.0, 1.0);
    for (std::size_t i = 0; i < problem.map()->getNodeNumElements(); ++i) {
      const GO g = problem.map()->getGlobalElement(LO(i));
      std::mt19937 local(unsigned(g) * 7919u + 5u);  // same value on any rank count
      const double v = r(local);
      xv(i, 0) = g < mc.n_u ? 1e-3 * v : (g - mc.n_u) % dim == dim - 1 ? -2.0 * v - 0.5 : v;
    }
  }
  problem.begin_step(1.0, *mc.x);
  problem.set_newton_iterate(2);  // past the start rules: the law alone decides
  ASSERT_TRUE(problem.residual(*mc.x, *mc.F));
  ASSERT_TRUE(problem.jacobian(*mc.x, mc.J));
  mc.b = Teuchos::rcp(new Vector(problem.map()));
  mc.b->update(-1.0, *mc.F, 0.0);
}

struct Counts {
  int identity = 0, pure_lambda = 0, constraint = 0, mixed = 0;
};

// Every declared row against J's row; the counts of each kind (this rank's).
Counts check_declared(const Case& mc) {
  const MultiplierRows* rows = mc.problem->multiplier_rows();
  Counts counts;
  EXPECT_NE(rows, nullptr);
  if (!rows) return counts;
  const Map& map = *mc.J->getRowMap();
  EXPECT_EQ(rows->gids.size(),
            map.getNodeNumElements() - mc.solid->owned_map()->getNodeNumElements());
  for (std::size_t k = 0; k < rows->gids.size(); ++k) {
    const GO g = rows->gids[k];
    const LO i = map.getLocalElement(g);
    EXPECT_GE(i, 0) << "declared row " << g << " not owned";
    if (i < 0) continue;
    typename Matrix::local_inds_host_view_type cols;
    typename Matrix::values_host_view_type vals;
    mc.J->getLocalRowView(i, cols, vals);
    bool diagonal = false, other_lambda = false, displacement = false;
    for (std::size_t e = 0; e < cols.extent(0); ++e) {
      if (vals(e) == 0.0) continue;  // the stored zero diagonal of a multiplier row
      const GO c = mc.J->getColMap()->getGlobalElement(cols(e));
      if (c == g)
        diagonal = true;
      else if (c >= mc.n_u)
        other_lambda = true;
      else
        displacement = true;
    }
    switch (rows->kinds[k]) {
      case LambdaRow::identity:
        ++counts.identity;
        EXPECT_TRUE(diagonal && !other_lambda && !displacement) << "identity row " << g;
        break;
      case LambdaRow::pure_lambda:
        ++counts.pure_lambda;
        EXPECT_TRUE((diagonal || other_lambda) && !displacement) << "pure-λ row " << g;
        break;
      case LambdaRow::constraint:
        ++counts.constraint;
        EXPECT_TRUE(displacement && !diagonal && !other_lambda) << "constraint row " << g;
        break;
      case LambdaRow::mixed:
        ++counts.mixed;
        EXPECT_TRUE(displacement && (diagonal || other_lambda)) << "mixed row " << g;
        break;
    }
  }
  return counts;
}

Counts summed(const Counts& c) {
  int local[4] = {c.identity, c.pure_lambda, c.constraint, c.mixed}, global[4] = {0, 0, 0, 0};
  Teuchos::reduceAll(*Tpetra::getDefaultComm(), Teuchos::REDUCE_SUM, 4, local, global);
  return {global[0], global[1], global[2], global[3]};
}

// The condensation with and without the declarations: the same reduced system.
void expect_same_condensation(const Case& mc, int dim) {
  const MultiplierPairing pairing = mc.problem->multiplier_pairing();
  MultiplierCondensation declared(pairing, dim), inferred(pairing, dim);
  declared.condense(*mc.J, *mc.b, mc.problem->multiplier_rows());
  inferred.condense(*mc.J, *mc.b);
  EXPECT_EQ(declared.statistics().identity, inferred.statistics().identity);
  EXPECT_EQ(declared.matrix()->getFrobeniusNorm(), inferred.matrix()->getFrobeniusNorm());
  EXPECT_EQ(declared.rhs().norm2(), inferred.rhs().norm2());
}

TEST(MultiplierRows, DeclarationsMatchTheJacobian) {
  struct Setup {
    int dim;
    ContactKind type;
    double mu;
    ContactGeometry geometry;
  };
  const Setup setups[] = {
      {2, ContactKind::frictionless, 0.0, ContactGeometry::reference},
      {2, ContactKind::frictionless, 0.0, ContactGeometry::current},
      {2, ContactKind::frictional, 0.3, ContactGeometry::reference},
      {2, ContactKind::tied, 0.0, ContactGeometry::reference},
      {3, ContactKind::frictionless, 0.0, ContactGeometry::reference},
      {3, ContactKind::frictional, 0.3, ContactGeometry::current},
      {3, ContactKind::tied, 0.0, ContactGeometry::reference},
  };
  for (const Setup& s : setups) {
    SCOPED_TRACE(std::to_string(s.dim) + "D type " + std::to_string(int(s.type)) + " geometry " +
                 std::to_string(int(s.geometry)));
    Case mc;
    build(mc, s.dim, s.type, s.mu, s.geometry);
    const Counts c = summed(check_declared(mc));
    if (s.type == ContactKind::tied) {
      EXPECT_GT(c.constraint, 0);
      EXPECT_EQ(c.mixed, 0);
    } else {
      EXPECT_GT(c.identity, 0);    // open nodes
      EXPECT_GT(c.constraint, 0);  // normal rows of closed nodes
      if (s.type == ContactKind::frictionless && s.geometry == ContactGeometry::reference) {
        EXPECT_EQ(c.mixed, 0);
        EXPECT_GT(c.pure_lambda, 0);
      }
      if (s.type == ContactKind::frictional || s.geometry == ContactGeometry::current) {
        EXPECT_GT(c.mixed, 0);
      }
    }
    expect_same_condensation(mc, s.dim);
    // The symmetric reduction: applies where every row is pure-λ or a constraint.
    SymmetricCondensation symmetric(mc.problem->multiplier_pairing(), s.dim);
    const bool declared = symmetric.condense(*mc.J, *mc.b, mc.problem->multiplier_rows());
    SymmetricCondensation inferred(mc.problem->multiplier_pairing(), s.dim);
    EXPECT_EQ(declared, inferred.condense(*mc.J, *mc.b)) << symmetric.reason();
    EXPECT_EQ(declared, c.mixed == 0) << symmetric.reason();
  }
}

TEST(MultiplierRows, AContradictedDeclarationIsRefused) {
  Case mc;
  build(mc, 2, ContactKind::frictionless, 0.0, ContactGeometry::reference);
  MultiplierRows wrong = *mc.problem->multiplier_rows();
  int changed = 0;
  for (auto& kind : wrong.kinds)
    if (kind == LambdaRow::constraint) kind = LambdaRow::identity, ++changed;
  int any = 0;
  Teuchos::reduceAll(*Tpetra::getDefaultComm(), Teuchos::REDUCE_SUM, changed, Teuchos::outArg(any));
  ASSERT_GT(any, 0);
  MultiplierCondensation condensation(mc.problem->multiplier_pairing(), 2);
  EXPECT_THROW(condensation.condense(*mc.J, *mc.b, &wrong), std::logic_error);
  SymmetricCondensation symmetric(mc.problem->multiplier_pairing(), 2);
  EXPECT_FALSE(symmetric.condense(*mc.J, *mc.b, &wrong));
  EXPECT_NE(symmetric.reason().find("declared"), std::string::npos) << symmetric.reason();
}

// The proximity start rule (a node with no pressure and a gap below start_gap × its face size
// counts as active) holds at the step's initial guess only: the phase comes from the iterate
// given, whatever the calls in between.
TEST(MultiplierRows, StartRulesFollowTheGivenIterate) {
  const auto comm = Tpetra::getDefaultComm();
  Case mc;
  mc.mesh = two_block_mesh_2d(3, 2, 4, 2, false, 1e-3);  // the upper block 1e-3 above
  mc.input = two_block_input(2, ContactKind::frictionless, 0.0, ContactGeometry::reference);
  mc.solid = std::make_unique<SolidProblem>(mc.mesh, mc.input, comm);
  MechanicsProblem problem(*mc.solid, mc.mesh, mc.input);
  Vector x(problem.map()), F(problem.map());
  problem.begin_step(0.0, x);
  ASSERT_TRUE(problem.residual(x, F));
  const int at_start = problem.active_set_size();
  Teuchos::RCP<Matrix> J;
  ASSERT_TRUE(problem.jacobian(x, J));
  ASSERT_TRUE(problem.residual(x, F));
  EXPECT_EQ(problem.active_set_size(), at_start);  // still iterate 0: jacobian() changed nothing
  problem.set_newton_iterate(1);
  ASSERT_TRUE(problem.residual(x, F));
  EXPECT_EQ(problem.active_set_size(), 0);  // open: the gap alone decides
  problem.set_newton_iterate(0);
  ASSERT_TRUE(problem.residual(x, F));
  EXPECT_EQ(problem.active_set_size(), at_start);
  EXPECT_GT(at_start, 0);
}

}  // namespace
}  // namespace grout
