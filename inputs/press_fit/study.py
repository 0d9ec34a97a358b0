#!/usr/bin/python3
"""Full press fit (docs/verification.md): press_fit.yaml (150 steps) on Kratos' three 2D meshes
and on structured meshes of levels 1, 2, 4 (press_fit_mesh.py), 1 rank; prints the peak and
the plateau (mean after step 137) of the horizontal reaction against the digitised figure.

Usage (from an empty folder): study.py GROUT_BINARY [KRATOS_2D_SOURCE_FOLDER]
(the Kratos folder holds press_fit_medium_refined.mdpa and press_fit_refined.mdpa; default
../shared/reference/kratos_examples/press_fit/source/2D next to the repository)
"""
import csv
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
TOOLS = os.path.join(HERE, "..", "..", "tools")


def run(grout, stem, mesh):
    text = open(os.path.join(HERE, "press_fit.yaml")).read()
    text = text.replace("file: press_fit.exo", "file: %s" % mesh)
    text = text.replace("press_fit.e,", stem + ".e,").replace("summary: press_fit.csv", "summary: %s.csv" % stem)
    open(stem + ".yaml", "w").write(text)
    subprocess.run([grout, stem + ".yaml", "--output-dir", "np1"], check=True, stdout=subprocess.DEVNULL)
    rows = list(csv.DictReader(open("np1/%s.csv" % stem)))
    s = np.array([float(r["time"]) for r in rows]) * 150 / 1.3
    rx = np.abs([float(r["reaction_displacement_displacement_auto3_x"]) for r in rows]) / 1e3
    return s, np.array(rx)


def main(argv):
    grout = os.path.abspath(argv[1])
    kratos = argv[2] if len(argv) > 2 else os.path.join(HERE, "..", "..", "..", "shared", "reference",
                                                        "kratos_examples", "press_fit", "source", "2D")
    ref = np.loadtxt(os.path.join(HERE, "reference_solution_2d.csv"), delimiter=",", skiprows=3)
    ref_peak, ref_plateau = ref[:, 1].max(), ref[ref[:, 0] > 137, 1].mean()
    cases = [("kratos_coarse", os.path.join(HERE, "press_fit.mdpa")),
             ("kratos_medium", os.path.join(kratos, "press_fit_medium_refined.mdpa")),
             ("kratos_refined", os.path.join(kratos, "press_fit_refined.mdpa"))]
    meshes = []
    for stem, mdpa in cases:
        subprocess.run([sys.executable, os.path.join(TOOLS, "mdpa_to_exodus.py"), mdpa, stem + ".exo"],
                       check=True, stdout=subprocess.DEVNULL)
        meshes.append((stem, stem + ".exo"))
    for k in (1, 2, 4):
        stem = "structured_%d" % k
        subprocess.run([sys.executable, os.path.join(HERE, "press_fit_mesh.py"), stem + ".exo", "--level", str(k)],
                       check=True, stdout=subprocess.DEVNULL)
        meshes.append((stem, stem + ".exo"))
    print("figure: peak %.4g, plateau %.4g" % (ref_peak, ref_plateau))
    for stem, mesh in meshes:
        s, rx = run(grout, stem, mesh)
        k = int(np.argmax(rx))
        plateau = rx[s > 137].mean()
        print("%-15s peak %.4g at step %.0f (%+.1f %%), plateau %.4g (%+.1f %%), first > 1e3 at step %.0f"
              % (stem, rx[k], s[k], 100 * (rx[k] / ref_peak - 1), plateau, 100 * (plateau / ref_plateau - 1),
                 s[np.argmax(rx > 1e3)]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
