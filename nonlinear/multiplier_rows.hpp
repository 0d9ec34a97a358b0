#pragma once
// What each multiplier row of the (u, λ) system is, as the contact interface that wrote it
// declares it (contact_interface.hpp, from the row kinds of kernels/contact_law.hpp). The
// condensations (condensed_solve.hpp, symmetric_condensation.hpp) are built from these
// declarations rather than from J's sparsity; they still read J's rows, and a row that does
// not have the declared structure is a logic error (the declaration and J disagree).

#include <algorithm>
#include <vector>

#include "assembly/tpetra_types.hpp"

namespace grout {

enum class LambdaRow : char {
  identity,  ///< λ_t = value, only J[t, t]: an open node's λ_a = 0 (kind A of the condensation)
  pure_lambda,  ///< the node's multipliers only: τ_k·λ = 0 (frictionless, reference geometry),
                ///< a held tangent's e_a·λ = 0
  constraint,   ///< displacements only: ĉ g = 0, the ties, c_t ū = 0 (stick)
  mixed,        ///< displacements and multipliers: Coulomb slip; τ_k·λ on the current geometry
};

/// The owned multiplier rows of one evaluation, ascending by GID.
struct MultiplierRows {
  std::vector<GO> gids;
  std::vector<LambdaRow> kinds;

  /// The declared kind of row `gid`, or nullptr if it is not among them.
  const LambdaRow* find(GO gid) const {
    const auto it = std::lower_bound(gids.begin(), gids.end(), gid);
    return it != gids.end() && *it == gid ? &kinds[std::size_t(it - gids.begin())] : nullptr;
  }
};

}  // namespace grout
