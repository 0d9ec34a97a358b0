"""tools/mdpa_to_exodus.py --layer on layer_test.mdpa (2 x 1 x 2 hexahedra of [0, 1] x [0, 1] x
[0, 0.5], stacked in z): the z = 0 layer (and the inner z = 0.25 layer) is two unit-height
quads of [0, 1] x [0, 1], counterclockwise, with the node sets and side sets of the parts.

Usage: check_layer.py LAYER0.exo LAYER025.exo
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402
from grout_results import Results  # noqa: E402


def check(path, failures):
    r = Results(path)
    xy = r.coordinates()
    conn = r.connectivity(1)
    if xy.shape != (2, 6) or conn.shape != (2, 4):
        failures.append("%s: %s coordinates, %s connectivity; expected 2 x 6 and 2 x 4"
                        % (path, xy.shape, conn.shape))
        return
    pts = sorted(zip(np.round(xy[0], 12), np.round(xy[1], 12)))
    if pts != sorted((0.5 * i, 1.0 * j) for i in range(3) for j in range(2)):
        failures.append("%s: nodes %s are not the layer's" % (path, pts))
    for e, c in enumerate(conn):
        x, y = xy[0][c], xy[1][c]
        area = 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)
        if not abs(area - 0.5) < 1e-12:
            failures.append("%s: element %d has signed area %g, expected 0.5" % (path, e + 1, area))
    left = cc.node_set(r, "displacement_left")
    if sorted(np.round(xy[0][left], 12)) != [0.0, 0.0]:
        failures.append("%s: node set displacement_left is not the 2 nodes at x = 0" % path)
    for name, coord, value, count in [("contact_top_parts_auto1_nodes", 1, 1.0, 3),
                                      ("load_bottom_nodes", 1, 0.0, 2)]:
        nodes = cc.node_set(r, name)
        if len(nodes) != count or not np.allclose(xy[coord][nodes], value):
            failures.append("%s: node set %s is %s, expected %d nodes at %s = %g"
                            % (path, name, nodes, count, "xy"[coord], value))
    print("%s: 6 nodes, 2 counterclockwise quads, sets as expected" % path)


failures = []
for p in sys.argv[1:]:
    check(p, failures)
if len(sys.argv) < 2 or failures:
    print("FAILED:\n  " + "\n  ".join(failures or ["no file given"]))
    sys.exit(1)
