"""What the Exodus files carry for the tools that read them (netCDF level, no ParaView):

- time values: step k of 10 is written as the double nearest k/10 (0.3, not
  0.30000000000000004; the last step exactly 1.0), on 1 and 2 ranks;
- stress components in the order in which ParaView's IOSS reader groups them into one
  tensor: stress_xx yy zz xy yz zx in 2D (yz, zx zero) and 3D;
- set names: no node set shares its name with a side set; side set X has node set X_nodes;
- a QA record (grout, version, mm/dd/yy, hh:mm:ss) and an info record naming the input;
- every name and text row is NUL-padded after its end (readers that decode whole rows, such
  as netCDF4.chartostring, fail on stray bytes there);
- values at every step: the uniform-stress contact patch (contact_2d.yaml, contact_3d.yaml),
  sigma_yy (sigma_zz in 3D) = -p, sigma_zz = -nu p in 2D plane strain, other components 0,
  contact_pressure = p at every slave node, p = 4 t, to 1e-8 relative; 1 vs 2 ranks 1e-10.
"""
import os
import re
import sys

import netCDF4
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402
from grout_results import Results  # noqa: E402

NU = 0.3
STRESS_ORDER = {2: ["stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_yz", "stress_zx"],
                3: ["stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_yz", "stress_zx"]}


def strings(ds, var):
    """Rows of a netCDF char array (QA records have one more axis: record x field)."""
    return np.vectorize(lambda s: s.strip())(netCDF4.chartostring(ds.variables[var][:]))


def expected_stress(dim, p):
    s = {k: 0.0 for k in STRESS_ORDER[dim]}
    if dim == 2:
        s["stress_yy"], s["stress_zz"] = -p, -NU * p
    else:
        s["stress_zz"] = -p
    return s


def check_file(path, stem, dim):
    failures = []
    r = Results(path)
    ds = r.ds
    times = r.times()
    expected_times = [k / 10 for k in range(1, 11)]  # the doubles nearest 0.1, 0.2, ..., 1.0
    if list(times) != expected_times:
        failures.append("%s: times %s, expected %s" % (path, [repr(t) for t in times], expected_times))
    if r.element_names != STRESS_ORDER[dim]:
        failures.append("%s: element variables %s, expected %s" % (path, r.element_names, STRESS_ORDER[dim]))
    side_sets = list(strings(ds, "ss_names"))
    node_sets = list(strings(ds, "ns_names"))
    shared = sorted(set(side_sets) & set(node_sets))
    if shared:
        failures.append("%s: node sets and side sets share the names %s" % (path, shared))
    missing = [s for s in side_sets if s + "_nodes" not in node_sets]
    if missing:
        failures.append("%s: no node set <name>_nodes for the side sets %s" % (path, missing))
    qa = strings(ds, "qa_records") if "qa_records" in ds.variables else np.empty((0, 4))
    if qa.shape[0] != 1 or qa[0][0] != "grout" or not qa[0][1] \
            or not re.fullmatch(r"\d\d/\d\d/\d\d", qa[0][2]) or not re.fullmatch(r"\d\d:\d\d:\d\d", qa[0][3]):
        failures.append("%s: QA records %s, expected one (grout, version, date, time)" % (path, qa.tolist()))
    info = list(strings(ds, "info_records")) if "info_records" in ds.variables else []
    if "grout input: %s.yaml" % stem not in info:
        failures.append("%s: info records %s do not name the input %s.yaml" % (path, info, stem))

    for name, var in ds.variables.items():
        if var.dtype != "S1":
            continue
        rows = np.asarray(var[:].data).view("uint8").reshape(-1, var.shape[-1])
        for row in rows:
            end = np.flatnonzero(row == 0)
            if end.size and np.any(row[end[0]:] != 0):
                failures.append("%s: %s has bytes after the end of a name: %r" % (path, name, bytes(row)))
                break
    slave = cc.side_set_nodes(r, "upper_bottom")
    worst = 0.0
    for k, t in enumerate(times):
        p = 4.0 * t
        worst = max(worst, np.abs(r.nodal("contact_pressure", k)[slave] - p).max() / p)
        for name, value in expected_stress(dim, p).items():
            worst = max(worst, np.abs(r.element(name, k) - value).max() / p)
    print("%-22s times %s, element variables %s, QA %s, worst value error %.2e"
          % (path, " ".join(repr(t) for t in times), " ".join(r.element_names), " ".join(qa[0]) if len(qa) else "-",
             worst))
    if not worst < 1e-8:
        failures.append("%s: contact pressure or stress off by %.2e (relative)" % (path, worst))
    return failures


def main():
    failures = []
    for stem, dim in (("contact_2d", 2), ("contact_3d", 3)):
        for np_ in (1, 2):
            failures += check_file("np%d/%s.e" % (np_, stem), stem, dim)
        fields = ["displ_" + "xyz"[d] for d in range(dim)] + ["contact_pressure"]
        diff, msg = cc.compare_ranks("np1/%s.e" % stem, "np2/%s.e" % stem, fields)
        print("%-22s 1 vs 2 ranks: %.2e" % (stem, diff))
        failures += [msg] if msg else []
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
