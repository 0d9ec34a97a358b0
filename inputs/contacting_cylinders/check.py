"""Contacting cylinders (docs/verification.md #17; Kratos use_cases/cylinders): the reaction at
the lower base of Kratos' three set-ups against what the geometry and the laws imply.

Usage: check.py [--horizontal STEM] [--frictional STEM] [--frictional-dynamic STEM]
                [--vertical STEM] [--tubes STEM:H ...] [--ranks STEM ...]
                [--mu 1.0] [--ratio-tol 0.02] [--small 2e-3]
  STEMs: np1/STEM.csv (the per-step summary) and np1/STEM.e; --ranks: the STEMs also ran on
  2 ranks (np2/), compared with 1 rank (displacements, contact pressures) to 1e-10.

Geometry (README.md, Kratos' meshes): the lower half-tube, outer radius R1 = 0.17 (inner 0.13),
axis = the z axis, z in [0, 0.17], flat faces y = 0 fixed; the upper, outer radius R2 = 0.13
(inner 0.09), z in [0.04, 0.15], its flat faces (through its axis) moved rigidly, so its axis
is at c(t) = c0 + u(t). Overlap length
L = 0.11. Rigid interference i(t) = R1 + R2 - |c(t)|, along n = c / |c| (from the lower axis to
the upper one).

--horizontal (horizontal_movement_2, frictionless; c0 = (-0.20, 0.23), u = (0.2 t, 0)): the
benchmark's check (#17), the reaction at the lower base rises, then vanishes on separation:
  - before contact (i < 0 at every time up to that step) the base reaction is zero
    (|R| <= 1e-6 of its peak: the Newton tolerance leaves ~1e-9);
  - |R| rises from the first contact step to its peak, step by step (a step may not lower it by
    more than 1e-3 of the peak); frictionless, the peak lies in the overlapping half of the
    pass (|x| <= 0.1: the conservative pass is symmetric about x = 0; friction shifts it);
  - |R| falls from the peak to separation, step by step (the same 1e-3), and once the rigid
    gap exceeds 2 % of R2 (t >= 2.1, x >= 0.22) it is zero (<= 1e-6 of the peak) and no slave
    node is active.
Printed, not checked: the symmetry of the frictionless pass about x = 0 (R_y(x) = R_y(-x),
R_x(x) = -R_x(-x) for a conservative elastic system; the meshes are not mirror-symmetric), and
the net work of the moved face over the pass, sum R_x du / sum |R_x du| (0 when nothing is
dissipated).
--frictional (the same pass, Coulomb mu, static; CI to t = 1.25): zero before contact and |R|
rising step by step over the whole run; it has no peak before x = 0.17: friction drags the
lower tube's surface along, and at t = 1.879 the static path ends in a snap-off (README.md).
--frictional-dynamic (the same pass in implicit dynamics through the snap-off, as Kratos):
zero before contact, |R| rising step by step to its peak; the fall from the peak is the
snap-off, a vibration (printed); once the rigid gap exceeds 2 % of R2 (t >= 2.1) |R| <= 1e-6 of
the peak and no slave node is active. Printed: the kinetic energy against its quasi-static
level and the strain energy released.
Sliding (#17: the tangential reaction = mu x normal within 2 %): at each step in contact where
every active slave node slips (contact_status = 2), the base reaction R (by equilibrium the
whole contact force) against the friction cone about the contact's normal n, the
pressure-weighted mean outward normal of the slave faces in the deformed configuration:
|R - (R.n) n| / |R.n| = mu within --ratio-tol. (Split along the line of the axes instead, T/N
drifts to 1.13 by t = 0.45: friction tilts the flattened contact, 20 degrees off that line at
t = 1.) In dynamics only the quasi-static steps (kinetic energy <= 1e-6 of the strain energy).
--vertical (vertical_movement, frictionless; c0 = (0.04, 0.31), u = (0, -0.1 t)): no reaction
before the rigid contact time (<= 1e-6 of the largest), then the normal reaction R.n rising at
every step. Printed for 0 < i <= --small: R.n against the tubes' reference (tube_force: the
approach of the flat faces = F (c_upper + c_lower) + each body's local Hertz compression, c
the compliance of a clamped half-ring, as bounds "stiff" and "soft") and against the Hertz
line-contact approach of two *solid* cylinders (Johnson, Contact Mechanics, Cambridge 1985,
section 4.3, pp. 99-104; Puttock and Thwaite 1969): per unit length P' = F / L,
    b = sqrt(4 P' R* / (pi E*)),  1/R* = 1/R1 + 1/R2,  1/E* = 2 (1 - nu^2) / E,
    approach of the axes  i = P' / (pi E*) [ln(4 R1 / b) + ln(4 R2 / b) - 1],
which does not apply: Kratos' bodies are tubes (R.n = 0.19-0.27 of it).
--tubes STEM:H ... (the same motion from t = 0.125 on gmsh meshes of the tubes, element size H,
coarse to fine; c0 = (0.04, 0.2975)): the refinement study, checked against the tubes'
reference (tubes()).
"""
import argparse
import csv
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402
from grout_results import Results  # noqa: E402

