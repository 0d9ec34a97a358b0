"""What each rank holds of the mesh and evaluates of the contact on the distributed mesh
(docs/performance.md, "Scale: what a rank holds"): runs the command after --, a `grout ...
--timers` run on several ranks, prints its output and checks its holdings report:
- the run read the distributed mesh;
- each rank owns its share of the elements, within --tol (5 %) of the even share (the mesh
  file's element count over the ranks);
- every rank evaluates slave faces (a rank evaluates the faces with a node it owns), and
  together they evaluate every face at least once; the counts are printed against the even
  share (the slave side set's face count over the ranks);
- each rank holds its share of the contact zone: the master faces its slave faces found in the
  search, within --search-tol (30 %) of the even share of their sum.
On the two hemispheres of sphere_sphere, RCB with weights 1 cuts between the bodies and one
rank evaluates every slave face. The slave elements cut apart by position alone
(GROUT_PARTITION=separate:positions) split the slave faces evenly, but not the zone, which is
a fraction of the surface round the pole: on level 1 the other rank's faces find no master
face, on levels 2 and 3 one rank's find 43 % and 38 % more than the even share. The default cuts the contact elements in bands of
their distance to the other surface (docs/input.md, "Checks against the mesh"): the zone is
shared, and the faces far from it, which find no master face and cost little, may lean to one
rank (rank 0 evaluates 24-32 % more than the even share: a node on two parts' contact
elements goes to the lower part, and the bands' cuts are longer than one cut).

Usage: check_holdings.py MESH.exo SLAVE_SET [--interface NAME] [--tol 0.05] [--search-tol 0.3]
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
        sys.exit("usage: check_holdings.py MESH.exo SLAVE_SET [--tol T] [--search-tol T] -- "
                 "COMMAND...")
    cut = argv.index("--")
    ap = argparse.ArgumentParser()
    ap.add_argument("mesh")
    ap.add_argument("slave_set")
    ap.add_argument("--interface", default="ball")
    ap.add_argument("--tol", type=float, default=0.05)
    ap.add_argument("--search-tol", type=float, default=0.3)
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
        evaluated = contact[r][0]
        share = elements / ranks
        ok = abs(owned[r] - share) <= a.tol * share
        print("rank %d: owned elements %d of %d, %+.1f %% off the even share %.1f (tolerance "
              "%.0f %%): %s" % (r, owned[r], elements, 100 * (owned[r] - share) / share, share,
                                100 * a.tol, "ok" if ok else "FAIL"))
        if not ok:
            fails.append("rank %d: owned elements %d, not within %g %% of %.1f" %
                         (r, owned[r], 100 * a.tol, share))
        print("rank %d: evaluated slave faces %d of %d, %+.1f %% off the even share %.1f" %
              (r, evaluated, faces, 100 * (evaluated - faces / ranks) / (faces / ranks),
               faces / ranks))
        if evaluated == 0:
            fails.append("rank %d evaluates no slave face" % r)
    searched = [contact[r][1] for r in range(ranks)]
    zone = sum(searched) / ranks
    for r in range(ranks):
        ok = abs(searched[r] - zone) <= a.search_tol * zone
        print("rank %d: master faces after the search %d, %+.1f %% off the even share %.1f of "
              "the contact zone (tolerance %.0f %%): %s" % (r, searched[r], 100 * (
                  searched[r] - zone) / max(zone, 1e-300), zone, 100 * a.search_tol,
                  "ok" if ok else "FAIL"))
        if not ok:
            fails.append("rank %d: master faces after the search %d, not within %g %% of %.1f"
                         % (r, searched[r], 100 * a.search_tol, zone))
    if sum(contact[r][0] for r in range(ranks)) < faces:
        fails.append("the ranks evaluate %d slave faces, the side set has %d" %
                     (sum(contact[r][0] for r in range(ranks)), faces))
    if fails:
        sys.exit("check_holdings: FAIL\n" + "\n".join(fails))
    print("check_holdings: pass")


if __name__ == "__main__":
    main()
