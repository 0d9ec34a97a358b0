"""The cylinder's rotation under small strain as a Hill equation (docs/verification.md,
"Rotation of the cylinder", item 5): I theta'' + r F(t) theta = 0, I = m r^2 / 2, with F the
normal force of the frictionless pendulum, F = m (g cos phi + L phi'^2), phi(t) the exact
pendulum released at 90 degrees. Prints the monodromy matrix over one period of F (a half
period of the pendulum, T/2) for a few cylinder radii: |trace| / 2 > 1 is a parametric
resonance (the rotation grows exponentially), = 1 its boundary (a Jordan block: linear growth).

Usage: hill.py [--length L]  (L = 0.7 for ring.yaml; 0.65 for the 3D mesh)
"""
import argparse

import numpy as np
from scipy.integrate import solve_ivp
from scipy.special import ellipk

ap = argparse.ArgumentParser()
ap.add_argument("--length", type=float, default=0.7)
a = ap.parse_args()
g, L = 9.81, a.length
T = 4 * np.sqrt(L / g) * ellipk(0.5)


def monodromy(r):
    def rhs(t, y):  # phi, phi', and two solutions (theta, theta') of the Hill equation
        k_over_I = r * (g * np.cos(y[0]) + L * y[1] ** 2) / (0.5 * r * r)
        return [y[1], -g / L * np.sin(y[0]), y[3], -k_over_I * y[2], y[5], -k_over_I * y[4]]
    s = solve_ivp(rhs, [0, T / 2], [np.pi / 2, 0, 1, 0, 0, 1], rtol=1e-11, atol=1e-13)
    return np.array([[s.y[2, -1], s.y[4, -1]], [s.y[3, -1], s.y[5, -1]]])


print("pendulum L = %g, T = %.4f s; monodromy of I theta'' + r F(t) theta = 0 over T/2:" % (L, T))
for r in (0.19, 0.2, 0.21):
    M = monodromy(r)
    print("r = %.2f: [[%+.4f, %+.4f], [%+.4f, %+.4f]], trace/2 = %+.4f" % (r, *M.ravel(),
                                                                          np.trace(M) / 2))
