#!/usr/bin/python3
"""Refinement study of the gmsh drag (docs/verification.md): drag_touch.yaml and drag_point.yaml
on meshes of contact size h = 0.125, 0.0625, 0.03125 (drag_mesh.py --size), 1 rank. Prints
the vertical force R_y at the end of pressing (t = 1: indentation 0.05 of the flat die) with
Richardson's extrapolation, the largest |R_x|/R_y while sliding, and the point start's contact
half-width against Hertz.

Usage (from an empty folder): study.py GROUT_BINARY [--sizes 0.125 0.0625 0.03125]
"""
import argparse
import math
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "contact_common"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))


def run(grout, variant, h):
    stem = "drag_%s_%g" % (variant, h)
    extra = ["--radius", "4"] if variant == "point" else []
    subprocess.run([sys.executable, os.path.join(HERE, "drag_mesh.py"), stem + ".exo", "--size", str(h)] + extra,
                   check=True, stdout=subprocess.DEVNULL)
    text = open(os.path.join(HERE, "drag_%s.yaml" % variant)).read().replace("drag_%s" % variant, stem)
    open(stem + ".yaml", "w").write(text)
    subprocess.run([grout, stem + ".yaml", "--output-dir", "np1"], check=True, stdout=subprocess.DEVNULL)
    return stem


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("grout")
    ap.add_argument("--sizes", type=float, nargs="+", default=[0.125, 0.0625, 0.03125])
    a = ap.parse_args()
    import check
    import contact_check as cc
    from grout_results import Results

    forces = []
    for h in a.sizes:
        stem = run(os.path.abspath(a.grout), "touch", h)
        t, rx, ry, _ = check.summary(stem, 1)
        k = int(np.argmin(abs(t - 1.0)))
        sliding = t > 1 + 1e-9
        forces.append(ry[k])
        print("touch h = %-8g R_y(t = 1) = %.6g, max |R_x|/R_y sliding %.2e" % (h, ry[k], (abs(rx[sliding]) / ry[sliding]).max()))
        stem = run(os.path.abspath(a.grout), "point", h)
        r = Results("np1/%s.e" % stem)
        times = np.round(r.times(), 9)
        i = int(np.nonzero(times == 1.0)[0][0])
        s = cc.side_set_nodes(r, "die_bottom")
        x = r.coordinates()[0, s] + r.nodal("displ_x", i)[s]
        p = r.nodal("contact_pressure", i)[s]
        t, rx, ry, _ = check.summary(stem, 1)
        P = ry[int(np.argmin(abs(t - 1.0)))]
        b = cc.half_width(x - np.average(x, weights=np.clip(p, 0, None)), p)
        bh, _ = cc.hertz_line_contact(P, check.R, math.inf, check.E, check.NU, check.E, check.NU)
        print("point h = %-8g P = %.6g, b = %.5f, Hertz %.5f (%+.2f %%)" % (h, P, b, bh, 100 * (b / bh - 1)))
    if len(forces) >= 3:
        f1, f2, f3 = forces[-3:]
        p = math.log(abs((f1 - f2) / (f2 - f3))) / math.log(2)
        print("R_y(t = 1): observed order %.2f, Richardson %.6g (finest %+.3f %%)"
              % (p, f3 + (f3 - f2) / (2**p - 1), 100 * ((f3 - f2) / (2**p - 1)) / f3))
    return 0


if __name__ == "__main__":
    sys.exit(main())
