#pragma once
// Isoparametric Lagrange shape functions of the first-order elements, their physical
// gradients, the area element of a side and the measure of an element.
//
// Reference elements and Exodus II node order (SAND92-2137, fig. 4), 0-based:
//   line2 [-1,1]:   N0 = (1 - xi)/2, N1 = (1 + xi)/2
//   tri3 (area 1/2): N0 = 1 - xi - eta, N1 = xi, N2 = eta
//   quad4 [-1,1]^2: N_a = (1 + xi_a xi)(1 + eta_a eta)/4, nodes (-1,-1) (1,-1) (1,1) (-1,1)
//   tet4 (vol 1/6): N0 = 1 - xi - eta - zeta, N1 = xi, N2 = eta, N3 = zeta
//   hex8 [-1,1]^3:  N_a = (1 + xi_a xi)(1 + eta_a eta)(1 + zeta_a zeta)/8, nodes 0-3 the quad4
//                   nodes at zeta = -1, nodes 4-7 the same at zeta = +1
// (Hughes, The Finite Element Method, §3.2, §3.5 for the formulas; node order of Exodus.)

#include "kernels/kernel_macros.hpp"
#include "kernels/quadrature.hpp"
#include "kernels/topology.hpp"

namespace grout {

/// Outcome of an element kernel: inverted = the reference element has det J <= 0 (a mesh
/// error); collapsed = the deformation has det F <= 0 at a quadrature point (finite strain: an
/// inadmissible iterate, not a mesh error).
enum class ElementStatus : int { ok = 0, inverted = 1, unsupported = 2, collapsed = 3 };

/// Largest number of element degrees of freedom (hex8 in 3D).
constexpr int max_element_dofs = 24;

/// T in a non-deduced context, so that outputs may be passed as nullptr.
template <class T>
struct NonDeduced {
  using type = T;
};

/// \brief Shape function values N[a] and reference derivatives dN_dxi[a * tdim + j] = dN_a/dxi_j
/// (tdim = topology_dimension(t)) at the reference point xi. Either output may be null.
/// Templated so that xi may carry derivatives (Sacado Fad) for projected points.
/// \return the number of nodes, 0 for an unknown topology.
template <class Scalar>
GROUT_INLINE_FUNCTION int shape_functions(Topology t, const Scalar* xi,
                                          typename NonDeduced<Scalar>::type* N,
                                          typename NonDeduced<Scalar>::type* dN_dxi) {
  static constexpr double s[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                     {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  switch (t) {
    case Topology::line2:
      if (N) {
        N[0] = 0.5 * (1.0 - xi[0]);
        N[1] = 0.5 * (1.0 + xi[0]);
      }
      if (dN_dxi) {
        dN_dxi[0] = -0.5;
        dN_dxi[1] = 0.5;
      }
      return 2;
    case Topology::tri3:
      if (N) {
        N[0] = 1.0 - xi[0] - xi[1];
        N[1] = xi[0];
        N[2] = xi[1];
      }
      if (dN_dxi) {
        static constexpr double d[6] = {-1, -1, 1, 0, 0, 1};
        for (int k = 0; k < 6; ++k) dN_dxi[k] = d[k];
      }
      return 3;
    case Topology::tet4:
      if (N) {
        N[0] = 1.0 - xi[0] - xi[1] - xi[2];
        N[1] = xi[0];
        N[2] = xi[1];
        N[3] = xi[2];
      }
      if (dN_dxi) {
        static constexpr double d[12] = {-1, -1, -1, 1, 0, 0, 0, 1, 0, 0, 0, 1};
        for (int k = 0; k < 12; ++k) dN_dxi[k] = d[k];
      }
      return 4;
    case Topology::quad4:
      for (int a = 0; a < 4; ++a) {
        const Scalar fx = 1.0 + s[a][0] * xi[0], fy = 1.0 + s[a][1] * xi[1];
        if (N) N[a] = 0.25 * fx * fy;
        if (dN_dxi) {
          dN_dxi[2 * a + 0] = 0.25 * s[a][0] * fy;
          dN_dxi[2 * a + 1] = 0.25 * s[a][1] * fx;
        }
      }
      return 4;
    case Topology::hex8:
      for (int a = 0; a < 8; ++a) {
        const Scalar fx = 1.0 + s[a][0] * xi[0], fy = 1.0 + s[a][1] * xi[1],
                     fz = 1.0 + s[a][2] * xi[2];
        if (N) N[a] = 0.125 * fx * fy * fz;
        if (dN_dxi) {
          dN_dxi[3 * a + 0] = 0.125 * s[a][0] * fy * fz;
          dN_dxi[3 * a + 1] = 0.125 * s[a][1] * fx * fz;
          dN_dxi[3 * a + 2] = 0.125 * s[a][2] * fx * fy;
        }
      }
      return 8;
  }
  return 0;
}

/// \brief Physical gradients of the shape functions of a solid element at xi (Hughes §3.2):
///   J_ij = dx_i/dxi_j = sum_a X_a,i dN_a/dxi_j,   dN_a/dX_i = sum_j dN_a/dxi_j (J^-1)_ji,
/// det_J = det J. dN_dX[a * dim + i]; N (nullable) gets the values.
/// X[a * dim + i] are nodal coordinates (Scalar, e.g. current coordinates under AD).
/// \return unsupported unless topology_dimension(t) == dim, inverted if det_J <= 0.
template <class Scalar>
GROUT_INLINE_FUNCTION ElementStatus shape_gradients(Topology t, int dim, const Scalar* X,
                                                    const double* xi, double* N, Scalar* dN_dX,
                                                    Scalar& det_J) {
  if (dim < 1 || dim > 3 || topology_dimension(t) != dim) return ElementStatus::unsupported;
  double dN[max_element_nodes * 3];
  const int n = shape_functions(t, xi, N, dN);
  Scalar J[3][3] = {};  // zeroed: GCC cannot see that the dim x dim block is filled
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) {
      J[i][j] = 0.0;
      for (int a = 0; a < n; ++a) J[i][j] += X[a * dim + i] * dN[a * dim + j];
    }
  // Inverse by cofactors: Jinv = adj(J) / det J.
  Scalar Jinv[3][3];
  if (dim == 1) {
    det_J = J[0][0];
    Jinv[0][0] = 1.0;
  } else if (dim == 2) {
    det_J = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    Jinv[0][0] = J[1][1];
    Jinv[0][1] = -J[0][1];
    Jinv[1][0] = -J[1][0];
    Jinv[1][1] = J[0][0];
  } else {
    for (int i = 0; i < 3; ++i) {
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
      for (int j = 0; j < 3; ++j) {
        const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
        Jinv[j][i] = J[i1][j1] * J[i2][j2] - J[i1][j2] * J[i2][j1];  // cofactor C_ij
      }
    }
    det_J = J[0][0] * Jinv[0][0] + J[0][1] * Jinv[1][0] + J[0][2] * Jinv[2][0];
  }
  if (!(det_J > 0.0)) return ElementStatus::inverted;
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < dim; ++i) {
      Scalar g = 0.0;
      for (int j = 0; j < dim; ++j) g += dN[a * dim + j] * Jinv[j][i];
      dN_dX[a * dim + i] = g / det_J;
    }
  return ElementStatus::ok;
}

/// \brief Area vector of a side (line2 in 2D, tri3/quad4 in 3D) at xi: with the tangents
/// T_j = sum_a X_a dN_a/dxi_j,
///   2D: a = (T_y, -T_x),   3D: a = T_1 x T_2,
/// so that a = n |a| with n the outward normal of topology.hpp's side order and |a| the
/// length/area Jacobian (dA = |a| dxi). N (nullable) gets the shape function values.
/// \return the number of side nodes, 0 if (side, dim) is not a side of a dim-D solid.
template <class Scalar>
GROUT_INLINE_FUNCTION int side_area_vector(Topology side, int dim, const Scalar* X,
                                           const double* xi, double* N, Scalar* a) {
  if (dim < 2 || dim > 3 || topology_dimension(side) != dim - 1) return 0;
  // Sized for any topology: the compiler cannot see that `side` is never a solid.
  double dN[max_element_nodes * 3];
  const int n = shape_functions(side, xi, N, dN);
  const int tdim = dim - 1;
  Scalar T[2][3] = {};  // zeroed: GCC cannot see that tdim rows are filled
  for (int j = 0; j < tdim; ++j)
    for (int i = 0; i < dim; ++i) {
      T[j][i] = 0.0;
      for (int k = 0; k < n; ++k) T[j][i] += X[k * dim + i] * dN[k * tdim + j];
    }
  if (dim == 2) {
    a[0] = T[0][1];
    a[1] = -T[0][0];
  } else {
    a[0] = T[0][1] * T[1][2] - T[0][2] * T[1][1];
    a[1] = T[0][2] * T[1][0] - T[0][0] * T[1][2];
    a[2] = T[0][0] * T[1][1] - T[0][1] * T[1][0];
  }
  return n;
}

/// \brief Measure of an element: volume of a solid (area in 2D, length in 1D),
///   V = sum_q w_q det J(xi_q),
/// with a Gauss rule exact for det J (degree 1 on simplices, 3 per direction on quad4/hex8,
/// whose det J is of degree <= 2 per direction), or the length/area of a side
/// (topology_dimension(t) == dim - 1), A = sum_q w_q |a(xi_q)| (exact for planar sides).
/// The signed value is returned for solids (negative/partly negative if inverted); 0 for an
/// unsupported (topology, dim).
GROUT_INLINE_FUNCTION double element_measure(Topology t, int dim, const double* X) {
  const bool simplex = t == Topology::tri3 || t == Topology::tet4;
  const int degree = simplex ? 1 : 3;
  const int num_points = quadrature_num_points(t, degree);
  double measure = 0.0;
  for (int q = 0; q < num_points; ++q) {
    const QuadraturePoint p = quadrature_point(t, degree, q);
    if (topology_dimension(t) == dim) {
      double dN_dX[max_element_nodes * 3], det_J = 0.0;
      if (shape_gradients(t, dim, X, p.xi, nullptr, dN_dX, det_J) == ElementStatus::unsupported)
        return 0.0;
      measure += p.weight * det_J;
    } else {
      double a[3] = {0.0, 0.0, 0.0};
      if (side_area_vector(t, dim, X, p.xi, nullptr, a) == 0) return 0.0;
      measure += p.weight * kmath::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    }
  }
  return measure;
}

}  // namespace grout
