#!/usr/bin/python3
"""Summarize perf/getfem_3d/run.sh's runs (WORK dir = argv[1]): results.json and a markdown
summary on stdout.

Hertz, two equal spheres R1 = R2 = 1 (Johnson §4.2): R* = 1/2, E* = E/(2(1 - nu^2)),
a = (3 F R*/(4 E*))^(1/3), p0 = 3 F/(2 pi a^2), each code compared with Hertz for ITS OWN
computed total force F = 4 x the z reaction on the upper flat face (quarter model).

Extraction, the same for both codes, from the nodal contact pressure p at the slave
(upper_contact) nodes and their distance r = sqrt(x^2 + y^2) from the axis (reference
positions):
  zone  = the slave nodes with p > 0 and r < r_open, r_open = the smallest r of a node with
          p <= 0 (the radial run of positive nodes from the centre; GetFEM's integral
          multiplier oscillates in sign outside the contact zone, Grout's is 0 there);
  a, p0 = least-squares fit of p^2 = p0^2 (1 - r^2/a^2) to the zone (inputs/gmsh_hertz/
          check_3d.py's fit, which takes every node with p > 0: reported as a_all/p0_all);
  p_max = the largest nodal pressure.
Grout: contact_pressure on node set upper_contact_nodes from the Exodus results, F from the
summary CSV (reaction_upper_top_nodes_z). GetFEM: getfem_hertz_3d.py's gf_pressure.csv
(-lambda.n at the slave nodes) and its F (internal force on the top z dofs).
"""
import csv
import glob
import json
import math
import os
import re
import sys

import numpy as np

ROOT = os.environ.get("GROUT_ROOT", os.getcwd())
sys.path.insert(0, os.path.join(ROOT, "tools"))

R, E, NU = 1.0, 200.0, 0.3
R_STAR = 1.0 / (1.0 / R + 1.0 / R)
E_STAR = E / (2 * (1 - NU ** 2))
STEM = "hemispheres"


def hertz(F):
    a = (3 * F * R_STAR / (4 * E_STAR)) ** (1.0 / 3.0)
    return a, 3 * F / (2 * math.pi * a * a)


def fit(r, p):
    A = np.vstack([np.ones(len(r)), r ** 2]).T
    c = np.linalg.lstsq(A, p ** 2, rcond=None)[0]
    if not (c[0] > 0 and c[1] < 0):
        return float("nan"), float("nan")
    return math.sqrt(-c[0] / c[1]), math.sqrt(c[0])


def accuracy(r, p, F):
    r, p = np.asarray(r, float), np.asarray(p, float)
    a_h, p0_h = hertz(F)
    closed = p <= 0
    r_open = float(r[closed].min()) if closed.any() else float("inf")
    zone = (p > 0) & (r < r_open)
    a, p0 = fit(r[zone], p[zone]) if zone.sum() >= 3 else (float("nan"), float("nan"))
    a_all, p0_all = fit(r[p > 0], p[p > 0]) if (p > 0).sum() >= 3 else (float("nan"), float("nan"))
    pm = float(p.max())
    return {"F": F, "a_hertz": a_h, "p0_hertz": p0_h, "a": a, "p0": p0,
            "err_a": (a - a_h) / a_h, "err_p0": (p0 - p0_h) / p0_h,
            "a_all": a_all, "p0_all": p0_all, "err_a_all": (a_all - a_h) / a_h,
            "err_p0_all": (p0_all - p0_h) / p0_h, "p_max": pm, "err_pmax": (pm - p0_h) / p0_h,
            "r_open": r_open, "n_zone": int(zone.sum()), "n_pos": int((p > 0).sum()),
            "n_pos_outside": int(((p > 0) & ~zone).sum()), "p_min": float(p.min()),
            "p_max_outside": float(p[~zone].max()) if (~zone).any() else 0.0}


def grout_profile(d):
    import netCDF4
    from grout_results import Results
    res = Results(os.path.join(d, STEM + ".e"))
    names = [str(s).strip() for s in netCDF4.chartostring(res.ds.variables["ns_names"][:])]
    s = np.asarray(res.ds.variables["node_ns%d" % (names.index("upper_contact_nodes") + 1)][:]) - 1
    xyz = res.coordinates()
    with open(os.path.join(d, STEM + ".csv")) as f:
        row = list(csv.DictReader(f))[-1]
    F = 4 * abs(float(row["reaction_upper_top_nodes_z"]))
    return np.hypot(xyz[0, s], xyz[1, s]), res.nodal("contact_pressure")[s], F, row


def getfem_result(d):
    lines = [l for l in open(os.path.join(d, "out.txt")) if l.startswith("RESULT ")]
    return json.loads(lines[0][7:]) if lines else None


def gnu_time(path):
    t = open(path).read()
    m = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", t)
    parts = [float(v) for v in m.group(1).split(":")]
    wall = sum(v * 60 ** i for i, v in enumerate(reversed(parts)))
    cpu = float(re.search(r"User time \(seconds\): (\S+)", t).group(1)) + \
        float(re.search(r"System time \(seconds\): (\S+)", t).group(1))
    rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", t).group(1))
    code = re.search(r"Exit status: (\d+)", t)
    return {"wall": wall, "cpu": cpu, "rss_mb": rss / 1024.0, "exit": int(code.group(1)) if code else None}


