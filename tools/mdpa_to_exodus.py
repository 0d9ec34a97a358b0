#!/usr/bin/python3
"""Converts a Kratos .mdpa mesh to Exodus II for grout.

Usage: tools/mdpa_to_exodus.py INPUT.mdpa OUTPUT.exo

Read: Nodes ("id x y z"), Elements ("id property n1 .. nk"; types *2D3N -> TRI3, *2D4N ->
QUAD4, *3D4N -> TETRA4, *3D8N -> HEX8), Conditions ("id property n1 .. nk", line or face
segments) and SubModelParts (nested ones get "<parent>_<child>" names) with their Nodes,
Elements and Conditions lists; ModelPartData, Properties and tables are skipped. Written
(names lower-cased):
  - one element block per SubModelPart holding elements (elements in none: "property_<id>");
  - one node set per SubModelPart holding nodes;
  - one side set per SubModelPart holding conditions: the element side each condition lies on;
  - for a SubModelPart holding nodes but no conditions (e.g. Kratos' Contact_Part), one side
    set "<part>_<block>" per block ("parts_" dropped from the block name; skipped with a note
    if longer than 32 characters): the block's boundary sides whose nodes all lie in the part.
Each side set also gets a node set of its nodes, unless a part already has that name; a node
set named like a side set is written as <name>_nodes (ParaView's IOSS reader mixes up sets of
the same name). Nodes no element uses are dropped (the rest renumbered); elements of negative measure are
re-ordered. Malformed input stops with "file:line: message" and exit code 2.
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exodus_mesh import Mesh, MeshError, SIDES, write_exodus  # noqa: E402

ELEMENT_TYPES = {"2D3N": "TRI3", "2D4N": "QUAD4", "3D4N": "TETRA4", "3D8N": "HEX8"}


class Part:
    def __init__(self, name, line):
        self.name, self.line = name, line
        self.nodes, self.elements, self.conditions = [], [], []


def parse(path):
    """Returns nodes {id: (x, y, z)}, elements {id: (type, prop, nodes, line)}, conditions
    {id: (nodes, line)}, parts [Part] (in file order)."""
    nodes, elements, conditions, parts = {}, {}, {}, []
    stack = []  # open blocks: (kind, extra)
    try:
        lines = open(path).read().splitlines()
    except OSError as e:
        raise MeshError("%s: cannot read (%s)" % (path, e.strerror))

    def fail(n, msg):
        raise MeshError("%s:%d: %s" % (path, n, msg))

    def ints(fields, n):
        try:
            return [int(f) for f in fields]
        except ValueError:
            fail(n, "expected integers, got '%s'" % " ".join(fields))

    for n, raw in enumerate(lines, start=1):
        text = raw.split("//")[0].strip()
        if not text:
            continue
        words = text.split()
        if words[0] == "Begin":
            if len(words) < 2:
                fail(n, "'Begin' without a block name")
            kind = words[1]
            if kind == "SubModelPart":
                if len(words) < 3:
                    fail(n, "SubModelPart without a name")
                parent = next((x for k, x in reversed(stack) if k == "SubModelPart"), None)
                part = Part(words[2] if parent is None else parent.name + "_" + words[2], n)
                parts.append(part)
                stack.append((kind, part))
            elif kind == "Elements":
                if len(words) < 3:
                    fail(n, "Elements block without an element name")
                m = re.search(r"(\dD\d+N)$", words[2])
                if not m or m.group(1) not in ELEMENT_TYPES:
                    fail(n, "unsupported element '%s' (supported: %s)" %
                         (words[2], ", ".join("*" + k for k in ELEMENT_TYPES)))
                stack.append((kind, ELEMENT_TYPES[m.group(1)]))
            else:
                stack.append((kind, None))
            continue
        if words[0] == "End":
            if not stack:
                fail(n, "'End' without a matching 'Begin'")
            kind = stack[-1][0]
            if len(words) < 2 or words[1] != kind:
                fail(n, "'%s' closes the block 'Begin %s'" % (text, kind))
            stack.pop()
            continue
        if not stack:
            fail(n, "text outside any Begin/End block: '%s'" % text)
        kind, extra = stack[-1]
        if kind == "Nodes":
            if len(words) != 4:
                fail(n, "a node line is 'id x y z', got '%s'" % text)
            try:
                nid, xyz = int(words[0]), tuple(float(w) for w in words[1:])
            except ValueError:
                fail(n, "a node line is 'id x y z', got '%s'" % text)
            if nid in nodes:
                fail(n, "node %d defined twice" % nid)
            nodes[nid] = xyz
        elif kind == "Elements":
            want = {"TRI3": 3, "QUAD4": 4, "TETRA4": 4, "HEX8": 8}[extra]
            v = ints(words, n)
            if len(v) != 2 + want:
                fail(n, "%s element line is 'id property' + %d nodes, got '%s'" % (extra, want, text))
            if v[0] in elements:
                fail(n, "element %d defined twice" % v[0])
            elements[v[0]] = (extra, v[1], v[2:], n)
        elif kind == "Conditions":
            v = ints(words, n)
            if len(v) < 4:
                fail(n, "a condition line is 'id property n1 n2 ...', got '%s'" % text)
            conditions[v[0]] = (v[2:], n)
        elif kind in ("SubModelPartNodes", "SubModelPartElements", "SubModelPartConditions"):
            part = next(x for k, x in reversed(stack) if k == "SubModelPart")
            target = {"SubModelPartNodes": part.nodes, "SubModelPartElements": part.elements,
                      "SubModelPartConditions": part.conditions}[kind]
            target += [(i, n) for i in ints(words, n)]
        # other blocks (ModelPartData, Properties, Table, SubModelPartData, ...) are skipped
    if stack:
        fail(len(lines), "end of file inside 'Begin %s'" % stack[-1][0])
    if not nodes or not elements:
        raise MeshError("%s: no %s" % (path, "nodes" if not nodes else "elements"))
    return nodes, elements, conditions, parts


def convert(path):
    nodes, elements, conditions, parts = parse(path)
    node_ids = sorted(nodes)
    index = {nid: k for k, nid in enumerate(node_ids)}
    dims = {{"TRI3": 2, "QUAD4": 2}.get(t, 3) for t, _, _, _ in elements.values()}
    if len(dims) != 1:
        raise MeshError("%s: mixes 2D and 3D elements" % path)
    dim = dims.pop()
    coords = [nodes[i][:dim] for i in node_ids]
    for eid, (t, _, conn, line) in elements.items():
        for nid in conn:
            if nid not in index:
                raise MeshError("%s:%d: element %d uses undefined node %d" % (path, line, eid, nid))
    # Blocks: SubModelParts with elements, then the rest by property.
    block_of = {}
    for part in parts:
        for eid, line in part.elements:
            if eid not in elements:
                raise MeshError("%s:%d: SubModelPart %s lists undefined element %d" %
                                (path, line, part.name, eid))
            if eid in block_of and block_of[eid] != part.name.lower():
                raise MeshError("%s:%d: element %d is in two SubModelParts with elements (%s, %s)"
                                % (path, line, eid, block_of[eid], part.name.lower()))
            block_of[eid] = part.name.lower()
    for eid, (_, prop, _, _) in elements.items():
        block_of.setdefault(eid, "property_%d" % prop)
    mesh = Mesh(coords)
    order = []  # element ids in global element order
    for name in dict.fromkeys(block_of[e] for e in sorted(elements)):
        ids = [e for e in sorted(elements) if block_of[e] == name]
        types = {elements[e][0] for e in ids}
        if len(types) != 1:
            raise MeshError("%s: block '%s' mixes element types %s" % (path, name, sorted(types)))
        mesh.add_block(name, types.pop(), [[index[v] for v in elements[e][2]] for e in ids])
        order += ids
    for part in parts:
        if part.nodes:
            for nid, line in part.nodes:
                if nid not in index:
                    raise MeshError("%s:%d: SubModelPart %s lists undefined node %d" %
                                    (path, line, part.name, nid))
            mesh.node_sets[part.name.lower()] = sorted({index[i] for i, _ in part.nodes})
    dropped = mesh.drop_unused_nodes()
    # Side sets (node numbers after the renumbering: look faces up by the original ids).
    used_ids = sorted({elements[e][2][i] for e in elements for i in range(len(elements[e][2]))})
    renumber = {nid: k for k, nid in enumerate(used_ids)}
    faces = mesh.boundary_faces()
    block_names = mesh.block_of_element()
    for part in parts:
        name = part.name.lower()
        if part.conditions:
            sides = []
            for cid, line in part.conditions:
                if cid not in conditions:
                    raise MeshError("%s:%d: SubModelPart %s lists undefined condition %d" %
                                    (path, line, part.name, cid))
                cnodes, cline = conditions[cid]
                if any(v not in renumber for v in cnodes):
                    raise MeshError("%s:%d: condition %d uses a node of no element" %
                                    (path, cline, cid))
                key = frozenset(renumber[v] for v in cnodes)
                if key not in faces:
                    raise MeshError("%s:%d: condition %d is not on a boundary side of an element"
                                    % (path, cline, cid))
                sides.append(faces[key])
            mesh.side_sets[name] = sorted(set(sides))
        elif part.nodes and not part.elements:
            inside = set(renumber[i] for i, _ in part.nodes if i in renumber)
            for block in dict.fromkeys(block_names):
                sides = [es for key, es in faces.items()
                         if block_names[es[0]] == block and key <= inside]
                full = "%s_%s" % (name, re.sub(r"^parts_", "", block))
                if sides and len(full) <= 32:
                    mesh.side_sets[full] = sorted(sides)
                elif sides:
                    print("mdpa_to_exodus: note: no side set for part %s on block %s (name '%s' "
                          "longer than 32 characters)" % (part.name, block, full))
    mesh.add_side_set_node_sets()
    return mesh, dropped


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    try:
        mesh, dropped = convert(argv[1])
        write_exodus(mesh, argv[2], title="converted from " + os.path.basename(argv[1]))
    except MeshError as e:
        print("mdpa_to_exodus: error: %s" % e, file=sys.stderr)
        return 2
    print("mdpa_to_exodus: %s -> %s: %d nodes (%d unused dropped), blocks %s, node sets %s, "
          "side sets %s" % (argv[1], argv[2], len(mesh.coords), dropped,
                            [b[0] for b in mesh.blocks], sorted(mesh.node_sets),
                            sorted(mesh.side_sets)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
