#!/usr/bin/python3
"""Full refinement study of the tied L-shape (docs/verification.md): tied and conforming gmsh
meshes of sizes h = 0.2, 0.1, 0.05, each run with lshape_tied.yaml / lshape_conforming_fine.yaml
on 1 rank; prints the top reaction R_y at t = 0.5, 1, 2 and the tied - conforming differences,
and checks the tie residual on every tied mesh (mortar_2d_ref.py).

Usage (from an empty folder): study.py GROUT_BINARY [--sizes 0.2 0.1 0.05]
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))


def run(grout, kind, h):
    stem = "%s_%g" % (kind, h)
    args = ["--size", str(h)] + (["--conforming"] if kind == "conforming" else [])
    subprocess.run([sys.executable, os.path.join(HERE, "lshape.py"), stem + ".exo"] + args, check=True)
    src = "lshape_tied.yaml" if kind == "tied" else "lshape_conforming_fine.yaml"
    text = open(os.path.join(HERE, src)).read()
    old = "lshape_tied" if kind == "tied" else "lshape_conforming_fine"
    open(stem + ".yaml", "w").write(text.replace(old, stem))
    subprocess.run([grout, stem + ".yaml", "--output-dir", "np1"], check=True, stdout=subprocess.DEVNULL)
    rows = csv.DictReader(open("np1/%s.csv" % stem))
    return stem, {round(float(r["time"]), 9): float(r["reaction_top_nodes_y"]) for r in rows}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("grout")
    ap.add_argument("--sizes", type=float, nargs="+", default=[0.2, 0.1, 0.05])
    a = ap.parse_args()
    import check  # noqa: E402  (tie_check)

    results = {}
    for h in a.sizes:
        for kind in ("tied", "conforming"):
            stem, r = run(os.path.abspath(a.grout), kind, h)
            results[(kind, h)] = r
            if kind == "tied":
                worst, jump, n, unmatched, steps = check.tie_check("np1/%s.e" % stem)
                print("h = %g tied: %d slave nodes (%d off the master nodes), tie residual %.2e, "
                      "pointwise jump %.2e max|u|" % (h, n, unmatched, worst, jump))
    for t in (0.5, 1.0, 2.0):
        for h in a.sizes:
            rt, rc = results[("tied", h)].get(t), results[("conforming", h)].get(t)
            if rt is None or rc is None:
                continue
            print("t = %.1f h = %-5g R_y tied %.6g conforming %.6g tied/conforming - 1 = %+.3f %%"
                  % (t, h, rt, rc, 100 * (rt / rc - 1)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
