"""Double arc, frictionless: GetFEM's solution (getfem_double_arch.py) against Grout's and the
literature (docs/verification.md, "Double arc", "Independent check with GetFEM").

Usage:
  getfem_compare.py --ci [--tol 0.01]
      The ctest (working folder build/inputs/double_arch, after the CI runs): runs
      getfem_double_arch.py on double_arch.exo on the steps of Grout's np1/double_arch_ci.e
      (frictionless, d to 0.024 in 8 steps) and np1/double_arch_mu05_ci.e (mu = 0.5, 16 steps;
      friction depends on the path, so the same steps) and compares with the np1/ and np2/
      runs step by step. Exit 77 (ctest: skipped) when python3-getfem is missing.
  getfem_compare.py --full STEM:MU[:SLAVE] ... [--tol 0.01] [--mesh double_arch.exo]
      docs/verification.md #14's "Grout within 1 % of GetFEM on the same mesh and law over the
      path" (ctest double_arch/getfem_full, after the 1-rank runs of double_arch.yaml and
      double_arch_mu05.yaml): runs getfem_double_arch.py on double_arch.exo with friction
      coefficient MU to the d of Grout's np1/STEM.e, on Grout's steps when they are equal
      (else in steps of 0.5 mm, Grout's largest), and compares the centre curves at Grout's
      steps (GetFEM interpolated linearly in d): max |u_G - u_g| within --tol of Grout's
      largest |u| over the path. SLAVE (default base, as Grout and Kratos) is GetFEM's slave
      side: with mu > 0 only slave = ring gives a GetFEM curve that converges in its steps
      (docs/verification.md, "Independent check with GetFEM"). Exit 77 when python3-getfem is
      missing.
  getfem_compare.py --grout STEM[:LABEL] ... --getfem CSV[:LABEL[:STEM]] ... [--plot PNG]
      The full path (run_getfem.sh): GetFEM CSVs and Grout runs (np1/STEM.e) against the
      literature curve (frictionless_reference_center_displacement.csv) and Kratos' 2017
      solution; a GetFEM curve naming a Grout STEM (the run on the same mesh) is also compared
      with it. Prints the numbers, writes PNG (a curve labelled "diagnostic" is dotted).
      --frictional: mu = 0.5 runs, against frictional_reference_figure.csv (Kratos' figure,
      digitised) instead.

Numbers (u = the centre's vertical displacement, ring_bottom; d = the imposed displacement):
- GetFEM vs Grout: max and rms of |u_G(d) - u_g(d)| over Grout's steps (GetFEM interpolated
  linearly in d), in mm and relative to max|u_ref| = 0.0519 m (the measure of check.py); the
  ring-end force likewise, relative to its largest value;
- each curve vs the literature: check.py's measure, max and rms over the reference points;
- each curve: the dip (min u and its d) and the snap-through d (where u crosses +0.02 m
  upwards, the middle of the jump; linear interpolation).

CI tolerance (--tol, default 0.01): max |u_G - u_g| over d <= 0.024 within 1 % of the largest
|u_g| on that portion (3.06 mm frictionless, 3.20 mm with mu = 0.5: about 31 um), and the end
forces within 1 %. Both codes solve the
same discrete elasticity (same mesh, bilinear quads, 2x2 Gauss, the same W, the same nodal
supports); they differ only in the contact discretisation (Grout: mortar segments with
multipliers at the slave nodes; GetFEM: Gauss-point raytracing with an augmented Lagrangian).
That difference, measured as GetFEM's own spread between slave = base and slave = ring, r =
E/h, 10 E/h and E/(10 h), release distance 5 and 10 mm, is at most 7.5 um (0.25 % of the dip;
docs/verification.md; with mu = 0.5 at most 5 um); 1 % is four times that, and eight times
smaller than a model error as small as 10 % on the base's E (the dip moves by 0.24 mm, 8 %);
friction itself moves the dip by 0.14 mm (4.5 %), so a friction law that is off fails too.
"""
import argparse
import csv
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "contact_common"))
sys.path.insert(0, HERE)
SKIP = 77


