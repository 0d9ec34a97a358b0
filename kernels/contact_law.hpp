#pragma once
// The contact law at one slave node j: its dim multiplier rows C_j(λ_j, n_j, τ_j, g_j, ū_j, t_j)
// as nonlinear complementarity functions differentiated branch by branch (semi-smooth Newton;
// docs/design.md, "Contact conditions"), on plain data, templated on the scalar:
//
//   not paired (D_jj ≤ D_tol):       C_a = λ_a                                     (open)
//   tied, per component a:           C_a = ĉ t_a,  t_a = (D u¹_j − Σ_l M_jl u²_l)_a / D_jj,
//                                    or C_a = λ_a if the component is held          (stick)
//   normal kinds, s = n·λ − ĉ g:     open (C_a = λ_a) if (s < −tol and not near) or held back,
//                                    else C_0 = ĉ g and
//     frictionless:                  C_{k+1} = τ_k·λ                                (slip)
//     Coulomb (Hüeber, Stadler & Wohlmuth 2008), ξ_k = τ_k·λ + c_t ū_k:
//       stick (μ > 0, |ξ| ≤ μ (s + tol)):  C_{k+1} = c_t ū_k                        (stick)
//       slip:                              C_{k+1} = τ_k·λ − μ s ξ_k/|ξ|  (ξ/|ξ| = 0 at ξ = 0)
//     with a held tangent k (τ_k within 0.1 rad of e_a, |τ_k·e_a|² ≥ 0.99, slave dof a
//     prescribed, the free master dofs' share of Σ_l |M_jl| at most 0.25 D_jj: a symmetry
//     plane cutting the contact surface): ū_k = ξ_k = 0 and C_{k+1} = λ_a (docs/design.md,
//     "Rows with nothing to hold"; docs/input.md, "Friction on a plane of symmetry").
//
// The decisions (active set, stick/slip, held components and tangents) are taken on the values;
// the rows' derivatives with respect to the ContactLawLayout variables come from Sacado forward
// AD (SFad<double, 18>, contact_law below), so no derivative is written by hand. At ξ = 0 in
// slip the direction ξ/|ξ| is the constant 0 (its derivative is not defined there). The launch
// over the slave nodes is in contact_laws.hpp.

#include <type_traits>

#include "kernels/kernel_macros.hpp"
#include "kernels/sacado_fad.hpp"
#include "kernels/scalar_value.hpp"

