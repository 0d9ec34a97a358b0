#pragma once
// Launch of the mortar pair kernels over all slave faces: for every slave face s and every
// candidate master face m of s (the CRS lists of coarse_search.hpp), integrate the pair and
// store its MortarPairResult at the pair's CRS position, results(candidate_offsets(s) + c). One
// labelled parallel_reduce per dimension, "grout::mortar_integrate<2D>" /
// "grout::mortar_integrate<3D>", whose max-reduced status is returned on the host (no_overlap is
// not an error: such pairs are stored with zeros).
//
// The per-dimension pair kernel is selected by MortarPairKernel<Dim>, which provides
//   SlaveFace                          per-slave data shared by all its candidates,
//   prepare(n_slave, xs, ns, options, slave)            once per slave face,
//   integrate(slave, n_master, xm, options, out)        once per candidate pair,
//   integrate(n_slave, xs, ns, n_master, xm, options, out)   both, for a single pair.
// MortarPairKernel<2>: integrate_mortar_2d / integrate_mortar_2d_collocation (mortar_2d.hpp);
// a slave segment with parallel nodal normals (flat parts of an interface) has an affine
// master map η(ξ), and n_gauss is then capped at 2, which is exact there.
// MortarPairKernel<3>: integrate_mortar_3d_dual / integrate_mortar_3d_collocation
// (mortar_3d.hpp); the dual coefficients A_e = D_e M_e⁻¹ (a 16-point mass matrix and a 4×4
// inverse on QUAD4) and the auxiliary plane depend on the slave face only and are computed once
// per slave face, and a candidate whose projection on the auxiliary plane has a bounding box
// separated from the slave's (by more than mortar_3d_reject_tolerance · size) is rejected before
// the clipping: the clipping would find no overlap either, so the results are unchanged.

#include <Kokkos_Core.hpp>
#include <cmath>
#include <type_traits>

#include "kernels/dual_basis_3d.hpp"
#include "kernels/mortar_2d.hpp"
#include "kernels/mortar_3d.hpp"
#include "kernels/mortar_matrices.hpp"
#include "kernels/mortar_pair_variables.hpp"
#include "kernels/mortar_types.hpp"
#include "kernels/multiplier_basis.hpp"
#include "kernels/surface_normals.hpp"

namespace grout {

/// Integration scheme of the pair kernels (typed once, from the input).
struct MortarOptions {
  MortarIntegration scheme = MortarIntegration::exact;
  int n_gauss = mortar_2d_gauss_points;  ///< Gauss points per 2D overlap segment (1..8)
  int n_collocation = 16;  ///< points per slave element for collocation (3D: k × k, k = ⌊√n⌋)
  /// 2D exact dual path only: x = r, every integral weighted by 2π r
  /// (integrate_mortar_2d_axisymmetric); the other paths refuse it (degenerate).
  bool axisymmetric = false;
};

/// \brief The MortarOptions of a scheme whose collocation points are counted as the input and
/// the API count them (docs/input.md, contact `collocation_points`): per slave element in 2D,
/// per direction in 3D (k × k points on a face).
inline MortarOptions mortar_options(int dim, MortarIntegration scheme, int collocation_points) {
  MortarOptions options;
  options.scheme = scheme;
  options.n_collocation = dim == 2 ? collocation_points : collocation_points * collocation_points;
  return options;
}

/// Relative separation (of the plane bounding boxes, in units of the pair's size) beyond which
/// a 3D candidate is rejected without clipping; far above the clipping tolerances (1e-12).
constexpr double mortar_3d_reject_tolerance = 1e-8;

/// Pair kernel of dimension Dim (specialised per dimension, see the file comment).
template <int Dim>
struct MortarPairKernel;

template <>
struct MortarPairKernel<2> {
  static constexpr const char* label = "grout::mortar_integrate<2D>";

