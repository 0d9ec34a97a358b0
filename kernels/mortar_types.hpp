#pragma once
// Plain data shared by the 2D and 3D mortar kernels.
//
// One (slave element, master element) pair contributes, on their overlap Γ_e ∩ χ⁻¹(Γ_m):
//   D_jk = ∫ Φ_j N¹_k dA  (diagonal for the dual basis Φ: only D_jj is stored)
//   M_jl = ∫ Φ_j (N²_l ∘ χ) dA
// (docs/design.md §2; Popp et al. 2010, eqs. 9-10). A later scatter sums the pair contributions
// per slave node j / master node l.

#include "kernels/kernel_macros.hpp"

namespace grout {

constexpr int max_face_nodes = 4;     ///< line2: 2, tri3: 3, quad4: 4
constexpr int max_clip_vertices = 8;  ///< convex tri/quad x tri/quad clip polygon

enum class MortarStatus : int {
  ok = 0,
  no_overlap = 1,         ///< the pair does not overlap (contributes nothing)
  degenerate = 2,         ///< zero-length/area slave element or normal
  projection_failed = 3,  ///< a local Newton projection did not converge
  capacity_exceeded = 4   ///< more vertices/points than the fixed capacities
};

enum class MortarIntegration : int { exact = 0, collocation = 1 };

/// Lagrange multiplier basis Φ_j on the slave (multiplier_basis.hpp): `dual` (biorthogonal,
/// D diagonal; Grout's driver) or `standard` (Φ_j = N¹_j, D a full slave × slave matrix).
enum class MultiplierBasis : int { dual = 0, standard = 1 };

/// Contribution of one (slave element, master element) pair.
template <class Scalar>
struct MortarPairResult {
  int n_slave = 0;                           ///< nodes of the slave element
  int n_master = 0;                          ///< nodes of the master element
  Scalar overlap;                            ///< measure of the integration domain (length or area)
  Scalar D[max_face_nodes];                  ///< D_jj (dual basis: D is diagonal)
  Scalar M[max_face_nodes][max_face_nodes];  ///< M_jl, j slave node, l master node
};

/// Contribution of one pair with the full D: D_jk = ∫ Φ_j N¹_k dA (slave nodes j, k), for
/// bases whose D is not diagonal (MultiplierBasis::standard; mortar_matrices.hpp).
template <class Scalar>
struct MortarPairMatrices {
  int n_slave = 0;
  int n_master = 0;
  Scalar overlap;
  Scalar D[max_face_nodes][max_face_nodes];  ///< D_jk, j, k slave nodes
  Scalar M[max_face_nodes][max_face_nodes];  ///< M_jl, j slave node, l master node
};

}  // namespace grout