R1, R2, L = 0.17, 0.13, 0.11
WALL = 0.04  # Kratos' bodies are half-tubes: radii 0.13-0.17 (lower), 0.09-0.13 (upper)
RM_LOWER, RM_UPPER = R1 - WALL / 2, R2 - WALL / 2
E, NU = 2.1e11, 0.29
E_STAR = E / (2 * (1 - NU ** 2))
R_STAR = 1.0 / (1.0 / R1 + 1.0 / R2)
HORIZONTAL = {"c0": (-0.20, 0.23), "v": (0.2, 0.0)}
VERTICAL = {"c0": (0.04, 0.31), "v": (0.0, -0.1)}
# The refinement study's gmsh tubes (tubes_mesh.py --upper-y 0.2975): Kratos' vertical motion
# from t = 0.125 on (vertical_tubes_*.yaml).
TUBES = {"c0": (0.04, 0.2975), "v": (0.0, -0.1)}
# The refinement study's range of rigid overlaps: from twice the facets' sagitta at the
# coarsest level, (1/R1 + 1/R2) h^2 / 8 = 6.8e-4 at h = 0.02 (the contact's onset moves with
# the nodes' positions), to 4e-3 (Hertz' half-width b = 0.006, 0.15 of the wall).
TUBES_I = (1.5e-3, 4e-3)


def summary(stem):
    with open("np1/%s.csv" % stem) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit("np1/%s.csv: no steps" % stem)
    col = {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}
    # The base's node set: "base" (Kratos' meshes) or "base_cylinders_nodes" (tubes_mesh.py).
    base = "reaction_base" if "reaction_base_x" in col else "reaction_base_cylinders_nodes"
    col["R"] = np.vstack([col["%s_%s" % (base, c)] for c in "xyz"])
    return col


def centre(setup, t):
    return np.array(setup["c0"])[:, None] + np.outer(setup["v"], t)


def interference(setup, t):
    c = centre(setup, t)
    return R1 + R2 - np.hypot(c[0], c[1]), c / np.hypot(c[0], c[1])


