#pragma once
// The mortar quantities of one contact interface at the current configuration, with their
// exact derivatives with respect to the displacement dofs (docs/design.md, "Linearisation"):
// slave nodal normals/tangents n_j, τ_j, the dual-mortar D_jj and M_jl summed over all
// (slave, master) pairs. Computed by the kernel launches (kernels/slave_frames.hpp: the frames
// and ∂frame/∂x per face around a node; kernels/mortar_pair_gradient.hpp: each pair's D, M and
// their derivatives with respect to the pair's nodal positions and, in 2D, the slave nodal
// normals, by Sacado forward AD through the pair kernels), then summed here per slave node with
// the chain rule through ∂n/∂x: compute per pair in the launches, scatter in one place.

#include <map>
#include <utility>
#include <vector>

#include "assembly/contact_surface.hpp"
#include "kernels/mortar_integrate.hpp"

namespace grout {

/// Derivative of a scalar with respect to global dofs (node * dim + component); entries
/// may repeat (they add up).
using SparseGradient = std::vector<std::pair<long long, double>>;

struct MortarValue {
  double value = 0.0;
  SparseGradient gradient;
};

struct SlaveFrame {
  double n[3] = {0.0, 0.0, 0.0};   ///< unit averaged normal, outward from the slave body
  double t[2][3] = {};             ///< unit tangents (one in 2D)
  SparseGradient dn[3], dt[2][3];  ///< their derivatives
};

struct ContactMortarOptions {
  MortarOptions mortar;        ///< the pair kernels' scheme and points (mortar_options)
  double search_factor = 0.5;  ///< bounding boxes grown by this fraction of their size
  bool derivatives = true;
};

struct ContactMortar {
  std::vector<SlaveFrame> frames;  ///< per slave node
  std::vector<MortarValue> D;      ///< D_jj per slave node
  /// w_j = ∫ N¹_j dA over the slave node's faces (face_node_weight), per slave node: D_jj = w_j
  /// when the faces are fully covered (0 for nodes of no evaluated face).
  std::vector<double> W;
  std::map<std::pair<int, GlobalIndex>, MortarValue> M;  ///< (slave node index, master node)
  int pairs = 0;                                         ///< pairs with a non-empty overlap
};

/// Dual coverage a slave node needs to count as paired in the contact rows (dual_covered).
constexpr double min_dual_coverage = 0.5;

/// \brief Whether slave node j's faces are covered enough for the contact rows to use its
/// nodal gap g_j = g̃_j / D_jj: D_jj ≥ min_dual_coverage · w_j (the driver applies it to
/// contact, not to tied rows, and holds it within a step: ContactInterface::paired). With
/// dual multipliers a node whose faces a master covers only in part has D_jj = ∫_cov Φ_j dA,
/// and Φ_j changes sign on each face, so g̃_j / D_jj is not a mean of the gap over the covered
/// part: where the gap varies across a small covered part it is an extrapolation that can lie
/// far outside the gap's range (a false penetration; docs/embedding.md, "Partly covered
/// rows"). The crossed tubes' flank nodes, covered by slivers of the lower tube's steep faces,
/// closed this way 4 cm clear of it (inputs/self_contact/README.md, "Step control on this
/// path"). Fully covered nodes (D_jj = w_j) are unaffected.
inline bool dual_covered(const ContactMortar& m, int j) {
  return m.D[j].value >= min_dual_coverage * m.W[j];
}

/// Sorts g by dof and sums the entries of each dof (in their order in g, so the result is
/// deterministic), dropping exact zeros: each dof then appears once.
void compress_gradient(SparseGradient& g);

/// Evaluate at positions x (x[i] = position of surface.nodes[i], 3 components), over the
/// slave faces surface.integrate selects (all if it is empty): D, M and frames are complete
/// for the slave nodes all of whose faces are selected; frames are left empty for slave
/// nodes of no selected face. Pairs are summed in (slave face, master face) order. The D
/// and M gradients are compressed (compress_gradient).
///
/// `search_x` (optional, positions like x): the (slave, master) candidate pairs are those of
/// a coarse search on x together with those of one on search_x. The linearised contact of
/// small-strain bodies integrates on the reference positions x but must pair the faces that
/// the current positions bring together: a curved interface's gap grows like r², so faces
/// that close under load can lie many face sizes apart in the reference configuration.
ContactMortar evaluate_contact_mortar(const ContactSurface& surface,
                                      const std::vector<std::array<double, 3>>& x,
                                      const ContactMortarOptions& options,
                                      const std::vector<std::array<double, 3>>* search_x = nullptr);

/// The (slave face id, master face id) candidate pairs that evaluate_contact_mortar with the
/// same arguments integrates, in that order: a coarse search, without the integration. Callers
/// that keep a ContactMortar of fixed positions use it to see whether the pairing changed.
std::vector<std::pair<GlobalIndex, GlobalIndex>> contact_pairs(
    const ContactSurface& surface, const std::vector<std::array<double, 3>>& x,
    const ContactMortarOptions& options,
    const std::vector<std::array<double, 3>>* search_x = nullptr);

}  // namespace grout
