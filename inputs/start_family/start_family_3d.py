"""The 3D members of the start family (start_family.py): point contact of spheres, quarter
models meshed by gmsh (TET4), load-controlled from first touch.

Each variant is an upper quarter hemisphere (radius R1, centre (0, 0, zc), zc = top + R1 + gap,
z <= zc, flat face z = zc on top) pressed by a uniform pressure p on that flat face, which is
held in x and y, onto a lower quarter hemisphere (R2, centre (0, 0, 0), flat face z = 0 fixed;
top = R2), a block ([0, 1.5 R1]^2 x [-R1, 0], bottom fixed; top = 0) or a rigid plane (the same
block with every node held). Symmetry planes x = 0 and y = 0 (faces "x0", "y0" of both bodies).
The bodies touch at one point (a node of each at (0, 0, top)) or are a small gap apart. The
upper body is held in z only by the contact (its rotations by the symmetry planes and the
support in x and y).

Hertz (Johnson, Contact Mechanics 1985, §4.2, eqs. 4.22-4.23), for the total force F on the
full model (4 x the quarter's load p A, A the area of the meshed quarter flat face):
    a = (3 F R*/(4 E*))^(1/3),  p0 = 3 F/(2 pi a^2),  1/R* = 1/R1 + 1/R2 (block: R* = R1),
    1/E* = (1 - nu^2)/E + (1 - nu^2)/E2 (E2 = E; rigid plane: 1/E* = (1 - nu^2)/E).
Computed a and p0: the least-squares fit of p^2 = p0^2 (1 - r^2/a^2) to the slave nodes with
p > 0 (nodal contact_pressure at the reference r = sqrt(x^2 + y^2)), as
inputs/gmsh_hertz/check_3d.py.
"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
sys.path.insert(0, os.path.join(HERE, "..", "gmsh_hertz"))
sys.path.insert(0, os.path.join(HERE, "..", "sphere_plane"))

E = 200.0

# A 3D variant: lower = sphere | block | rigid;  n_a: elements across the Hertz contact radius
# a at the contact; grading: the growth length of the element size away from the contact, in
# units of R1; the rest as the 2D variants (start_family.DEFAULT).
DEFAULT_3D = dict(dim=3, mesher="gmsh_tet", lower="sphere", r1=1.0, r2=1.0, e_over_p=1e3,
                  nu=0.3, n_a=8, grading=0.5, steps=2, swap=False, gap=0.0, ranks=1)

# Names: blocks, the upper flat face (pressure, held in x and y), the node set of the lower
# support (held in x, y, z), the contact side sets.
NAMES_3D = dict(upper="upper", lower="lower", top="upper_top", support="lower_bottom_nodes",
                upper_contact="upper_contact", lower_contact="lower_contact")


def hertz_3d(v, area):
    """(F, a, p0, p) of a variant whose meshed quarter flat face has the area `area`:
    p = E / e_over_p, F = 4 p area (the full model's force)."""
    p = E / v["e_over_p"]
    F = 4 * p * area
    inv_r = 1 / v["r1"] + (1 / v["r2"] if v["lower"] == "sphere" else 0.0)
    k = (1 - v["nu"] ** 2) / E
    inv_e = k if v["lower"] == "rigid" else 2 * k
    a = (3 * F / inv_r * inv_e / 4) ** (1.0 / 3.0)
    return F, a, 3 * F / (2 * math.pi * a * a), p


def nominal_a(v):
    """Hertz a for the exact quarter disc area pi R1^2 / 4 (the mesh size is set from it)."""
    return hertz_3d(v, math.pi * v["r1"] ** 2 / 4)[1]


def faces_by_plane(volume, flat_z, zc):
    """(flat, curved-or-top, x0, y0) boundary surfaces of a quarter body: flat at z = flat_z;
    for a block (zc None) the second list is its top face z = 0."""
    import gmsh
    tol = 1e-5 * max(1.0, abs(flat_z))  # OCC bounding boxes are padded
    flat, other, x0, y0 = [], [], [], []
    for _, s in gmsh.model.getBoundary([(3, volume)], oriented=False):
        xmin, ymin, zmin, xmax, ymax, zmax = gmsh.model.getBoundingBox(2, s)
        if abs(zmax - zmin) < tol and abs(zmin - flat_z) < tol:
            flat.append(s)
        elif abs(xmax - xmin) < tol and abs(xmin) < tol:
            x0.append(s)
        elif abs(ymax - ymin) < tol and abs(ymin) < tol:
            y0.append(s)
        elif zc is not None or (abs(zmax - zmin) < tol and abs(zmax) < tol):
            other.append(s)
    return flat, other, x0, y0


def flat_area(surfaces):
    """Area of the meshed (polygonal) surfaces: the sum of their triangles."""
    import gmsh
    area = 0.0
    for s in surfaces:
        types, _, nodes = gmsh.model.mesh.getElements(2, s)
        for t, n in zip(types, nodes):
            for tri in np.asarray(n, dtype=np.int64).reshape(-1, 3):
                p = [np.array(gmsh.model.mesh.getNode(int(k))[0]) for k in tri]
                area += 0.5 * np.linalg.norm(np.cross(p[1] - p[0], p[2] - p[0]))
    return area


def gmsh_mesh_3d(v, path, h):
    """Mesh of a 3D variant (TET4), graded from h at the contact point; returns (nodes, area
    of the quarter flat face that carries the load)."""
    import gmsh
    from exodus_mesh import MeshError, write_exodus
    from gmsh_to_exodus import model_to_mesh
    from hemispheres import quarter_hemisphere

    r1, r2 = v["r1"], v["r2"]
    top = r2 if v["lower"] == "sphere" else 0.0
    zc = top + r1 + v["gap"] * h
    a = nominal_a(v)
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("start3d")
        occ = gmsh.model.occ
        upper = quarter_hemisphere(r1, zc, False)
        if v["lower"] == "sphere":
            lower = quarter_hemisphere(r2, 0.0, True)
        else:
            w = 1.5 * r1
            lower = occ.addBox(0, 0, -r1, w, w, r1)
        occ.synchronize()
        uf, us, ux, uy = faces_by_plane(upper, zc, zc)
        if v["lower"] == "sphere":
            lf, ls, lx, ly = faces_by_plane(lower, 0.0, 0.0)
        else:
            lf, ls, lx, ly = faces_by_plane(lower, -r1, None)
        for dim, tags, name in [(3, [lower], "lower"), (3, [upper], "upper"),
                                (2, lf, "lower_bottom"), (2, uf, "upper_top"),
                                (2, ls, "lower_contact"), (2, us, "upper_contact"),
                                (2, ux + lx, "x0"), (2, uy + ly, "y0")]:
            if not tags:
                raise MeshError("start_family_3d: no surface for '%s'" % name)
            gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), name)
        eps = 1e-6 * r1
        points = [t for _, t in gmsh.model.getEntitiesInBoundingBox(
            -eps, -eps, top - eps, eps, eps, zc + eps, 0)]
        f = gmsh.model.mesh.field
        dist = f.add("Distance")
        f.setNumbers(dist, "NodesList", points)
        # Per body: h within 1.3 a of the contact point, growing over grading x R1 to a fifth
        # of the body's own size (R1, R2, or the block's 1.5 R1), restricted to that body.
        restricted = []
        for volume, size in [(upper, r1), (lower, r2 if v["lower"] == "sphere" else 1.5 * r1)]:
            thr = f.add("Threshold")
            f.setNumber(thr, "InField", dist)
            f.setNumber(thr, "SizeMin", h)
            f.setNumber(thr, "SizeMax", max(0.2 * size, h))
            f.setNumber(thr, "DistMin", 1.3 * a)
            f.setNumber(thr, "DistMax", 1.3 * a + v["grading"] * r1)
            faces = [t for _, t in gmsh.model.getBoundary([(3, volume)], oriented=False)]
            curves = [t for _, t in gmsh.model.getBoundary([(2, t) for t in faces],
                                                           combined=False, oriented=False)]
            res = f.add("Restrict")
            f.setNumber(res, "InField", thr)
            f.setNumbers(res, "VolumesList", [volume])
            f.setNumbers(res, "SurfacesList", faces)
            f.setNumbers(res, "CurvesList", sorted(set(curves)))
            restricted.append(res)
        both = f.add("Min")
        f.setNumbers(both, "FieldsList", restricted)
        f.setAsBackgroundMesh(both)
        gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
        gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
        gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
        gmsh.model.mesh.generate(3)
        area = flat_area(uf)
        mesh = model_to_mesh("start_family " + v["name"])
    finally:
        gmsh.finalize()
    if v["lower"] == "rigid":  # every node of the plane held
        conn = [c for name, _, c in mesh.blocks if name == "lower"][0]
        mesh.node_sets["lower_all"] = sorted(set(int(k) for k in np.ravel(conn)))
    write_exodus(mesh, path, title="start_family " + v["name"])
    return len(mesh.coords), area