def ring_compliance(rm, width, plane_strain, theta, n=720):
    """Radial displacement per unit load at the loaded point of a half-ring: a semicircular
    curved beam of centroid radius rm, wall WALL, the given width, clamped at both ends (the
    tube's flat faces), loaded radially inwards at angle theta from one end. Timoshenko beam
    theory (bending, stretching, shear with k = 5/6) on n straight two-node frame elements with
    the exact stiffness of a straight Timoshenko beam (Przemieniecki, Theory of Matrix Structural
    Analysis, 1968, ch. 5); E' = E / (1 - nu^2) in plane strain, E in plane stress. (Without
    shear, such a frame gives a quarter-circle cantilever's tip deflection (3 pi / 4 - 2) P R^3 /
    (E I), Castigliano, to 1e-4 with 400 elements.) Thick-ring corrections (R / wall = 2.75 and
    3.75 here) are a few per cent."""
    e = E / (1 - NU ** 2) if plane_strain else E
    g = E / (2 * (1 + NU))
    area, inertia = width * WALL, width * WALL ** 3 / 12
    th = np.linspace(0.0, math.pi, n + 1)
    k_load = int(round(theta / math.pi * n))
    x = rm * np.vstack([np.cos(th), np.sin(th)]).T
    K = np.zeros((3 * (n + 1), 3 * (n + 1)))
    for j in range(n):
        d = x[j + 1] - x[j]
        le = math.hypot(d[0], d[1])
        c, s = d / le
        phi = 12 * e * inertia / (5.0 / 6.0 * g * area * le ** 2)
        f = e * inertia / (le ** 3 * (1 + phi))
        k = np.zeros((6, 6))
        k[np.ix_([0, 3], [0, 3])] = e * area / le * np.array([[1, -1], [-1, 1]])
        a, b = (4 + phi) * le ** 2, (2 - phi) * le ** 2
        k[np.ix_([1, 2, 4, 5], [1, 2, 4, 5])] = f * np.array(
            [[12, 6 * le, -12, 6 * le], [6 * le, a, -6 * le, b],
             [-12, -6 * le, 12, -6 * le], [6 * le, b, -6 * le, a]])
        r = np.array([[c, s, 0], [-s, c, 0], [0, 0, 1]])
        T = np.kron(np.eye(2), r)
        dof = slice(3 * j, 3 * j + 6)
        K[dof, dof] += T.T @ k @ T
    free = np.arange(3, 3 * n)
    load = np.zeros(3 * (n + 1))
    direction = -np.array([math.cos(th[k_load]), math.sin(th[k_load])])
    load[3 * k_load:3 * k_load + 2] = direction
    u = np.linalg.solve(K[np.ix_(free, free)], load[free])
    return float(u[3 * k_load - 3:3 * k_load - 1] @ direction)


def local_approach(p):
    """Approach of the contact point to the wall's mid-surface (depth d = WALL / 2) of one body
    under a line load p per unit length with Hertz' pressure of half-width b (from both
    curvatures R1, R2): Flamant's line load on a half-plane displaces a point at depth z by
    2 (1 - nu^2) p / (pi E) ln z plus a constant (Johnson, Contact Mechanics, 1985, section
    2.2); spread over Hertz' pressure, the centre of the contact approaches depth d by
    (1 - nu^2) p / (pi E) [2 ln(2 d / b) - nu / (1 - nu)] (the form of the per-body term of
    the solid estimate below, with d in place of 2 R)."""
    b = math.sqrt(4 * p * R_STAR / (math.pi * E_STAR))
    return (1 - NU ** 2) * p / (math.pi * E) * (2 * math.log(WALL / b) - NU / (1 - NU)), b


def tube_references(c):
    """Compliances (upper, lower) of the two half-rings for the contact on the line of the axes
    c (from the lower axis to the upper; the load's angle from the flat faces is the same for
    both), as bounds: "stiff" = plane strain with the lower tube's whole length 0.17 carrying the
    load (uniform along z: a constraint, so stiffer than the 3D body), "soft" = plane stress with
    both carrying it over the contact length L = 0.11 only."""
    theta = math.atan2(abs(c[1]), abs(c[0]))
    return {"stiff": (ring_compliance(RM_UPPER, L, True, theta),
                      ring_compliance(RM_LOWER, 0.17, True, theta)),
            "soft": (ring_compliance(RM_UPPER, L, False, theta),
                     ring_compliance(RM_LOWER, L, False, theta))}


def tube_force(i, comp):
    """Total force F whose approach of the two tubes' flat faces along the line of the axes is
    the rigid interference i: i = F (c_upper + c_lower) + the local approach of each body at
    p = F / L (fixed point; README.md, "Vertical motion: a reference for the tubes")."""
    f = i / sum(comp)
    for _ in range(200):
        d, _ = local_approach(f / L)
        f_new = (i - 2 * d) / sum(comp)
        if abs(f_new - f) <= 1e-13 * abs(f):
            break
        f = f_new
    return f


