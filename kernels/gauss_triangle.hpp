#pragma once
// Symmetric Gauss rules on a triangle, for the 3D mortar integration cells.
//
// Degree 1 (centroid), degree 2 (3 interior points) and the Dunavant rules of degree 4, 6
// and 8 (D. A. Dunavant, "High degree efficient symmetrical Gaussian quadrature rules for
// the triangle", IJNME 21 (1985), tables for p = 4, 6, 8). The Dunavant points and weights
// were re-solved here from the moment equations ∫_T a^i b^j = 2 i! j! / (i+j+2)! (weights
// normalised to the area) to full double precision, so every rule integrates every
// polynomial of its degree to round-off (unit_tests/test_kernels_mortar_3d checks this).
//
// All weights are positive and all points interior.

#include "kernels/kernel_macros.hpp"

namespace grout {

/// Symmetric Gauss rule of polynomial degree `Degree` on a triangle (1, 2, 4, 6, 8).
template <int Degree>
struct GaussTriangle {
  static_assert(Degree == 1 || Degree == 2 || Degree == 4 || Degree == 6 || Degree == 8,
                "grout::GaussTriangle: available degrees are 1, 2, 4, 6 and 8");
};

/// Degree-1 rule, 1 points.
template <>
struct GaussTriangle<1> {
  static constexpr int num_points = 1;
  /// \brief Point i: area coordinates (a, b) (x = (1-a-b) v0 + a v1 + b v2) and weight w
  /// (fraction of the triangle area; the weights sum to 1).
  GROUT_INLINE_FUNCTION static void point(int i, double& a, double& b, double& w) {
    static constexpr double table[num_points][3] = {
        {1.0 / 3.0, 1.0 / 3.0, 1.0},
    };
    a = table[i][0];
    b = table[i][1];
    w = table[i][2];
  }
};

/// Degree-2 rule, 3 points.
template <>
struct GaussTriangle<2> {
  static constexpr int num_points = 3;
  /// \brief Point i: area coordinates (a, b) (x = (1-a-b) v0 + a v1 + b v2) and weight w
  /// (fraction of the triangle area; the weights sum to 1).
  GROUT_INLINE_FUNCTION static void point(int i, double& a, double& b, double& w) {
    static constexpr double table[num_points][3] = {
        {1.0 / 6.0, 1.0 / 6.0, 1.0 / 3.0},
        {2.0 / 3.0, 1.0 / 6.0, 1.0 / 3.0},
        {1.0 / 6.0, 2.0 / 3.0, 1.0 / 3.0},
    };
    a = table[i][0];
    b = table[i][1];
    w = table[i][2];
  }
};

/// Degree-4 rule, 6 points (Dunavant 1985).
template <>
struct GaussTriangle<4> {
  static constexpr int num_points = 6;
  /// \brief Point i: area coordinates (a, b) (x = (1-a-b) v0 + a v1 + b v2) and weight w
  /// (fraction of the triangle area; the weights sum to 1).
  GROUT_INLINE_FUNCTION static void point(int i, double& a, double& b, double& w) {
    static constexpr double table[num_points][3] = {
        {0.44594849091596488632, 0.44594849091596488632, 0.2233815896780114657},
        {0.44594849091596488632, 0.10810301816807022736, 0.2233815896780114657},
        {0.10810301816807022736, 0.44594849091596488632, 0.2233815896780114657},
        {0.09157621350977074346, 0.09157621350977074346, 0.10995174365532186764},
        {0.09157621350977074346, 0.81684757298045851308, 0.10995174365532186764},
        {0.81684757298045851308, 0.09157621350977074346, 0.10995174365532186764},
    };
    a = table[i][0];
    b = table[i][1];
    w = table[i][2];
  }
};

/// Degree-6 rule, 12 points (Dunavant 1985).
template <>
struct GaussTriangle<6> {
  static constexpr int num_points = 12;
  /// \brief Point i: area coordinates (a, b) (x = (1-a-b) v0 + a v1 + b v2) and weight w
  /// (fraction of the triangle area; the weights sum to 1).
  GROUT_INLINE_FUNCTION static void point(int i, double& a, double& b, double& w) {
    static constexpr double table[num_points][3] = {
        {0.24928674517091042129, 0.24928674517091042129, 0.11678627572637936603},
        {0.24928674517091042129, 0.50142650965817915742, 0.11678627572637936603},
        {0.50142650965817915742, 0.24928674517091042129, 0.11678627572637936603},
        {0.06308901449150222834, 0.06308901449150222834, 0.050844906370206816921},
        {0.06308901449150222834, 0.87382197101699554332, 0.050844906370206816921},
        {0.87382197101699554332, 0.06308901449150222834, 0.050844906370206816921},
        {0.053145049844816947353, 0.31035245103378440542, 0.082851075618373575194},
        {0.31035245103378440542, 0.053145049844816947353, 0.082851075618373575194},
        {0.053145049844816947353, 0.63650249912139864723, 0.082851075618373575194},
        {0.63650249912139864723, 0.053145049844816947353, 0.082851075618373575194},
        {0.31035245103378440542, 0.63650249912139864723, 0.082851075618373575194},
        {0.63650249912139864723, 0.31035245103378440542, 0.082851075618373575194},
    };
    a = table[i][0];
    b = table[i][1];
    w = table[i][2];
  }
};

/// Degree-8 rule, 16 points (Dunavant 1985).
template <>
struct GaussTriangle<8> {
  static constexpr int num_points = 16;
  /// \brief Point i: area coordinates (a, b) (x = (1-a-b) v0 + a v1 + b v2) and weight w
  /// (fraction of the triangle area; the weights sum to 1).
  GROUT_INLINE_FUNCTION static void point(int i, double& a, double& b, double& w) {
    static constexpr double table[num_points][3] = {
        {0.33333333333333333333, 0.33333333333333333333, 0.14431560767778716825},
        {0.45929258829272315603, 0.45929258829272315603, 0.095091634267284624794},
        {0.45929258829272315603, 0.081414823414553687942, 0.095091634267284624794},
        {0.081414823414553687942, 0.45929258829272315603, 0.095091634267284624794},
        {0.17056930775176020662, 0.17056930775176020662, 0.10321737053471825028},
        {0.17056930775176020662, 0.65886138449647958676, 0.10321737053471825028},
        {0.65886138449647958676, 0.17056930775176020662, 0.10321737053471825028},
        {0.050547228317030975458, 0.050547228317030975458, 0.032458497623198080311},
        {0.050547228317030975458, 0.89890554336593804908, 0.032458497623198080311},
        {0.89890554336593804908, 0.050547228317030975458, 0.032458497623198080311},
        {0.0083947774099576053372, 0.26311282963463811342, 0.027230314174434994265},
        {0.26311282963463811342, 0.0083947774099576053372, 0.027230314174434994265},
        {0.0083947774099576053372, 0.72849239295540428124, 0.027230314174434994265},
        {0.72849239295540428124, 0.0083947774099576053372, 0.027230314174434994265},
        {0.26311282963463811342, 0.72849239295540428124, 0.027230314174434994265},
        {0.72849239295540428124, 0.26311282963463811342, 0.027230314174434994265},
    };
    a = table[i][0];
    b = table[i][1];
    w = table[i][2];
  }
};

}  // namespace grout
