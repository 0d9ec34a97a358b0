#!/usr/bin/env python3
"""ctest driver_load_order: the driver's busiest libraries come first in its global scope, and
no symbol that two loaded libraries define strongly binds differently because of it
(cmake/GroutLoadOrder.cmake).

    check_load_order.py <grout executable> <library,library,...>

Runs `grout --help` (start-up and MPI_Init/MPI_Finalize) with LD_DEBUG=scopes,bindings and
LD_BIND_NOW=1 and checks:
  1. the global scope starts with the executable and then the given libraries, in order;
  2. every start-up binding of a symbol that two or more libraries of the scope define strongly
     (GLOBAL, not weak or unique: no C++ vague linkage) goes to a definer that no other definer
     depends on (through DT_NEEDED, transitively): the wrapper wins over what it wraps, as it
     does in the linker's natural breadth-first order (libblas.so.3 and liblapack.so.3 over
     libopenblas.so.0, ScaLAPACK over LAPACK, MUMPS's Fortran MPI sentinels over libmpi's).
     Moving a wrapped library in front of its wrapper would fail here;
  3. one MUMPS build: Debian's plain MUMPS (libdmumps-*, libmumps_common-*: Amesos2's)
     beside the PT-SCOTCH build Grout uses would replace the latter's common functions when
     loaded before it (a driver that named the plain libmumps_common directly had
     libdmumps_ptscotch's calls bound to it, and PT-SCOTCH orderings failed on 2 ranks).
"""
import collections
import glob
import os
import re
import subprocess
import sys
import tempfile


def defined_symbols(path):
    """Strongly defined dynamic symbols of `path` (GLOBAL, not UND): {name: type}."""
    out = subprocess.run(["readelf", "--dyn-syms", "-W", path], capture_output=True,
                         text=True, check=True).stdout
    strong = {}
    for row in out.splitlines():
        f = row.split()
        if len(f) < 8 or not f[0].endswith(":") or f[6] == "UND" or f[4] != "GLOBAL":
            continue
        strong[f[7].split("@")[0]] = f[3]
    return strong


def needed(path):
    out = subprocess.run(["readelf", "-d", "-W", path], capture_output=True, text=True,
                         check=True).stdout
    return re.findall(r"\(NEEDED\)\s+Shared library: \[([^\]]+)\]", out)


def main():
    exe, expected = sys.argv[1], [n for n in sys.argv[2].split(",") if n]
    expected = [os.path.basename(n) for n in expected]
    with tempfile.TemporaryDirectory() as tmp:
        # LD_BIND_NOW: the libraries not linked with BIND_NOW (MUMPS, ...) bind their calls at
        # start-up too, so that every call --help never makes is checked.
        env = dict(os.environ, LD_DEBUG="scopes,bindings", LD_DEBUG_OUTPUT=tmp + "/ld",
                   LD_BIND_NOW="1", OPENBLAS_NUM_THREADS="1")
        subprocess.run([exe, "--help"], env=env, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL, check=True)
        logs = sorted(glob.glob(tmp + "/ld.*"), key=os.path.getsize)
        text = open(logs[-1]).read()  # the driver's own log (helpers write small ones)
    scope = None
    for line in text.splitlines():
        if "scope 0:" in line:
            scope = line.split("scope 0:")[1].split()
            break
    if not scope:
        sys.exit("no global scope in the LD_DEBUG output")
    names = [os.path.basename(p) for p in scope]
    failures = []
    # 1. the busiest libraries first.
    if names[1:1 + len(expected)] != expected:
        failures.append("scope does not start with the listed libraries:\n  expected %s\n  got      %s"
                        % (expected, names[1:1 + len(expected)]))
    # 3. one MUMPS build.
    plain = [n for n in names if re.match(r"lib(dmumps|mumps_common)-[0-9]", n)]
    if plain and any("ptscotch" in n and "mumps" in n for n in names):
        failures.append("Debian's plain MUMPS beside the PT-SCOTCH build: %s" % ", ".join(plain))
    # 2. strong definitions shared by several libraries bind to the outermost wrapper.
    libs = scope[1:]
    by_name = {os.path.basename(p): p for p in libs}
    strong = {p: defined_symbols(p) for p in libs}
    deps = {p: [by_name[n] for n in needed(p) if n in by_name] for p in libs}
    closure = {}

    def reach(p):
        if p not in closure:
            closure[p] = set()
            for d in deps[p]:
                closure[p] |= {d} | reach(d)
        return closure[p]

    definers = collections.defaultdict(list)
    for p in libs:
        for s in strong[p]:
            definers[s].append(p)
    checked = 0
    pattern = re.compile(r"binding file (\S+) \[0\] to (\S+) \[0\]: normal symbol `([^']+)'")
    for line in text.splitlines():
        m = pattern.search(line)
        if not m or m.group(2) not in strong:
            continue
        symbol, target = m.group(3), m.group(2)
        d = definers.get(symbol, [])
        if len(d) < 2 or target not in d:
            continue
        checked += 1
        wrappers = [o for o in d if o != target and target in reach(o)]
        if wrappers:
            failures.append("%s binds to %s, which %s wraps" % (
                symbol, os.path.basename(target), os.path.basename(wrappers[0])))
    if checked == 0:
        failures.append("no binding of a strongly interposed symbol seen: nothing was checked")
    positions = sum(names.index(os.path.basename(m.group(2))) for m in pattern.finditer(text)
                    if os.path.basename(m.group(2)) in names)
    print("scope: %d objects; first: %s" % (len(names), ", ".join(names[1:6])))
    print("bindings of strongly interposed symbols checked: %d" % checked)
    print("sum of the scope positions of the binding targets: %d" % positions)
    for f in failures[:20]:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
