#!/usr/bin/python3
"""The tooth model (Kratos use_cases/tooth_model, thesis Fig. 4.61): the contact force's
refinement study, the dentine layer's effect on the composite's peak von Mises stress, a
picture of each variant, 1 and 2 ranks (README.md).

Usage: check.py [--stems EC1 EC2 EC3 EDC1 EDC2 EDC3] [--ranks STEM ...] [--figures PREFIX]
  --stems: the results np1/STEM.e of the enamel-composite (EC) and enamel-dentine-composite
           (EDC) variants on three nested meshes, coarse to fine (default tooth_ec_1 ...
           tooth_edc_3);
  --ranks: these STEMs also ran on 2 ranks (np2/STEM.e): compared with 1 rank to 1e-10;
  --figures: PREFIX_ec.png and PREFIX_edc.png, the von Mises stress of the finest level of
             each variant (default tooth).

The contact force F is the punch's reaction, -reaction_punch_top_nodes_y, which balances the
tooth's bottom reaction (checked to 1e-8 of F). On three nested meshes (h, h/2, h/4) with
values F1, F2, F3, Richardson extrapolation (e.g. Roache, Verification and Validation in
Computational Science and Engineering, 1998, section 5.4) gives the observed order and the
limit
    p = log2((F1 - F2) / (F2 - F3)),   F_inf = F3 + (F3 - F2) / (2^p - 1),
and the error estimate e_i = |F_i - F_inf| / |F_inf|. Targets (each variant): the differences
keep their sign and shrink, p >= 1 (the errors fall at least like h), e3 <= 1 %.

Von Mises: from each element's stress as Grout writes it (docs/input.md, element stress_xx,
yy, zz, xy; plane strain, so stress_zz = nu (sxx + syy) is part of it),
    s_vm = sqrt(((sxx - syy)^2 + (syy - szz)^2 + (szz - sxx)^2) / 2 + 3 sxy^2),
and the peak is the largest s_vm over the elements of block "composite" at the last step.
Target (the thesis's conclusion, section 4.5.5): the dentine layer lowers the peak, on every
level, and on the finest by more than the two peaks' Richardson error estimates together (so
the difference is not a discretisation error).

Hertz (the contact zone is small: the composite is 75 b thick): for the computed force F,
the punch R = 2 on the composite as a half-plane, Johnson, Contact Mechanics (1985), section
4.2, eqs. (4.43)-(4.45) (contact_check.hertz_line_contact) give b and p0; below the centre
of the contact, eq. (4.49),
    sxx = -(p0/b) ((b^2 + 2 z^2) / sqrt(b^2 + z^2) - 2 z),   szz = -p0 b / sqrt(b^2 + z^2),
    sxz = 0, and syy = nu (sxx + szz) in plane strain,
whose von Mises stress peaks at z = 0.704 b with 0.5575 p0 (nu = 0.3; the largest over the
half-plane). Targets on the finest mesh: the half-width (contact_check.half_width), the
largest nodal contact pressure and the composite's peak von Mises stress within 2 % of
Hertz's for the computed force.
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_common"))
import contact_check as cc  # noqa: E402
from grout_results import Results  # noqa: E402

E = {"composite": 1.03e10, "punch": 2.069e11}
NU = {"composite": 0.3, "punch": 0.29}
RADIUS = 2.0
PUNCH = "reaction_punch_top_nodes_y"
BOTTOM = "reaction_tooth_bottom_nodes_y"
SLAVE = "composite_contact"


def von_mises(r, step=-1):
    s = {c: r.element("stress_" + c, step) for c in ("xx", "yy", "zz", "xy")}
    return np.sqrt(((s["xx"] - s["yy"]) ** 2 + (s["yy"] - s["zz"]) ** 2
                    + (s["zz"] - s["xx"]) ** 2) / 2 + 3 * s["xy"] ** 2)


def hertz_peak_von_mises(p0, nu):
    """Largest von Mises stress under a Hertz line contact, plane strain: eq. (4.49) of Johnson
    on the axis x = 0, maximised over the depth z (in units of b) on a grid of 1e-5 b."""
    z = np.linspace(0.0, 3.0, 300001)
    root = np.sqrt(1 + z ** 2)
    sx = -((1 + 2 * z ** 2) / root - 2 * z)
    sz = -1 / root
    sy = nu * (sx + sz)
    vm = np.sqrt(((sx - sy) ** 2 + (sy - sz) ** 2 + (sz - sx) ** 2) / 2)
    return p0 * float(vm.max())


def level(stem):
    r = Results("np1/%s.e" % stem)
    force = -r.global_var(PUNCH)
    bottom = r.global_var(BOTTOM)
    vm = von_mises(r)
    comp = cc.element_block_slices(r)["composite"]
    k = int(np.argmax(vm[comp]))
    where = r.element_centroids()[comp][k]
    s = cc.side_set_nodes(r, SLAVE)
    x = r.coordinates()[0, s]
    b = cc.half_width(x, r.nodal("contact_pressure")[s])
    b_h, p0_h = cc.hertz_line_contact(force, RADIUS, math.inf, E["punch"], NU["punch"],
                                      E["composite"], NU["composite"])
    return {"stem": stem, "F": force, "bottom": bottom, "vm": float(vm[comp][k]), "at": where,
            "b": b, "b_hertz": b_h, "p_max": float(r.nodal("contact_pressure")[s].max()),
            "p0_hertz": p0_h, "vm_hertz": hertz_peak_von_mises(p0_h, NU["composite"])}


def richardson(q):
    """Observed order, extrapolated value and the relative errors of q1, q2, q3 (nested meshes,
    ratio 2); order None when the differences do not shrink with the same sign."""
    d1, d2 = q[0] - q[1], q[1] - q[2]
    if d2 == 0 or d1 / d2 <= 1:
        return None, None, None
    p = math.log2(d1 / d2)
    limit = q[2] + (q[2] - q[1]) / (2 ** p - 1)
    return p, limit, [abs(v - limit) / abs(limit) for v in q]


def study(name, stems, failures):
    levels = [level(s) for s in stems]
    for lv in levels:
        print("%-12s F = %.8g  (bottom %.8g)  peak von Mises in the composite %.6g at (%.4f, %.4f)"
              " (Hertz %.6g)  b = %.5f (Hertz %.5f)  p_max = %.5g (Hertz %.5g)"
              % (lv["stem"], lv["F"], lv["bottom"], lv["vm"], lv["at"][0], lv["at"][1],
                 lv["vm_hertz"], lv["b"], lv["b_hertz"], lv["p_max"], lv["p0_hertz"]))
        if not abs(lv["bottom"] - lv["F"]) <= 1e-8 * abs(lv["F"]):
            failures.append("%s: the tooth's bottom reaction %.10g does not balance F = %.10g"
                            % (lv["stem"], lv["bottom"], lv["F"]))
    fine = levels[-1]
    for key, ref, label in (("b", "b_hertz", "half-width"), ("p_max", "p0_hertz", "peak pressure"),
                            ("vm", "vm_hertz", "peak von Mises")):
        err = (fine[key] - fine[ref]) / fine[ref]
        print("%s: finest mesh: %s %+.2f %% of Hertz's" % (name, label, 100 * err))
        if not abs(err) <= 0.02:
            failures.append("%s: finest mesh: %s %+.2f %% off Hertz's (target 2 %%)"
                            % (name, label, 100 * err))
    out = {}
    for key, label in (("F", "contact force"), ("vm", "peak von Mises")):
        q = [lv[key] for lv in levels]
        p, limit, err = richardson(q)
        if p is None:
            print("%s: %s %s: the differences do not shrink" % (name, label, q))
            out[key] = (None, None, None)
        else:
            print("%s: %s: observed order %.2f, extrapolated %.8g, errors %s"
                  % (name, label, p, limit, ", ".join("%.3f %%" % (100 * e) for e in err)))
            out[key] = (p, limit, err)
    p, limit, err = out["F"]
    if p is None:
        failures.append("%s: the contact force's differences do not shrink: %s"
                        % (name, [lv["F"] for lv in levels]))
    else:
        if p < 1:
            failures.append("%s: contact force: observed order %.2f < 1" % (name, p))
        if err[2] > 0.01:
            failures.append("%s: contact force: finest mesh's error estimate %.2f %% > 1 %%"
                            % (name, 100 * err[2]))
    return levels, out


def picture(stem, title, path):
    """Three panels, as the thesis's Fig. 4.62: the displacement magnitude on the deformed
    model (displacement x 200), the von Mises stress on the whole model (log scale), and the
    von Mises stress under the punch at true scale."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection
    from matplotlib.colors import LogNorm

    r = Results("np1/%s.e" % stem)
    xy = r.coordinates()[:2].T
    u = np.stack([r.nodal("displ_x"), r.nodal("displ_y")], axis=1)
    umag = np.linalg.norm(u, axis=1) * 1e3
    vm = von_mises(r) / 1e6
    blocks = cc.block_names(r)
    conn = np.concatenate([r.connectivity(b + 1) for b in range(len(blocks))])
    peak = np.max(vm[cc.element_block_slices(r)["composite"]])
    fig, axes = plt.subplots(1, 3, figsize=(17, 4.6))
    panels = [(200.0, umag[conn].mean(axis=1), None, "displacement (um)", (-4.2, 4.2, -4.7, 2.1)),
              (1.0, vm, LogNorm(peak * 1e-3, peak), "von Mises (MPa)", (-4.2, 4.2, -4.7, 2.1)),
              (1.0, vm, None, "von Mises (MPa)", (-0.08, 0.08, -0.07, 0.03))]
    for ax, (scale, field, norm, label, box) in zip(axes, panels):
        pc = PolyCollection((xy + scale * u)[conn], array=field, cmap="viridis", norm=norm,
                            edgecolors="face", linewidths=0.3)
        if norm is None and field is vm:
            pc.set_clim(0, peak)
        ax.add_collection(pc)
        ax.set_xlim(box[0], box[1])
        ax.set_ylim(box[2], box[3])
        ax.set_aspect("equal")
        ax.set_xlabel("x (mm)")
        fig.colorbar(pc, ax=ax, label=label, shrink=0.8)
    for b, name in enumerate(blocks):
        if name != "punch":
            y = xy[np.unique(r.connectivity(b + 1)), 1]
            axes[1].text(3.0, 0.5 * (y.min() + y.max()), name, color="w", ha="center",
                         va="center", fontsize=9)
    axes[0].set_ylabel("y (mm)")
    axes[0].set_title("|u|, deformed x 200")
    axes[1].set_title("von Mises stress, log scale")
    axes[2].set_title("von Mises under the punch, true scale")
    fig.suptitle("%s: peak von Mises in the composite %.1f MPa" % (title, peak))
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
    try:  # 128 colours: a third of the size (Pillow comes with Debian's python3-matplotlib)
        from PIL import Image
        Image.open(path).convert("RGB").quantize(colors=128).save(path, optimize=True)
    except ImportError:
        pass
    print("wrote %s" % path)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--stems", nargs=6, default=["tooth_ec_1", "tooth_ec_2", "tooth_ec_3",
                                                  "tooth_edc_1", "tooth_edc_2", "tooth_edc_3"])
    ap.add_argument("--ranks", nargs="*", default=[])
    ap.add_argument("--figures", default="tooth")
    a = ap.parse_args()
    failures = []
    ec, ec_r = study("enamel-composite", a.stems[:3], failures)
    edc, edc_r = study("enamel-dentine-composite", a.stems[3:], failures)
    for i, (x, y) in enumerate(zip(ec, edc), start=1):
        drop = (x["vm"] - y["vm"]) / x["vm"]
        print("level %d: the dentine changes the composite's peak von Mises by %+.2f %% "
              "(%.6g -> %.6g), the contact force by %+.2f %%"
              % (i, -100 * drop, x["vm"], y["vm"], 100 * (y["F"] - x["F"]) / x["F"]))
        if not y["vm"] < x["vm"]:
            failures.append("level %d: the dentine does not lower the composite's peak von Mises "
                            "(%.6g with, %.6g without)" % (i, y["vm"], x["vm"]))
    p1, _, e1 = ec_r["vm"]
    p2, _, e2 = edc_r["vm"]
    if p1 is None or p2 is None:
        failures.append("the peak von Mises stresses do not converge: no error estimate")
    else:
        gap = (ec[-1]["vm"] - edc[-1]["vm"]) / ec[-1]["vm"]
        bound = e1[2] + e2[2] * edc[-1]["vm"] / ec[-1]["vm"]
        print("finest: the dentine lowers the peak by %.2f %%, the error estimates add to %.2f %%"
              % (100 * gap, 100 * bound))
        if not gap > bound:
            failures.append("finest: the dentine's %.2f %% drop of the peak von Mises is within "
                            "the error estimates (%.2f %%)" % (100 * gap, 100 * bound))
    for stem in a.ranks:
        diff, msg = cc.compare_ranks("np1/%s.e" % stem, "np2/%s.e" % stem,
                                     ["displ_x", "displ_y", "contact_pressure"])
        print("%s: 1 vs 2 ranks %.1e" % (stem, diff))
        if msg:
            failures.append(msg)
    picture(a.stems[2], "enamel-composite", a.figures + "_ec.png")
    picture(a.stems[5], "enamel-dentine-composite", a.figures + "_edc.png")
    for f in failures:
        print("FAIL: " + f)
    print("tooth: %s" % ("FAILED" if failures else "all checks pass"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
