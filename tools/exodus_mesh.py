"""Plain mesh data and an Exodus II writer (netCDF classic layout, python3-netcdf4), shared by
tools/mdpa_to_exodus.py and the gmsh mesh scripts of inputs/.

A Mesh holds 0-based node coordinates (n, dim), named element blocks (topology QUAD4, TRI3,
TETRA4 or HEX8 and 0-based connectivity), named node sets (0-based node ids) and named side
sets ((element, side) pairs: 0-based global element index in block order, 1-based Exodus side
number, Sjaardema et al., SAND92-2137, fig. 4; the table below).
"""
import numpy as np

# Exodus local side -> 0-based local nodes (kernels/topology.hpp has the same tables).
SIDES = {
    "QUAD4": [(0, 1), (1, 2), (2, 3), (3, 0)],
    "TRI3": [(0, 1), (1, 2), (2, 0)],
    "TETRA4": [(0, 1, 3), (1, 2, 3), (0, 3, 2), (0, 2, 1)],
    "HEX8": [(0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (0, 4, 7, 3), (0, 3, 2, 1), (4, 5, 6, 7)],
}
DIMENSION = {"QUAD4": 2, "TRI3": 2, "TETRA4": 3, "HEX8": 3}
NODES = {"QUAD4": 4, "TRI3": 3, "TETRA4": 4, "HEX8": 8}


class MeshError(Exception):
    """Malformed or inconsistent mesh input; the message names the file and line or entity."""


class Mesh:
    def __init__(self, coords):
        self.coords = np.asarray(coords, dtype=float)
        self.blocks = []  # (name, topology, connectivity (n_e, n_per) int array)
        self.node_sets = {}  # name -> sorted int array
        self.side_sets = {}  # name -> list of (element, side)

    @property
    def dim(self):
        return self.coords.shape[1]

    def add_block(self, name, topology, conn):
        conn = np.asarray(conn, dtype=np.int64).reshape(-1, NODES[topology])
        self.blocks.append((name, topology, orient(self.coords, topology, conn)))

    def elements(self):
        """(global element index, topology, node tuple) over all blocks in order."""
        e = 0
        for _, topology, conn in self.blocks:
            for row in conn:
                yield e, topology, row
                e += 1

    def boundary_faces(self):
        """dict frozenset(face nodes) -> (element, side) for the faces of exactly one element."""
        seen = {}
        count = {}
        for e, topology, row in self.elements():
            for s, local in enumerate(SIDES[topology]):
                key = frozenset(int(row[i]) for i in local)
                count[key] = count.get(key, 0) + 1
                seen[key] = (e, s + 1)
        return {k: v for k, v in seen.items() if count[k] == 1}

    def block_of_element(self):
        names = []
        for name, _, conn in self.blocks:
            names += [name] * len(conn)
        return names

    def side_set_nodes(self, name):
        """Sorted nodes of the sides of side set `name`."""
        conn = {e: (t, row) for e, t, row in self.elements()}
        nodes = set()
        for e, side in self.side_sets[name]:
            t, row = conn[e]
            nodes.update(int(row[i]) for i in SIDES[t][side - 1])
        return np.array(sorted(nodes), dtype=np.int64)

    def add_side_set_node_sets(self):
        """A node set per side set (its nodes; written as <name>_nodes) where none has that name
        and <name>_nodes fits in the 32 characters of an Exodus name."""
        for name in self.side_sets:
            if name not in self.node_sets and len(name) + len("_nodes") <= 32:
                self.node_sets[name] = self.side_set_nodes(name)

    def drop_unused_nodes(self):
        """Removes nodes no element uses (renumbering the rest); returns how many."""
        used = np.zeros(len(self.coords), dtype=bool)
        for _, _, conn in self.blocks:
            used[conn.ravel()] = True
        new = -np.ones(len(self.coords), dtype=np.int64)
        new[used] = np.arange(used.sum())
        self.coords = self.coords[used]
        self.blocks = [(n, t, new[c]) for n, t, c in self.blocks]
        self.node_sets = {k: np.unique(new[v][new[v] >= 0]) for k, v in self.node_sets.items()}
        return int((~used).sum())


def extrude(mesh, thickness, layers):
    """3D mesh of a 2D QUAD4 mesh swept along z over [0, thickness] in `layers` equal layers:
    each quad (a, b, c, d) of layer k gives the HEX8 (a, b, c, d) at z_k and (a, b, c, d) at
    z_{k+1} (positive volume: the quads are counter-clockwise, orient()). Blocks keep their
    names; a 2D side set becomes the side set of the swept faces (same name); a 2D node set
    becomes its nodes on every layer (same name); node set "z_faces" holds the nodes on
    z = 0 and z = thickness, "z0_nodes" those on z = 0 (a plane of symmetry, say) and
    "zt_nodes" those on z = thickness."""
    if mesh.dim != 2:
        raise MeshError("extrude: the mesh is %dD (need 2D)" % mesh.dim)
    if not (thickness > 0 and layers >= 1):
        raise MeshError("extrude: need thickness > 0 and layers >= 1")
    n = len(mesh.coords)
    z = np.linspace(0.0, thickness, layers + 1)
    coords = np.vstack([np.column_stack([mesh.coords, np.full(n, zk)]) for zk in z])
    out = Mesh(coords)
    for name, topology, conn in mesh.blocks:
        if topology != "QUAD4":
            raise MeshError("extrude: block '%s' is %s (need QUAD4)" % (name, topology))
        out.add_block(name, "HEX8", np.vstack([np.hstack([conn + k * n, conn + (k + 1) * n])
                                               for k in range(layers)]))
    conn2d = {e: (t, row) for e, t, row in mesh.elements()}
    faces = out.boundary_faces()
    for name, sides in mesh.side_sets.items():
        swept = []
        for e, side in sides:
            t, row = conn2d[e]
            a, b = (int(row[i]) for i in SIDES[t][side - 1])
            for k in range(layers):
                swept.append(faces[frozenset((a + k * n, b + k * n, a + (k + 1) * n,
                                              b + (k + 1) * n))])
        out.side_sets[name] = sorted(swept)
    for name, nodes in mesh.node_sets.items():
        out.node_sets[name] = np.concatenate([np.asarray(nodes) + k * n for k in range(layers + 1)])
    out.node_sets["z_faces"] = np.concatenate([np.arange(n), np.arange(n) + layers * n])
    out.node_sets["z0_nodes"] = np.arange(n)
    out.node_sets["zt_nodes"] = np.arange(n) + layers * n
    return out


def orient(coords, topology, conn):
    """Reorders elements of negative measure (clockwise 2D, inverted 3D) to positive."""
    conn = conn.copy()
    x = coords
    if topology in ("QUAD4", "TRI3"):
        p = x[conn]  # (n_e, k, dim)
        area = 0.5 * np.sum(p[:, :, 0] * np.roll(p[:, :, 1], -1, axis=1)
                            - np.roll(p[:, :, 0], -1, axis=1) * p[:, :, 1], axis=1)
        flip = area < 0
        conn[flip] = conn[flip][:, ::-1]
    elif topology == "TETRA4":
        p = x[conn]
        vol = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0])
        flip = vol < 0
        conn[flip] = conn[flip][:, [0, 2, 1, 3]]
    return conn


