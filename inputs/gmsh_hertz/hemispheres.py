#!/usr/bin/python3
"""Two hemispheres touching at one point, quarter model, meshed by gmsh (TET4, graded towards
the contact point), written as Exodus.

Usage: hemispheres.py OUTPUT.exo [--radius R] [--contact-size H] [--far-size H]
                       [--fine-within D0] [--grade-to D1]

Lower: ball of radius R (default 1) centred at (0, 0, 0), z >= 0, flat face z = 0
("lower_bottom"), spherical face "lower_contact". Upper: centred at (0, 0, 2R), z <= 2R, flat
face z = 2R ("upper_top"), spherical face "upper_contact". Both apexes at (0, 0, R). Quarter
x >= 0, y >= 0: symmetry faces "x0" (x = 0) and "y0" (y = 0) of both bodies. Element size H
(default 0.03) within distance D0 (default 0.25 R) of the apex, growing linearly to the far
size (default 0.3) at distance D1 (default R); with --rim-size H2 the flat faces' curved
edges are meshed at H2, growing to the far size over a distance of the far size (a load on
the flat face then sums to q pi R^2 / 4 within the polygon's area deficit (H2/R)^2/6: each
chord of angle H2/R misses (H2/R)^3 R^2 / 12, and the quarter circle has (pi/2)/(H2/R) of
them). Blocks "lower", "upper".
"""
import argparse
import os
import sys

import gmsh

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from exodus_mesh import MeshError, write_exodus  # noqa: E402
from gmsh_to_exodus import model_to_mesh  # noqa: E402

def quarter_hemisphere(R, zc, up):
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


def rim_arcs(flat_faces):
    """The curved edges of the flat faces (the quarter circles; the other edges are straight,
    on x = 0 or y = 0)."""
    arcs = []
    for _, c in gmsh.model.getBoundary([(2, s) for s in flat_faces], oriented=False):
        xmin, ymin, _, xmax, ymax, _ = gmsh.model.getBoundingBox(1, c)
        if xmax - xmin > 1e-5 and ymax - ymin > 1e-5:
            arcs.append(c)
    return arcs


def build(R, h_contact, h_far, d_fine, d_grade, h_rim):
    lower = quarter_hemisphere(R, 0.0, True)
    upper = quarter_hemisphere(R, 2 * R, False)
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
    f.setNumber(thr, "DistMin", d_fine)
    f.setNumber(thr, "DistMax", d_grade)
    if h_rim:
        rim = f.add("Distance")
        f.setNumbers(rim, "CurvesList", rim_arcs(lf + uf))
        f.setNumber(rim, "NumPointsPerCurve", 200)
        rim_thr = f.add("Threshold")
        f.setNumber(rim_thr, "InField", rim)
        f.setNumber(rim_thr, "SizeMin", h_rim)
        f.setNumber(rim_thr, "SizeMax", h_far)
        f.setNumber(rim_thr, "DistMin", 0.0)
        f.setNumber(rim_thr, "DistMax", h_far)
        both = f.add("Min")
        f.setNumbers(both, "FieldsList", [thr, rim_thr])
        thr = both
    f.setAsBackgroundMesh(thr)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    gmsh.model.mesh.generate(3)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output")
    ap.add_argument("--radius", type=float, default=1.0)
    ap.add_argument("--contact-size", type=float, default=0.03)
    ap.add_argument("--far-size", type=float, default=0.3)
    ap.add_argument("--fine-within", type=float, help="default 0.25 R")
    ap.add_argument("--grade-to", type=float, help="default R")
    ap.add_argument("--rim-size", type=float, help="element size on the flat faces' curved "
                    "edges (default: the far size)")
    a = ap.parse_args()
    d_fine = 0.25 * a.radius if a.fine_within is None else a.fine_within
    d_grade = a.radius if a.grade_to is None else a.grade_to
    if not (a.radius > 0 and 0 < a.contact_size <= a.far_size and 0 < d_fine < d_grade):
        print("hemispheres.py: error: need --radius > 0, 0 < --contact-size <= --far-size and "
              "0 < --fine-within < --grade-to", file=sys.stderr)
        return 2
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("hemispheres")
        build(a.radius, a.contact_size, a.far_size, d_fine, d_grade, a.rim_size)
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
