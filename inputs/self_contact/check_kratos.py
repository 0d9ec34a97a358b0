"""Benchmark 16 on Kratos' meshes (docs/verification.md #16; README.md): the crossed
hyperelastic tubes (tubes*.yaml) and the S profile (s_profile*.yaml).

Benchmark 16's targets: the run completes and self-contact is found; no face penetrates
another by more than 1 % of the wall thickness (the tubes' wall: 0.012 - 0.0112 = 0.0008).
Checked, on the results in np<ranks>/:
- completes: the last converged step is at the input's end time;
- contact found: at the end, nodes of each self-contact surface are active (contact_status
  > 0 at nodes of its side sets), and for the tubes nodes of the tube-tube slave surface too;
- no penetration (--tubes), at every written step: for every node of a contact surface, its
  signed distance to every face of the deformed mesh that faces it (the face's normal opposed
  to the node's, the node not on the face nor on a face next to it; quadrilaterals split
  into two triangles) is > -1 % of the wall thickness where the node projects inside the face
  and lies within a wall thickness behind it. Surfaces: the upper tube's inner surface against
  itself, its outer surface against the lower tube's and the reverse;
- the reaction on the moved faces grows at every step once the surfaces touch (--s-profile:
  the folds close and only stiffen the profile; the tubes' reaction is printed);
- --ranks A B: the runs in npA/ and npB/ agree (displacements, 1e-8 of their largest).
--short (the CI run of the tubes, the start of the path): the cavity is still open, so its
self-contact is not asked for (its surface is still checked for penetration).

Usage: check_kratos.py --tubes STEM --end T [--short] [--mesh MESH.exo] [--ranks 1 2]
                       [--plot PNG]
       check_kratos.py --s-profile STEM --end T [--mesh MESH.exo] [--ranks 1 2]
"""
import argparse
import csv
import os
import sys

import netCDF4
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402
from grout_results import Results  # noqa: E402