  /// LINE2 slave face in 2D arrays.
  template <class Scalar>
  struct SlaveFace {
    int n_nodes;
    bool parallel_normals;  ///< n₁ ∥ n₂: η(ξ) is affine, Φ_j N²_l quadratic (2 points exact)
    Scalar xs[2][2], ns[2][2];
    MortarSlave2D<Scalar> segment;  ///< what the exact pair kernel needs of the slave
    /// Multiplier basis; its LINE2 coefficients are constants (multiplier_basis.hpp), built
    /// per pair by the full-D integrate only, not for the dual path.
    MultiplierBasis basis;
  };

  /// Copies the padded (max_face_nodes × 3) slave arrays and the basis; degenerate unless LINE2.
  template <class Scalar>
  KOKKOS_INLINE_FUNCTION static MortarStatus prepare(int n_slave,
                                                     const Scalar xs[max_face_nodes][3],
                                                     const Scalar ns[max_face_nodes][3],
                                                     const MortarOptions&, MultiplierBasis basis,
                                                     SlaveFace<Scalar>& slave) {
    slave.n_nodes = n_slave;
    slave.basis = basis;
    for (int k = 0; k < 2; ++k)
      for (int d = 0; d < 2; ++d) slave.xs[k][d] = xs[k][d], slave.ns[k][d] = ns[k][d];
    // Exactly parallel (double only: for a Fad scalar the derivatives of η(ξ) are not affine).
    slave.parallel_normals = std::is_same<Scalar, double>::value &&
                             ns[0][0] * ns[1][1] - ns[0][1] * ns[1][0] == 0.0 &&
                             ns[0][0] * ns[1][0] + ns[0][1] * ns[1][1] > 0.0;
    mortar_slave_2d(slave.xs, slave.ns, slave.segment);
    return n_slave == 2 ? MortarStatus::ok : MortarStatus::degenerate;
  }

  /// prepare for the dual basis.
  template <class Scalar>
  KOKKOS_INLINE_FUNCTION static MortarStatus prepare(int n_slave,
                                                     const Scalar xs[max_face_nodes][3],
                                                     const Scalar ns[max_face_nodes][3],
                                                     const MortarOptions& options,
                                                     SlaveFace<Scalar>& slave) {
    return prepare(n_slave, xs, ns, options, MultiplierBasis::dual, slave);
  }

  /// LINE2/LINE2 pair; only xm[0..1][0..1] are read.
  template <class Scalar>
  KOKKOS_INLINE_FUNCTION static MortarStatus integrate(const SlaveFace<Scalar>& slave, int n_master,
                                                       const Scalar xm[max_face_nodes][3],
                                                       const MortarOptions& options,
                                                       MortarPairResult<Scalar>& out) {
    if (slave.n_nodes != 2 || n_master != 2) {
      zero_pair_result_2d(out);
      return MortarStatus::degenerate;
    }
    const Scalar xm2[2][2] = {{xm[0][0], xm[0][1]}, {xm[1][0], xm[1][1]}};
    if (options.axisymmetric) {
      if (options.scheme == MortarIntegration::collocation) {
        zero_pair_result_2d(out);
        return MortarStatus::degenerate;
      }
      // One point more than the plane kernel for the factor r(ξ): with parallel slave normals
      // Φ_j N²_l r is cubic in ξ, so the 3-point rule is exact with a degree to spare.
      const int n_axi = slave.parallel_normals && options.n_gauss > 2 ? 3 : options.n_gauss + 1;
      return integrate_mortar_2d_axisymmetric(
          slave.segment, xm2, n_axi < max_gauss_line_points ? n_axi : max_gauss_line_points, out);
    }
    if (options.scheme == MortarIntegration::collocation)
      return integrate_mortar_2d_collocation(slave.xs, slave.ns, xm2, options.n_collocation, out);
    // With parallel slave normals the 2-point rule is exact (Φ_j N²_l quadratic in ξ).
    const int n_gauss = slave.parallel_normals && options.n_gauss > 2 ? 2 : options.n_gauss;
    return integrate_mortar_2d(slave.segment, xm2, n_gauss, out);
  }

