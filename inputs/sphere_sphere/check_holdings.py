"""What each rank holds of the mesh and evaluates of the contact on the distributed mesh
(docs/performance.md, "Scale: what a rank holds"): runs the command after --, a `grout ...
--timers` run on several ranks, prints its output and checks its holdings report:
- the run read the distributed mesh;
- each rank owns its share of the elements, within --tol (5 %) of the even share (the mesh
  file's element count over the ranks);
- each rank evaluates its share of the slave faces, within --face-tol (20 %) of the even share
  (the slave side set's face count over the ranks): a rank evaluates the faces with a node it
  owns, so the faces along the cut count on both sides, and together the ranks evaluate every
  face at least once.
On the two hemispheres of sphere_sphere, RCB with weights 1 cuts between the bodies and one
rank evaluates every slave face.

Usage: check_holdings.py MESH.exo SLAVE_SET [--interface NAME] [--tol 0.05] [--face-tol 0.2]
       -- COMMAND...
"""
import argparse
import re
import subprocess
import sys

import netCDF4
import numpy as np


def mesh_counts(path, side_set):
    """(element count, faces of side set `side_set`) of the Exodus file `path`."""
    with netCDF4.Dataset(path) as ds:
        names = [bytes(np.ma.getdata(n)).split(b"\0")[0].decode() for n in ds["ss_names"][:]]
        if side_set not in names:
            sys.exit("check_holdings: no side set %r in %s (%s)" % (side_set, path, names))
        k = names.index(side_set) + 1
        return ds.dimensions["num_elem"].size, ds.dimensions["num_side_ss%d" % k].size


def main():
    argv = sys.argv[1:]
    if "--" not in argv:
        sys.exit("usage: check_holdings.py MESH.exo SLAVE_SET [--tol T] [--face-tol T] -- "
                 "COMMAND...")
    cut = argv.index("--")
    ap = argparse.ArgumentParser()
    ap.add_argument("mesh")
    ap.add_argument("slave_set")
    ap.add_argument("--interface", default="ball")
    ap.add_argument("--tol", type=float, default=0.05)
    ap.add_argument("--face-tol", type=float, default=0.2)
    a = ap.parse_args(argv[:cut])
    run = subprocess.run(argv[cut + 1:], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True)
    print(run.stdout)
    if run.returncode != 0:
        sys.exit("check_holdings: the run exited with %d" % run.returncode)
    elements, faces = mesh_counts(a.mesh, a.slave_set)
    owned = {int(r): int(e) for r, e in re.findall(
        r"^mesh on rank (\d+): nodes \d+ owned \+ \d+ ghost \([^)]*\), elements (\d+) owned",
        run.stdout, re.M)}
    contact = {int(r): (int(e), int(s)) for r, e, s in re.findall(
        r"^contact %s on rank (\d+): slave faces \d+ \((\d+) evaluated\), master faces \d+ owned, "
        r"(\d+) after the search" % re.escape(a.interface), run.stdout, re.M)}
    fails = []
    if "grout: mesh: distributed" not in run.stdout:
        fails.append("the run did not read the distributed mesh")
    ranks = len(owned)
    if ranks < 2 or sorted(owned) != sorted(contact) or sorted(owned) != list(range(ranks)):
        sys.exit("check_holdings: no holdings report of 2 or more ranks (--timers)\n" +
                 "\n".join(fails))
    for r in range(ranks):
        evaluated, searched = contact[r]
        for what, mine, total, tol in (("owned elements", owned[r], elements, a.tol),
                                       ("evaluated slave faces", evaluated, faces, a.face_tol)):
            share = total / ranks
            ok = abs(mine - share) <= tol * share
            print("rank %d: %s %d of %d, %+.1f %% off the even share %.1f (tolerance %.0f %%): %s"
                  % (r, what, mine, total, 100 * (mine - share) / share, share, 100 * tol,
                     "ok" if ok else "FAIL"))
            if not ok:
                fails.append("rank %d: %s %d, not within %g %% of %.1f" %
                             (r, what, mine, 100 * tol, share))
        print("rank %d: master faces after the search %d" % (r, searched))
    if sum(contact[r][0] for r in range(ranks)) < faces:
        fails.append("the ranks evaluate %d slave faces, the side set has %d" %
                     (sum(contact[r][0] for r in range(ranks)), faces))
    if fails:
        sys.exit("check_holdings: FAIL\n" + "\n".join(fails))
    print("check_holdings: pass")


if __name__ == "__main__":
    main()