WALL = 0.012 - 0.0112  # the tubes' wall thickness
# Exodus side numbering (tools/exodus_mesh.py): local nodes of each side, right-handed outward.
SIDES = {8: [(0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (0, 4, 7, 3), (0, 3, 2, 1), (4, 5, 6, 7)],
         4: [(0, 1, 3), (1, 2, 3), (0, 3, 2), (0, 2, 1)]}


def side_set_faces(mesh_path, names):
    """{name: (faces, k) int array of 0-based nodes} of the mesh's side sets `names`, outward."""
    ds = netCDF4.Dataset(mesh_path)
    ds.set_auto_mask(False)
    conn = []
    for b in range(len(ds.dimensions["num_el_blk"])):
        conn += [row for row in np.array(ds.variables["connect%d" % (b + 1)][:]) - 1]
    set_names = [str(s).strip() for s in netCDF4.chartostring(ds.variables["ss_names"][:])]
    out = {}
    for name in names:
        k = set_names.index(name) + 1
        elems = np.array(ds.variables["elem_ss%d" % k][:]) - 1
        sides = np.array(ds.variables["side_ss%d" % k][:]) - 1
        out[name] = np.array([conn[e][list(SIDES[len(conn[e])][s])] for e, s in zip(elems, sides)])
    return out


def triangles(faces):
    """Quadrilaterals split into two triangles (0 1 2, 0 2 3); triangles kept."""
    if faces.shape[1] == 3:
        return faces, np.arange(len(faces))
    return (np.concatenate([faces[:, [0, 1, 2]], faces[:, [0, 2, 3]]]),
            np.concatenate([np.arange(len(faces))] * 2))


def penetration(x, nodes_faces, target_faces, depth):
    """Largest penetration (>= 0) of a node of `nodes_faces` behind a facing face of
    `target_faces` (x: (n, 3) deformed coordinates); nodes further than `depth` behind are
    not counted (the other side of a wall)."""
    return deepest_node(x, nodes_faces, target_faces, depth)[0]


def deepest_node(x, nodes_faces, target_faces, depth):
    """penetration()'s value, the node it is at and the face of `target_faces` it lies
    behind (None, None where nothing penetrates)."""
    tri, owner = triangles(target_faces)
    a, b, c = x[tri[:, 0]], x[tri[:, 1]], x[tri[:, 2]]
    n_tri = np.cross(b - a, c - a)
    area2 = np.linalg.norm(n_tri, axis=1)
    n_tri /= area2[:, None]
    # Node normals: the mean of their faces' normals (each face's from its first triangle).
    src_tri, src_owner = triangles(nodes_faces)
    fn = np.cross(x[src_tri[:, 1]] - x[src_tri[:, 0]], x[src_tri[:, 2]] - x[src_tri[:, 0]])
    node_normal, near = {}, {}
    face_normal = np.zeros((len(nodes_faces), 3))
    np.add.at(face_normal, src_owner, fn)
    for f, row in enumerate(nodes_faces):
        for p in row:
            node_normal[p] = node_normal.get(p, 0.0) + face_normal[f]
            near.setdefault(p, set()).update(int(q) for q in row)
    worst, at, face = 0.0, None, None
    for p, n_p in node_normal.items():
        n_p = n_p / np.linalg.norm(n_p)
        dist = np.einsum("ij,ij->i", x[p] - a, n_tri)
        cand = (dist < 0.0) & (dist > -depth) & (n_tri @ n_p < 0.0)
        if not cand.any():
            continue
        idx = np.nonzero(cand)[0]
        skip = np.array([any(int(q) in near[p] for q in target_faces[owner[i]]) for i in idx])
        idx = idx[~skip]
        if idx.size == 0:
            continue
        # Barycentric coordinates of the projection onto each triangle's plane.
        q = x[p] - dist[idx, None] * n_tri[idx]
        v0, v1, v2 = b[idx] - a[idx], c[idx] - a[idx], q - a[idx]
        d00, d01, d11 = (np.einsum("ij,ij->i", v0, v0), np.einsum("ij,ij->i", v0, v1),
                         np.einsum("ij,ij->i", v1, v1))
        d20, d21 = np.einsum("ij,ij->i", v2, v0), np.einsum("ij,ij->i", v2, v1)
        den = d00 * d11 - d01 * d01
        s, t = (d11 * d20 - d01 * d21) / den, (d00 * d21 - d01 * d20) / den
        inside = (s >= 0.0) & (t >= 0.0) & (s + t <= 1.0)
        if inside.any() and float(-dist[idx][inside].min()) > worst:
            j = int(np.argmin(np.where(inside, dist[idx], np.inf)))
            worst, at, face = float(-dist[idx][j]), int(p), int(owner[idx[j]])
    return worst, at, face


def rows_of(path):
    return list(csv.DictReader(open(path)))


def active_on(r, faces, step=-1):
    nodes = np.unique(faces)
    return int(np.sum(r.nodal("contact_status", step)[nodes] > 0))


def finished(path, end, failures):
    """The rows of PATH.csv if the run reached t = end, else None (and a failure)."""
    rows = rows_of(path + ".csv")
    if not rows or abs(float(rows[-1]["time"]) - end) > 1e-9:
        failures.append("%s: ends at t = %s (expected %g)"
                        % (path, rows[-1]["time"] if rows else "-", end))
        return None
    return rows


def check_tubes(stem, mesh, ranks, end, short=False, plot=None):
    failures = []
    sets = side_set_faces(mesh, ["inner_lower", "inner_upper", "upper_outer", "lower_outer"])
    inner = np.concatenate([sets["inner_lower"], sets["inner_upper"]])
    for np_ in ranks:
        path = "np%d/%s" % (np_, stem)
        rows = finished(path, end, failures)
        if rows is None:
            continue
        r = Results(path + ".e")
        X = r.coordinates().T
        worst_self, worst_pair, at = 0.0, [0.0, 0.0], None
        for k in range(r.times().size):
            u = np.array([r.nodal("displ_" + c, k) for c in "xyz"]).T
            x = X + u
            w_self = penetration(x, inner, inner, WALL)
            # The slave's (upper outer) nodes into the master's faces, and the reverse.
            w_pair = [penetration(x, sets["upper_outer"], sets["lower_outer"], WALL),
                      penetration(x, sets["lower_outer"], sets["upper_outer"], WALL)]
            if max(w_self, *w_pair) > max(worst_self, *worst_pair):
                at = float(r.times()[k])
            worst_self = max(worst_self, w_self)
            worst_pair = [max(a, b) for a, b in zip(worst_pair, w_pair)]
        self_active = active_on(r, inner)
        pair_active = active_on(r, sets["upper_outer"])
        first_self = next((k for k in range(r.times().size) if active_on(r, inner, k) > 0), None)
        reaction = [-float(row["reaction_upper_ends_y"]) for row in rows]
        iterations = sum(int(float(row["newton_iterations"])) for row in rows)
        print("%s: %d steps to t = %g (%d Newton iterations); self-contact from t = %s, active at "
              "the end: %d inner (self), %d outer (tube on tube); penetration of the wall: %.2e "
              "(self), %.2e (upper tube's nodes into the lower's faces), %.2e (lower's into "
              "upper's), largest at t = %s; reaction on the upper ends %.4g at the end"
              % (path, len(rows), end, iterations,
                 "%g" % r.times()[first_self] if first_self is not None else "-", self_active,
                 pair_active, worst_self / WALL, worst_pair[0] / WALL, worst_pair[1] / WALL, at,
                 reaction[-1]))
        if self_active == 0 and not short:
            failures.append("%s: no active node on the inner surface at the end (self-contact "
                            "not found)" % path)
        if pair_active == 0:
            failures.append("%s: no active node on the upper tube's outer surface" % path)
        for what, w in (("self", worst_self), ("upper tube's nodes into the lower's faces",
                                                 worst_pair[0]),
                        ("lower tube's nodes into the upper's faces", worst_pair[1])):
            if not w <= 0.01 * WALL:
                failures.append("%s: penetration (%s) %.2e = %.2f %% of the wall (> 1 %%)"
                                % (path, what, w, 100 * w / WALL))
        if plot and np_ == ranks[0]:
            plot_tubes(r, sets, inner, plot)
    failures += compare(stem, ranks)
    return failures


def check_s_profile(stem, mesh, ranks, end):
    failures = []
    sets = side_set_faces(mesh, ["fold_lower", "fold_upper"])
    for np_ in ranks:
        path = "np%d/%s" % (np_, stem)
        rows = finished(path, end, failures)
        if rows is None:
            continue
        r = Results(path + ".e")
        X = r.coordinates().T
        x = X + np.array([r.nodal("displ_" + c) for c in "xyz"]).T
        active = {k: active_on(r, f) for k, f in sets.items()}
        depth = {k: penetration(x, f, f, 0.005) for k, f in sets.items()}
        reaction = np.array([-float(row["reaction_top_y"]) for row in rows])
        times = np.array([float(row["time"]) for row in rows])
        total = np.array([int(float(row["active_nodes"])) for row in rows])
        first = next((k for k, a in enumerate(total) if a > 0), len(total))
        print("%s: %d steps to t = %g; contact from t = %s; active at the end: %s; reaction on "
              "the top %s; penetration %s" % (
                  path, len(rows), end, "%g" % times[first] if first < len(times) else "-",
                  active, ", ".join("%.4g" % v for v in reaction[max(first - 1, 0):]),
                  ", ".join("%s %.2e" % kv for kv in depth.items())))
        for k, a in active.items():
            if a == 0:
                failures.append("%s: no active node on %s at the end" % (path, k))
        after = reaction[max(first - 1, 0):]
        if first >= len(total) or after.size < 3 or not np.all(np.diff(after) > 0.0):
            failures.append("%s: the reaction does not grow at every step after contact: %s"
                            % (path, after))
    failures += compare(stem, ranks)
    return failures


def compare(stem, ranks):
    if len(ranks) < 2:
        return []
    diff, msg = cc.compare_ranks("np%d/%s.e" % (ranks[0], stem), "np%d/%s.e" % (ranks[1], stem),
                                 ["displ_x", "displ_y", "displ_z"], tol=1e-8)
    print("%s: %d vs %d ranks: %.2e" % (stem, ranks[0], ranks[1], diff))
    return [msg] if msg else []


def plot_tubes(r, sets, inner, path):
    """The upper tube's inner surface at the end, cut at x = 0 (the crossing): its nodes in
    the y-z plane, coloured by contact_status, with the reference circle."""
    import matplotlib.pyplot as plt
    X = r.coordinates().T
    x = X + np.array([r.nodal("displ_" + c) for c in "xyz"]).T
    status = r.nodal("contact_status")
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.5))
    nodes = np.unique(inner)
    outer = np.unique(sets["upper_outer"])
    lower = np.unique(sets["lower_outer"])
    sections = (("section x = 0 (the crossing)", 0.0), ("section x = 0.025", 0.025))
    shown = []  # (z, y) of the upper tube's plotted nodes: both sections' axes fit them all
    for ax, (title, cut) in zip(axes, sections):
        for which, ns, style in (("inner (self-contact)", nodes, "o"),
                                 ("upper outer", outer, "."), ("lower outer", lower, ".")):
            sel = ns[np.abs(X[ns, 0] - cut) < 1e-6] if which != "lower outer" else \
                ns[np.abs(x[ns, 0] - cut) < 0.0008]
            ax.scatter(x[sel, 2], x[sel, 1], s=10, marker=style,
                       c=np.where(status[sel] > 0, "tab:red", "tab:blue") if which != "lower outer"
                       else "0.6", label=which)
            if which != "lower outer":
                shown.append((x[sel, 2], x[sel, 1]))
        ax.set_title(title + ", t = %g" % r.times()[-1])
        ax.set_xlabel("z")
        ax.set_ylabel("y")
    # The same limits on both sections: the upper tube's nodes with a margin of 2 mm (the lower
    # tube's crown below them stays in view; its far side is left out).
    z = np.concatenate([a for a, _ in shown])
    y = np.concatenate([b for _, b in shown])
    for ax in axes:
        ax.set_xlim(z.min() - 0.002, z.max() + 0.002)
        ax.set_ylim(y.min() - 0.004, y.max() + 0.002)
        ax.set_aspect("equal")
    axes[0].legend(fontsize=7, loc="upper left")
    fig.suptitle("Crossed tubes on Kratos' coarse mesh: deformed nodes (red: active contact)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print("wrote", path)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    g = p.add_mutually_exclusive_group(required=True)
    g.add_argument("--tubes")
    g.add_argument("--s-profile")
    p.add_argument("--mesh")
    p.add_argument("--end", type=float, required=True)
    p.add_argument("--ranks", type=int, nargs="+", default=[1])
    p.add_argument("--short", action="store_true",
                   help="the start of the path: the cavity is still open (no self-contact asked)")
    p.add_argument("--plot")
    a = p.parse_args()
    if a.tubes:
        failures = check_tubes(a.tubes, a.mesh or "tubes_coarse.exo", a.ranks, a.end, a.short,
                               a.plot)
    else:
        failures = check_s_profile(a.s_profile, a.mesh or "s_profile.exo", a.ranks, a.end)
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