  /// LINE2/LINE2 pair, full D_jk and M_jl with the basis of `prepare` (mortar_matrices.hpp).
  template <class Scalar>
  KOKKOS_INLINE_FUNCTION static MortarStatus integrate(const SlaveFace<Scalar>& slave, int n_master,
                                                       const Scalar xm[max_face_nodes][3],
                                                       const MortarOptions& options,
                                                       MortarPairMatrices<Scalar>& out) {
    if (slave.n_nodes != 2 || n_master != 2 || options.axisymmetric) {
      reset_pair_matrices(2, 2, out);
      return MortarStatus::degenerate;
    }
    const Scalar xm2[2][2] = {{xm[0][0], xm[0][1]}, {xm[1][0], xm[1][1]}};
    Scalar xs[max_face_nodes][3] = {}, A[max_face_nodes][max_face_nodes];
    for (int k = 0; k < 2; ++k)
      for (int d = 0; d < 2; ++d) xs[k][d] = slave.xs[k][d];
    if (multiplier_basis_coefficients(slave.basis, 2, 2, xs, A) != MortarStatus::ok) {
      reset_pair_matrices(2, 2, out);
      return MortarStatus::degenerate;
    }
    if (options.scheme == MortarIntegration::collocation)
      return integrate_mortar_matrices_2d_collocation(slave.xs, slave.ns, A, xm2,
                                                      options.n_collocation, out);
    // Parallel slave normals: N¹_j N¹_k and Φ_j N²_l are quadratic in ξ, 2 points are exact.
    const int n_gauss = slave.parallel_normals && options.n_gauss > 2 ? 2 : options.n_gauss;
    return integrate_mortar_matrices_2d(slave.segment, A, xm2, n_gauss, out);
  }

  /// LINE2/LINE2 pair from padded (max_face_nodes × 3) arrays; only [0..1][0..1] are read.
  template <class Scalar>
  KOKKOS_INLINE_FUNCTION static MortarStatus integrate(
      int n_slave, const Scalar xs[max_face_nodes][3], const Scalar ns[max_face_nodes][3],
      int n_master, const Scalar xm[max_face_nodes][3], const MortarOptions& options,
      MortarPairResult<Scalar>& out) {
    SlaveFace<Scalar> slave;
    prepare(n_slave, xs, ns, options, slave);
    return integrate(slave, n_master, xm, options, out);
  }
};

template <>
struct MortarPairKernel<3> {
  static constexpr const char* label = "grout::mortar_integrate<3D>";

  /// TRI3/QUAD4 slave face with its dual coefficients, auxiliary plane and plane bounding box.
  template <class Scalar>
  struct SlaveFace {
    int n_nodes;
    MortarStatus status;  ///< ok, or degenerate (every pair then returns degenerate)
    Scalar xs[max_face_nodes][3], ns[max_face_nodes][3];
    Scalar A[max_face_nodes][max_face_nodes];
    AuxiliaryPlane<Scalar> plane;
    Scalar lo[2], hi[2];  ///< bounding box of plane.ps
  };