def hertz_force(i):
    """Total force F = P' L whose Hertz line-contact approach of two *solid* cylinders is i
    (fixed point on b): the estimate the vertical motion was first compared with (0.19-0.27 of
    it, README.md: Kratos' bodies are tubes)."""
    p = 1e7
    for _ in range(200):
        b = math.sqrt(4 * p * R_STAR / (math.pi * E_STAR))
        p_new = i * math.pi * E_STAR / (math.log(4 * R1 / b) + math.log(4 * R2 / b) - 1)
        if abs(p_new - p) <= 1e-13 * p:
            break
        p = p_new
    return p * L, b


def rise_and_vanish(stem, col, failures, symmetric, vanish=True, snap=False):
    """snap (the mu = 1 pass in dynamics): the fall from the peak is the snap-off, a vibration
    of the bodies (rebounds, printed), not a static path: only its end is checked."""
    t, R = col["time"], col["R"]
    mag = np.linalg.norm(R, axis=0)
    i, _ = interference(HORIZONTAL, t)
    peak = float(mag.max())
    k = int(np.argmax(mag))
    x_peak = HORIZONTAL["c0"][0] + HORIZONTAL["v"][0] * t[k]
    print("%s: peak |R| = %.4g at t = %.3f (x = %+.3f); %d steps" % (stem, peak, t[k], x_peak,
                                                                   len(t)))
    if peak <= 0:
        failures.append("%s: no reaction at the base" % stem)
        return mag
    before = np.maximum.accumulate(i) < 0
    if np.any(before) and mag[before].max() > 1e-6 * peak:
        failures.append("%s: base reaction %.3g before contact" % (stem, mag[before].max()))
    first = int(np.argmax(~before))
    rise = np.diff(mag[first:k + 1] if vanish else mag[first:])
    fall = np.diff(mag[k:]) if vanish and not snap else np.zeros(0)
    if snap:
        print("%s: from the peak to t = 2.1: %d steps, largest rebound %.3g of the peak"
              % (stem, int(np.sum((t > t[k]) & (t < 2.1))),
                 max(0.0, float(np.diff(mag[k:]).max(initial=0.0))) / peak))
    if rise.size and rise.min() < -1e-3 * peak:
        failures.append("%s: |R| drops by %.3g of the peak while rising"
                        % (stem, -rise.min() / peak))
    if fall.size and fall.max() > 1e-3 * peak:
        failures.append("%s: |R| grows by %.3g of the peak while falling"
                        % (stem, fall.max() / peak))
    if symmetric and abs(x_peak) > 0.1:
        failures.append("%s: the peak lies at x = %+.3f, outside |x| <= 0.1" % (stem, x_peak))
    if vanish:
        after = t >= 2.1 - 1e-12
        if not np.any(after):
            failures.append("%s: the run ends at t = %.3f, before separation (t >= 2.1)"
                            % (stem, t[-1]))
        else:
            left = mag[after].max() / peak
            active = int(col["active_nodes"][after].max())
            print("%s: after separation (t >= 2.1): |R| <= %.2e of the peak, %d active nodes"
                  % (stem, left, active))
            if left > 1e-6 or active:
                failures.append("%s: the reaction does not vanish on separation (%.3g of the peak, "
                                "%d active)" % (stem, left, active))
    if not vanish or snap:
        return mag
    # Printed: the pass's symmetry about x = 0 (t <-> 2 - t) and the net work.
    mirror = {round(tt, 9): j for j, tt in enumerate(t)}
    worst_y = worst_x = 0.0
    for j, tt in enumerate(t):
        m = mirror.get(round(2.0 - tt, 9))
        if m is not None:
            worst_y = max(worst_y, abs(R[1, j] - R[1, m]))
            worst_x = max(worst_x, abs(R[0, j] + R[0, m]))
    du = np.diff(np.concatenate([[0.0], HORIZONTAL["v"][0] * t]))
    rx = -R[0]  # the force on the moved face balances the base's reaction
    work = np.sum(0.5 * (rx + np.concatenate([[0.0], rx[:-1]])) * du)
    scale = np.sum(np.abs(0.5 * (rx + np.concatenate([[0.0], rx[:-1]])) * du))
    print("%s: mirror x -> -x: max |R_y(x) - R_y(-x)| = %.2e, |R_x(x) + R_x(-x)| = %.2e of the "
          "peak; net work of the moved face %.3e of sum |R_x du|"
          % (stem, worst_y / peak, worst_x / peak, work / scale))
    return mag


