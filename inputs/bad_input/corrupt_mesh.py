"""Write a copy of an Exodus mesh with one defect, for the mesh-integrity error cases.

    corrupt_mesh.py <in.exo> <out.exo> <defect> [set name]

Defects (each edits values in place; no dimension changes):
  duplicate_node     node set <name>: its second entry repeats its first
  duplicate_face     side set <name>: its second face repeats its first
  duplicate_set_name the second node set gets the first node set's name
  duplicate_set_id   the second side set gets the first side set's id
  inverted           element 1 of block 1: two nodes swapped (negative det J)
  degenerate         element 1 of block 1 (QUAD4): its last two nodes moved onto its first
                     two (zero area)
  nan_coordinate     node 1: x = NaN
  foreign_face       side set <name>: its first face replaced by a face of another body
                     (element 1, side 1: block 1 must be the other body)
"""
import shutil
import sys

import netCDF4
import numpy as np


def set_index(ds, kind, name):
    names = netCDF4.chartostring(ds.variables[f"{kind}_names"][:])
    return [str(n) for n in names].index(name) + 1


def main():
    source, target, defect = sys.argv[1:4]
    name = sys.argv[4] if len(sys.argv) > 4 else None
    shutil.copyfile(source, target)
    with netCDF4.Dataset(target, "r+") as ds:
        ds.set_auto_mask(False)
        if defect == "duplicate_node":
            v = ds.variables[f"node_ns{set_index(ds, 'ns', name)}"]
            v[1] = v[0]
        elif defect == "duplicate_face":
            i = set_index(ds, "ss", name)
            for var in (f"elem_ss{i}", f"side_ss{i}"):
                ds.variables[var][1] = ds.variables[var][0]
        elif defect == "duplicate_set_name":
            names = ds.variables["ns_names"]
            names[1, :] = names[0, :]
        elif defect == "duplicate_set_id":
            ids = ds.variables["ss_prop1"]
            ids[1] = ids[0]
        elif defect == "inverted":
            c = ds.variables["connect1"]
            row = c[0, :].copy()
            row[[1, 3]] = row[[3, 1]] if len(row) == 4 else row[[2, 1]]
            c[0, :] = row
        elif defect == "degenerate":
            c = ds.variables["connect1"]
            nodes = [int(n) - 1 for n in c[0, :]]
            for axis in ("coordx", "coordy"):
                x = ds.variables[axis]
                x[nodes[2]] = x[nodes[1]]
                x[nodes[3]] = x[nodes[0]]
        elif defect == "nan_coordinate":
            ds.variables["coordx"][0] = np.nan
        elif defect == "foreign_face":
            i = set_index(ds, "ss", name)
            ds.variables[f"elem_ss{i}"][0] = 1
            ds.variables[f"side_ss{i}"][0] = 1
        else:
            sys.exit(f"corrupt_mesh.py: unknown defect '{defect}'")


if __name__ == "__main__":
    main()
