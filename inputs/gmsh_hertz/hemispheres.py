#!/usr/bin/python3
"""Two hemispheres touching at one point, quarter model, meshed by gmsh (TET4, graded towards
the contact point), written as Exodus.

Usage: hemispheres.py OUTPUT.exo [--contact-size H] [--far-size H]

Lower: ball of radius R = 1 centred at (0, 0, 0), z >= 0, flat face z = 0 ("lower_bottom"),
spherical face "lower_contact". Upper: centred at (0, 0, 2), z <= 2, flat face z = 2
("upper_top"), spherical face "upper_contact". Both apexes at (0, 0, 1). Quarter x >= 0,
y >= 0: symmetry faces "x0" (x = 0) and "y0" (y = 0) of both bodies. Element size H (default
0.03) within distance 0.25 of the apex, growing linearly to the far size (default 0.3) at
distance 1. Blocks "lower", "upper".
"""
import argparse
import os
import sys

import gmsh

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from exodus_mesh import MeshError, write_exodus  # noqa: E402
from gmsh_to_exodus import model_to_mesh  # noqa: E402

R = 1.0


def quarter_hemisphere(zc, up):
    """Volume tag of the quarter ball of centre (0, 0, zc) with z >= zc (up) or z <= zc."""
    occ = gmsh.model.occ
    ball = occ.addSphere(0, 0, zc, R)
    box = occ.addBox(0, 0, zc if up else zc - R, R, R, R)
    out, _ = occ.intersect([(3, ball)], [(3, box)])
    return out[0][1]


def classify(volume, zc, up):
    """(flat, spherical, x0, y0) surface tags of a quarter hemisphere."""
    flat, sphere, x0, y0 = [], [], [], []
    for _, s in gmsh.model.getBoundary([(3, volume)], oriented=False):
        xmin, ymin, zmin, xmax, ymax, zmax = gmsh.model.getBoundingBox(2, s)
        if abs(zmax - zmin) < 1e-5 and abs(zmin - zc) < 1e-5:
            flat.append(s)
        elif abs(xmax - xmin) < 1e-5 and abs(xmin) < 1e-5:
            x0.append(s)
        elif abs(ymax - ymin) < 1e-5 and abs(ymin) < 1e-5:
            y0.append(s)
        else:
            sphere.append(s)
    return flat, sphere, x0, y0


def build(h_contact, h_far):
    lower = quarter_hemisphere(0.0, True)
    upper = quarter_hemisphere(2 * R, False)
    gmsh.model.occ.synchronize()
    lf, ls, lx, ly = classify(lower, 0.0, True)
    uf, us, ux, uy = classify(upper, 2 * R, False)
    for dim, tags, name in [(3, [lower], "lower"), (3, [upper], "upper"),
                            (2, lf, "lower_bottom"), (2, uf, "upper_top"),
                            (2, ls, "lower_contact"), (2, us, "upper_contact"),
                            (2, lx + ux, "x0"), (2, ly + uy, "y0")]:
        if not tags:
            raise MeshError("hemispheres: no surface for '%s'" % name)
        gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), name)
    apexes = [t for _, t in gmsh.model.getEntitiesInBoundingBox(-1e-6, -1e-6, R - 1e-6, 1e-6,
                                                                   1e-6, R + 1e-6, 0)]
    f = gmsh.model.mesh.field
    dist = f.add("Distance")
    f.setNumbers(dist, "NodesList", apexes)
    thr = f.add("Threshold")
    f.setNumber(thr, "InField", dist)
    f.setNumber(thr, "SizeMin", h_contact)
    f.setNumber(thr, "SizeMax", h_far)
    f.setNumber(thr, "DistMin", 0.25 * R)
    f.setNumber(thr, "DistMax", R)
    f.setAsBackgroundMesh(thr)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    gmsh.model.mesh.generate(3)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output")
    ap.add_argument("--contact-size", type=float, default=0.03)
    ap.add_argument("--far-size", type=float, default=0.3)
    a = ap.parse_args()
    if not (a.contact_size > 0 and a.far_size >= a.contact_size):
        print("hemispheres.py: error: need 0 < --contact-size <= --far-size", file=sys.stderr)
        return 2
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("hemispheres")
        build(a.contact_size, a.far_size)
        mesh = model_to_mesh("hemispheres")
    except MeshError as e:
        print("hemispheres.py: error: %s" % e, file=sys.stderr)
        return 2
    finally:
        gmsh.finalize()
    write_exodus(mesh, a.output, title="gmsh hemispheres, contact size %g" % a.contact_size)
    print("hemispheres.py: %s: %d nodes, %d tets" % (a.output, len(mesh.coords),
                                                   sum(len(c) for _, _, c in mesh.blocks)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
