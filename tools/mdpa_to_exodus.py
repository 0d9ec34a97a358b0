#!/usr/bin/python3
"""Converts a Kratos .mdpa mesh to Exodus II for grout.

Usage: tools/mdpa_to_exodus.py [--layer Z] INPUT.mdpa OUTPUT.exo
       tools/mdpa_to_exodus.py --help        (this text, exit code 0)

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
the same name). Nodes no element uses are dropped (the rest renumbered); elements of negative
measure are re-ordered. Malformed input stops with "file:line: message" and exit code 2, among
others a byte that is not UTF-8 outside a // comment (comments may hold any bytes) and a
SubModelPartNodes, -Elements or -Conditions block outside a SubModelPart. A side set name
"<part>_<block>" longer than 32 characters drops every leading "parts_" of the block name
(Kratos' "Parts_Parts_Auto1" gives "<part>_auto1") before it is skipped. See docs/meshes.md.

--layer Z: a 2D (plane-strain) mesh from the z = Z layer of a 3D hexahedral mesh whose elements
are stacked in z (Kratos' extruded 2D benchmarks, e.g. the double arch). Every HEX8 element with
a face on the plane z = Z (within 1e-9 of the mesh size) becomes a QUAD4 of that face's four
nodes (counterclockwise in x-y; on an inner plane, from the element above it); hexahedra with no
node on the plane are dropped. SubModelPart nodes, elements and conditions keep what lies on the
layer: nodes on the plane, the elements that gave a quad, and a surface condition with exactly
two nodes on the plane becomes the line of those two (other conditions are dropped). Refused
with an error: a non-HEX8 element, a hexahedron with 1 to 3 (or 4 not forming a face, or more
than 4) nodes on the plane or crossing it with none (the mesh is not layered in z there), and a
plane that no face lies on.
"""
import gzip
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exodus_mesh import Mesh, MeshError, SIDES, write_exodus  # noqa: E402

