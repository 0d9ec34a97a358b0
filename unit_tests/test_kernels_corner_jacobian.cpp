// min_corner_det_F: det F at the corners of a folded element against determinants computed by
// hand from its edges, where the Gauss points stay positive.

#include <gtest/gtest.h>

#include <cmath>

#include "kernels/corner_jacobian.hpp"
#include "kernels/element_jacobian.hpp"
#include "kernels/linear_elastic.hpp"

namespace grout {
namespace {

TEST(CornerJacobian, FoldedQuadCornerWhileGaussPointsArePositive) {
  // Unit square; node 2 pushed from (1, 1) to (0.4, 0.4). At corner a the bilinear map has
  // det J = ¼ (e_ξ × e_η) with its edges: corner 2: e_ξ = x2 − x3 = (0.4, −0.6),
  // e_η = x2 − x1 = (−0.6, 0.4): det J = ¼ (0.16 − 0.36) = −0.05, against ¼ before:
  // det F = −0.2. det J is linear in ξ, η: 0.1 − 0.075 (ξ + η), 0.013 at the Gauss point
  // (1/√3, 1/√3), so the 2x2 rule sees nothing wrong.
  const double X[8] = {0, 0, 1, 0, 1, 1, 0, 1};
  const double x[8] = {0, 0, 1, 0, 0.4, 0.4, 0, 1};
  int corner = -1;
  EXPECT_NEAR(min_corner_det_F(Topology::quad4, 2, X, x, corner), -0.2, 1e-14);
  EXPECT_EQ(corner, 2);
  double det_gauss = 0.0;
  ASSERT_TRUE(min_jacobian_determinant(Topology::quad4, 2, x,
                                       full_integration_degree(Topology::quad4), det_gauss));
  EXPECT_NEAR(det_gauss, 0.1 - 0.15 / std::sqrt(3.0), 1e-14);
  EXPECT_GT(det_gauss, 0.0);
}

TEST(CornerJacobian, RigidMotionAndStretchOfAHex) {
  // det F = 1 under a rotation about z, and λ1 λ2 λ3 under a uniform stretch, at every corner.
  const double X[24] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  double x[24];
  const double c = std::cos(0.7), s = std::sin(0.7);
  for (int a = 0; a < 8; ++a) {
    x[3 * a] = c * X[3 * a] - s * X[3 * a + 1];
    x[3 * a + 1] = s * X[3 * a] + c * X[3 * a + 1];
    x[3 * a + 2] = X[3 * a + 2];
  }
  int corner = -1;
  EXPECT_NEAR(min_corner_det_F(Topology::hex8, 3, X, x, corner), 1.0, 1e-14);
  for (int a = 0; a < 8; ++a)
    for (int d = 0; d < 3; ++d) x[3 * a + d] = X[3 * a + d] * (d == 0 ? 2.0 : d == 1 ? 0.5 : 3.0);
  EXPECT_NEAR(min_corner_det_F(Topology::hex8, 3, X, x, corner), 3.0, 1e-14);
}

TEST(CornerJacobian, LinearElementsHaveOneDeterminant) {
  const double X[6] = {0, 0, 1, 0, 0, 1};
  const double x[6] = {0, 0, 1, 0, 0.5, -1};  // node 2 moved through edge 0-1: inverted
  int corner = -1;
  EXPECT_NEAR(min_corner_det_F(Topology::tri3, 2, X, x, corner), -1.0, 1e-14);
  EXPECT_EQ(corner, 0);
}

}  // namespace
}  // namespace grout