def write_input_3d(v, path, mesh_file, p):
    n = NAMES_3D
    slave, master = n["upper_contact"], n["lower_contact"]
    if v["swap"]:
        slave, master = master, slave
    support = "lower_all" if v["lower"] == "rigid" else n["support"]
    text = """# start_family variant %(name)s (start_family.py, start_family_3d.py): load-controlled
# point contact, quarter model.
grout:
  mesh: {file: %(mesh)s}
  model: {dimension: 3, strain: small}
  materials:
    upper: {block: upper, law: linear_elastic, youngs_modulus: %(E)r, poissons_ratio: %(nu)r}
    lower: {block: lower, law: linear_elastic, youngs_modulus: %(E)r, poissons_ratio: %(nu)r}
  dirichlet:
    top_x: {node_set: upper_top_nodes, component: x, value: "0"}
    top_y: {node_set: upper_top_nodes, component: y, value: "0"}
    bottom_x: {node_set: %(support)s, component: x, value: "0"}
    bottom_y: {node_set: %(support)s, component: y, value: "0"}
    bottom_z: {node_set: %(support)s, component: z, value: "0"}
    sym_x: {node_set: x0_nodes, component: x, value: "0"}
    sym_y: {node_set: y0_nodes, component: y, value: "0"}
  loads:
    load: {side_set: upper_top, type: pressure, value: "%(p)r*t"}
  contact:
    interface: {slave: %(slave)s, master: %(master)s, type: frictionless}
  time: {end: 1.0, steps: %(steps)d}
  output: {file: result.e}
""" % dict(name=v["name"], mesh=mesh_file, E=E, nu=v["nu"], p=p, slave=slave, master=master,
           steps=v["steps"], support=support)
    with open(path, "w") as f:
        f.write(text)
    return slave, support


