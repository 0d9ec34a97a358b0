#pragma once
// Quadrature rules on the reference elements of topology.hpp.
//
// Reference elements (the ones shape_functions.hpp is written on):
//   line2 [-1,1];  quad4 [-1,1]^2;  hex8 [-1,1]^3                      (tensor Gauss-Legendre)
//   tri3 {xi,eta >= 0, xi+eta <= 1}, area 1/2                         (symmetric, Dunavant 1985)
//   tet4 {xi,eta,zeta >= 0, xi+eta+zeta <= 1}, volume 1/6             (symmetric, Keast 1986)
// A rule is selected by the polynomial degree it must integrate exactly: total degree for
// simplices, degree per direction for tensor rules. Weights include the reference measure
// (they sum to 2, 4, 8, 1/2, 1/6).

#include "kernels/kernel_macros.hpp"
#include "kernels/topology.hpp"

namespace grout {

constexpr int max_gauss_points_1d = 5;
constexpr int max_quadrature_points =
    max_gauss_points_1d * max_gauss_points_1d * max_gauss_points_1d;

/// One quadrature point: reference coordinates (unused entries 0) and weight.
struct QuadraturePoint {
  double xi[3];
  double weight;
};

/// \brief Point i (0-based) of the n-point Gauss-Legendre rule on [-1,1], exact for degree 2n-1.
/// Abscissae are the roots of P_n, weights 2 / ((1 - x^2) P_n'(x)^2) (Abramowitz & Stegun,
/// table 25.4; values to double precision).
/// \return false if n is not in 1..max_gauss_points_1d or i not in 0..n-1.
GROUT_INLINE_FUNCTION bool gauss_legendre_1d(int n, int i, double& x, double& w) {
  // Rules n = 1..5 stored one after the other; rule n starts at offset n(n-1)/2.
  // clang-format off
  static constexpr double points[15] = {
      0.0,
      -0.5773502691896257, 0.5773502691896257,
      -0.7745966692414834, 0.0, 0.7745966692414834,
      -0.8611363115940526, -0.33998104358485626, 0.33998104358485626, 0.8611363115940526,
      -0.906179845938664, -0.5384693101056831, 0.0, 0.5384693101056831, 0.906179845938664};
  static constexpr double weights[15] = {
      2.0,
      1.0, 1.0,
      5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0,
      0.34785484513745385, 0.6521451548625461, 0.6521451548625461, 0.34785484513745385,
      0.23692688505618908, 0.47862867049936647, 128.0 / 225.0, 0.47862867049936647,
      0.23692688505618908};
  // clang-format on
  if (n < 1 || n > max_gauss_points_1d || i < 0 || i >= n) return false;
  const int k = n * (n - 1) / 2 + i;
  x = points[k];
  w = weights[k];
  return true;
}

/// Points per direction of the tensor Gauss rule exact for degree `degree` per direction
/// (2n - 1 >= degree), 0 if more than max_gauss_points_1d would be needed.
GROUT_INLINE_FUNCTION int gauss_points_per_direction(int degree) {
  const int n = degree < 1 ? 1 : (degree + 2) / 2;
  return n <= max_gauss_points_1d ? n : 0;
}

/// \brief Symmetric triangle rules, Dunavant, "High degree efficient symmetrical Gaussian
/// quadrature rules for the triangle", IJNME 21 (1985), rules of degree 1, 2, 4, 5 (1, 3, 6, 7
/// points; all weights positive). Degree 3 uses the 6-point degree-4 rule to avoid the
/// negative weight of Dunavant's 4-point rule. Closed forms of the degree-4/5 orbits:
/// Strang & Fix (1973), table 4.1; values to double precision.
/// Stored as (xi, eta, w) with weights normalised to sum 1 (multiplied by the area 1/2 in
/// quadrature_point). Rule offsets: degree 1 -> 0, 2 -> 1, 4 -> 4, 5 -> 10.
GROUT_INLINE_FUNCTION int triangle_rule_offset(int degree, int& num_points) {
  num_points = degree <= 1 ? 1 : degree == 2 ? 3 : degree <= 4 ? 6 : degree == 5 ? 7 : 0;
  return degree <= 1 ? 0 : degree == 2 ? 1 : degree <= 4 ? 4 : 10;
}

GROUT_INLINE_FUNCTION void triangle_rule_point(int k, double& xi, double& eta, double& w) {
  constexpr double a2 = 1.0 / 6.0, b2 = 2.0 / 3.0, w2 = 1.0 / 3.0;
  constexpr double a4 = 0.4459484909159649, b4 = 0.10810301816807023, w4a = 0.22338158967801147;
  constexpr double c4 = 0.09157621350977074, d4 = 0.8168475729804585, w4c = 0.10995174365532187;
  constexpr double a5 = 0.4701420641051151, b5 = 0.05971587178976982, w5a = 0.1323941527885062;
  constexpr double c5 = 0.10128650732345634, d5 = 0.7974269853530873, w5c = 0.12593918054482714;
  // clang-format off
  static constexpr double table[17][3] = {
      {1.0 / 3.0, 1.0 / 3.0, 1.0},                                      // degree 1
      {a2, a2, w2}, {b2, a2, w2}, {a2, b2, w2},                         // degree 2
      {a4, a4, w4a}, {b4, a4, w4a}, {a4, b4, w4a},                      // degree 4
      {c4, c4, w4c}, {d4, c4, w4c}, {c4, d4, w4c},
      {1.0 / 3.0, 1.0 / 3.0, 9.0 / 40.0},                               // degree 5
      {a5, a5, w5a}, {b5, a5, w5a}, {a5, b5, w5a},
      {c5, c5, w5c}, {d5, c5, w5c}, {c5, d5, w5c}};
  // clang-format on
  xi = table[k][0];
  eta = table[k][1];
  w = table[k][2];
}

/// \brief Symmetric tetrahedron rules, Keast, "Moderate-degree tetrahedral quadrature
/// formulas", CMAME 55 (1986): degree 1 (centroid), degree 2 (4 points,
/// a = (5 + 3 sqrt 5)/20, b = (5 - sqrt 5)/20), degree 3 (5 points; the centroid weight -4/5 is
/// negative). Stored as (xi, eta, zeta, w), weights normalised to sum 1.
/// Rule offsets: degree 1 -> 0, 2 -> 1, 3 -> 5.
GROUT_INLINE_FUNCTION int tetrahedron_rule_offset(int degree, int& num_points) {
  num_points = degree <= 1 ? 1 : degree == 2 ? 4 : degree == 3 ? 5 : 0;
  return degree <= 1 ? 0 : degree == 2 ? 1 : 5;
}

GROUT_INLINE_FUNCTION void tetrahedron_rule_point(int k, double xi[3], double& w) {
  constexpr double a = 0.5854101966249684, b = 0.1381966011250105;
  constexpr double c = 0.5, d = 1.0 / 6.0;
  // clang-format off
  static constexpr double table[10][4] = {
      {0.25, 0.25, 0.25, 1.0},                                          // degree 1
      {b, b, b, 0.25}, {a, b, b, 0.25}, {b, a, b, 0.25}, {b, b, a, 0.25},  // degree 2
      {0.25, 0.25, 0.25, -0.8},                                         // degree 3
      {d, d, d, 0.45}, {c, d, d, 0.45}, {d, c, d, 0.45}, {d, d, c, 0.45}};
  // clang-format on
  for (int i = 0; i < 3; ++i) xi[i] = table[k][i];
  w = table[k][3];
}

/// Number of points of the rule on topology t exact for polynomials of degree `degree`
/// (see the header comment), 0 if no such rule is tabulated.
GROUT_INLINE_FUNCTION int quadrature_num_points(Topology t, int degree) {
  int n = 0;
  switch (t) {
    case Topology::line2:
      return gauss_points_per_direction(degree);
    case Topology::quad4:
      n = gauss_points_per_direction(degree);
      return n * n;
    case Topology::hex8:
      n = gauss_points_per_direction(degree);
      return n * n * n;
    case Topology::tri3:
      triangle_rule_offset(degree, n);
      return n;
    case Topology::tet4:
      tetrahedron_rule_offset(degree, n);
      return n;
  }
  return 0;
}

/// \brief Point q of the rule quadrature_num_points(t, degree) describes.
/// \pre 0 <= q < quadrature_num_points(t, degree) (otherwise the weight returned is 0).
GROUT_INLINE_FUNCTION QuadraturePoint quadrature_point(Topology t, int degree, int q) {
  QuadraturePoint p{{0.0, 0.0, 0.0}, 0.0};
  const int num_points = quadrature_num_points(t, degree);
  if (q < 0 || q >= num_points) return p;
  int n = 0;
  switch (t) {
    case Topology::line2:
    case Topology::quad4:
    case Topology::hex8: {
      // Tensor product, first direction fastest: q = i + n j + n^2 k.
      n = gauss_points_per_direction(degree);
      const int dim = topology_dimension(t);
      p.weight = 1.0;
      for (int d = 0, rest = q; d < dim; ++d, rest /= n) {
        double w = 0.0;
        gauss_legendre_1d(n, rest % n, p.xi[d], w);
        p.weight *= w;
      }
      break;
    }
    case Topology::tri3: {
      const int offset = triangle_rule_offset(degree, n);
      triangle_rule_point(offset + q, p.xi[0], p.xi[1], p.weight);
      p.weight *= 0.5;
      break;
    }
    case Topology::tet4: {
      const int offset = tetrahedron_rule_offset(degree, n);
      tetrahedron_rule_point(offset + q, p.xi, p.weight);
      p.weight *= 1.0 / 6.0;
      break;
    }
  }
  return p;
}

}  // namespace grout
