"""Results at scale (docs/input.md, output/parallel), read with python3-netcdf4 through
tools/grout_results.py, on 1, 2 and 3 ranks, 2D and 3D:

- `per_rank` writes exactly the files <file>.<ranks>.<rank> (SEACAS's naming; on 1 rank
  <file> itself), no temporary left; each holds the rank's own elements (every element in exactly one file; with 2 or 3
  ranks no file holds them all) and exactly the nodes they use, their global numbers in the
  node and element id maps, elements in the file match the whole mesh's connectivity;
- the Nemesis I data: global counts, block and set sizes of the whole mesh; the border nodes
  are exactly the nodes that another file holds, and each nodal communication map lists the
  nodes shared with that neighbour (the neighbour's map lists the same global nodes);
- the set read as one mesh equals the single file of the same input bit for bit (times,
  coordinates, connectivity, every nodal, element and global variable at every step): the
  two layouts write the same numbers. The two are separate runs: where the solve itself is
  not repeatable bit for bit, distributed MUMPS in 3D on 2 or 3 ranks (its rounding follows
  the order in which its fronts finish, docs/performance.md), the values agree to
  SOLVE_REPEAT = 1e-12 of each variable's largest value instead (a misplaced node or element
  in either layout differs at O(1)). Both layouts read the distributed mesh
  (drivers/mesh_choice.hpp), one partition: the converged residual too is bitwise the same
  (in 3D on 2 and 3 ranks within SOLVE_REPEAT, as every value);
- the single file of 2 and 3 ranks has the time steps and names of the 1-rank file, and its
  values agree to 1e-8 relative (the solve's round-off on another partition; normal_gap,
  round-off itself where the contact is closed, relative to the displacement).
"""
import os
import sys

import netCDF4
import numpy as np

from grout_results import Results, relative_difference

CASES = ["contact_2d", "contact_3d"]
RANKS = [1, 2, 3]
ROUND_OFF = 1e-8  # 1 rank against 2 and 3 (the inputs' 1-rank/2-rank agreement is 1e-10)
SOLVE_REPEAT = 1e-12  # two runs of one 3D input on several ranks (distributed MUMPS)
failures = []


def check(ok, message):
    print(("ok   " if ok else "FAIL ") + message)
    if not ok:
        failures.append(message)


def same_values(a, b, what, tolerance=0.0, residual_tolerance=None):
    """Every step of every variable, coordinates and connectivity: bitwise equal (variables:
    within `tolerance` relative to each one's largest value when it is > 0; the global
    `residual` within `residual_tolerance` of the step's load when that is given)."""
    # Each value against the scale of its kind, as for 1 rank against several below: a
    # reaction or the residual against the largest global value of the step (the load), the
    # normal gap against the displacement; quantities that are zero up to round-off (the
    # reactions on symmetry planes, a closed gap) would otherwise compare their round-off.
    def agree(x, y, scale=None, tolerance=tolerance):
        if tolerance == 0.0:
            return np.array_equal(x, y)
        x = np.atleast_1d(np.asarray(x, dtype=float))
        y = np.atleast_1d(np.asarray(y, dtype=float))
        if x.shape != y.shape:
            return False
        if scale is None:
            return relative_difference(x, y) <= tolerance
        return np.abs(x - y).max(initial=0.0) <= tolerance * max(scale, 1e-300)

    check(np.array_equal(a.times(), b.times()), "%s: same times" % what)
    check(a.nodal_names == b.nodal_names and a.element_names == b.element_names and
          a.global_names == b.global_names, "%s: same variable names" % what)
    check(np.array_equal(a.coordinates(), b.coordinates()), "%s: same coordinates" % what)
    check(all(np.array_equal(a.connectivity(k), b.connectivity(k))
              for k in range(1, a.num_blocks + 1)), "%s: same connectivity" % what)
    equal = True
    for step in range(len(a.times())):
        length = np.abs(a.nodal("displ_y", step)).max() if "displ_y" in a.nodal_names else None
        load = max((abs(a.global_var(n, step)) for n in a.global_names), default=0.0)
        equal &= all(agree(a.nodal(n, step), b.nodal(n, step),
                           length if n == "normal_gap" else None) for n in a.nodal_names)
        equal &= all(agree(a.element(n, step), b.element(n, step)) for n in a.element_names)
        equal &= all(agree(a.global_var(n, step), b.global_var(n, step), load,
                           residual_tolerance if n == "residual" and residual_tolerance
                           else tolerance)
                     for n in a.global_names)
    check(equal, "%s: every nodal, element and global value equal at every step%s" %
          (what, " (to %g)" % tolerance if tolerance else ""))