  /// Basis coefficients (multiplier_basis_coefficients), auxiliary plane and its bounding box
  /// of one slave face.
  template <class Scalar>
  KOKKOS_INLINE_FUNCTION static MortarStatus prepare(int n_slave,
                                                     const Scalar xs[max_face_nodes][3],
                                                     const Scalar ns[max_face_nodes][3],
                                                     const MortarOptions&, MultiplierBasis basis,
                                                     SlaveFace<Scalar>& slave) {
    slave.n_nodes = n_slave;
    for (int k = 0; k < max_face_nodes; ++k)
      for (int d = 0; d < 3; ++d) slave.xs[k][d] = xs[k][d], slave.ns[k][d] = ns[k][d];
    slave.status = MortarStatus::degenerate;
    if (n_slave != 3 && n_slave != 4) return slave.status;
    if (multiplier_basis_coefficients(basis, 3, n_slave, slave.xs, slave.A) != MortarStatus::ok ||
        auxiliary_plane(n_slave, slave.xs, slave.plane) != MortarStatus::ok)
      return slave.status;
    for (int a = 0; a < 2; ++a) {
      slave.lo[a] = slave.hi[a] = slave.plane.ps[0][a];
      for (int k = 1; k < n_slave; ++k) {
        if (slave.plane.ps[k][a] < slave.lo[a]) slave.lo[a] = slave.plane.ps[k][a];
        if (slave.plane.ps[k][a] > slave.hi[a]) slave.hi[a] = slave.plane.ps[k][a];
      }
    }
    slave.status = MortarStatus::ok;
    return slave.status;
  }

  /// prepare for the dual basis.
  template <class Scalar>
  KOKKOS_INLINE_FUNCTION static MortarStatus prepare(int n_slave,
                                                     const Scalar xs[max_face_nodes][3],
                                                     const Scalar ns[max_face_nodes][3],
                                                     const MortarOptions& options,
                                                     SlaveFace<Scalar>& slave) {
    return prepare(n_slave, xs, ns, options, MultiplierBasis::dual, slave);
  }

  /// \brief True if the master face, projected on the slave's auxiliary plane, has a bounding
  /// box separated from the slave's by more than mortar_3d_reject_tolerance · (pair size).
  template <class Scalar>
  KOKKOS_INLINE_FUNCTION static bool separated(const SlaveFace<Scalar>& slave, int n_master,
                                               const Scalar xm[max_face_nodes][3]) {
    Scalar lo[2], hi[2];
    for (int l = 0; l < n_master; ++l) {
      Scalar y[2];
      project_on_plane(slave.plane, xm[l], y);
      for (int a = 0; a < 2; ++a) {
        if (l == 0 || y[a] < lo[a]) lo[a] = y[a];
        if (l == 0 || y[a] > hi[a]) hi[a] = y[a];
      }
    }
    Scalar size = 0.0;
    for (int a = 0; a < 2; ++a) {
      const Scalar ext =
          (hi[a] > slave.hi[a] ? hi[a] : slave.hi[a]) - (lo[a] < slave.lo[a] ? lo[a] : slave.lo[a]);
      size = ext > size ? ext : size;
    }
    const Scalar gap = mortar_3d_reject_tolerance * size;
    for (int a = 0; a < 2; ++a)
      if (lo[a] > slave.hi[a] + gap || hi[a] < slave.lo[a] - gap) return true;
    return false;
  }

  /// TRI3/QUAD4 × TRI3/QUAD4 pair, exact (integrate_mortar_3d_dual) or collocation with
  /// k = ⌊√n_collocation⌋ points per direction (integrate_mortar_3d_collocation).
  template <class Scalar>
  KOKKOS_INLINE_FUNCTION static MortarStatus integrate(const SlaveFace<Scalar>& slave, int n_master,
                                                       const Scalar xm[max_face_nodes][3],
                                                       const MortarOptions& options,
                                                       MortarPairResult<Scalar>& out) {
    detail3d::reset_pair_result(slave.n_nodes, n_master, out);
    if (slave.status != MortarStatus::ok || (n_master != 3 && n_master != 4))
      return MortarStatus::degenerate;
    if (separated(slave, n_master, xm)) return MortarStatus::no_overlap;
    if (options.scheme == MortarIntegration::collocation) {
      int k = 1;
      while ((k + 1) * (k + 1) <= options.n_collocation) ++k;
      return integrate_mortar_3d_collocation_dual(slave.n_nodes, slave.xs, slave.A, n_master, xm, k,
                                                  out);
    }
    return integrate_mortar_3d_dual(slave.n_nodes, slave.xs, slave.A, n_master, xm, out);
  }

