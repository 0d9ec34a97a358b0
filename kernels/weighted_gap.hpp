#pragma once
// Weighted gap and weighted slip increment per slave node from (slave, master) pair results
// (docs/design.md §2; Popp et al. 2010, eq. 30; Gitterle, Popp, Gee, Wall, IJNME 84 (2010) §3):
//
//   g̃_j     = −n_j · (D_jj x¹_j − Σ_l M_jl x²_l)          (positive = open)
//   ũ_τ,j   =  τ_j · (D_jj Δx¹_j − Σ_l M_jl Δx²_l)        (increment over a step)
//   ũ^obj_τ,j = −τ_j · ((D_jj − Dⁿ_jj) x¹_j − Σ_l (M_jl − Mⁿ_jl) x²_l)   (frame-indifferent)
//
// Each is linear in (D, M), so a node's value is the sum of its pairs' contributions: the
// *_pair functions return one pair's contribution for each slave node of the pair. They work
// in 2D and 3D (Dim) and are templated on the scalar.

#include <Kokkos_Core.hpp>

#include "kernels/mortar_types.hpp"

namespace grout {

/// \brief v_j = D_jj u¹_j − Σ_l M_jl u²_l for the slave nodes j of one pair (u = x or Δx).
template <int Dim, class Scalar>
KOKKOS_INLINE_FUNCTION void mortar_weighted_vector(const MortarPairResult<Scalar>& pair,
                                                   const Scalar us[][Dim], const Scalar um[][Dim],
                                                   Scalar v[max_face_nodes][Dim]) {
  for (int j = 0; j < pair.n_slave; ++j)
    for (int d = 0; d < Dim; ++d) {
      v[j][d] = pair.D[j] * us[j][d];
      for (int l = 0; l < pair.n_master; ++l) v[j][d] -= pair.M[j][l] * um[l][d];
    }
}

/// \brief v = D_jj x¹_j − Σ_l M_jl x²_l of one assembled slave row j (the sum of
/// mortar_weighted_vector over j's pairs), a < dim. The row's masters l < n_masters are given
/// by their weights M(l) and positions xm(l, a); x may equally be a displacement or an
/// increment (the tied row, the contact work).
template <class Scalar, class MasterWeight, class MasterPosition>
KOKKOS_INLINE_FUNCTION void mortar_row_weighted_vector(int dim, const Scalar& D, const Scalar* xs,
                                                       int n_masters, const MasterWeight& M,
                                                       const MasterPosition& xm, Scalar* v) {
  for (int a = 0; a < dim; ++a) {
    v[a] = D * xs[a];
    for (int l = 0; l < n_masters; ++l) v[a] -= M(l) * xm(l, a);
  }
}

/// \brief The weighted gap of one assembled slave row, g̃_j = −n_j · v_j with v_j of
/// mortar_row_weighted_vector (positive = open); the nodal gap is g_j = g̃_j / D_jj.
template <class Scalar>
KOKKOS_INLINE_FUNCTION Scalar weighted_gap_of_row(int dim, const Scalar* n, const Scalar* v) {
  Scalar g = 0.0;
  for (int a = 0; a < dim; ++a) g -= n[a] * v[a];
  return g;
}

/// \brief One pair's contribution to g̃_j = −n_j · (D_jj x¹_j − Σ_l M_jl x²_l), j < n_slave.
/// \pre ns: unit slave nodal normals (outward from the slave body).
template <int Dim, class Scalar>
KOKKOS_INLINE_FUNCTION void weighted_gap_pair(const MortarPairResult<Scalar>& pair,
                                              const Scalar xs[][Dim], const Scalar ns[][Dim],
                                              const Scalar xm[][Dim], Scalar g[max_face_nodes]) {
  Scalar v[max_face_nodes][Dim];
  mortar_weighted_vector<Dim>(pair, xs, xm, v);
  for (int j = 0; j < pair.n_slave; ++j) {
    g[j] = -ns[j][0] * v[j][0];
    for (int d = 1; d < Dim; ++d) g[j] -= ns[j][d] * v[j][d];
  }
}

/// \brief One pair's contribution to ũ_τ,j = τ_j · (D_jj Δx¹_j − Σ_l M_jl Δx²_l) for one
/// tangent direction τ_j (2D: the tangent; 3D: call once per tangent).
template <int Dim, class Scalar>
KOKKOS_INLINE_FUNCTION void weighted_slip_increment_pair(const MortarPairResult<Scalar>& pair,
                                                         const Scalar dxs[][Dim],
                                                         const Scalar tau[][Dim],
                                                         const Scalar dxm[][Dim],
                                                         Scalar slip[max_face_nodes]) {
  Scalar v[max_face_nodes][Dim];
  mortar_weighted_vector<Dim>(pair, dxs, dxm, v);
  for (int j = 0; j < pair.n_slave; ++j) {
    slip[j] = tau[j][0] * v[j][0];
    for (int d = 1; d < Dim; ++d) slip[j] += tau[j][d] * v[j][d];
  }
}

/// \brief Frame-indifferent weighted slip increment (Gitterle et al. 2010):
/// ũ_τ,j = −τ_j · ((D_jj − Dⁿ_jj) x¹_j − Σ_l (M_jl − Mⁿ_jl) x²_l), with `pair` at the current
/// and `pair_old` at the last converged configuration of the same (slave, master) pair, x current.
/// To first order it equals weighted_slip_increment_pair, and it vanishes under rigid motion.
template <int Dim, class Scalar>
KOKKOS_INLINE_FUNCTION void weighted_slip_increment_objective_pair(
    const MortarPairResult<Scalar>& pair, const MortarPairResult<Scalar>& pair_old,
    const Scalar xs[][Dim], const Scalar tau[][Dim], const Scalar xm[][Dim],
    Scalar slip[max_face_nodes]) {
  MortarPairResult<Scalar> diff;
  diff.n_slave = pair.n_slave;
  diff.n_master = pair.n_master;
  diff.overlap = pair.overlap - pair_old.overlap;
  for (int j = 0; j < max_face_nodes; ++j) {
    diff.D[j] = pair.D[j] - pair_old.D[j];
    for (int l = 0; l < max_face_nodes; ++l) diff.M[j][l] = pair.M[j][l] - pair_old.M[j][l];
  }
  weighted_slip_increment_pair<Dim>(diff, xs, tau, xm, slip);
  for (int j = 0; j < pair.n_slave; ++j) slip[j] = -slip[j];
}

/// \brief Nodal weighted gaps g̃ (n_nodes) summed over every candidate pair, launch
/// "grout::weighted_gap". Inputs as for mortar_integrate_2d (mortar_integrate.hpp): faces with
/// −1 padding, coords and unit nodal normals (n_nodes, dim), the CRS candidate lists
/// (candidate_offsets, candidates) of coarse_search and the pair results of that integration
/// (pair p at the CRS position p). g̃ is zeroed first.
template <class ExecSpace>
void accumulate_weighted_gaps(
    const ExecSpace& space, Kokkos::View<const int**, typename ExecSpace::memory_space> slave_faces,
    Kokkos::View<const int**, typename ExecSpace::memory_space> master_faces,
    Kokkos::View<const double**, typename ExecSpace::memory_space> coords,
    Kokkos::View<const double**, typename ExecSpace::memory_space> normals,
    Kokkos::View<const int*, typename ExecSpace::memory_space> candidate_offsets,
    Kokkos::View<const int*, typename ExecSpace::memory_space> candidates,
    Kokkos::View<const MortarPairResult<double>*, typename ExecSpace::memory_space> results,
    Kokkos::View<double*, typename ExecSpace::memory_space> g_tilde) {
  const int dim = static_cast<int>(coords.extent(1));
  Kokkos::deep_copy(space, g_tilde, 0.0);
  Kokkos::parallel_for(
      "grout::weighted_gap", Kokkos::RangePolicy<ExecSpace>(space, 0, slave_faces.extent(0)),
      KOKKOS_LAMBDA(const int s) {
        for (int p = candidate_offsets(s); p < candidate_offsets(s + 1); ++p) {
          const MortarPairResult<double>& pair = results(p);
          const int m = candidates(p);
          for (int j = 0; j < pair.n_slave; ++j) {
            const int node = slave_faces(s, j);
            double v = 0.0;
            for (int d = 0; d < dim; ++d) {
              double vd = pair.D[j] * coords(node, d);
              for (int l = 0; l < pair.n_master; ++l)
                vd -= pair.M[j][l] * coords(master_faces(m, l), d);
              v -= normals(node, d) * vd;
            }
            Kokkos::atomic_add(&g_tilde(node), v);
          }
        }
      });
}

/// Default-execution-space overload of accumulate_weighted_gaps.
inline void accumulate_weighted_gaps(
    Kokkos::View<const int**> slave_faces, Kokkos::View<const int**> master_faces,
    Kokkos::View<const double**> coords, Kokkos::View<const double**> normals,
    Kokkos::View<const int*> candidate_offsets, Kokkos::View<const int*> candidates,
    Kokkos::View<const MortarPairResult<double>*> results, Kokkos::View<double*> g_tilde) {
  accumulate_weighted_gaps(Kokkos::DefaultExecutionSpace(), slave_faces, master_faces, coords,
                           normals, candidate_offsets, candidates, results, g_tilde);
}

}  // namespace grout