# Exodus TET4 sides (local nodes), outward.
TET_SIDES = {1: (0, 1, 3), 2: (1, 2, 3), 3: (0, 3, 2), 4: (0, 2, 1)}


def snap_energy(stem, col):
    """Printed: the snap-off in energies: the kinetic energy against the quasi-static level
    (1/2 m v^2 of the moved tube at 0.2: 0.24) and the strain energy released."""
    t, ke, se = col["time"], col["kinetic_energy"], col["strain_energy"]
    k = int(np.argmax(ke))
    before = t < t[k]
    print("%s: kinetic energy %.3g at t = %.6f (before the snap at most %.3g); strain energy "
          "%.4g before, %.4g at t = %.3f" % (stem, ke[k], t[k], ke[t < 1.8].max(initial=0.0),
                                             se[before].max(initial=0.0), se[-1], t[-1]))


def slave_faces(res):
    """Node triples of the side set slave_cylinders (the upper curved face), outward."""
    names = cc._names(res.ds, "ss_names")
    k = names.index("slave_cylinders") + 1
    elems = np.array(res.ds.variables["elem_ss%d" % k][:]) - 1
    sides = np.array(res.ds.variables["side_ss%d" % k][:])
    conn = res.connectivity(1)
    return np.array([conn[e, list(TET_SIDES[int(sd)])] for e, sd in zip(elems, sides)])


def contact_normal(res, faces, X, step):
    """The pressure-weighted mean outward normal of the slave faces in the deformed
    configuration: sum over faces of (mean nodal pressure) x (area vector), normalised."""
    x = X + np.vstack([res.nodal("displ_%s" % c, step) for c in "xyz"])
    p = res.nodal("contact_pressure", step)
    a = 0.5 * np.cross((x[:, faces[:, 1]] - x[:, faces[:, 0]]).T,
                       (x[:, faces[:, 2]] - x[:, faces[:, 0]]).T)
    n = (p[faces].mean(axis=1)[:, None] * a).sum(axis=0)
    return n / np.linalg.norm(n)


def sliding_ratio(stem, col, mu, tol, failures):
    """While every active slave node slips: the base reaction R (the whole contact force, by
    equilibrium) against the friction cone about the contact's mean deformed normal n:
    |R - (R.n) n| / |R.n| = mu within tol. In dynamics only where the kinetic energy is below
    1e-6 of the strain energy (quasi-static: no inertia in R)."""
    res = Results("np1/%s.e" % stem)
    slave = cc.node_set(res, "slave")
    faces = slave_faces(res)
    X = res.coordinates()
    t = np.asarray(res.times())
    csv_t = col["time"]
    checked, worst = 0, 0.0
    for k, tt in enumerate(t):
        j = int(np.argmin(np.abs(csv_t - tt)))
        if "kinetic_energy" in col and col["kinetic_energy"][j] > 1e-6 * col["strain_energy"][j]:
            continue  # in dynamics: quasi-static steps only (the base reaction then holds no M a)
        status = res.nodal("contact_status", k)[slave]
        active = status > 0
        if not active.any() or np.any(status[active] != 2):
            continue
        R = col["R"][:, j]
        n = contact_normal(res, faces, X, k)
        N = abs(R @ n)
        T = np.linalg.norm(R - (R @ n) * n)
        ratio = T / N
        checked += 1
        worst = max(worst, abs(ratio / mu - 1))
        print("%s: t = %.3f, %d slipping nodes, n = (%+.3f, %+.3f, %+.3f): N = %.4g, T = %.4g, "
              "T/N = %.4f" % (stem, tt, int(active.sum()), n[0], n[1], n[2], N, T, ratio))
    if not checked:
        failures.append("%s: no step with every active node slipping" % stem)
    elif worst > tol:
        failures.append("%s: T/N off mu = %g by %.2f %% (> %g %%)"
                        % (stem, mu, 100 * worst, 100 * tol))
    else:
        print("%s: T/N = mu within %.2f %% over %d sliding steps" % (stem, 100 * worst, checked))


