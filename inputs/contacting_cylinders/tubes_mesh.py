#!/usr/bin/python3
"""The vertical set-up of the contacting cylinders (docs/verification.md #17) meshed by gmsh
(TET4) at a chosen size, for a refinement study of Kratos' geometry: two half-tubes (Kratos'
meshes are hollow, README.md), written as Exodus with the names cylinders_mesh.py gives
Kratos' mesh.

Usage: tubes_mesh.py OUTPUT.exo [--size H] [--contact-size HC] [--upper-y Y] [--msh OUTPUT.msh]

--upper-y: the upper axis at (0.04, Y) (default 0.31, Kratos' start; 0.2975: Kratos' vertical
motion at t = 0.125, the rigid gap 1.3e-4).
Lower half-tube: axis = the z axis, radii 0.13-0.17, z in [0, 0.17], y >= 0; its flat faces
y = 0 are "base_cylinders". Upper half-tube: axis (0.04, 0.31), radii 0.09-0.13, z in
[0.04, 0.15], y <= 0.31; its flat faces y = 0.31 are "top_cylinders". Outer curved faces:
"slave_cylinders" (upper), "master_cylinders" (lower); block "cylinders" (both bodies); node
sets "<side set>_nodes". Element size H (default 0.02, about Kratos' mesh), HC (default H)
within 0.01 of the line where the outer surfaces meet (their common normal, from the lower
axis towards the upper), growing to H at 0.05.
"""
import argparse
import math
import os
import sys

import gmsh

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from exodus_mesh import MeshError, write_exodus  # noqa: E402
from gmsh_to_exodus import model_to_mesh  # noqa: E402

LOWER = {"c": (0.0, 0.0), "r": (0.13, 0.17), "z": (0.0, 0.17), "up": True}
UPPER = {"c": (0.04, 0.31), "r": (0.09, 0.13), "z": (0.04, 0.15), "up": False}


def half_tube(t):
    """Volume tag of the half-tube t (y >= axis: up; y <= axis: down)."""
    occ = gmsh.model.occ
    (cx, cy), (ri, ro), (z0, z1) = t["c"], t["r"], t["z"]
    outer = occ.addCylinder(cx, cy, z0, 0, 0, z1 - z0, ro)
    inner = occ.addCylinder(cx, cy, z0, 0, 0, z1 - z0, ri)
    tube, _ = occ.cut([(3, outer)], [(3, inner)])
    box = occ.addBox(cx - ro, cy if t["up"] else cy - ro, z0, 2 * ro, ro, z1 - z0)
    out, _ = occ.intersect(tube, [(3, box)])
    return out[0][1]


def classify(volume, t):
    """(flat, outer) surface tags of a half-tube: the flat faces y = axis, the outer curved face
    (OCC splits it in two at its seam): the curved faces that reach the outer radius (the end
    faces z = const are flat)."""
    cy, ro = t["c"][1], t["r"][1]
    flat, outer = [], []
    for _, s in gmsh.model.getBoundary([(3, volume)], oriented=False):
        xmin, ymin, zmin, xmax, ymax, zmax = gmsh.model.getBoundingBox(2, s)
        if abs(ymax - ymin) < 1e-6 and abs(ymin - cy) < 1e-6:
            flat.append(s)
        elif zmax - zmin > 1e-6 and (ymax > cy + ro - 1e-6 if t["up"] else ymin < cy - ro + 1e-6):
            outer.append(s)
    return flat, outer


def build(h, hc, upper_y):
    UPPER["c"] = (UPPER["c"][0], upper_y)
    lower, upper = half_tube(LOWER), half_tube(UPPER)
    gmsh.model.occ.synchronize()
    lf, lo = classify(lower, LOWER)
    uf, uo = classify(upper, UPPER)
    for dim, tags, name in [(3, [lower, upper], "cylinders"), (2, lf, "base_cylinders"),
                            (2, uf, "top_cylinders"), (2, uo, "slave_cylinders"),
                            (2, lo, "master_cylinders")]:
        if not tags:
            raise MeshError("tubes_mesh: no entity for '%s'" % name)
        gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), name)
    # Where the outer surfaces meet: on the line of the axes, 0.17 from the lower axis.
    cx, cy = UPPER["c"]
    d = math.hypot(cx, cy)
    xc, yc = 0.17 * cx / d, 0.17 * cy / d
    f = gmsh.model.mesh.field
    m = f.add("MathEval")
    f.setString(m, "F", "Min(%.17g, Max(%.17g, %.17g + (Sqrt((x - %.17g)^2 + (y - %.17g)^2) - 0.01)"
                " * %.17g))" % (h, hc, hc, xc, yc, (h - hc) / 0.04))
    f.setAsBackgroundMesh(m)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    gmsh.model.mesh.generate(3)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output")
    ap.add_argument("--size", type=float, default=0.02)
    ap.add_argument("--contact-size", type=float)
    ap.add_argument("--upper-y", type=float, default=0.31)
    ap.add_argument("--msh")
    a = ap.parse_args()
    hc = a.size if a.contact_size is None else a.contact_size
    if not (a.size > 0 and 0 < hc <= a.size):
        print("tubes_mesh.py: error: need --size > 0 and 0 < --contact-size <= --size",
              file=sys.stderr)
        return 2
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("tubes")
        build(a.size, hc, a.upper_y)
        if a.msh:
            gmsh.write(a.msh)
        mesh = model_to_mesh("tubes")
    except MeshError as e:
        print("tubes_mesh.py: error: %s" % e, file=sys.stderr)
        return 2
    finally:
        gmsh.finalize()
    write_exodus(mesh, a.output, title="gmsh half-tubes, size %g, contact size %g, upper axis "
                 "y = %g" % (a.size, hc, a.upper_y))
    n_tets = sum(len(c) for _, t, c in mesh.blocks if t == "TETRA4")
    print("tubes_mesh.py: %s: %d nodes, %d tetrahedra" % (a.output, len(mesh.coords), n_tets))
    return 0


if __name__ == "__main__":
    sys.exit(main())