def check_pieces(per, single, ranks, what):
    expected = (["%s.%d.%0*d" % (per.path, ranks, len(str(ranks)), r) for r in range(ranks)]
                if ranks > 1 else [per.path])  # IOSS names a set of one file as the plain name
    check(per.files == expected and all(os.path.exists(f) for f in expected),
          "%s: files %s" % (what, ", ".join(os.path.basename(f) for f in expected)))
    folder = os.path.dirname(per.path) or "."
    check(not [f for f in os.listdir(folder) if f.endswith(".partial")],
          "%s: no temporary file left" % what)
    owners = np.zeros(single.num_elements, dtype=int)
    holders = {}  # global node -> ranks whose file holds it
    for r, ds in enumerate(per.sets):
        elements = np.concatenate(per.element_ids[r])
        owners[elements] += 1
        used = set()
        for k in range(1, per.num_blocks + 1):
            var = "connect%d" % k
            if var not in ds.variables:
                continue
            rows = per.node_ids[r][np.array(ds.variables[var][:]) - 1]
            used.update(rows.ravel().tolist())
            first = sum(Results._block_size(single.ds, j) for j in range(1, k))
            whole = single.connectivity(k)[per.element_ids[r][k - 1] - first]
            if not np.array_equal(rows, whole):
                check(False, "%s: rank %d block %d connectivity matches the mesh" % (what, r, k))
        check(sorted(used) == sorted(per.node_ids[r].tolist()),
              "%s: rank %d holds exactly the nodes of its %d elements" % (what, r, len(elements)))
        if ranks > 1:
            check(len(elements) < single.num_elements,
                  "%s: rank %d holds %d of %d elements" % (what, r, len(elements),
                                                          single.num_elements))
        for n in per.node_ids[r]:
            holders.setdefault(int(n), []).append(r)
        # Nemesis I: global counts.
        dims = ds.dimensions
        check(len(dims["num_nodes_global"]) == single.num_nodes and
              len(dims["num_elems_global"]) == single.num_elements and
              len(dims["num_processors"]) == ranks,
              "%s: rank %d Nemesis global counts" % (what, r))
        blocks_global = np.array(ds.variables["el_blk_cnt_global"][:])
        check(np.array_equal(blocks_global, [Results._block_size(single.ds, k)
                                             for k in range(1, single.num_blocks + 1)]),
              "%s: rank %d global block sizes" % (what, r))
    check(np.all(owners == 1), "%s: every element in exactly one file" % what)
    for r, ds in enumerate(per.sets):
        ids = per.node_ids[r]
        border = set(np.array(ds.variables["node_mapb"][:]).tolist()) if "node_mapb" in ds.variables else set()
        expected_border = {i + 1 for i, n in enumerate(ids) if len(holders[int(n)]) > 1}
        check(border == expected_border, "%s: rank %d border nodes (%d) are those another file "
              "holds" % (what, r, len(border)))
        maps_ok = True
        if "n_comm_ids" in ds.variables:
            neighbours = np.array(ds.variables["n_comm_ids"][:])
            nodes = np.array(ds.variables["n_comm_nids"][:])
            procs = np.array(ds.variables["n_comm_proc"][:])
            for q in neighbours:
                listed = {int(ids[n - 1]) for n, p in zip(nodes, procs) if p == q}
                shared = {int(n) for n in ids if q in holders[int(n)]}
                maps_ok &= listed == shared
            maps_ok &= set(neighbours.tolist()) == {q for n in ids for q in holders[int(n)]} - {r}
        else:
            maps_ok = all(holders[int(n)] == [r] for n in ids)
        check(maps_ok, "%s: rank %d communication maps list the nodes shared with each "
              "neighbour" % (what, r))


def main():
    for case in CASES:
        reference = Results("np1/%s.e" % case)
        for ranks in RANKS:
            what = "%s np%d" % (case, ranks)
            single = Results("np%d/%s.e" % (ranks, case))
            per = Results("np%d/%s_per_rank.e" % (ranks, case))
            check_pieces(per, single, ranks, what + " per_rank")
            repeat = SOLVE_REPEAT if case.endswith("_3d") and ranks > 1 else 0.0
            same_values(per, single, what + ": per_rank set against the single file", repeat)
            if ranks == 1:
                continue
            check(np.array_equal(single.times(), reference.times()) and
                  single.nodal_names == reference.nodal_names and
                  single.element_names == reference.element_names,
                  "%s: the 1-rank file's steps and names" % what)
            worst = 0.0
            for step in range(len(reference.times())):
                # normal_gap is round-off (1e-16) where the contact is closed: measured
                # against the displacement, the length it is a part of.
                length = np.abs(reference.nodal("displ_y", step)).max()
                for n in reference.nodal_names:
                    a, b = single.nodal(n, step), reference.nodal(n, step)
                    if n == "normal_gap":
                        worst = max(worst, np.abs(a - b).max() / length)
                    else:
                        worst = max(worst, relative_difference(a, b))
                for n in reference.element_names:
                    worst = max(worst, relative_difference(single.element(n, step),
                                                           reference.element(n, step)))
            check(worst < ROUND_OFF, "%s: single file within %g of 1 rank (%.1e)" %
                  (what, ROUND_OFF, worst))
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
