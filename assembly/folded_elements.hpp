#pragma once
// Elements folded at their corners in a converged state: a warning, not an error. The solve
// checks det F > 0 only at the Gauss points it integrates with, so a bilinear or trilinear
// element can turn a corner inside out (det F < 0 there) and still converge.

#include <string>

#include "assembly/solid_problem.hpp"

namespace grout {

/// The element with the smallest corner det F over all ranks.
struct FoldedElement {
  double det_F = 1.0;        ///< smallest det F at a corner (kernels/corner_jacobian.hpp)
  std::string block;         ///< its element block
  GlobalIndex element = -1;  ///< its global element index (0-based), -1 if none
  int corner = -1;           ///< its local node
};

/// \brief The owned element of a finite-strain block with the smallest det F at a corner
/// (min_corner_det_F) for the displacement u (owned map), over all ranks (collective: two
/// reductions; every rank gets the result).
FoldedElement most_folded_element(const SolidProblem& solid, const Vector& u);

/// \brief On rank 0 of `solid`'s communicator: when det F ≤ 0 at a corner of an element,
/// "grout: warning: step <step> (t = <time>): element <e> of block '<b>' is folded ..." on
/// stderr. Collective.
void warn_of_folded_elements(const SolidProblem& solid, const Vector& u, int step, double time);

}  // namespace grout
