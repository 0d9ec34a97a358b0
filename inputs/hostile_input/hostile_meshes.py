"""Write the meshes of the hostile-input cases: copies of a valid Exodus mesh with one defect
each, or a small mesh written here.

    hostile_meshes.py <source.exo> <target> <defect>

Defects:
  repeated_variable_name  one bit of the variable name side_ss2 flipped: two variables side_ss3
  unwritten_nodes         netCDF-4 copy declaring 20 000 000 nodes whose coordinates were never
                          written (HDF5 returns fill values), 200 kB of stored random bytes beside
                          them so that the file is large enough for the reader's size bound
  block_id_2_32           netCDF-4 copy, 64-bit ids, element block id 2^32 + 1
  empty_block             a second element block without elements (Exodus type NULL)
  huge_coordinate         node 1: x = 1e300
  copy                    the source unchanged (under another name)
  folding_quad            (no source: pass -) one QUAD4 on the unit square, node sets held_nodes
                          (nodes 1, 2, 4) and corner_nodes (node 3)
  mass_inverted_hex       (no source: pass -) one HEX8, det J > 0 at the stiffness's 2x2x2 Gauss
                          points and < 0 at a point of the mass matrix's 3x3x3 rule
"""
import shutil
import sys

import netCDF4
import numpy as np


def copy_dataset(source, target, fmt, dims=None, skip=(), types=None, attrs=None, extra=None):
    """Copy an Exodus file into format fmt with dimension sizes `dims` overridden, the values
    of the variables in `skip` not written, `types` overriding variable types and `extra`
    (name -> (dims, values, dtype)) appended; `attrs` overrides global attributes."""
    dims, types, attrs, extra = dims or {}, types or {}, attrs or {}, extra or {}
    with netCDF4.Dataset(source) as src, netCDF4.Dataset(target, "w", format=fmt) as dst:
        src.set_auto_mask(False)
        for name in src.ncattrs():
            dst.setncattr(name, attrs.get(name, src.getncattr(name)))
        for name, dim in src.dimensions.items():
            dst.createDimension(name, None if dim.isunlimited() else dims.get(name, len(dim)))
        for name, var in src.variables.items():
            out = dst.createVariable(name, types.get(name, var.datatype), var.dimensions)
            out.set_auto_mask(False)
            for a in var.ncattrs():
                out.setncattr(a, var.getncattr(a))
            if name not in skip and var.size > 0:
                out[:] = var[:]
        for name, (shape, values, dtype) in extra.items():
            for k, n in enumerate(shape):
                dst.createDimension(f"{name}_{k}", n)
            out = dst.createVariable(name, dtype, tuple(f"{name}_{k}" for k in range(len(shape))))
            out[:] = values


def hex_inverted_at_mass_points():
    """Unit cube with node 7 (1, 1, 1) moved along the diagonal towards node 1 past the centre,
    by the first amount that makes det J negative at a 3x3x3 Gauss point while it stays
    positive at the 2x2x2 ones (det J of a trilinear hex: Hughes, eq. 3.2.21)."""
    corners = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                        [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], dtype=float)
    signs = 2 * corners - 1

    def det_min(X, points):
        worst = np.inf
        for xi in points:
            dN = np.array([[s[0] * (1 + s[1] * xi[1]) * (1 + s[2] * xi[2]),
                            s[1] * (1 + s[0] * xi[0]) * (1 + s[2] * xi[2]),
                            s[2] * (1 + s[0] * xi[0]) * (1 + s[1] * xi[1])] for s in signs]) / 8
            worst = min(worst, np.linalg.det(X.T @ dN))
        return worst

    g2 = [np.array(p) for p in np.array(np.meshgrid(*[[-1, 1]] * 3)).T.reshape(-1, 3) / np.sqrt(3)]
    g3 = [np.array(p) for p in np.array(np.meshgrid(*[[-1, 0, 1]] * 3)).T.reshape(-1, 3)
          * np.sqrt(0.6)]
    for s in np.linspace(0.0, 2.0, 2001):
        X = corners.copy()
        X[6] = corners[6] - s * np.ones(3)
        if det_min(X, g2) > 1e-3 and det_min(X, g3) < -1e-3:
            return X
    raise SystemExit("hostile_meshes.py: no hex inverted only at the 3x3x3 points")


def main():
    source, target, defect = sys.argv[1:4]
    if defect == "repeated_variable_name":
        data = bytearray(open(source, "rb").read())
        at = data.find(b"\x00\x00\x00\x08side_ss2")  # the variable's name (length 8)
        assert at > 0, "no variable side_ss2"
        data[at + 11] ^= 0x01  # '2' -> '3'
        open(target, "wb").write(bytes(data))
    elif defect == "unwritten_nodes":
        padding = np.random.default_rng(1).integers(0, 256, 200_000, dtype=np.uint8)
        copy_dataset(source, target, "NETCDF4", dims={"num_nodes": 20_000_000},
                     skip={"coordx", "coordy", "coordz"},
                     extra={"padding": ((padding.size,), padding, "u1")})
    elif defect == "block_id_2_32":
        copy_dataset(source, target, "NETCDF4", types={"eb_prop1": "i8"},
                     attrs={"int64_status": np.int32(2)})  # EX_IDS_INT64_DB
        with netCDF4.Dataset(target, "r+") as ds:
            ds.variables["eb_prop1"][0] = 2**32 + 1
    elif defect == "empty_block":
        copy_dataset(source, target, "NETCDF3_64BIT_OFFSET", dims={"num_el_blk": 2},
                     skip={"eb_status", "eb_prop1", "eb_names"})
        with netCDF4.Dataset(source) as src, netCDF4.Dataset(target, "r+") as ds:
            ds.variables["eb_status"][:] = [1, 0]
            ds.variables["eb_prop1"][:] = [1, 2]
            names = np.zeros((2, len(ds.dimensions["len_name"])), dtype="S1")
            names[0] = src.variables["eb_names"][0]
            names[1, :5] = list("empty")
            ds.variables["eb_names"][:] = names
    elif defect == "huge_coordinate":
        shutil.copyfile(source, target)
        with netCDF4.Dataset(target, "r+") as ds:
            ds.variables["coordx"][0] = 1e300
    elif defect == "copy":
        shutil.copyfile(source, target)
    elif defect == "folding_quad":
        sys.path.insert(0, __file__.rsplit("/", 3)[0] + "/tools")
        import exodus_mesh

        mesh = exodus_mesh.Mesh([[0, 0], [1, 0], [1, 1], [0, 1]])
        mesh.blocks.append(("block", "QUAD4", np.arange(4, dtype=np.int64).reshape(1, 4)))
        mesh.node_sets["held_nodes"] = np.array([0, 1, 3])
        mesh.node_sets["corner_nodes"] = np.array([2])
        exodus_mesh.write_exodus(mesh, target)
    elif defect == "mass_inverted_hex":
        sys.path.insert(0, __file__.rsplit("/", 3)[0] + "/tools")
        import exodus_mesh

        mesh = exodus_mesh.Mesh(hex_inverted_at_mass_points())
        mesh.blocks.append(("block", "HEX8", np.arange(8, dtype=np.int64).reshape(1, 8)))
        mesh.node_sets["base_nodes"] = np.array([0, 1, 2, 3])
        exodus_mesh.write_exodus(mesh, target)
    else:
        raise SystemExit(f"hostile_meshes.py: unknown defect {defect}")


if __name__ == "__main__":
    main()
