"""Read Grout's Exodus II results with Debian's python3-netcdf4 (no Exodus library needed).

    from grout_results import Results
    r = Results("out.e")
    x, y = r.coordinates()[:2]
    ux = r.nodal("displ_x")            # last step; r.nodal("displ_x", step=0) for the first
    sxx = r.element("stress_xx")       # all blocks concatenated in block order
    n = r.global_var("newton_iterations")

A file-per-rank set (`output: {parallel: per_rank}`: out.e.2.0, out.e.2.1) reads the same
way, as the whole mesh in global numbering: Results("out.e.2.0"), or Results("out.e") when
out.e itself does not exist. r.files lists the files read.
"""
import glob
import os
import re

import netCDF4
import numpy as np


def _names(ds, var):
    if var not in ds.variables:
        return []
    # Each name ends at its first NUL: Exodus writes in no-fill mode, so the bytes after it
    # are whatever the file held (not necessarily valid UTF-8).
    # (numpy's S1 turns a NUL into b"").
    names = []
    for row in np.array(ds.variables[var][:], dtype="S1"):
        chars = list(row)
        end = chars.index(b"") if b"" in chars else len(chars)
        names.append(b"".join(chars[:end]).decode("utf-8", "replace").strip())
    return names


def spread_files(path):
    """The files of the set `path` names: [path] for a single file; for `base.N.r` or for a
    `base` that does not exist beside `base.N.0`, the N files base.N.0 ... (SEACAS naming:
    the rank zero-padded to the digits of N)."""
    match = re.match(r"^(.*)\.(\d+)\.(\d+)$", path)
    if match and os.path.exists(path):
        base, n = match.group(1), int(match.group(2))
    elif not os.path.exists(path):
        found = sorted(glob.glob(glob.escape(path) + ".*.0*"))
        counts = [f[len(path) + 1:].split(".")[0] for f in found]
        counts = sorted({int(c) for c in counts if c.isdigit()})
        if not counts:
            return [path]  # netCDF4 reports the missing file
        base, n = path, counts[-1]
    else:
        return [path]
    width = len(str(n))
    return ["%s.%d.%0*d" % (base, n, width, r) for r in range(n)]


