"""Stiffness of a half ring clamped at both ends and loaded by a point force at its lowest
point (inputs/double_arch, inputs/arc_block): Castigliano's theorem on a curved beam.

Section (per unit thickness, plane strain E' = E / (1 - nu^2), G = E / (2 (1 + nu))): layers
(r_in, r_out, E, nu), transformed to one beam about the stiffness-weighted centre radius
R = sum E' h r_c / sum E' h: E'A = sum E' h, E'I = sum E' (h^3 / 12 + h (r_c - R)^2),
GA = sum G h (shear correction kappa = 6/5 for a rectangle).

A quarter (0 <= theta <= pi/2 from the lowest point to the clamped end) carries at its cut
the vertical force V = P / 2, a horizontal force H and a moment M0; symmetry makes the cut
neither rotate nor move horizontally, dU/dM0 = dU/dH = 0, and the deflection under the load
is delta = dU/dV with
  U = 1/2 int (M^2 / E'I + N^2 / E'A + kappa Q^2 / GA) R dtheta,
  M = M0 + H R (1 - cos) - V R sin,  N = H cos + V sin,  Q = -H sin + V cos.
Returns P / delta. (Bending alone gives the classical result; the axial and shear terms change
it by 7 % for R / h = 14.5.) Valid for small deflections.

Self-test: python3 arch_theory.py (the bending-only stiffness against the same Castigliano
equations written out with the integrals in closed form).
"""
import numpy as np
from scipy.integrate import quad


def section(layers):
    """layers: [(r_in, r_out, E, nu)] -> (R, E'A, E'I, GA)."""
    ea = ei_0 = ga = 0.0
    sr = 0.0
    for r_in, r_out, e, nu in layers:
        h, rc, ep = r_out - r_in, 0.5 * (r_in + r_out), e / (1 - nu ** 2)
        ea += ep * h
        sr += ep * h * rc
        ga += e / (2 * (1 + nu)) * h
    r = sr / ea
    for r_in, r_out, e, nu in layers:
        h, rc, ep = r_out - r_in, 0.5 * (r_in + r_out), e / (1 - nu ** 2)
        ei_0 += ep * (h ** 3 / 12 + h * (rc - r) ** 2)
    return r, ea, ei_0, ga


def arch_stiffness(layers, axial=True, shear=True):
    r, ea, ei, ga = section(layers)

    def parts(t):
        s, c = np.sin(t), np.cos(t)
        return np.array([1, r * (1 - c), -r * s]), np.array([0, c, s]), np.array([0, -s, c])

    flex = np.zeros((3, 3))
    for p in range(3):
        for q in range(3):
            def f(t):
                m, n, s = parts(t)
                return (m[p] * m[q] / ei + axial * n[p] * n[q] / ea
                        + shear * 1.2 * s[p] * s[q] / ga) * r
            flex[p, q] = quad(f, 0, np.pi / 2)[0]
    x = np.linalg.solve(flex[:2, :2], -flex[:2, 2])
    return 2.0 / (flex[2, 2] + flex[2, :2] @ x)


if __name__ == "__main__":
    # Bending only: with a = int 1 = pi/2, b = int (1 - c) = pi/2 - 1, c2 = int (1 - c)^2 =
    # 3 pi/4 - 2, s1 = int s = 1, s2 = int s^2 = pi/4, sc = int s (1 - c) = 1/2 (R = 1, EI = 1):
    # solve [a b; b c2] [M0; H] = -[-s1; -sc] V, delta = (s2 V - s1 M0 - sc H) -> P/delta.
    a, b, c2, s1, s2, sc = np.pi / 2, np.pi / 2 - 1, 3 * np.pi / 4 - 2, 1.0, np.pi / 4, 0.5
    m0, h = np.linalg.solve([[a, b], [b, c2]], [s1, sc])
    closed = 2.0 / (s2 - s1 * m0 - sc * h)
    numeric = arch_stiffness([(1 - 0.5e-3, 1 + 0.5e-3, 12 / 1e-9, 0.0)], axial=False, shear=False)
    print("P R^3 / (E'I delta): closed form %.6f, numeric %.6f" % (closed, numeric))
    assert abs(numeric / closed - 1) < 1e-6
    layers = [(2.8, 3.0, 6.896e9, 0.32)]
    print("arc_block arc (E = 6.896e9): k = %.4e N/m per m" % arch_stiffness(layers))
    ring = [(0.085, 0.09, 1e11, 0.3), (0.09, 0.095, 1e9, 0.3)]
    print("double arch ring (inner 1e11, outer 1e9): k = %.4e N/m per m" % arch_stiffness(ring))