def grout_curve(path):
    """(d, u_centre, end force) from a Grout Exodus file, with the undeformed state first."""
    from check import centre_curve
    return centre_curve(path, force="reaction_ring_ends_nodes_y")


def getfem_curve(path):
    g = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return np.r_[0.0, g[:, 0]], np.r_[0.0, g[:, 1]], np.r_[0.0, g[:, 2]]


def reference(name):
    rows = [r for r in csv.reader(open(os.path.join(HERE, name))) if r and not r[0].startswith("#")]
    data = np.array([[float(v) for v in r] for r in rows[1:]])
    return data[:, -2], data[:, -1]


SNAP_U = 0.02  # m: the middle of the snap-through jump (u goes from about 0 to 0.04)


def dip_and_snap(d, u):
    """(min u, its d, the d where u first reaches SNAP_U after the dip, linear interpolation)."""
    k = int(np.argmin(u))
    snap = float("nan")
    for i in range(k, len(d) - 1):
        if u[i] < SNAP_U <= u[i + 1]:
            snap = d[i] + (SNAP_U - u[i]) * (d[i + 1] - d[i]) / (u[i + 1] - u[i])
            break
    return u[k], d[k], snap


def against_reference(d, u, d_ref, u_ref):
    inside = (d_ref >= d[0]) & (d_ref <= d[-1] + 1e-12)
    err = np.abs(np.interp(d_ref[inside], d, u) - u_ref[inside]) / np.abs(u_ref).max()
    return err.max(), np.sqrt((err ** 2).mean()), int(inside.sum())


def difference(d_a, u_a, d_b, u_b):
    """|u_a - u_b| at b's d (a interpolated), over b's d within a's range."""
    inside = d_b <= d_a[-1] + 1e-12
    return np.abs(np.interp(d_b[inside], d_a, u_a) - u_b[inside]), d_b[inside]


def ci_case(stem, mu, tol, failures):
    """GetFEM on the steps of Grout's np1/STEM.e (equal steps from 0), against np1 and np2."""
    d1 = grout_curve("np1/%s.e" % stem)[0]
    steps = len(d1) - 1
    if steps < 1 or np.abs(np.diff(d1) - d1[1]).max() > 1e-9:
        failures.append("np1/%s.e: not equal steps from d = 0" % stem)
        return 0
    csv_out = "getfem_%s.csv" % stem
    cmd = [sys.executable, os.path.join(HERE, "getfem_double_arch.py"), "--mesh",
           "double_arch.exo", "--d-max", repr(d1[-1]), "--steps", str(steps), "--mu", repr(mu),
           "--csv", csv_out]
    rc = subprocess.call(cmd)
    if rc == SKIP:
        return SKIP
    if rc != 0:
        failures.append("%s: getfem_double_arch.py failed (exit code %d)" % (stem, rc))
        return 0
    dg, ug, fg = getfem_curve(csv_out)
    for np_ in (1, 2):
        d, u, f = grout_curve("np%d/%s.e" % (np_, stem))
        if len(d) != len(dg) or np.abs(d - dg).max() > 1e-9:
            failures.append("np%d/%s: steps differ from GetFEM's" % (np_, stem))
            continue
        du, df = np.abs(ug - u), np.abs(fg - f)
        scale_u, scale_f = np.abs(u).max(), np.abs(f).max()
        print("np%d/%s (mu = %g): GetFEM vs Grout over d <= %.4f (%d steps): centre max %.2e m "
              "(%.2f %% of max|u| = %.3e), end force max %.3e N/m (%.2f %% of %.3e)"
              % (np_, stem, mu, d[-1], steps, du.max(), 100 * du.max() / scale_u, scale_u,
                 df.max(), 100 * df.max() / scale_f, scale_f))
        if np_ == 1:
            for di, ui, uGi in zip(d, u, ug):
                print("   d = %.4f  Grout %+.6f  GetFEM %+.6f" % (di, ui, uGi))
        if not du.max() <= tol * scale_u:
            failures.append("np%d/%s: centre differs by %.2e m > %.1f %% of %.3e"
                            % (np_, stem, du.max(), 100 * tol, scale_u))
        if not df.max() <= tol * scale_f:
            failures.append("np%d/%s: end force differs by %.3e > %.1f %% of %.3e"
                            % (np_, stem, df.max(), 100 * tol, scale_f))
    return 0