def vertical(stem, col, small, failures, setup=VERTICAL):
    """The vertical motion: no reaction before the rigid contact time, then R.n rising step by
    step. Printed: R.n against the tubes' reference bounds (tube_force; README.md) and the
    solid cylinders' Hertz estimate in the small-load part (0 < i <= small). Returns the
    steps in contact as (i, R.n, F_stiff, F_soft)."""
    t, R = col["time"], col["R"]
    i, n = interference(setup, t)
    N = np.abs(R[0] * n[0] + R[1] * n[1])
    peak = float(N.max())
    if peak <= 0:
        failures.append("%s: no reaction at the base" % stem)
        return []
    before = i <= 0
    if np.any(before) and N[before].max() > 1e-6 * peak:
        failures.append("%s: base reaction %.3g (%.2e of the last) before contact"
                        % (stem, N[before].max(), N[before].max() / peak))
    first = int(np.argmax(~before))
    rise = np.diff(N[first:])
    if rise.size and rise.min() <= 0:
        failures.append("%s: R.n does not rise at every step after contact" % stem)
    comp = tube_references(centre(setup, t[first:first + 1])[:, 0])
    rows = []
    for k in range(first, len(t)):
        if i[k] > small:
            continue
        stiff, soft = tube_force(i[k], comp["stiff"]), tube_force(i[k], comp["soft"])
        solid, _ = hertz_force(i[k])
        rows.append((i[k], N[k], stiff, soft))
        print("%s: t = %.3f, i = %.3e: R.n = %.4g; tubes' reference %.4g (stiff) .. %.4g (soft): "
              "R.n = %.3f / %.3f of them; solid cylinders' Hertz estimate %.4g (R.n = %.3f of it)"
              % (stem, t[k], i[k], N[k], stiff, soft, N[k] / stiff, N[k] / soft, solid,
                 N[k] / solid))
    print("%s: no reaction before contact (t < %.4f), R.n rising over %d steps in contact"
          % (stem, t[first], len(t) - first))
    return rows


def tubes(stems, sizes, failures):
    """The refinement study (README.md): the vertical motion on gmsh meshes of Kratos' tubes of
    element sizes `sizes`, coarse to fine. At every step with TUBES_I[0] <= i <= TUBES_I[1]:
      - convergence: R.n falls with each refinement (linear tetrahedra are too stiff in bending:
        the study approaches the reference from above);
      - target: the first-order extrapolation of the two finest levels,
        F = F_h2 - (F_h1 - F_h2) h2 / (h1 - h2), lies between the tubes' bounds, within its
        own error estimate e = |F - F_h2| (Richardson: the extrapolation is uncertain by about
        the correction it makes): F_soft - e <= F <= F_stiff + e.
    Printed: R.n / F_stiff per level and extrapolated."""
    levels = []
    for stem in stems:
        rows = vertical(stem, summary(stem), TUBES_I[1], failures, setup=TUBES)
        levels.append([r for r in rows if r[0] >= TUBES_I[0]])
    for stem, h, rows in zip(stems, sizes, levels):
        print("%s (h = %g): R.n / F_stiff = %s"
              % (stem, h, ", ".join("%.3f" % (r[1] / r[2]) for r in rows)))
    if len(levels) < 2 or not all(len(r) == len(levels[-1]) and r for r in levels):
        failures.append("tubes: need two or more levels with the same steps in %g <= i <= %g"
                        % TUBES_I)
        return
    h1, h2 = sizes[-2], sizes[-1]
    for k in range(len(levels[-1])):
        forces = [rows[k][1] for rows in levels]
        i, _, stiff, soft = levels[-1][k]
        if np.any(np.diff(forces) >= 0):
            failures.append("tubes: i = %.3e: R.n does not fall with refinement (%s)"
                            % (i, ", ".join("%.4g" % f for f in forces)))
        f = forces[-1] - (forces[-2] - forces[-1]) * h2 / (h1 - h2)
        print("tubes: i = %.3e: extrapolated R.n = %.4g = %.3f of F_stiff, %.3f of F_soft"
              % (i, f, f / stiff, f / soft))
        e = abs(f - forces[-1])
        if not soft - e <= f <= stiff + e:
            failures.append("tubes: i = %.3e: extrapolated R.n = %.4g outside the tubes' "
                            "reference %.4g .. %.4g (+-%.3g, the extrapolation's error "
                            "estimate)" % (i, f, soft, stiff, e))


