"""Kratos' Hertz mesh (hertz_complete_test, converted from .mdpa), load-controlled from zero
displacement with a 1e-4 initial gap: contact half-width b and peak pressure p_max within 5 %
of Hertz, equilibrium |reaction| = P, 1 and 2 ranks agree to 1e-10.

Reference: Johnson, Contact Mechanics (Cambridge 1985), §4.2, two parallel cylinders
(contact_check.hertz_line_contact): R1 = R2 = 8 (R* = 4), E = 200, nu = 0.3
(E* = E/(2(1 - nu^2)) = 109.89), P = 0.5 x 16 = 8 per unit length:
    b = sqrt(4 P R*/(pi E*)) = 0.6089,    p_max = 2P/(pi b) = 8.364.
The 1e-4 gap changes the load carried by contact by 1e-4 x (stiffness) -- far below 5 %. The
mesh has 40 slave faces over x in [-1, 1] (h = 0.05, b/h = 12); the computed b and p_max are
measured as in hertz_cylinders (contact_check.hertz_level).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402
from grout_results import Results  # noqa: E402

R, E, NU, P = 8.0, 200.0, 0.3, 0.5 * 16.0
B, P0 = cc.hertz_line_contact(P, R, R, E, NU, E, NU)
TOL = 0.05


def main():
    failures = []
    lv = cc.hertz_level("np1/hertz_complete.e", "contact_part_body_upper", B, P0)
    diff, msg = cc.compare_ranks("np1/hertz_complete.e", "np2/hertz_complete.e",
                                 ["displ_x", "displ_y", "contact_pressure"])
    if msg:
        failures.append(msg)
    force = abs(Results("np1/hertz_complete.e").global_var("reaction_displacement_bc_fix_y"))
    print("Kratos Hertz mesh: b = %.5f (Hertz %.5f, err %.2f %%), p_max = %.5g (Hertz %.5g, "
          "err %.2f %%), |reaction| = %.8g (P = %g), 1 vs 2 ranks %.1e"
          % (lv["b"], B, 100 * lv["err_b"], lv["p_max"], P0, 100 * lv["err_p"], force, P, diff))
    if not lv["err_b"] <= TOL:
        failures.append("half-width error %.2f %% > 5 %%" % (100 * lv["err_b"]))
    if not lv["err_p"] <= TOL:
        failures.append("p_max error %.2f %% > 5 %%" % (100 * lv["err_p"]))
    if not abs(force - P) <= 1e-6 * P:
        failures.append("|reaction| = %.8g, expected P = %g" % (force, P))
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
