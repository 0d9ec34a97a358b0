#pragma once
// Initial conditions of a dynamic analysis on the solid's dofs.

#include "assembly/solid_problem.hpp"

namespace grout {

/// v_0 on the owned dofs from `grout/initial_velocity`: each entry's expressions evaluated at
/// t = 0 and the reference coordinates of every node of its block (0 elsewhere). A node of
/// several listed blocks takes the value of the last entry that lists one of its blocks.
/// `mesh`: the replicated mesh or this rank's part (for the block names only).
Teuchos::RCP<Vector> initial_velocity(const SolidProblem& solid, const Mesh& mesh,
                                      const Input& input);

}  // namespace grout
