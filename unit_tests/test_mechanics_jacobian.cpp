// The Jacobian of the mechanics problem with frictionless and Coulomb frictional contact on
// the current geometry (all linearisation terms: normals, tangents, D, M, projections, the
// slip increment and the stick/slip NCP rows) against central finite differences of the
// residual, in 2D and 3D, on 1 and 2 ranks; with small-strain solids and with finite-strain
// (total-Lagrangian Neo-Hookean) solids under a large homogeneous deformation of both bodies.

#include <gtest/gtest.h>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>
#include <array>
#include <cmath>
#include <map>
#include <random>

#include "assembly/solid_problem.hpp"
#include "io/mesh_generators.hpp"
#include "nonlinear/mechanics_problem.hpp"
#include "unit_tests/two_block_contact_input.hpp"

namespace grout {
namespace {

Input contact_input(int dim, ContactKind type, double mu, StrainKind strain) {
  return two_block_bodies(dim, type, mu, ContactGeometry::current, strain);
}

// Random displacements that press the upper body into the lower one (so most slave nodes
// are active) and random multipliers; with `finite`, plus u = (F - I) X for both bodies with
// F = [[1.2, 0.3, 0], [-0.1, 0.9, 0], [0, 0, 1]] (stretch, shear and a rotation of the
// interface by about 6 degrees: finite strains, rotated normals, the same pairs).
void random_state(const MechanicsProblem& problem, const Mesh& mesh, Vector& x, unsigned seed,
                  bool finite = false) {
  const double F_minus_I[3][3] = {{0.2, 0.3, 0.0}, {-0.1, -0.1, 0.0}, {0.0, 0.0, 0.0}};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  const int dim = mesh.dimension;
  const auto& map = *problem.map();
  auto xv = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
  const GO n_u = GO(mesh.num_nodes()) * dim;
  for (std::size_t i = 0; i < map.getNodeNumElements(); ++i) {
    const GO g = map.getGlobalElement(LO(i));
    std::mt19937 local(unsigned(g) * 7919u + seed);  // same value on any rank count
    const double v = r(local);
    if (g < n_u) {
      const GO node = g / dim;
      const bool upper_axis = g % dim == dim - 1;
      const double height = mesh.coordinates[node * dim + dim - 1];
      xv(i, 0) = 0.01 * v - (upper_axis && height > 0.99 ? 0.01 : 0.0);
      if (finite)
        for (int J = 0; J < dim; ++J)
          xv(i, 0) += F_minus_I[g % dim][J] * mesh.coordinates[node * dim + J];
    } else {
      xv(i, 0) = 5.0 + v;  // compressive multipliers
    }
  }
  (void)rng;
}

/// Checks the Jacobian; returns the number of stick (1) and slip (2) slave nodes.
/// With `committed`, a first state (another seed) is accepted (commit_step) before: the slip
/// increment is then measured from a deformed state (the objective slip's D_n, M_n).
std::array<int, 3> check_jacobian(int dim, ContactKind type = ContactKind::frictionless,
                                  double mu = 0.0, StrainKind strain = StrainKind::small,
                                  bool committed = false) {
  const bool finite = strain == StrainKind::finite;
  const auto comm = Tpetra::getDefaultComm();
  const Mesh mesh = dim == 2 ? two_block_mesh_2d(3, 2, 4, 2) : two_block_mesh_3d(2, 2, 1, 3, 2, 1);
  const Input input = contact_input(dim, type, mu, strain);
  const SolidProblem solid(mesh, input, comm);
  MechanicsProblem problem(solid, mesh, input);
  Vector x(problem.map()), F(problem.map()), Fp(problem.map()), Fm(problem.map());
  Vector dx(problem.map()), JdX(problem.map()), xp(problem.map()), xm(problem.map());
  if (committed) {
    random_state(problem, mesh, x, 7, finite);
    EXPECT_TRUE(problem.residual(x, F));
    problem.commit_step();
  }
  random_state(problem, mesh, x, 3, finite);
  EXPECT_TRUE(problem.residual(x, F));
  const int active = problem.active_set_size();
  EXPECT_GT(active, 0);
  const ContactFields fields = problem.contact_fields();
  std::array<int, 3> status{0, 0, 0};
  for (double st : fields.status) ++status[int(st)];  // this rank's slave nodes
  std::array<int, 3> local = status;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 3, local.data(), status.data());
  Teuchos::RCP<Matrix> J;
  EXPECT_TRUE(problem.jacobian(x, J));
  random_state(problem, mesh, dx, 11);
  const double h = 1e-7;
  xp.update(1.0, x, h, dx, 0.0);
  xm.update(1.0, x, -h, dx, 0.0);
  EXPECT_TRUE(problem.residual(xp, Fp));
  EXPECT_EQ(problem.active_set_changes(), 0);
  EXPECT_TRUE(problem.residual(xm, Fm));
  EXPECT_EQ(problem.active_set_changes(), 0);
  EXPECT_EQ(problem.active_set_size(), active);
  J->apply(dx, JdX);
  Fp.update(-1.0 / (2 * h), Fm, 1.0 / (2 * h));  // central difference
  Fp.update(-1.0, JdX, 1.0);
  EXPECT_LT(Fp.norm2() / JdX.norm2(), 1e-6) << "|J dx - FD| / |J dx|";
  return status;
}

TEST(MechanicsJacobian, MatchesFiniteDifferences2D) {
  check_jacobian(2);
}
TEST(MechanicsJacobian, MatchesFiniteDifferences3D) {
  check_jacobian(3);
}

// μ small: active nodes slip; μ large: active nodes stick.
TEST(MechanicsJacobian, FrictionalSlipMatchesFiniteDifferences2D) {
  EXPECT_GT(check_jacobian(2, ContactKind::frictional, 0.3)[2], 0);
}
TEST(MechanicsJacobian, FrictionalStickMatchesFiniteDifferences2D) {
  EXPECT_GT(check_jacobian(2, ContactKind::frictional, 1e3)[1], 0);
}
TEST(MechanicsJacobian, FrictionalSlipMatchesFiniteDifferences3D) {
  EXPECT_GT(check_jacobian(3, ContactKind::frictional, 0.3)[2], 0);
}
TEST(MechanicsJacobian, FrictionalStickMatchesFiniteDifferences3D) {
  EXPECT_GT(check_jacobian(3, ContactKind::frictional, 1e3)[1], 0);
}

// The objective slip (weighted_slip.hpp) on the current geometry: a rigid motion of a state
// with gaps and finite deformation, after that state was accepted, adds no slip at any
// active slave node (D, M and the relative position of the bodies are unchanged); the
// standard increment τ·(D Δx¹ − M Δx²) would add τ·(R − I) v_n, of the order of the gaps
// (1e-2 here) times the rotation. A rigid shift of the slave body alone along a flat
// interface is a slip of the shift (interior slave nodes, small strain, no deformation).
void check_objective_slip(int dim) {
  const auto comm = Tpetra::getDefaultComm();
  const Mesh mesh = dim == 2 ? two_block_mesh_2d(3, 2, 4, 2) : two_block_mesh_3d(2, 2, 1, 3, 2, 1);
  const Input input = contact_input(dim, ContactKind::frictional, 0.3, StrainKind::finite);
  const SolidProblem solid(mesh, input, comm);
  MechanicsProblem problem(solid, mesh, input);
  Vector x(problem.map()), F(problem.map()), x2(problem.map());
  random_state(problem, mesh, x, 3, true);
  ASSERT_TRUE(problem.residual(x, F));
  problem.commit_step();
  const ContactFields before = problem.contact_fields();
  // x2: u2 = R (X + u) − X + b, λ2 = R λ; R a rotation by 0.5 rad about z (3D: and a tilt).
  const double c = std::cos(0.5), s = std::sin(0.5), c2 = std::cos(0.3), s2 = std::sin(0.3);
  const double Rz[3][3] = {{c, -s, 0.0}, {s, c, 0.0}, {0.0, 0.0, 1.0}};
  const double Rx[3][3] = {{1.0, 0.0, 0.0}, {0.0, c2, -s2}, {0.0, s2, c2}};
  double R[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      R[i][j] = 0.0;
      for (int k = 0; k < 3; ++k) R[i][j] += (dim == 3 ? Rx[i][k] : double(i == k)) * Rz[k][j];
    }
  const double b[3] = {0.3, -0.2, 0.1};
  const auto& map = *problem.map();
  const GO n_u = GO(mesh.num_nodes()) * dim;
  {
    // The owned entries of a node are its dim consecutive dofs (map order): rotate per node.
    const auto xv = x.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto yv = x2.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t i = 0; i < map.getNodeNumElements(); i += dim) {
      const GO g = map.getGlobalElement(LO(i));
      ASSERT_EQ(g % dim, 0);
      double p[3] = {0.0, 0.0, 0.0};
      for (int a = 0; a < dim; ++a)
        p[a] = xv(i + a, 0) + (g < n_u ? mesh.coordinates[(g / dim) * dim + a] : 0.0);
      for (int a = 0; a < dim; ++a) {
        double v = 0.0;
        for (int k = 0; k < dim; ++k) v += R[a][k] * p[k];
        yv(i + a, 0) = g < n_u ? v - mesh.coordinates[(g / dim) * dim + a] + b[a] : v;
      }
    }
  }
  ASSERT_TRUE(problem.residual(x2, F));
  const ContactFields after = problem.contact_fields();
  double largest = 0.0, accumulated = 0.0;
  int active = 0;
  ASSERT_EQ(after.nodes, before.nodes);  // this rank's slave nodes, in the same order
  for (std::size_t n = 0; n < after.nodes.size(); ++n) {
    if (after.status[n] == 0.0) continue;
    ++active;
    for (int a = 0; a < dim; ++a) {
      largest = std::max(largest, std::abs(after.slip[a][n] - before.slip[a][n]));
      accumulated = std::max(accumulated, std::abs(before.slip[a][n]));
    }
  }
  const int local_active = active;
  const double local_max[2] = {largest, accumulated};
  double global_max[2];
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 1, &local_active, &active);
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, 2, local_max, global_max);
  largest = global_max[0];
  accumulated = global_max[1];
  EXPECT_GT(active, 0);
  EXPECT_GT(accumulated, 1e-3) << "the first step slipped";
  EXPECT_LT(largest, 1e-12) << "slip added by a rigid motion";
}

