"""Cut-back budget per step (hertz_cutback_1): the run reaches t = 1 through more than 6
halvings in all, and its last step is the one-step solution of hertz_1 (frictionless, small
strain: the solution does not depend on the load path) to 1e-8 relative, on 1 and 2 ranks.
"""
import sys

import numpy as np

from grout_results import Results, relative_difference

failures = []
for np_ in (1, 2):
    a, c = Results("np%d/hertz_1.e" % np_), Results("np%d/hertz_cutback_1.e" % np_)
    times = c.times()
    print("np%d: %d steps, last t = %.17g" % (np_, len(times), times[-1]))
    if abs(times[-1] - 1.0) > 1e-12:
        failures.append("np%d: last step at t = %.17g, not 1" % (np_, times[-1]))
    if len(times) < 3:
        failures.append("np%d: %d steps: the case no longer needs cut-backs" % (np_, len(times)))
    for name in ("displacement", "contact_pressure"):
        if name == "displacement":
            ua = np.concatenate([a.nodal("displ_x"), a.nodal("displ_y")])
            uc = np.concatenate([c.nodal("displ_x"), c.nodal("displ_y")])
            d = relative_difference(ua, uc)
        else:
            d = relative_difference(a.nodal(name), c.nodal(name))
        print("np%d %s: one step vs cut-backs: %.2e" % (np_, name, d))
        if not d < 1e-8:
            failures.append("np%d %s differs from the one-step run (%.2e)" % (np_, name, d))
if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("cut-back budget per step: OK")
