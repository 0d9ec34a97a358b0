#!/usr/bin/python3
"""One of Kratos' self-contact meshes (docs/verification.md #16: the crossed hyperelastic tubes
and the S profile) to Exodus: INPUT.mdpa.gz is Kratos' .mdpa gzipped unchanged (README.md:
where from); the SubModelParts named in OLD=NEW are renamed to short names (so that no two sets
clash and every name fits Exodus' 32 characters) and the mesh is converted by
tools/mdpa_to_exodus.py's rules (docs/meshes.md): a side set per SubModelPart with conditions,
each condition the element side with its nodes (the face's orientation is the element's,
whatever the order of the condition's nodes), nodes of no element dropped.

Usage: kratos_mesh.py OUTPUT.exo INPUT.mdpa.gz OLD=NEW [OLD=NEW ...]
"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from exodus_mesh import MeshError, write_exodus  # noqa: E402
from mdpa_to_exodus import convert_renamed  # noqa: E402


def main(argv):
    if len(argv) < 4 or any("=" not in a for a in argv[3:]):
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    out, src = argv[1], argv[2]
    pairs = (a.split("=", 1) for a in argv[3:])
    renames = [(r"\b%s\b" % re.escape(old), new) for old, new in pairs]
    try:
        mesh, dropped = convert_renamed(src, renames)
    except MeshError as e:
        print("kratos_mesh.py: error: %s" % e, file=sys.stderr)
        return 2
    write_exodus(mesh, out, title="Kratos " + os.path.basename(src))
    print("kratos_mesh.py: %s -> %s: %d nodes (%d of no element dropped), node sets %s, side "
          "sets %s" % (src, out, len(mesh.coords), dropped, sorted(mesh.node_sets),
                       sorted((k, len(v)) for k, v in mesh.side_sets.items())))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