TEST(MechanicsJacobian, ObjectiveSlipUnderRigidMotion2D) {
  check_objective_slip(2);
}
TEST(MechanicsJacobian, ObjectiveSlipUnderRigidMotion3D) {
  check_objective_slip(3);
}

// The same problem on this rank alone (a serial communicator) and distributed over all ranks:
// F and J at the same state agree entry by entry (to 1e-14 relative; on 1 rank trivially).
// On 2 ranks each rank owns part of the slave surface (checked), so this covers the parallel
// search, the slave faces shared by two ranks and the master rows sent to their owners.
void check_distributed_equals_serial(int dim, ContactKind type, double mu,
                                     ContactGeometry geometry) {
  const auto world = Tpetra::getDefaultComm();
  const auto self = world->split(world->getRank(), 0);
  const Mesh mesh = dim == 2 ? two_block_mesh_2d(6, 2, 7, 2) : two_block_mesh_3d(4, 3, 1, 5, 4, 1);
  Input input = contact_input(dim, type, mu, StrainKind::small);
  input.contact[0].geometry = geometry;
  const SolidProblem solid(mesh, input, world), solid_serial(mesh, input, self);
  MechanicsProblem problem(solid, mesh, input), serial(solid_serial, mesh, input);
  Vector x(problem.map()), F(problem.map()), xs(serial.map()), Fs(serial.map());
  random_state(problem, mesh, x, 5);
  random_state(serial, mesh, xs, 5);
  problem.begin_step(1.0, x);
  serial.begin_step(1.0, xs);
  ASSERT_TRUE(problem.residual(x, F));
  ASSERT_TRUE(serial.residual(xs, Fs));
  EXPECT_EQ(problem.active_set_size(), serial.active_set_size());
  EXPECT_GT(problem.active_set_size(), 0);
  Teuchos::RCP<Matrix> J, Js;
  ASSERT_TRUE(problem.jacobian(x, J));
  ASSERT_TRUE(serial.jacobian(xs, Js));

  const auto& map = *problem.map();
  const GO n_u = GO(mesh.num_nodes()) * dim;
  int owned_multipliers = 0;
  const double F_scale = Fs.normInf(), J_scale = Js->getFrobeniusNorm();
  const auto Fv = F.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto Fsv = Fs.getLocalViewHost(Tpetra::Access::ReadOnly);
  double F_diff = 0.0, J_diff = 0.0;
  for (LO i = 0; i < LO(map.getNodeNumElements()); ++i) {
    const GO g = map.getGlobalElement(i);
    owned_multipliers += g >= n_u;
    F_diff = std::max(F_diff, std::abs(Fv(i, 0) - Fsv(serial.map()->getLocalElement(g), 0)));
    std::map<GO, double> row;
    for (const Matrix* A : {J.get(), Js.get()}) {
      const std::size_t n = A->getNumEntriesInGlobalRow(g);
      Teuchos::Array<GO> cols(n);
      Teuchos::Array<double> vals(n);
      std::size_t count = 0;
      A->getGlobalRowCopy(g, cols(), vals(), count);
      for (std::size_t k = 0; k < count; ++k) row[cols[k]] += A == J.get() ? vals[k] : -vals[k];
    }
    for (const auto& [col, d] : row) J_diff = std::max(J_diff, std::abs(d));
  }
  EXPECT_LE(F_diff, 1e-14 * F_scale) << "max |F - F_serial|";
  EXPECT_LE(J_diff, 1e-14 * J_scale) << "max |J - J_serial|";
  EXPECT_GT(owned_multipliers, 0) << "this rank owns no slave node";
}

