#pragma once
// The AD variables of one mortar pair and the pair's D, M with their derivatives: plain data
// and copies, shared by the derivative launch (mortar_pair_gradient.hpp) and its callers.
//
//   ∂D_jj/∂v, ∂M_jl/∂v for v the slave and master nodal coordinates and, in 2D, the slave nodal
//   normals that the projection χ follows (docs/design.md, "Linearisation").

#include <type_traits>

#include "kernels/kernel_macros.hpp"
#include "kernels/mortar_types.hpp"
#include "kernels/sacado_fad.hpp"

namespace grout {

/// \brief out ← x as Scalar: a copy for double; for a Sacado Fad over n_vars variables, every
/// coordinate that `seed` names (seed(a, d) = variable index, or −1 for a constant) is seeded
/// with its unit derivative.
template <class Scalar, class Seed>
GROUT_INLINE_FUNCTION void seed_face(int n_nodes, const double x[max_face_nodes][3],
                                     Scalar out[max_face_nodes][3], const Seed& seed, int n_vars) {
  for (int a = 0; a < max_face_nodes; ++a)
    for (int d = 0; d < 3; ++d) {
      const int v = a < n_nodes ? seed(a, d) : -1;
      if constexpr (std::is_same<Scalar, double>::value) {
        (void)v, (void)n_vars;
        out[a][d] = x[a][d];
      } else {
        out[a][d] = v >= 0 ? Scalar(n_vars, v, x[a][d]) : Scalar(x[a][d]);
      }
    }
}

/// Numbering of a pair's AD variables in dimension Dim, on the padded face sizes (2 nodes per
/// LINE2, 4 per TRI3/QUAD4; the variables of an absent fourth node stay zero):
///   2D: slave x_a,d (0..3), slave normal n_a,d (4..7), master x_b,d (8..11): 12 variables;
///   3D: slave x_a,d (0..11), master x_b,d (12..23): 24 variables (the auxiliary plane is built
///       from the slave coordinates, so the 3D pair does not depend on the nodal normals).
template <int Dim>
struct MortarPairVariables {
  static_assert(Dim == 2 || Dim == 3, "grout::MortarPairVariables: Dim must be 2 or 3");
  static constexpr int face_nodes = Dim == 2 ? 2 : max_face_nodes;
  static constexpr int normal_offset = Dim == 2 ? face_nodes * Dim : -1;
  static constexpr int master_offset = (Dim == 2 ? 2 : 1) * face_nodes * Dim;
  static constexpr int count = master_offset + face_nodes * Dim;  ///< 12 (2D), 24 (3D)

  GROUT_INLINE_FUNCTION static constexpr int slave(int a, int d) { return a * Dim + d; }
  GROUT_INLINE_FUNCTION static constexpr int normal(int a, int d) {
    return normal_offset + a * Dim + d;
  }
  GROUT_INLINE_FUNCTION static constexpr int master(int b, int d) {
    return master_offset + b * Dim + d;
  }

  struct Slave {
    GROUT_INLINE_FUNCTION int operator()(int a, int d) const {
      return a < face_nodes && d < Dim ? MortarPairVariables::slave(a, d) : -1;
    }
  };
  struct Normal {
    GROUT_INLINE_FUNCTION int operator()(int a, int d) const {
      return Dim == 2 && a < face_nodes && d < Dim ? MortarPairVariables::normal(a, d) : -1;
    }
  };
  struct Master {
    GROUT_INLINE_FUNCTION int operator()(int b, int d) const {
      return b < face_nodes && d < Dim ? MortarPairVariables::master(b, d) : -1;
    }
  };
};

/// One pair's D_jj and M_jl (dual basis) with their derivatives with respect to the
/// MortarPairVariables<Dim>; j < n_slave, l < n_master are set, the rest is not read.
template <int Dim>
struct MortarPairGradient {
  static constexpr int nodes = MortarPairVariables<Dim>::face_nodes;
  static constexpr int vars = MortarPairVariables<Dim>::count;
  int status;  ///< MortarStatus of the pair: only `ok` pairs contribute
  int n_slave, n_master;
  double D[nodes];
  double dD[nodes][vars];
  double M[nodes][nodes];
  double dM[nodes][nodes][vars];
};

/// The AD scalar of a Dim-dimensional pair.
template <int Dim>
using MortarPairFad = Sacado::Fad::SFad<double, MortarPairVariables<Dim>::count>;

/// One pair's D_jj and M_jl (dual basis) without derivatives, for the values-only launch.
template <int Dim>
struct MortarPairValues {
  static constexpr int nodes = MortarPairVariables<Dim>::face_nodes;
  int status, n_slave, n_master;
  double D[nodes];
  double M[nodes][nodes];
};

/// \brief Copies a pair's status, sizes and values into `out` (MortarPairValues<Dim>), and for a
/// pair integrated in MortarPairFad<Dim> its derivatives too (out: MortarPairGradient<Dim>).
template <int Dim, class Scalar, class Out>
GROUT_INLINE_FUNCTION void store_pair_gradient(MortarStatus status,
                                               const MortarPairResult<Scalar>& pair, int n_slave,
                                               int n_master, Out& out) {
  constexpr int vars = MortarPairVariables<Dim>::count;
  constexpr bool derivatives = !std::is_same<Scalar, double>::value;
  out.status = static_cast<int>(status);
  out.n_slave = n_slave;
  out.n_master = n_master;
  if (status != MortarStatus::ok) return;
  for (int j = 0; j < n_slave; ++j) {
    if constexpr (derivatives) {
      out.D[j] = pair.D[j].val();
      for (int v = 0; v < vars; ++v) out.dD[j][v] = pair.D[j].fastAccessDx(v);
    } else {
      out.D[j] = pair.D[j];
    }
    for (int l = 0; l < n_master; ++l) {
      if constexpr (derivatives) {
        out.M[j][l] = pair.M[j][l].val();
        for (int v = 0; v < vars; ++v) out.dM[j][l][v] = pair.M[j][l].fastAccessDx(v);
      } else {
        out.M[j][l] = pair.M[j][l];
      }
    }
  }
}

}  // namespace grout