  /// The same pair with the full D_jk and M_jl, basis of `prepare` (mortar_matrices.hpp).
  template <class Scalar>
  KOKKOS_INLINE_FUNCTION static MortarStatus integrate(const SlaveFace<Scalar>& slave, int n_master,
                                                       const Scalar xm[max_face_nodes][3],
                                                       const MortarOptions& options,
                                                       MortarPairMatrices<Scalar>& out) {
    reset_pair_matrices(slave.n_nodes, n_master, out);
    if (slave.status != MortarStatus::ok || (n_master != 3 && n_master != 4))
      return MortarStatus::degenerate;
    if (separated(slave, n_master, xm)) return MortarStatus::no_overlap;
    if (options.scheme == MortarIntegration::collocation) {
      int k = 1;
      while ((k + 1) * (k + 1) <= options.n_collocation) ++k;
      return integrate_mortar_matrices_3d_collocation(slave.n_nodes, slave.xs, slave.A, n_master,
                                                      xm, k, out);
    }
    return integrate_mortar_matrices_3d(slave.n_nodes, slave.xs, slave.A, n_master, xm, out);
  }

  /// One pair from padded (max_face_nodes × 3) arrays (prepare + integrate).
  template <class Scalar>
  KOKKOS_INLINE_FUNCTION static MortarStatus integrate(
      int n_slave, const Scalar xs[max_face_nodes][3], const Scalar ns[max_face_nodes][3],
      int n_master, const Scalar xm[max_face_nodes][3], const MortarOptions& options,
      MortarPairResult<Scalar>& out) {
    SlaveFace<Scalar> slave;
    prepare(n_slave, xs, ns, options, slave);
    return integrate(slave, n_master, xm, options, out);
  }
};

namespace detail {

/// Seeds no variable (seed_face): the pair is integrated in plain values.
struct NoSeed {
  KOKKOS_INLINE_FUNCTION int operator()(int, int) const { return -1; }
};

/// The launch shared by mortar_integrate, mortar_integrate_matrices, mortar_integrate_each and
/// mortar_integrate_gradients: one work item per slave face (gathered and prepared once, in
/// Scalar), looping over its candidates; pair(p, slave, n_master, xm, s) integrates candidate p
/// and returns its status. Scalar is double, or a Sacado SFad whose variables
/// seeds.slave/normal/master(a, d) number among Seeds::count (the slave coordinates, the slave
/// nodal normals and the master coordinates; −1: not a variable). capacity: the number of pair
/// slots the caller has (the candidates' CRS end must fit in it).
template <int Dim, class Scalar, class ExecSpace, class PairIntegrator, class Seeds>
MortarStatus mortar_integrate_launch(
    const ExecSpace& space, Kokkos::View<const int**, typename ExecSpace::memory_space> slave_faces,
    Kokkos::View<const int**, typename ExecSpace::memory_space> master_faces,
    Kokkos::View<const double**, typename ExecSpace::memory_space> coords,
    Kokkos::View<const double**, typename ExecSpace::memory_space> normals,
    Kokkos::View<const int*, typename ExecSpace::memory_space> candidate_offsets,
    Kokkos::View<const int*, typename ExecSpace::memory_space> candidates, MultiplierBasis basis,
    const MortarOptions& options, size_t capacity, const PairIntegrator& pair, const Seeds& seeds) {
  static_assert(Dim == 2 || Dim == 3, "grout::mortar_integrate: Dim must be 2 or 3");
  const size_t n_s = slave_faces.extent(0);
  if (static_cast<int>(coords.extent(1)) != Dim || normals.extent(0) != coords.extent(0) ||
      static_cast<int>(normals.extent(1)) != Dim || candidate_offsets.extent(0) != n_s + 1)
    return MortarStatus::degenerate;
  if (candidates.extent(0) < capacity) capacity = candidates.extent(0);
  int status = 0;
  Kokkos::parallel_reduce(
      Seeds::label(MortarPairKernel<Dim>::label), Kokkos::RangePolicy<ExecSpace>(space, 0, n_s),
      KOKKOS_LAMBDA(const int s, int& worst) {
        using Kernel = MortarPairKernel<Dim>;
        double xs[max_face_nodes][3], ns[max_face_nodes][3], xm[max_face_nodes][3];
        const int n_slave = gather_face_coordinates(slave_faces, s, coords, xs);
        gather_face_coordinates(slave_faces, s, normals, ns);
        const int begin = candidate_offsets(s), end = candidate_offsets(s + 1);
        if (end > static_cast<int>(capacity)) {
          worst = static_cast<int>(MortarStatus::capacity_exceeded);
          return;
        }
        Scalar xs_s[max_face_nodes][3], ns_s[max_face_nodes][3], xm_s[max_face_nodes][3];
        seed_face(n_slave, xs, xs_s, seeds.slave, Seeds::count);
        seed_face(n_slave, ns, ns_s, seeds.normal, Seeds::count);
        typename Kernel::template SlaveFace<Scalar> slave;
        Kernel::prepare(n_slave, xs_s, ns_s, options, basis, slave);
        for (int p = begin; p < end; ++p) {
          const int n_master = gather_face_coordinates(master_faces, candidates(p), coords, xm);
          seed_face(n_master, xm, xm_s, seeds.master, Seeds::count);
          const MortarStatus st = pair(p, slave, n_master, xm_s, s);
          const int code = st == MortarStatus::no_overlap ? 0 : static_cast<int>(st);
          worst = code > worst ? code : worst;
        }
      },
      Kokkos::Max<int>(status));
  status = status > 0 ? status : 0;  // Max starts from INT_MIN (empty range)
  return static_cast<MortarStatus>(status);
}

/// The seeds of the values-only launches: no variable, the label of the pair kernel.
struct ValueSeeds {
  static constexpr int count = 0;
  NoSeed slave, normal, master;
  static const char* label(const char* kernel_label) { return kernel_label; }
};

/// Pair integrator of mortar_integrate(_matrices): into the caller's array, results(p).
template <int Dim, class ResultView>
struct StorePair {
  ResultView results;
  MortarOptions options;
  template <class SlaveFace>
  KOKKOS_INLINE_FUNCTION MortarStatus operator()(int p, const SlaveFace& slave, int n_master,
                                                 const double (&xm)[max_face_nodes][3], int) const {
    return MortarPairKernel<Dim>::integrate(slave, n_master, xm, options, results(p));
  }
};

/// Pair integrator of mortar_integrate_each: into a local Pair, handed to sink(s, p, pair).
template <int Dim, class Pair, class PairSink>
struct SinkPair {
  PairSink sink;
  MortarOptions options;
  template <class SlaveFace>
  KOKKOS_INLINE_FUNCTION MortarStatus operator()(int p, const SlaveFace& slave, int n_master,
                                                 const double (&xm)[max_face_nodes][3],
                                                 int s) const {
    Pair pair;
    const MortarStatus st = MortarPairKernel<Dim>::integrate(slave, n_master, xm, options, pair);
    sink(s, p, pair);
    return st;
  }
};

/// The launch of mortar_integrate and mortar_integrate_matrices, for either result type.
template <int Dim, class ExecSpace, class ResultView>
MortarStatus mortar_integrate_pairs(
    const ExecSpace& space, Kokkos::View<const int**, typename ExecSpace::memory_space> slave_faces,
    Kokkos::View<const int**, typename ExecSpace::memory_space> master_faces,
    Kokkos::View<const double**, typename ExecSpace::memory_space> coords,
    Kokkos::View<const double**, typename ExecSpace::memory_space> normals,
    Kokkos::View<const int*, typename ExecSpace::memory_space> candidate_offsets,
    Kokkos::View<const int*, typename ExecSpace::memory_space> candidates, MultiplierBasis basis,
    const MortarOptions& options, ResultView results) {
  return mortar_integrate_launch<Dim, double>(
      space, slave_faces, master_faces, coords, normals, candidate_offsets, candidates, basis,
      options, results.extent(0), StorePair<Dim, ResultView>{results, options}, ValueSeeds{});
}

/// The launch of mortar_integrate_each: as mortar_integrate_pairs, each pair integrated into a
/// local Pair and handed to sink(s, p, pair) instead of stored.
template <int Dim, class Pair, class ExecSpace, class PairSink>
MortarStatus mortar_integrate_to_sink(
    const ExecSpace& space, Kokkos::View<const int**, typename ExecSpace::memory_space> slave_faces,
    Kokkos::View<const int**, typename ExecSpace::memory_space> master_faces,
    Kokkos::View<const double**, typename ExecSpace::memory_space> coords,
    Kokkos::View<const double**, typename ExecSpace::memory_space> normals,
    Kokkos::View<const int*, typename ExecSpace::memory_space> candidate_offsets,
    Kokkos::View<const int*, typename ExecSpace::memory_space> candidates, MultiplierBasis basis,
    const MortarOptions& options, const PairSink& sink) {
  return mortar_integrate_launch<Dim, double>(
      space, slave_faces, master_faces, coords, normals, candidate_offsets, candidates, basis,
      options, candidates.extent(0), SinkPair<Dim, Pair, PairSink>{sink, options}, ValueSeeds{});
}

}  // namespace detail

/// \brief Integrates every (slave face, candidate master face) pair with MortarPairKernel<Dim>,
/// dual basis (D_jj per slave node).
/// \pre slave_faces, master_faces: (n, ≤ max_face_nodes) node ids, −1 padding; coords and unit
/// nodal normals: (n_nodes, Dim); candidate_offsets (n_slave + 1) and candidates
/// (≥ candidate_offsets(n_slave)): the CRS lists of coarse_search (SearchCandidates offsets and
/// masters); results: (≥ candidate_offsets(n_slave)), pair c of slave s at
/// candidate_offsets(s) + c. \return the worst pair status other than no_overlap (ok if all
/// pairs succeeded), degenerate for inconsistent sizes, capacity_exceeded if results is short.
template <int Dim, class ExecSpace>
MortarStatus mortar_integrate(
    const ExecSpace& space, Kokkos::View<const int**, typename ExecSpace::memory_space> slave_faces,
    Kokkos::View<const int**, typename ExecSpace::memory_space> master_faces,
    Kokkos::View<const double**, typename ExecSpace::memory_space> coords,
    Kokkos::View<const double**, typename ExecSpace::memory_space> normals,
    Kokkos::View<const int*, typename ExecSpace::memory_space> candidate_offsets,
    Kokkos::View<const int*, typename ExecSpace::memory_space> candidates,
    const MortarOptions& options,
    Kokkos::View<MortarPairResult<double>*, typename ExecSpace::memory_space> results) {
  return detail::mortar_integrate_pairs<Dim>(space, slave_faces, master_faces, coords, normals,
                                             candidate_offsets, candidates, MultiplierBasis::dual,
                                             options, results);
}

/// \brief mortar_integrate with the full pair matrices D_jk, M_jl of the multiplier basis
/// `basis` (MortarPairMatrices; for the standard basis, whose D is not diagonal). Same launch
/// label, arguments and return as mortar_integrate.
template <int Dim, class ExecSpace>
MortarStatus mortar_integrate_matrices(
    const ExecSpace& space, Kokkos::View<const int**, typename ExecSpace::memory_space> slave_faces,
    Kokkos::View<const int**, typename ExecSpace::memory_space> master_faces,
    Kokkos::View<const double**, typename ExecSpace::memory_space> coords,
    Kokkos::View<const double**, typename ExecSpace::memory_space> normals,
    Kokkos::View<const int*, typename ExecSpace::memory_space> candidate_offsets,
    Kokkos::View<const int*, typename ExecSpace::memory_space> candidates, MultiplierBasis basis,
    const MortarOptions& options,
    Kokkos::View<MortarPairMatrices<double>*, typename ExecSpace::memory_space> results) {
  return detail::mortar_integrate_pairs<Dim>(space, slave_faces, master_faces, coords, normals,
                                             candidate_offsets, candidates, basis, options,
                                             results);
}

/// \brief mortar_integrate (Pair = MortarPairResult<double>: dual basis) or
/// mortar_integrate_matrices (Pair = MortarPairMatrices<double>: the basis `basis`) without a
/// pair array: each pair is integrated into a local Pair and handed to sink(s, p, pair) (slave
/// face s, CRS position p; called once per candidate, no_overlap and failed pairs with their
/// zeroed result), which keeps what the caller needs of it (e.g. a compact copy, where the
/// padded Pair is sized for QUAD4 × QUAD4). Same launch label, arguments and return as
/// mortar_integrate (MortarPairResult: degenerate unless basis is dual).
/// \pre sink(s, p, pair) writes nothing that another slave face's call writes (faces run in
/// parallel).
template <int Dim, class Pair, class ExecSpace, class PairSink>
MortarStatus mortar_integrate_each(
    const ExecSpace& space, Kokkos::View<const int**, typename ExecSpace::memory_space> slave_faces,
    Kokkos::View<const int**, typename ExecSpace::memory_space> master_faces,
    Kokkos::View<const double**, typename ExecSpace::memory_space> coords,
    Kokkos::View<const double**, typename ExecSpace::memory_space> normals,
    Kokkos::View<const int*, typename ExecSpace::memory_space> candidate_offsets,
    Kokkos::View<const int*, typename ExecSpace::memory_space> candidates, MultiplierBasis basis,
    const MortarOptions& options, const PairSink& sink) {
  constexpr bool dual = std::is_same<Pair, MortarPairResult<double>>::value;
  static_assert(dual || std::is_same<Pair, MortarPairMatrices<double>>::value,
                "grout::mortar_integrate_each: Pair is MortarPairResult<double> (dual basis) or "
                "MortarPairMatrices<double>");
  if (dual && basis != MultiplierBasis::dual) return MortarStatus::degenerate;  // D not diagonal
  return detail::mortar_integrate_to_sink<Dim, Pair>(space, slave_faces, master_faces, coords,
                                                     normals, candidate_offsets, candidates, basis,
                                                     options, sink);
}

/// mortar_integrate<2> (launch "grout::mortar_integrate<2D>") on the default execution space.
inline MortarStatus mortar_integrate_2d(
    Kokkos::View<const int**> slave_faces, Kokkos::View<const int**> master_faces,
    Kokkos::View<const double**> coords, Kokkos::View<const double**> normals,
    Kokkos::View<const int*> candidate_offsets, Kokkos::View<const int*> candidates,
    const MortarOptions& options, Kokkos::View<MortarPairResult<double>*> results) {
  return mortar_integrate<2>(Kokkos::DefaultExecutionSpace(), slave_faces, master_faces, coords,
                             normals, candidate_offsets, candidates, options, results);
}

/// mortar_integrate<3> (launch "grout::mortar_integrate<3D>") on the default execution space.
inline MortarStatus mortar_integrate_3d(
    Kokkos::View<const int**> slave_faces, Kokkos::View<const int**> master_faces,
    Kokkos::View<const double**> coords, Kokkos::View<const double**> normals,
    Kokkos::View<const int*> candidate_offsets, Kokkos::View<const int*> candidates,
    const MortarOptions& options, Kokkos::View<MortarPairResult<double>*> results) {
  return mortar_integrate<3>(Kokkos::DefaultExecutionSpace(), slave_faces, master_faces, coords,
                             normals, candidate_offsets, candidates, options, results);
}

}  // namespace grout
