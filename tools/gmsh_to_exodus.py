#!/usr/bin/python3
"""Gmsh -> Exodus II for grout: converts a .msh file, or (as a module) the current gmsh model.

Usage: tools/gmsh_to_exodus.py INPUT.msh OUTPUT.exo
       tools/gmsh_to_exodus.py --help        (these rules, exit code 0)

Physical groups become named Exodus entities (python3-gmsh reads the model):
  - a physical group of the mesh dimension (surfaces in 2D, volumes in 3D): an element block
    (one element type per group);
  - a physical group one dimension lower (curves in 2D, surfaces in 3D): a side set (the block
    element sides its line/face elements lie on) and a node set of its nodes, named <name>_nodes;
  - a physical group of points: a node set.
Names are lowercased (as tools/mdpa_to_exodus.py does): physical "Contact" is side set
"contact" in the Exodus file and in grout's input; the summary line lists every name that
changed, and two groups whose names differ only in case are refused.
Elements: first order only, Triangle 3 and Quadrilateral 4 (TRI3, QUAD4) in 2D, Tetrahedron 4
and Hexahedron 8 (TETRA4, HEX8) in 3D, with Line 2, Triangle 3 and Quadrilateral 4 on side
sets. A second-order mesh (Triangle 6, Quadrilateral 9, Tetrahedron 10, ...) is refused
naming its element: mesh with Mesh.ElementOrder = 1 (gmsh -order 1).
Elements of the mesh dimension outside every physical group are ignored, and so are nodes
no block element uses. A malformed or unreadable file, an unnamed physical group, a physical
group with no mesh elements (a curve gmsh did not mesh or save) or a boundary element that
lies on no block element side stops with the file, the group and what is wrong, exit code 2.
See docs/meshes.md.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exodus_mesh import Mesh, MeshError, write_exodus  # noqa: E402

GMSH_TYPES = {3: "QUAD4", 2: "TRI3", 4: "TETRA4", 5: "HEX8"}  # gmsh element type -> Exodus
SIDE_NODES = {1: 2, 2: 3, 3: 4}  # gmsh side element type (Line 2, Triangle 3, Quad 4) -> nodes
SUPPORTED = ("first order only: Triangle 3, Quadrilateral 4, Tetrahedron 4, Hexahedron 8 blocks; "
             "Line 2, Triangle 3, Quadrilateral 4 sides (Mesh.ElementOrder = 1)")


def element_name(gmsh_type):
    """gmsh's name of an element type, with its order: 'Quadrilateral 9 (order 2)'."""
    import gmsh
    try:
        name, _, order = gmsh.model.mesh.getElementProperties(int(gmsh_type))[:3]
        return "%s (gmsh type %d, order %d)" % (name, gmsh_type, order)
    except Exception:  # an unknown type number
        return "gmsh element type %d" % gmsh_type


def generate_all_quads():
    """Mesh the current 2D gmsh model in quadrilaterals only: Frontal-Delaunay for quads
    (Mesh.Algorithm 6), triangles recombined, then every element subdivided once (the mesh
    sizes set before are halved by the subdivision)."""
    import gmsh
    gmsh.option.setNumber("Mesh.RecombineAll", 1)
    gmsh.option.setNumber("Mesh.SubdivisionAlgorithm", 1)  # all quads
    gmsh.option.setNumber("Mesh.Algorithm", 6)
    gmsh.model.mesh.generate(2)