namespace grout {

enum ContactLawKind : int { frictionless_law = 0, coulomb_law = 1, tied_law = 2 };

/// A node's contact status: a tied node is `node_stick`, an active frictionless one `node_slip`.
enum ContactNodeStatus : int { node_open = 0, node_stick = 1, node_slip = 2 };

/// What a multiplier row depends on, for the linear algebra (declared by the law, not read off J).
enum MultiplierRowKind : char {
  row_identity = 0,    ///< C = λ_a, a = the row's `component` (its own or a held tangent's axis)
  row_constraint = 1,  ///< displacements only, through g, t or ū: normal, tied and stick rows
  row_slip = 2,        ///< Coulomb slip: λ and displacements (through n, τ, g, ū)
  row_tangent = 3      ///< frictionless τ_k·λ: λ, and displacements only through the frame τ_k
};

/// The law's parameters, per interface. kind: ContactLawKind (any other value: frictionless).
struct ContactLawParameters {
  int dim;
  int kind;
  double c_hat, c_t_hat, mu, active_tolerance;
};

/// One slave node's state (components ≥ dim and tangents ≥ dim − 1 are not read).
struct ContactLawNode {
  double lambda[3];      ///< Cartesian multiplier λ_j
  double n[3], t[2][3];  ///< slave frame: unit normal, tangents
  double gap;            ///< nodal gap g = g̃ / D_jj (normal kinds)
  double slip[2];        ///< weighted slip increment per unit D_jj, ū_k (Coulomb)
  double tied[3];        ///< (D u¹_j − Σ_l M_jl u²_l) / D_jj per component (tied)
  int paired;            ///< D_jj > D_tol (else the rows λ_j = 0)
  int near;              ///< proximity rule of the step start: active although s < −tol
  int held_back;         ///< the active-set policy holds this node open at this iterate
  int prescribed[3];     ///< slave dof component a prescribed (Dirichlet)
  double free_share[3];  ///< Σ_{l: master dof a free} |M_jl| / D_jj, per component a
};

/// Held components: a tie component with a free share at most 1e-12 (the round-off the
/// integration leaves where M_jl vanishes), a Coulomb tangent with |τ_k·e_a|² ≥ 0.99 and a free
/// share at most 0.25 (a die 0.8 of its face size into a one-layer slab tilts the plane's
/// tangents by 0.011 rad and shares 0.07; docs/verification.md, "Friction on the slab's plane").
constexpr double contact_law_tie_held_share = 1e-12;
constexpr double contact_law_held_tangent = 0.99;
constexpr double contact_law_tangent_held_share = 0.25;

/// The law's local variables, one numbering for 2D and 3D (18; in 2D λ_2, n_2, τ_{0,2}, τ_1,
/// ū_1 and t_2 are not read, so their derivatives are zero).
struct ContactLawLayout {
  static constexpr int count = 18;
  GROUT_INLINE_FUNCTION static constexpr int lambda(int a) { return a; }
  GROUT_INLINE_FUNCTION static constexpr int normal(int a) { return 3 + a; }
  GROUT_INLINE_FUNCTION static constexpr int tangent(int k, int a) { return 6 + 3 * k + a; }
  GROUT_INLINE_FUNCTION static constexpr int gap() { return 12; }
  GROUT_INLINE_FUNCTION static constexpr int slip(int k) { return 13 + k; }
  GROUT_INLINE_FUNCTION static constexpr int tied(int a) { return 15 + a; }
};

/// The node's value of layout variable v (0 ≤ v < ContactLawLayout::count).
GROUT_INLINE_FUNCTION double& contact_law_variable(ContactLawNode& node, int v) {
  if (v < 3) return node.lambda[v];
  if (v < 6) return node.n[v - 3];
  if (v < 12) return node.t[(v - 6) / 3][(v - 6) % 3];
  if (v == 12) return node.gap;
  if (v < 15) return node.slip[v - 13];
  return node.tied[v - 15];
}

/// The rows' inputs as Scalar (the variables of ContactLawLayout).
template <class Scalar>
struct ContactLawVariables {
  Scalar lambda[3], n[3], t[2][3], gap, slip[2], tied[3];
};

/// Per row: its kind, and the λ component an identity row reads (−1 for other rows and for
/// rows ≥ dim); the Coulomb held tangents' axes (−1: not held).
struct ContactLawRowInfo {
  int status;  ///< ContactNodeStatus
  MultiplierRowKind kind[3];
  int component[3];
  int held_axis[2];
};

/// Rows, status, row kinds and ∂C_r/∂v (v: ContactLawLayout; zero for rows ≥ dim and for a
/// values-only evaluation).
struct ContactLawResult {
  double C[3];
  double dC[3][ContactLawLayout::count];
  int status;  ///< ContactNodeStatus
  MultiplierRowKind kind[3];
  int component[3];
  int held_axis[2];
};

/// The AD scalar of the law.
using ContactLawFad = Sacado::Fad::SFad<double, ContactLawLayout::count>;

namespace detail_law {

/// x as Scalar: a copy, or for a Fad the variable `index` (seeded) if `used`, else a constant.
template <class Scalar>
GROUT_INLINE_FUNCTION Scalar variable(double x, int index, bool used) {
  if constexpr (std::is_same<Scalar, double>::value) {
    (void)index, (void)used;
    return x;
  } else {
    return used ? Scalar(ContactLawLayout::count, index, x) : Scalar(x);
  }
}

template <class Scalar>
GROUT_INLINE_FUNCTION void identity_row(int r, int a, const ContactLawVariables<Scalar>& v,
                                        Scalar C[3], ContactLawRowInfo& info) {
  C[r] = v.lambda[a];
  info.kind[r] = row_identity;
  info.component[r] = a;
}

}  // namespace detail_law

/// \brief The node's variables as Scalar: copies, or for ContactLawFad each variable of
/// dimension `dim` seeded with its unit derivative (the others constants).
template <class Scalar>
GROUT_INLINE_FUNCTION void contact_law_variables(int dim, const ContactLawNode& node,
                                                 ContactLawVariables<Scalar>& v) {
  using L = ContactLawLayout;
  using detail_law::variable;
  for (int a = 0; a < 3; ++a) {
    v.lambda[a] = variable<Scalar>(node.lambda[a], L::lambda(a), a < dim);
    v.n[a] = variable<Scalar>(node.n[a], L::normal(a), a < dim);
    v.tied[a] = variable<Scalar>(node.tied[a], L::tied(a), a < dim);
    for (int k = 0; k < 2; ++k)
      v.t[k][a] = variable<Scalar>(node.t[k][a], L::tangent(k, a), a < dim && k < dim - 1);
  }
  v.gap = variable<Scalar>(node.gap, L::gap(), true);
  for (int k = 0; k < 2; ++k) v.slip[k] = variable<Scalar>(node.slip[k], L::slip(k), k < dim - 1);
}

/// \brief The rows C[0..dim−1] of the law at one node (the table at the top of this file);
/// rows ≥ dim are 0. `node` gives the flags (paired, near, held_back, prescribed, free_share),
/// `v` the variables. \return the ContactNodeStatus (also in info.status).
template <class Scalar>
GROUT_INLINE_FUNCTION int contact_law_rows(const ContactLawParameters& p,
                                           const ContactLawNode& node,
                                           const ContactLawVariables<Scalar>& v, Scalar C[3],
                                           ContactLawRowInfo& info) {
  using detail_law::identity_row;
  using std::sqrt;
  const int dim = p.dim;
  for (int r = 0; r < 3; ++r) {
    C[r] = Scalar(0.0);
    info.kind[r] = row_identity;
    info.component[r] = -1;
  }
  info.held_axis[0] = info.held_axis[1] = -1;
  info.status = node_open;
  if (!node.paired) {  // no master facing the node: λ_j = 0
    for (int a = 0; a < dim; ++a) identity_row(a, a, v, C, info);
    return info.status;
  }
  if (p.kind == tied_law) {  // ĉ t_a = 0, or λ_a = 0 for a held component
    info.status = node_stick;
    for (int a = 0; a < dim; ++a) {
      if (node.prescribed[a] && node.free_share[a] <= contact_law_tie_held_share) {
        identity_row(a, a, v, C, info);
        continue;
      }
      C[a] = p.c_hat * v.tied[a];
      info.kind[a] = row_constraint;
    }
    return info.status;
  }
  Scalar lambda_n = 0.0;
  for (int a = 0; a < dim; ++a) lambda_n += v.n[a] * v.lambda[a];
  const Scalar s = lambda_n - p.c_hat * v.gap;  // the augmented normal multiplier
  const double s_value = value_of(s);
  if ((s_value < -p.active_tolerance && !node.near) || node.held_back) {  // inactive: λ_j = 0
    for (int a = 0; a < dim; ++a) identity_row(a, a, v, C, info);
    return info.status;
  }
  C[0] = p.c_hat * v.gap;
  info.kind[0] = row_constraint;
  Scalar lambda_t[2] = {0.0, 0.0};
  for (int k = 0; k < dim - 1; ++k)
    for (int a = 0; a < dim; ++a) lambda_t[k] += v.t[k][a] * v.lambda[a];
  if (p.kind != coulomb_law) {  // frictionless: τ_k·λ = 0
    info.status = node_slip;
    for (int k = 0; k < dim - 1; ++k) {
      C[k + 1] = lambda_t[k];
      info.kind[k + 1] = row_tangent;
    }
    return info.status;
  }
  // Coulomb: held tangents first (the first axis a that qualifies), then ξ = λ_τ + c_t ū.
  bool held[2] = {false, false};
  Scalar xi[2] = {0.0, 0.0}, xi2 = 0.0;
  for (int k = 0; k < dim - 1; ++k) {
    for (int a = 0; a < dim && info.held_axis[k] < 0; ++a) {
      const double tka = value_of(v.t[k][a]);
      if (tka * tka >= contact_law_held_tangent && node.prescribed[a] &&
          node.free_share[a] <= contact_law_tangent_held_share)
        info.held_axis[k] = a;
    }
    held[k] = info.held_axis[k] >= 0;
    if (!held[k]) xi[k] = lambda_t[k] + p.c_t_hat * v.slip[k];
    xi2 += xi[k] * xi[k];
  }
  const double xi_norm = kmath::sqrt(value_of(xi2));
  // Stick includes |ξ| = μ s (the start of a step, λ = ū = 0, sticks); μ = 0 always slips.
  if (p.mu > 0.0 && xi_norm <= p.mu * (s_value + p.active_tolerance)) {
    info.status = node_stick;
    for (int k = 0; k < dim - 1; ++k) {
      if (held[k]) {
        identity_row(k + 1, info.held_axis[k], v, C, info);
        continue;
      }
      C[k + 1] = p.c_t_hat * v.slip[k];
      info.kind[k + 1] = row_constraint;
    }
    return info.status;
  }
  info.status = node_slip;  // λ_τ − μ s ξ/|ξ|
  Scalar norm = 1.0;
  if (xi_norm > 0.0) norm = sqrt(xi2);
  for (int k = 0; k < dim - 1; ++k) {
    if (held[k]) {
      identity_row(k + 1, info.held_axis[k], v, C, info);
      continue;
    }
    if (xi_norm > 0.0)
      C[k + 1] = lambda_t[k] - p.mu * s * xi[k] / norm;
    else
      C[k + 1] = lambda_t[k];
    info.kind[k + 1] = row_slip;
  }
  return info.status;
}

/// \brief The law at one node: the rows' values, status and kinds, and if `derivatives` ∂C/∂v
/// over ContactLawLayout by AD (ContactLawFad; else dC = 0).
GROUT_INLINE_FUNCTION void contact_law(const ContactLawParameters& p, const ContactLawNode& node,
                                       bool derivatives, ContactLawResult& out) {
  ContactLawRowInfo info;
  if (derivatives) {
    ContactLawVariables<ContactLawFad> v;
    contact_law_variables(p.dim, node, v);
    ContactLawFad C[3];
    contact_law_rows(p, node, v, C, info);
    for (int r = 0; r < 3; ++r) {
      out.C[r] = C[r].val();
      for (int q = 0; q < ContactLawLayout::count; ++q) out.dC[r][q] = C[r].fastAccessDx(q);
    }
  } else {
    ContactLawVariables<double> v;
    contact_law_variables(p.dim, node, v);
    contact_law_rows(p, node, v, out.C, info);
    for (int r = 0; r < 3; ++r)
      for (int q = 0; q < ContactLawLayout::count; ++q) out.dC[r][q] = 0.0;
  }
  out.status = info.status;
  for (int r = 0; r < 3; ++r) out.kind[r] = info.kind[r], out.component[r] = info.component[r];
  out.held_axis[0] = info.held_axis[0];
  out.held_axis[1] = info.held_axis[1];
}

}  // namespace grout
