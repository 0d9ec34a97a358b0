#pragma once
// Gauss–Legendre rules on the reference line [-1, 1].
//
// \brief  ∫_{-1}^{1} f(ξ) dξ ≈ Σ_{i<n} w_i f(ξ_i), exact for polynomials of degree ≤ 2n − 1
//         (Abramowitz & Stegun, Handbook of Mathematical Functions, table 25.4).
// Points are listed in ascending order; the values were computed by Newton's method on
// P_n in extended precision and rounded to 17 significant digits.

#include "kernels/kernel_macros.hpp"

namespace grout {

constexpr int max_gauss_line_points = 8;  ///< largest tabulated rule

/// \brief Point `i` (0-based, ascending) and weight of the n-point Gauss–Legendre rule.
/// \pre 1 ≤ n ≤ max_gauss_line_points, 0 ≤ i < n.
/// \return false (and ξ = w = 0) if n or i is out of range.
GROUT_INLINE_FUNCTION bool gauss_line_point(int n, int i, double& xi, double& w) {
  // Rule n starts at offset n(n-1)/2 in both tables.
  static constexpr double points[36] = {0.0,  // n = 1
                                        -0.57735026918962576,
                                        0.57735026918962576,  // n = 2
                                        -0.77459666924148338,
                                        0.0,
                                        0.77459666924148338,  // n = 3
                                        -0.86113631159405258,
                                        -0.33998104358485626,
                                        0.33998104358485626,
                                        0.86113631159405258,  // n = 4
                                        -0.90617984593866399,
                                        -0.53846931010568309,
                                        0.0,
                                        0.53846931010568309,
                                        0.90617984593866399,  // n = 5
                                        -0.93246951420315203,
                                        -0.66120938646626451,
                                        -0.23861918608319691,
                                        0.23861918608319691,
                                        0.66120938646626451,
                                        0.93246951420315203,  // n = 6
                                        -0.94910791234275852,
                                        -0.74153118559939444,
                                        -0.40584515137739717,
                                        0.0,
                                        0.40584515137739717,
                                        0.74153118559939444,
                                        0.94910791234275852,  // n = 7
                                        -0.96028985649753623,
                                        -0.79666647741362674,
                                        -0.52553240991632899,
                                        -0.1834346424956498,
                                        0.1834346424956498,
                                        0.52553240991632899,
                                        0.79666647741362674,
                                        0.96028985649753623};  // n = 8
  static constexpr double weights[36] = {2.0,                  // n = 1
                                         1.0,
                                         1.0,  // n = 2
                                         0.55555555555555556,
                                         0.88888888888888889,
                                         0.55555555555555556,  // n = 3
                                         0.34785484513745386,
                                         0.65214515486254614,
                                         0.65214515486254614,
                                         0.34785484513745386,  // n = 4
                                         0.23692688505618909,
                                         0.47862867049936647,
                                         0.56888888888888889,
                                         0.47862867049936647,
                                         0.23692688505618909,  // n = 5
                                         0.17132449237917034,
                                         0.36076157304813861,
                                         0.46791393457269105,
                                         0.46791393457269105,
                                         0.36076157304813861,
                                         0.17132449237917034,  // n = 6
                                         0.12948496616886969,
                                         0.27970539148927667,
                                         0.38183005050511894,
                                         0.41795918367346939,
                                         0.38183005050511894,
                                         0.27970539148927667,
                                         0.12948496616886969,  // n = 7
                                         0.10122853629037626,
                                         0.22238103445337447,
                                         0.31370664587788729,
                                         0.36268378337836198,
                                         0.36268378337836198,
                                         0.31370664587788729,
                                         0.22238103445337447,
                                         0.10122853629037626};  // n = 8
  if (n < 1 || n > max_gauss_line_points || i < 0 || i >= n) {
    xi = 0.0;
    w = 0.0;
    return false;
  }
  const int k = n * (n - 1) / 2 + i;
  xi = points[k];
  w = weights[k];
  return true;
}

}  // namespace grout
