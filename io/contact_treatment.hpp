#pragma once
// The contact treatment of implicit dynamics as one value: what a step's contact force does
// after the step, and where the energy that closing contacts lose goes
// (`dynamics/contact_treatment` with `dynamics/sliding`, docs/input.md; docs/design.md §4,
// "Implicit dynamics"). All but standard keep the force to its own step; the velocity_update
// ones also give that loss back to the bodies as a velocity jump. read_dynamics
// (io/input_dynamics.cpp) sets it in DynamicsInput::contact_treatment.

namespace grout {

enum class ContactTreatment {
  standard,    ///< standard: carried into the next step like any force
  stabilized,  ///< stabilized (default): acts on its own step only
  /// velocity_update, sliding: impact: and every closing node's loss goes back along the
  /// step's contact impulse
  velocity_update_impact,
  /// velocity_update (sliding: tangential): the loss of the nodes that close on an interface
  /// already in contact (a sliding contact reaching the next node) goes back along the sliding
  velocity_update_tangential,
  /// velocity_update, sliding: balanced: and so does the energy of the nodes that stay closed,
  /// of either sign (frictionless and tied contact only)
  velocity_update_balanced,
};

}  // namespace grout
