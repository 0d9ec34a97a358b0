#include "io/contact_treatment.hpp"

namespace grout {

// read_dynamics (input_dynamics.cpp) sets velocity_update only with stabilized_contact, and
// sliding_balance only with sliding_update.
ContactTreatment contact_treatment_of(const DynamicsInput& input) {
  if (!input.stabilized_contact) return ContactTreatment::standard;
  if (!input.velocity_update) return ContactTreatment::stabilized;
  if (!input.sliding_update) return ContactTreatment::velocity_update_impact;
  return input.sliding_balance ? ContactTreatment::velocity_update_balanced
                               : ContactTreatment::velocity_update_tangential;
}

}  // namespace grout
