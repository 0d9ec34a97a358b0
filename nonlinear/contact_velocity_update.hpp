#pragma once
// Velocity update at the end of a dynamic step with contact: the velocities are projected, in
// the lumped-mass metric, onto the persistency condition of the closed contacts,
//
//   v⁺ = v − M_L⁻¹ Gᵀ μ,   (G M_L⁻¹ Gᵀ) μ = G v,   so that G v⁺ = 0,
//
// where the rows of G are the displacement gradients of the contact constraints active at
// t_{n+1}: the weighted normal gap of every closed slave node, and also its weighted tangential
// slip for a stuck or tied node (taken from the u part of the multiplier rows of the exact
// Jacobian). This is the velocity-update idea of Laursen & Love (Int. J. Numer. Meth. Engng 53
// (2002) 245), in its dissipative form: a closed contact carries no relative normal velocity
// into the next step, so a release cannot push the bodies apart with a contact force that did
// work while closing (the source of energy growth of the plain implicit rules with contact
// enforced at t_{n+1}); the kinetic energy can only decrease, by at most the kinetic energy of
// the relative normal motion of the contact nodes (an M_L-orthogonal projection).
// Prescribed dofs keep their velocities (infinite mass).

#include "nonlinear/linear_solver.hpp"
#include "nonlinear/mechanics_problem.hpp"

namespace grout {

/// Projects v (owned solid map) as in the file comment, at the state x of the last residual
/// evaluation of `problem`; `lumped_mass` are the row sums of M (owned solid map). Returns the
/// number of constraint rows (0: v unchanged). Collective.
int project_contact_velocities(MechanicsProblem& problem, const Vector& x,
                               const Vector& lumped_mass, LinearSolver& solver, Vector& v);

}  // namespace grout
