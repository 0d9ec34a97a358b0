"""Read Grout's Exodus II results with Debian's python3-netcdf4 (no Exodus library needed).

    from grout_results import Results
    r = Results("out.e")
    x, y = r.coordinates()[:2]
    ux = r.nodal("displ_x")            # last step; r.nodal("displ_x", step=0) for the first
    sxx = r.element("stress_xx")       # all blocks concatenated in block order
    n = r.global_var("newton_iterations")
"""
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


class Results:
    def __init__(self, path):
        self.path = path
        self.ds = netCDF4.Dataset(path, "r")
        self.ds.set_auto_mask(False)
        self.nodal_names = _names(self.ds, "name_nod_var")
        self.element_names = _names(self.ds, "name_elem_var")
        self.global_names = _names(self.ds, "name_glo_var")
        self.num_blocks = len(self.ds.dimensions["num_el_blk"])

    def times(self):
        return np.array(self.ds.variables["time_whole"][:])

    def coordinates(self):
        names = ["coordx", "coordy", "coordz"]
        if "coord" in self.ds.variables:  # older layout: one 2D array
            return np.array(self.ds.variables["coord"][:])
        return np.array([self.ds.variables[n][:] for n in names if n in self.ds.variables])

    def connectivity(self, block):
        """0-based connectivity of block `block` (1-based block index)."""
        return np.array(self.ds.variables["connect%d" % block][:]) - 1

    def nodal(self, name, step=-1):
        if name not in self.nodal_names:
            raise KeyError("%s: no nodal variable '%s' (has %s)" % (self.path, name, self.nodal_names))
        i = self.nodal_names.index(name) + 1
        return np.array(self.ds.variables["vals_nod_var%d" % i][step, :])

    def element(self, name, step=-1):
        if name not in self.element_names:
            raise KeyError("%s: no element variable '%s' (has %s)" % (self.path, name, self.element_names))
        i = self.element_names.index(name) + 1
        parts = []
        for b in range(1, self.num_blocks + 1):
            var = "vals_elem_var%deb%d" % (i, b)
            if var in self.ds.variables:
                parts.append(np.array(self.ds.variables[var][step, :]))
        return np.concatenate(parts)

    def global_var(self, name, step=-1):
        if name not in self.global_names:
            raise KeyError("%s: no global variable '%s' (has %s)" % (self.path, name, self.global_names))
        return float(self.ds.variables["vals_glo_var"][step, self.global_names.index(name)])

    def node_blocks(self):
        """Per node, the 1-based index of the (last) block whose elements use it; 0 for a node
        of no element. Bodies in contact have their own nodes at the same coordinates: key a
        node by (block, coordinates) to match it across two meshes."""
        blocks = np.zeros(self.ds.dimensions["num_nodes"].size, dtype=int)
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
