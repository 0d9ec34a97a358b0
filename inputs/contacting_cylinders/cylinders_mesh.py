#!/usr/bin/python3
"""Kratos' contacting-cylinders mesh (docs/verification.md #17) to Exodus: INPUT.mdpa.gz is one
of Kratos' cylinders.mdpa files, gzipped unchanged (README.md: where from); its SubModelParts
are renamed to short names, so that tools/mdpa_to_exodus.py's side sets "<part>_<block>" fit
Exodus' 32 characters, and converted by that tool's rules (docs/meshes.md).

Usage: cylinders_mesh.py OUTPUT.exo INPUT.mdpa.gz

Renamed: Parts_Parts_Auto1 -> "cylinders" (the one block, both bodies),
DISPLACEMENT_FixedBase -> "base" (the lower half-cylinder's flat face y = 0),
DISPLACEMENT_Displacement_Auto1/2 -> "top" (the upper half-cylinder's flat face, moved),
CONTACT_Contact_slave_Auto1 -> "slave" (the upper curved face, R = 0.13),
CONTACT_Contact_master_Auto1 -> "master" (the lower curved face, R = 0.17).
Written: block "cylinders"; node sets base, top, slave, master; side sets "slave_cylinders",
"master_cylinders", "base_cylinders", "top_cylinders" (the block's boundary faces whose three
nodes lie in the part), each with a node set "<side set>_nodes".
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from exodus_mesh import MeshError, write_exodus  # noqa: E402
from mdpa_to_exodus import convert_renamed  # noqa: E402

RENAME = [(r"\bParts_Parts_Auto1\b", "cylinders"), (r"\bDISPLACEMENT_FixedBase\b", "base"),
          (r"\bDISPLACEMENT_Displacement_Auto[12]\b", "top"),
          (r"\bCONTACT_Contact_slave_Auto1\b", "slave"),
          (r"\bCONTACT_Contact_master_Auto1\b", "master")]


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip().splitlines()[5], file=sys.stderr)
        return 2
    out, src = argv[1], argv[2]
    try:
        mesh, _ = convert_renamed(src, RENAME)
    except MeshError as e:
        print("cylinders_mesh.py: error: %s" % e, file=sys.stderr)
        return 2
    write_exodus(mesh, out, title="Kratos cylinders, " + os.path.basename(src))
    print("cylinders_mesh.py: %s -> %s: %d nodes, node sets %s, side sets %s"
          % (src, out, len(mesh.coords), sorted(mesh.node_sets), sorted(mesh.side_sets)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
