#pragma once
// Launch of the mortar pair kernels over all slave faces: for every slave face s and every
// candidate master face m of s (coarse_search.hpp), integrate the pair and store its
// MortarPairResult in results(pair_offsets(s) + c), a compact pair array (candidate_offsets). One
// labelled parallel_reduce per dimension, "grout::mortar_integrate<2D>" /
// "grout::mortar_integrate<3D>", whose max-reduced status is returned on the host (no_overlap is
// not an error: such pairs are stored with zeros).
//
// The per-dimension pair kernel is selected by MortarPairKernel<Dim>. This header defines
// MortarPairKernel<2> (integrate_mortar_2d / integrate_mortar_2d_collocation, mortar_2d.hpp).
// The 3D code defines, in its own header,
//
//   template <> struct MortarPairKernel<3> {
//     static constexpr const char* label = "grout::mortar_integrate<3D>";
//     template <class Scalar> KOKKOS_INLINE_FUNCTION static MortarStatus integrate(
//         int n_slave, const Scalar xs[max_face_nodes][3], const Scalar ns[max_face_nodes][3],
//         int n_master, const Scalar xm[max_face_nodes][3], const MortarOptions& options,
//         MortarPairResult<Scalar>& out);   // calls integrate_mortar_3d(n_slave, xs, ns, ...)
//   };
//
// after which mortar_integrate<3>(...) below works unchanged.

#include <Kokkos_Core.hpp>

#include "kernels/mortar_2d.hpp"
#include "kernels/mortar_types.hpp"
#include "kernels/surface_normals.hpp"

namespace grout {

/// Integration scheme of the pair kernels (typed once, from the input).
struct MortarOptions {
  MortarIntegration scheme = MortarIntegration::exact;
  int n_gauss = mortar_2d_gauss_points;  ///< Gauss points per 2D overlap segment (1..8)
  int n_collocation = 16;                ///< points per slave element for collocation
};

/// Pair kernel of dimension Dim (specialised per dimension, see the file comment).
template <int Dim>
struct MortarPairKernel;

template <>
struct MortarPairKernel<2> {
  static constexpr const char* label = "grout::mortar_integrate<2D>";

