"""Tip displacement of the inextensible elastica of a cantilever under a dead tip load.

    EI theta'(s) = P (x(L) - x(s)),  so  theta'' = -k cos(theta) / L^2,  k = P L^2 / EI,
    theta(0) = 0 (clamped), theta'(L) = 0 (no end moment);  x' = cos theta, y' = sin theta.
Shooting on theta'(0) (bisection) with classical RK4 on 1000 steps; tip displacements
u/L = 1 - x(L)/L and w/L = y(L)/L (Bisshopp & Drucker, Quart. Appl. Math. 3 (1945) 272;
tabulated by Mattiasson, Int. J. Numer. Meth. Eng. 17 (1981) 145, Table I:
k = 1: u/L = 0.05643, w/L = 0.30172;  k = 2: u/L = 0.16064, w/L = 0.49346).
"""
import math


def _integrate(k, kappa0, n=1000):
    """(theta'(1), x(1), y(1)) for unit length and initial curvature kappa0."""
    h = 1.0 / n

    def rhs(z):
        theta, kappa, x, y = z
        return (kappa, -k * math.cos(theta), math.cos(theta), math.sin(theta))

    z = (0.0, kappa0, 0.0, 0.0)
    for _ in range(n):
        k1 = rhs(z)
        k2 = rhs(tuple(a + 0.5 * h * b for a, b in zip(z, k1)))
        k3 = rhs(tuple(a + 0.5 * h * b for a, b in zip(z, k2)))
        k4 = rhs(tuple(a + h * b for a, b in zip(z, k3)))
        z = tuple(a + h / 6 * (b + 2 * c + 2 * d + e) for a, b, c, d, e in zip(z, k1, k2, k3, k4))
    return z[1], z[2], z[3]


def tip_displacement(k):
    """(u/L, w/L) of the elastica with load parameter k = P L^2 / EI (k < ~20)."""
    if k == 0.0:
        return 0.0, 0.0
    lo, hi = 0.0, k  # theta'(1) > 0 at kappa0 = 0 is false; at kappa0 = k it is >= 0
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        if _integrate(k, mid)[0] > 0.0:
            hi = mid
        else:
            lo = mid
    _, x, y = _integrate(k, 0.5 * (lo + hi))
    return 1.0 - x, y


if __name__ == "__main__":
    for k in (1.0, 2.0):
        print(k, tip_displacement(k))