def grout_timers(path):
    """{timer: seconds} from grout --timers (1 rank: Global time; 2 ranks: MaxOverProcs), the
    driver's own total ('wrote ... (x s)') and the Newton/linear iteration counts."""
    out = {}
    txt = open(path).read()
    for line in txt.splitlines():
        m = re.match(r"(grout: [^0-9]+?|Belos: [^0-9]+?|MueLu: [^0-9]+?)\s{2,}([0-9.e+-]+) \((\d+)\)(.*)$", line)
        if m:
            vals = re.findall(r"([0-9.e+-]+) \((\d+)\)", line[len(m.group(1)):])
            v = float(vals[2][0]) if len(vals) >= 3 else float(vals[0][0])
            out[m.group(1).strip()] = v
    m = re.search(r"wrote .* \(([0-9.]+) s\)", txt)
    out["run_total"] = float(m.group(1)) if m else float("nan")
    m = re.search(r"newton (\d+)\s+linear (\d+)\s+\|F\| = (\S+)\s*$", txt, re.M)
    if m:
        out["newton"], out["linear"], out["residual"] = int(m.group(1)), int(m.group(2)), float(m.group(3))
    out["solver"] = ("MUMPS" if "MUMPS" in txt else "") + ("Belos" if "Belos" in txt else "") or "?"
    return out


def main(work):
    rows = []
    for sd in sorted(glob.glob(os.path.join(work, "h*")), key=lambda p: -float(os.path.basename(p)[1:])):
        reps = sorted(glob.glob(os.path.join(sd, "rep*")))
        if not reps:
            continue
        rec = {"size": os.path.basename(sd)[1:], "reps": []}
        for rp in reps:
            one = {}
            for k in ("grout_np1", "getfem", "grout_np2"):
                tf = os.path.join(rp, k, "time.txt")
                if os.path.exists(tf):
                    one[k] = gnu_time(tf)
                    if k != "getfem":
                        one[k]["timers"] = grout_timers(os.path.join(rp, k, "out.txt"))
            g = getfem_result(os.path.join(rp, "getfem")) if "getfem" in one else None
            if g:
                one["getfem"]["result"] = g
            for k, nm in (("grout_np1", "ratio1"), ("grout_np2", "ratio2")):
                if k in one and "getfem" in one:
                    one[nm] = one["getfem"]["wall"] / one[k]["wall"]
                    one[nm + "_cpu"] = one["getfem"]["cpu"] / one[k]["cpu"]
            rec["reps"].append(one)
        rp = reps[0]
        for k in ("grout_np1", "grout_np2"):
            d = os.path.join(rp, k)
            if os.path.exists(os.path.join(d, STEM + ".e")):
                r, p, F, row = grout_profile(d)
                rec["acc_" + k] = accuracy(r, p, F)
                rec["acc_" + k]["newton"] = int(row["newton_iterations"])
                rec["nodes"] = int(open(os.path.join(d, "out.txt")).read().split(" nodes")[0].split()[-1])
        gd = os.path.join(rp, "getfem")
        g = getfem_result(gd)
        if g:
            rec["nodes"] = g["nodes"]
            prof = np.loadtxt(os.path.join(gd, "gf_pressure.csv"), delimiter=",", skiprows=1)
            rec["acc_getfem"] = accuracy(np.hypot(prof[:, 0], prof[:, 1]), prof[:, 3], g["F"])
            rec["acc_getfem"]["newton"] = g["iterations"]
            rec["getfem"] = g
        rows.append(rec)
    with open(os.path.join(work, "results.json"), "w") as f:
        json.dump(rows, f, indent=1)
    return rows


def med(v):
    v = [x for x in v if x is not None]
    return float(np.median(v)) if v else float("nan")


def tms(v):
    v = [x for x in v if x is not None]
    if not v:
        return "–"
    return "%.2f" % med(v) if len(v) == 1 else "%.2f (%s)" % (med(v), " ".join("%.2f" % t for t in v))


def pct(x):
    return "–" if x is None or not np.isfinite(x) else "%+.1f %%" % (100 * x)