def full_case(spec, tol, failures, mesh="double_arch.exo"):
    """Row 14: GetFEM over the whole path of np1/STEM.e (STEM:MU[:SLAVE]) on MESH (Grout's),
    within tol of max |u|; SLAVE (base, the default, or ring) is GetFEM's slave side."""
    stem, _, rest = spec.partition(":")
    mu, _, slave = rest.partition(":")
    mu = float(mu or 0.0)
    slave = slave or "base"
    d, u, f = grout_curve("np1/%s.e" % stem)
    steps = len(d) - 1
    if np.abs(np.diff(d) - d[-1] / steps).max() > 1e-9:
        steps = int(round(d[-1] / 0.0005))
    csv_out = "getfem_full_%s.csv" % stem
    cmd = [sys.executable, os.path.join(HERE, "getfem_double_arch.py"), "--mesh",
           mesh, "--d-max", repr(d[-1]), "--steps", str(steps), "--mu", repr(mu),
           "--slave", slave, "--csv", csv_out]
    rc = subprocess.call(cmd)
    if rc == SKIP:
        return SKIP
    if rc != 0:
        failures.append("%s: getfem_double_arch.py failed (exit code %d)" % (stem, rc))
        return 0
    dg, ug, fg = getfem_curve(csv_out)
    du = np.abs(np.interp(d, dg, ug) - u)
    df = np.abs(np.interp(d, dg, fg) - f)
    k = int(np.argmax(du))
    scale_u, scale_f = np.abs(u).max(), np.abs(f).max()
    print("np1/%s (mu = %g), d up to %.4f (Grout %d steps, GetFEM %d, slave %s): centre max "
          "|u_G - u_g| "
          "%.3f mm at d = %.4f (%.2f %% of Grout's max|u| = %.4f m; tolerance %.1f %%), rms "
          "%.3f mm; end force max %.2f %% of max|F| = %.3e N/m (printed)"
          % (stem, mu, d[-1], len(d) - 1, steps, slave, 1e3 * du.max(), d[k],
             100 * du.max() / scale_u,
             scale_u, 100 * tol, 1e3 * np.sqrt((du ** 2).mean()), 100 * df.max() / scale_f,
             scale_f))
    if not du.max() <= tol * scale_u:
        failures.append("np1/%s: centre differs from GetFEM's by %.3f mm > %.1f %% of %.4f m"
                        % (stem, 1e3 * du.max(), 100 * tol, scale_u))
    return 0


def full_check(a):
    failures = []
    for spec in a.full:
        if full_case(spec, a.tol, failures, a.mesh) == SKIP:
            return SKIP
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        return 1
    print("double_arch/getfem_full: Grout within %.1f %% of GetFEM over the path" % (100 * a.tol))
    return 0


def ci(a):
    failures = []
    for stem, mu in (("double_arch_ci", 0.0), ("double_arch_mu05_ci", 0.5)):
        if ci_case(stem, mu, a.tol, failures) == SKIP:
            return SKIP
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        return 1
    print("double_arch/getfem: GetFEM and Grout agree within %.1f %%" % (100 * a.tol))
    return 0