TEST(MechanicsJacobian, DistributedEqualsSerial2D) {
  check_distributed_equals_serial(2, ContactKind::frictionless, 0.0, ContactGeometry::current);
  check_distributed_equals_serial(2, ContactKind::frictional, 0.3, ContactGeometry::current);
  check_distributed_equals_serial(2, ContactKind::frictionless, 0.0, ContactGeometry::reference);
  check_distributed_equals_serial(2, ContactKind::tied, 0.0, ContactGeometry::reference);
}
TEST(MechanicsJacobian, DistributedEqualsSerial3D) {
  check_distributed_equals_serial(3, ContactKind::frictionless, 0.0, ContactGeometry::current);
  check_distributed_equals_serial(3, ContactKind::frictional, 0.3, ContactGeometry::current);
  check_distributed_equals_serial(3, ContactKind::frictional, 1e3, ContactGeometry::reference);
  check_distributed_equals_serial(3, ContactKind::tied, 0.0, ContactGeometry::reference);
}

// Finite-strain solids (total Lagrangian, Neo-Hookean) with current-geometry contact.
TEST(MechanicsJacobian, FiniteStrainMatchesFiniteDifferences2D) {
  check_jacobian(2, ContactKind::frictionless, 0.0, StrainKind::finite);
}
TEST(MechanicsJacobian, FiniteStrainMatchesFiniteDifferences3D) {
  check_jacobian(3, ContactKind::frictionless, 0.0, StrainKind::finite);
}
TEST(MechanicsJacobian, FiniteStrainFrictionalSlipMatchesFiniteDifferences2D) {
  EXPECT_GT(check_jacobian(2, ContactKind::frictional, 0.3, StrainKind::finite)[2], 0);
}
TEST(MechanicsJacobian, FiniteStrainFrictionalStickMatchesFiniteDifferences2D) {
  EXPECT_GT(check_jacobian(2, ContactKind::frictional, 1e3, StrainKind::finite)[1], 0);
}
TEST(MechanicsJacobian, FiniteStrainFrictionalSlipMatchesFiniteDifferences3D) {
  EXPECT_GT(check_jacobian(3, ContactKind::frictional, 0.3, StrainKind::finite)[2], 0);
}
TEST(MechanicsJacobian, FiniteStrainFrictionalStickMatchesFiniteDifferences3D) {
  EXPECT_GT(check_jacobian(3, ContactKind::frictional, 1e3, StrainKind::finite)[1], 0);
}
// The slip measured from an accepted deformed state (D_n, M_n of that state).
TEST(MechanicsJacobian, FiniteStrainFrictionalAfterCommitMatchesFiniteDifferences) {
  for (int dim : {2, 3}) {
    EXPECT_GT(check_jacobian(dim, ContactKind::frictional, 0.3, StrainKind::finite, true)[2], 0);
    EXPECT_GT(check_jacobian(dim, ContactKind::frictional, 1e3, StrainKind::finite, true)[1], 0);
  }
}

}  // namespace
}  // namespace grout