class Results:
    def __init__(self, path):
        self.path = path
        self.files = spread_files(path)
        self.sets = [netCDF4.Dataset(f, "r") for f in self.files]
        for ds in self.sets:
            ds.set_auto_mask(False)
        self.ds = self.sets[0]
        self.nodal_names = _names(self.ds, "name_nod_var")
        self.element_names = _names(self.ds, "name_elem_var")
        self.global_names = _names(self.ds, "name_glo_var")
        self.num_blocks = len(self.ds.dimensions["num_el_blk"])
        # Global (0-based) node and element of each local one, per file; element maps split
        # by block. A single file without maps numbers them 0, 1, ...
        self.node_ids, self.element_ids = [], []
        for ds in self.sets:
            n = len(ds.dimensions["num_nodes"]) if "num_nodes" in ds.dimensions else 0
            ids = (np.array(ds.variables["node_num_map"][:]) - 1 if len(self.sets) > 1
                   else np.arange(n))
            self.node_ids.append(ids)
            counts = [self._block_size(ds, b) for b in range(1, self.num_blocks + 1)]
            elements = (np.array(ds.variables["elem_num_map"][:]) - 1
                        if len(self.sets) > 1 and "elem_num_map" in ds.variables
                        else np.arange(sum(counts)))
            self.element_ids.append(np.split(elements, np.cumsum(counts)[:-1]))
        self.num_nodes = int(max((ids.max(initial=-1) for ids in self.node_ids))) + 1
        self.num_elements = sum(len(e) for ids in self.element_ids for e in ids)

    @staticmethod
    def _block_size(ds, block):
        dim = "num_el_in_blk%d" % block
        return len(ds.dimensions[dim]) if dim in ds.dimensions else 0

    def times(self):
        return np.array(self.ds.variables["time_whole"][:])

    def _nodal_values(self, name_of_var):
        """Whole-mesh array from the per-file arrays `name_of_var(ds)` (None: absent)."""
        out = np.zeros(self.num_nodes)
        for ds, ids in zip(self.sets, self.node_ids):
            values = name_of_var(ds)
            if values is not None:
                out[ids] = values
        return out

    def coordinates(self):
        names = ["coordx", "coordy", "coordz"]
        if "coord" in self.ds.variables and len(self.sets) == 1:  # older layout: one 2D array
            return np.array(self.ds.variables["coord"][:])
        return np.array([self._nodal_values(lambda ds: np.array(ds.variables[n][:])
                                            if n in ds.variables else None)
                         for n in names if n in self.ds.variables])

    def _element_rows(self, block, get):
        """Rows of block `block` (1-based) over all files, in global element order."""
        ids, rows = [], []
        for ds, elements, nodes in zip(self.sets, self.element_ids, self.node_ids):
            values = get(ds, nodes)
            if values is None:
                continue
            ids.append(elements[block - 1])
            rows.append(values)
        if not rows:
            return np.array([])
        order = np.argsort(np.concatenate(ids), kind="stable")
        return np.concatenate(rows)[order]

    def connectivity(self, block):
        """0-based connectivity of block `block` (1-based block index), global node numbers."""
        var = "connect%d" % block
        return self._element_rows(block, lambda ds, nodes: nodes[np.array(ds.variables[var][:]) - 1]
                                  if var in ds.variables else None)

    def nodal(self, name, step=-1):
        if name not in self.nodal_names:
            raise KeyError("%s: no nodal variable '%s' (has %s)" % (self.path, name, self.nodal_names))
        var = "vals_nod_var%d" % (self.nodal_names.index(name) + 1)
        return self._nodal_values(lambda ds: np.array(ds.variables[var][step, :]))

    def element(self, name, step=-1):
        if name not in self.element_names:
            raise KeyError("%s: no element variable '%s' (has %s)" % (self.path, name, self.element_names))
        i = self.element_names.index(name) + 1
        parts = []
        for b in range(1, self.num_blocks + 1):
            var = "vals_elem_var%deb%d" % (i, b)
            part = self._element_rows(b, lambda ds, nodes: np.array(ds.variables[var][step, :])
                                      if var in ds.variables else None)
            if len(part):
                parts.append(part)
        return np.concatenate(parts)

    def global_var(self, name, step=-1):
        if name not in self.global_names:
            raise KeyError("%s: no global variable '%s' (has %s)" % (self.path, name, self.global_names))
        return float(self.ds.variables["vals_glo_var"][step, self.global_names.index(name)])

    def node_blocks(self):
        """Per node, the 1-based index of the (last) block whose elements use it; 0 for a node
        of no element. Bodies in contact have their own nodes at the same coordinates: key a
        node by (block, coordinates) to match it across two meshes."""
        blocks = np.zeros(self.num_nodes, dtype=int)
        for b in range(1, self.num_blocks + 1):
            blocks[np.unique(self.connectivity(b))] = b
        return blocks

    def node_map(self, other, move=lambda x: x):
        """For each node of this mesh, the index of the node of `other` in the same block at
        move(its coordinates) (matched to 1e-9: half and full models, mirror images). The
        block is part of the key: bodies in contact have their own nodes at the same place."""
        def key(block, x):
            return (block,) + tuple(np.round(x, 9))
        index = {key(b, x): i for i, (x, b) in enumerate(zip(other.coordinates().T,
                                                             other.node_blocks()))}
        return np.array([index[key(b, move(x))]
                         for x, b in zip(self.coordinates().T, self.node_blocks())])

    def element_centroids(self):
        xyz = self.coordinates()
        parts = []
        for b in range(1, self.num_blocks + 1):
            conn = self.connectivity(b)
            parts.append(np.stack([xyz[d][conn].mean(axis=1) for d in range(xyz.shape[0])], axis=1))
        return np.concatenate(parts)


def relative_difference(a, b):
    """max |a - b| / max(|a|, |b|, tiny): for comparing 1-rank and 2-rank results."""
    scale = max(np.abs(a).max(initial=0.0), np.abs(b).max(initial=0.0), 1e-300)
    return np.abs(a - b).max(initial=0.0) / scale