def plot(curves, vert):
    """cylinders_reactions.png: the base reaction against t (horizontal II) and R.n against the
    rigid interference (vertical, with the tubes' reference bounds and the solid cylinders'
    Hertz estimate)."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.5))
    for stem, col in curves:
        R = col["R"]
        ax.plot(col["time"], np.linalg.norm(R, axis=0), "-", label="%s |R|" % stem)
        ax.plot(col["time"], R[0], "--", lw=0.8, label="%s R_x" % stem)
        ax.plot(col["time"], R[1], ":", lw=0.8, label="%s R_y" % stem)
    ax.set_xlabel("t (x = -0.2 + 0.2 t)")
    ax.set_ylabel("base reaction")
    ax.set_title("horizontal II")
    ax.legend(fontsize=7)
    if vert is not None:
        stem, col = vert
        i, n = interference(VERTICAL, col["time"])
        N = np.abs(col["R"][0] * n[0] + col["R"][1] * n[1])
        on = i > 0
        bx.plot(i[on], N[on], "o-", ms=3, label="%s R.n" % stem)
        ii = np.linspace(i[on].min() if on.any() else 1e-4, i.max(), 50)
        comp = tube_references(np.array(VERTICAL["c0"]))
        bx.plot(ii, [tube_force(v, comp["stiff"]) for v in ii], "k-", label="tubes, stiff bound")
        bx.plot(ii, [tube_force(v, comp["soft"]) for v in ii], "k--", label="tubes, soft bound")
        bx.plot(ii, [hertz_force(v)[0] for v in ii], "k:", label="solid cylinders, Hertz")
        bx.set_xlabel("rigid interference i")
        bx.set_ylabel("normal reaction")
        bx.set_title("vertical")
        bx.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig("cylinders_reactions.png", dpi=110)
    plt.close(fig)
    print("wrote cylinders_reactions.png")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--horizontal")
    ap.add_argument("--frictional")
    ap.add_argument("--frictional-dynamic")
    ap.add_argument("--vertical")
    ap.add_argument("--tubes", nargs="*", default=[], help="STEM:SIZE, coarse to fine")
    ap.add_argument("--ranks", nargs="*", default=[])
    ap.add_argument("--mu", type=float, default=1.0)
    ap.add_argument("--ratio-tol", type=float, default=0.02)
    ap.add_argument("--small", type=float, default=2e-3)
    a = ap.parse_args()
    failures, curves, vert = [], [], None
    if a.horizontal:
        col = summary(a.horizontal)
        rise_and_vanish(a.horizontal, col, failures, True)
        curves.append((a.horizontal, col))
    if a.frictional:
        col = summary(a.frictional)
        rise_and_vanish(a.frictional, col, failures, False, vanish=False)
        sliding_ratio(a.frictional, col, a.mu, a.ratio_tol, failures)
        curves.append((a.frictional, col))
    if a.frictional_dynamic:
        col = summary(a.frictional_dynamic)
        rise_and_vanish(a.frictional_dynamic, col, failures, False, snap=True)
        snap_energy(a.frictional_dynamic, col)
        sliding_ratio(a.frictional_dynamic, col, a.mu, a.ratio_tol, failures)
        curves.append((a.frictional_dynamic, col))
    if a.vertical:
        vert = (a.vertical, summary(a.vertical))
        vertical(a.vertical, vert[1], a.small, failures)
    if a.tubes:
        tubes([x.split(":")[0] for x in a.tubes], [float(x.split(":")[1]) for x in a.tubes],
              failures)
    for stem in a.ranks:
        diff, msg = cc.compare_ranks("np1/%s.e" % stem, "np2/%s.e" % stem,
                                     ["displ_x", "displ_y", "displ_z", "contact_pressure"])
        print("%s: 1 vs 2 ranks %.1e" % (stem, diff))
        if msg:
            failures.append(msg)
    plot(curves, vert)
    for f in failures:
        print("FAIL:", f)
    if not failures:
        print("contacting_cylinders: all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
