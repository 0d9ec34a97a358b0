#pragma once
// Element normals of contact faces (LINE2 in 2D, TRI3/QUAD4 in 3D), averaged nodal normals
// and nodal tangents, from current coordinates.
//
//   element normal   LINE2: n_e = (dy, −dx) / |x₂ − x₁|           (topology.hpp convention)
//                    TRI3:  n_e = (x₂ − x₁) × (x₃ − x₁) / |…|
//                    QUAD4: n_e = (x₃ − x₁) × (x₄ − x₂) / |…|      (normal at the centre)
//   nodal normal     n_j = Σ_{e∋j} n_e / |Σ_{e∋j} n_e|              (DESIGN.md §2;
//                    Popp et al. 2010, eq. 4: unweighted average of unit element normals)
//   tangents         2D: τ = e_z × n = (−n_y, n_x);  3D: τ₁ ⊥ n from the coordinate axis least
//                    aligned with n, τ₂ = n × τ₁ (right-handed (τ₁, τ₂, n)).
// Per-face functions are templated on the scalar (double or Sacado::Fad::SFad).

#include <Kokkos_Core.hpp>
#include <cmath>

#include "kernels/mortar_types.hpp"

namespace grout {

/// \brief n ← n/|n| for a Dim-vector. \return false if |n| = 0 (n left unchanged).
template <int Dim, class Scalar>
KOKKOS_INLINE_FUNCTION bool normalize_vector(Scalar n[Dim]) {
  using std::sqrt;
  Scalar nn = n[0] * n[0];
  for (int d = 1; d < Dim; ++d) nn += n[d] * n[d];
  if (!(nn > 0.0)) return false;
  const Scalar len = sqrt(nn);
  for (int d = 0; d < Dim; ++d) n[d] /= len;
  return true;
}

/// \brief Unit normal of a LINE2 face x₁→x₂: n = (dy, −dx)/L. \pre x in any length unit.
template <class Scalar>
KOKKOS_INLINE_FUNCTION MortarStatus line2_normal(const Scalar x[2][2], Scalar n[2]) {
  n[0] = x[1][1] - x[0][1];
  n[1] = x[0][0] - x[1][0];
  return normalize_vector<2>(n) ? MortarStatus::ok : MortarStatus::degenerate;
}

template <class Scalar>
KOKKOS_INLINE_FUNCTION void cross_product(const Scalar a[3], const Scalar b[3], Scalar c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

/// \brief Unit normal of a TRI3 face: (x₂ − x₁) × (x₃ − x₁) normalised.
template <class Scalar>
KOKKOS_INLINE_FUNCTION MortarStatus tri3_normal(const Scalar x[][3], Scalar n[3]) {
  Scalar a[3], b[3];
  for (int d = 0; d < 3; ++d) {
    a[d] = x[1][d] - x[0][d];
    b[d] = x[2][d] - x[0][d];
  }
  cross_product(a, b, n);
  return normalize_vector<3>(n) ? MortarStatus::ok : MortarStatus::degenerate;
}

/// \brief Unit normal at the centre of a bilinear QUAD4 face: (x₃ − x₁) × (x₄ − x₂) normalised
/// (∂x/∂ξ × ∂x/∂η at ξ = η = 0 is a quarter of this product).
template <class Scalar>
KOKKOS_INLINE_FUNCTION MortarStatus quad4_normal(const Scalar x[][3], Scalar n[3]) {
  Scalar a[3], b[3];
  for (int d = 0; d < 3; ++d) {
    a[d] = x[2][d] - x[0][d];
    b[d] = x[3][d] - x[1][d];
  }
  cross_product(a, b, n);
  return normalize_vector<3>(n) ? MortarStatus::ok : MortarStatus::degenerate;
}

/// \brief Unit element normal of a face with `n_nodes` nodes in dimension `dim`
/// (2: LINE2 using x[k][0..1]; 3: TRI3 or QUAD4). Unused components of n are set to zero.
template <class Scalar>
KOKKOS_INLINE_FUNCTION MortarStatus face_normal(int dim, int n_nodes,
                                                const Scalar x[max_face_nodes][3], Scalar n[3]) {
  n[0] = n[1] = n[2] = 0.0;
  if (dim == 2 && n_nodes == 2) {
    const Scalar x2[2][2] = {{x[0][0], x[0][1]}, {x[1][0], x[1][1]}};
    return line2_normal(x2, n);
  }
  if (dim == 3 && n_nodes == 3) return tri3_normal(x, n);
  if (dim == 3 && n_nodes == 4) return quad4_normal(x, n);
  return MortarStatus::degenerate;
}

/// \brief 2D tangent τ = e_z × n = (−n_y, n_x): for a LINE2 element normal it points x₁→x₂.
template <class Scalar>
KOKKOS_INLINE_FUNCTION void tangent_2d(const Scalar n[2], Scalar t[2]) {
  t[0] = -n[1];
  t[1] = n[0];
}

/// \brief 3D tangents: τ₁ = normalised projection of the axis e_a with the smallest |n_a| onto
/// the plane ⊥ n, τ₂ = n × τ₁. \pre |n| = 1.
template <class Scalar>
KOKKOS_INLINE_FUNCTION void tangents_3d(const Scalar n[3], Scalar t1[3], Scalar t2[3]) {
  using std::abs;
  int a = 0;
  if (abs(n[1]) < abs(n[a])) a = 1;
  if (abs(n[2]) < abs(n[a])) a = 2;
  for (int d = 0; d < 3; ++d) t1[d] = (d == a ? 1.0 : 0.0) - n[a] * n[d];
  normalize_vector<3>(t1);
  cross_product(n, t1, t2);
}

/// \brief Gathers the coordinates of face f (rows of `faces`, −1 padding) into x (unused
/// components zero). \return the number of face nodes.
template <class FaceView, class CoordView>
KOKKOS_INLINE_FUNCTION int gather_face_coordinates(const FaceView& faces, int f,
                                                   const CoordView& coords,
                                                   double x[max_face_nodes][3]) {
  const int n_cols = static_cast<int>(faces.extent(1));
  const int dim = static_cast<int>(coords.extent(1));
  int n_nodes = 0;
  for (int k = 0; k < max_face_nodes; ++k) x[k][0] = x[k][1] = x[k][2] = 0.0;
  while (n_nodes < n_cols && n_nodes < max_face_nodes && faces(f, n_nodes) >= 0) {
    for (int d = 0; d < dim; ++d) x[n_nodes][d] = coords(faces(f, n_nodes), d);
    ++n_nodes;
  }
  return n_nodes;
}

namespace detail {

/// Unit normal of face f and its node count, from the coordinates (2D: LINE2 read straight from
/// the views; 3D: gathered TRI3/QUAD4).
template <int Dim, class FaceView, class CoordView>
KOKKOS_INLINE_FUNCTION MortarStatus face_normal_of(const FaceView& faces, int f,
                                                   const CoordView& coords, int& n_nodes,
                                                   double n[3]) {
  if constexpr (Dim == 2) {
    const int n_cols = static_cast<int>(faces.extent(1));
    n_nodes = 0;
    while (n_nodes < n_cols && n_nodes < max_face_nodes && faces(f, n_nodes) >= 0) ++n_nodes;
    n[2] = 0.0;
    if (n_nodes != 2) return MortarStatus::degenerate;
    const int a = faces(f, 0), b = faces(f, 1);
    n[0] = coords(b, 1) - coords(a, 1);
    n[1] = coords(a, 0) - coords(b, 0);
    return normalize_vector<2>(n) ? MortarStatus::ok : MortarStatus::degenerate;
  } else {
    double x[max_face_nodes][3];
    n_nodes = gather_face_coordinates(faces, f, coords, x);
    return face_normal(3, n_nodes, x, n);
  }
}

template <int Dim, class ExecSpace>
MortarStatus compute_nodal_normals(
    const ExecSpace& space, Kokkos::View<const int**, typename ExecSpace::memory_space> faces,
    Kokkos::View<const double**, typename ExecSpace::memory_space> coords,
    Kokkos::View<double**, typename ExecSpace::memory_space> normals) {
  using Policy = Kokkos::RangePolicy<ExecSpace>;
  Kokkos::parallel_for(
      "grout::nodal_normals_zero", Policy(space, 0, normals.extent(0)), KOKKOS_LAMBDA(const int j) {
        for (int d = 0; d < Dim; ++d) normals(j, d) = 0.0;
      });
  int status = 0;
  Kokkos::parallel_reduce(
      "grout::nodal_normals", Policy(space, 0, faces.extent(0)),
      KOKKOS_LAMBDA(const int f, int& worst) {
        int n_nodes;
        double n[3];
        const MortarStatus s = face_normal_of<Dim>(faces, f, coords, n_nodes, n);
        if (s != MortarStatus::ok) {
          worst = worst > static_cast<int>(s) ? worst : static_cast<int>(s);
          return;
        }
        for (int k = 0; k < n_nodes; ++k)
          for (int d = 0; d < Dim; ++d) Kokkos::atomic_add(&normals(faces(f, k), d), n[d]);
      },
      Kokkos::Max<int>(status));
  status = status > 0 ? status : 0;  // Max starts from INT_MIN (empty range)
  Kokkos::parallel_for(
      "grout::nodal_normals_normalise", Policy(space, 0, normals.extent(0)),
      KOKKOS_LAMBDA(const int j) {
        using std::sqrt;
        double nn = 0.0;
        for (int d = 0; d < Dim; ++d) nn += normals(j, d) * normals(j, d);
        if (!(nn > 0.0)) return;  // node on no face, or opposite face normals cancel: n_j = 0
        const double inv = 1.0 / sqrt(nn);
        for (int d = 0; d < Dim; ++d) normals(j, d) *= inv;
      });
  return static_cast<MortarStatus>(status);
}

}  // namespace detail

/// \brief Averaged unit nodal normals n_j of the faces `faces` (one row per face, local nodes
/// in the columns, −1 pads a TRI3 row of a 4-column table), launches "grout::nodal_normals_zero",
/// "grout::nodal_normals" (per face, summed into its nodes) and "grout::nodal_normals_normalise".
/// \pre coords: (n_nodes, dim), dim ∈ {2, 3}; normals: (n_nodes, dim). Nodes on no face get 0.
/// \return degenerate if a face has zero length/area or bad sizes, ok otherwise. A node whose
/// adjacent face normals cancel keeps n_j = 0.
template <class ExecSpace>
MortarStatus compute_nodal_normals(
    const ExecSpace& space, Kokkos::View<const int**, typename ExecSpace::memory_space> faces,
    Kokkos::View<const double**, typename ExecSpace::memory_space> coords,
    Kokkos::View<double**, typename ExecSpace::memory_space> normals) {
  const int dim = static_cast<int>(coords.extent(1));
  const int n_cols = static_cast<int>(faces.extent(1));
  if ((dim != 2 && dim != 3) || normals.extent(0) != coords.extent(0) ||
      static_cast<int>(normals.extent(1)) != dim || n_cols > max_face_nodes) {
    return MortarStatus::degenerate;
  }
  return dim == 2 ? detail::compute_nodal_normals<2>(space, faces, coords, normals)
                  : detail::compute_nodal_normals<3>(space, faces, coords, normals);
}

/// Default-execution-space overload of compute_nodal_normals.
inline MortarStatus compute_nodal_normals(Kokkos::View<const int**> faces,
                                          Kokkos::View<const double**> coords,
                                          Kokkos::View<double**> normals) {
  return compute_nodal_normals(Kokkos::DefaultExecutionSpace(), faces, coords, normals);
}

/// \brief Nodal tangents from unit nodal normals, launch "grout::nodal_tangents".
/// \pre normals: (n_nodes, dim); tangents: (n_nodes, dim − 1, dim). Zero normals give zero
/// tangents.
template <class ExecSpace>
void compute_nodal_tangents(const ExecSpace& space,
                            Kokkos::View<const double**, typename ExecSpace::memory_space> normals,
                            Kokkos::View<double***, typename ExecSpace::memory_space> tangents) {
  const int dim = static_cast<int>(normals.extent(1));
  Kokkos::parallel_for(
      "grout::nodal_tangents", Kokkos::RangePolicy<ExecSpace>(space, 0, normals.extent(0)),
      KOKKOS_LAMBDA(const int j) {
        double n[3] = {normals(j, 0), normals(j, 1), dim == 3 ? normals(j, 2) : 0.0};
        const bool zero = n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0;
        if (dim == 2) {
          double t[2];
          tangent_2d(n, t);
          for (int d = 0; d < 2; ++d) tangents(j, 0, d) = zero ? 0.0 : t[d];
        } else {
          double t1[3], t2[3];
          tangents_3d(n, t1, t2);
          for (int d = 0; d < 3; ++d) {
            tangents(j, 0, d) = zero ? 0.0 : t1[d];
            tangents(j, 1, d) = zero ? 0.0 : t2[d];
          }
        }
      });
}

/// Default-execution-space overload of compute_nodal_tangents.
inline void compute_nodal_tangents(Kokkos::View<const double**> normals,
                                   Kokkos::View<double***> tangents) {
  compute_nodal_tangents(Kokkos::DefaultExecutionSpace(), normals, tangents);
}

}  // namespace grout
