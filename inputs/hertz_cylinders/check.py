"""Hertz contact of two cylinders, plane strain, frictionless (docs/verification.md #8), on three
nested meshes: contact half-width b and peak pressure p_max against Hertz, errors decreasing
with refinement, the finest within 3 %; equilibrium |reaction_lower_bottom_y| = P; 1 and 2
ranks agree to 1e-10. Writes hertz_profile.csv (finest mesh: x, p computed, p analytic),
hertz_convergence.csv and hertz_profile.png.

Reference: Johnson, Contact Mechanics (Cambridge 1985), §4.2 (two-dimensional contact of
cylindrical bodies). For two parallel cylinders of radii R1, R2 pressed together by a force P
per unit length, with the effective radius and plane-strain modulus
    1/R* = 1/R1 + 1/R2,        1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2,
the contact is the strip |x| <= b with
    b^2 = 4 P R*/(pi E*),      p(x) = (2P/(pi b^2)) sqrt(b^2 - x^2),   p_max = 2P/(pi b)
(the elliptic pressure integrates to P). Here R1 = R2 = R = 8 (R* = 4), E = 200, nu = 0.3
(E* = E/(2(1 - nu^2)) = 109.89), and the load is p = 0.625 on the full diameter, P = 2Rp = 10:
    b = sqrt(4 * 10 * 4/(pi * 109.89)) = 0.6808,    p_max = 20/(pi * 0.6808) = 9.351.
docs/verification.md #8 writes the same pair as b = 2 sqrt(2 R^2 p (1 - nu^2)/(E pi)) and
p_max = 4Rp/(pi b) = 2P/(pi b) (consistent: 4Rp = 2P).

Computed b: on each side the edge between the last active slave node x_a and the first
inactive one is located with the Hertz edge behaviour p^2 ~ (b - x) (p^2 linear in x^2 through
the last two active nodes), clamped to [x_a, x_i]; the mean of both sides is b_h.
p_max = the largest nodal contact_pressure (a slave node sits at x = 0).
Hertz assumes b << R (here b/R* = 0.17) and half-spaces; the finite bodies and the held
loaded face make the converged FE solution differ from Hertz by up to a couple of per cent,
hence the 3 % tolerance; "decreasing" is judged finest vs coarsest level, or, where the error
against Hertz stalls at that model error, by the computed values converging
(|q3 - q2| < |q2 - q1|, contact_check.assess_convergence).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402

R, E, NU, LOAD = 8.0, 200.0, 0.3, 0.625
P = 2 * R * LOAD
B, P0 = cc.hertz_line_contact(P, R, R, E, NU, E, NU)


def self_test():
    assert abs(P - 10.0) < 1e-15
    assert abs(B - 0.6808) < 5e-5 and abs(P0 - 9.35) < 5e-3, (B, P0)
    print("hertz_cylinders self-test: ok (b = %.6f, p_max = %.6f)" % (B, P0))


if __name__ == "__main__":
    if "--self-test" in sys.argv:
        self_test()
        sys.exit(0)
    failures = cc.hertz_study(["hertz_1", "hertz_2", "hertz_3"], "upper_contact", B, P0, P,
                              "reaction_lower_bottom_y",
                              "Hertz cylinder-cylinder (R = 8, P = 10): contact pressure", "hertz")
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)
