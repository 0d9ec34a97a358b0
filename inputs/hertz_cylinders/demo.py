"""Hertz cylinders demo: compare one result with Hertz' solution (Johnson, Contact Mechanics,
§4.2), print the half-width and peak pressure, and plot p(x) against the analytic curve.

    python3 demo.py <result.e> <plot.png>
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402

R, E, NU, LOAD = 8.0, 200.0, 0.3, 0.625
P = 2 * R * LOAD
result, png = sys.argv[1], sys.argv[2]
b, p0 = cc.hertz_line_contact(P, R, R, E, NU, E, NU)
level = cc.hertz_level(result, "upper_contact", b, p0)
print("Hertz contact of two cylinders, plane strain: R = %g, E = %g, nu = %g, P = %g per unit "
      "thickness" % (R, E, NU, P))
print("%-22s %12s %12s %10s" % ("", "Grout", "Hertz", "rel. err"))
print("%-22s %12.5f %12.5f %9.2f%%" % ("contact half-width b", level["b"], b, 100 * level["err_b"]))
print("%-22s %12.5f %12.5f %9.2f%%" % ("peak pressure p_max", level["p_max"], p0, 100 * level["err_p"]))
print("%-22s %12.2f%%" % ("profile RMS error", 100 * level["err_rms"]))
cc.plot_profiles([level], b, p0, "Hertz contact of two cylinders (plane strain)", png,
                 labels=["Grout, " + os.path.basename(result)])
