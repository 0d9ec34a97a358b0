"""The mesh converters on the inputs that used to crash them or that they misread
(issue 29): each case runs the converter as a user would and checks its exit code and the
message; no case may print a Python traceback.

    /usr/bin/python3 check_converters.py WORKDIR

tools/gmsh_to_exodus.py:
- --help prints the rules (names lowercased, first-order elements only) with exit code 0;
- a second-order mesh: exit 2 naming the element (Triangle 6) and what is supported;
- a physical curve with mesh nodes but no line elements (a .msh written without them):
  exit 2 naming the group (it crashed in netCDF: "NC_UNLIMITED size already in use");
- physical names in mixed case: converted, lowercased, and the summary says so;
- two physical curves whose names differ only in case: exit 2 naming both.
tools/mdpa_to_exodus.py:
- a Latin-1 byte inside a // comment: converted (it crashed with UnicodeDecodeError);
- a Latin-1 byte in a SubModelPart name: exit 2 with file:line;
- 'Begin SubModelPartNodes' at top level: exit 2 with file:line (it crashed, StopIteration);
- --help: exit code 0.
"""
import os
import re
import subprocess
import sys

import netCDF4

TOOLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
failures = []


def run(tool, *args):
    p = subprocess.run([sys.executable, os.path.join(TOOLS, tool)] + list(args),
                       capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def expect(what, tool, args, code, pattern, stream="stderr"):
    rc, out, err = run(tool, *args)
    text = out if stream == "stdout" else err
    ok = rc == code and re.search(pattern, text, re.S) and "Traceback" not in out + err
    print("%s %s: exit %d, %s" % ("ok  " if ok else "FAIL", what, rc, (text.strip() or "-")[:300]))
    if not ok:
        failures.append("%s: exit %d (expected %d), output does not match %r or has a traceback:"
                        "\n%s%s" % (what, rc, code, pattern, out, err))
    return rc, out, err


def gmsh_square(path, names, order=1, drop_lines=False):
    """A unit square meshed by gmsh, physical surface names[0] and physical curves names[1:]
    on its bottom edge (curve 1), written as MSH 4.1 text; drop_lines removes the line
    elements from the file (their nodes stay)."""
    import gmsh
    gmsh.initialize()
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.model.add("square")
        s = gmsh.model.occ.addRectangle(0, 0, 0, 1, 1)
        gmsh.model.occ.synchronize()
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, [s]), names[0])
        for name in names[1:]:
            gmsh.model.setPhysicalName(1, gmsh.model.addPhysicalGroup(1, [1]), name)
        gmsh.option.setNumber("Mesh.MeshSizeMax", 0.5)
        gmsh.model.mesh.generate(2)
        if order != 1:
            gmsh.model.mesh.setOrder(order)
        gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
        gmsh.write(path)
    finally:
        gmsh.finalize()
    if drop_lines:  # $Elements: numEntityBlocks numElements minTag maxTag, then the blocks
        lines = open(path).read().split("\n")
        start = lines.index("$Elements")
        head = lines[start + 1].split()
        k, kept, n_blocks, n_elements = start + 2, [], 0, 0
        for _ in range(int(head[0])):
            dim, _, _, count = map(int, lines[k].split())  # entityDim entityTag type count
            if dim != 1:
                kept += lines[k:k + 1 + count]
                n_blocks, n_elements = n_blocks + 1, n_elements + count
            k += 1 + count
        header = "%d %d %s %s" % (n_blocks, n_elements, head[2], head[3])
        open(path, "w").write("\n".join(lines[:start + 1] + [header] + kept + lines[k:]))


def exodus_names(path, var):
    with netCDF4.Dataset(path) as ds:
        return [s.strip() for s in netCDF4.chartostring(ds.variables[var][:])]


