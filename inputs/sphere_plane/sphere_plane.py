#!/usr/bin/python3
"""A hemisphere resting on a block, quarter model, meshed by gmsh (TET4, graded towards the
contact point), written as Exodus (docs/verification.md #11).

Usage: sphere_plane.py OUTPUT.exo [--radius R] [--contact-size H] [--far-size H]
                       [--fine-within D0] [--grade-to D1] [--rim-size H2]
                       [--block-width L] [--block-depth T]

Sphere: the half ball of radius R (default 6.1237) centred at (0, 0, R) with z <= R, so its
apex touches the block at the origin; flat face z = R ("sphere_top"), spherical face
"sphere_contact", block "sphere". Block: [0, L] x [0, L] x [-T, 0] (defaults L = 1.5 R,
T = R), top face z = 0 "plane_top", bottom z = -T "plane_bottom", block "plane". Quarter
x >= 0, y >= 0: symmetry faces "x0" (x = 0) and "y0" (y = 0) of both bodies. Element size H
(default 0.17) within distance D0 (default 0.3 R) of the contact point, growing linearly to
the far size (default 1.0) at distance D1 (default R); the flat face's curved edge is meshed
at H2 (default 0.2) so that a pressure on it sums to q pi R^2 / 4 within (H2/R)^2/6 (the
polygon's area deficit: chords of angle H2/R each miss (H2/R)^3 R^2 / 12).
The geometry helpers are ../gmsh_hertz/hemispheres.py's.
"""
import argparse
import os
import sys

import gmsh

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
sys.path.insert(0, os.path.join(HERE, "..", "gmsh_hertz"))
from exodus_mesh import MeshError, write_exodus  # noqa: E402
from gmsh_to_exodus import model_to_mesh  # noqa: E402
from hemispheres import classify, quarter_hemisphere, rim_arcs  # noqa: E402


def block_faces(volume, depth, width):
    """(top, bottom, x0, y0) surface tags of the box [0, L]^2 x [-T, 0]."""
    top, bottom, x0, y0 = [], [], [], []
    for _, s in gmsh.model.getBoundary([(3, volume)], oriented=False):
        xmin, ymin, zmin, xmax, ymax, zmax = gmsh.model.getBoundingBox(2, s)
        if abs(zmax - zmin) < 1e-5:
            (top if abs(zmin) < 1e-5 else bottom).append(s)
        elif abs(xmax - xmin) < 1e-5 and abs(xmin) < 1e-5:
            x0.append(s)
        elif abs(ymax - ymin) < 1e-5 and abs(ymin) < 1e-5:
            y0.append(s)
    return top, bottom, x0, y0


def threshold(f, dist, h_min, h_max, d_min, d_max):
    thr = f.add("Threshold")
    f.setNumber(thr, "InField", dist)
    f.setNumber(thr, "SizeMin", h_min)
    f.setNumber(thr, "SizeMax", h_max)
    f.setNumber(thr, "DistMin", d_min)
    f.setNumber(thr, "DistMax", d_max)
    return thr


def build(R, h_contact, h_far, d_fine, d_grade, h_rim, width, depth):
    sphere = quarter_hemisphere(R, R, False)
    block = gmsh.model.occ.addBox(0, 0, -depth, width, width, depth)
    gmsh.model.occ.synchronize()
    sf, ss, sx, sy = classify(sphere, R, False)
    bt, bb, bx, by = block_faces(block, depth, width)
    for dim, tags, name in [(3, [sphere], "sphere"), (3, [block], "plane"),
                            (2, sf, "sphere_top"), (2, ss, "sphere_contact"),
                            (2, bt, "plane_top"), (2, bb, "plane_bottom"),
                            (2, sx + bx, "x0"), (2, sy + by, "y0")]:
        if not tags:
            raise MeshError("sphere_plane: no surface for '%s'" % name)
        gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), name)
    # The sphere's apex and the block's corner, both at the origin.
    points = [t for _, t in gmsh.model.getEntitiesInBoundingBox(-1e-6, -1e-6, -1e-6, 1e-6, 1e-6,
                                                                   1e-6, 0)]
    f = gmsh.model.mesh.field
    dist = f.add("Distance")
    f.setNumbers(dist, "NodesList", points)
    thr = threshold(f, dist, h_contact, h_far, d_fine, d_grade)
    rim = f.add("Distance")
    f.setNumbers(rim, "CurvesList", rim_arcs(sf))
    f.setNumber(rim, "NumPointsPerCurve", 200)
    both = f.add("Min")
    f.setNumbers(both, "FieldsList", [thr, threshold(f, rim, h_rim, h_far, 0.0, h_far)])
    f.setAsBackgroundMesh(both)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    gmsh.model.mesh.generate(3)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output")
    ap.add_argument("--radius", type=float, default=6.1237)
    ap.add_argument("--contact-size", type=float, default=0.17)
    ap.add_argument("--far-size", type=float, default=1.0)
    ap.add_argument("--fine-within", type=float, help="default 0.3 R")
    ap.add_argument("--grade-to", type=float, help="default R")
    ap.add_argument("--rim-size", type=float, default=0.2)
    ap.add_argument("--block-width", type=float, help="default 1.5 R")
    ap.add_argument("--block-depth", type=float, help="default R")
    a = ap.parse_args()
    R = a.radius
    d_fine = 0.3 * R if a.fine_within is None else a.fine_within
    d_grade = R if a.grade_to is None else a.grade_to
    width = 1.5 * R if a.block_width is None else a.block_width
    depth = R if a.block_depth is None else a.block_depth
    if not (R > 0 and 0 < a.contact_size <= a.far_size and 0 < d_fine < d_grade
            and 0 < a.rim_size and width > 0 and depth > 0):
        print("sphere_plane.py: error: need --radius > 0, 0 < --contact-size <= --far-size, "
              "0 < --fine-within < --grade-to, --rim-size, --block-width, --block-depth > 0",
              file=sys.stderr)
        return 2
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("sphere_plane")
        build(R, a.contact_size, a.far_size, d_fine, d_grade, a.rim_size, width, depth)
        mesh = model_to_mesh("sphere_plane")
    except MeshError as e:
        print("sphere_plane.py: error: %s" % e, file=sys.stderr)
        return 2
    finally:
        gmsh.finalize()
    write_exodus(mesh, a.output, title="gmsh sphere on a block, contact size %g" % a.contact_size)
    print("sphere_plane.py: %s: %d nodes, %d tets" % (a.output, len(mesh.coords),
                                                    sum(len(c) for _, _, c in mesh.blocks)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
