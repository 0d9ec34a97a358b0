"""Compare a thick-walled cylinder result with Lame's solution: print a table and write a
PNG of u_r(r) and the hoop stress against the analytic curves.

    python3 demo.py <result.e> <plot.png>
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from grout_results import Results
from lame import A, B, hoop_stress, nodal_radial, radial_displacement

result, png = sys.argv[1], sys.argv[2]
r, ur, exact = nodal_radial(result)

print("Thick-walled cylinder, plane strain, a = %g, b = %g, p = 10, E = 1000, nu = 0.3" % (A, B))
print("%8s %14s %14s %10s" % ("r", "u_r Grout", "u_r Lame", "rel. err"))
for target in np.linspace(A, B, 5):
    sel = np.isclose(r, r[np.argmin(np.abs(r - target))])
    print("%8.4f %14.6e %14.6e %10.2e" % (r[sel][0], ur[sel].mean(), exact[sel][0],
                                          abs(ur[sel].mean() - exact[sel][0]) / exact[sel][0]))
print("max relative nodal error of u_r: %.3e" % (np.abs(ur - exact).max() / np.abs(exact).max()))

res = Results(result)
xc = res.element_centroids()
rc = np.hypot(xc[:, 0], xc[:, 1])
cos, sin = xc[:, 0] / rc, xc[:, 1] / rc
sxx, syy, sxy = res.element("stress_xx"), res.element("stress_yy"), res.element("stress_xy")
s_hoop = sxx * sin**2 + syy * cos**2 - 2 * sxy * sin * cos

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
rr = np.linspace(A, B, 200)
ax1.plot(rr, radial_displacement(rr), "k-", label="Lamé (analytic)")
ax1.plot(r, ur, "o", ms=3, label="Grout (nodes)")
ax1.set_xlabel("r")
ax1.set_ylabel("radial displacement $u_r$")
ax1.legend()
ax2.plot(rr, hoop_stress(rr), "k-", label="Lamé (analytic)")
ax2.plot(rc, s_hoop, "s", ms=2, label="Grout (element average)")
ax2.set_xlabel("r")
ax2.set_ylabel(r"hoop stress $\sigma_{\theta\theta}$")
ax2.legend()
fig.suptitle("Thick-walled cylinder under internal pressure (plane strain)")
fig.tight_layout()
fig.savefig(png, dpi=120)
print("wrote", png)
