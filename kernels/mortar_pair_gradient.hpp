#pragma once
// The mortar pair terms with their exact first derivatives: the launch of mortar_integrate.hpp
// run in Sacado forward AD. For every (slave face, candidate master face) pair,
//
//   D_jj = ∫ Φ_j N¹_j dA,   M_jl = ∫ Φ_j (N²_l ∘ χ) dA          (docs/design.md, "Mortar terms")
//
// and ∂D_jj/∂v, ∂M_jl/∂v for the pair variables v (MortarPairVariables): the slave and master
// nodal coordinates, and in 2D the slave nodal normals that the projection χ follows. The
// integration is the pair kernel of MortarPairKernel<Dim> itself, on SFad<double, count>
// scalars (Sacado forward AD: the derivatives are those of the operations, exact to round-off,
// including those of the segment end points, the clip polygon and the dual coefficients A_e).
// The caller chains the normal variables with ∂n_j/∂x (slave_frames.hpp) and scatters
// (assembly/contact_mortar.cpp): each pair is computed here, summed there.

#include <Kokkos_Core.hpp>

#include "kernels/mortar_integrate.hpp"
#include "kernels/mortar_pair_variables.hpp"

namespace grout {

namespace detail {

/// The seeds of the derivative launch (MortarPairVariables<Dim>) and its label.
template <int Dim>
struct GradientSeeds {
  static constexpr int count = MortarPairVariables<Dim>::count;
  typename MortarPairVariables<Dim>::Slave slave;
  typename MortarPairVariables<Dim>::Normal normal;
  typename MortarPairVariables<Dim>::Master master;
  static const char* label(const char*) {
    return Dim == 2 ? "grout::mortar_integrate_ad<2D>" : "grout::mortar_integrate_ad<3D>";
  }
};

/// Pair integrator of mortar_integrate_gradients: integrate in the launch's scalar
/// (MortarPairFad<Dim> with derivatives, double without), store results(p) (store_pair_gradient).
template <int Dim, class ResultView>
struct StorePairTerms {
  ResultView results;
  MortarOptions options;
  template <class SlaveFace, class Scalar>
  KOKKOS_INLINE_FUNCTION MortarStatus operator()(int p, const SlaveFace& slave, int n_master,
                                                 const Scalar (&xm)[max_face_nodes][3], int) const {
    MortarPairResult<Scalar> pair;
    const MortarStatus st = MortarPairKernel<Dim>::integrate(slave, n_master, xm, options, pair);
    store_pair_gradient<Dim>(st, pair, slave.n_nodes, n_master, results(p));
    return st;
  }
};

}  // namespace detail

/// \brief mortar_integrate (dual basis) with exact derivatives: launch
/// "grout::mortar_integrate_ad<2D>" / "<3D>", one work item per slave face (its dual coefficients
/// and auxiliary plane prepared once in AD), results(candidate_offsets(s) + c) for candidate c of
/// slave face s. Same arguments and return as mortar_integrate; a failed or non-overlapping pair
/// is stored with its status only. With a View of MortarPairValues the same launch runs in double
/// (label "grout::mortar_integrate<2D>" / "<3D>", mortar_integrate's) and stores values only.
/// \pre normals: the unit slave nodal normals (2D: the projection direction; their derivatives
/// are the normal variables' chain, slave_frames.hpp). Pair: MortarPairGradient<Dim> or
/// MortarPairValues<Dim>.
template <int Dim, class Pair, class ExecSpace>
MortarStatus mortar_integrate_gradients(
    const ExecSpace& space, Kokkos::View<const int**, typename ExecSpace::memory_space> slave_faces,
    Kokkos::View<const int**, typename ExecSpace::memory_space> master_faces,
    Kokkos::View<const double**, typename ExecSpace::memory_space> coords,
    Kokkos::View<const double**, typename ExecSpace::memory_space> normals,
    Kokkos::View<const int*, typename ExecSpace::memory_space> candidate_offsets,
    Kokkos::View<const int*, typename ExecSpace::memory_space> candidates,
    const MortarOptions& options, Kokkos::View<Pair*, typename ExecSpace::memory_space> results) {
  constexpr bool derivatives = std::is_same<Pair, MortarPairGradient<Dim>>::value;
  static_assert(derivatives || std::is_same<Pair, MortarPairValues<Dim>>::value,
                "grout::mortar_integrate_gradients: results of MortarPairGradient<Dim> or "
                "MortarPairValues<Dim>");
  using Results = Kokkos::View<Pair*, typename ExecSpace::memory_space>;
  using Scalar = std::conditional_t<derivatives, MortarPairFad<Dim>, double>;
  using Seeds = std::conditional_t<derivatives, detail::GradientSeeds<Dim>, detail::ValueSeeds>;
  return detail::mortar_integrate_launch<Dim, Scalar>(
      space, slave_faces, master_faces, coords, normals, candidate_offsets, candidates,
      MultiplierBasis::dual, options, results.extent(0),
      detail::StorePairTerms<Dim, Results>{results, options}, Seeds{});
}

}  // namespace grout
