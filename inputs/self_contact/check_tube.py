"""Squeezed flat tube (flat_tube.yaml; docs/verification.md, benchmark 16, 2D CI version):
the cavity of a Neo-Hookean tube pressed flat until its wall folds onto itself.

Benchmark 16's targets (../../docs/verification.md): it completes and self-contact is found,
and no face penetrates another by more than 1 % of the wall thickness. Checked here, on 1 and
2 ranks (np1/, np2/):
- completes: every step converged, to t = 1 (the top moved down 0.33 > the cavity's gap 0.3);
- self-contact found: no active node at the first step (the cavity is open), active nodes at
  the last one;
- no penetration: for every node of the cavity wall, its signed distance to every wall face
  of the deformed mesh that faces it (element normals opposed, the node not on the face nor
  on a neighbour) is > -1 % of the wall thickness where the node projects onto the face and
  lies within a wall thickness behind it;
- the reactions balance: the self-contact forces are internal, so the top's and the bottom's
  reactions cancel, to 1e-8 of the top's;
- the reaction grows monotonically once the walls touch (a closed cavity only stiffens);
- 1 and 2 ranks agree (displacements to 1e-8).
flat_tube_3d.yaml is the tube itself, the section swept along z and held in z at both ends:
the same checks on its first layer of nodes, which must move as every other layer, and its
reaction per unit length within 1e-3 of the 2D run's (comment in check()).
"""
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402
from grout_results import Results  # noqa: E402

T = 0.1  # wall thickness (flat_tube.py default)
D_END = 0.33  # the top's final displacement


def wall_faces(r, inner):
    """(a, b) node pairs of the cavity wall's faces, ordered so that (dy, -dx) points out of
    the body (the elements are counter-clockwise)."""
    conn = r.connectivity(1)
    inner = set(int(n) for n in inner)
    count = {}
    for row in conn:
        for k in range(4):
            a, b = int(row[k]), int(row[(k + 1) % 4])
            key = frozenset((a, b))
            count[key] = count.get(key, []) + [(a, b)]
    return [v[0] for k, v in count.items() if len(v) == 1 and k <= inner]


def penetration(X, u, faces):
    """Largest penetration (>= 0) of a wall node behind a facing wall face: X (2, n) reference
    coordinates, u (2, n) displacements."""
    x = X + u
    normal, node_faces = {}, {}
    for a, b in faces:
        t = x[:, b] - x[:, a]
        normal[a, b] = np.array([t[1], -t[0]]) / np.hypot(*t)
        for n in (a, b):
            node_faces.setdefault(n, []).append((a, b))
    near = {n: {m for f in fs for m in f} for n, fs in node_faces.items()}
    worst = 0.0
    for p, fs in node_faces.items():
        n_p = sum(normal[f] for f in fs)
        n_p /= np.linalg.norm(n_p)
        for a, b in faces:
            if a in near[p] or b in near[p] or np.dot(normal[a, b], n_p) >= 0.0:
                continue
            t = x[:, b] - x[:, a]
            s = np.dot(x[:, p] - x[:, a], t) / np.dot(t, t)
            d = np.dot(x[:, p] - x[:, a], normal[a, b])
            if 0.0 <= s <= 1.0 and -T < d < 0.0:
                worst = max(worst, -d)
    return worst


