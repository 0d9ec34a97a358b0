#pragma once
// The mass matrix of the solid, assembled like its stiffness (owner computes, on the solid's
// graph): M = Σ_e ρ_e ∫ N_a N_b dV δ_ij, consistent or row-sum lumped (kernels/mass_matrix.hpp).

#include <Teuchos_RCP.hpp>

#include "assembly/solid_problem.hpp"

namespace grout {

/// M on the solid's owned map and graph (fill-completed); each block's density from its
/// material. Throws InputError naming the block on an inverted element.
Teuchos::RCP<Matrix> assemble_mass_matrix(const SolidProblem& solid, bool lumped);

}  // namespace grout
