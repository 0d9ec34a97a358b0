#pragma once
// The dynamics part of the input: `grout/dynamics`, `grout/gravity`, `grout/initial_velocity`
// (docs/input.md). Private to io/ (read_input calls it).

#include "io/input.hpp"
#include "io/input_schema.hpp"

namespace grout {

/// Reads the three sections into input.dynamics, input.gravity, input.initial_velocity;
/// needs input.model and input.materials (every material needs a density > 0 in dynamics).
void read_dynamics(const input_schema::Section& grout, Input& input);

}  // namespace grout