def check(stem, np_, steps, section=None):
    """The checks above on np<np_>/<stem>; section: the 2D run's stem when <stem> is its
    section swept along z (its first layer of nodes is the 2D mesh's nodes, in order)."""
    failures = []
    path = "np%d/%s" % (np_, stem)
    rows = list(csv.DictReader(open(path + ".csv")))
    if len(rows) != steps or abs(float(rows[-1]["time"]) - 1.0) > 1e-12:
        return ["%s: %d steps to t = %s (expected %d to 1)" % (path, len(rows), rows[-1]["time"] if rows else "-", steps)]
    active = [int(float(row["active_nodes"])) for row in rows]
    top = np.array([float(row["reaction_top_nodes_y"]) for row in rows])
    bottom = np.array([float(row["reaction_bottom_nodes_y"]) for row in rows])
    top_x = np.array([float(row["reaction_top_nodes_x"]) for row in rows])
    bottom_x = np.array([float(row["reaction_bottom_nodes_x"]) for row in rows])
    if active[0] != 0 or active[-1] == 0:
        failures.append("%s: active nodes %d at the first step, %d at the last (expected 0, > 0)"
                        % (path, active[0], active[-1]))
    balance = np.max(np.abs(top + bottom) + np.abs(top_x + bottom_x)) / np.max(np.abs(top))
    if not balance <= 1e-8:
        failures.append("%s: reactions top + bottom = %.2e of the top's (> 1e-8)" % (path, balance))
    first = next((k for k, a in enumerate(active) if a > 0), len(active))
    after = -top[first:]  # the top is pushed down: its reaction on the body is upward (< 0)
    grows = bool(np.all(np.diff(after) > 0.0)) if after.size > 1 else False
    if not grows:
        failures.append("%s: the reaction does not grow after contact (step %d on): %s"
                        % (path, first + 1, after))
    r = Results(path + ".e")
    u = np.array([r.nodal("displ_" + c) for c in "xyz"[:r.coordinates().shape[0]]])
    plane = r if section is None else Results("np%d/%s.e" % (np_, section))
    n = plane.coordinates().shape[1]
    if section is not None:
        # Held in z at both ends, the swept tube deforms as its plane-strain section: every
        # layer of nodes moves as the first, u_z = 0; per unit length, the reaction is the
        # 2D run's (up to the 3D mortar's projection onto the slave face's plane instead of
        # along the nodal normals: a discretisation difference, O(h^2) where the walls meet).
        layers = u.shape[1] // n
        spread = max(np.abs(u[:2, k * n:(k + 1) * n] - u[:2, :n]).max() for k in range(layers))
        spread = max(spread, np.abs(u[2]).max()) / np.abs(u).max()
        rows2d = list(csv.DictReader(open("np%d/%s.csv" % (np_, section))))
        length = r.coordinates()[2].max()
        ratio = -top[-1] / length / -float(rows2d[-1]["reaction_top_nodes_y"])
        print("%-18s layers move alike to %.1e; reaction per length / 2D = %.8f" % (path, spread, ratio))
        if not spread <= 1e-8:
            failures.append("%s: the layers differ by %.2e (> 1e-8)" % (path, spread))
        if not abs(ratio - 1.0) <= 1e-3:
            failures.append("%s: reaction per length / 2D = %.6f (not within 1e-3)" % (path, ratio))
    faces = wall_faces(plane, cc.node_set(plane, "inner_nodes"))
    depth = penetration(plane.coordinates()[:2], u[:2, :n], faces)
    if not depth <= 0.01 * T:
        failures.append("%s: penetration %.3e > 1 %% of the wall thickness" % (path, depth))
    cp = r.nodal("contact_pressure")
    print("%-18s contact from step %d (d = %.2f), active %d at the end, reaction %.4g -> %.4g, "
          "balance %.1e, penetration %.2e T, max contact_pressure %.4g"
          % (path, first + 1, D_END * (first + 1) / steps, active[-1], -top[first - 1] if first else 0.0,
             -top[-1], balance, depth / T, cp.max()))
    return failures


if __name__ == "__main__":
    failures = []
    for np_ in (1, 2):
        failures += check("flat_tube", np_, 33)
        failures += check("flat_tube_3d", np_, 22, section="flat_tube")
    # (displ_z of the swept tube is round-off: checked above against the displacement scale.)
    for stem, fields in (("flat_tube", ["displ_x", "displ_y"]),
                         ("flat_tube_3d", ["displ_x", "displ_y"])):
        diff, msg = cc.compare_ranks("np1/%s.e" % stem, "np2/%s.e" % stem, fields, tol=1e-8)
        print("%-18s 1 vs 2 ranks: %.2e" % (stem, diff))
        failures += [msg] if msg else []
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)
