"""L-shape with a tied circular region, Neo-Hookean (docs/verification.md #21; thesis App. A.3.5).

Checks, on 1 and 2 ranks (the two agree to 1e-10):
1. The tying constraint at every slave node and every step, on an independent transcription of
   the mortar integrals (mortar_2d_ref.py): D_jj u_disc,j = sum_l M_jl u_outer,l to 1e-10
   relative (|D u_s - M u_m| / (D_jj max|u|)): the disc's interface nodes move with the
   mortar projection of the outer body's displacement (dual mortar: the slave displacement IS
   that projection). The arc nodes do not match (so the check is not trivial), and the
   pointwise jump between each slave node and the master polygon (discretisation size, not
   round-off: the dual mortar tie is weak) is below 1e-2 max|u| (measured 2.5e-3).
2. The global response against the same L-shape meshed conformingly without the interface
   (size h/2 = 0.1): the top reaction R_y(t) of the tied meshes converges to it. At every
   common time, the tied mesh of size h/2 is within 1 % of the conforming one and at least
   twice as close to it as the tied mesh of size h = 0.2:
   |R_tied,h/2 - R_conf,h/2| <= min(0.01 |R|, 0.5 |R_tied,h - R_conf,h/2|).
   (A wrong tie - a loose or a rigid interface - would not converge to the conforming answer.)
Writes lshape_reaction.png (R_y against t, tied and conforming).
"""
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mortar_2d_ref as mr  # noqa: E402
from grout_results import Results, relative_difference  # noqa: E402

TOL_TIE = 1e-10


def tie_check(path):
    """Largest relative tie residual over all steps, and the largest pointwise jump."""
    r = Results(path)
    X = r.coordinates()[:2].T
    sf, mf = mr.side_set_faces(r, "disc_arc"), mr.side_set_faces(r, "outer_arc")
    D, M = mr.mortar_matrices(sf, mf, X)
    rows = {}
    for (j, l), v in M.items():
        rows.setdefault(j, []).append((l, v))
    slave = sorted(D)
    master_nodes = np.unique(mf)
    # non-matching: distance of each slave node to the nearest master node
    gaps = [np.min(np.hypot(*(X[master_nodes] - X[j]).T)) for j in slave]
    n_unmatched = sum(g > 1e-6 for g in gaps)
    worst, jump = 0.0, 0.0
    for step in range(len(r.times())):
        u = np.array([r.nodal("displ_x", step), r.nodal("displ_y", step)]).T
        scale = np.abs(u).max()
        if scale == 0.0:
            continue
        for j in slave:
            res = D[j] * u[j] - sum(v * u[l] for l, v in rows[j])
            worst = max(worst, np.abs(res).max() / (D[j] * scale))
        # pointwise: the master displacement interpolated at the slave node's closest point
        for j in slave:
            best = None
            for a, b in mf:
                t = np.clip(np.dot(X[j] - X[a], X[b] - X[a]) / np.dot(X[b] - X[a], X[b] - X[a]), 0, 1)
                d = np.hypot(*(X[a] + t * (X[b] - X[a]) - X[j]))
                if best is None or d < best[0]:
                    best = (d, (1 - t) * u[a] + t * u[b])
            jump = max(jump, np.hypot(*(u[j] - best[1])) / scale)
    return worst, jump, len(slave), n_unmatched, len(r.times())


def reaction(stem, np_=1):
    rows = list(csv.DictReader(open("np%d/%s.csv" % (np_, stem))))
    return {round(float(r["time"]), 9): float(r["reaction_top_nodes_y"]) for r in rows}


def main():
    failures = []
    for np_ in (1, 2):
        worst, jump, n, unmatched, steps = tie_check("np%d/lshape_tied.e" % np_)
        print("np%d: %d steps, %d slave nodes (%d not on a master node): max |D u_s - M u_m| / "
              "(D max|u|) = %.2e; largest pointwise jump to the master polygon %.2e max|u|"
              % (np_, steps, n, unmatched, worst, jump))
        if not worst < TOL_TIE:
            failures.append("np%d: tie residual %.2e above %g" % (np_, worst, TOL_TIE))
        if not jump < 1e-2:
            failures.append("np%d: pointwise jump %.2e max|u| across the interface" % (np_, jump))
        if unmatched < n // 2:
            failures.append("np%d: the interface meshes match (%d of %d slave nodes off the "
                            "master nodes): the check would be trivial" % (np_, unmatched, n))
    r1, r2 = Results("np1/lshape_tied.e"), Results("np2/lshape_tied.e")
    diff = max(relative_difference(r1.nodal("displ_" + c), r2.nodal("displ_" + c)) for c in "xy")
    print("1 vs 2 ranks: %.2e" % diff)
    if not diff < 1e-10:
        failures.append("1 and 2 ranks differ by %.2e" % diff)

    tied, tied_fine, conf = (reaction("lshape_tied"), reaction("lshape_tied_fine"),
                             reaction("lshape_conforming_fine"))
    common = sorted(set(tied) & set(tied_fine) & set(conf))
    if not common or common[-1] != 2.0:
        failures.append("no common output times ending at t = 2: %s" % common)
    for t in common:
        coarse, fine = abs(tied[t] - conf[t]) / abs(conf[t]), abs(tied_fine[t] - conf[t]) / abs(conf[t])
        ok = fine <= min(0.01, 0.5 * coarse)
        print("t = %.3f: R_y conforming (h/2) %.6g; tied h %.6g (%+.2f %%), tied h/2 %.6g (%+.2f %%) %s"
              % (t, conf[t], tied[t], 100 * (tied[t] / conf[t] - 1), tied_fine[t],
                 100 * (tied_fine[t] / conf[t] - 1), "" if ok else "FAIL"))
        if not ok:
            failures.append("t = %g: tied R_y does not converge to the conforming one" % t)
    try:
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 4))
        for d, style, label in ((tied, "o-", "tied, h = 0.2"), (tied_fine, "s--", "tied, h = 0.1"),
                                (conf, "^:", "conforming (no interface), h = 0.1")):
            ts = sorted(d)
            ax.plot(ts, [d[t] for t in ts], style, label=label)
        ax.set_xlabel("t = top displacement u_y")
        ax.set_ylabel("top reaction R_y (N per m)")
        ax.set_title("L-shape with a tied disc, Neo-Hookean")
        ax.legend()
        fig.tight_layout()
        fig.savefig("lshape_reaction.png", dpi=100)
    except ImportError:
        pass
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        return 1
    print("lshape_tied: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