  /// LINE2/LINE2 pair from padded (max_face_nodes × 3) arrays; only [0..1][0..1] are read.
  template <class Scalar>
  KOKKOS_INLINE_FUNCTION static MortarStatus integrate(
      int n_slave, const Scalar xs[max_face_nodes][3], const Scalar ns[max_face_nodes][3],
      int n_master, const Scalar xm[max_face_nodes][3], const MortarOptions& options,
      MortarPairResult<Scalar>& out) {
    if (n_slave != 2 || n_master != 2) {
      zero_pair_result_2d(out);
      return MortarStatus::degenerate;
    }
    const Scalar xs2[2][2] = {{xs[0][0], xs[0][1]}, {xs[1][0], xs[1][1]}};
    const Scalar ns2[2][2] = {{ns[0][0], ns[0][1]}, {ns[1][0], ns[1][1]}};
    const Scalar xm2[2][2] = {{xm[0][0], xm[0][1]}, {xm[1][0], xm[1][1]}};
    if (options.scheme == MortarIntegration::collocation)
      return integrate_mortar_2d_collocation(xs2, ns2, xm2, options.n_collocation, out);
    return integrate_mortar_2d(xs2, ns2, xm2, options.n_gauss, out);
  }
};

/// \brief Integrates every (slave face, candidate master face) pair with MortarPairKernel<Dim>.
/// \pre slave_faces, master_faces: (n, ≤ max_face_nodes) node ids, −1 padding; coords and unit
/// nodal normals: (n_nodes, Dim); n_candidates, candidates from coarse_search; pair_offsets
/// (n_slave + 1) from candidate_offsets; results: (pair_offsets(n_slave)), pair c of slave s at
/// pair_offsets(s) + c. \return the worst pair status other than no_overlap (ok if all pairs
/// succeeded), degenerate for inconsistent sizes.
template <int Dim, class ExecSpace>
MortarStatus mortar_integrate(
    const ExecSpace& space, Kokkos::View<const int**, typename ExecSpace::memory_space> slave_faces,
    Kokkos::View<const int**, typename ExecSpace::memory_space> master_faces,
    Kokkos::View<const double**, typename ExecSpace::memory_space> coords,
    Kokkos::View<const double**, typename ExecSpace::memory_space> normals,
    Kokkos::View<const int*, typename ExecSpace::memory_space> n_candidates,
    Kokkos::View<const int**, typename ExecSpace::memory_space> candidates,
    Kokkos::View<const int*, typename ExecSpace::memory_space> pair_offsets,
    const MortarOptions& options,
    Kokkos::View<MortarPairResult<double>*, typename ExecSpace::memory_space> results) {
  static_assert(Dim == 2 || Dim == 3, "grout::mortar_integrate: Dim must be 2 or 3");
  const size_t n_s = slave_faces.extent(0);
  if (static_cast<int>(coords.extent(1)) != Dim || normals.extent(0) != coords.extent(0) ||
      static_cast<int>(normals.extent(1)) != Dim || n_candidates.extent(0) != n_s ||
      candidates.extent(0) != n_s || pair_offsets.extent(0) != n_s + 1)
    return MortarStatus::degenerate;
  int status = 0;
  Kokkos::parallel_reduce(
      MortarPairKernel<Dim>::label, Kokkos::RangePolicy<ExecSpace>(space, 0, n_s),
      KOKKOS_LAMBDA(const int s, int& worst) {
        double xs[max_face_nodes][3], ns[max_face_nodes][3], xm[max_face_nodes][3];
        const int n_slave = gather_face_coordinates(slave_faces, s, coords, xs);
        gather_face_coordinates(slave_faces, s, normals, ns);
        const int n_cand = n_candidates(s);
        if (pair_offsets(s) + n_cand > static_cast<int>(results.extent(0))) {
          worst = static_cast<int>(MortarStatus::capacity_exceeded);
          return;
        }
        for (int c = 0; c < n_cand && c < max_pair_candidates; ++c) {
          const int n_master = gather_face_coordinates(master_faces, candidates(s, c), coords, xm);
          const MortarStatus st = MortarPairKernel<Dim>::integrate(
              n_slave, xs, ns, n_master, xm, options, results(pair_offsets(s) + c));
          const int code = st == MortarStatus::no_overlap ? 0 : static_cast<int>(st);
          worst = code > worst ? code : worst;
        }
        if (n_cand > max_pair_candidates)
          worst = static_cast<int>(MortarStatus::capacity_exceeded) > worst
                      ? static_cast<int>(MortarStatus::capacity_exceeded)
                      : worst;
      },
      Kokkos::Max<int>(status));
  status = status > 0 ? status : 0;  // Max starts from INT_MIN (empty range)
  return static_cast<MortarStatus>(status);
}

/// 2D launch ("grout::mortar_integrate<2D>") on an explicit execution space.
template <class ExecSpace>
MortarStatus mortar_integrate_2d(
    const ExecSpace& space, Kokkos::View<const int**, typename ExecSpace::memory_space> slave_faces,
    Kokkos::View<const int**, typename ExecSpace::memory_space> master_faces,
    Kokkos::View<const double**, typename ExecSpace::memory_space> coords,
    Kokkos::View<const double**, typename ExecSpace::memory_space> normals,
    Kokkos::View<const int*, typename ExecSpace::memory_space> n_candidates,
    Kokkos::View<const int**, typename ExecSpace::memory_space> candidates,
    Kokkos::View<const int*, typename ExecSpace::memory_space> pair_offsets,
    const MortarOptions& options,
    Kokkos::View<MortarPairResult<double>*, typename ExecSpace::memory_space> results) {
  return mortar_integrate<2>(space, slave_faces, master_faces, coords, normals, n_candidates,
                             candidates, pair_offsets, options, results);
}

/// 2D launch on the default execution space.
inline MortarStatus mortar_integrate_2d(
    Kokkos::View<const int**> slave_faces, Kokkos::View<const int**> master_faces,
    Kokkos::View<const double**> coords, Kokkos::View<const double**> normals,
    Kokkos::View<const int*> n_candidates, Kokkos::View<const int**> candidates,
    Kokkos::View<const int*> pair_offsets, const MortarOptions& options,
    Kokkos::View<MortarPairResult<double>*> results) {
  return mortar_integrate_2d(Kokkos::DefaultExecutionSpace(), slave_faces, master_faces, coords,
                             normals, n_candidates, candidates, pair_offsets, options, results);
}

}  // namespace grout
