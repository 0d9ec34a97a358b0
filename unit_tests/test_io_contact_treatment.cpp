// contact_treatment_of (io/contact_treatment.hpp): each combination read_dynamics can set
// (test_io_input checks the YAML → DynamicsInput part) maps to its one named treatment.
#include <gtest/gtest.h>

#include "io/contact_treatment.hpp"

namespace {

using grout::ContactTreatment;
using grout::DynamicsInput;

// The flags read_dynamics (io/input_dynamics.cpp) sets for `contact_treatment` and `sliding`.
DynamicsInput flags(bool stabilized, bool velocity_update, bool sliding_update, bool balance) {
  DynamicsInput d;
  d.stabilized_contact = stabilized;
  d.velocity_update = velocity_update;
  d.sliding_update = sliding_update;
  d.sliding_balance = balance;
  return d;
}

TEST(ContactTreatment, EachInputCombinationHasItsValue) {
  EXPECT_EQ(contact_treatment_of(DynamicsInput()), ContactTreatment::stabilized);  // defaults
  // contact_treatment: standard (sliding is refused without velocity_update; its default
  // tangential leaves sliding_update set).
  EXPECT_EQ(contact_treatment_of(flags(false, false, true, false)), ContactTreatment::standard);
  EXPECT_EQ(contact_treatment_of(flags(true, false, true, false)), ContactTreatment::stabilized);
  EXPECT_EQ(contact_treatment_of(flags(true, true, false, false)),
            ContactTreatment::velocity_update_impact);
  EXPECT_EQ(contact_treatment_of(flags(true, true, true, false)),
            ContactTreatment::velocity_update_tangential);
  EXPECT_EQ(contact_treatment_of(flags(true, true, true, true)),
            ContactTreatment::velocity_update_balanced);
}

}  // namespace
