#pragma once
// Averaged nodal normals and nodal tangents of a contact surface, from current coordinates
// (launches over Views; the per-face math is in face_normal.hpp):
//
//   nodal normal     n_j = Σ_{e∋j} n_e / |Σ_{e∋j} n_e|              (docs/design.md §2;
//                    Popp et al. 2010, eq. 4: unweighted average of unit element normals n_e)
//   tangents         tangent_2d / tangents_3d of n_j (face_normal.hpp).

#include <Kokkos_Core.hpp>
#include <cmath>

#include "kernels/face_normal.hpp"
#include "kernels/mortar_types.hpp"

namespace grout {

/// \brief Gathers the coordinates of face f (rows of `faces`, −1 padding) into x (unused
/// components zero). \return the number of face nodes.
template <class FaceView, class CoordView>
KOKKOS_FORCEINLINE_FUNCTION int gather_face_coordinates(const FaceView& faces, int f,
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