def table(rows):
    def col(rec, k, f):
        return [f(r[k]) if k in r else None for r in rec["reps"]]
    out = ["| contact size | nodes | Grout 1 rank s | GetFEM s | Grout 2 ranks s | GetFEM / Grout-1 | "
           "GetFEM / Grout-2 | CPU s Grout-1 / GetFEM / Grout-2 | CPU ratio GetFEM / Grout-1, / Grout-2 | Newton its Grout / GetFEM | "
           "a err Grout / GetFEM | p0 err Grout / GetFEM | p_max err Grout / GetFEM | "
           "peak RSS MB Grout-1 / GetFEM / Grout-2 |", "|" + "---|" * 14]
    for rec in rows:
        ag, af = rec.get("acc_grout_np1", {}), rec.get("acc_getfem", {})
        reps = rec["reps"]
        out.append("| %s | %d | %s | %s | %s | %s | %s | %s / %s / %s | %s, %s | %s / %s | %s / %s | %s / %s | %s / %s | %s / %s / %s |" % (
            rec["size"], rec.get("nodes", 0),
            tms(col(rec, "grout_np1", lambda t: t["wall"])), tms(col(rec, "getfem", lambda t: t["wall"])),
            tms(col(rec, "grout_np2", lambda t: t["wall"])),
            " ".join("%.2f" % r["ratio1"] for r in reps if "ratio1" in r) or "–",
            " ".join("%.2f" % r["ratio2"] for r in reps if "ratio2" in r) or "–",
            tms(col(rec, "grout_np1", lambda t: t["cpu"])), tms(col(rec, "getfem", lambda t: t["cpu"])),
            tms(col(rec, "grout_np2", lambda t: t["cpu"])),
            " ".join("%.2f" % r["ratio1_cpu"] for r in reps if "ratio1_cpu" in r) or "–",
            " ".join("%.2f" % r["ratio2_cpu"] for r in reps if "ratio2_cpu" in r) or "–",
            ag.get("newton", "–"), af.get("newton", "–"),
            pct(ag.get("err_a")), pct(af.get("err_a")), pct(ag.get("err_p0")), pct(af.get("err_p0")),
            pct(ag.get("err_pmax")), pct(af.get("err_pmax")),
            "%.0f" % max(r["grout_np1"]["rss_mb"] for r in reps) if all("grout_np1" in r for r in reps) else "–",
            "%.0f" % max(r["getfem"]["rss_mb"] for r in reps) if all("getfem" in r for r in reps) else "–",
            "%.0f" % max(r["grout_np2"]["rss_mb"] for r in reps) if all("grout_np2" in r for r in reps) else "–"))
    return "\n".join(out)


def timers_table(rows):
    keys = ["solid assembly", "contact (search, integration, assembly)", "jacobian (u, lambda)", "linear solve"]
    out = ["| contact size | ranks | solver | Newton / linear its | process wall s | driver run total s | "
           + " | ".join(k + " s" for k in keys) + " | linear solve share of run total | GetFEM set-up s / solve() s |",
           "|" + "---|" * (8 + len(keys) - 1)]
    for rec in rows:
        rp = rec["reps"][0]
        for k, ranks in (("grout_np1", 1), ("grout_np2", 2)):
            if k not in rp:
                continue
            t = rp[k]["timers"]
            lin = t.get("grout: linear solve", float("nan"))
            gf = rec.get("getfem")
            out.append("| %s | %d | %s | %s / %s | %.2f | %.2f | %s | %.0f %% | %s |" % (
                rec["size"], ranks, t["solver"], t.get("newton", "?"), t.get("linear", "?"), rp[k]["wall"],
                t["run_total"], " | ".join("%.3f" % t.get("grout: " + key, float("nan")) for key in keys),
                100 * lin / t["run_total"],
                ("%.2f / %.2f" % (gf["t_setup"], gf["t_solve"])) if (gf and ranks == 1) else ""))
    return "\n".join(out)


def detail(rows):
    out = ["| contact size | code | F | Hertz a / p0 for this F | a (zone fit) | p0 (zone fit) | p_max | "
           "a / p0 (check_3d.py rule: all p > 0) | nodes in zone / p > 0 | min nodal p | max p outside zone | Newton its | final residual |",
           "|" + "---|" * 13]
    for rec in rows:
        for k, name in (("acc_grout_np1", "Grout 1 rank"), ("acc_grout_np2", "Grout 2 ranks"), ("acc_getfem", "GetFEM")):
            if k not in rec:
                continue
            a = rec[k]
            if k == "acc_getfem":
                res = "|r|/|R_top| = %.1e" % rec["getfem"]["rel_residual"]
            else:
                t = rec["reps"][0]["grout_np1" if "np1" in k else "grout_np2"]["timers"]
                res = "|F| = %.1e" % t.get("residual", float("nan"))
            out.append("| %s | %s | %.5f | %.5f / %.3f | %.5f (%s) | %.3f (%s) | %.3f (%s) | %.5f / %.3f (%s / %s) | %d / %d | %.3f | %.3f | %s | %s |" % (
                rec["size"], name, a["F"], a["a_hertz"], a["p0_hertz"], a["a"], pct(a["err_a"]),
                a["p0"], pct(a["err_p0"]), a["p_max"], pct(a["err_pmax"]), a["a_all"], a["p0_all"],
                pct(a["err_a_all"]), pct(a["err_p0_all"]), a["n_zone"], a["n_pos"], a["p_min"],
                a["p_max_outside"], a["newton"], res))
    return "\n".join(out)


if __name__ == "__main__":
    rows = main(sys.argv[1])
    print("## Times (whole process, /usr/bin/time -v; ratios per repetition, wall)\n")
    print(table(rows))
    print("\n## Grout --timers (repetition 1; 2 ranks: max over ranks)\n")
    print(timers_table(rows))
    print("\n## Accuracy against Hertz (repetition 1)\n")
    print(detail(rows))
