#pragma once
// grout::contact_law_at_nodes: Grout's contact law at a host's slave nodes — the multiplier
// rows C_j of frictionless, tied and Coulomb contact as nonlinear complementarity functions,
// their status and kinds, and their exact derivatives with respect to the node's variables
// (docs/embedding.md, "The contact law at the slave nodes"; docs/design.md, "Contact
// conditions"). Installed as <grout/contact_law.hpp>, target Grout::mortar.
//
// The rows, with s = n·λ − ĉ g the augmented normal multiplier and ξ_k = τ_k·λ + c_t ū_k:
//   not paired:                   C_a = λ_a                                   (open)
//   tied:                         C_a = ĉ t_a, or C_a = λ_a for a held component (stick)
//   normal laws, s < −tol (and not near) or held back:  C_a = λ_a            (open)
//   else C_0 = ĉ g and
//     frictionless:               C_{k+1} = τ_k·λ                             (slip)
//     Coulomb, |ξ| ≤ μ (s + tol): C_{k+1} = c_t ū_k                           (stick)
//     Coulomb, else:              C_{k+1} = τ_k·λ − μ s ξ_k/|ξ|               (slip)
//   and a Coulomb tangent along a held axis a gives C_{k+1} = λ_a.
// These are the rows Grout's driver solves: the function runs the driver's own Kokkos launch
// ("grout::contact_law", kernels/contact_laws.hpp) on the default execution space.
//
// This header includes nothing of Grout's internals: plain structs, converted to the kernel's
// at the library boundary (api/contact_law.cpp).

#include <cstddef>
#include <stdexcept>
#include <vector>

namespace grout {

/// A settings or node value the law cannot take (the message names the field and the node).
class ContactLawError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

enum class ContactLawType : int { frictionless = 0, coulomb = 1, tied = 2 };

/// A node's status: a tied node sticks, an active frictionless one slips.
enum class ContactNodeState : int { open = 0, stick = 1, slip = 2 };

/// What a row depends on (for a host's linear algebra or condensation).
enum class ContactRowKind : int {
  identity = 0,    ///< C = λ_a, a = ContactLawRows::component[r]
  constraint = 1,  ///< displacements only, through g, t or ū: normal, tied and stick rows
  slip = 2,        ///< Coulomb slip: λ and displacements (through n, τ, g, ū)
  tangent = 3      ///< frictionless τ_k·λ: λ, and displacements only through τ_k
};

/// The law's parameters, one set per interface.
struct ContactLawSettings {
  int dim = 3;  ///< 2 or 3
  ContactLawType law = ContactLawType::frictionless;
  double c_hat = 1.0;             ///< ĉ > 0 of the normal and tied rows (Grout: E/h)
  double c_t_hat = 1.0;           ///< c_t > 0 of the Coulomb tangential rows
  double mu = 0.0;                ///< Coulomb friction coefficient μ ≥ 0
  double active_tolerance = 0.0;  ///< tol ≥ 0 of the active-set and stick tests
};

/// One slave node j (components ≥ dim and tangents ≥ dim − 1 are not read).
struct ContactLawInput {
  double lambda[3] = {0.0, 0.0, 0.0};  ///< Cartesian multiplier λ_j
  double n[3] = {0.0, 0.0, 0.0};       ///< unit normal n_j (MortarCoupling::normals())
  double t[2][3] = {{0.0, 0.0, 0.0},   ///< unit tangents τ_j (MortarCoupling::tangents())
                    {0.0, 0.0, 0.0}};
  double gap = 0.0;                  ///< nodal gap g = g̃_j / D_jj (normal laws)
  double slip[2] = {0.0, 0.0};       ///< slip increment per unit D_jj, ū_k (Coulomb)
  double tied[3] = {0.0, 0.0, 0.0};  ///< (D_jj u¹_j − Σ_l M_jl u²_l) / D_jj (tied)
  bool paired = true;                ///< D_jj above the host's tolerance (else λ_j = 0)
  bool near = false;                 ///< kept active although s < −tol (host's proximity rule)
  bool held_back = false;            ///< kept open at this iterate (host's active-set policy)
  bool prescribed[3] = {false, false, false};  ///< slave dof component a prescribed
  double free_share[3] = {0.0, 0.0, 0.0};      ///< Σ_{l: master dof a free} |M_jl| / D_jj
};

/// The columns of ContactLawRows::dC: the node's variables v, one numbering for 2D and 3D (in
/// 2D the columns of λ_2, n_2, τ_{0,2}, τ_1, ū_1 and t_2 are zero).
struct ContactLawColumn {
  static constexpr int count = 18;
  static constexpr int lambda(int a) { return a; }
  static constexpr int normal(int a) { return 3 + a; }
  static constexpr int tangent(int k, int a) { return 6 + 3 * k + a; }
  static constexpr int gap() { return 12; }
  static constexpr int slip(int k) { return 13 + k; }
  static constexpr int tied(int a) { return 15 + a; }
};

/// One node's rows C[0..dim−1] (rows ≥ dim are 0), ∂C_r/∂v (zero without derivatives), its
/// state and row kinds; component[r] the λ component of an identity row (else −1); held_axis[k]
/// the Cartesian axis a Coulomb tangent k is held along (else −1).
struct ContactLawRows {
  double C[3];
  double dC[3][ContactLawColumn::count];
  ContactNodeState state;
  ContactRowKind kind[3];
  int component[3];
  int held_axis[2];
};

/// \brief rows[i] = the law at nodes[i], i < count, by the launch "grout::contact_law" on
/// Kokkos' default execution space (nodes copied there and back); `derivatives`: also ∂C/∂v.
/// Serial per call, no MPI: every rank calls it for the nodes it owns.
/// \throws ContactLawError for settings out of range or a non-finite value read from a node.
void contact_law_at_nodes(const ContactLawSettings& settings, const ContactLawInput* nodes,
                          std::size_t count, bool derivatives, ContactLawRows* rows);

/// The same, on vectors.
std::vector<ContactLawRows> contact_law_at_nodes(const ContactLawSettings& settings,
                                                 const std::vector<ContactLawInput>& nodes,
                                                 bool derivatives = true);

}  // namespace grout
