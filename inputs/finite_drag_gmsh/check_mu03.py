"""Finite-strain drag with Coulomb friction (mu = 0.3) from a touching and from an open start
(drag_touch_mu03.yaml, drag_gap_mu03.yaml; both with line_search: Backtrack).

References and checks:
- Both runs take the 12 steps of their input with no cut-back (the open start's landing step
  used to cycle and be cut to 1.5e-8; it then took 42 steps).
- Rate-independent friction: the open start reaches the touching start's indentation along the
  same path (die top moved straight down), so at t = 1 the forces agree up to the time
  discretisation of the stick/slip history (limit 1e-4 relative); once the die slides (every
  slave node slips, t >= 1.25) the history is gone and the two runs solve the same problem:
  forces equal to 1e-8 relative.
- Coulomb while sliding: the die carries only the contact and its top support, so the
  support's R_x / R_y is the interface's tangential over normal resultant, mu for full slip up
  to the tilt of the contact (the die's finite block): within 3 % of mu.
- The die stays in contact while it slides; 1 and 2 ranks: displacements within 1e-8.
- Grout's default Newton (drag_gap_mu03_default.yaml: no line_search key): the full step, and a
  failed step retried once at the same increment with line search Backtrack. It takes the 12
  steps with no cut-back; its Newton log shows damped updates (step_length < 1) in the landing
  step only (t = 0.5), full steps everywhere else; and it reaches drag_gap_mu03's forces
  (Backtrack throughout, which takes the full step wherever that decreases |F|) at every step
  within 1e-10 of R_y (measured 1e-11).
"""
import csv
import sys

import numpy as np

from drag_summary import summary
from grout_results import Results, relative_difference

MU, STEPS = 0.3, 12
failures = []

runs = {stem: summary(stem, 1) for stem in ("drag_touch_mu03", "drag_gap_mu03")}
for stem, (t, rx, ry, active) in runs.items():
    print("%s: %d steps to t = %g" % (stem, len(t), t[-1]))
    if len(t) != STEPS or abs(t[-1] - 3.0) > 1e-12:
        failures.append("%s: %d steps to t = %g (expected %d equal steps to 3: no cut-back)"
                        % (stem, len(t), t[-1], STEPS))
    sliding = t >= 1.25 - 1e-12
    if not active[t > 1.0 + 1e-9].min() > 0:
        failures.append("%s: the die left contact while sliding" % stem)
    ratio = rx[sliding] / ry[sliding]
    print("%s: R_x/R_y while sliding %.4f ... %.4f (mu = %g)" % (stem, ratio.min(), ratio.max(), MU))
    if np.abs(ratio / MU - 1).max() > 0.03:
        failures.append("%s: R_x/R_y while sliding off mu by %.2f %% (limit 3 %%)"
                        % (stem, 100 * np.abs(ratio / MU - 1).max()))

(t1, rx1, ry1, _), (t2, rx2, ry2, _) = runs["drag_touch_mu03"], runs["drag_gap_mu03"]
for t in t1[t1 >= 1.0 - 1e-12]:
    i, j = np.argmin(abs(t1 - t)), np.argmin(abs(t2 - t))
    if abs(t2[j] - t) > 1e-12:
        continue
    scale = abs(ry1[i])
    d = max(abs(rx2[j] - rx1[i]), abs(ry2[j] - ry1[i])) / scale
    limit = 1e-4 if t < 1.25 - 1e-12 else 1e-8
    print("t = %.3f: open start - touching start, forces %.2e of R_y (limit %g)" % (t, d, limit))
    if d > limit:
        failures.append("t = %g: the open start's forces differ from the touching start's by %.2e "
                        "of R_y (limit %g)" % (t, d, limit))

# Grout's default Newton: full step, a failed step retried with Backtrack.
t3, rx3, ry3, _ = runs["drag_gap_mu03_default"] = summary("drag_gap_mu03_default", 1)
if len(t3) != STEPS or abs(t3[-1] - 3.0) > 1e-12 or len(t3) != len(t2):
    failures.append("drag_gap_mu03_default: %d steps to t = %g (expected %d: no cut-back)"
                    % (len(t3), t3[-1], STEPS))
else:
    d = max(np.abs(rx3 - rx2).max(), np.abs(ry3 - ry2).max()) / np.abs(ry2).max()
    print("default Newton - line_search Backtrack, forces at every step: %.2e of R_y (limit 1e-10)"
          % d)
    if d > 1e-10:
        failures.append("the default Newton's forces differ from drag_gap_mu03's by %.2e of R_y" % d)
damped = sorted({float(r["time"]) for r in csv.DictReader(open("np1/drag_gap_mu03_default_newton.csv"))
                 if 0.0 < float(r["step_length"]) < 1.0})
print("default Newton: damped updates in the steps ending at t = %s" % damped)
if damped != [0.5]:
    failures.append("default Newton: damped updates at t = %s (expected the landing step, 0.5, only)"
                    % damped)

for stem in runs:
    r1, r2 = Results("np1/%s.e" % stem), Results("np2/%s.e" % stem)
    for name in ("displ_x", "displ_y"):
        d = relative_difference(r1.nodal(name), r2.nodal(name))
        if d > 1e-8:
            failures.append("%s: %s differs between 1 and 2 ranks by %.3e" % (stem, name, d))

for f in failures:
    print("FAIL:", f)
print("check_mu03: %s" % ("all checks passed" if not failures else "%d failure(s)" % len(failures)))
sys.exit(1 if failures else 0)
