"""Write an Exodus-like results file (one step) from a mesh file and given fields, in the
layout Grout's writer uses, so the contact checks can be exercised before the solver exists:

    python3 fake_results.py            # self-test of the writer with grout_results.Results

    from fake_results import write_results
    write_results("mesh.exo", "np1/case.e", nodal={"displ_x": ux, ...},
                  element={"stress_xx": sxx, ...}, globals_={"newton_iterations": 3})

Element arrays are given for all elements, blocks concatenated in block order. Not used by
ctest; a tool for testing the checks.
"""
import os
import shutil

import netCDF4
import numpy as np


def _put_names(ds, dim, var, names, length):
    ds.createDimension(dim, len(names))
    v = ds.createVariable(var, "S1", (dim, "len_name"))
    arr = np.zeros((len(names), length), dtype="S1")
    for i, n in enumerate(names):
        arr[i, : len(n)] = list(n)
    v[:] = arr


def write_results(mesh, path, nodal, element=None, globals_=None, time=1.0):
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    shutil.copyfile(mesh, path)
    ds = netCDF4.Dataset(path, "a")
    length = len(ds.dimensions["len_name"])
    if "time_whole" not in ds.variables:
        ds.createVariable("time_whole", "f8", ("time_step",))
    ds.variables["time_whole"][0] = time
    n_nodes = len(ds.dimensions["num_nodes"])
    _put_names(ds, "num_nod_var", "name_nod_var", list(nodal), length)
    for i, (name, values) in enumerate(nodal.items(), start=1):
        v = ds.createVariable("vals_nod_var%d" % i, "f8", ("time_step", "num_nodes"))
        assert len(values) == n_nodes, name
        v[0, :] = np.asarray(values, dtype=float)
    element = element or {}
    if element:
        _put_names(ds, "num_elem_var", "name_elem_var", list(element), length)
        n_blocks = len(ds.dimensions["num_el_blk"])
        for i, (name, values) in enumerate(element.items(), start=1):
            start = 0
            for b in range(1, n_blocks + 1):
                n = len(ds.dimensions["num_el_in_blk%d" % b])
                v = ds.createVariable("vals_elem_var%deb%d" % (i, b), "f8", ("time_step", "num_el_in_blk%d" % b))
                v[0, :] = np.asarray(values[start:start + n], dtype=float)
                start += n
    globals_ = globals_ or {}
    if globals_:
        _put_names(ds, "num_glo_var", "name_glo_var", list(globals_), length)
        v = ds.createVariable("vals_glo_var", "f8", ("time_step", "num_glo_var"))
        v[0, :] = np.array(list(globals_.values()), dtype=float)
    ds.close()