def full(a):
    if a.frictional:
        d_ref, u_ref = reference("frictional_reference_figure.csv")
        d_k, u_k = np.zeros(0), np.zeros(0)
    else:
        d_ref, u_ref = reference("frictionless_reference_center_displacement.csv")
        d_k, u_k = reference("frictionless_kratos2017_center_displacement.csv")
    scale = np.abs(u_ref).max()
    grouts = {}
    for spec in a.grout:
        stem, _, label = spec.partition(":")
        grouts[stem] = ("Grout " + (label or stem),) + grout_curve("np1/%s.e" % stem)
    curves = []
    for spec in a.getfem:
        path, label, stem = (spec.split(":") + ["", ""])[:3]
        if stem and stem not in grouts:
            raise SystemExit("--getfem %s: no --grout %s" % (spec, stem))
        curves.append(("GetFEM " + (label or os.path.basename(path)),) + getfem_curve(path)
                      + (stem,))
    print("%-40s %9s %8s %8s %9s %9s" % ("curve", "dip (mm)", "at d", "snap d", "lit. max",
                                         "lit. rms"))
    table = [("literature", d_ref, u_ref)] + ([("Kratos 2017", d_k, u_k)] if len(d_k) else [])
    for name, d, u in table + [(c[0], c[1], c[2]) for c in list(grouts.values()) + curves]:
        dip, at, snap = dip_and_snap(d, u)
        emax, erms, n = against_reference(d, u, d_ref, u_ref)
        print("%-40s %9.3f %8.4f %8.4f %8.1f%% %8.1f%%" % (name, 1e3 * dip, at, snap, 100 * emax,
                                                        100 * erms))
    for c in curves:
        if not c[4]:
            continue
        g = grouts[c[4]]
        du, dd = difference(c[1], c[2], g[1], g[2])
        df, _ = difference(c[1], c[3], g[1], g[3])
        k = int(np.argmax(du))
        print("%s vs %s over %d steps: centre max %.3f mm (%.2f %% of max|u_ref|, at d = %.4f), "
              "rms %.3f mm (%.2f %%); end force max %.2f %% of max|F|"
              % (c[0], g[0], len(dd) - 1, 1e3 * du.max(), 100 * du.max() / scale, dd[k],
                 1e3 * np.sqrt((du ** 2).mean()), 100 * np.sqrt((du ** 2).mean()) / scale,
                 100 * df.max() / np.abs(g[3]).max()))
    if a.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 5))
        ax.plot(d_ref, u_ref, "o", mfc="none", color="k",
                label="reference: Kratos' figure, digitised" if a.frictional else
                "literature (Drouet 2015; Poulios & Renard 2015)")
        if len(d_k):
            ax.plot(d_k, u_k, "--", color="gray", lw=1, label="Kratos 2017 (3D hexa)")
        for i, g in enumerate(grouts.values()):
            ax.plot(g[1], g[2], "-", color="C%d" % (3 + i), lw=3, alpha=0.45, label=g[0])
        for i, c in enumerate(curves):
            ax.plot(c[1], c[2], ":" if "diagnostic" in c[0] else "-",
                    color="C%d" % ([0, 1, 2, 5, 6, 7][i % 6]), lw=1.2, label=c[0])
        ax.set_xlabel("imposed displacement d (m)")
        ax.set_ylabel("vertical displacement of the centre (m)")
        ax.set_title("Double arc, %s, plane strain: GetFEM, Grout, literature"
                     % ("mu = 0.5" if a.frictional else "frictionless"))
        ax.legend(fontsize=7)
        ax.grid(alpha=0.3)
        fig.tight_layout()
        fig.savefig(a.plot, dpi=100)
        print("wrote %s" % a.plot)
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ci", action="store_true")
    ap.add_argument("--full", nargs="+", metavar="STEM:MU[:SLAVE]")
    ap.add_argument("--tol", type=float, default=0.01)
    ap.add_argument("--mesh", default="double_arch.exo",
                    help="--full: the Exodus mesh of Grout's runs, for GetFEM")
    ap.add_argument("--getfem", nargs="*", default=[])
    ap.add_argument("--grout", nargs="*", default=[])
    ap.add_argument("--plot")
    ap.add_argument("--frictional", action="store_true",
                    help="against frictional_reference_figure.csv (mu = 0.5)")
    a = ap.parse_args()
    if a.full:
        return full_check(a)
    return ci(a) if a.ci else full(a)


if __name__ == "__main__":
    sys.exit(main())