def fit_hertz(r, p):
    """(a, p0) of p^2 = p0^2 (1 - r^2/a^2) fitted to the nodes with p > 0 (least squares)."""
    on = p > 0
    A = np.vstack([np.ones(on.sum()), r[on] ** 2]).T
    c, _, _, _ = np.linalg.lstsq(A, p[on] ** 2, rcond=None)
    if not (c[0] > 0 and c[1] < 0):
        return float("nan"), float("nan")
    return math.sqrt(-c[0] / c[1]), math.sqrt(c[0])


def check_3d(v, result, slave, support, area):
    """(ok, message): a and p0 within tol of Hertz, the support reaction = the load to 1e-6."""
    import contact_check as cc
    from grout_results import Results

    F, a_h, p0_h, p = hertz_3d(v, area)
    res = Results(result)
    s = cc.side_set_nodes(res, slave)
    xyz = res.coordinates()
    r = np.hypot(xyz[0, s], xyz[1, s])
    pc = res.nodal("contact_pressure")[s]
    a, p0 = fit_hertz(r, pc)
    reaction = 4 * abs(res.global_var("reaction_%s_z" % support))
    ea, ep = abs(a - a_h) / a_h, abs(p0 - p0_h) / p0_h
    em = abs(float(pc.max()) - p0_h) / p0_h
    return ea, ep, em, (reaction - F) / F, int((pc > 0).sum()), a, p0
