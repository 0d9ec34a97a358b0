"""Lamé's thick-walled cylinder under internal pressure, plane strain (Timoshenko & Goodier,
Theory of Elasticity, §28): the analytic fields and the nodal error of a Grout result."""
import numpy as np

from grout_results import Results

A, B, P, E, NU = 1.0, 2.0, 10.0, 1000.0, 0.3


def radial_displacement(r):
    return (1 + NU) * P * A**2 / (E * (B**2 - A**2)) * ((1 - 2 * NU) * r + B**2 / r)


def hoop_stress(r):
    return P * A**2 / (B**2 - A**2) * (1 + B**2 / r**2)


def radial_stress(r):
    return P * A**2 / (B**2 - A**2) * (1 - B**2 / r**2)


def nodal_radial(path, step=-1):
    """(r, computed u_r, exact u_r at t = 1) at every node of the result file."""
    res = Results(path)
    x, y = res.coordinates()[:2]
    r = np.hypot(x, y)
    ur = (res.nodal("displ_x", step) * x + res.nodal("displ_y", step) * y) / r
    return r, ur, radial_displacement(r)


def max_relative_error(path):
    r, ur, exact = nodal_radial(path)
    return np.abs(ur - exact).max() / np.abs(exact).max()