def name_node_sets_apart(mesh):
    """A node set named like a side set becomes <name>_nodes (grout_mesh's rule: ParaView's
    IOSS reader mixes up the data of a node set and a side set of the same name). Where that
    is longer than the 32 characters of an Exodus name, <name> is cut to 26 characters
    (Kratos' contact parts: contact_contact_master_auto1 -> contact_contact_master_aut_nodes)."""
    for name in [n for n in mesh.node_sets if n in mesh.side_sets]:
        new = name[:32 - len("_nodes")] + "_nodes"
        if new in mesh.node_sets:
            raise MeshError("node sets '%s' and '%s' would get the same name" % (name, new))
        mesh.node_sets[new] = mesh.node_sets.pop(name)


def write_exodus(mesh, path, title="grout mesh"):
    """Writes mesh as an Exodus II file (netCDF classic, 64-bit offsets, 1-based ids); node sets
    named like a side set are renamed <name>_nodes first (name_node_sets_apart)."""
    import netCDF4

    name_node_sets_apart(mesh)
    # netCDF classic takes a dimension of length 0 for the unlimited one ("NC_UNLIMITED size
    # already in use"), and grout refuses empty sets anyway: name the entity instead.
    for kind, entities in (("element block", {b[0]: b[2] for b in mesh.blocks}),
                           ("node set", mesh.node_sets), ("side set", mesh.side_sets)):
        for name, items in entities.items():
            if len(items) == 0:
                raise MeshError("%s: %s '%s' would be empty (no %s)" % (
                    path, kind, name, "elements" if kind == "element block" else kind[:4] + "s"))
    try:
        netCDF4.Dataset(path, "w", format="NETCDF3_64BIT_OFFSET").close()
    except (OSError, RuntimeError) as e:
        raise MeshError("%s: cannot write (%s)" % (path, e))

    def names_var(ds, var, dim, names):
        v = ds.createVariable(var, "S1", (dim, "len_name"))
        v.set_auto_mask(False)
        arr = np.zeros((len(names), 33), dtype="S1")
        for k, n in enumerate(names):
            if len(n) > 32:
                raise MeshError("name '%s' is longer than 32 characters" % n)
            arr[k, :len(n)] = np.array(list(n), dtype="S1")
        v[:] = arr

    with netCDF4.Dataset(path, "w", format="NETCDF3_64BIT_OFFSET") as ds:
        ds.api_version = np.float32(8.0)
        ds.version = np.float32(8.0)
        ds.floating_point_word_size = np.int32(8)
        ds.file_size = np.int32(1)
        ds.maximum_name_length = np.int32(32)
        ds.int64_status = np.int32(0)
        ds.title = title
        n_elem = sum(len(c) for _, _, c in mesh.blocks)
        ds.createDimension("len_string", 33)
        ds.createDimension("len_line", 81)
        ds.createDimension("four", 4)
        ds.createDimension("len_name", 33)
        ds.createDimension("time_step", None)
        ds.createDimension("num_dim", mesh.dim)
        ds.createDimension("num_nodes", len(mesh.coords))
        ds.createDimension("num_elem", n_elem)
        ds.createDimension("num_el_blk", len(mesh.blocks))
        ds.createVariable("time_whole", "f8", ("time_step",))
        for d, axis in enumerate("xyz"[:mesh.dim]):
            ds.createVariable("coord" + axis, "f8", ("num_nodes",))[:] = mesh.coords[:, d]
        names_var(ds, "coor_names", "num_dim", ["x", "y", "z"][:mesh.dim])
        ds.createVariable("eb_status", "i4", ("num_el_blk",))[:] = 1
        prop = ds.createVariable("eb_prop1", "i4", ("num_el_blk",))
        prop.setncattr("name", "ID")
        prop[:] = np.arange(1, len(mesh.blocks) + 1)
        names_var(ds, "eb_names", "num_el_blk", [b[0] for b in mesh.blocks])
        for k, (_, topology, conn) in enumerate(mesh.blocks, start=1):
            ds.createDimension("num_el_in_blk%d" % k, len(conn))
            ds.createDimension("num_nod_per_el%d" % k, conn.shape[1])
            v = ds.createVariable("connect%d" % k, "i4", ("num_el_in_blk%d" % k,
                                                          "num_nod_per_el%d" % k))
            v.elem_type = topology
            v[:] = conn + 1
        if mesh.node_sets:
            names = sorted(mesh.node_sets)
            ds.createDimension("num_node_sets", len(names))
            ds.createVariable("ns_status", "i4", ("num_node_sets",))[:] = 1
            prop = ds.createVariable("ns_prop1", "i4", ("num_node_sets",))
            prop.setncattr("name", "ID")
            prop[:] = np.arange(1, len(names) + 1)
            names_var(ds, "ns_names", "num_node_sets", names)
            for k, n in enumerate(names, start=1):
                nodes = np.asarray(mesh.node_sets[n], dtype=np.int64)
                ds.createDimension("num_nod_ns%d" % k, len(nodes))
                ds.createVariable("node_ns%d" % k, "i4", ("num_nod_ns%d" % k,))[:] = nodes + 1
        if mesh.side_sets:
            names = sorted(mesh.side_sets)
            ds.createDimension("num_side_sets", len(names))
            ds.createVariable("ss_status", "i4", ("num_side_sets",))[:] = 1
            prop = ds.createVariable("ss_prop1", "i4", ("num_side_sets",))
            prop.setncattr("name", "ID")
            prop[:] = np.arange(1, len(names) + 1)
            names_var(ds, "ss_names", "num_side_sets", names)
            for k, n in enumerate(names, start=1):
                sides = sorted(mesh.side_sets[n])
                ds.createDimension("num_side_ss%d" % k, len(sides))
                ds.createVariable("elem_ss%d" % k, "i4", ("num_side_ss%d" % k,))[:] = \
                    [e + 1 for e, _ in sides]
                ds.createVariable("side_ss%d" % k, "i4", ("num_side_ss%d" % k,))[:] = \
                    [s for _, s in sides]
