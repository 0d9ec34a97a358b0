"""Hertz contact of a cylinder on a rigid plane, plane strain, frictionless (docs/verification.md
#10), on three nested meshes: half-width b and peak pressure p_max against Hertz, errors
decreasing with refinement, the finest within 3 %; equilibrium |reaction_plane_y| = P;
1 and 2 ranks agree to 1e-10. Writes hertz_plane_profile.csv (finest mesh: x, p computed,
p analytic), hertz_plane_convergence.csv and hertz_plane_profile.png.

Reference: Johnson, Contact Mechanics (1985), §4.2, as in hertz_cylinders/check.py with a
rigid flat second body (R2 = inf, E2 = inf): R* = R, E* = E/(1 - nu^2),
    b^2 = 4 P R (1 - nu^2)/(pi E),    p(x) = (2P/(pi b^2)) sqrt(b^2 - x^2),   p_max = 2P/(pi b).
Benchmark data (Kratos thesis Table 4.7, used there for the axisymmetric sphere): R = 6.1237,
E = 1e8, nu = 0.29, plane E = 1e25 (rigid), load 5e5. Decision for the plane-strain cylinder:
5e5 is the pressure on the cylinder's flat face (the full diameter), P = 2 R p = 6.1237e6 per
unit thickness (the same load style as row 8), giving b = 0.6613 (b/R = 0.11) and
p_max = 5.895e6. (The E = 1e25 plane of the benchmark is held fixed: it is rigid either way.)
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402

R, E, NU, LOAD = 6.1237, 1.0e8, 0.29, 5.0e5
P = 2 * R * LOAD
B, P0 = cc.hertz_line_contact(P, R, math.inf, E, NU, math.inf, NU)


def self_test():
    assert abs(B - math.sqrt(4 * P * R * (1 - NU**2) / (math.pi * E))) < 1e-14
    assert abs(B - 0.6613) < 5e-5 and abs(P0 / 5.895e6 - 1) < 1e-3, (B, P0)
    print("hertz_plane self-test: ok (b = %.6f, p_max = %.6g)" % (B, P0))


if __name__ == "__main__":
    if "--self-test" in sys.argv:
        self_test()
        sys.exit(0)
    failures = cc.hertz_study(["hertz_plane_1", "hertz_plane_2", "hertz_plane_3"], "cylinder_contact",
                              B, P0, P, "reaction_plane_y",
                              "Hertz cylinder on rigid plane (R = 6.1237, P = 6.12e6)", "hertz_plane")
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)