def check_gmsh(work):
    g2e = "gmsh_to_exodus.py"
    expect("gmsh --help", g2e, ["--help"], 0, r"lowercased.*first order", "stdout")
    expect("gmsh without arguments", g2e, [], 2, r"usage: .*--help")
    msh = os.path.join(work, "second_order.msh")
    gmsh_square(msh, ["body", "bottom"], order=2)
    expect("gmsh second-order mesh", g2e, [msh, os.path.join(work, "second_order.exo")], 2,
           r"second_order\.msh: block 'body' has Triangle 6 .*order 2.*supported: first order")
    msh = os.path.join(work, "no_lines.msh")
    gmsh_square(msh, ["body", "bottom"], drop_lines=True)
    expect("gmsh physical curve without line elements", g2e,
           [msh, os.path.join(work, "no_lines.exo")], 2,
           r"no_lines\.msh: physical curve 'bottom' \(tag \d+\) has no line elements")
    msh = os.path.join(work, "mixed_case.msh")
    exo = os.path.join(work, "mixed_case.exo")
    gmsh_square(msh, ["Body", "Bottom_Edge"])
    rc, _, _ = expect("gmsh mixed-case names", g2e, [msh, exo], 0,
                      r"names lowercased: Body -> body, Bottom_Edge -> bottom_edge", "stdout")
    if rc == 0:
        got = (exodus_names(exo, "eb_names"), exodus_names(exo, "ss_names"))
        ok = got == (["body"], ["bottom_edge"])
        print("%s mixed-case names in the Exodus file: blocks %s, side sets %s"
              % ("ok  " if ok else "FAIL", got[0], got[1]))
        if not ok:
            failures.append("mixed-case names in the Exodus file: %s" % (got,))
    msh = os.path.join(work, "case_clash.msh")
    gmsh_square(msh, ["body", "Top", "top"])
    expect("gmsh names differing only in case", g2e, [msh, os.path.join(work, "clash.exo")], 2,
           r"case_clash\.msh: physical groups 'Top' and 'top' both become side set 'top'")


MDPA = (b"Begin Nodes // caf\xe9 (Latin-1)\n 1 0 0 0\n 2 1 0 0\n 3 1 1 0\n 4 0 1 0\nEnd Nodes\n"
        b"Begin Elements SmallDisplacementElement2D4N\n 1 0 1 2 3 4\nEnd Elements\n"
        b"Begin SubModelPart top // \xff\xfe\n Begin SubModelPartNodes\n 3\n 4\n"
        b" End SubModelPartNodes\nEnd SubModelPart\n")


def check_mdpa(work):
    m2e = "mdpa_to_exodus.py"
    expect("mdpa --help", m2e, ["--help"], 0, r"Usage: .*--layer", "stdout")
    path = os.path.join(work, "latin1_comment.mdpa")
    open(path, "wb").write(MDPA)
    expect("mdpa Latin-1 bytes in // comments", m2e, [path, os.path.join(work, "latin1.exo")],
           0, r"side sets \['top_property_0'\]", "stdout")
    path = os.path.join(work, "latin1_name.mdpa")
    open(path, "wb").write(MDPA.replace(b"SubModelPart top", b"SubModelPart t\xe9p"))
    expect("mdpa Latin-1 byte in a name", m2e, [path, os.path.join(work, "bad.exo")], 2,
           r"latin1_name\.mdpa:10: byte 0xe9 at column 21 is not UTF-8")
    path = os.path.join(work, "top_level_nodes.mdpa")
    open(path, "wb").write(MDPA.replace(b"Begin SubModelPart top // \xff\xfe\n", b"")
                           .replace(b"End SubModelPart\n", b""))
    expect("mdpa SubModelPartNodes at top level", m2e, [path, os.path.join(work, "bad.exo")], 2,
           r"top_level_nodes\.mdpa:10: 'Begin SubModelPartNodes' outside a SubModelPart")


def main(work):
    os.makedirs(work, exist_ok=True)
    check_gmsh(work)
    check_mdpa(work)
    for f in failures:
        print("FAIL:", f)
    print("check_converters: %s" % ("%d failure(s)" % len(failures) if failures else "ok"))
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(sys.argv[1]))