# HEX8 faces (0-based local nodes, cyclic): a face on the --layer plane becomes a QUAD4 in
# this order, re-oriented counterclockwise by Mesh.add_block.
HEX8_FACES = [(0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
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
        with open(path, "rb") as f:
            raw_lines = f.read().splitlines()
    except OSError as e:
        raise MeshError("%s: cannot read (%s)" % (path, e.strerror))

    def fail(n, msg):
        raise MeshError("%s:%d: %s" % (path, n, msg))

    # Comments are dropped as bytes, so any encoding may appear in them (GiD writes Latin-1);
    # what is left must be UTF-8 text (ids, numbers and names).
    lines = []
    for n, raw in enumerate(raw_lines, start=1):
        code = raw.split(b"//")[0]
        try:
            lines.append(code.decode("utf-8"))
        except UnicodeDecodeError as e:
            fail(n, "byte 0x%02x at column %d is not UTF-8 text (outside a // comment)"
                 % (code[e.start], e.start + 1))

    def ints(fields, n):
        try:
            return [int(f) for f in fields]
        except ValueError:
            fail(n, "expected integers, got '%s'" % " ".join(fields))

    for n, raw in enumerate(lines, start=1):
        text = raw.strip()
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
            elif kind in ("SubModelPartNodes", "SubModelPartElements", "SubModelPartConditions"):
                if not stack or stack[-1][0] != "SubModelPart":
                    listed = kind[len("SubModelPart"):].lower()
                    fail(n, "'Begin %s' outside a SubModelPart (it lists the %s of the "
                         "SubModelPart it is written in)" % (kind, listed))
                stack.append((kind, stack[-1][1]))
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
            part = extra  # the SubModelPart the block is written in (checked at its Begin)
            target = {"SubModelPartNodes": part.nodes, "SubModelPartElements": part.elements,
                      "SubModelPartConditions": part.conditions}[kind]
            target += [(i, n) for i in ints(words, n)]
        # other blocks (ModelPartData, Properties, Table, SubModelPartData, ...) are skipped
    if stack:
        fail(len(lines), "end of file inside 'Begin %s'" % stack[-1][0])
    if not nodes or not elements:
        raise MeshError("%s: no %s" % (path, "nodes" if not nodes else "elements"))
    return nodes, elements, conditions, parts


def extract_layer(path, nodes, elements, conditions, parts, z):
    """The z = `z` layer of a z-stacked HEX8 mesh as QUAD4 (see --layer in the docstring):
    returns nodes {id: (x, y, 0)}, elements, conditions and parts of the layer."""
    zs = [xyz[2] for xyz in nodes.values()]
    extent = max(max(c[d] for c in nodes.values()) - min(c[d] for c in nodes.values())
                 for d in range(3))
    tol = 1e-9 * max(extent, abs(z), 1e-300)
    if not min(zs) - tol <= z <= max(zs) + tol:
        raise MeshError("%s: --layer %g is outside the mesh (z in [%g, %g])"
                        % (path, z, min(zs), max(zs)))
    on = {nid for nid, xyz in nodes.items() if abs(xyz[2] - z) <= tol}
    layer_elements, faces_seen = {}, {}  # faces_seen: face nodes -> element giving its quad
    for eid, (etype, prop, conn, line) in elements.items():
        if etype != "HEX8":
            raise MeshError("%s:%d: --layer needs HEX8 elements, element %d is %s"
                            % (path, line, eid, etype))
        for nid in conn:
            if nid not in nodes:
                raise MeshError("%s:%d: element %d uses undefined node %d" % (path, line, eid, nid))
        local = [i for i, nid in enumerate(conn) if nid in on]
        if not local:
            if min(nodes[v][2] for v in conn) < z < max(nodes[v][2] for v in conn):
                raise MeshError("%s:%d: element %d crosses the plane z = %g with no node on it "
                                "(--layer needs a mesh layered in z)" % (path, line, eid, z))
            continue
        face = next((f for f in HEX8_FACES if set(f) == set(local)), None)
        if face is None:
            raise MeshError("%s:%d: element %d has %d of its 8 nodes on the plane z = %g, not "
                            "one face (--layer needs a mesh layered in z)"
                            % (path, line, eid, len(local), z))
        above = any(nodes[nid][2] > z for nid in conn if nid not in on)
        key = frozenset(conn[i] for i in face)
        if key in faces_seen and not above:
            continue  # an inner plane: the element above it gives the quad
        faces_seen[key] = eid
        layer_elements[eid] = ("QUAD4", prop, [conn[i] for i in face], line)
    layer_elements = {eid: layer_elements[eid] for eid in faces_seen.values()}
    if not layer_elements:
        raise MeshError("%s: no element has a face on the plane z = %g (--layer)" % (path, z))
    layer_conditions = {}
    for cid, (cnodes, line) in conditions.items():
        kept = [nid for nid in cnodes if nid in on]
        if len(kept) == 2 and len(cnodes) > 2:
            layer_conditions[cid] = (kept, line)
    layer_nodes = {nid: (nodes[nid][0], nodes[nid][1], 0.0) for nid in on}
    for part in parts:
        part.nodes = [(i, n) for i, n in part.nodes if i in on]
        part.elements = [(i, n) for i, n in part.elements if i in layer_elements]
        part.conditions = [(i, n) for i, n in part.conditions if i in layer_conditions]
    return layer_nodes, layer_elements, layer_conditions, parts


def convert(path, layer=None):
    nodes, elements, conditions, parts = parse(path)
    if layer is not None:
        nodes, elements, conditions, parts = extract_layer(path, nodes, elements, conditions,
                                                           parts, layer)
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
                if len(full) > 32:
                    full = "%s_%s" % (name, re.sub(r"^(parts_)+", "", block))
                if sides and len(full) <= 32:
                    mesh.side_sets[full] = sorted(sides)
                elif sides:
                    print("mdpa_to_exodus: note: no side set for part %s on block %s (name '%s' "
                          "longer than 32 characters)" % (part.name, block, full))
    mesh.add_side_set_node_sets()
    return mesh, dropped


def convert_renamed(src, renames, layer=None):
    """convert() of a Kratos .mdpa read from `src` (gzipped if its name ends in .gz), with each
    regular expression of `renames`, [(pattern, new name)], replaced in the text first (the
    cases' meshes, published with long SubModelPart names): every pattern must match. Returns
    (mesh, nodes dropped); a MeshError names the file."""
    opener = gzip.open if src.endswith(".gz") else open
    try:
        with opener(src, "rt", encoding="utf-8", newline="") as f:
            text = f.read()
    except (OSError, UnicodeDecodeError) as e:
        raise MeshError("%s: %s" % (src, e))
    for pattern, new in renames:
        text, n = re.subn(pattern, new, text)
        if n == 0:
            raise MeshError("%s: no SubModelPart matches %s" % (src, pattern))
    with tempfile.TemporaryDirectory() as tmp:
        name = os.path.basename(src)
        path = os.path.join(tmp, name[:-3] if name.endswith(".gz") else name)
        with open(path, "w", encoding="utf-8", newline="") as f:
            f.write(text)
        return convert(path, layer)


def main(argv):
    if len(argv) == 2 and argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0
    layer = None
    if len(argv) >= 2 and argv[1] == "--layer":
        try:
            layer = float(argv[2])
        except (IndexError, ValueError):
            print("mdpa_to_exodus: error: --layer needs a number (the plane z = Z), got %s"
                  % (repr(argv[2]) if len(argv) > 2 else "nothing"), file=sys.stderr)
            return 2
        argv = argv[:1] + argv[3:]
    if len(argv) != 3:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    try:
        mesh, dropped = convert(argv[1], layer)
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
