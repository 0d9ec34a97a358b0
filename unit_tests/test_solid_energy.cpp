// SolidProblem::stored_energy (the `strain_energy` output of implicit dynamics) against the
// closed-form energy of a homogeneous deformation u = (F − I) X, which the linear elements
// reproduce exactly: Π = W(F) × volume, with W written out here from the laws' definitions
// (Bonet & Wood, Nonlinear Continuum Mechanics for FEA, 2nd ed., §6.4.2–6.4.3):
//   Neo-Hookean  W = μ/2 (I₁ − 3) − μ ln J + λ/2 (ln J)²,
//   St. Venant-Kirchhoff  W = λ/2 (tr E)² + μ E:E,  E = (FᵀF − I)/2,
//   small strain  W = λ/2 (tr ε)² + μ ε:ε,  ε = sym(F − I).
// Under finite strain the stored energy is not ½ uᵀ f_int (the small-strain formula the output
// used before): checked too. Runs on 1 and 2 ranks (every element counted once).

#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <cmath>

#include "assembly/solid_problem.hpp"
#include "io/mesh_generators.hpp"

namespace grout {
namespace {

constexpr double kE = 1000.0, kNu = 0.3;
const double kLambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), kMu = kE / (2 * (1 + kNu));

using Matrix3 = std::array<std::array<double, 3>, 3>;

double det3(const Matrix3& F) {
  return F[0][0] * (F[1][1] * F[2][2] - F[1][2] * F[2][1]) -
         F[0][1] * (F[1][0] * F[2][2] - F[1][2] * F[2][0]) +
         F[0][2] * (F[1][0] * F[2][1] - F[1][1] * F[2][0]);
}

double energy_density(StrainKind strain, MaterialLaw law, const Matrix3& F) {
  if (strain == StrainKind::small) {
    double tr = 0.0, ee = 0.0;
    for (int i = 0; i < 3; ++i) {
      tr += F[i][i] - 1.0;
      for (int j = 0; j < 3; ++j) {
        const double e = 0.5 * (F[i][j] + F[j][i]) - (i == j ? 1.0 : 0.0);
        ee += e * e;
      }
    }
    return 0.5 * kLambda * tr * tr + kMu * ee;
  }
  if (law == MaterialLaw::neo_hookean) {
    double I1 = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) I1 += F[i][j] * F[i][j];
    const double lnJ = std::log(det3(F));
    return 0.5 * kMu * (I1 - 3.0) - kMu * lnJ + 0.5 * kLambda * lnJ * lnJ;
  }
  double tr = 0.0, EE = 0.0;
  for (int I = 0; I < 3; ++I)
    for (int J = 0; J < 3; ++J) {
      double C = 0.0;
      for (int k = 0; k < 3; ++k) C += F[k][I] * F[k][J];
      const double E = 0.5 * (C - (I == J ? 1.0 : 0.0));
      EE += E * E;
      if (I == J) tr += E;
    }
  return 0.5 * kLambda * tr * tr + kMu * EE;
}

struct EnergyCheck {
  double stored, exact, half_u_f;
};

EnergyCheck check(int dim, StrainKind strain, MaterialLaw law) {
  Matrix3 F = {{{1.2, 0.3, 0.0}, {-0.1, 0.9, 0.0}, {0.0, 0.0, 1.0}}};
  if (dim == 3) {
    F[2] = {0.05, 0.1, 1.1};
    F[0][2] = -0.08;
  }
  BoxBounds box;
  box.x1 = 2.0, box.y1 = 1.5, box.z1 = 0.5;
  const Mesh mesh = dim == 2 ? rectangle_mesh(4, 3, 0.0, 2.0, 0.0, 1.5, false, 0.2)
                             : box_mesh(3, 2, 2, box, true, 0.2);
  const double volume = dim == 2 ? 3.0 : 1.5;
  Input input;
  input.file = "test.yaml";
  input.model.dimension = dim;
  input.model.strain = strain;
  MaterialInput m;
  m.name = m.block = "block";
  m.law = law;
  m.youngs_modulus = kE;
  m.poissons_ratio = kNu;
  input.materials.push_back(m);
  const SolidProblem solid(mesh, input, Tpetra::getDefaultComm());
  Vector u(solid.owned_map()), f(solid.owned_map());
  {
    const auto& map = *solid.owned_map();
    auto uv = u.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t i = 0; i < map.getNodeNumElements(); ++i) {
      const GO g = map.getGlobalElement(LO(i));
      const GO node = g / dim;
      const int c = int(g % dim);
      double v = 0.0;
      for (int J = 0; J < dim; ++J)
        v += (F[c][J] - (c == J ? 1.0 : 0.0)) * mesh.coordinates[node * dim + J];
      uv(i, 0) = v;
    }
  }
  EXPECT_TRUE(solid.assemble(u, f, nullptr));
  return {solid.stored_energy(u), energy_density(strain, law, F) * volume, 0.5 * u.dot(f)};
}

TEST(StoredEnergy, SmallStrainIsHalfUTransposeF) {
  for (int dim : {2, 3}) {
    const EnergyCheck e = check(dim, StrainKind::small, MaterialLaw::linear_elastic);
    EXPECT_NEAR(e.stored, e.exact, 1e-12 * e.exact) << dim << "D";
    EXPECT_NEAR(e.stored, e.half_u_f, 1e-12 * e.exact) << dim << "D";
  }
}

TEST(StoredEnergy, FiniteStrainNeoHookean) {
  for (int dim : {2, 3}) {
    const EnergyCheck e = check(dim, StrainKind::finite, MaterialLaw::neo_hookean);
    EXPECT_NEAR(e.stored, e.exact, 1e-12 * e.exact) << dim << "D";
    // ½ uᵀ f_int is not the stored energy at finite strain.
    EXPECT_GT(std::abs(e.half_u_f - e.exact), 1e-3 * e.exact) << dim << "D";
  }
}

TEST(StoredEnergy, FiniteStrainSaintVenantKirchhoff) {
  for (int dim : {2, 3}) {
    const EnergyCheck e = check(dim, StrainKind::finite, MaterialLaw::linear_elastic);
    EXPECT_NEAR(e.stored, e.exact, 1e-12 * e.exact) << dim << "D";
    EXPECT_GT(std::abs(e.half_u_f - e.exact), 1e-3 * e.exact) << dim << "D";
  }
}

}  // namespace
}  // namespace grout
