"""Bar impact (inputs/bar_impact) against the 1D wave solution.

Two identical bars of length L = 1, wave speed c = sqrt(E/rho) = 1; the striker hits the struck
bar at v0 = -0.01. Elementary wave theory (e.g. Graff, Wave Motion in Elastic Solids, section
1.5): the contact lasts 2L/c = 2; afterwards the striker is at rest and the struck bar moves
with v0, and no energy is lost. Checked: the mass-weighted mean velocity of each bar after the
contact (within 3 % of |v0|), the contact duration (within 3 %), the total energy (within
1 % of the initial kinetic energy 1/2 m v0^2, and never above it: the stabilised contact
treatment cannot add energy), and 1 rank = 2 ranks to 1e-10.
"""
import csv
import sys

import numpy as np

from grout_results import Results, relative_difference

v0, m, duration = -0.01, 0.1, 2.0
E0 = 0.5 * m * v0**2
failures = []

with open("np1/bar_impact.csv") as f:
    rows = list(csv.DictReader(f))
t = np.array([float(r["time"]) for r in rows])
active = np.array([float(r["active_nodes"]) for r in rows])
E = np.array([float(r["total_energy"]) for r in rows])
t_release = t[active > 0].max() if (active > 0).any() else 0.0
# Contact is counted on the steps that end with an active node: it ends between t_release and
# the next step.
dt = t[1] - t[0]
t_contact = t_release + 0.5 * dt
print("contact duration %.4f (exact %.4f, error %.2f %%)" % (t_contact, duration,
                                                               100 * (t_contact / duration - 1)))
if abs(t_contact / duration - 1) > 0.03:
    failures.append("contact duration %.4f, expected %.4f within 3 %%" % (t_contact, duration))
drift = (E - E0) / E0
print("total energy: final drift %.3e, max gain %.3e, max loss %.3e"
      % (drift[-1], drift.max(), -drift.min()))
if np.abs(drift).max() > 0.01:
    failures.append("total energy changes by %.3e of the initial (limit 1 %%)" % np.abs(drift).max())
if drift.max() > 1e-9:
    failures.append("contact adds energy: %.3e of the initial" % drift.max())

# Energy history (bar_impact_energy.png): kinetic, strain and total against the initial value.
import matplotlib.pyplot as plt  # noqa: E402

kin = np.array([float(r["kinetic_energy"]) for r in rows])
strain = np.array([float(r["strain_energy"]) for r in rows])
fig, ax = plt.subplots(figsize=(6, 3.6))
ax.plot(t, kin / E0, label="kinetic")
ax.plot(t, strain / E0, label="strain")
ax.plot(t, E / E0, "k", label="total")
ax.axvline(duration, color="grey", ls=":", label="2L/c")
ax.set_xlabel("t")
ax.set_ylabel("energy / initial kinetic energy")
ax.set_title("Bar impact, Newmark, stabilised contact")
ax.legend(loc="center right")
fig.tight_layout()
fig.savefig("bar_impact_energy.png", dpi=120)

r = Results("np1/bar_impact.e")
y = r.coordinates()[1]
vy = r.nodal("velocity_y")
for block, name, expected in ((1, "struck (lower)", v0), (2, "striker (upper)", 0.0)):
    nodes = np.unique(r.connectivity(block))
    ys = y[nodes]
    # Lumped (trapezoidal) weights along the bar: half at both ends.
    w = np.where((ys == ys.min()) | (ys == ys.max()), 0.5, 1.0)
    mean = (w * vy[nodes]).sum() / w.sum()
    err = abs(mean - expected) / abs(v0)
    print("%-16s mean velocity %+.5e (exact %+.5e), error %.2f %% of |v0|" % (name, mean, expected,
                                                                          100 * err))
    if err > 0.03:
        failures.append("%s: mean velocity %.4e, expected %.4e within 3 %% of |v0|"
                        % (name, mean, expected))
r2 = Results("np2/bar_impact.e")
for name in ("displ_y", "velocity_y", "contact_pressure"):
    d = relative_difference(r.nodal(name), r2.nodal(name))
    if d > 1e-10:
        failures.append("%s differs between 1 and 2 ranks by %.3e" % (name, d))
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
