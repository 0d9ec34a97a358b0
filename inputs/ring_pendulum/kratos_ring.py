#!/usr/bin/python3
"""Kratos' 3D cylinder-in-a-ring mesh (in_ring.mdpa, TET4) as Exodus for ring_3d.yaml.

Usage: kratos_ring.py IN_RING.mdpa OUTPUT.exo

Converts with tools/mdpa_to_exodus.py, then names what the case needs (the contact part's
side sets are not written by the converter: "<part>_<block>" would exceed 32 characters):
  blocks     parts_parts_auto1 -> "cylinder" (r = 0.2 about (0.649, 0)),
             parts_parts_auto2 -> "ring" (0.85 <= r <= 1);
  node sets  displacement_displacement_auto1 -> "ring_outer" (r = 1, fixed),
             displacement_displacement_auto2 -> "z_faces" (z = 0 and z = 0.2, u_z = 0);
  side sets  "cylinder_surface": the cylinder's boundary faces on its curved surface,
             "ring_inner": the ring's boundary faces on r = 0.85 (those whose three nodes lie
             within 1e-3 of the circle; the flat z faces are left out).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from exodus_mesh import MeshError, write_exodus  # noqa: E402
from mdpa_to_exodus import convert  # noqa: E402

CYLINDER_CENTRE, CYLINDER_RADIUS, RING_INNER = (0.649, 0.0), 0.2, 0.85


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    try:
        mesh, _ = convert(argv[1])
        renames = {"parts_parts_auto1": "cylinder", "parts_parts_auto2": "ring"}
        if sorted(b[0] for b in mesh.blocks) != sorted(renames):
            raise MeshError("%s: expected blocks %s, found %s"
                            % (argv[1], sorted(renames), [b[0] for b in mesh.blocks]))
        mesh.blocks = [(renames[n], t, c) for n, t, c in mesh.blocks]
        sets = {"displacement_displacement_auto1": "ring_outer",
                "displacement_displacement_auto2": "z_faces"}
        mesh.node_sets = {sets[k]: v for k, v in mesh.node_sets.items() if k in sets}
        mesh.side_sets = {}
        x = mesh.coords
        block = mesh.block_of_element()
        cyl, ring = [], []
        for key, (e, side) in mesh.boundary_faces().items():
            nodes = np.array(sorted(key))
            r_cyl = np.hypot(x[nodes, 0] - CYLINDER_CENTRE[0], x[nodes, 1] - CYLINDER_CENTRE[1])
            r_ring = np.hypot(x[nodes, 0], x[nodes, 1])
            if block[e] == "cylinder" and np.all(np.abs(r_cyl - CYLINDER_RADIUS) < 1e-3):
                cyl.append((e, side))
            elif block[e] == "ring" and np.all(np.abs(r_ring - RING_INNER) < 1e-3):
                ring.append((e, side))
        if not cyl or not ring:
            raise MeshError("%s: no cylinder surface (%d faces) or ring inner surface (%d faces)"
                            % (argv[1], len(cyl), len(ring)))
        mesh.side_sets = {"cylinder_surface": sorted(cyl), "ring_inner": sorted(ring)}
        mesh.add_side_set_node_sets()
        write_exodus(mesh, argv[2], title="converted from " + os.path.basename(argv[1]))
    except MeshError as e:
        print("kratos_ring: error: %s" % e, file=sys.stderr)
        return 2
    print("kratos_ring: %s -> %s: %d nodes, %d cylinder surface faces, %d ring inner faces"
          % (argv[1], argv[2], len(mesh.coords), len(cyl), len(ring)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
