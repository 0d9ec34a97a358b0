#include "io/input_dynamics.hpp"

#include "io/errors.hpp"

namespace grout {

using input_schema::Key;
using input_schema::Section;

void read_dynamics(const Section& grout, Input& input) {
  const int dim = input.model.dimension;
  const char* const axes[3] = {"x", "y", "z"};
  if (grout.has("gravity")) {
    std::vector<Key> keys = {Key::number("x").defaults("0"), Key::number("y").defaults("0")};
    if (dim == 3) keys.push_back(Key::number("z").defaults("0"));
    const Section g = grout.section("gravity", keys);
    for (int d = 0; d < dim; ++d) input.gravity[d] = g.number(axes[d]);
  }
  std::vector<Key> velocity_keys = {Key::string("block").required(),
                                    Key::expression("x").defaults("0"),
                                    Key::expression("y").defaults("0")};
  if (dim == 3) velocity_keys.push_back(Key::expression("z").defaults("0"));
  for (const Section& s : grout.named_sections("initial_velocity", velocity_keys)) {
    InitialVelocityInput v;
    v.name = s.name();
    v.block = s.string("block");
    for (int d = 0; d < dim; ++d) v.components.push_back(s.expression(axes[d]));
    input.initial_velocity.push_back(std::move(v));
  }

  const bool dynamic = grout.has("dynamics");
  if (!dynamic) {
    if (grout.has("initial_velocity"))
      grout.fail("initial_velocity", "needs a 'dynamics' section (the analysis is quasi-static)");
    if (grout.has("gravity"))
      grout.fail("gravity", "needs a 'dynamics' section (quasi-static gravity is not supported)");
    return;
  }
  const Section d = grout.section(
      "dynamics",
      {Key::choice("scheme", {"newmark", "hht", "bossak", "generalized_alpha", "energy_momentum"},
                   "time scheme")
           .defaults("newmark"),
       Key::number("rho_infinity").at_least(0).defaults("1"),
       Key::number("beta").above(0).defaults("0.25"),
       Key::number("gamma").at_least(0.5).defaults("0.5"),
       Key::choice("mass", {"consistent", "lumped"}, "mass matrix").defaults("consistent"),
       Key::choice("contact_treatment", {"stabilized", "standard", "velocity_update"},
                   "contact treatment")
           .defaults("stabilized"),
       Key::choice("sliding", {"tangential", "impact", "balanced"},
                   "velocity update of sliding contacts")
           .defaults("tangential")});
  DynamicsInput& dyn = input.dynamics;
  dyn.enabled = true;
  const std::string scheme = d.string("scheme");
  dyn.scheme = scheme == "hht"                 ? DynamicsScheme::hht
               : scheme == "bossak"            ? DynamicsScheme::bossak
               : scheme == "generalized_alpha" ? DynamicsScheme::generalized_alpha
               : scheme == "energy_momentum"   ? DynamicsScheme::energy_momentum
                                               : DynamicsScheme::newmark;
  const bool newmark = dyn.scheme == DynamicsScheme::newmark;
  const bool energy_momentum = dyn.scheme == DynamicsScheme::energy_momentum;
  if ((newmark || energy_momentum) && d.has("rho_infinity"))
    d.fail("rho_infinity", "only for the schemes hht, bossak and generalized_alpha");
  if (!newmark && (d.has("beta") || d.has("gamma")))
    d.fail(d.has("beta") ? "beta" : "gamma", "only for scheme newmark (the " + scheme +
                                                 " scheme sets it" +
                                                 (energy_momentum ? ")" : " from rho_infinity)"));
  dyn.rho_infinity = d.number("rho_infinity");
  if (dyn.rho_infinity > 1.0) d.fail("rho_infinity", "must be <= 1");
  if (dyn.scheme == DynamicsScheme::hht && dyn.rho_infinity < 0.5)
    d.fail("rho_infinity", "must be >= 0.5 for hht (alpha >= -1/3)");
  dyn.beta = d.number("beta");
  dyn.gamma = d.number("gamma");
  if (dyn.beta < 0.25 * (dyn.gamma + 0.5) * (dyn.gamma + 0.5) * (1.0 - 1e-12))
    d.fail("beta", "must be >= (gamma + 1/2)^2 / 4 for unconditional stability");
  dyn.mass = d.string("mass") == "lumped" ? MassKind::lumped : MassKind::consistent;
  const std::string treatment = d.string("contact_treatment");
  const bool velocity_update = treatment == "velocity_update";
  if (d.has("sliding") && !velocity_update)
    d.fail("sliding", "only with contact_treatment: velocity_update");
  const std::string sliding = d.string("sliding");
  dyn.contact_treatment = treatment == "standard" ? ContactTreatment::standard
                          : !velocity_update      ? ContactTreatment::stabilized
                          : sliding == "impact"   ? ContactTreatment::velocity_update_impact
                          : sliding == "balanced" ? ContactTreatment::velocity_update_balanced
                                                  : ContactTreatment::velocity_update_tangential;
  // balanced gives back the energy of the nodes that stay closed, of either sign: with
  // friction that would undo its dissipation.
  if (dyn.contact_treatment == ContactTreatment::velocity_update_balanced)
    for (const ContactInput& c : input.contact)
      if (c.type == ContactKind::frictional)
        d.fail("sliding",
               "balanced is for frictionless and tied contact (it would give back the "
               "friction's dissipation); contact pair '" +
                   c.name + "' is frictional");
  for (const MaterialInput& m : input.materials) {
    if (!(m.density > 0.0)) {
      throw InputError(input.file + ": grout/materials/" + m.name +
                       "/density: required > 0 with a 'dynamics' section");
    }
  }
}

}  // namespace grout
