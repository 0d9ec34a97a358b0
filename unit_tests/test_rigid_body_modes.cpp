// rigid_body_modes (nonlinear/elasticity_preconditioner.hpp), MueLu's near-null space for
// elasticity: on a few 3D nodes, on 1 and 2 ranks, the six modes are the translations and the
// rotations about the centroid, K·mode = 0 checked by their definition (u = e_c, and
// u = e_k × (x − c)); `translations_only` keeps the first three columns, unchanged.

#include <gtest/gtest.h>

#include <Teuchos_DefaultComm.hpp>
#include <vector>

#include "nonlinear/elasticity_preconditioner.hpp"

namespace grout {
namespace {

constexpr int kDim = 3;
constexpr GO kNodesPerRank = 4;

TEST(RigidBodyModes, TranslationsOnlyAreTheFirstThreeModes) {
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const GO n_nodes = kNodesPerRank * comm->getSize();
  std::vector<double> coordinates;  // every node, replicated
  for (GO n = 0; n < n_nodes; ++n)
    coordinates.insert(coordinates.end(), {double(n), 0.5 * double(n * n), 1.0 - double(n % 3)});
  const Map map(GO(n_nodes * kDim), std::size_t(kNodesPerRank * kDim), 0, comm);
  const auto all = rigid_body_modes(map, kDim, coordinates);
  const auto translations = rigid_body_modes(map, kDim, coordinates, nullptr, true);
  ASSERT_EQ(all->getNumVectors(), std::size_t(6));
  ASSERT_EQ(translations->getNumVectors(), std::size_t(kDim));
  double centre[kDim] = {0.0, 0.0, 0.0};
  for (GO n = 0; n < n_nodes; ++n)
    for (int d = 0; d < kDim; ++d) centre[d] += coordinates[std::size_t(n * kDim + d)] / n_nodes;
  const auto a = all->getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto t = translations->getLocalViewHost(Tpetra::Access::ReadOnly);
  for (LO i = 0; i < LO(map.getNodeNumElements()); ++i) {
    const GO g = map.getGlobalElement(i);
    const int c = int(g % kDim);
    const double* x = &coordinates[std::size_t(g / kDim * kDim)];
    for (int k = 0; k < kDim; ++k) {
      EXPECT_EQ(t(i, k), c == k ? 1.0 : 0.0) << "dof " << g << ", translation " << k;
      EXPECT_EQ(t(i, k), a(i, k));
    }
    // Rotation about axis k: (e_k × r)_c with r = x − centre.
    const double r[kDim] = {x[0] - centre[0], x[1] - centre[1], x[2] - centre[2]};
    for (int k = 0; k < kDim; ++k) {
      const int k1 = (k + 1) % kDim, k2 = (k + 2) % kDim;
      const double expected = c == k1 ? -r[k2] : c == k2 ? r[k1] : 0.0;
      EXPECT_NEAR(a(i, kDim + k), expected, 1e-12) << "dof " << g << ", rotation " << k;
    }
  }
}

}  // namespace
}  // namespace grout
