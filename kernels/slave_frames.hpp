#pragma once
// The launch of slave_frame.hpp over the slave nodes of a surface: each node's frame (unit
// averaged normal and tangents) from the faces around it, and the derivatives of the frame with
// respect to each of those faces' coordinates (docs/design.md, "Mortar terms").

#include <Kokkos_Core.hpp>

#include "kernels/slave_frame.hpp"
#include "kernels/surface_normals.hpp"

namespace grout {

/// \brief Frames of the slave nodes, launch "grout::slave_frames<2D>" / "<3D>", one work item
/// per node: frames(i, r) (rows of SlaveFrameLayout<Dim>) and, if `derivatives`,
/// dframes(q, r, a·Dim + c) = ∂frame_r/∂x_{f,a,c} for the face f = node_faces(q) at CRS position
/// q ∈ [node_face_offsets(i), node_face_offsets(i + 1)) (a node shared by several faces of the
/// patch gets a column in each: the caller sums them).
/// \pre faces: (n_faces, ≤ max_face_nodes) rows into coords, −1 padding; coords (n, Dim);
/// frames (n_nodes, Dim·Dim); dframes (≥ node_face_offsets(n_nodes), Dim·Dim, max_face_nodes·Dim)
/// when derivatives. \return the worst face status (degenerate for a zero-size face).
template <int Dim, class ExecSpace>
MortarStatus compute_slave_frames(
    const ExecSpace& space, Kokkos::View<const int**, typename ExecSpace::memory_space> faces,
    Kokkos::View<const double**, typename ExecSpace::memory_space> coords,
    Kokkos::View<const int*, typename ExecSpace::memory_space> node_face_offsets,
    Kokkos::View<const int*, typename ExecSpace::memory_space> node_faces, bool derivatives,
    Kokkos::View<double**, typename ExecSpace::memory_space> frames,
    Kokkos::View<double***, typename ExecSpace::memory_space> dframes) {
  static_assert(Dim == 2 || Dim == 3, "grout::compute_slave_frames: Dim must be 2 or 3");
  using L = SlaveFrameLayout<Dim>;
  const int n_nodes = static_cast<int>(frames.extent(0));
  if (static_cast<int>(coords.extent(1)) != Dim || static_cast<int>(frames.extent(1)) != L::rows ||
      static_cast<int>(node_face_offsets.extent(0)) != n_nodes + 1)
    return MortarStatus::degenerate;
  int status = 0;
  Kokkos::parallel_reduce(
      Dim == 2 ? "grout::slave_frames<2D>" : "grout::slave_frames<3D>",
      Kokkos::RangePolicy<ExecSpace>(space, 0, n_nodes),
      KOKKOS_LAMBDA(const int i, int& worst) {
        double N[3] = {0.0, 0.0, 0.0}, x[max_face_nodes][3], nf[3];
        const int begin = node_face_offsets(i), end = node_face_offsets(i + 1);
        for (int q = begin; q < end; ++q) {
          const int n_face = gather_face_coordinates(faces, node_faces(q), coords, x);
          const MortarStatus s = face_normal(Dim, n_face, x, nf);
          worst = static_cast<int>(s) > worst ? static_cast<int>(s) : worst;
          for (int d = 0; d < 3; ++d) N[d] += nf[d];
        }
        double frame[L::rows], J[L::rows][Dim];
        frame_of_normal_sum<Dim>(N, frame, J);
        for (int r = 0; r < L::rows; ++r) frames(i, r) = frame[r];
        if (!derivatives) return;
        // Per face: ∂n_f/∂x in AD (the values again, as a by-product), chained through J.
        for (int q = begin; q < end; ++q) {
          double dn_f[3][L::columns], block[L::rows][L::columns];
          const int n_face = gather_face_coordinates(faces, node_faces(q), coords, x);
          face_normal_gradient<Dim>(n_face, x, nf, dn_f);
          chain_frame_gradient<Dim>(J, dn_f, block);
          for (int r = 0; r < L::rows; ++r)
            for (int v = 0; v < L::columns; ++v) dframes(q, r, v) = block[r][v];
        }
      },
      Kokkos::Max<int>(status));
  status = status > 0 ? status : 0;  // Max starts from INT_MIN (empty range)
  return static_cast<MortarStatus>(status);
}

}  // namespace grout