def model_to_mesh(source="gmsh model"):
    """Mesh of the current gmsh model (gmsh initialised, model meshed or loaded)."""
    import gmsh

    dim = gmsh.model.getDimension()
    if dim not in (2, 3):
        raise MeshError("%s: mesh dimension %d (need 2 or 3)" % (source, dim))
    tags, xyz, _ = gmsh.model.mesh.getNodes()
    if len(tags) == 0:
        raise MeshError("%s: no nodes (not meshed?)" % source)
    index = {int(t): k for k, t in enumerate(tags)}
    coords = np.asarray(xyz).reshape(-1, 3)[:, :dim]
    mesh = Mesh(coords)
    groups = gmsh.model.getPhysicalGroups()
    names, original, kind_of = {}, {}, {}
    kinds = {dim: "block", dim - 1: "side set"}
    for d, tag in groups:
        name = gmsh.model.getPhysicalName(d, tag)
        if not name:
            raise MeshError("%s: physical group (dim %d, tag %d) has no name" % (source, d, tag))
        # Lowercased, as the .mdpa converter does; the same lowercased name twice in one kind
        # of entity would merge two groups silently.
        key = (kinds.get(d, "node set"), name.lower())
        if key in kind_of:
            raise MeshError("%s: physical groups '%s' and '%s' both become %s '%s' (names are "
                            "lowercased)" % (source, kind_of[key], name, key[0], key[1]))
        kind_of[key] = name
        names[(d, tag)] = name.lower()
        if name != name.lower():
            original[name.lower()] = name
    for (d, tag), name in names.items():
        if d != dim:
            continue
        conn, topology = [], None
        for entity in gmsh.model.getEntitiesForPhysicalGroup(d, tag):
            types, _, nodes = gmsh.model.mesh.getElements(d, entity)
            for t, n in zip(types, nodes):
                if t not in GMSH_TYPES:
                    raise MeshError("%s: block '%s' has %s elements (supported: %s)" %
                                    (source, name, element_name(t), SUPPORTED))
                if topology not in (None, GMSH_TYPES[t]):
                    raise MeshError("%s: block '%s' mixes %s and %s elements" %
                                    (source, name, topology, GMSH_TYPES[t]))
                topology = GMSH_TYPES[t]
                conn += [index[int(v)] for v in n]
        if topology is None:
            raise MeshError("%s: block '%s' has no elements" % (source, name))
        mesh.add_block(name, topology, conn)
    if not mesh.blocks:
        raise MeshError("%s: no physical group of dimension %d (element blocks)" % (source, dim))
    faces = mesh.boundary_faces()
    for (d, tag), name in names.items():
        if d == dim:
            continue
        what = "physical %s '%s' (tag %d)" % (("point", "curve", "surface")[d], name, tag)
        nodes = gmsh.model.mesh.getNodesForPhysicalGroup(d, tag)[0]
        if len(nodes) == 0 and d != dim - 1:  # a side set's group: its elements are asked below
            raise MeshError("%s: %s has no mesh nodes (the .msh holds no mesh of it)"
                            % (source, what))
        mesh.node_sets[name] = sorted({index[int(v)] for v in nodes if int(v) in index})
        if d != dim - 1:
            continue
        sides = []
        for entity in gmsh.model.getEntitiesForPhysicalGroup(d, tag):
            types, _, enodes = gmsh.model.mesh.getElements(d, entity)
            for t, n in zip(types, enodes):
                k = SIDE_NODES.get(int(t))
                if k is None:
                    raise MeshError("%s: side set '%s' has %s elements (supported: %s)" %
                                    (source, name, element_name(t), SUPPORTED))
                for row in np.asarray(n, dtype=np.int64).reshape(-1, k):
                    key = frozenset(index[int(v)] for v in row)
                    if key not in faces:
                        raise MeshError("%s: side set '%s': element with nodes %s is not on the "
                                        "boundary of a block" % (source, name, list(row)))
                    sides.append(faces[key])
        if not sides:
            raise MeshError("%s: %s has no %s elements, so no side set '%s' can be made (the "
                            ".msh holds no mesh of that %s: was the group added after meshing?)"
                            % (source, what, ("line", "face")[d - 1], name, what.split()[1]))
        mesh.side_sets[name] = sorted(set(sides))
    mesh.drop_unused_nodes()
    mesh.lowercased = original  # lowercased name -> the physical group's name
    return mesh


def convert(path, out):
    import gmsh

    if not os.path.isfile(path):
        raise MeshError("%s: no such file" % path)
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        try:
            gmsh.open(path)
        except Exception as e:  # gmsh raises plain Exceptions with its last error message
            raise MeshError("%s: gmsh cannot read it (%s)" % (path, e))
        mesh = model_to_mesh(path)
    finally:
        gmsh.finalize()
    write_exodus(mesh, out, title="converted from " + os.path.basename(path))
    return mesh


def main(argv):
    if len(argv) == 2 and argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0
    if len(argv) != 3:
        print("usage: gmsh_to_exodus.py INPUT.msh OUTPUT.exo (--help: the rules)", file=sys.stderr)
        return 2
    try:
        mesh = convert(argv[1], argv[2])
    except MeshError as e:
        print("gmsh_to_exodus: error: %s" % e, file=sys.stderr)
        return 2
    print("gmsh_to_exodus: %s -> %s: %d nodes, blocks %s, node sets %s, side sets %s" %
          (argv[1], argv[2], len(mesh.coords), [b[0] for b in mesh.blocks],
           sorted(mesh.node_sets), sorted(mesh.side_sets)))
    if mesh.lowercased:
        print("gmsh_to_exodus: names lowercased: %s" % ", ".join(
            "%s -> %s" % (mesh.lowercased[k], k) for k in sorted(mesh.lowercased)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
