#!/usr/bin/python3
"""Copy an Exodus mesh with one empty side set and one empty node set added, both named
`empty` (Exodus status 0: no entries stored), for the bad-input runs of compare_errors.py.

    empty_sets.py <source.exo> <target.exo>
"""
import pathlib
import sys

import netCDF4
import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "hostile_input"))
from hostile_meshes import copy_dataset  # noqa: E402


def main():
    source, target = sys.argv[1], sys.argv[2]
    with netCDF4.Dataset(source) as src:
        side_sets, node_sets = len(src.dimensions["num_side_sets"]), len(src.dimensions["num_node_sets"])
    copy_dataset(source, target, "NETCDF3_64BIT_OFFSET",
                 dims={"num_side_sets": side_sets + 1, "num_node_sets": node_sets + 1},
                 skip={"ss_status", "ss_prop1", "ss_names", "ns_status", "ns_prop1", "ns_names"})
    with netCDF4.Dataset(source) as src, netCDF4.Dataset(target, "r+") as ds:
        for kind, count in (("ss", side_sets), ("ns", node_sets)):
            ds.variables[f"{kind}_status"][:] = list(src.variables[f"{kind}_status"][:]) + [0]
            ids = list(src.variables[f"{kind}_prop1"][:])
            ds.variables[f"{kind}_prop1"][:] = ids + [max(ids) + 1]
            names = np.zeros((count + 1, len(ds.dimensions["len_name"])), dtype="S1")
            names[:count] = src.variables[f"{kind}_names"][:]
            names[count, :5] = list("empty")
            ds.variables[f"{kind}_names"][:] = names


if __name__ == "__main__":
    main()
