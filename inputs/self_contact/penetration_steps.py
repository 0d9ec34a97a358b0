"""Penetration of the crossed tubes step by step (README.md, "Penetration"): for every
written step of a tubes*.yaml run, the active nodes and the three penetrations of
check_kratos.py (the cavity into itself, the upper tube's outer nodes into the lower tube's
faces, the lower's into the upper's) in % of the wall, where the deepest lower-tube node
sits (undeformed x, y, z), the size of the upper tube's face it lies behind (its longest edge,
deformed) and how many of that face's nodes are active. Runs on an unfinished run too.

Usage: penetration_steps.py RESULTS.e [--mesh tubes_coarse.exo] [--every K]
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_kratos import WALL, Results, active_on, deepest_node, side_set_faces  # noqa: E402


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("results")
    p.add_argument("--mesh", default="tubes_coarse.exo")
    p.add_argument("--every", type=int, default=1, help="every K-th written step (and the last)")
    a = p.parse_args()
    sets = side_set_faces(a.mesh, ["inner_lower", "inner_upper", "upper_outer", "lower_outer"])
    inner = np.concatenate([sets["inner_lower"], sets["inner_upper"]])
    r = Results(a.results)
    X = r.coordinates().T
    n = r.times().size
    print("    t   active(outer, inner)  self %   upper->lower %   lower->upper %   "
          "deepest lower node (x, y, z), the face it is behind")
    for k in range(n):
        if k % a.every and k != n - 1:
            continue
        x = X + np.array([r.nodal("displ_" + c, k) for c in "xyz"]).T
        w_self = deepest_node(x, inner, inner, WALL)[0]
        w_up = deepest_node(x, sets["upper_outer"], sets["lower_outer"], WALL)[0]
        w_low, node, face = deepest_node(x, sets["lower_outer"], sets["upper_outer"], WALL)
        where = "-"
        if node is not None:
            f = sets["upper_outer"][face]
            edge = max(np.linalg.norm(x[f[i]] - x[f[i - 1]]) for i in range(len(f)))
            active = int(np.sum(r.nodal("contact_status", k)[f] > 0))
            where = "(%.4f, %.4f, %.4f) behind a face of edge %.2e, %d/%d nodes active" % (
                *X[node], edge, active, len(f))
        print("%6.3f  %4d %4d  %14.2f  %14.2f  %14.2f   %s"
              % (r.times()[k], active_on(r, sets["upper_outer"], k), active_on(r, inner, k),
                 100 * w_self / WALL, 100 * w_up / WALL, 100 * w_low / WALL, where))
        sys.stdout.flush()


if __name__ == "__main__":
    main()
